//! The one integration-test binary of cagd-cli: runs the built `cagd` binary.

mod batch;
mod commands;
mod common;
mod limits;
