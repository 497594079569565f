//! Curves and surfaces fitted to data over any [`Scalar`](cagd_scalar::Scalar), solved exactly.
//!
//! Curves:
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
//! Surfaces (the notes' chapter 5, §7, "Interpolación y aproximación"):
//!
//! - Tensor-grid interpolation by a Bézier patch, eqs. (26)-(27): `B_U C B_Vᵗ = A`, solved as
//!   `C̃ B_Vᵗ = A` (each row of data) and then `B_U C = C̃` (each column), or columns first
//!   ([`interpolate_bezier_surface`], [`interpolate_bezier_surface_in_passes`] with the matrices
//!   B_U, B_V and C̃; [`coordinate_matrices`] splits a mesh into C_x, C_y, C_z).
//! - Bicubic B-spline interpolation of a grid: a cubic spline through each row, then through
//!   each column of control points, natural or Bessel ends per direction
//!   ([`interpolate_bicubic_spline`], [`interpolate_bicubic_spline_in_passes`]).
//! - Scattered data a_k = c(u_k, v_k), eq. (28) with B ordered c_00, c_01, ..., c_mn
//!   ([`bezier_surface_matrix`]): interpolation when there are as many points as control points
//!   ([`interpolate_bezier_surface_scattered`], which explains why it can be singular), least
//!   squares (29) `BᵗB C = BᵗA` otherwise ([`approximate_bezier_surface`],
//!   [`approximate_bezier_surface_by_normal_equations`]), and least squares by a B-spline surface with given
//!   knots ([`approximate_bspline_surface`]).
//!
//! Every matrix is factored once for all right-hand sides (every row or column of a grid) and
//! all coordinates ([`cagd_linalg::Factorization::solve_points`]). Nothing rounds: over
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
mod fast;
mod parameters;
mod scattered;
mod scattered_spline;
mod spline;
mod surface;
mod surface_spline;

pub use bezier::{approximate_bezier, bernstein_matrix, bezier_domain, interpolate_bezier};
pub use bspline::{
    approximate_bspline, bspline_matrix, end_derivative_system,
    interpolate_bspline_end_derivatives, EndDerivativeSystem,
};
pub use cagd_spline_surface::Direction;
pub use error::{Datum, FitError, Fitted, Singularity, Support};
pub use parameters::{averaged_knots, parameters, ParameterError, Parametrization};
pub use scattered::{
    approximate_bezier_surface, approximate_bezier_surface_by_normal_equations,
    bezier_surface_matrix, interpolate_bezier_surface_scattered, normal_equations_first_rows,
    LeastSquaresStep, ScatteredInterpolation,
};
pub use scattered_spline::{approximate_bspline_surface, bspline_surface_matrix};
pub use spline::{
    bessel_tangents, cubic_spline_knots, cubic_spline_system, interpolate_cubic_spline,
    CubicSplineSystem, EndCondition, EndConditions,
};
pub use surface::{
    coordinate_matrices, interpolate_bezier_surface, interpolate_bezier_surface_in_passes,
    GridStep, PassOrder,
};
pub use surface_spline::{
    interpolate_bicubic_spline, interpolate_bicubic_spline_in_passes, SurfaceEndConditions,
};
