//! The notes' worked examples, embedded at build time (cagd-fixtures).

pub use cagd_fixtures::FIXTURES;
