//! Triangular Bézier patches.

pub(crate) mod triangle;
