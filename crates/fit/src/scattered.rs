//! Bézier patches fitted to scattered data a_k = c(u_k, v_k) (the notes' chapter 5, §7,
//! eqs. (28)-(29)): interpolation when there are as many points as control points, least
//! squares when there are more.

use crate::bezier::local_parameters;
use crate::data::{check_scattered, count_distinct_up_to};
use crate::{Direction, FitError};
use cagd_bezier::bernstein_all;
use cagd_linalg::{Factorization, LinalgError, Matrix, NormalEquations, Point};
use cagd_record::{NoSteps, Record};
use cagd_scalar::Scalar;
use cagd_surface::{BezierSurface, Mesh};

/// The collocation matrix B of eq. (28) for bidegree (m, n): one row per parameter pair
/// (u_k, v_k), one column per control point in the notes' order c_00, c_01, ..., c_0n,
/// c_10, ..., c_mn (row by row of the mesh),
///
/// `B_{k, i(n+1)+j} = B_i^m(u_k) B_j^n(v_k)`.
///
/// ```
/// use cagd_fit::bezier_surface_matrix;
/// use cagd_scalar::q;
/// let b = bezier_surface_matrix(1, 1, &[(q!(1), q!(0)), (q!(1/2), q!(1/2))]);
/// assert_eq!(b.to_text(), "0  0  1  0\n1/4  1/4  1/4  1/4");
/// ```
pub fn bezier_surface_matrix<S: Scalar>(m: usize, n: usize, params: &[(S, S)]) -> Matrix<S> {
    let mut b = Matrix::zeros(params.len(), (m + 1) * (n + 1));
    for (k, (u, v)) in params.iter().enumerate() {
        let bu = bernstein_all(m, u);
        let bv = bernstein_all(n, v);
        for (i, x) in bu.iter().enumerate() {
            for (j, y) in bv.iter().enumerate() {
                b.set(k, i * (n + 1) + j, x.mul_ref(y));
            }
        }
    }
    b
}

/// The steps of an interpolation with scattered parameters, eq. (28) solved directly.
#[derive(Clone, Debug, PartialEq)]
pub struct ScatteredInterpolation<S: Scalar> {
    /// The square collocation matrix B ([`bezier_surface_matrix`]).
    pub collocation: Matrix<S>,
    /// det B (nonzero: the problem is solvable).
    pub determinant: S,
    /// The interpolating patch.
    pub surface: BezierSurface<S>,
}

/// One step of a least-squares fit (28)-(29), in the order they are made.
#[derive(Clone, Debug, PartialEq)]
pub enum LeastSquaresStep<S: Scalar> {
    /// The collocation matrix B of eq. (28), one row per data point.
    Collocation(Matrix<S>),
    /// The normal matrix BᵗB of eq. (29).
    NormalMatrix(Matrix<S>),
    /// The right-hand side BᵗA of eq. (29), one point per control point c_00, c_01, ..., c_mn.
    NormalRhs(Vec<Point<S>>),
}

/// The local parameters of scattered data (each coordinate on its own domain, as
/// [`crate::bezier_domain`]), and the domain [a, b] x [c, d].
fn local_pairs<S: Scalar>(params: &[(S, S)]) -> (Vec<(S, S)>, [S; 4]) {
    let us: Vec<S> = params.iter().map(|p| p.0.clone()).collect();
    let vs: Vec<S> = params.iter().map(|p| p.1.clone()).collect();
    let (lu, a, b) = local_parameters(&us);
    let (lv, c, d) = local_parameters(&vs);
    (lu.into_iter().zip(lv).collect(), [a, b, c, d])
}

/// At least m + 1 distinct u_k and n + 1 distinct v_k: otherwise the columns of B are
/// dependent whatever the data.
fn check_distinct_values<S: Scalar>(m: usize, n: usize, params: &[(S, S)]) -> Result<(), FitError> {
    let us: Vec<S> = params.iter().map(|p| p.0.clone()).collect();
    let vs: Vec<S> = params.iter().map(|p| p.1.clone()).collect();
    for (direction, degree, values) in [(Direction::U, m, us), (Direction::V, n, vs)] {
        let found = count_distinct_up_to(&values, degree.saturating_add(1));
        if found < degree + 1 {
            return Err(FitError::TooFewDistinctSurfaceParameters {
                direction,
                degree,
                found,
            });
        }
    }
    Ok(())
}

/// The patch with this mesh (row-major control points) on this domain.
fn patch<S: Scalar>(
    n: usize,
    control: &[Point<S>],
    [a, b, c, d]: [S; 4],
) -> Result<BezierSurface<S>, FitError> {
    let mesh = Mesh::mesh(control.chunks(n + 1).map(<[_]>::to_vec).collect())?;
    let s = BezierSurface::try_new(mesh)?;
    if a.is_zero() && b.is_one() && c.is_zero() && d.is_one() {
        Ok(s)
    } else {
        Ok(s.with_domain(a, b, c, d)?)
    }
}

/// The patch of bidegree (m, n) through (m + 1)(n + 1) scattered points,
/// `c(u_k, v_k) = a_k`, from eq. (28) solved directly: `B C = A` (see
/// [`bezier_surface_matrix`] for B and the order of the unknowns).
///
/// Unlike interpolation of curves, this problem can be singular for parameters that look
/// harmless: swapping the parameters of two points swaps two rows of B and changes the sign
/// of det B, so moving them continuously from one order to the other passes through a
/// singular choice (the notes, §7). Then the error is [`FitError::SingularScattered`], which
/// says so; two points with the same parameters, or too few distinct u_k or v_k, are named
/// as such.
///
/// ```
/// use cagd_fit::interpolate_bezier_surface_scattered;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let params = [(q!(0), q!(0)), (q!(1), q!(0)), (q!(0), q!(1)), (q!(1/2), q!(1/2))];
/// let a: Vec<Point<BigRational>> =
///     [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 1]].iter().map(|c| Point::from_ints(c)).collect();
/// let fit = interpolate_bezier_surface_scattered(1, 1, &params, &a).unwrap();
/// assert_eq!(fit.surface.to_text(), "{(0, 0, 0), (0, 1, 0); (1, 0, 0), (3, 3, 4)}");
/// // Points on one line u = v of the domain: a bilinear patch restricted to it is only a
/// // parabola, so four points on the line cannot fix it.
/// let line = [(q!(0), q!(0)), (q!(1/3), q!(1/3)), (q!(2/3), q!(2/3)), (q!(1), q!(1))];
/// let e = interpolate_bezier_surface_scattered(1, 1, &line, &a).unwrap_err();
/// assert!(e.to_string().starts_with(
///     "the interpolation problem with scattered parameters is singular for these parameters"));
/// ```
pub fn interpolate_bezier_surface_scattered<S: Scalar>(
    m: usize,
    n: usize,
    params: &[(S, S)],
    points: &[Point<S>],
) -> Result<ScatteredInterpolation<S>, FitError> {
    check_scattered(params, points)?;
    let unknowns = (m + 1) * (n + 1);
    let what = || crate::Fitted::ScatteredInterpolation { m, n, unknowns };
    if points.len() < unknowns {
        return Err(FitError::TooFewPoints {
            what: what(),
            needed: unknowns,
            found: points.len(),
        });
    }
    if points.len() > unknowns {
        return Err(FitError::TooManyPoints {
            what: what(),
            expected: unknowns,
            found: points.len(),
        });
    }
    check_distinct_values(m, n, params)?;
    for (k, p) in params.iter().enumerate() {
        if let Some(l) = params.iter().take(k).position(|q| q == p) {
            return Err(FitError::SingularScattered {
                bidegree: (m, n),
                detail: crate::Singularity::SameParameters {
                    first: l,
                    second: k,
                    u: p.0.to_text(),
                    v: p.1.to_text(),
                },
            });
        }
    }
    let (local, domain) = local_pairs(params);
    let collocation = bezier_surface_matrix(m, n, &local);
    let factorization = Factorization::new(&collocation).map_err(|e| match e {
        LinalgError::Singular { detail } => FitError::SingularScattered {
            bidegree: (m, n),
            detail: crate::Singularity::Elimination(detail),
        },
        e => FitError::Linalg(e),
    })?;
    let control = factorization.solve_points(points)?;
    Ok(ScatteredInterpolation {
        determinant: factorization.determinant(),
        collocation,
        surface: patch(n, &control, domain)?,
    })
}

/// The patch of bidegree (m, n) closest to scattered data in the least-squares sense, by the
/// normal equations: B of eq. (28), then (29), `BᵗB C = BᵗA`, which minimize
/// `Σ_k |c(u_k, v_k) − a_k|²`; B, BᵗB and BᵗA are recorded ([`LeastSquaresStep`]).
///
/// Always goes through (29), so that BᵗB and BᵗA can be shown; with exactly (m + 1)(n + 1)
/// points the result is the interpolant of [`interpolate_bezier_surface_scattered`]. Needs at
/// least (m + 1)(n + 1) points, m + 1 distinct u_k and n + 1 distinct v_k; a singular BᵗB for
/// other reasons (parameters on one line of the domain, ...) is
/// [`FitError::UndeterminedMesh`].
///
/// The notes' example: five points, a hyperbolic paraboloid (bidegree (1, 1)).
///
/// ```
/// use cagd_fit::approximate_bezier_surface_by_normal_equations;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let a: Vec<Point<BigRational>> = vec![
///     Point::new(vec![q!(0), q!(0), q!(1/4)]), Point::new(vec![q!(1), q!(0), q!(1/3)]),
///     Point::new(vec![q!(0), q!(1), q!(1/2)]), Point::new(vec![q!(1), q!(1), q!(3/4)]),
///     Point::new(vec![q!(1/2), q!(1/2), q!(1/4)]),
/// ];
/// let params = [(q!(0), q!(0)), (q!(1), q!(0)), (q!(0), q!(1)), (q!(1), q!(1)), (q!(1/2), q!(1/2))];
/// let mut steps = Vec::new();
/// let fit = approximate_bezier_surface_by_normal_equations(1, 1, &params, &a, &mut steps).unwrap();
/// assert_eq!(fit.to_text(), "{(0, 0, 5/24), (0, 1, 11/24); (1, 0, 7/24), (1, 1, 17/24)}");
/// assert_eq!(steps.len(), 3);
/// ```
pub fn approximate_bezier_surface_by_normal_equations<S: Scalar>(
    m: usize,
    n: usize,
    params: &[(S, S)],
    points: &[Point<S>],
    rec: &mut impl Record<LeastSquaresStep<S>>,
) -> Result<BezierSurface<S>, FitError> {
    check_scattered(params, points)?;
    let unknowns = (m + 1) * (n + 1);
    if points.len() < unknowns {
        return Err(FitError::TooFewPoints {
            what: crate::Fitted::LeastSquaresPatch { m, n, unknowns },
            needed: unknowns,
            found: points.len(),
        });
    }
    check_distinct_values(m, n, params)?;
    let (local, domain) = local_pairs(params);
    let collocation = bezier_surface_matrix(m, n, &local);
    let normal = NormalEquations::new(&collocation).map_err(|e| match e {
        LinalgError::Singular { detail } => FitError::UndeterminedMesh {
            what: crate::Fitted::BezierPatch { m, n },
            detail,
        },
        e => FitError::Linalg(e),
    })?;
    rec.record(|| LeastSquaresStep::Collocation(collocation));
    rec.record(|| LeastSquaresStep::NormalMatrix(normal.normal_matrix().clone()));
    if rec.on() {
        let rhs = normal.rhs_points(points)?;
        rec.record(|| LeastSquaresStep::NormalRhs(rhs));
    }
    let control = normal.solve_points(points)?;
    patch(n, &control, domain)
}

/// The patch of bidegree (m, n) fitted to scattered data: with exactly (m + 1)(n + 1) points
/// the interpolant, from eq. (28) directly ([`interpolate_bezier_surface_scattered`]); with
/// more, the least-squares patch of eq. (29) ([`approximate_bezier_surface_by_normal_equations`]).
///
/// ```
/// use cagd_fit::approximate_bezier_surface;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// // The plane z = x + y sampled at five points is reproduced exactly.
/// let params = [(q!(0), q!(0)), (q!(1), q!(0)), (q!(0), q!(1)), (q!(1), q!(1)), (q!(1/3), q!(1/2))];
/// let a: Vec<Point<BigRational>> = params.iter()
///     .map(|(u, v)| Point::new(vec![u.clone(), v.clone(), u.clone() + v])).collect();
/// let s = approximate_bezier_surface(1, 1, &params, &a).unwrap();
/// assert_eq!(s.to_text(), "{(0, 0, 0), (0, 1, 1); (1, 0, 1), (1, 1, 2)}");
/// ```
pub fn approximate_bezier_surface<S: Scalar>(
    m: usize,
    n: usize,
    params: &[(S, S)],
    points: &[Point<S>],
) -> Result<BezierSurface<S>, FitError> {
    if points.len() == (m + 1) * (n + 1) {
        return Ok(interpolate_bezier_surface_scattered(m, n, params, points)?.surface);
    }
    if points.len() > (m + 1) * (n + 1)
        && check_scattered(params, points).is_ok()
        && check_distinct_values(m, n, params).is_ok()
    {
        let (local, domain) = local_pairs(params);
        if let Some(control) = crate::fast::least_squares(m, n, &local, points) {
            // the same mesh, from the normal equations on integers
            return patch(n, &control, domain);
        }
    }
    // the step-by-step path, which also names whatever is wrong with the data
    approximate_bezier_surface_by_normal_equations(m, n, params, points, &mut NoSteps)
}

/// The first `count` rows of the normal equations (29) of a least-squares fit, BᵗB and BᵗA
/// (row a of BᵗA is the point `Σ_k B_{k,a} a_k`), for a key that shows a big system by its first
/// rows: on integers, as [`approximate_bezier_surface`] forms them, when every number is
/// rational (each entry reduced once), else summed over the rows of B.
///
/// ```
/// use cagd_fit::{
///     approximate_bezier_surface_by_normal_equations, normal_equations_first_rows,
///     LeastSquaresStep,
/// };
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let params = [(q!(0), q!(0)), (q!(1), q!(0)), (q!(0), q!(1)), (q!(1), q!(1)), (q!(1/2), q!(1/2))];
/// let a: Vec<Point<BigRational>> = params.iter()
///     .map(|(u, v)| Point::new(vec![u.clone(), v.clone(), u.clone() * v])).collect();
/// let (btb, bta) = normal_equations_first_rows(1, 1, &params, &a, 2);
/// let mut whole = Vec::new();
/// approximate_bezier_surface_by_normal_equations(1, 1, &params, &a, &mut whole).unwrap();
/// let [_, LeastSquaresStep::NormalMatrix(normal), LeastSquaresStep::NormalRhs(rhs)] =
///     whole.as_slice() else { panic!() };
/// assert_eq!(btb, normal.to_rows()[..2]);
/// assert_eq!(bta, rhs[..2]);
/// ```
pub fn normal_equations_first_rows<S: Scalar>(
    m: usize,
    n: usize,
    params: &[(S, S)],
    points: &[Point<S>],
    count: usize,
) -> (Vec<Vec<S>>, Vec<Point<S>>) {
    let (local, _) = local_pairs(params);
    if let Some([normal, rhs]) = crate::fast::normal_equations_rows(m, n, &local, points, count) {
        return (normal, rhs.into_iter().map(Point::new).collect());
    }
    let b = bezier_surface_matrix(m, n, &local).to_rows();
    let unknowns = (m + 1) * (n + 1);
    let dim = points.first().map_or(0, Point::dim);
    let column = |a: usize| b.iter().map(move |row| row.get(a));
    let rows = 0..count.min(unknowns);
    let normal = rows
        .clone()
        .map(|a| {
            (0..unknowns)
                .map(|c| {
                    column(a)
                        .zip(column(c))
                        .fold(S::zero(), |acc, pair| match pair {
                            (Some(x), Some(y)) => acc + x.mul_ref(y),
                            _ => acc,
                        })
                })
                .collect()
        })
        .collect();
    let rhs = rows
        .map(|a| {
            column(a)
                .zip(points)
                .fold(Point::zero(dim), |acc, (x, p)| match x {
                    Some(x) => acc + p.scale(x),
                    None => acc,
                })
        })
        .collect();
    (normal, rhs)
}
