//! The one integration-test binary of cagd-generate: the notes' examples of chapter 6 and
//! property tests over random small rationals.

mod coons;
mod coons_rational;
mod developable;
mod revolution;
mod ruled;
mod spline;
mod support;
mod translational;
