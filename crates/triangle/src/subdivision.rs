//! Subdivision: the patch over a sub-triangle, and the split at a point into three patches.

use crate::index::{multi_indices, pos};
use crate::{Barycentric, TriangularPatch};
use cagd_record::NoSteps;
use cagd_scalar::Scalar;

impl<S: Scalar> TriangularPatch<S> {
    /// The patch over the sub-triangle with vertices a, b, c of the domain (given in barycentric
    /// coordinates), reparametrized so that its vertices e1, e2, e3 go to a, b, c: its control
    /// points are values of the blossom,
    ///
    /// c_{ijk} = b[a^i, b^j, c^k]  (a repeated i times, b j times, c k times),
    ///
    /// and c(ρ, σ, τ) = b(ρ a + σ b + τ c). The triangle may extend outside the domain (the
    /// patch is then extrapolated) or be degenerate (the patch then traces a curve or a point).
    ///
    /// ```
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational};
    /// use cagd_triangle::{Barycentric, TriangularPatch};
    /// let net: Vec<Point<BigRational>> = (0..6).map(|m| Point::from_ints(&[m])).collect();
    /// let patch = TriangularPatch::try_new(2, net).unwrap();
    /// let (a, b, c) = (Barycentric::e1(), Barycentric::e2(), Barycentric::centroid());
    /// let sub = patch.restrict(&a, &b, &c);
    /// let x = Barycentric::try_new(q!(1/2), q!(1/4), q!(1/4)).unwrap();
    /// // x in the sub-triangle is 1/2 a + 1/4 b + 1/4 c = (7/12, 4/12, 1/12) in the domain
    /// let y = Barycentric::try_new(q!(7/12), q!(1/3), q!(1/12)).unwrap();
    /// assert_eq!(sub.evaluate(&x), patch.evaluate(&y));
    /// ```
    pub fn restrict(&self, a: &Barycentric<S>, b: &Barycentric<S>, c: &Barycentric<S>) -> Self {
        let points = multi_indices(self.degree())
            .map(|(i, j, k)| {
                let args = std::iter::repeat_n(a.coords(), i)
                    .chain(std::iter::repeat_n(b.coords(), j))
                    .chain(std::iter::repeat_n(c.coords(), k));
                self.blossom_triples(args, &mut NoSteps)
            })
            .collect();
        TriangularPatch::from_valid(self.degree(), points)
    }

    /// The split of the patch at the point x into the three patches over the triangles
    /// (x, e2, e3), (e1, x, e3) and (e1, e2, x) (vertex m replaced by x), read off the levels of
    /// De Casteljau at x:
    ///
    /// - over (x, e2, e3): c_{ijk} = b^i_{0,j,k}(x),
    /// - over (e1, x, e3): c_{ijk} = b^j_{i,0,k}(x),
    /// - over (e1, e2, x): c_{ijk} = b^k_{i,j,0}(x),
    ///
    /// since b^l_{ijk}(x) = b[x^l, e1^i, e2^j, e3^k]. Each equals
    /// [`TriangularPatch::restrict`] to its triangle. For x inside the domain the three patches
    /// cover the patch; for x on an edge one of them is degenerate.
    pub fn split(&self, x: &Barycentric<S>) -> [Self; 3] {
        let n = self.degree();
        let steps = self.de_casteljau(x);
        let levels = steps.levels();
        let build = |pick: fn(usize, usize, usize) -> (usize, usize)| {
            let points = multi_indices(n)
                .map(|(i, j, k)| {
                    let (l, p) = pick(i, j, k);
                    // every level of the De Casteljau triangle holds these positions
                    levels
                        .get(l)
                        .and_then(|level| level.get(p))
                        .cloned()
                        .unwrap_or_else(|| cagd_linalg::Point::zero(self.dim()))
                })
                .collect();
            TriangularPatch::from_valid(n, points)
        };
        [
            build(|i, j, k| (i, pos(j, k))),
            build(|_, j, k| (j, pos(0, k))),
            build(|_, j, k| (k, pos(j, 0))),
        ]
    }
}
