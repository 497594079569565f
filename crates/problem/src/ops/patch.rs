//! Operations on one tensor-product patch (chapter 5): evaluation, restriction, elevation,
//! derivatives, normals, and the continuity of two patches.

use super::surface::mesh_map;
use super::Out;
use crate::input::{Field, SurfaceIn};
use crate::value::{exact_map, exact_point, exact_points, exact_rational, Exact, ExactScalar};
use crate::ProblemError;
use cagd_linalg::Point;
use cagd_poly::{Var, VecPoly};
use cagd_spline_surface::{BSplineSurface, Direction, NurbsSurface};
use cagd_surface::{
    continuity as join_continuity, BezierSurface, Join, NormalAtCorner, RationalBezierSurface,
    Smoothness,
};

/// A validated surface.
pub(crate) enum Patch<S: ExactScalar> {
    Bezier(BezierSurface<S>),
    Rational(RationalBezierSurface<S>),
    BSpline(BSplineSurface<S>),
    Nurbs(NurbsSurface<S>),
    Expr(VecPoly<S>),
}

/// The error for an operation that needs a Bézier patch.
fn not_bezier<T>(f: &Field<'_>, what: &str) -> Result<T, ProblemError> {
    Err(f.error(format!(
        "{what} needs a Bézier patch (`bezier`); for a B-spline surface, split it into Bézier patches first"
    )))
}

fn at<'f, E: std::fmt::Display>(f: &'f Field<'_>) -> impl Fn(E) -> ProblemError + 'f {
    move |e| f.error(e.to_string())
}

impl<S: ExactScalar> Patch<S> {
    pub fn read(f: &Field<'_>) -> Result<Self, ProblemError> {
        Ok(match f.surface::<S>()? {
            SurfaceIn::Bezier {
                mesh,
                weights: None,
            } => Patch::Bezier(BezierSurface::try_new(mesh).map_err(at(f))?),
            SurfaceIn::Bezier {
                mesh,
                weights: Some(w),
            } => Patch::Rational(RationalBezierSurface::try_new(mesh, w).map_err(at(f))?),
            SurfaceIn::Expr(e) => Patch::Expr(e),
            SurfaceIn::BSpline {
                mesh,
                degree,
                knots,
                weights: None,
            } => Patch::BSpline(BSplineSurface::read(degree, knots, mesh).map_err(at(f))?.0),
            SurfaceIn::BSpline {
                mesh,
                degree,
                knots,
                weights: Some(w),
            } => Patch::Nurbs(NurbsSurface::read(degree, knots, mesh, w).map_err(at(f))?.0),
        })
    }

    pub fn exact(&self) -> Exact {
        match self {
            Patch::Bezier(s) => Exact::bezier_surface(s.mesh(), None),
            Patch::Rational(s) => Exact::bezier_surface(s.mesh(), Some(s.weights())),
            Patch::BSpline(s) => Exact::spline_surface(s.knots_u(), s.knots_v(), s.mesh(), None),
            Patch::Nurbs(s) => {
                Exact::spline_surface(s.knots_u(), s.knots_v(), s.mesh(), Some(s.weights()))
            }
            Patch::Expr(e) => Exact::Surface(SurfaceIn::Expr(exact_map(e))),
        }
    }

    /// The bidegree (m, n) of a control mesh; `None` for an expression.
    fn bidegree(&self) -> Option<(usize, usize)> {
        match self {
            Patch::Bezier(s) => Some(s.bidegree()),
            Patch::Rational(s) => Some(s.bidegree()),
            Patch::BSpline(s) => Some(s.bidegree()),
            Patch::Nurbs(s) => Some(s.bidegree()),
            Patch::Expr(_) => None,
        }
    }

    fn eval(&self, f: &Field<'_>, u: &S, v: &S) -> Result<Point<S>, ProblemError> {
        match self {
            Patch::Bezier(s) => s.eval(u, v).map_err(at(f)),
            Patch::Rational(s) => s.eval(u, v).map_err(at(f)),
            Patch::BSpline(s) => s.eval(u, v).map_err(at(f)),
            Patch::Nurbs(s) => s.eval(u, v).map_err(at(f)),
            Patch::Expr(e) => e
                .eval(&[(Var::U, u.clone()), (Var::V, v.clone())])
                .map_err(at(f)),
        }
    }
}

/// `evaluate` a surface at `params` = [[u, v], ...].
pub(crate) fn evaluate<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let sf = p.req("surface")?;
    let s = Patch::<S>::read(&sf)?;
    let mut points = Vec::new();
    for uv in p.req("params")?.items()? {
        let (u, v) = uv.pair::<S>()?;
        points.push(s.eval(&uv, &u, &v)?);
    }
    Ok(Out::default().result("points", Exact::Points(exact_points(&points))))
}

/// `restrict` a patch to `u` = [a, b] × `v` = [c, d], eq. (13), with the row step ĉ.
pub(crate) fn restrict<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let sf = p.req("surface")?;
    let (a, b) = p.req("u")?.pair::<S>()?;
    let (c, d) = p.req("v")?.pair::<S>()?;
    let (rows_step, result) = match Patch::<S>::read(&sf)? {
        Patch::Bezier(s) => {
            let r = s.restrict(&a, &b, &c, &d).map_err(at(&sf))?;
            (Patch::Bezier(r.rows_step), Patch::Bezier(r.result))
        }
        Patch::Rational(s) => {
            let r = s.restrict(&a, &b, &c, &d).map_err(at(&sf))?;
            (Patch::Rational(r.rows_step), Patch::Rational(r.result))
        }
        _ => return not_bezier(&sf, "restriction"),
    };
    Ok(Out::default()
        .result("surface", result.exact())
        .step("c_hat", rows_step.exact()))
}

/// `elevate` a patch by `by` = [r, s], eq. (14)-(15).
pub(crate) fn elevate<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let sf = p.req("surface")?;
    let by = p.req("by")?;
    let (r, s_) = by.usize_pair()?;
    let patch = Patch::<S>::read(&sf)?;
    if let Some((m, n)) = patch.bidegree() {
        let (m2, n2) = (m.saturating_add(r), n.saturating_add(s_));
        by.check_degree(
            m2.max(n2),
            &format!("elevating bidegree ({m}, {n}) by ({r}, {s_})"),
        )?;
        if matches!(patch, Patch::Bezier(_) | Patch::Rational(_)) {
            by.check_points(
                m2.saturating_add(1).saturating_mul(n2.saturating_add(1)),
                &format!("the elevated patch of bidegree ({m2}, {n2})"),
            )?;
        }
    }
    let out = match patch {
        Patch::Bezier(s) => Patch::Bezier(s.elevate(r, s_).map_err(at(&sf))?),
        Patch::Rational(s) => Patch::Rational(s.elevate(r, s_).map_err(at(&sf))?),
        Patch::BSpline(s) => Patch::BSpline(s.elevate_degree(r, s_).map_err(at(&sf))?),
        Patch::Nurbs(s) => Patch::Nurbs(s.elevate_degree(r, s_).map_err(at(&sf))?),
        Patch::Expr(_) => {
            return Err(sf.error("degree elevation needs a control mesh (`bezier` or `bspline`)"))
        }
    };
    Ok(Out::default().result("surface", out.exact()))
}

/// `derivative` of order `order` = [r, s] of a patch: the derivative patch (18) and its closed
/// form, optionally on a border `at` = {"u": 1}.
pub(crate) fn derivative<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let sf = p.req("surface")?;
    let (r, s_) = p.req("order")?.degree_pair()?;
    let restrict_to = |mut d: VecPoly<S>| -> Result<VecPoly<S>, ProblemError> {
        if let Some(at) = p.get("at") {
            for (name, var) in [("u", Var::U), ("v", Var::V)] {
                if let Some(x) = at.get(name) {
                    d = d.substitute_value(var, &x.scalar::<S>()?);
                }
            }
        }
        Ok(d)
    };
    let mut out = Out::default();
    match Patch::<S>::read(&sf)? {
        Patch::Bezier(s) => {
            let d = s.partial_derivative(r, s_).map_err(at(&sf))?;
            let closed = restrict_to(mesh_map(&sf, d.mesh())?)?;
            out = out
                .result("surface", Patch::Bezier(d).exact())
                .result("closed_form", Exact::Map(exact_map(&closed)));
        }
        Patch::Rational(s) => {
            let d = s.partial_derivative(r, s_).map_err(at(&sf))?;
            out = out.result("closed_form", Exact::Rational(exact_rational(&d)));
        }
        Patch::Expr(e) => {
            let mut d = e;
            for var in std::iter::repeat_n(Var::U, r).chain(std::iter::repeat_n(Var::V, s_)) {
                if d.is_zero() {
                    break;
                }
                d = d.partial(var);
            }
            out = out.result("closed_form", Exact::Map(exact_map(&restrict_to(d)?)));
        }
        _ => return not_bezier(&sf, "the derivative as a surface"),
    }
    Ok(out)
}

fn corner_value<S: ExactScalar>(n: &NormalAtCorner<S>) -> Exact {
    match n.normal() {
        Some(p) => Exact::Point(exact_point(p)),
        None => Exact::Text(n.to_text()),
    }
}

/// `normal`: c_u × c_v as a closed form, and at the four corners (25).
pub(crate) fn normal<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let sf = p.req("surface")?;
    let names = ["corner_00", "corner_10", "corner_01", "corner_11"];
    let mut out = Out::default();
    match Patch::<S>::read(&sf)? {
        Patch::Bezier(s) => {
            out = out.result(
                "closed_form",
                Exact::Map(exact_map(&s.normal().map_err(at(&sf))?)),
            );
            let corners = s.normals_at_corners().map_err(at(&sf))?;
            for (name, c) in names.iter().zip(corners.iter()) {
                out = out.result(name, corner_value(c));
            }
        }
        Patch::Rational(s) => {
            out = out.result(
                "closed_form",
                Exact::Rational(exact_rational(&s.normal().map_err(at(&sf))?)),
            );
            let corners = s.normals_at_corners().map_err(at(&sf))?;
            for (name, c) in names.iter().zip(corners.iter()) {
                out = out.result(name, corner_value(c));
            }
        }
        Patch::Expr(e) => {
            let n = e
                .partial(Var::U)
                .cross(&e.partial(Var::V))
                .map_err(at(&sf))?;
            out = out.result("closed_form", Exact::Map(exact_map(&n)));
        }
        _ => return not_bezier(&sf, "the normal"),
    }
    Ok(out)
}

/// `continuity` of two Bézier patches across `border` (21)-(23).
pub(crate) fn continuity<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let (ff, sf) = (p.req("first")?, p.req("second")?);
    let read = |f: &Field<'_>| match Patch::<S>::read(f)? {
        Patch::Bezier(s) => Ok(s),
        _ => Err(f.error("continuity takes two polynomial Bézier patches (`bezier`, no weights)")),
    };
    let (first, second) = (read(&ff)?, read(&sf)?);
    let join = match p.get("border") {
        None => Join::U,
        Some(b) => match b.str()? {
            "u" => Join::U,
            "v" => Join::V,
            other => {
                return Err(b.error(format!(
                    "expected \"u\" (first's u = 1 meets second's u = 0) or \"v\", found {other:?}"
                )))
            }
        },
    };
    let (du0, du1) = match p.get("lengths") {
        Some(l) => l.pair::<S>()?,
        None => (S::one(), S::one()),
    };
    let k = join_continuity(&first, &second, join, &du0, &du1).map_err(at(p))?;
    let order = match k.smoothness {
        Smoothness::NotContinuous => Exact::Int(-1),
        Smoothness::C(r) => Exact::Int(i64::try_from(r).unwrap_or(i64::MAX)),
        Smoothness::Infinite => Exact::Text("infinite".into()),
    };
    let mut out = Out::default()
        .result("order", order)
        .result("smoothness", Exact::Text(k.smoothness.to_string()));
    if let Some(f) = &k.failure {
        out = out.result("fails", Exact::Text(f.text.clone()));
    }
    out = out
        .result(
            "closed_form_first",
            Exact::Map(exact_map(&mesh_map(&ff, first.mesh())?)),
        )
        .result(
            "closed_form_second",
            Exact::Map(exact_map(&mesh_map(&sf, second.mesh())?)),
        )
        .result(
            "differences_first",
            Exact::Points(exact_points(&k.differences_first)),
        )
        .result(
            "differences_second",
            Exact::Points(exact_points(&k.differences_second)),
        )
        .result(
            "derivative_first",
            Exact::Map(exact_map(&k.derivative_first)),
        )
        .result(
            "derivative_second",
            Exact::Map(exact_map(&k.derivative_second)),
        );
    if let (Some(n1), Some(n2)) = (&k.normal_first, &k.normal_second) {
        out = out
            .result("normal_first", Exact::Map(exact_map(n1)))
            .result("normal_second", Exact::Map(exact_map(n2)));
    }
    Ok(out)
}

/// `insert_knot` into a B-spline or NURBS surface in `direction` `u` or `v`.
pub(crate) fn insert_knot<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let sf = p.req("surface")?;
    let knot = p.req("knot")?.scalar::<S>()?;
    let times = p.get("times").map(|t| t.degree()).transpose()?.unwrap_or(1);
    let df = p.req("direction")?;
    let dir = match df.str()? {
        "u" => Direction::U,
        "v" => Direction::V,
        other => return Err(df.error(format!("expected \"u\" or \"v\", found {other:?}"))),
    };
    let out = match Patch::<S>::read(&sf)? {
        Patch::BSpline(s) => Patch::BSpline(s.insert_knot(dir, &knot, times).map_err(at(&sf))?),
        Patch::Nurbs(s) => Patch::Nurbs(s.insert_knot(dir, &knot, times).map_err(at(&sf))?),
        _ => return Err(sf.error("knot insertion needs a B-spline surface (`bspline`, `knots`)")),
    };
    Ok(Out::default().result("surface", out.exact()))
}
