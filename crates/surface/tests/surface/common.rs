//! Helpers shared by the tests: meshes read from the notes' notation, and proptest strategies.

use cagd_linalg::Point;
use cagd_poly::{parse_vec_poly, VecPoly};
use cagd_scalar::{parse_number, BigRational, FieldOps, Scalar};
use cagd_surface::{BezierSurface, Grid, Mesh, RationalBezierSurface};
use proptest::prelude::*;

/// A point of the notes' notation, `(2/3, 0, 19/9)`, over any scalar.
pub fn point<S: Scalar>(text: &str) -> Point<S> {
    let inner = text.trim().trim_start_matches('(').trim_end_matches(')');
    Point::new(
        inner
            .split(',')
            .map(|c| S::try_from_number(&parse_number(c.trim()).unwrap()).unwrap())
            .collect(),
    )
}

/// A mesh in the notes' notation: `{(0, 0, 0), (0, 1, 0); (1, 0, 0), (1, 1, 1)}`.
pub fn mesh<S: Scalar>(text: &str) -> Mesh<S> {
    let inner = text.trim().trim_start_matches('{').trim_end_matches('}');
    let rows = inner
        .split(';')
        .map(|row| {
            row.split(')')
                .filter(|p| p.contains('('))
                .map(|p| point(&format!("{})", p.trim().trim_start_matches(','))))
                .collect()
        })
        .collect();
    Mesh::mesh(rows).unwrap()
}

/// The Bézier patch of a mesh in the notes' notation.
pub fn patch<S: Scalar>(text: &str) -> BezierSurface<S> {
    BezierSurface::try_new(mesh(text)).unwrap()
}

/// A grid of numbers: `{1, sqrt2/2, 1; ...}`.
pub fn numbers<S: Scalar>(text: &str) -> Grid<S> {
    let inner = text.trim().trim_start_matches('{').trim_end_matches('}');
    let rows = inner
        .split(';')
        .map(|row| {
            row.split(',')
                .map(|x| S::try_from_number(&parse_number(x.trim()).unwrap()).unwrap())
                .collect()
        })
        .collect();
    Grid::from_rows(rows).unwrap()
}

/// A rational patch from a mesh and a weight grid in the notes' notation.
pub fn rational<S: Scalar>(points: &str, weights: &str) -> RationalBezierSurface<S> {
    RationalBezierSurface::try_new(mesh(points), numbers(weights)).unwrap()
}

/// A tuple of polynomials, `(2 v, 2 v - 2 v^2, u)`.
pub fn vp(text: &str) -> VecPoly<BigRational> {
    parse_vec_poly(text).unwrap()
}

/// Exact rational.
pub fn r(n: i64, d: i64) -> BigRational {
    <BigRational as FieldOps>::from_ratio(n, d)
}

/// Small random rationals n/d, n in [-9, 9], d in 1..9.
pub fn rat() -> impl Strategy<Value = BigRational> {
    (-9i64..=9, 1i64..=9).prop_map(|(n, d)| r(n, d))
}

/// A random rational in [0, 1].
pub fn unit() -> impl Strategy<Value = BigRational> {
    (1i64..=9).prop_flat_map(|d| (0..=d).prop_map(move |n| r(n, d)))
}

/// A random rational strictly inside (0, 1).
pub fn interior() -> impl Strategy<Value = BigRational> {
    (2i64..=9).prop_flat_map(|d| (1..d).prop_map(move |n| r(n, d)))
}

/// A random positive rational weight.
pub fn positive() -> impl Strategy<Value = BigRational> {
    (1i64..=9, 1i64..=9).prop_map(|(n, d)| r(n, d))
}

/// A random mesh of bidegree (m, n) <= (max, max) with points of dimension `dim`.
pub fn random_mesh(max: usize, dim: usize) -> impl Strategy<Value = Mesh<BigRational>> {
    (0..=max, 0..=max).prop_flat_map(move |(m, n)| {
        prop::collection::vec(
            prop::collection::vec(prop::collection::vec(rat(), dim), n + 1),
            m + 1,
        )
        .prop_map(|rows| {
            Mesh::mesh(
                rows.into_iter()
                    .map(|r| r.into_iter().map(Point::new).collect())
                    .collect(),
            )
            .unwrap()
        })
    })
}

/// A random Bézier patch (bidegree up to (3, 3)) in R^3.
pub fn random_patch() -> impl Strategy<Value = BezierSurface<BigRational>> {
    random_mesh(3, 3).prop_map(|m| BezierSurface::try_new(m).unwrap())
}

/// A random rational patch with positive weights, bidegree up to (max, max), in R^3.
pub fn random_rational(max: usize) -> impl Strategy<Value = RationalBezierSurface<BigRational>> {
    random_mesh(max, 3).prop_flat_map(|m| {
        let (rows, cols) = (m.rows(), m.cols());
        prop::collection::vec(prop::collection::vec(positive(), cols), rows).prop_map(move |w| {
            RationalBezierSurface::try_new(m.clone(), Grid::from_rows(w).unwrap()).unwrap()
        })
    })
}

/// A random domain [a, b] x [c, d] with ends in [-9, 9].
pub fn random_domain() -> impl Strategy<Value = (BigRational, BigRational, BigRational, BigRational)>
{
    (rat(), positive(), rat(), positive())
        .prop_map(|(a, la, c, lc)| (a.clone(), a + la, c.clone(), c + lc))
}
