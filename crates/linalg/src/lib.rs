//! Points, vectors and matrices over any [`Scalar`], and exact linear algebra.
//!
//! A [`Point`] is a point (or vector) of any dimension: the control points of curves and
//! surfaces, in R^2, R^3 or homogeneous R^4. A [`Matrix`] is a dense row-major matrix. Both are
//! generic over [`Scalar`]; nothing here rounds.

mod error;
mod matrix;
mod point;

pub use error::LinalgError;
pub use matrix::Matrix;
pub use point::Point;

pub use cagd_scalar::Scalar;
