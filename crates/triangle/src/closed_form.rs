//! The closed form of a patch as a polynomial map in (u, v), and back.

use crate::bernstein::multinomial;
use crate::index::{multi_indices, pos};
use crate::{TriangleError, TriangularPatch};
use cagd_linalg::Point;
use cagd_poly::{Poly, Var, VecPoly};
use cagd_scalar::Scalar;

impl<S: Scalar> TriangularPatch<S> {
    /// The parametrization of the patch as a polynomial map in (u, v) of total degree ≤ n,
    ///
    /// b(u, v) = Σ_{i+j+k=n} b_{ijk} n!/(i! j! k!) (1 - u - v)^i u^j v^k,
    ///
    /// the Bernstein sum with r = 1 - u - v, s = u, t = v.
    ///
    /// ```
    /// use cagd_poly::parse_vec_poly;
    /// use cagd_scalar::BigRational;
    /// use cagd_triangle::TriangularPatch;
    /// // the graph of z = u v over the domain triangle, as a quadratic patch
    /// let f = parse_vec_poly::<BigRational>("(u, v, u*v)").unwrap();
    /// let patch = TriangularPatch::from_closed_form(&f, 2).unwrap();
    /// assert_eq!(patch.point(0, 1, 1).unwrap().to_text(), "(1/2, 1/2, 1/2)");
    /// assert_eq!(patch.point(1, 1, 0).unwrap().to_text(), "(1/2, 0, 0)");
    /// assert_eq!(patch.closed_form().to_text(), "(u, v, u v)");
    /// ```
    pub fn closed_form(&self) -> VecPoly<S> {
        let n = self.degree();
        let (u, v) = (Poly::var(Var::U), Poly::var(Var::V));
        let r = Poly::one() - &u - &v;
        let powers = |p: &Poly<S>| {
            let mut out = vec![Poly::one()];
            for _ in 1..=n {
                let next = out.last().map_or_else(Poly::one, |last| last * p);
                out.push(next);
            }
            out
        };
        let (rp, up, vp) = (powers(&r), powers(&u), powers(&v));
        let basis: Vec<Poly<S>> = multi_indices(n)
            .map(|(i, j, k)| match (rp.get(i), up.get(j), vp.get(k)) {
                // the powers go up to n ≥ i, j, k
                (Some(a), Some(b), Some(c)) => (&(a * b) * c).scale(&multinomial::<S>(i, j, k)),
                _ => Poly::zero(),
            })
            .collect();
        let comps = (0..self.dim())
            .map(|c| {
                basis
                    .iter()
                    .zip(self.points())
                    .fold(Poly::zero(), |acc, (b, p)| {
                        cagd_scalar::cancel::checkpoint();
                        match p.coords().get(c) {
                            Some(x) => acc + b.scale(x),
                            None => acc,
                        }
                    })
            })
            .collect();
        VecPoly::new(comps)
    }

    /// The patch of degree n whose closed form is the polynomial map `f` in (u, v) (total
    /// degree ≤ n): the change from the monomial to the Bernstein basis,
    ///
    /// b_{ijk} = Σ_{a ≤ j, b ≤ k} f_{ab} · C(n - a - b; i, j - a, k - b) / C(n; i, j, k),
    ///
    /// where f = Σ f_{ab} u^a v^b and C(m; ·) is the multinomial coefficient; it follows from
    /// u^a v^b = s^a t^b (r + s + t)^{n-a-b}. The inverse of [`TriangularPatch::closed_form`].
    ///
    /// Errors: [`TriangleError::NotInUV`] if `f` uses another variable,
    /// [`TriangleError::DegreeTooHigh`] if its total degree exceeds n.
    pub fn from_closed_form(f: &VecPoly<S>, degree: usize) -> Result<Self, TriangleError> {
        let others: Vec<String> = f
            .vars()
            .into_iter()
            .filter(|&x| x != Var::U && x != Var::V)
            .map(|x| x.to_string())
            .collect();
        if !others.is_empty() {
            return Err(TriangleError::NotInUV {
                vars: others.join(", "),
            });
        }
        let found = f.degree() as usize;
        if found > degree {
            return Err(TriangleError::DegreeTooHigh { found, degree });
        }
        let count =
            crate::control_point_count(degree).ok_or_else(|| TriangleError::DegreeTooLarge {
                degree: degree.to_string(),
            })?;
        let mut coords = vec![vec![S::zero(); f.dim()]; count];
        for (c, comp) in f.components().iter().enumerate() {
            for (m, coef) in comp.terms() {
                let (a, b) = (m.exp(Var::U) as usize, m.exp(Var::V) as usize);
                // u^a v^b = Σ_{j ≥ a, k ≥ b} C(n - a - b; i, j - a, k - b)/C(n; i, j, k) B^n_{ijk}
                for (i, j, k) in multi_indices(degree) {
                    if j >= a && k >= b {
                        let w = multinomial::<S>(i, j - a, k - b) / multinomial::<S>(i, j, k);
                        if let Some(x) = coords.get_mut(pos(j, k)).and_then(|p| p.get_mut(c)) {
                            *x += w * coef;
                        }
                    }
                }
            }
        }
        Self::try_new(degree, coords.into_iter().map(Point::new).collect())
    }
}
