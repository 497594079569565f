//! Helpers shared by the test modules: the rational type, strategies for small rationals,
//! points and increasing parameters.

use cagd_linalg::Point;
use cagd_scalar::{BigRational, FieldOps, Scalar};
use cagd_surface::Mesh;
use proptest::prelude::*;

pub type Q = BigRational;

pub fn p2(x: Q, y: Q) -> Point<Q> {
    Point::new(vec![x, y])
}

pub fn texts<S: Scalar>(points: &[Point<S>]) -> Vec<String> {
    points.iter().map(Point::to_text).collect()
}

pub fn small_rational() -> impl Strategy<Value = Q> {
    (-9i64..=9, 1i64..=9).prop_map(|(n, d)| Q::from_ratio(n, d))
}

pub fn positive_rational() -> impl Strategy<Value = Q> {
    (1i64..=9, 1i64..=9).prop_map(|(n, d)| Q::from_ratio(n, d))
}

pub fn point(dim: usize) -> impl Strategy<Value = Point<Q>> {
    prop::collection::vec(small_rational(), dim).prop_map(Point::new)
}

/// `count` strictly increasing rationals: a start and positive steps.
pub fn increasing(count: usize) -> impl Strategy<Value = Vec<Q>> {
    (
        small_rational(),
        prop::collection::vec(positive_rational(), count - 1),
    )
        .prop_map(|(start, steps)| {
            let mut u = vec![start];
            for s in steps {
                let next = u[u.len() - 1].clone() + s;
                u.push(next);
            }
            u
        })
}

/// A parameter of the unit interval: k/12, k = 0..=12.
pub fn unit_rational() -> impl Strategy<Value = Q> {
    (0i64..=12).prop_map(|k| Q::from_ratio(k, 12))
}

/// A `rows × cols` grid of random points of dimension `dim`.
pub fn grid(rows: usize, cols: usize, dim: usize) -> impl Strategy<Value = Mesh<Q>> {
    prop::collection::vec(prop::collection::vec(point(dim), cols), rows)
        .prop_map(|rows| Mesh::mesh(rows).unwrap())
}

/// The points of a grid given by a function of its parameters, a_ij = f(u_i, v_j).
pub fn sample(u: &[Q], v: &[Q], f: impl Fn(&Q, &Q) -> Point<Q>) -> Mesh<Q> {
    Mesh::from_fn(u.len(), v.len(), |i, j| f(&u[i], &v[j]))
}
