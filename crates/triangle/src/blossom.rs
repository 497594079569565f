//! The blossom (polar form) of a triangular patch.

use crate::de_casteljau::Level;
use crate::{Barycentric, TriangleError, TriangularPatch};
use cagd_linalg::Point;
use cagd_record::{NoSteps, Record};
use cagd_scalar::Scalar;

impl<S: Scalar> TriangularPatch<S> {
    /// The blossom (polar form) b[x_1, ..., x_n] of the patch: the unique function of n
    /// barycentric points that is
    ///
    /// - symmetric in its arguments,
    /// - affine in each argument,
    /// - the patch on the diagonal: b[x, ..., x] = b(x),
    ///
    /// computed by De Casteljau with the argument x_l at level l. The control points are its
    /// values at the vertices, b_{ijk} = b[e1^i, e2^j, e3^k] (e1 repeated i times, ...).
    ///
    /// ```
    /// use cagd_linalg::Point;
    /// use cagd_scalar::BigRational;
    /// use cagd_triangle::{Barycentric, TriangularPatch};
    /// let net: Vec<Point<BigRational>> = (0..6).map(|m| Point::from_ints(&[m * m])).collect();
    /// let patch = TriangularPatch::try_new(2, net).unwrap();
    /// let (e1, e2, e3) = (Barycentric::e1(), Barycentric::e2(), Barycentric::e3());
    /// assert_eq!(patch.blossom(&[e2.clone(), e3.clone()]).unwrap(), *patch.point(0, 1, 1).unwrap());
    /// assert_eq!(
    ///     patch.blossom(&[e1]).unwrap_err().to_string(),
    ///     "the blossom of a patch of degree 2 takes 2 arguments, found 1"
    /// );
    /// ```
    pub fn blossom(&self, args: &[Barycentric<S>]) -> Result<Point<S>, TriangleError> {
        self.blossom_recorded(args, &mut NoSteps)
    }

    /// [`TriangularPatch::blossom`] step by step: records every level of the De Casteljau
    /// algorithm run with the argument x_l at level l,
    ///
    /// b^l_{ijk} = x_{l,1} b^{l-1}_{i+1,j,k} + x_{l,2} b^{l-1}_{i,j+1,k} + x_{l,3} b^{l-1}_{i,j,k+1},
    /// i + j + k = n - l,
    ///
    /// level 0 (the control net) first, level n the single point b[x_1, ..., x_n]. Errors with
    /// [`TriangleError::BlossomArity`] unless there are exactly n arguments.
    ///
    /// ```
    /// use cagd_linalg::Point;
    /// use cagd_scalar::BigRational;
    /// use cagd_triangle::{Barycentric, TriangularPatch};
    /// let net: Vec<Point<BigRational>> = (0..6).map(|m| Point::from_ints(&[m * m])).collect();
    /// let patch = TriangularPatch::try_new(2, net).unwrap();
    /// let mut levels = Vec::new();
    /// let b = patch.blossom_recorded(&[Barycentric::e2(), Barycentric::e3()], &mut levels).unwrap();
    /// assert_eq!(levels.iter().map(Vec::len).collect::<Vec<_>>(), [6, 3, 1]);
    /// assert_eq!(levels[2][0], b);
    /// ```
    pub fn blossom_recorded(
        &self,
        args: &[Barycentric<S>],
        rec: &mut impl Record<Level<S>>,
    ) -> Result<Point<S>, TriangleError> {
        self.check_arity(args.len())?;
        Ok(self.blossom_triples(args.iter().map(Barycentric::coords), rec))
    }

    /// The blossom extended multilinearly to arbitrary triples (barycentric points, directions,
    /// or any mix): the polar form of the homogeneous polynomial Σ b_{ijk} B^n_{ijk}(r, s, t).
    /// The callers pass exactly n triples. Each level is recorded, the control net first.
    pub(crate) fn blossom_triples<'a>(
        &self,
        args: impl IntoIterator<Item = &'a [S; 3]>,
        rec: &mut impl Record<Level<S>>,
    ) -> Point<S> {
        let n = self.degree();
        let mut net = self.points().to_vec();
        rec.record(|| net.clone());
        for (l, x) in (1..=n).zip(args) {
            net = crate::de_casteljau::step(&net, n - l, x);
            rec.record(|| net.clone());
        }
        net.swap_remove(0)
    }

    /// The polar values c_l = b[p^{n-l}, q^l], l = 0, ..., n: the control points of the
    /// Bézier curve of degree n that the patch traces over the segment from p to q,
    /// c(λ) = b((1 - λ) p + λ q). The steps with q are shared (the net after l of them is
    /// kept, and n - l steps with p finish c_l): Σ (n - l)³/6 point operations instead of the
    /// (n + 1) n³/6 of n + 1 separate blossoms.
    ///
    /// ```
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational};
    /// use cagd_triangle::{Barycentric, TriangularPatch};
    /// let net: Vec<Point<BigRational>> = (0..6).map(|m| Point::from_ints(&[m * m])).collect();
    /// let patch = TriangularPatch::try_new(2, net).unwrap();
    /// let (p, q) = (Barycentric::e1(), Barycentric::centroid());
    /// let c = patch.polar_segment(&p, &q);
    /// assert_eq!(c[1], patch.blossom(&[p.clone(), q.clone()]).unwrap());
    /// assert_eq!(c[2], patch.evaluate(&q));
    /// ```
    pub fn polar_segment(&self, p: &Barycentric<S>, q: &Barycentric<S>) -> Vec<Point<S>> {
        let n = self.degree();
        let mut out = Vec::with_capacity(n + 1);
        let mut q_net = self.points().to_vec();
        for l in 0..=n {
            if l > 0 {
                q_net = crate::de_casteljau::step(&q_net, n - l, q.coords());
            }
            let mut net = q_net.clone();
            for m in (0..n - l).rev() {
                net = crate::de_casteljau::step(&net, m, p.coords());
            }
            out.push(net.swap_remove(0));
        }
        out
    }

    fn check_arity(&self, found: usize) -> Result<(), TriangleError> {
        if found == self.degree() {
            Ok(())
        } else {
            Err(TriangleError::BlossomArity {
                degree: self.degree(),
                found,
            })
        }
    }
}
