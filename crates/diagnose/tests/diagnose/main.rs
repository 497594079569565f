//! The catalogue of mistakes over random problems: each mistaken answer is diagnosed as its
//! mistake (or as ambiguous, naming it), and the key's own answer is correct, with no
//! diagnosis. One module per operation family; `common` holds the harness.

mod common;
mod coons;
mod interpolate;
mod ruled;
mod translational;
