//! Least-squares approximation of scattered data by a B-spline surface with given knot vectors
//! (the notes' eq. (29) with B-spline functions in place of Bernstein polynomials).

use crate::data::check_scattered;
use crate::{bspline_matrix, Direction, FitError, Support};
use cagd_bspline::KnotVector;
use cagd_linalg::{LinalgError, Matrix, NormalEquations, Point};
use cagd_scalar::Scalar;
use cagd_spline_surface::BSplineSurface;
use cagd_surface::Mesh;

/// The collocation matrix of a B-spline surface at scattered parameters: one row per
/// (u_k, v_k), one column per control point d_00, d_01, ..., row by row of the mesh,
///
/// `B_{k, i C + j} = N_i(u_k) N_j(v_k)`,
///
/// C the number of columns of the mesh (control points of `knots_v`). Every parameter must lie
/// in the domain of its knot vector (the error names the first that does not).
///
/// ```
/// use cagd_bspline::KnotVector;
/// use cagd_fit::bspline_surface_matrix;
/// use cagd_scalar::q;
/// let u = KnotVector::clamped(1, &[q!(0), q!(1)]).unwrap();
/// let v = KnotVector::clamped(1, &[q!(0), q!(1/2), q!(1)]).unwrap();
/// let b = bspline_surface_matrix(&u, &v, &[(q!(1/4), q!(3/4))]).unwrap();
/// assert_eq!(b.to_text(), "0  3/8  3/8  0  1/8  1/8");
/// ```
pub fn bspline_surface_matrix<S: Scalar>(
    knots_u: &KnotVector<S>,
    knots_v: &KnotVector<S>,
    params: &[(S, S)],
) -> Result<Matrix<S>, FitError> {
    let us: Vec<S> = params.iter().map(|p| p.0.clone()).collect();
    let vs: Vec<S> = params.iter().map(|p| p.1.clone()).collect();
    let bu = direction_matrix(Direction::U, knots_u, &us)?;
    let bv = direction_matrix(Direction::V, knots_v, &vs)?;
    let cols = bv.cols();
    Ok(Matrix::from_fn(params.len(), bu.cols() * cols, |k, c| {
        bu.get(k, c / cols).mul_ref(bv.get(k, c % cols))
    }))
}

/// [`bspline_matrix`] of one direction, with errors that name the direction.
fn direction_matrix<S: Scalar>(
    direction: Direction,
    knots: &KnotVector<S>,
    params: &[S],
) -> Result<Matrix<S>, FitError> {
    bspline_matrix(knots, params).map_err(|e| match e {
        FitError::ParameterOutsideDomain {
            index,
            value,
            start,
            end,
        } => FitError::SurfaceParameterOutsideDomain {
            direction,
            index,
            value,
            start,
            end,
        },
        e => e,
    })
}

/// The B-spline surface with these knot vectors closest to scattered data in the
/// least-squares sense: the mesh d_ij minimizes `Σ_k |c(u_k, v_k) − a_k|²`, from the normal
/// equations `BᵗB D = BᵗA` (the notes' eq. (29)) with B of [`bspline_surface_matrix`].
///
/// The errors name the cause: fewer data than control points; a parameter outside the domain;
/// a control point d_ij whose basis function N_i(u) N_j(v) vanishes at every parameter; or a
/// singular BᵗB for parameters badly placed ([`FitError::UndeterminedMesh`]).
///
/// ```
/// use cagd_bspline::KnotVector;
/// use cagd_fit::approximate_bspline_surface;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational, FieldOps, Print};
/// // The plane z = u + 2v is in the space of bilinear splines: least squares recovers it.
/// let u = KnotVector::clamped(1, &[q!(0), q!(1)]).unwrap();
/// let v = KnotVector::clamped(1, &[q!(0), q!(1/2), q!(1)]).unwrap();
/// let params: Vec<(BigRational, BigRational)> = (0..3)
///     .flat_map(|i| (0..3).map(move |j| (BigRational::from_ratio(i, 2), BigRational::from_ratio(j, 2))))
///     .collect();
/// let a: Vec<Point<BigRational>> =
///     params.iter().map(|(s, t)| Point::new(vec![s.clone() + t + t])).collect();
/// let s = approximate_bspline_surface(&u, &v, &params, &a).unwrap();
/// assert_eq!(s.mesh().to_text(), "{(0), (1), (2); (1), (2), (3)}");
/// ```
pub fn approximate_bspline_surface<S: Scalar>(
    knots_u: &KnotVector<S>,
    knots_v: &KnotVector<S>,
    params: &[(S, S)],
    points: &[Point<S>],
) -> Result<BSplineSurface<S>, FitError> {
    check_scattered(params, points)?;
    let (rows, cols) = (knots_u.control_point_count(), knots_v.control_point_count());
    let (p, q) = (knots_u.degree(), knots_v.degree());
    let what = || crate::Fitted::SplineSurface { p, q, rows, cols };
    if points.len() < rows * cols {
        return Err(FitError::TooFewPoints {
            what: crate::Fitted::LeastSquaresSplineSurface { p, q, rows, cols },
            needed: rows * cols,
            found: points.len(),
        });
    }
    let b = bspline_surface_matrix(knots_u, knots_v, params)?;
    if let Some(c) = (0..b.cols()).find(|&c| (0..b.rows()).all(|k| b.get(k, c).is_zero())) {
        let (i, j) = (c / cols, c % cols);
        return Err(FitError::UndeterminedSurfaceControlPoint {
            row: i,
            col: j,
            support: (support(knots_u, i), support(knots_v, j)),
        });
    }
    let normal = NormalEquations::new(&b).map_err(|e| match e {
        LinalgError::Singular { detail } => FitError::UndeterminedMesh {
            what: what(),
            detail,
        },
        e => FitError::Linalg(e),
    })?;
    let control = normal.solve_points(points)?;
    let mesh = Mesh::mesh(control.chunks(cols).map(<[_]>::to_vec).collect())?;
    Ok(BSplineSurface::try_new(
        knots_u.clone(),
        knots_v.clone(),
        mesh,
    )?)
}

/// The support [t_i, t_{i+p+1}] of N_i (full convention).
fn support<S: Scalar>(knots: &KnotVector<S>, i: usize) -> Support {
    let full = knots.full();
    let end = i + knots.degree() + 1;
    match (full.get(i), full.get(end)) {
        (Some(a), Some(b)) => Support::Interval {
            start: a.to_text(),
            end: b.to_text(),
        },
        _ => Support::Outside,
    }
}
