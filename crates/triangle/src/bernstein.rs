//! Barycentric Bernstein polynomials and evaluation by the Bernstein sum.

use crate::index::multi_indices;
use crate::{Barycentric, TriangularPatch};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// The integer `n` as a scalar. Degrees are small (a control net of degree n is stored in
/// memory), so the conversion to `i64` never wraps.
pub(crate) fn int<S: Scalar>(n: usize) -> S {
    S::from_i64(n as i64)
}

/// The binomial coefficient C(n, m) as a scalar, by C(n, l) = C(n, l - 1)(n - l + 1)/l.
/// Every partial value is an integer, so it is exact in every scalar type.
pub(crate) fn binomial<S: Scalar>(n: usize, m: usize) -> S {
    if m > n {
        return S::zero();
    }
    let m = m.min(n - m);
    let mut c = S::one();
    for l in 1..=m {
        c = c * int::<S>(n - l + 1) / int::<S>(l);
    }
    c
}

/// The multinomial coefficient n!/(i! j! k!) with n = i + j + k, as C(n, i) C(n - i, j).
///
/// ```
/// use cagd_scalar::{q, BigRational};
/// use cagd_triangle::multinomial;
/// assert_eq!(multinomial::<BigRational>(1, 1, 1), q!(6));
/// assert_eq!(multinomial::<BigRational>(2, 1, 0), q!(3));
/// assert_eq!(multinomial::<BigRational>(2, 2, 2), q!(90));
/// ```
pub fn multinomial<S: Scalar>(i: usize, j: usize, k: usize) -> S {
    binomial::<S>(i + j + k, i) * binomial::<S>(j + k, j)
}

/// The barycentric Bernstein polynomial of degree n = i + j + k at x = (r, s, t):
///
/// B^n_{ijk}(r, s, t) = n!/(i! j! k!) · r^i s^j t^k.
///
/// ```
/// use cagd_scalar::{q, BigRational};
/// use cagd_triangle::{bernstein, Barycentric};
/// let x = Barycentric::<BigRational>::centroid();
/// // 2!/(1! 1! 0!) (1/3)(1/3) = 2/9
/// assert_eq!(bernstein(1, 1, 0, &x), q!(2/9));
/// ```
pub fn bernstein<S: Scalar>(i: usize, j: usize, k: usize, x: &Barycentric<S>) -> S {
    multinomial::<S>(i, j, k) * x.r().powi(exp(i)) * &x.s().powi(exp(j)) * &x.t().powi(exp(k))
}

/// An exponent as `u32`; degrees never reach 2^32 (the net would not fit in memory), and a
/// saturated exponent would only make the value wrong, never panic.
fn exp(e: usize) -> u32 {
    u32::try_from(e).unwrap_or(u32::MAX)
}

/// All Bernstein polynomials B^n_{ijk}(x) of degree n, in the order of the control net
/// ([`crate::multi_indices`]). They are a partition of unity: their sum is (r + s + t)^n = 1.
///
/// ```
/// use cagd_scalar::{q, BigRational};
/// use cagd_triangle::{bernstein_basis, Barycentric};
/// let x = Barycentric::from_uv(q!(1/2), q!(1/4));
/// let b = bernstein_basis(2, &x);
/// let texts: Vec<String> = b.iter().map(|c| c.to_string()).collect();
/// assert_eq!(texts, ["1/16", "1/4", "1/8", "1/4", "1/4", "1/16"]);
/// assert_eq!(b.iter().fold(q!(0), |acc, c| acc + c), q!(1));
/// ```
pub fn bernstein_basis<S: Scalar>(degree: usize, x: &Barycentric<S>) -> Vec<S> {
    multi_indices(degree)
        .map(|(i, j, k)| bernstein(i, j, k, x))
        .collect()
}

impl<S: Scalar> TriangularPatch<S> {
    /// The point of the patch at x by the Bernstein sum
    ///
    /// b(x) = Σ_{i+j+k=n} b_{ijk} B^n_{ijk}(x).
    ///
    /// The route independent of [`TriangularPatch::evaluate`] (De Casteljau); both are exact and
    /// agree.
    pub fn evaluate_bernstein(&self, x: &Barycentric<S>) -> Point<S> {
        let basis = bernstein_basis(self.degree(), x);
        Point::combination(self.points(), &basis, self.dim())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, BigRational};

    #[test]
    fn binomials_and_multinomials() {
        assert_eq!(binomial::<BigRational>(5, 2), q!(10));
        assert_eq!(binomial::<BigRational>(5, 6), q!(0));
        assert_eq!(binomial::<f64>(10, 3), 120.0);
        assert_eq!(multinomial::<BigRational>(3, 0, 0), q!(1));
        assert_eq!(multinomial::<BigRational>(1, 2, 1), q!(12));
    }

    #[test]
    fn linear_bernstein_are_the_barycentric_coordinates() {
        let x = Barycentric::try_new(q!(1 / 2), q!(1 / 3), q!(1 / 6)).unwrap();
        assert_eq!(
            bernstein_basis(1, &x),
            vec![q!(1 / 2), q!(1 / 3), q!(1 / 6)]
        );
        assert_eq!(bernstein_basis(0, &x), vec![q!(1)]);
    }
}
