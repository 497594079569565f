//! Curves fitted to data over any [`Scalar`](cagd_scalar::Scalar), solved exactly.
//!
//! - Bézier interpolation: the curve of degree n through n + 1 points at given parameters,
//!   from the Bernstein collocation matrix `B_ij = B_j^n(u_i)` ([`interpolate_bezier`],
//!   [`bernstein_matrix`]).
//! - C² cubic spline interpolation in B-spline form (Farin, chapter 9): control points
//!   d_0, ..., d_{N+2} on the knots `{u_0, u_0, u_0, u_1, ..., u_{N−1}, u_N, u_N, u_N}`, with
//!   natural, clamped or Bessel end conditions ([`interpolate_cubic_spline`]).
//! - Least-squares approximation by the normal equations `BᵗB C = Bᵗ A` (the notes' chapter 5,
//!   eq. (29)): Bézier curves of a given degree ([`approximate_bezier`]) and B-spline curves
//!   with given knots ([`approximate_bspline`]).
//!
//! Every system is solved once for all coordinates (one factorization, one solve per
//! coordinate, [`cagd_linalg::Factorization::solve_points`]). Nothing rounds: over
//! `BigRational` the control points are exact, and the interpolants pass through their data
//! exactly.
//!
//! ```
//! use cagd_fit::interpolate_bezier;
//! use cagd_linalg::Point;
//! use cagd_scalar::{q, BigRational};
//! // The notes' column u = 1/2 of the bidegree (2, 3) example, z only: c(1/2, v) at v = 0, 1/3, 2/3, 1.
//! let a: Vec<Point<BigRational>> = [q!(1), q!(2), q!(1), q!(1/2)].into_iter().map(|z| Point::new(vec![z])).collect();
//! let c = interpolate_bezier(&[q!(0), q!(1/3), q!(2/3), q!(1)], &a).unwrap();
//! assert_eq!(c.to_text(), "(1), (23/6), (-1/12), (1/2)");
//! ```

mod bezier;
mod bspline;
mod data;
mod error;
mod spline;

pub use bezier::{approximate_bezier, bernstein_matrix, bezier_domain, interpolate_bezier};
pub use bspline::{approximate_bspline, bspline_matrix};
pub use error::FitError;
pub use spline::{
    bessel_tangents, cubic_spline_knots, cubic_spline_system, interpolate_cubic_spline,
    CubicSplineSystem, EndCondition, EndConditions,
};
