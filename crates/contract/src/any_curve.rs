//! A curve of any kind read from the problem in the scalar of its solve, evaluated, measured
//! and written as an exact value.

use crate::any::AnyCurve as Curve;
use crate::convert::{at, convert_all, convert_map, convert_points};
use crate::input::CurveIn;
use crate::value::Number;
use crate::value::{exact, exact_map, exact_points, Exact, ExactScalar};
use crate::ProblemError;
use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_bspline::{BSplineCurve, KnotConvention, KnotVector, NurbsCurve};
use cagd_linalg::Point;
use cagd_poly::{Var, VecPoly};
use cagd_scalar::Scalar;

impl<S: ExactScalar> Curve<S> {
    /// Validates the curve written at `path`, in the scalar `S`; every control point must be a
    /// point (a zero weight, a control vector, is refused naming it: see
    /// [`Curve::read_with_vectors`] for the operations on the homogeneous form).
    pub fn read(c: &CurveIn<Number>, path: &str) -> Result<Self, ProblemError> {
        let curve = Self::read_with_vectors(c, path)?;
        if let Curve::RationalBezier(b) = &curve {
            b.require_points().map_err(at(path))?;
        }
        Ok(curve)
    }

    /// Validates the curve written at `path`, in the scalar `S`; a rational Bézier curve may
    /// have zero weights (its entry the control vector), for the operations that run on the
    /// homogeneous form (evaluate, closed form, elevate, subdivide, restrict, blossom,
    /// derivative, reverse). A NURBS curve's zero weight is refused as before.
    pub fn read_with_vectors(c: &CurveIn<Number>, path: &str) -> Result<Self, ProblemError> {
        let pts = |p: &[Point<Number>]| convert_points::<S>(p, path);
        let ws =
            |w: &Option<Vec<Number>>| w.as_ref().map(|w| convert_all::<S>(w, path)).transpose();
        Ok(match c {
            CurveIn::Bezier { points, weights } => match ws(weights)? {
                None => Curve::Bezier(BezierCurve::try_new(pts(points)?).map_err(at(path))?),
                Some(w) => Curve::RationalBezier(
                    RationalBezierCurve::try_new(pts(points)?, w).map_err(at(path))?,
                ),
            },
            CurveIn::BSpline {
                points,
                degree,
                knots,
                weights,
            } => {
                let knots = convert_all::<S>(knots, path)?;
                match ws(weights)? {
                    None => Curve::BSpline(
                        BSplineCurve::read(*degree, knots, pts(points)?)
                            .map_err(at(path))?
                            .0,
                    ),
                    Some(w) => Curve::Nurbs(
                        NurbsCurve::read(*degree, knots, pts(points)?, w)
                            .map_err(at(path))?
                            .0,
                    ),
                }
            }
            CurveIn::Expr(e) => Curve::Map(convert_map::<S>(e, path)?),
        })
    }

    /// c(t).
    pub fn eval(&self, path: &str, t: &S) -> Result<Point<S>, ProblemError> {
        match self {
            Curve::Bezier(c) => c.eval(t).map_err(at(path)),
            Curve::RationalBezier(c) => c.eval(t).map_err(at(path)),
            Curve::BSpline(c) => c.eval(t).map_err(at(path)),
            Curve::Nurbs(c) => c.eval(t).map_err(at(path)),
            Curve::Map(e) => {
                let var = curve_var(e);
                e.eval(&[(var, t.clone())]).map_err(at(path))
            }
        }
    }

    /// The degree (of the control polygon; of the map for an expression).
    pub fn degree(&self) -> usize {
        match self {
            Curve::Bezier(c) => c.degree(),
            Curve::RationalBezier(c) => c.degree(),
            Curve::BSpline(c) => c.degree(),
            Curve::Nurbs(c) => c.degree(),
            Curve::Map(e) => usize::try_from(e.degree()).unwrap_or(usize::MAX),
        }
    }

    /// The number of control points after elevating the degree by `r`, known before the work:
    /// n + r for a Bézier curve, n + r·s for a B-spline of s spans.
    pub fn elevated_len(&self, r: usize) -> usize {
        match self {
            Curve::BSpline(c) => c.knots().elevated_point_count(r),
            Curve::Nurbs(c) => c.knots().elevated_point_count(r),
            _ => self.point_count().saturating_add(r),
        }
    }

    /// The number of control points (none for an expression).
    pub fn point_count(&self) -> usize {
        match self {
            Curve::Bezier(c) => c.points().len(),
            Curve::RationalBezier(c) => c.points().len(),
            Curve::BSpline(c) => c.points().len(),
            Curve::Nurbs(c) => c.points().len(),
            Curve::Map(_) => 0,
        }
    }

    /// The curve as an exact value, knots in the notes' convention.
    pub fn to_exact(&self) -> Exact {
        let ws = |w: &[S]| Some(w.iter().map(exact).collect());
        let knots = |k: &KnotVector<S>| {
            k.to_convention(KnotConvention::Notes)
                .iter()
                .map(exact)
                .collect()
        };
        Exact::Curve(match self {
            Curve::Bezier(c) => CurveIn::Bezier {
                points: exact_points(c.points()),
                weights: None,
            },
            Curve::RationalBezier(c) => CurveIn::Bezier {
                points: exact_points(c.points()),
                weights: ws(c.weights()),
            },
            Curve::BSpline(c) => CurveIn::BSpline {
                points: exact_points(c.points()),
                degree: c.degree(),
                knots: knots(c.knots()),
                weights: None,
            },
            Curve::Nurbs(c) => CurveIn::BSpline {
                points: exact_points(c.points()),
                degree: c.degree(),
                knots: knots(c.knots()),
                weights: ws(c.weights()),
            },
            Curve::Map(e) => CurveIn::Expr(exact_map(e)),
        })
    }
}

/// The variable of a curve given as an expression: its only variable (t when constant).
pub fn curve_var<S: Scalar>(e: &VecPoly<S>) -> Var {
    e.vars().first().copied().unwrap_or(Var::T)
}
