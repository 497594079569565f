//! Degree elevation of triangular patches.

use crate::bernstein::{int, multinomial};
use crate::index::{control_point_count, multi_indices, pos};
use crate::{TriangleError, TriangularPatch};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

impl<S: Scalar> TriangularPatch<S> {
    /// The same surface as a patch of degree n + 1:
    ///
    /// b^{n+1}_{ijk} = (i b_{i-1,j,k} + j b_{i,j-1,k} + k b_{i,j,k-1}) / (n + 1),
    ///
    /// (a term whose index would be negative is absent); it follows from
    /// B^n_{ijk} = ((i+1) B^{n+1}_{i+1,j,k} + (j+1) B^{n+1}_{i,j+1,k} + (k+1) B^{n+1}_{i,j,k+1})/(n+1),
    /// that is, from multiplying by r + s + t = 1.
    ///
    /// ```
    /// use cagd_linalg::Point;
    /// use cagd_scalar::BigRational;
    /// use cagd_triangle::TriangularPatch;
    /// let net = vec![
    ///     Point::from_ints(&[0, 0]),
    ///     Point::from_ints(&[2, 0]),
    ///     Point::from_ints(&[0, 2]),
    /// ];
    /// let patch = TriangularPatch::<BigRational>::try_new(1, net).unwrap();
    /// let up = patch.elevate_degree();
    /// assert_eq!(up.point(1, 1, 0).unwrap().to_text(), "(1, 0)");
    /// assert_eq!(up.point(0, 1, 1).unwrap().to_text(), "(1, 1)");
    /// ```
    pub fn elevate_degree(&self) -> Self {
        let n1 = self.degree() + 1;
        let inv = S::from_ratio(1, n1 as i64);
        let dim = self.dim();
        let points = multi_indices(n1)
            .map(|(i, j, k)| {
                let mut p = Point::zero(dim);
                if i > 0 {
                    p.add_scaled(self.at(j, k), &int::<S>(i));
                }
                if j > 0 {
                    p.add_scaled(self.at(j - 1, k), &int::<S>(j));
                }
                if k > 0 {
                    p.add_scaled(self.at(j, k - 1), &int::<S>(k));
                }
                p.scale(&inv)
            })
            .collect();
        TriangularPatch::from_valid(n1, points)
    }

    /// The same surface as a patch of degree n + e, in one step:
    ///
    /// b^{n+e}_{I} = Σ_{|J| = n, J ≤ I} [C(n; J) C(e; I - J) / C(n + e; I)] b_J,
    ///
    /// with multinomial coefficients C(n; i, j, k) = n!/(i! j! k!); it follows from
    /// B^n_J · B^e_K = C(n; J) C(e; K) / C(n + e; J + K) · B^{n+e}_{J+K} and
    /// (r + s + t)^e = 1. It equals e repetitions of [`TriangularPatch::elevate_degree`].
    ///
    /// Errors with [`TriangleError::DegreeTooLarge`] when n + e overflows.
    pub fn elevate_degree_by(&self, e: usize) -> Result<Self, TriangleError> {
        let n = self.degree();
        let too_large = || TriangleError::DegreeTooLarge {
            degree: format!("{n} + {e}"),
        };
        let ne = n.checked_add(e).ok_or_else(too_large)?;
        control_point_count(ne).ok_or_else(too_large)?;
        let dim = self.dim();
        let points = multi_indices(ne)
            .map(|(i, j, k)| {
                let mut p = Point::zero(dim);
                for (a, b, c) in multi_indices(n) {
                    if a <= i && b <= j && c <= k {
                        let coef =
                            multinomial::<S>(a, b, c) * multinomial::<S>(i - a, j - b, k - c);
                        if let Some(q) = self.points().get(pos(b, c)) {
                            p.add_scaled(q, &coef);
                        }
                    }
                }
                p.scale(&(S::one() / multinomial::<S>(i, j, k)))
            })
            .collect();
        Ok(TriangularPatch::from_valid(ne, points))
    }
}
