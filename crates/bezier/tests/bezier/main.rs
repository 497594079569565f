//! The one integration-test binary of cagd-bezier.

mod closed_form;
mod common;
mod conic;
mod curve;
mod properties;
mod rational;
mod slices;
