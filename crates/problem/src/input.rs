//! The curves and surfaces of the problem format (the shapes of `docs/format.md`), as written:
//! a problem's arguments, and the values of answers. They are read with serde
//! ([`crate::spec`]); the algorithms validate them ([`crate::Problem`] runs them).

use crate::message::contract::Found;
use cagd_linalg::Point;
use cagd_poly::VecPoly;
use cagd_scalar::Scalar;
use cagd_surface::{Grid, Mesh};
use serde_json::Value;

/// A string quoted for an error message, cut to its first 40 characters so that the
/// message stays one short line whatever the input holds.
pub fn quoted(s: &str) -> String {
    const SHOWN: usize = 40;
    let mut chars = s.chars();
    let head: String = chars.by_ref().take(SHOWN).collect();
    if chars.next().is_some() {
        format!("{:?}", head + "...")
    } else {
        format!("{s:?}")
    }
}

/// The JSON kind of a value, in words (typed; its `Display` is the English).
pub fn kind(v: &Value) -> Found {
    match v {
        Value::Null => Found::Null,
        Value::Bool(b) => Found::Bool(*b),
        Value::Number(n) => Found::Number(n.to_string()),
        Value::String(s) => Found::Str(quoted(s)),
        Value::Array(a) => Found::ListOf(a.len()),
        Value::Object(_) => Found::Object,
    }
}

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
