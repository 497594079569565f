//! The integration tests of cagd-problem, one binary (it links once): bad input, degenerate
//! geometry, the fixtures of the notes, the examples of docs/format.md, the limits, and the JSON Schemas.

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

mod arc_length;
mod bad_input;
mod circles_and_conics;
mod curvature;
mod curve_operations;
mod degenerate;
mod developable;
mod expected_check;
mod fitting;
mod fixtures;
mod format_doc;
mod glossary;
mod homogeneous;
mod inversion;
mod json_numbers;
mod knots;
mod letters;
mod limits;
mod patch_operations;
mod pieces;
mod read_text;
mod refusals;
mod schema;
mod steps;
mod stream;
mod student_steps;
mod triangle;
mod values;
