//! NURBS curves: every algorithm runs on the homogeneous control points `(w d, w)`.

use crate::knots::scalar_of;
use crate::{BSplineCurve, BSplineError, DeBoorTriangle, KnotConvention, KnotVector};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// One piece of a NURBS curve as a rational Bézier curve on its parameter interval.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalBezierPiece<S: Scalar> {
    /// The interval of the piece.
    pub interval: (S, S),
    /// The (affine) control points.
    pub points: Vec<Point<S>>,
    /// Their weights.
    pub weights: Vec<S>,
}

/// A NURBS curve `c(t) = Σ w_i d_i N_i^p(t) / Σ w_i N_i^p(t)`.
///
/// Internally and for every algorithm it is the B-spline curve of the homogeneous points
/// `(w_i d_i, w_i)` (weight last, [`Point::to_homogeneous`]): insertion, refinement, Bézier
/// extraction and degree elevation act on them and project back. Zero weights are an error;
/// negative weights are allowed (the curve may then leave the convex hull or go through
/// infinity) and listed by [`NurbsCurve::negative_weights`] so that callers can warn.
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsCurve<S: Scalar> {
    knots: KnotVector<S>,
    points: Vec<Point<S>>,
    weights: Vec<S>,
}

impl<S: Scalar> NurbsCurve<S> {
    /// The NURBS curve with these knots, control points and weights.
    pub fn try_new(
        knots: KnotVector<S>,
        points: Vec<Point<S>>,
        weights: Vec<S>,
    ) -> Result<Self, BSplineError> {
        crate::check_control_points(&knots, &points)?;
        if weights.len() != points.len() {
            return Err(BSplineError::WeightCount {
                points: points.len(),
                weights: weights.len(),
            });
        }
        if let Some(index) = weights.iter().position(|w| w.is_zero()) {
            return Err(BSplineError::ZeroWeight { index });
        }
        Ok(NurbsCurve {
            knots,
            points,
            weights,
        })
    }

    /// The NURBS curve of degree p with knots in either convention (see [`KnotVector::read`]).
    pub fn read(
        degree: usize,
        knots: Vec<S>,
        points: Vec<Point<S>>,
        weights: Vec<S>,
    ) -> Result<(Self, KnotConvention), BSplineError> {
        let (knots, convention) = KnotVector::read(knots, degree, points.len())?;
        Ok((Self::try_new(knots, points, weights)?, convention))
    }

    /// The NURBS curve whose homogeneous control points `(w x, ..., w)` are those of a
    /// B-spline curve; a zero last coordinate is an error naming the point.
    pub fn from_homogeneous(curve: BSplineCurve<S>) -> Result<Self, BSplineError> {
        let (knots, hpoints) = curve.into_parts();
        let mut points = Vec::with_capacity(hpoints.len());
        let mut weights = Vec::with_capacity(hpoints.len());
        for (index, h) in hpoints.iter().enumerate() {
            let (p, w) = h
                .from_homogeneous()
                .ok_or(BSplineError::ZeroWeight { index })?;
            points.push(p);
            weights.push(w);
        }
        Self::try_new(knots, points, weights)
    }

    /// The B-spline curve of the homogeneous points `(w_i d_i, w_i)`.
    pub fn homogeneous(&self) -> BSplineCurve<S> {
        let hpoints = self
            .points
            .iter()
            .zip(&self.weights)
            .map(|(p, w)| p.to_homogeneous(w))
            .collect();
        // Same knots, same count and one dimension more for every point: still valid.
        BSplineCurve::from_parts((self.knots.clone(), hpoints))
    }

    /// The degree p.
    pub fn degree(&self) -> usize {
        self.knots.degree()
    }

    /// The knot vector.
    pub fn knots(&self) -> &KnotVector<S> {
        &self.knots
    }

    /// The same curve on the domain [0, 1]: the knots (u - a)/(b - a) of
    /// [`KnotVector::normalized`], the same control points and weights; its point at s is this
    /// curve's at a + s (b - a).
    pub fn normalized(&self) -> Self {
        Self {
            knots: self.knots.normalized(),
            ..self.clone()
        }
    }

    /// The (affine) control points.
    pub fn points(&self) -> &[Point<S>] {
        &self.points
    }

    /// The weights.
    pub fn weights(&self) -> &[S] {
        &self.weights
    }

    /// The domain.
    pub fn domain(&self) -> (S, S) {
        self.knots.domain()
    }

    /// The indices of the negative weights (empty for a curve in the convex hull of its
    /// control points).
    pub fn negative_weights(&self) -> Vec<usize> {
        self.weights
            .iter()
            .enumerate()
            .filter(|(_, w)| **w < S::zero())
            .map(|(i, _)| i)
            .collect()
    }

    /// The point c(t): De Boor on the homogeneous points, then the projection
    /// `(X, ..., W) ↦ (X/W, ...)`.
    pub fn eval(&self, t: &S) -> Result<Point<S>, BSplineError> {
        let h = self.homogeneous().eval(t)?;
        project(&h, t)
    }

    /// The De Boor triangle of the homogeneous points (each intermediate point projects to
    /// the affine one by [`Point::from_homogeneous`]).
    pub fn de_boor_triangle(&self, t: &S) -> Result<DeBoorTriangle<S>, BSplineError> {
        self.homogeneous().de_boor_triangle(t)
    }

    /// `c(t), c'(t), ..., c^(order)(t)` (Piegl and Tiller, eq. 4.8, A4.2): with `A(t)` the
    /// homogeneous curve's first coordinates and `w(t)` its weight,
    ///
    /// `c^(k) = (A^(k) - Σ_{i=1}^{k} C(k, i) w^(i) c^(k-i)) / w`.
    ///
    /// ```
    /// use cagd_bspline::unit_circle;
    /// use cagd_scalar::{parse_number, Print, Quadratic};
    /// let c = unit_circle::<Quadratic>().unwrap();
    /// let t = parse_number("1/8").unwrap();
    /// let d = c.derivatives(&t, 1).unwrap();
    /// // The tangent is orthogonal to the radius.
    /// assert_eq!(d[0].dot(&d[1]).to_text(), "0");
    /// ```
    pub fn derivatives(&self, t: &S, order: usize) -> Result<Vec<Point<S>>, BSplineError> {
        let h = self.homogeneous().derivatives(t, order)?;
        let mut out: Vec<Point<S>> = Vec::with_capacity(order + 1);
        let split = |p: &Point<S>| -> (Point<S>, S) {
            let c = p.coords();
            let (w, a) = c
                .split_last()
                .map_or((S::zero(), &[][..]), |(w, a)| (w.clone(), a));
            (Point::new(a.to_vec()), w)
        };
        let parts: Vec<(Point<S>, S)> = h.iter().map(split).collect();
        let w0 = parts.first().map_or_else(S::zero, |p| p.1.clone());
        if w0.is_zero() {
            return Err(BSplineError::PointAtInfinity { t: t.to_text() });
        }
        for (k, (a_k, _)) in parts.iter().enumerate().take(order + 1) {
            let mut v = a_k.clone();
            let mut binom = S::one();
            // out holds c^(0..k-1): out[k - i] for i = 1..=k is out reversed
            for (i, (w_i, c)) in parts
                .iter()
                .skip(1)
                .map(|p| &p.1)
                .zip(out.iter().rev())
                .enumerate()
            {
                let i = i + 1;
                // C(k, i) = C(k, i-1) (k - i + 1) / i
                binom = binom * scalar_of::<S>(k - i + 1) / scalar_of::<S>(i);
                let coef = -(binom.mul_ref(w_i));
                v.add_scaled(c, &coef);
            }
            let inv = S::one()
                .checked_div(&w0)
                .ok_or(BSplineError::PointAtInfinity { t: t.to_text() })?;
            out.push(v.scale(&inv));
        }
        Ok(out)
    }

    /// The same curve with the knot t inserted `times` times.
    pub fn insert_knot(&self, t: &S, times: usize) -> Result<Self, BSplineError> {
        Self::from_homogeneous(self.homogeneous().insert_knot(t, times)?)
    }

    /// The same curve with all these knots inserted.
    pub fn refine_knots(&self, new_knots: &[S]) -> Result<Self, BSplineError> {
        Self::from_homogeneous(self.homogeneous().refine_knots(new_knots)?)
    }

    /// The same curve with the knot t removed `times` times, if the curve allows it.
    pub fn remove_knot(&self, t: &S, times: usize) -> Result<Self, BSplineError> {
        Self::from_homogeneous(self.homogeneous().remove_knot(t, times)?)
    }

    /// The same curve with degree p + r.
    pub fn elevate_degree(&self, r: usize) -> Result<Self, BSplineError> {
        Self::from_homogeneous(self.homogeneous().elevate_degree(r)?)
    }

    /// The rational Bézier pieces, one per non-empty span.
    pub fn bezier_pieces(&self) -> Result<Vec<RationalBezierPiece<S>>, BSplineError> {
        let mut out = Vec::new();
        for piece in self.homogeneous().bezier_pieces()? {
            let mut points = Vec::with_capacity(piece.points.len());
            let mut weights = Vec::with_capacity(piece.points.len());
            for (index, h) in piece.points.iter().enumerate() {
                let (p, w) = h
                    .from_homogeneous()
                    .ok_or(BSplineError::ZeroWeight { index })?;
                points.push(p);
                weights.push(w);
            }
            out.push(RationalBezierPiece {
                interval: piece.interval,
                points,
                weights,
            });
        }
        Ok(out)
    }
}

/// The affine point of a homogeneous point of the curve at t.
fn project<S: Scalar>(h: &Point<S>, t: &S) -> Result<Point<S>, BSplineError> {
    h.from_homogeneous()
        .map(|(p, _)| p)
        .ok_or(BSplineError::PointAtInfinity { t: t.to_text() })
}
