//! Validation of control polygons, shared by every algorithm of the crate.

use crate::{BezierError, Rule};
use cagd_linalg::Point;
use cagd_scalar::Scalar;
use std::cmp::Ordering;

/// Checks a control polygon `c_0, ..., c_n`: not empty, every point of the same dimension.
/// Returns that dimension.
///
/// ```
/// use cagd_bezier::check_polygon;
/// use cagd_linalg::Point;
/// use cagd_scalar::BigRational;
/// let ok: Vec<Point<BigRational>> = vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2])];
/// assert_eq!(check_polygon(&ok).unwrap(), 2);
/// let bad: Vec<Point<BigRational>> = vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2, 3])];
/// assert_eq!(
///     check_polygon(&bad).unwrap_err().to_string(),
///     "control point 1 has dimension 3 but control point 0 has dimension 2"
/// );
/// ```
pub fn check_polygon<S: Scalar>(points: &[Point<S>]) -> Result<usize, BezierError> {
    let first = points.first().ok_or(BezierError::EmptyPolygon)?;
    let expected = first.dim();
    for (index, p) in points.iter().enumerate() {
        if p.dim() != expected {
            return Err(BezierError::DimensionMismatch {
                index,
                expected,
                found: p.dim(),
            });
        }
    }
    Ok(expected)
}

/// The interval [a, b] must have a < b (decided: an order that cannot be decided is an error).
pub(crate) fn check_interval<S: Scalar>(a: &S, b: &S) -> Result<(), BezierError> {
    match a.compare(b) {
        Some(Ordering::Less) => Ok(()),
        // in letters (an exact value without a decided sign)
        None if S::is_exact() => Err(BezierError::SignUnknown {
            expression: b.sub_ref(a).to_text(),
            rule: Rule::IncreasingInterval {
                a: a.to_text(),
                b: b.to_text(),
            },
        }),
        _ => Err(BezierError::DegenerateInterval {
            a: a.to_text(),
            b: b.to_text(),
        }),
    }
}

/// One level of De Casteljau's algorithm in place: `c_i ← (1 - t) c_i + t c_{i+1}` for every
/// point but the last, which is then dropped (n + 1 points become n).
pub(crate) fn lerp_level<S: Scalar>(work: &mut Vec<Point<S>>, t: &S) {
    let mut rest = work.as_mut_slice();
    while let Some((c_i, tail)) = rest.split_first_mut() {
        if let Some(c_next) = tail.first() {
            *c_i = c_i.lerp(c_next, t);
        }
        rest = tail;
    }
    work.pop();
}

/// `usize` as a scalar (polygon sizes are far below `i64::MAX`).
pub(crate) fn scalar_of<S: Scalar>(n: usize) -> S {
    S::from_i64(i64::try_from(n).unwrap_or(i64::MAX))
}
