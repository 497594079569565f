//! The Bernstein polynomials and the Bernstein form of a Bézier curve.

use crate::polygon::{check_polygon, scalar_of};
use crate::BezierError;
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// The binomial coefficient `C(n, k)` as a scalar, `0` when `k > n`.
///
/// Computed as `∏_{j=1}^{k} (n - k + j) / j`; every partial product is an integer, so the
/// result is exact for the exact scalar types.
pub fn binomial<S: Scalar>(n: usize, k: usize) -> S {
    if k > n {
        return S::zero();
    }
    let k = k.min(n - k);
    let mut c = S::one();
    for j in 1..=k {
        c = c * scalar_of::<S>(n - k + j) / scalar_of::<S>(j);
    }
    c
}

/// The Bernstein polynomial `B_i^n(t) = C(n, i) t^i (1 - t)^(n - i)`; `0` when `i > n`.
///
/// ```
/// use cagd_bezier::bernstein;
/// use cagd_scalar::{q, Print};
/// assert_eq!(bernstein(1, 3, &q!(1/3)).to_text(), "4/9");
/// assert_eq!(bernstein(4, 3, &q!(1/3)).to_text(), "0");
/// ```
pub fn bernstein<S: Scalar>(i: usize, n: usize, t: &S) -> S {
    if i > n {
        return S::zero();
    }
    let s = S::one() - t;
    let exp = |k: usize| u32::try_from(k).unwrap_or(u32::MAX);
    binomial::<S>(n, i) * t.powi(exp(i)) * s.powi(exp(n - i))
}

/// All Bernstein polynomials of degree n at t: `[B_0^n(t), ..., B_n^n(t)]`.
///
/// Built with the recurrence `B_i^n = (1 - t) B_i^{n-1} + t B_{i-1}^{n-1}`, so no binomial
/// coefficient is formed. They sum to 1 (partition of unity).
///
/// ```
/// use cagd_bezier::bernstein_all;
/// use cagd_scalar::{q, Print};
/// let b: Vec<String> = bernstein_all(3, &q!(1/3)).iter().map(|x| x.to_text()).collect();
/// assert_eq!(b, ["8/27", "4/9", "2/9", "1/27"]);
/// ```
pub fn bernstein_all<S: Scalar>(n: usize, t: &S) -> Vec<S> {
    let s = S::one() - t;
    let mut b = Vec::with_capacity(n + 1);
    b.push(S::one());
    for _ in 0..n {
        let mut next = Vec::with_capacity(b.len() + 1);
        let mut carry = S::zero(); // t B_{i-1}^{k-1}
        for bi in &b {
            next.push(bi.mul_ref(&s) + &carry);
            carry = bi.mul_ref(t);
        }
        next.push(carry);
        b = next;
    }
    b
}

/// The point of a Bézier curve in Bernstein form: `c(t) = Σ_{i=0}^{n} B_i^n(t) c_i`.
///
/// The independent route to [`crate::de_casteljau`]; both agree exactly for every t.
///
/// ```
/// use cagd_bezier::bernstein_sum;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let c: Vec<Point<BigRational>> =
///     vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2]), Point::from_ints(&[3, 3])];
/// assert_eq!(bernstein_sum(&c, &q!(1/3)).unwrap().to_text(), "(7/9, 11/9)");
/// ```
pub fn bernstein_sum<S: Scalar>(points: &[Point<S>], t: &S) -> Result<Point<S>, BezierError> {
    let dim = check_polygon(points)?;
    let b = bernstein_all(points.len() - 1, t);
    Ok(Point::combination(points, &b, dim))
}
