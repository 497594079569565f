//! The typed B-spline curve: knots and control points validated once.

use crate::{
    bezier_pieces, blossom, check_control_points, de_boor, de_boor_triangle, derivative_curve,
    derivatives, elevate_degree, insert_knot, refine_knots, remove_knot, BSplineError, BezierPiece,
    DeBoorTriangle, KnotConvention, KnotVector,
};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// A B-spline curve `c(t) = Σ_{i=0}^{n-1} d_i N_i^p(t)` on the domain of its knot vector.
///
/// The degree p is the knot vector's. Every method calls the free function of the same name
/// on `(self.knots(), self.points())`; those functions are what the surface code applies to
/// the rows and columns of a mesh.
///
/// ```
/// use cagd_bspline::{BSplineCurve, KnotConvention};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let d: Vec<Point<BigRational>> =
///     [[0, 0], [1, 2], [3, 2], [4, 0]].iter().map(|c| Point::from_ints(c)).collect();
/// let (c, conv) = BSplineCurve::read(2, vec![q!(0), q!(0), q!(1), q!(2), q!(2)], d).unwrap();
/// assert_eq!(conv, KnotConvention::Notes);
/// assert_eq!(c.eval(&q!(1)).unwrap().to_text(), "(2, 2)");
/// assert_eq!(c.insert_knot(&q!(1), 1).unwrap().points()[2].to_text(), "(2, 2)");
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct BSplineCurve<S: Scalar> {
    knots: KnotVector<S>,
    points: Vec<Point<S>>,
}

impl<S: Scalar> BSplineCurve<S> {
    /// The curve with this knot vector and these control points (as many as the knot vector
    /// is made for, all of one dimension).
    pub fn try_new(knots: KnotVector<S>, points: Vec<Point<S>>) -> Result<Self, BSplineError> {
        check_control_points(&knots, &points)?;
        Ok(BSplineCurve { knots, points })
    }

    /// The curve of degree p with these knots in either convention (told apart by length, see
    /// [`KnotVector::read`]) and control points.
    pub fn read(
        degree: usize,
        knots: Vec<S>,
        points: Vec<Point<S>>,
    ) -> Result<(Self, KnotConvention), BSplineError> {
        let (knots, convention) = KnotVector::read(knots, degree, points.len())?;
        Ok((Self::try_new(knots, points)?, convention))
    }

    /// A curve from parts known to fit (the output of an algorithm of this crate).
    pub(crate) fn from_parts(parts: (KnotVector<S>, Vec<Point<S>>)) -> Self {
        BSplineCurve {
            knots: parts.0,
            points: parts.1,
        }
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
    /// [`KnotVector::normalized`], the same control points; its point at s is this
    /// curve's at a + s (b - a).
    pub fn normalized(&self) -> Self {
        Self {
            knots: self.knots.normalized(),
            ..self.clone()
        }
    }

    /// The control points `d_0, ..., d_{n-1}`.
    pub fn points(&self) -> &[Point<S>] {
        &self.points
    }

    /// The dimension of the control points.
    pub fn dim(&self) -> usize {
        self.points.first().map_or(0, Point::dim)
    }

    /// The domain `[u_{p-1}, u_{n-1}]` (notes' convention).
    pub fn domain(&self) -> (S, S) {
        self.knots.domain()
    }

    /// The knot vector and control points, consuming the curve.
    pub fn into_parts(self) -> (KnotVector<S>, Vec<Point<S>>) {
        (self.knots, self.points)
    }

    /// The point c(t), by De Boor ([`de_boor`]).
    pub fn eval(&self, t: &S) -> Result<Point<S>, BSplineError> {
        de_boor(&self.knots, &self.points, t)
    }

    /// The De Boor triangle at t ([`de_boor_triangle`]).
    pub fn de_boor_triangle(&self, t: &S) -> Result<DeBoorTriangle<S>, BSplineError> {
        de_boor_triangle(&self.knots, &self.points, t)
    }

    /// The blossom of the piece on a span ([`blossom`]).
    pub fn blossom(&self, span: usize, args: &[S]) -> Result<Point<S>, BSplineError> {
        blossom(&self.knots, &self.points, span, args)
    }

    /// `c(t), c'(t), ..., c^(order)(t)` ([`derivatives`]).
    pub fn derivatives(&self, t: &S, order: usize) -> Result<Vec<Point<S>>, BSplineError> {
        derivatives(&self.knots, &self.points, t, order)
    }

    /// The derivative curve, of degree p - 1 ([`derivative_curve`]).
    pub fn derivative(&self) -> Result<Self, BSplineError> {
        derivative_curve(&self.knots, &self.points).map(Self::from_parts)
    }

    /// The same curve with the knot t inserted `times` times ([`insert_knot`]).
    pub fn insert_knot(&self, t: &S, times: usize) -> Result<Self, BSplineError> {
        insert_knot(&self.knots, &self.points, t, times).map(Self::from_parts)
    }

    /// The same curve with all these knots inserted ([`refine_knots`]).
    pub fn refine_knots(&self, new_knots: &[S]) -> Result<Self, BSplineError> {
        refine_knots(&self.knots, &self.points, new_knots).map(Self::from_parts)
    }

    /// The same curve with the knot t removed `times` times, if possible ([`remove_knot`]).
    pub fn remove_knot(&self, t: &S, times: usize) -> Result<Self, BSplineError> {
        remove_knot(&self.knots, &self.points, t, times).map(Self::from_parts)
    }

    /// The Bézier pieces ([`bezier_pieces`]).
    pub fn bezier_pieces(&self) -> Result<Vec<BezierPiece<S>>, BSplineError> {
        bezier_pieces(&self.knots, &self.points)
    }

    /// The same curve with degree p + r ([`elevate_degree`]).
    pub fn elevate_degree(&self, r: usize) -> Result<Self, BSplineError> {
        elevate_degree(&self.knots, &self.points, r).map(Self::from_parts)
    }

    /// Plain text: the degree, the knots in a convention and the control points, one item a
    /// line.
    pub fn to_text_in(&self, convention: KnotConvention) -> String {
        let points: Vec<String> = self.points.iter().map(Point::to_text).collect();
        format!(
            "degree {}\nknots {}\npoints {}",
            self.degree(),
            self.knots.to_text_in(convention),
            points.join(", ")
        )
    }
}
