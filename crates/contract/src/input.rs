//! The curves and surfaces of the problem format (the shapes of `docs/format.md`), as written:
//! a problem's arguments, and the values of answers. They are read with serde
//! ([`crate::spec`]); the algorithms validate them ([`crate::Problem`] runs them).

pub use crate::message::found::quoted;
use cagd_linalg::Point;
use cagd_poly::VecPoly;
use cagd_scalar::Scalar;
use cagd_surface::{Grid, Mesh};

/// A curve as the problem gives it.
#[derive(Debug, Clone, PartialEq)]
pub enum CurveIn<S: Scalar> {
    /// `{"bezier": [...], "weights": [...]}`.
    Bezier {
        /// Control polygon.
        points: Vec<Point<S>>,
        /// Weights (rational curve) or `None`.
        weights: Option<Vec<S>>,
    },
    /// `{"bspline": [...], "degree": p, "knots": [...], "weights": [...]}`.
    BSpline {
        /// Control polygon.
        points: Vec<Point<S>>,
        /// Degree.
        degree: usize,
        /// Knots, in either convention (told apart by length).
        knots: Vec<S>,
        /// Weights (NURBS) or `None`.
        weights: Option<Vec<S>>,
    },
    /// `{"expr": "(u, 0, u^2)"}`: a polynomial map in one variable.
    Expr(VecPoly<S>),
}

/// A surface as the problem gives it.
#[derive(Debug, Clone, PartialEq)]
pub enum SurfaceIn<S: Scalar> {
    /// `{"bezier": [[...]], "weights": [[...]]}`.
    Bezier {
        /// Control mesh.
        mesh: Mesh<S>,
        /// Weights or `None`.
        weights: Option<Grid<S>>,
    },
    /// `{"bspline": [[...]], "degree": [p, q], "knots": [[...], [...]], "weights": [[...]]}`.
    BSpline {
        /// Control mesh.
        mesh: Mesh<S>,
        /// Degrees (p, q).
        degree: (usize, usize),
        /// Knots in u and in v.
        knots: (Vec<S>, Vec<S>),
        /// Weights or `None`.
        weights: Option<Grid<S>>,
    },
    /// `{"expr": "(u, v, u v)"}`: a polynomial map in u and v.
    Expr(VecPoly<S>),
}
