//! Fitting: interpolation and least-squares approximation, and their parameters.

pub(crate) mod fit;
pub(crate) mod params;
