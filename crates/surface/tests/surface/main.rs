//! The one integration-test binary of cagd-surface.

mod common;
mod errors;
mod notes;
mod props;
mod rational;
