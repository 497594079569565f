//! The one integration-test binary of cagd-surface.

mod common;
mod errors;
mod fast_paths;
mod notes;
mod props;
mod rational;
