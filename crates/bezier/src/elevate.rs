//! Degree elevation of a Bézier curve.

use crate::polygon::{check_polygon, scalar_of};
use crate::BezierError;
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// The control points of the same curve written with degree n + r, by r steps of
///
/// `c_i^(1) = (i / (n+1)) c_{i-1} + (1 - i / (n+1)) c_i`, `i = 0..n+1`
///
/// (with `c_{-1}`, `c_{n+1}` not needed since their factors vanish). `r = 0` returns the
/// polygon unchanged.
///
/// ```
/// use cagd_bezier::elevate_degree;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let c: Vec<Point<BigRational>> =
///     vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2]), Point::from_ints(&[3, 3])];
/// let e = elevate_degree(&c, 1).unwrap();
/// let text: Vec<String> = e.iter().map(|p| p.to_text()).collect();
/// assert_eq!(text, ["(0, 0)", "(2/3, 4/3)", "(5/3, 7/3)", "(3, 3)"]);
/// ```
pub fn elevate_degree<S: Scalar>(
    points: &[Point<S>],
    r: usize,
) -> Result<Vec<Point<S>>, BezierError> {
    check_polygon(points)?;
    Ok(elevate_checked(points, r))
}

/// [`elevate_degree`] on a polygon already checked.
pub(crate) fn elevate_checked<S: Scalar>(points: &[Point<S>], r: usize) -> Vec<Point<S>> {
    let mut c = points.to_vec();
    for _ in 0..r {
        c = elevate_once(&c);
    }
    c
}

/// One step of degree elevation on a checked, non-empty polygon.
fn elevate_once<S: Scalar>(c: &[Point<S>]) -> Vec<Point<S>> {
    let m = c.len(); // n + 1
    let denom = scalar_of::<S>(m);
    let mut out = Vec::with_capacity(m + 1);
    for i in 0..=m {
        let p = match (i.checked_sub(1).and_then(|k| c.get(k)), c.get(i)) {
            (Some(prev), Some(cur)) => {
                let alpha = scalar_of::<S>(i) / &denom; // i/(n+1)
                cur.lerp(prev, &alpha)
            }
            (None, Some(cur)) => cur.clone(),
            (Some(prev), None) => prev.clone(),
            (None, None) => continue,
        };
        out.push(p);
    }
    out
}
