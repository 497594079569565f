//! The one integration-test binary of cagd-generate: the notes' examples of chapter 6 and
//! property tests over random small rationals.

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

mod coons;
mod coons_rational;
mod developable;
mod revolution;
mod ruled;
mod spline;
mod support;
mod translational;
