//! Empty on purpose: this package only exists so that `cargo insta review` (which looks inside
//! workspace packages) finds the snapshot files kept in the top-level `snapshots/` folder.
