//! The catalogue of mistakes over random problems: each mistaken answer is diagnosed as its
//! mistake (or as ambiguous, naming it), and the key's own answer is correct, with no
//! diagnosis. One module per operation family; `common` holds the harness.

#![allow(clippy::expect_used, clippy::panic, clippy::indexing_slicing)]

mod common;
mod coons;
mod elevate;
mod evaluate;
mod subdivide;
