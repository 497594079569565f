//! The catalogue of mistakes over random problems: each mistaken answer is diagnosed as its
//! mistake (or as ambiguous, naming it), and the key's own answer is correct, with no
//! diagnosis. One module per operation family; `common` holds the harness.

// the helpers beside the tests (the harness, sums by hand) index and expect, as tests do
#![allow(clippy::indexing_slicing, clippy::expect_used, clippy::panic)]

mod common;
mod continuity;
mod coons;
mod derivative;
mod normal;
