//! The one integration-test binary of cagd-triangle.

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

#[path = "suite/closed_form.rs"]
mod closed_form;
#[path = "suite/common.rs"]
mod common;
#[path = "suite/errors.rs"]
mod errors;
#[path = "suite/hand.rs"]
mod hand;
#[path = "suite/properties.rs"]
mod properties;
#[path = "suite/scalars.rs"]
mod scalars;
