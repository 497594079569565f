//! Answers as exact values, independent of the scalar a problem ran in: the values
//! ([`Exact`], [`Number`]), the scalars a problem runs in and their results as values
//! ([`ExactScalar`]), the comparison with a fixture's `expected`, and the JSON of a value.
//!
//! A module below this one (read by the scalars or the comparison) names the part it uses
//! (`value::exact`), not this module.

pub mod exact;
pub(crate) mod expected;
pub(crate) mod json;
pub mod quantity;
pub mod scalar;

pub use exact::{Exact, Number};
pub use json::{matrix_text, numbers_text, rational_json};
pub use quantity::Quantity;
pub use scalar::{
    exact, exact_grid, exact_map, exact_mesh, exact_point, exact_points, exact_poly,
    exact_rational, ExactScalar,
};
