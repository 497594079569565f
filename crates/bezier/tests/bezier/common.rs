//! Helpers shared by the tests: exact literals, polygons, and proptest strategies.

use cagd_linalg::Point;
use cagd_scalar::{parse_number, parse_rational, BigRational, FieldOps, Quadratic, Scalar};
use proptest::prelude::*;

/// The rational point with these literal coordinates: `pt(&["1/2", "3"])`.
pub fn pt(coords: &[&str]) -> Point<BigRational> {
    Point::new(coords.iter().map(|c| parse_rational(c).unwrap()).collect())
}

/// A polygon of integer points.
pub fn ints(points: &[&[i64]]) -> Vec<Point<BigRational>> {
    points.iter().map(|c| Point::from_ints(c)).collect()
}

/// Exact number of Q(√d).
pub fn qn(text: &str) -> Quadratic {
    parse_number(text).unwrap()
}

/// The polygon as text.
pub fn text<S: Scalar>(points: &[Point<S>]) -> Vec<String> {
    points.iter().map(Point::to_text).collect()
}

/// Small random rationals n/d, n in [-9, 9], d in 1..9.
pub fn rat() -> impl Strategy<Value = BigRational> {
    (-9i64..=9, 1i64..=9).prop_map(|(n, d)| <BigRational as FieldOps>::from_ratio(n, d))
}

/// A random control polygon of degree 0..=max_degree in dimension 1..=3.
pub fn polygon(max_degree: usize) -> impl Strategy<Value = Vec<Point<BigRational>>> {
    (1usize..=3, 0usize..=max_degree).prop_flat_map(|(dim, n)| {
        prop::collection::vec(prop::collection::vec(rat(), dim), n + 1)
            .prop_map(|pts| pts.into_iter().map(Point::new).collect())
    })
}

/// A random positive rational weight.
pub fn positive_weight() -> impl Strategy<Value = BigRational> {
    (1i64..=9, 1i64..=9).prop_map(|(n, d)| <BigRational as FieldOps>::from_ratio(n, d))
}

/// A random polygon with positive weights, degree 1..=max_degree, dimension 1..=3.
pub fn weighted_polygon(
    max_degree: usize,
) -> impl Strategy<Value = (Vec<Point<BigRational>>, Vec<BigRational>)> {
    (1usize..=3, 1usize..=max_degree).prop_flat_map(|(dim, n)| {
        (
            prop::collection::vec(prop::collection::vec(rat(), dim), n + 1)
                .prop_map(|pts| pts.into_iter().map(Point::new).collect()),
            prop::collection::vec(positive_weight(), n + 1),
        )
    })
}
