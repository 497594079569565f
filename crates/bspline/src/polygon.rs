//! Validation of a control polygon against its knot vector, shared by every algorithm.

use crate::{BSplineError, KnotVector};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// Checks the control points `d_0, ..., d_{n-1}` of a B-spline curve: as many as the knot
/// vector is made for, all of the same dimension. Returns that dimension.
///
/// ```
/// use cagd_bspline::{check_control_points, KnotVector};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let u = KnotVector::clamped(1, &[q!(0), q!(1)]).unwrap();
/// let d: Vec<Point<BigRational>> = vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2])];
/// assert_eq!(check_control_points(&u, &d).unwrap(), 2);
/// assert_eq!(
///     check_control_points(&u, &d[..1]).unwrap_err().to_string(),
///     "the knot vector is made for 2 control points, but 1 were given"
/// );
/// ```
pub fn check_control_points<S: Scalar>(
    knots: &KnotVector<S>,
    points: &[Point<S>],
) -> Result<usize, BSplineError> {
    if points.len() != knots.control_point_count() {
        return Err(BSplineError::PointCount {
            expected: knots.control_point_count(),
            found: points.len(),
        });
    }
    let expected = points.first().map_or(0, Point::dim);
    for (index, p) in points.iter().enumerate() {
        if p.dim() != expected {
            return Err(BSplineError::DimensionMismatch {
                index,
                expected,
                found: p.dim(),
            });
        }
    }
    Ok(expected)
}
