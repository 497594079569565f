//! Bézier curves through data points (interpolation) and closest to them (least squares).

use crate::data::{check_data, check_distinct, count_distinct};
use crate::FitError;
use cagd_bezier::{bernstein_all, BezierCurve};
use cagd_linalg::{Factorization, Matrix, NormalEquations, Point};
use cagd_scalar::Scalar;

/// The Bernstein collocation matrix of degree n at the parameters u_0, ..., u_M:
/// `B_ij = B_j^n(u_i)`, one row per parameter, n + 1 columns (the notes' B_U of eq. (27)).
///
/// ```
/// use cagd_fit::bernstein_matrix;
/// use cagd_scalar::q;
/// let b = bernstein_matrix(3, &[q!(0), q!(1/3), q!(2/3), q!(1)]);
/// assert_eq!(b.to_text(), "1  0  0  0\n8/27  4/9  2/9  1/27\n1/27  2/9  4/9  8/27\n0  0  0  1");
/// ```
pub fn bernstein_matrix<S: Scalar>(degree: usize, params: &[S]) -> Matrix<S> {
    let rows: Vec<Vec<S>> = params.iter().map(|u| bernstein_all(degree, u)).collect();
    Matrix::from_fn(params.len(), degree + 1, |i, j| {
        rows.get(i)
            .and_then(|r| r.get(j))
            .cloned()
            .unwrap_or_else(S::zero)
    })
}

/// The domain [a, b] of a Bézier fit: [0, 1] when every parameter lies in [0, 1] (the notes'
/// case), otherwise [min u_i, max u_i] (so that the curve can be evaluated at every parameter).
pub fn bezier_domain<S: Scalar>(params: &[S]) -> (S, S) {
    let (zero, one) = (S::zero(), S::one());
    if params.iter().all(|u| *u >= zero && *u <= one) {
        return (zero, one);
    }
    let mut lo = params.first().cloned().unwrap_or_else(S::zero);
    let mut hi = lo.clone();
    for u in params {
        if *u < lo {
            lo = u.clone();
        }
        if *u > hi {
            hi = u.clone();
        }
    }
    if lo == hi {
        hi = lo.clone() + S::one();
    }
    (lo, hi)
}

/// The local parameters (u_i − a)/(b − a) on the domain [a, b] of [`bezier_domain`], and the
/// domain.
pub(crate) fn local_parameters<S: Scalar>(params: &[S]) -> (Vec<S>, S, S) {
    let (a, b) = bezier_domain(params);
    let h = b.sub_ref(&a);
    let local = if a.is_zero() && h == S::one() {
        params.to_vec()
    } else {
        params.iter().map(|u| u.sub_ref(&a) / &h).collect()
    };
    (local, a, b)
}

fn curve<S: Scalar>(points: Vec<Point<S>>, a: S, b: S) -> Result<BezierCurve<S>, FitError> {
    let c = BezierCurve::try_new(points)?;
    if a.is_zero() && b == S::one() {
        Ok(c)
    } else {
        Ok(c.with_domain(a, b)?)
    }
}

/// The Bézier curve of degree n through n + 1 points a_i at the parameters u_i:
/// `c(u_i) = Σ_j B_j^n(u_i) c_j = a_i`, solved exactly: for rational data on integers with the
/// inverse of the Bernstein–Vandermonde matrix written down from its structure (the integer
/// kernel of [`crate::interpolate_bezier_surface`]), otherwise one system per coordinate with
/// one factorization of the Bernstein matrix ([`bernstein_matrix`]).
///
/// The parameters may come in any order but must be distinct (else the error names the two
/// equal ones). The domain is [0, 1] when all parameters lie there, else [min u_i, max u_i]
/// ([`bezier_domain`]).
///
/// ```
/// use cagd_fit::interpolate_bezier;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// // The notes' row v = 1/3 of the bidegree (2, 3) example: c(0), c(1/2), c(1).
/// let a: Vec<Point<BigRational>> = vec![
///     Point::from_ints(&[1, 0, 1]), Point::from_ints(&[1, 1, 2]), Point::from_ints(&[1, 2, 1]),
/// ];
/// let c = interpolate_bezier(&[q!(0), q!(1/2), q!(1)], &a).unwrap();
/// assert_eq!(c.to_text(), "(1, 0, 1), (1, 1, 3), (1, 2, 1)");
/// let e = interpolate_bezier(&[q!(0), q!(1/2), q!(1/2)], &a).unwrap_err();
/// assert!(e.to_string().starts_with("singular: parameters u_1 and u_2 are equal (both 1/2)"));
/// ```
pub fn interpolate_bezier<S: Scalar>(
    params: &[S],
    points: &[Point<S>],
) -> Result<BezierCurve<S>, FitError> {
    check_data(params, points)?;
    check_distinct(params)?;
    let (local, a, b) = local_parameters(params);
    let data: Vec<&Point<S>> = points.iter().collect();
    if let Some(control) =
        crate::fast::interpolate_grid(&local, &[S::zero()], points.len(), 1, &data)
    {
        // the same control points, C = B⁻¹ A with B⁻¹ from its Bernstein–Vandermonde structure
        // (a patch of degree 0 in v)
        return curve(control, a, b);
    }
    let matrix = bernstein_matrix(points.len() - 1, &local);
    let control = Factorization::new(&matrix)?.solve_points(points)?;
    curve(control, a, b)
}

/// The Bézier curve of degree n closest to the data in the least-squares sense: the control
/// points C minimize `Σ_i |c(u_i) − a_i|²`, from the normal equations `BᵗB C = Bᵗ A`
/// (the notes' eq. (29)) with `B_ij = B_j^n(u_i)`. For rational data the normal equations are
/// formed and solved on integers (the kernel of [`crate::approximate_bezier_surface`]:
/// fraction-free or multimodular elimination), otherwise by [`NormalEquations`].
///
/// Needs at least n + 1 points with n + 1 distinct parameters (otherwise the normal matrix is
/// singular, and the error says which). With exactly n + 1 points it is the interpolant.
///
/// ```
/// use cagd_fit::approximate_bezier;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// // The line closest to (0, 0), (1, 1), (2, 1) at u = 0, 1/2, 1.
/// let a: Vec<Point<BigRational>> =
///     vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 1]), Point::from_ints(&[2, 1])];
/// let c = approximate_bezier(1, &[q!(0), q!(1/2), q!(1)], &a).unwrap();
/// assert_eq!(c.to_text(), "(0, 1/6), (2, 7/6)");
/// ```
pub fn approximate_bezier<S: Scalar>(
    degree: usize,
    params: &[S],
    points: &[Point<S>],
) -> Result<BezierCurve<S>, FitError> {
    check_data(params, points)?;
    if points.len() < degree + 1 {
        return Err(FitError::TooFewPoints {
            what: crate::Fitted::LeastSquaresDegree {
                degree,
                unknowns: degree + 1,
            },
            needed: degree + 1,
            found: points.len(),
        });
    }
    let distinct = count_distinct(params);
    if distinct < degree + 1 {
        return Err(FitError::TooFewDistinctParameters {
            degree,
            found: distinct,
        });
    }
    let (local, a, b) = local_parameters(params);
    if points.len() > degree + 1 {
        let pairs: Vec<(S, S)> = local.iter().map(|u| (u.clone(), S::zero())).collect();
        if let Some(control) = crate::fast::least_squares(degree, 0, &pairs, points) {
            // the same control points, from the normal equations on integers (a patch of
            // degree 0 in v)
            return curve(control, a, b);
        }
    }
    let matrix = bernstein_matrix(degree, &local);
    let control = NormalEquations::new(&matrix)?.solve_points(points)?;
    curve(control, a, b)
}
