//! [`BezierCurve`]: a validated control polygon over a parameter interval [a, b].

use crate::bernstein::bernstein_sum;
use crate::blossom::{blossom, restrict};
use crate::casteljau::{de_casteljau, de_casteljau_triangle, subdivide};
use crate::derivative::{derivative_checked, differences_checked};
use crate::elevate::elevate_checked;
use crate::polygon::{check_interval, check_polygon};
use crate::BezierError;
use cagd_linalg::Point;
use cagd_scalar::Scalar;
use std::fmt;

/// A Bézier curve `c(t) = Σ_{i=0}^{n} B_i^n(u) c_i` with `u = (t - a)/(b - a)` on its domain
/// [a, b] (by default [0, 1], where u = t).
///
/// The control polygon is checked once, at construction (not empty, one dimension), so the
/// methods only fail on a bad parameter. The free functions of the crate ([`de_casteljau`],
/// [`crate::restrict`], ...) do the work on the polygon in the local parameter u.
///
/// ```
/// use cagd_bezier::BezierCurve;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let c = BezierCurve::<BigRational>::try_new(vec![
///     Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2]), Point::from_ints(&[3, 3]),
/// ]).unwrap();
/// assert_eq!(c.eval(&q!(1/3)).unwrap().to_text(), "(7/9, 11/9)");
/// assert_eq!(
///     c.eval(&q!(3/2)).unwrap_err().to_string(),
///     "parameter t = 3/2 is outside the domain [0, 1]"
/// );
/// ```
#[derive(Clone, PartialEq)]
pub struct BezierCurve<S> {
    points: Vec<Point<S>>,
    a: S,
    b: S,
}

impl<S: Scalar> BezierCurve<S> {
    /// The curve with these control points `c_0, ..., c_n`, on the domain [0, 1]; an error if
    /// the polygon is empty or its points have different dimensions.
    pub fn try_new(points: Vec<Point<S>>) -> Result<Self, BezierError> {
        check_polygon(&points)?;
        Ok(BezierCurve {
            points,
            a: S::zero(),
            b: S::one(),
        })
    }

    /// The same control points on the domain [a, b] (an affine reparametrization); an error
    /// unless a < b.
    pub fn with_domain(self, a: S, b: S) -> Result<Self, BezierError> {
        check_interval(&a, &b)?;
        Ok(BezierCurve { a, b, ..self })
    }

    /// The domain [a, b].
    pub fn domain(&self) -> (&S, &S) {
        (&self.a, &self.b)
    }

    /// The degree n (one less than the number of control points).
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }

    /// The dimension of the control points.
    pub fn dim(&self) -> usize {
        self.points.first().map_or(0, Point::dim)
    }

    /// The control points `c_0, ..., c_n`.
    pub fn points(&self) -> &[Point<S>] {
        &self.points
    }

    /// The control points, consuming the curve.
    pub fn into_points(self) -> Vec<Point<S>> {
        self.points
    }

    /// Whether the domain is the standard [0, 1].
    fn is_standard(&self) -> bool {
        self.a.is_zero() && self.b.is_one()
    }

    /// The local parameter `u = (t - a)/(b - a)` of any t (no domain check).
    pub fn local_parameter(&self, t: &S) -> S {
        if self.is_standard() {
            t.clone()
        } else {
            t.sub_ref(&self.a) / self.b.sub_ref(&self.a)
        }
    }

    /// The local parameter of a t of the domain, or the error naming t and the domain.
    fn checked_local(&self, t: &S) -> Result<S, BezierError> {
        if *t < self.a || *t > self.b {
            return Err(BezierError::OutsideDomain {
                t: t.to_text(),
                a: self.a.to_text(),
                b: self.b.to_text(),
            });
        }
        Ok(self.local_parameter(t))
    }

    /// The point c(t); t must lie in the domain. For rational points and t the Bernstein sum
    /// `Σ B_i^n(t) c_i` on integer numerators over one common denominator, reduced once
    /// ([`cagd_linalg::exact::bernstein_combination`]); otherwise (a + b√d, `f64`) De
    /// Casteljau's algorithm. Both give the same point.
    pub fn eval(&self, t: &S) -> Result<Point<S>, BezierError> {
        let local = self.checked_local(t)?;
        if let Some(p) = cagd_linalg::exact::bernstein_combination(&self.points, &local) {
            return Ok(p);
        }
        de_casteljau(&self.points, &local)
    }

    /// The point c(t) as the Bernstein sum `Σ B_i^n(u) c_i`; t must lie in the domain.
    pub fn eval_bernstein(&self, t: &S) -> Result<Point<S>, BezierError> {
        bernstein_sum(&self.points, &self.checked_local(t)?)
    }

    /// The triangle of De Casteljau at t, level by level (`[r][i] = c_i^r`), for step-by-step
    /// answers; t must lie in the domain.
    pub fn triangle(&self, t: &S) -> Result<Vec<Vec<Point<S>>>, BezierError> {
        de_casteljau_triangle(&self.points, &self.checked_local(t)?)
    }

    /// The blossom `c[t_1, ..., t_n]` in the curve's parameter (each `t_k` is mapped to the
    /// local parameter); any values are accepted, exactly n of them.
    pub fn blossom(&self, args: &[S]) -> Result<Point<S>, BezierError> {
        let local: Vec<S> = args.iter().map(|t| self.local_parameter(t)).collect();
        blossom(&self.points, &local)
    }

    /// The two pieces of the curve split at t, on the domains [a, t] and [t, b] (so each piece
    /// gives the same points as the curve at the same parameters). t must lie strictly inside.
    pub fn subdivide(&self, t: &S) -> Result<(Self, Self), BezierError> {
        if *t <= self.a || *t >= self.b {
            return Err(BezierError::NotInterior {
                t: t.to_text(),
                a: self.a.to_text(),
                b: self.b.to_text(),
            });
        }
        let (left, right) = subdivide(&self.points, &self.local_parameter(t))?;
        Ok((
            BezierCurve {
                points: left,
                a: self.a.clone(),
                b: t.clone(),
            },
            BezierCurve {
                points: right,
                a: t.clone(),
                b: self.b.clone(),
            },
        ))
    }

    /// The curve restricted to [s, e] (s < e; the interval may reach outside the domain, which
    /// extrapolates): control points `c[u_s^<n-i>, u_e^<i>]` by [`crate::restrict`], on the
    /// domain [s, e]. Call [`BezierCurve::with_domain`] to read it over [0, 1] instead; the
    /// control points are the same.
    pub fn restrict(&self, s: &S, e: &S) -> Result<Self, BezierError> {
        check_interval(s, e)?;
        let points = restrict(
            &self.points,
            &self.local_parameter(s),
            &self.local_parameter(e),
        )?;
        Ok(BezierCurve {
            points,
            a: s.clone(),
            b: e.clone(),
        })
    }

    /// The same curve written with degree n + r (see [`crate::elevate_degree`]).
    pub fn elevate_degree(&self, r: usize) -> Self {
        BezierCurve {
            points: elevate_checked(&self.points, r),
            a: self.a.clone(),
            b: self.b.clone(),
        }
    }

    /// The r-th derivative `c^(r)(t)` as a (vector-valued) Bézier curve of degree n - r on the
    /// same domain: control points `n!/(n-r)! Δ^r c_i / (b - a)^r` (the factor `1/(b - a)^r`
    /// is the chain rule of u = (t - a)/(b - a), and is 1 on [0, 1]). For r > n it is the zero
    /// curve of degree 0.
    pub fn derivative(&self, r: usize) -> Self {
        let mut points = derivative_checked(&self.points, r, self.dim());
        if !self.is_standard() && r <= self.degree() {
            let h = self.b.sub_ref(&self.a);
            let scale = S::one() / h.powi(u32::try_from(r).unwrap_or(u32::MAX));
            points = points.iter().map(|p| p.scale(&scale)).collect();
        }
        BezierCurve {
            points,
            a: self.a.clone(),
            b: self.b.clone(),
        }
    }

    /// The forward differences `Δ^r c_i`, `i = 0..n-r` (empty when r > n).
    pub fn forward_differences(&self, r: usize) -> Vec<Point<S>> {
        differences_checked(&self.points, r)
    }

    /// The curve traversed backwards: control points `c_n, ..., c_0` on the same domain.
    pub fn reverse(&self) -> Self {
        BezierCurve {
            points: self.points.iter().rev().cloned().collect(),
            a: self.a.clone(),
            b: self.b.clone(),
        }
    }

    /// The control points as text: `(0, 0), (1, 2), (3, 3)`.
    pub fn to_text(&self) -> String {
        let parts: Vec<String> = self.points.iter().map(Point::to_text).collect();
        parts.join(", ")
    }
}

impl<S: Scalar> fmt::Debug for BezierCurve<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "BezierCurve(degree {}, [{}, {}]: {})",
            self.degree(),
            self.a.to_text(),
            self.b.to_text(),
            self.to_text()
        )
    }
}

impl<S: Scalar> fmt::Display for BezierCurve<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}
