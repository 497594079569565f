//! The one integration-test binary of cagd-triangle.

#[path = "suite/closed_form.rs"]
mod closed_form;
#[path = "suite/common.rs"]
mod common;
#[path = "suite/errors.rs"]
mod errors;
#[path = "suite/hand.rs"]
mod hand;
#[path = "suite/properties.rs"]
mod properties;
#[path = "suite/scalars.rs"]
mod scalars;
