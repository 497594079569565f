//! Least-squares approximation by a B-spline curve with given knots.

use crate::data::check_data;
use crate::FitError;
use cagd_bspline::{basis_functions_at, BSplineCurve, BSplineError, KnotVector};
use cagd_linalg::{Matrix, NormalEquations, Point};
use cagd_scalar::Scalar;

/// The B-spline collocation matrix `B_ij = N_j^p(u_i)`: one row per parameter, one column per
/// control point of the knot vector. Every parameter must lie in the domain (the error names
/// the first that does not).
///
/// ```
/// use cagd_bspline::KnotVector;
/// use cagd_fit::bspline_matrix;
/// use cagd_scalar::q;
/// let u = KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap();
/// let b = bspline_matrix(&u, &[q!(0), q!(1/2), q!(1), q!(2)]).unwrap();
/// assert_eq!(b.to_text(), "1  0  0  0\n1/4  5/8  1/8  0\n0  1/2  1/2  0\n0  0  0  1");
/// ```
pub fn bspline_matrix<S: Scalar>(
    knots: &KnotVector<S>,
    params: &[S],
) -> Result<Matrix<S>, FitError> {
    let mut matrix = Matrix::zeros(params.len(), knots.control_point_count());
    for (i, u) in params.iter().enumerate() {
        let (first, values) = basis_functions_at(knots, u).map_err(|e| match e {
            BSplineError::OutsideDomain { t, start, end } => FitError::ParameterOutsideDomain {
                index: i,
                value: t,
                start,
                end,
            },
            e => FitError::BSpline(e),
        })?;
        for (k, v) in values.into_iter().enumerate() {
            matrix.set(i, first + k, v);
        }
    }
    Ok(matrix)
}

/// The B-spline curve with these knots closest to the data in the least-squares sense: the
/// control points d_j minimize `Σ_i |Σ_j N_j(u_i) d_j − a_i|²`, from the normal equations
/// `BᵗB D = Bᵗ A` (the notes' eq. (29) with B-spline functions) and `B_ij = N_j(u_i)`.
///
/// The errors name the cause: fewer data than control points; a control point d_j whose basis
/// function vanishes at every parameter (no parameter in its support); or, when the parameters
/// are badly placed (the Schoenberg–Whitney condition fails), a singular normal matrix with
/// the first column that has no pivot. With as many data as control points, satisfying the
/// condition, the curve interpolates the data.
///
/// ```
/// use cagd_bspline::KnotVector;
/// use cagd_fit::approximate_bspline;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// // A quadratic B-spline with the knots {0, 0, 1, 2, 2} through four points (as many as control points: the interpolant).
/// let u = KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap();
/// let a: Vec<Point<BigRational>> = [0, 1, 1, 0].iter().enumerate()
///     .map(|(i, &y)| Point::from_ints(&[i as i64, y])).collect();
/// let c = approximate_bspline(&u, &[q!(0), q!(1/2), q!(3/2), q!(2)], &a).unwrap();
/// let d: Vec<String> = c.points().iter().map(|p| p.to_text()).collect();
/// assert_eq!(d, ["(0, 0)", "(5/4, 4/3)", "(7/4, 4/3)", "(3, 0)"]);
/// ```
pub fn approximate_bspline<S: Scalar>(
    knots: &KnotVector<S>,
    params: &[S],
    points: &[Point<S>],
) -> Result<BSplineCurve<S>, FitError> {
    check_data(params, points)?;
    let unknowns = knots.control_point_count();
    if points.len() < unknowns {
        return Err(FitError::TooFewPoints {
            what: format!(
                "least squares with {unknowns} unknown control points (degree {})",
                knots.degree()
            ),
            needed: unknowns,
            found: points.len(),
        });
    }
    let matrix = bspline_matrix(knots, params)?;
    if let Some(j) = (0..unknowns).find(|&j| (0..matrix.rows()).all(|i| matrix.get(i, j).is_zero()))
    {
        let full = knots.full();
        let p = knots.degree();
        return Err(FitError::UndeterminedControlPoint {
            index: j,
            support: match (full.get(j), full.get(j + p + 1)) {
                (Some(a), Some(b)) => format!("[{}, {}]", a.to_text(), b.to_text()),
                _ => String::from("its support"),
            },
        });
    }
    let control = NormalEquations::new(&matrix)?.solve_points(points)?;
    Ok(BSplineCurve::try_new(knots.clone(), control)?)
}
