//! Knot vectors, B-spline and NURBS curves over any [`Scalar`](cagd_scalar::Scalar).
//!
//! Two layers, as in `cagd-bezier`:
//!
//! - free functions on `(&KnotVector<S>, &[Point<S>], ...)`, which the surface code applies
//!   to the rows and columns of a control mesh ("two passes"): [`basis_functions`],
//!   [`basis_derivatives`], [`de_boor`], [`de_boor_triangle`], [`blossom`], [`insert_knot`],
//!   [`insert_knot_recorded`], [`refine_knots`], [`remove_knot`], [`bezier_pieces`],
//!   [`elevate_degree`], [`derivative_curve`], [`derivatives`]. The degree is the knot
//!   vector's own ([`KnotVector::degree`]), so it cannot disagree with the knots; rational
//!   meshes go through these functions in homogeneous form `(w x, w y, w z, w)`;
//! - typed curves that validate their data once: [`BSplineCurve`], [`NurbsCurve`], and the
//!   exact circles of [`unit_circle`], [`circle_slides`], [`circle_of_arcs`].
//!
//! # Knot conventions
//!
//! The notes (Farin's convention) write a curve of degree p with n control points with
//! n + p - 1 knots, domain `[u_{p-1}, u_{n-1}]`; The NURBS Book adds one knot at each end
//! (n + p + 1 knots, domain `[u_p, u_n]`). [`KnotVector::read`] accepts both, tells them apart
//! by length and says which it read; output uses the notes' convention by default
//! ([`KnotVector::to_convention`] for the other). The algorithms follow Piegl and Tiller, so
//! span indices ([`KnotVector::find_span`]) are those of the full convention; control-point
//! indices are the same in both.
//!
//! Nothing rounds: the notes' circle evaluated at t = 1/8 over `a + b√2` is exactly
//! `(√2/2, √2/2)`:
//!
//! ```
//! use cagd_bspline::unit_circle;
//! use cagd_scalar::{parse_number, Quadratic};
//! let circle = unit_circle::<Quadratic>().unwrap();
//! let p = circle.eval(&parse_number("1/8").unwrap()).unwrap();
//! assert_eq!(p.to_text(), "(√2/2, √2/2)");
//! ```

mod arc;
mod basis;
mod checked;
mod circle;
mod curve;
mod de_boor;
mod derivative;
mod elevate;
mod error;
mod extract;
mod insert;
mod integral;
mod knots;
mod nurbs;
mod polygon;
mod reduce;
mod remove;
mod split;

pub use arc::{default_arcs, exact_arc, root_of_angles, ArcError};
pub use basis::{basis_derivatives, basis_function, basis_functions, basis_functions_at};
pub use circle::{circle_of_arcs, circle_slides, unit_circle};
pub use curve::BSplineCurve;
pub use de_boor::{blossom, de_boor, de_boor_triangle, DeBoorLevel, DeBoorTriangle};
pub use derivative::{derivative_curve, derivatives};
pub use elevate::elevate_degree;
pub use error::{BSplineError, CircleData, Construction, NoDerivative};
pub use extract::{bezier_pieces, insert_breakpoints, BezierPiece};
pub use insert::{insert_knot, insert_knot_recorded, refine_knots, Insertion};
pub use integral::{basis_integrals, curve_integral, support_integrals};
pub use knots::{
    knots_spaced, multiplicities, normalize_list, KnotConvention, KnotVector, Spacing,
};
pub use nurbs::{NurbsCurve, RationalBezierPiece};
pub use polygon::check_control_points;
pub use reduce::{ReducedPiece, SplineReduction, SplineReductionError};
pub use remove::remove_knot;
pub use split::SplitError;
