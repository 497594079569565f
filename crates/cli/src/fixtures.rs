//! The notes' worked examples, embedded at build time from `fixtures/` (see build.rs).

include!(concat!(env!("OUT_DIR"), "/fixtures.rs"));
