//! Operations on curves: evaluation, elevation, restriction, derivatives, knot insertion, and
//! circles.

use super::Out;
use crate::input::{CurveIn, Field};
use crate::value::{exact, exact_map, exact_points, Exact, ExactScalar};
use crate::ProblemError;
use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_bspline::{circle_of_arcs, BSplineCurve, KnotConvention, KnotVector, NurbsCurve};
use cagd_linalg::Point;
use cagd_poly::{Var, VecPoly};
use cagd_scalar::Scalar;

/// A validated curve of any kind.
pub(crate) enum Curve<S: Scalar> {
    Bezier(BezierCurve<S>),
    Rational(RationalBezierCurve<S>),
    BSpline(BSplineCurve<S>),
    Nurbs(NurbsCurve<S>),
    Expr(VecPoly<S>),
}

/// The error of a curve algorithm, at the field of the curve.
fn at<'f, E: std::fmt::Display>(f: &'f Field<'_>) -> impl Fn(E) -> ProblemError + 'f {
    move |e| f.error(e.to_string())
}

impl<S: ExactScalar> Curve<S> {
    /// Validates the curve written at `f`.
    pub fn read(f: &Field<'_>) -> Result<Self, ProblemError> {
        Ok(match f.curve::<S>()? {
            CurveIn::Bezier {
                points,
                weights: None,
            } => Curve::Bezier(BezierCurve::try_new(points).map_err(at(f))?),
            CurveIn::Bezier {
                points,
                weights: Some(w),
            } => Curve::Rational(RationalBezierCurve::try_new(points, w).map_err(at(f))?),
            CurveIn::BSpline {
                points,
                degree,
                knots,
                weights: None,
            } => Curve::BSpline(BSplineCurve::read(degree, knots, points).map_err(at(f))?.0),
            CurveIn::BSpline {
                points,
                degree,
                knots,
                weights: Some(w),
            } => Curve::Nurbs(NurbsCurve::read(degree, knots, points, w).map_err(at(f))?.0),
            CurveIn::Expr(e) => Curve::Expr(e),
        })
    }

    /// c(t).
    pub fn eval(&self, f: &Field<'_>, t: &S) -> Result<Point<S>, ProblemError> {
        match self {
            Curve::Bezier(c) => c.eval(t).map_err(at(f)),
            Curve::Rational(c) => c.eval(t).map_err(at(f)),
            Curve::BSpline(c) => c.eval(t).map_err(at(f)),
            Curve::Nurbs(c) => c.eval(t).map_err(at(f)),
            Curve::Expr(e) => {
                let var = curve_var(e);
                e.eval(&[(var, t.clone())]).map_err(at(f))
            }
        }
    }

    /// The degree (of the control polygon; of the map for an expression).
    pub fn degree(&self) -> usize {
        match self {
            Curve::Bezier(c) => c.degree(),
            Curve::Rational(c) => c.degree(),
            Curve::BSpline(c) => c.degree(),
            Curve::Nurbs(c) => c.degree(),
            Curve::Expr(e) => usize::try_from(e.degree()).unwrap_or(usize::MAX),
        }
    }

    /// The number of control points (none for an expression).
    pub fn len(&self) -> usize {
        match self {
            Curve::Bezier(c) => c.points().len(),
            Curve::Rational(c) => c.points().len(),
            Curve::BSpline(c) => c.points().len(),
            Curve::Nurbs(c) => c.points().len(),
            Curve::Expr(_) => 0,
        }
    }

    /// The curve as an exact value, knots in the notes' convention.
    pub fn exact(&self) -> Exact {
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
            Curve::Rational(c) => CurveIn::Bezier {
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
            Curve::Expr(e) => CurveIn::Expr(exact_map(e)),
        })
    }
}

/// The variable of a curve given as an expression: its only variable (t when constant).
pub(crate) fn curve_var<S: Scalar>(e: &VecPoly<S>) -> Var {
    e.vars().first().copied().unwrap_or(Var::T)
}

/// `evaluate` on a curve: the points c(t) for `params`.
pub(crate) fn evaluate<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let cf = p.req("curve")?;
    let c = Curve::<S>::read(&cf)?;
    let mut points = Vec::new();
    for t in p.req("params")?.items()? {
        points.push(c.eval(&t, &t.scalar::<S>()?)?);
    }
    Ok(Out::default().result("points", Exact::Points(exact_points(&points))))
}

/// `elevate` on a curve by `by` = r.
pub(crate) fn elevate<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let cf = p.req("curve")?;
    let by = p.req("by")?;
    let r = by.usize()?;
    let c = Curve::<S>::read(&cf)?;
    if !matches!(c, Curve::Expr(_)) {
        let p0 = c.degree();
        by.check_degree(
            p0.saturating_add(r),
            &format!("elevating degree {p0} by {r}"),
        )?;
    }
    let c =
        match c {
            Curve::Bezier(c) => Curve::Bezier(c.elevate_degree(r)),
            Curve::Rational(c) => Curve::Rational(c.elevate_degree(r).map_err(at(&cf))?),
            Curve::BSpline(c) => Curve::BSpline(c.elevate_degree(r).map_err(at(&cf))?),
            Curve::Nurbs(c) => Curve::Nurbs(c.elevate_degree(r).map_err(at(&cf))?),
            Curve::Expr(_) => return Err(cf.error(
                "a curve given as an expression has no degree to elevate; give its control polygon",
            )),
        };
    cf.check_points(c.len(), "the elevated curve")?;
    Ok(Out::default().result("curve", c.exact()))
}

/// `restrict` a Bézier curve to `t` = [a, b] (the control polygon of c on [a, b], read on [0, 1]).
pub(crate) fn restrict<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let cf = p.req("curve")?;
    let (a, b) = p.req("t")?.pair::<S>()?;
    let c = match Curve::<S>::read(&cf)? {
        Curve::Bezier(c) => Curve::Bezier(
            c.restrict(&a, &b)
                .and_then(|r| r.with_domain(S::zero(), S::one()))
                .map_err(at(&cf))?,
        ),
        Curve::Rational(c) => Curve::Rational(
            c.restrict(&a, &b)
                .and_then(|r| r.with_domain(S::zero(), S::one()))
                .map_err(at(&cf))?,
        ),
        _ => {
            return Err(cf.error(
                "restriction is for Bézier curves; split a B-spline at knots with insert_knot",
            ))
        }
    };
    Ok(Out::default().result("curve", c.exact()))
}

/// `derivative` of order r of a curve: the derivative curve's control polygon (Bézier), or
/// its closed form.
pub(crate) fn derivative<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let cf = p.req("curve")?;
    let r = p.req("order")?.degree()?;
    match Curve::<S>::read(&cf)? {
        Curve::Bezier(c) => {
            let d = c.derivative(r);
            let closed = d.closed_form(Var::T);
            Ok(Out::default()
                .result("curve", Curve::Bezier(d).exact())
                .result("closed_form", Exact::Map(exact_map(&closed))))
        }
        Curve::Expr(e) => {
            let var = curve_var(&e);
            let mut d = e;
            for _ in 0..r {
                if d.is_zero() {
                    break;
                }
                d = d.partial(var);
            }
            Ok(Out::default().result("closed_form", Exact::Map(exact_map(&d))))
        }
        _ => Err(cf.error(
            "derivatives of rational and B-spline curves are given by `evaluate`-ing their closed form; not available as a curve yet",
        )),
    }
}

/// `insert_knot` into a B-spline or NURBS curve.
pub(crate) fn insert_knot<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let cf = p.req("curve")?;
    let knot = p.req("knot")?.scalar::<S>()?;
    let times = p.get("times").map(|t| t.degree()).transpose()?.unwrap_or(1);
    let c = match Curve::<S>::read(&cf)? {
        Curve::BSpline(c) => Curve::BSpline(c.insert_knot(&knot, times).map_err(at(&cf))?),
        Curve::Nurbs(c) => Curve::Nurbs(c.insert_knot(&knot, times).map_err(at(&cf))?),
        _ => return Err(cf.error("knot insertion needs a B-spline curve (`bspline`, `knots`)")),
    };
    Ok(Out::default().result("curve", c.exact()))
}

/// `circle`: the circle of `radius` (default 1) about `center` (default the origin of R^3, the
/// circle in the plane z = c_z) as a quadratic NURBS of `arcs` arcs (default 4) on `interval`
/// (default [0, 1]; the slides use [0, 4]).
pub(crate) fn circle<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let radius = p
        .get("radius")
        .map(|r| r.scalar::<S>())
        .transpose()?
        .unwrap_or_else(S::one);
    let arcs_field = p.get("arcs");
    let arcs = arcs_field
        .as_ref()
        .map(Field::count)
        .transpose()?
        .unwrap_or(4);
    if let Some(a) = &arcs_field {
        a.check_points(arcs.saturating_mul(2).saturating_add(1), "the circle")?;
    }
    let center = match p.get("center") {
        Some(c) => c.point::<S>()?,
        None => Point::zero(3),
    };
    if center.dim() < 2 {
        return Err(p.error("the center of a circle needs at least two coordinates"));
    }
    let domain = match p.get("interval") {
        Some(i) => i.pair::<S>()?,
        None => (S::zero(), S::one()),
    };
    let c = circle_of_arcs(arcs, &radius, None, domain).map_err(|e| p.error(e.to_string()))?;
    let moved: Vec<Point<S>> = c
        .points()
        .iter()
        .map(|q| {
            let mut coords = center.coords().to_vec();
            for (c, x) in coords.iter_mut().zip(q.coords()).take(2) {
                *c = c.add_ref(x);
            }
            Point::new(coords)
        })
        .collect();
    let moved = NurbsCurve::try_new(c.knots().clone(), moved, c.weights().to_vec())
        .map_err(|e| p.error(e.to_string()))?;
    Ok(Out::default().result("curve", Curve::Nurbs(moved).exact()))
}
