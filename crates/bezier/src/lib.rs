//! Bézier and rational Bézier curves over any [`Scalar`](cagd_scalar::Scalar).
//!
//! Three layers:
//!
//! - free functions on control polygons (`&[Point<S>]`), which the surface and B-spline crates
//!   apply to the rows and columns of meshes and to the pieces of splines:
//!   [`bernstein`], [`bernstein_all`], [`de_casteljau`], [`de_casteljau_triangle`],
//!   [`bernstein_sum`], [`blossom`], [`subdivide`], [`restrict`], [`elevate_degree`],
//!   [`forward_differences`], [`derivative_points`]. They accept any parameter value
//!   (extrapolation is legitimate mathematics) and check the polygon (not empty, one
//!   dimension);
//! - typed curves that validate their data once: [`BezierCurve`] and [`RationalBezierCurve`]
//!   (weights, homogeneous form weight-last), on a domain [a, b] (by default [0, 1]) outside of
//!   which `eval` is an error; their closed forms as polynomial and rational maps of
//!   `cagd-poly` ([`BezierCurve::closed_form`], [`RationalBezierCurve::closed_form`]);
//! - conics and exact circles ([`quarter_circle`], [`circle_arc`],
//!   [`circle_arc_from_tangents`], [`circle_four_arcs`], [`circle_three_arcs`],
//!   [`circle_four_arcs_rational`]), exact in the quadratic field a + b√d.
//!
//! Nothing rounds: over `BigRational` every control point is exact, e.g. the point at t = 1/3
//! of the parabola with control points (0, 0), (1, 2), (3, 3):
//!
//! ```
//! use cagd_bezier::de_casteljau;
//! use cagd_linalg::Point;
//! use cagd_scalar::{q, BigRational};
//! let c: Vec<Point<BigRational>> =
//!     vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2]), Point::from_ints(&[3, 3])];
//! assert_eq!(de_casteljau(&c, &q!(1/3)).unwrap().to_text(), "(7/9, 11/9)");
//! ```

mod bernstein;
mod blossom;
mod casteljau;
mod closed_form;
mod conic;
mod curve;
mod derivative;
mod elevate;
mod error;
mod integral;
mod length;
mod polygon;
mod rational;
mod reduce;

pub use bernstein::{bernstein, bernstein_all, bernstein_sum, binomial};
pub use blossom::{blossom, restrict};
pub use casteljau::{de_casteljau, de_casteljau_triangle, subdivide};
pub use conic::{
    circle_arc, circle_arc_from_tangents, circle_four_arcs, circle_four_arcs_rational,
    circle_three_arcs, conic_arc, quarter_circle,
};
pub use curve::BezierCurve;
pub use derivative::{derivative_points, forward_differences};
pub use elevate::elevate_degree;
pub use error::{BezierError, NeedsRoot, NotAnArc, Quantity, Rule};
pub use integral::{control_point_average, polygon_integral};
pub use length::{
    polynomial_length, rational_length, LengthError, LengthNotGiven, NotExact, PieceLength,
};
pub use polygon::check_polygon;
pub use rational::{lift, project_one, ConicKind, RationalBezierCurve};
pub use reduce::{reduce_homogeneous, reduce_polygon, PolygonReduction, ReductionError};
