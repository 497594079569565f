//! The one integration-test binary of cagd-surface.

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

mod common;
mod errors;
mod fast_paths;
mod notes;
mod props;
mod rational;
