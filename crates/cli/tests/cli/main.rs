//! The one integration-test binary of cagd-cli: runs the built `cagd` binary.

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

mod batch;
mod class;
mod commands;
mod common;
mod figures;
mod limits;
mod lost;
mod sheet;
mod spanish;
mod stream;
mod text_is_data;
