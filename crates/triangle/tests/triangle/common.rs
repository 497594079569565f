//! Shared helpers: points, patches and proptest strategies over small rationals.

use cagd_linalg::Point;
use cagd_scalar::{BigInt, BigRational};
use cagd_triangle::{control_point_count, Barycentric, Direction, TriangularPatch};
use proptest::prelude::*;

pub type Q = BigRational;

/// The rational n/d.
pub fn r(n: i64, d: i64) -> Q {
    BigRational::new(BigInt::from(n), BigInt::from(d))
}

/// A point of integer coordinates.
pub fn pt(c: &[i64]) -> Point<Q> {
    Point::from_ints(c)
}

/// A small rational: numerator in [-9, 9], denominator in 1..=9.
pub fn small() -> impl Strategy<Value = Q> {
    (-9i64..=9, 1i64..=9).prop_map(|(n, d)| r(n, d))
}

/// A point of dimension `dim` with small rational coordinates.
pub fn point(dim: usize) -> impl Strategy<Value = Point<Q>> {
    prop::collection::vec(small(), dim).prop_map(Point::new)
}

/// A random patch of degree 1..=4 in R^1..R^3.
pub fn patch() -> impl Strategy<Value = TriangularPatch<Q>> {
    (1usize..=4, 1usize..=3).prop_flat_map(|(n, dim)| {
        let count = control_point_count(n).unwrap_or(0);
        prop::collection::vec(point(dim), count)
            .prop_map(move |pts| TriangularPatch::try_new(n, pts).unwrap())
    })
}

/// A barycentric point (r, s, 1 - r - s) with small rational r, s (inside or outside the
/// domain triangle).
pub fn bary() -> impl Strategy<Value = Barycentric<Q>> {
    (small(), small()).prop_map(|(u, v)| Barycentric::from_uv(u, v))
}

/// A direction (-a - b, a, b) with small rational a, b.
pub fn direction() -> impl Strategy<Value = Direction<Q>> {
    (small(), small()).prop_map(|(a, b)| Direction::from_uv(a, b))
}

/// x + h d, a barycentric point.
pub fn shift(x: &Barycentric<Q>, h: &Q, d: &Direction<Q>) -> Barycentric<Q> {
    let c: Vec<Q> = (0..3)
        .map(|m| x.coords()[m].clone() + h * &d.coords()[m])
        .collect();
    Barycentric::try_new(c[0].clone(), c[1].clone(), c[2].clone()).unwrap()
}

/// ρ a + σ b + τ c for a barycentric point y = (ρ, σ, τ): the image of y under the affine map
/// taking e1, e2, e3 to a, b, c.
pub fn map_point(y: &Barycentric<Q>, tri: [&Barycentric<Q>; 3]) -> Barycentric<Q> {
    let c: Vec<Q> = (0..3)
        .map(|m| {
            (0..3).fold(r(0, 1), |acc, v| {
                acc + y.coords()[v].clone() * &tri[v].coords()[m]
            })
        })
        .collect();
    Barycentric::try_new(c[0].clone(), c[1].clone(), c[2].clone()).unwrap()
}
