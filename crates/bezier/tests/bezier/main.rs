//! The one integration-test binary of cagd-bezier.

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

mod closed_form;
mod common;
mod conic;
mod curve;
mod properties;
mod rational;
mod slices;
mod zero_weights;
