//! Least-squares approximation by a B-spline curve with given knots.

use crate::data::{check_data, check_increasing, check_vector};
use crate::{FitError, Support};
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
            what: crate::Fitted::LeastSquaresUnknowns {
                unknowns,
                degree: knots.degree(),
            },
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
                (Some(a), Some(b)) => Support::Interval {
                    start: a.to_text(),
                    end: b.to_text(),
                },
                _ => Support::Outside,
            },
        });
    }
    let control = NormalEquations::new(&matrix)?.solve_points(points)?;
    Ok(BSplineCurve::try_new(knots.clone(), control)?)
}

/// The linear system of a B-spline interpolant with given end derivatives, for step-by-step
/// answers ([`end_derivative_system`]).
#[derive(Clone, Debug, PartialEq)]
pub struct EndDerivativeSystem<S: Scalar> {
    /// The knots: t_0 and t_n p + 1 times, inside the averages of eq. (9.22).
    pub knots: KnotVector<S>,
    /// The (n + 3) × (n + 3) matrix, rows in order: Q_0, the start derivative, Q_1, ...,
    /// Q_{n−1}, the end derivative, Q_n.
    pub matrix: Matrix<S>,
    /// The right-hand side: Q_0, (u_{p+1} − t_0)/p · D_0, Q_1, ..., Q_{n−1},
    /// (t_n − u_{n+2})/p · D_n, Q_n.
    pub rhs: Vec<Point<S>>,
}

/// The linear system of the global B-spline interpolant of degree p through Q_0, ..., Q_n at
/// t_0 < ... < t_n with the first derivatives D_0 at t_0 and D_n at t_n (Piegl and Tiller
/// §9.2.2): n + 3 control points P_0, ..., P_{n+2} on the knots t_0 and t_n p + 1 times and,
/// inside, `u_{j+p+1} = (t_j + ... + t_{j+p−1}) / p`, j = 0, ..., n − p + 1 (eq. (9.22)).
/// The rows are `C(t_k) = Σ_i N_i^p(t_k) P_i = Q_k` (eq. (9.7)) and, since
/// `C'(t_0) = p/(u_{p+1} − t_0) (P_1 − P_0)` and `C'(t_n) = p/(t_n − u_{n+2}) (P_{n+2} − P_{n+1})`,
/// `−P_0 + P_1 = (u_{p+1} − t_0)/p · D_0` and `−P_{n+1} + P_{n+2} = (t_n − u_{n+2})/p · D_n`
/// (eqs. (9.19)-(9.20)).
///
/// The errors name the cause: fewer than two points, parameters that do not increase
/// strictly, a degree outside 2..=n + 2, or a derivative of another dimension than the data.
pub fn end_derivative_system<S: Scalar>(
    degree: usize,
    params: &[S],
    points: &[Point<S>],
    start: &Point<S>,
    end: &Point<S>,
) -> Result<EndDerivativeSystem<S>, FitError> {
    let dim = check_data(params, points)?;
    let what = crate::Fitted::EndDerivatives;
    let (Some(first), Some(last)) = (params.first(), params.last()) else {
        return Err(FitError::NoData);
    };
    if points.len() < 2 {
        return Err(FitError::TooFewPoints {
            what: what.clone(),
            needed: 2,
            found: points.len(),
        });
    }
    check_increasing(params)?;
    check_vector(start, dim, crate::Datum::StartDerivative)?;
    check_vector(end, dim, crate::Datum::EndDerivative)?;
    let n = points.len() - 1;
    let p = degree;
    if p < 2 || p > n + 2 {
        return Err(FitError::DegreeOutOfRange {
            what,
            degree: p,
            points: points.len(),
            low: 2,
            high: n + 2,
        });
    }
    let pp = S::from_i64(i64::try_from(p).unwrap_or(i64::MAX));
    let mut notes = vec![first.clone(); p];
    for j in 0..n + 2 - p {
        let sum = params.iter().skip(j).take(p).fold(S::zero(), |a, t| a + t);
        notes.push(sum / &pp);
    }
    notes.extend(std::iter::repeat_n(last.clone(), p));
    let knots = KnotVector::from_notes(notes, p)?;
    let full = knots.full();
    let first_step = full.get(p + 1).map_or_else(S::zero, |u| u.clone() - first);
    let last_step = full.get(n + 2).map_or_else(S::zero, |u| last.clone() - u);
    let size = n + 3;
    let mut matrix = Matrix::zeros(size, size);
    let mut rhs = vec![Point::zero(dim); size];
    for (k, (t, q)) in params.iter().zip(points).enumerate() {
        let row = match k {
            0 => 0,
            k if k == n => n + 2,
            k => k + 1,
        };
        let (at, values) = basis_functions_at(&knots, t)?;
        for (i, v) in values.into_iter().enumerate() {
            matrix.set(row, at + i, v);
        }
        if let Some(r) = rhs.get_mut(row) {
            *r = q.clone();
        }
    }
    for (row, step, d) in [(1, first_step, start), (n + 1, last_step, end)] {
        let (before, after) = if row == 1 { (0, 1) } else { (n + 1, n + 2) };
        matrix.set(row, before, -S::one());
        matrix.set(row, after, S::one());
        if let Some(r) = rhs.get_mut(row) {
            *r = d.scale(&(step / &pp));
        }
    }
    Ok(EndDerivativeSystem { knots, matrix, rhs })
}

/// The global B-spline interpolant of degree p through Q_0, ..., Q_n at t_0 < ... < t_n with
/// the end derivatives C'(t_0) = D_0 and C'(t_n) = D_n (Piegl and Tiller §9.2.2): the
/// control points P_0, ..., P_{n+2} solve the system of [`end_derivative_system`].
///
/// ```
/// use cagd_fit::interpolate_bspline_end_derivatives;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// // A quadratic through (0, 0), (1, 1), (2, 0) at 0, 1, 2, leaving along (1, 1) and arriving along (1, -1).
/// let a: Vec<Point<BigRational>> = [[0, 0], [1, 1], [2, 0]].iter().map(|p| Point::from_ints(p)).collect();
/// let c = interpolate_bspline_end_derivatives(2, &[q!(0), q!(1), q!(2)], &a,
///     &Point::from_ints(&[1, 1]), &Point::from_ints(&[1, -1])).unwrap();
/// // Knots {0, 0, 0, 1/2, 3/2, 2, 2, 2}; P_1 − P_0 = (1/2)/2 · D_0 and P_4 − P_3 = (1/2)/2 · D_n.
/// let d: Vec<String> = c.points().iter().map(|p| p.to_text()).collect();
/// assert_eq!(d, ["(0, 0)", "(1/4, 1/4)", "(1, 11/8)", "(7/4, 1/4)", "(2, 0)"]);
/// assert_eq!(c.eval(&q!(1)).unwrap().to_text(), "(1, 1)");
/// assert_eq!(c.derivatives(&q!(2), 1).unwrap()[1].to_text(), "(1, -1)");
/// ```
pub fn interpolate_bspline_end_derivatives<S: Scalar>(
    degree: usize,
    params: &[S],
    points: &[Point<S>],
    start: &Point<S>,
    end: &Point<S>,
) -> Result<BSplineCurve<S>, FitError> {
    let system = end_derivative_system(degree, params, points, start, end)?;
    let control = cagd_linalg::solve_points(&system.matrix, &system.rhs)?;
    Ok(BSplineCurve::try_new(system.knots, control)?)
}
