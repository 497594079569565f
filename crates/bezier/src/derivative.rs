//! Forward differences and the control points of the derivatives (the hodograph).

use crate::polygon::{check_polygon, scalar_of};
use crate::BezierError;
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// The forward differences `Δ^r c_i`, `i = 0..n-r`, with `Δ^0 c_i = c_i` and
/// `Δ^r c_i = Δ^{r-1} c_{i+1} - Δ^{r-1} c_i` (equivalently `Σ_j (-1)^{r-j} C(r, j) c_{i+j}`).
///
/// When `r > n` there is no index i with `0 ≤ i ≤ n - r`, and the list is empty.
///
/// ```
/// use cagd_bezier::forward_differences;
/// use cagd_linalg::Point;
/// use cagd_scalar::BigRational;
/// let c: Vec<Point<BigRational>> =
///     vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2]), Point::from_ints(&[3, 3])];
/// let d1: Vec<String> = forward_differences(&c, 1).unwrap().iter().map(|p| p.to_text()).collect();
/// assert_eq!(d1, ["(1, 2)", "(2, 1)"]);
/// let d2: Vec<String> = forward_differences(&c, 2).unwrap().iter().map(|p| p.to_text()).collect();
/// assert_eq!(d2, ["(1, -1)"]);
/// assert!(forward_differences(&c, 3).unwrap().is_empty());
/// ```
pub fn forward_differences<S: Scalar>(
    points: &[Point<S>],
    r: usize,
) -> Result<Vec<Point<S>>, BezierError> {
    check_polygon(points)?;
    Ok(differences_checked(points, r))
}

/// [`forward_differences`] on a polygon already checked.
pub(crate) fn differences_checked<S: Scalar>(points: &[Point<S>], r: usize) -> Vec<Point<S>> {
    let mut d = points.to_vec();
    for _ in 0..r {
        if d.is_empty() {
            break;
        }
        d = d.iter().zip(d.iter().skip(1)).map(|(a, b)| b - a).collect();
    }
    d
}

/// The control points of the r-th derivative of the degree-n curve (a curve of degree n - r):
///
/// `c^(r)(t) = n!/(n-r)! Σ_{i=0}^{n-r} Δ^r c_i B_i^{n-r}(t)`,
///
/// i.e. the points `n!/(n-r)! Δ^r c_i`. For r = 1 they are the hodograph `n (c_{i+1} - c_i)`.
/// They are vectors (differences of points). When `r > n` the derivative is identically zero:
/// the result is the single zero vector (a degree-0 curve), so it can still be evaluated.
///
/// ```
/// use cagd_bezier::derivative_points;
/// use cagd_linalg::Point;
/// use cagd_scalar::BigRational;
/// let c: Vec<Point<BigRational>> =
///     vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2]), Point::from_ints(&[3, 3])];
/// let h: Vec<String> = derivative_points(&c, 1).unwrap().iter().map(|p| p.to_text()).collect();
/// assert_eq!(h, ["(2, 4)", "(4, 2)"]);
/// let z: Vec<String> = derivative_points(&c, 5).unwrap().iter().map(|p| p.to_text()).collect();
/// assert_eq!(z, ["(0, 0)"]);
/// ```
pub fn derivative_points<S: Scalar>(
    points: &[Point<S>],
    r: usize,
) -> Result<Vec<Point<S>>, BezierError> {
    let dim = check_polygon(points)?;
    Ok(derivative_checked(points, r, dim))
}

/// [`derivative_points`] on a polygon already checked, of dimension `dim`.
pub(crate) fn derivative_checked<S: Scalar>(
    points: &[Point<S>],
    r: usize,
    dim: usize,
) -> Vec<Point<S>> {
    let n = points.len().saturating_sub(1);
    if r > n || points.is_empty() {
        return vec![Point::zero(dim)];
    }
    // n!/(n-r)! = n (n-1) ... (n-r+1)
    let factor = ((n - r + 1)..=n).fold(S::one(), |acc, k| acc * scalar_of::<S>(k));
    differences_checked(points, r)
        .iter()
        .map(|d| d.scale(&factor))
        .collect()
}
