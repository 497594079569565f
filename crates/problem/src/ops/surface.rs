//! Operations on one surface (or curve): closed forms, graphs, derivatives.

use super::curve::Curve;
use super::patch::Patch;
use super::{at, req, Out, Run};
use crate::problem::{ClosedForm, Graph};
use crate::spec::Orders;
use crate::value::{exact_map, exact_rational, Exact, ExactScalar};
use crate::ProblemError;
use cagd_poly::{Poly, Var};
use cagd_surface::BezierSurface;

/// The closed form of a surface (`surface`) or a curve (`curve`), from the validated patch or
/// curve (a zero weight is refused, not printed).
pub(crate) fn closed_form<S: ExactScalar>(
    a: &ClosedForm,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    if let Some(surface) = &a.surface {
        let sf = "surface";
        let e = match Patch::<S>::read(surface, sf)? {
            Patch::Bezier(s) => Exact::Map(exact_map(&s.closed_form().map_err(at(sf))?)),
            Patch::RationalBezier(s) => {
                Exact::Rational(exact_rational(&s.closed_form().map_err(at(sf))?))
            }
            Patch::Map(e) => Exact::Map(exact_map(&e)),
            Patch::BSpline(_) | Patch::Nurbs(_) => {
                return Err(ProblemError::at(
                    sf,
                    "a B-spline surface has one closed form per patch: split it into Bézier patches first",
                ))
            }
        };
        return Ok(run.out().result("closed_form", e));
    }
    if let Some(curve) = &a.curve {
        let cf = "curve";
        let e = match Curve::<S>::read(curve, cf)? {
            Curve::Bezier(c) => Exact::Map(exact_map(&c.closed_form(Var::T))),
            Curve::RationalBezier(c) => Exact::Rational(exact_rational(&c.closed_form(Var::T))),
            Curve::Map(e) => Exact::Map(exact_map(&e)),
            Curve::BSpline(_) | Curve::Nurbs(_) => return Err(ProblemError::at(
                cf,
                "a B-spline curve has one closed form per span: split it into Bézier pieces first",
            )),
        };
        return Ok(run.out().result("closed_form", e));
    }
    Err(ProblemError::at(
        "",
        "closed_form needs a `surface` or a `curve`",
    ))
}

/// The graph of f(x, y) as a Bézier patch of bidegree (m, n), notes chapter 5 eq. (3):
/// c_ij = (i/m, j/n, ĉ_ij) where ĉ_ij are the Bernstein coefficients of f.
pub(crate) fn graph<S: ExactScalar>(a: &Graph, run: Run<'_>) -> Result<Out, ProblemError> {
    let f = req(&a.f, "f")?;
    let poly: Poly<S> = f.scalar().map_err(|e| ProblemError::at("f", e))?;
    // The notes write f(x, y); u and v are accepted too.
    let poly = poly
        .substitute(Var::X, &Poly::var(Var::U))
        .substitute(Var::Y, &Poly::var(Var::V));
    let (m, n, path) = match a.degree {
        Some(Orders::Two(m, n)) => (
            run.degree("degree[0]", m)?,
            run.degree("degree[1]", n)?,
            "degree",
        ),
        Some(Orders::One(n)) => {
            return Err(ProblemError::at(
                "degree",
                format!("expected two integers [m, n], found the number {}", n.0),
            ))
        }
        None => {
            let degree = |var| usize::try_from(poly.degree_in(var).max(1)).unwrap_or(usize::MAX);
            (degree(Var::U), degree(Var::V), "f")
        }
    };
    run.check_points(
        path,
        m.saturating_add(1).saturating_mul(n.saturating_add(1)),
        &format!("the graph of bidegree ({m}, {n})"),
    )?;
    // chapter 5's construction itself (cagd-surface), in u and v
    let surface = BezierSurface::graph(&poly, m, n).map_err(at("f"))?;
    let closed = surface.closed_form().map_err(at("f"))?;
    Ok(run
        .out()
        .result("surface", Patch::Bezier(surface).to_exact())
        .result("closed_form", Exact::Map(exact_map(&closed))))
}
