//! The one integration-test binary of cagd-triangle.

mod closed_form;
mod common;
mod errors;
mod hand;
mod properties;
mod scalars;
