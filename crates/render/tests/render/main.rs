//! The integration tests of cagd-render (one binary).

mod answers;
mod browser;
mod debug_out;
mod export;
mod html;
mod iges;
mod kinds;
mod plots;
mod props;
mod raster;
mod scenes;
mod snapshots;
