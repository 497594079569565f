//! Helpers shared by the test modules: the rational type, strategies for small rationals,
//! points and increasing parameters; the recorded steps of the surface fits, by name.

use cagd_fit::{
    approximate_bezier_surface_by_normal_equations, interpolate_bezier_surface_in_passes,
    interpolate_bicubic_spline_in_passes, FitError, GridStep, LeastSquaresStep, PassOrder,
    SurfaceEndConditions,
};
use cagd_linalg::{Matrix, Point};
use cagd_scalar::{BigRational, FieldOps, Scalar};
use cagd_spline_surface::BSplineSurface;
use cagd_surface::{BezierSurface, Mesh};
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

/// The steps a grid interpolation in two passes records, by name, with its surface.
#[derive(Debug)]
pub struct Passes<S: Scalar, T> {
    pub order: PassOrder,
    pub matrix_u: Matrix<S>,
    pub matrix_v: Matrix<S>,
    pub intermediate: Mesh<S>,
    pub surface: T,
}

fn passes<S: Scalar, T>(surface: T, steps: Vec<GridStep<S>>) -> Passes<S, T> {
    let [GridStep::MatrixU(matrix_u), GridStep::MatrixV(matrix_v), GridStep::FirstPass { order, mesh }] =
        <[GridStep<S>; 3]>::try_from(steps).expect("three steps")
    else {
        panic!("the steps in their order");
    };
    Passes {
        order,
        matrix_u,
        matrix_v,
        intermediate: mesh,
        surface,
    }
}

/// [`interpolate_bezier_surface_in_passes`] with its recorded steps.
pub fn bezier_in_passes<S: Scalar>(
    u: &[S],
    v: &[S],
    data: &Mesh<S>,
    order: PassOrder,
) -> Result<Passes<S, BezierSurface<S>>, FitError> {
    let mut steps = Vec::new();
    let surface = interpolate_bezier_surface_in_passes(u, v, data, order, &mut steps)?;
    Ok(passes(surface, steps))
}

/// [`interpolate_bicubic_spline_in_passes`] with its recorded steps.
pub fn bicubic_in_passes<S: Scalar>(
    u: &[S],
    v: &[S],
    data: &Mesh<S>,
    ends: &SurfaceEndConditions<S>,
    order: PassOrder,
) -> Result<Passes<S, BSplineSurface<S>>, FitError> {
    let mut steps = Vec::new();
    let surface = interpolate_bicubic_spline_in_passes(u, v, data, ends, order, &mut steps)?;
    Ok(passes(surface, steps))
}

/// The steps a least-squares fit by the normal equations records, by name, with its patch.
#[derive(Debug)]
pub struct LeastSquares<S: Scalar> {
    pub collocation: Matrix<S>,
    pub normal_matrix: Matrix<S>,
    pub rhs: Vec<Point<S>>,
    pub surface: BezierSurface<S>,
}

/// [`approximate_bezier_surface_by_normal_equations`] with its recorded steps.
pub fn normal_equations<S: Scalar>(
    m: usize,
    n: usize,
    params: &[(S, S)],
    points: &[Point<S>],
) -> Result<LeastSquares<S>, FitError> {
    let mut steps = Vec::new();
    let surface = approximate_bezier_surface_by_normal_equations(m, n, params, points, &mut steps)?;
    let [LeastSquaresStep::Collocation(collocation), LeastSquaresStep::NormalMatrix(normal_matrix), LeastSquaresStep::NormalRhs(rhs)] =
        <[LeastSquaresStep<S>; 3]>::try_from(steps).expect("three steps")
    else {
        panic!("the steps in their order");
    };
    Ok(LeastSquares {
        collocation,
        normal_matrix,
        rhs,
        surface,
    })
}
