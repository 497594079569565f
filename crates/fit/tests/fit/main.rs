//! Integration tests of cagd-fit (one test binary): every fit checked exactly against an
//! independent route (De Boor evaluation, Bézier pieces, Bernstein sums, the matrix form).

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

mod common;
mod curves;
mod fast_paths;
mod grid;
mod scattered;
mod spline_grid;
