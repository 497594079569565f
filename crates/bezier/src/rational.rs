//! [`RationalBezierCurve`]: control points with weights, computed through the homogeneous form.

use crate::blossom::{blossom, restrict};
use crate::casteljau::{de_casteljau, de_casteljau_triangle, subdivide};
use crate::elevate::elevate_checked;
use crate::polygon::{check_interval, check_polygon};
use crate::{BezierError, Quantity};
use cagd_linalg::Point;
use cagd_scalar::{Print, Scalar};
use std::fmt;

/// A rational Bézier curve
///
/// `c(t) = Σ w_i c_i B_i^n(u) / Σ w_i B_i^n(u)`, `u = (t - a)/(b - a)`,
///
/// on its domain [a, b] (by default [0, 1]). It is the projection of the polynomial Bézier
/// curve with the homogeneous control points `(w_i c_i, w_i)` (weight last, see
/// [`Point::to_homogeneous`]); every algorithm (evaluation, blossom, subdivision, restriction,
/// degree elevation) runs the polynomial algorithm on the homogeneous points and projects.
///
/// Weights are validated: one per control point, not all zero. A zero weight is a control
/// vector (Farin, rational Bézier curves; Piegl and Tiller §7.2): the entry `c_i` with `w_i = 0`
/// stores the vector `v_i`, and its homogeneous point is `(v_i, 0)` (see [`lift`]); the
/// semicircle is `(1, 0), (0, 1), (-1, 0)` with weights `1, 0, 1`. Every algorithm on the
/// homogeneous form (evaluation, blossom, subdivision, restriction, degree elevation, closed
/// form, derivative) takes such a curve; what needs every entry to be a point asks
/// [`RationalBezierCurve::require_points`]. Negative weights are allowed (they are legitimate
/// mathematics) and reported by [`RationalBezierCurve::has_positive_weights`]; with them or
/// with a zero weight the denominator may vanish inside the domain, which evaluation reports
/// as an error (a point at infinity).
///
/// ```
/// use cagd_bezier::RationalBezierCurve;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// // a quarter of the unit circle, in a form with rational weights
/// let c = RationalBezierCurve::<BigRational>::try_new(
///     vec![Point::from_ints(&[1, 0]), Point::from_ints(&[1, 1]), Point::from_ints(&[0, 1])],
///     vec![q!(1), q!(1/2), q!(1/2)],
/// ).unwrap();
/// assert_eq!(c.eval(&q!(1/2)).unwrap().to_text(), "(4/5, 3/5)");
/// ```
#[derive(Clone, PartialEq)]
pub struct RationalBezierCurve<S> {
    points: Vec<Point<S>>,
    weights: Vec<S>,
    a: S,
    b: S,
}

impl<S: Scalar> RationalBezierCurve<S> {
    /// The curve with control points `c_0, ..., c_n` and weights `w_0, ..., w_n` on [0, 1]
    /// (an entry of weight zero is a control vector); an error if the polygon is empty or
    /// mixed in dimension, the counts differ, or every weight is zero.
    pub fn try_new(points: Vec<Point<S>>, weights: Vec<S>) -> Result<Self, BezierError> {
        check_polygon(&points)?;
        if points.len() != weights.len() {
            return Err(BezierError::WeightCount {
                points: points.len(),
                weights: weights.len(),
            });
        }
        if weights.iter().all(|w| w.is_zero()) {
            return Err(BezierError::AllWeightsZero);
        }
        Ok(RationalBezierCurve {
            points,
            weights,
            a: S::zero(),
            b: S::one(),
        })
    }

    /// The curve whose homogeneous control points are `(w_i c_i, w_i)` (weight last), on
    /// [0, 1]; a point `(v, 0)` is the control vector v; an error when every weight is zero.
    pub fn from_homogeneous(homogeneous: &[Point<S>]) -> Result<Self, BezierError> {
        Self::project(homogeneous, S::zero(), S::one())
    }

    /// Projects homogeneous points onto a curve on [a, b].
    fn project(homogeneous: &[Point<S>], a: S, b: S) -> Result<Self, BezierError> {
        let dim = check_polygon(homogeneous)?;
        if dim == 0 {
            return Err(BezierError::HomogeneousWithoutWeight);
        }
        let mut points = Vec::with_capacity(homogeneous.len());
        let mut weights = Vec::with_capacity(homogeneous.len());
        for h in homogeneous {
            let (p, w) = project_one(h);
            points.push(p);
            weights.push(w);
        }
        if weights.iter().all(|w| w.is_zero()) {
            return Err(BezierError::AllWeightsZero);
        }
        Ok(RationalBezierCurve {
            points,
            weights,
            a,
            b,
        })
    }

    /// The same curve on the domain [a, b]; an error unless a < b.
    pub fn with_domain(self, a: S, b: S) -> Result<Self, BezierError> {
        check_interval(&a, &b)?;
        Ok(RationalBezierCurve { a, b, ..self })
    }

    /// The domain [a, b].
    pub fn domain(&self) -> (&S, &S) {
        (&self.a, &self.b)
    }

    /// The degree n.
    pub fn degree(&self) -> usize {
        self.points.len() - 1
    }

    /// The dimension of the (affine) control points.
    pub fn dim(&self) -> usize {
        self.points.first().map_or(0, Point::dim)
    }

    /// The control points `c_0, ..., c_n`; an entry of weight zero is a control vector.
    pub fn points(&self) -> &[Point<S>] {
        &self.points
    }

    /// The index of the first zero weight (its entry is a control vector), if any.
    pub fn first_vector(&self) -> Option<usize> {
        self.weights.iter().position(|w| w.is_zero())
    }

    /// Ok when every entry is a control point (no weight is zero); else the error naming the
    /// first control vector, for what needs points (a convex hull, a conic's shape factor
    /// from points, a figure's polygon).
    pub fn require_points(&self) -> Result<(), BezierError> {
        match self.first_vector() {
            Some(index) => Err(BezierError::ZeroWeight { index }),
            None => Ok(()),
        }
    }

    /// The weights `w_0, ..., w_n`.
    pub fn weights(&self) -> &[S] {
        &self.weights
    }

    /// Whether every weight is positive (then the curve lies in the convex hull of its
    /// control points and the denominator never vanishes on the domain).
    pub fn has_positive_weights(&self) -> bool {
        self.weights.iter().all(|w| *w > S::zero())
    }

    /// The homogeneous control points `(w_i c_i, w_i)`, weight last; `(v_i, 0)` for a
    /// control vector.
    pub fn homogeneous(&self) -> Vec<Point<S>> {
        self.points
            .iter()
            .zip(&self.weights)
            .map(|(p, w)| lift(p, w))
            .collect()
    }

    /// The local parameter `u = (t - a)/(b - a)` of any t.
    pub fn local_parameter(&self, t: &S) -> S {
        if self.a.is_zero() && self.b.is_one() {
            t.clone()
        } else {
            t.sub_ref(&self.a) / self.b.sub_ref(&self.a)
        }
    }

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

    /// The homogeneous point `(w(t) c(t), w(t))`: the Bernstein sum on integers for rational
    /// data, else De Casteljau on the homogeneous points; t must lie in the domain.
    pub fn eval_homogeneous(&self, t: &S) -> Result<Point<S>, BezierError> {
        let (h, local) = (self.homogeneous(), self.checked_local(t)?);
        // rational data: the Bernstein sum on integers, the same point as De Casteljau
        if let Some(p) = cagd_linalg::exact::bernstein_combination(&h, &local) {
            return Ok(p);
        }
        de_casteljau(&h, &local)
    }

    /// The denominator `w(t) = Σ w_i B_i^n(u)`; t must lie in the domain.
    pub fn weight_at(&self, t: &S) -> Result<S, BezierError> {
        let h = self.eval_homogeneous(t)?;
        Ok(h.coords().last().cloned().unwrap_or_else(S::zero))
    }

    /// The point c(t); an error if t is outside the domain or the denominator w(t) vanishes.
    pub fn eval(&self, t: &S) -> Result<Point<S>, BezierError> {
        let h = self.eval_homogeneous(t)?;
        h.from_homogeneous()
            .map(|(p, _)| p)
            .ok_or_else(|| BezierError::VanishingDenominator { t: t.to_text() })
    }

    /// The triangle of De Casteljau of the homogeneous points at t (`[r][i]`, weight last),
    /// for step-by-step answers; t must lie in the domain.
    pub fn triangle_homogeneous(&self, t: &S) -> Result<Vec<Vec<Point<S>>>, BezierError> {
        de_casteljau_triangle(&self.homogeneous(), &self.checked_local(t)?)
    }

    /// The blossom of the homogeneous curve `C[t_1, ..., t_n]` (weight last), arguments in the
    /// curve's parameter.
    pub fn blossom_homogeneous(&self, args: &[S]) -> Result<Point<S>, BezierError> {
        let local: Vec<S> = args.iter().map(|t| self.local_parameter(t)).collect();
        blossom(&self.homogeneous(), &local)
    }

    /// The blossom projected: the affine point of `C[t_1, ..., t_n]`; an error if its weight
    /// vanishes. On the diagonal it is c(t).
    pub fn blossom(&self, args: &[S]) -> Result<Point<S>, BezierError> {
        self.blossom_homogeneous(args)?
            .from_homogeneous()
            .map(|(p, _)| p)
            .ok_or_else(|| {
                let list: Vec<String> = args.iter().map(Print::to_text).collect();
                BezierError::VanishingDenominator {
                    t: format!("[{}]", list.join(", ")),
                }
            })
    }

    /// The two pieces split at t (strictly inside the domain), on [a, t] and [t, b], by
    /// subdividing the homogeneous polygon.
    pub fn subdivide(&self, t: &S) -> Result<(Self, Self), BezierError> {
        if *t <= self.a || *t >= self.b {
            return Err(BezierError::NotInterior {
                t: t.to_text(),
                a: self.a.to_text(),
                b: self.b.to_text(),
            });
        }
        let (left, right) = subdivide(&self.homogeneous(), &self.local_parameter(t))?;
        Ok((
            Self::project(&left, self.a.clone(), t.clone())?,
            Self::project(&right, t.clone(), self.b.clone())?,
        ))
    }

    /// The curve restricted to [s, e] (s < e), on the domain [s, e]: the homogeneous points
    /// `C[u_s^<n-i>, u_e^<i>]` projected (a zero weight among them is a control vector).
    pub fn restrict(&self, s: &S, e: &S) -> Result<Self, BezierError> {
        check_interval(s, e)?;
        let h = restrict(
            &self.homogeneous(),
            &self.local_parameter(s),
            &self.local_parameter(e),
        )?;
        Self::project(&h, s.clone(), e.clone())
    }

    /// The same curve with degree n + r (degree elevation of the homogeneous points; a zero
    /// weight among them is a control vector).
    pub fn elevate_degree(&self, r: usize) -> Result<Self, BezierError> {
        let h = elevate_checked(&self.homogeneous(), r);
        Self::project(&h, self.a.clone(), self.b.clone())
    }

    /// The first derivative c'(t) by the quotient rule: with the homogeneous curve
    /// `C = (p, w)` and its hodograph `C'(u) = n (C_1^{n-1} - C_0^{n-1})` (the last level but one
    /// of De Casteljau),
    ///
    /// `c'(t) = (p'(u) - w'(u) c(t)) / w(u) · 1/(b - a)`.
    ///
    /// An error if t is outside the domain or w(t) = 0.
    pub fn derivative_at(&self, t: &S) -> Result<Point<S>, BezierError> {
        let tri = self.triangle_homogeneous(t)?;
        let n = self.degree();
        let vanishing = || BezierError::VanishingDenominator { t: t.to_text() };
        let top = tri.get(n).and_then(|l| l.first()).ok_or_else(vanishing)?;
        let (c, w) = top.from_homogeneous().ok_or_else(vanishing)?;
        if n == 0 {
            return Ok(Point::zero(self.dim()));
        }
        let pair = tri.get(n - 1).ok_or_else(vanishing)?;
        let (Some(c0), Some(c1)) = (pair.first(), pair.get(1)) else {
            return Err(vanishing());
        };
        let mut d = c1 - c0; // C'(u) / n
        d = d.scale(&S::from_i64(i64::try_from(n).unwrap_or(i64::MAX)));
        let coords = d.into_coords();
        let (dw, dp) = coords.split_last().ok_or_else(vanishing)?;
        let mut num = Point::new(dp.to_vec());
        num.add_scaled(&c, &-dw.clone());
        let mut scale = S::one() / w;
        if !(self.a.is_zero() && self.b.is_one()) {
            scale /= self.b.sub_ref(&self.a);
        }
        Ok(num.scale(&scale))
    }

    /// The same point set with weights `w_i ρ^i` (ρ > 0): a reparametrization
    /// `u ↦ ρ u / ((1 - u) + ρ u)` of the curve, which leaves the control points unchanged
    /// (a control vector v_i becomes ρ^i v_i, its homogeneous point scaled as the others).
    /// With ρ = √2/2 it turns the quarter circle's weights {1, √2/2, 1} into {1, 1/2, 1/2}.
    pub fn reweight(&self, rho: &S) -> Result<Self, BezierError> {
        if *rho <= S::zero() {
            return Err(BezierError::NotPositive {
                what: Quantity::ReweightingFactor,
                value: rho.to_text(),
            });
        }
        let mut factor = S::one();
        let mut weights = Vec::with_capacity(self.weights.len());
        let mut points = Vec::with_capacity(self.points.len());
        for (p, w) in self.points.iter().zip(&self.weights) {
            weights.push(w.mul_ref(&factor));
            // a control vector is the homogeneous (v, 0): it scales with the weights
            points.push(if w.is_zero() {
                p.scale(&factor)
            } else {
                p.clone()
            });
            factor *= rho;
        }
        Ok(RationalBezierCurve {
            points,
            weights,
            a: self.a.clone(),
            b: self.b.clone(),
        })
    }

    /// For a conic (degree 2) with `w_0 w_2 > 0`: which conic, by the shape factor
    /// `k = w_1^2 / (w_0 w_2)`: an ellipse when k < 1, a parabola when k = 1, a hyperbola when
    /// k > 1. `None` for another degree or when `w_0 w_2 < 0`.
    pub fn conic_kind(&self) -> Option<ConicKind> {
        let [w0, w1, w2] = self.weights.as_slice() else {
            return None;
        };
        let w02 = w0.mul_ref(w2);
        if w02 <= S::zero() {
            return None;
        }
        let k = w1.mul_ref(w1);
        Some(if k < w02 {
            ConicKind::Ellipse
        } else if k == w02 {
            ConicKind::Parabola
        } else {
            ConicKind::Hyperbola
        })
    }

    /// Control points and weights as text: `(1, 0) w = 1; (1, 1) w = √2/2; (0, 1) w = 1`.
    pub fn to_text(&self) -> String {
        let parts: Vec<String> = self
            .points
            .iter()
            .zip(&self.weights)
            .map(|(p, w)| {
                if w.is_zero() {
                    format!("vector {} w = 0", p.to_text())
                } else {
                    format!("{} w = {}", p.to_text(), w.to_text())
                }
            })
            .collect();
        parts.join("; ")
    }
}

/// The homogeneous point of a control point p of weight w, `(w p, w)`; of a control vector
/// (w = 0) `(v, 0)`.
pub fn lift<S: Scalar>(p: &Point<S>, w: &S) -> Point<S> {
    if w.is_zero() {
        let mut coords = p.coords().to_vec();
        coords.push(S::zero());
        Point::new(coords)
    } else {
        p.to_homogeneous(w)
    }
}

/// The entry and weight of a homogeneous point: `(p, w)` for w ≠ 0, the vector `(v, 0)` for
/// w = 0 (the inverse of [`lift`]).
pub fn project_one<S: Scalar>(h: &Point<S>) -> (Point<S>, S) {
    if let Some(pw) = h.from_homogeneous() {
        return pw;
    }
    let coords = h.coords();
    let rest = coords.split_last().map_or(&[][..], |(_, r)| r);
    (Point::new(rest.to_vec()), S::zero())
}

/// The kind of conic a quadratic rational Bézier curve lies on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ConicKind {
    /// Shape factor `w_1^2/(w_0 w_2) < 1` (circles included).
    Ellipse,
    /// Shape factor 1: the polynomial case, up to reparametrization.
    Parabola,
    /// Shape factor > 1.
    Hyperbola,
}

impl<S: Scalar> fmt::Debug for RationalBezierCurve<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "RationalBezierCurve(degree {}, [{}, {}]: {})",
            self.degree(),
            self.a.to_text(),
            self.b.to_text(),
            self.to_text()
        )
    }
}

impl<S: Scalar> fmt::Display for RationalBezierCurve<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}
