//! The catalogue of mistakes over random problems: each mistaken answer is diagnosed as its
//! mistake (or as ambiguous, naming it), and the key's own answer is correct, with no
//! diagnosis. One module per operation family; `common` holds the harness.

#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

mod circle;
mod common;
mod coons;
mod elevate;
mod evaluate;
mod insert_knot;
mod revolution;
mod subdivide;
