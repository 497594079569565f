//! Helpers: exact points and curves from text, and proptest strategies of small rationals
//! (numerators in [-9, 9], denominators 1..9).

#![allow(dead_code)]

use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_linalg::Point;
use cagd_poly::{parse_poly, parse_vec_poly, Poly, Var, VecPoly};
pub use cagd_record::NoSteps;
use cagd_scalar::{parse_number, parse_rational, BigInt, BigRational, Quadratic};
use proptest::prelude::*;

pub type Q = BigRational;

/// A point from exact text coordinates: `pt(&["1/2", "0", "2"])`.
pub fn pt(c: &[&str]) -> Point<Q> {
    Point::new(c.iter().map(|x| parse_rational(x).unwrap()).collect())
}

/// A point of integer coordinates.
pub fn pi(c: &[i64]) -> Point<Q> {
    Point::from_ints(c)
}

/// A Bézier curve from text points.
pub fn curve(points: &[&[&str]]) -> BezierCurve<Q> {
    BezierCurve::try_new(points.iter().map(|c| pt(c)).collect()).unwrap()
}

/// A Bézier curve from integer points.
pub fn icurve(points: &[&[i64]]) -> BezierCurve<Q> {
    BezierCurve::try_new(points.iter().map(|c| pi(c)).collect()).unwrap()
}

/// A rational Bézier curve from integer points and text weights.
pub fn rcurve(points: &[&[i64]], weights: &[&str]) -> RationalBezierCurve<Q> {
    RationalBezierCurve::try_new(
        points.iter().map(|c| pi(c)).collect(),
        weights.iter().map(|w| parse_rational(w).unwrap()).collect(),
    )
    .unwrap()
}

/// A polynomial map from text.
pub fn e(text: &str) -> VecPoly<Q> {
    parse_vec_poly(text).unwrap()
}

/// A scalar polynomial from text.
pub fn p(text: &str) -> Poly<Q> {
    parse_poly(text).unwrap()
}

/// An exact number of the quadratic field from text (`"sqrt2/2"`).
pub fn qd(text: &str) -> Quadratic {
    parse_number(text).unwrap()
}

/// The rational `n/d`.
pub fn r(n: i64, d: i64) -> Q {
    Q::new(BigInt::from(n), BigInt::from(d))
}

/// `c` restricted to `var = x`, written as a constant point (the map must then be constant).
pub fn at(c: &VecPoly<Q>, var: Var, x: &Q) -> VecPoly<Q> {
    c.substitute_value(var, x)
}

/// A small rational: numerator in [-9, 9], denominator in 1..9.
pub fn small() -> impl Strategy<Value = Q> {
    (-9i64..=9, 1i64..=9).prop_map(|(n, d)| r(n, d))
}

/// A small positive rational (a weight): numerator in 1..9, denominator in 1..9.
pub fn positive() -> impl Strategy<Value = Q> {
    (1i64..=9, 1i64..=9).prop_map(|(n, d)| r(n, d))
}

/// A parameter in [0, 1]: k/9 for k in 0..=9... written as n/d with 0 ≤ n ≤ d ≤ 9.
pub fn param() -> impl Strategy<Value = Q> {
    (1i64..=9).prop_flat_map(|d| (0..=d).prop_map(move |n| r(n, d)))
}

/// A point of R^3 with small rational coordinates.
pub fn point3() -> impl Strategy<Value = Point<Q>> {
    prop::collection::vec(small(), 3).prop_map(Point::new)
}

/// A control polygon of R^3 with `len` points.
pub fn polygon(len: usize) -> impl Strategy<Value = Vec<Point<Q>>> {
    prop::collection::vec(point3(), len)
}

/// A list of `len` positive weights.
pub fn weights(len: usize) -> impl Strategy<Value = Vec<Q>> {
    prop::collection::vec(positive(), len)
}
