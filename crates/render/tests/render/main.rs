//! The integration tests of cagd-render (one binary).

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

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
mod roles;
mod scenes;
mod snapshots;
