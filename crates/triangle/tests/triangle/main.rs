//! The one integration-test binary of cagd-triangle.

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

mod closed_form;
mod common;
mod errors;
mod hand;
mod properties;
mod scalars;
