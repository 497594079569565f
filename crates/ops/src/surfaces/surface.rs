//! Operations on one surface (or curve): closed forms, graphs, derivatives.

use crate::any::AnyCurve as Curve;
use crate::any::AnySurface as Patch;
use crate::message::surface::Surface;
use crate::out::{at, req, Out, Run};
use crate::problem::{ClosedForm, Graph};
use crate::spec::Orders;
use crate::steps::Formula;
use crate::value::Quantity;
use crate::value::{exact, exact_map, exact_rational, Exact, ExactScalar};
use crate::ProblemError;
use cagd_poly::{Poly, Var};
use cagd_surface::BezierSurface;

/// The closed form of a surface (`surface`) or a curve (`curve`), from the validated patch or
/// curve (a zero weight is refused, not printed).
pub(crate) fn closed_form<S: ExactScalar>(
    a: &ClosedForm,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let mut out = run.out();
    if let Some(surface) = &a.surface {
        let sf = "surface";
        let patch = Patch::<S>::read(surface, sf)?;
        if out.steps_on() {
            match &patch {
                Patch::Bezier(s) => {
                    out.formula(Formula::BernsteinSurface);
                    bernstein_polys::<S>(&mut out, s.bidegree());
                }
                Patch::RationalBezier(s) => {
                    out.formula(Formula::RationalSurface);
                    bernstein_polys::<S>(&mut out, s.bidegree());
                }
                _ => {}
            }
        }
        let e = match patch {
            // the coefficients built as the answer's numbers (no second copy to convert)
            Patch::Bezier(s) => Exact::Map(s.closed_form_in(exact).map_err(at(sf))?),
            Patch::RationalBezier(s) => {
                Exact::Rational(exact_rational(&s.closed_form().map_err(at(sf))?))
            }
            Patch::Map(e) => Exact::Map(exact_map(&e)),
            Patch::BSpline(_) | Patch::Nurbs(_) => {
                return crate::pieces::closed_form(&patch, sf, out);
            }
        };
        return Ok(out.closed_form(e));
    }
    if let Some(curve) = &a.curve {
        let cf = "curve";
        let curve = Curve::<S>::read_with_vectors(curve, cf)?;
        if out.steps_on() {
            let n = curve.degree();
            match &curve {
                Curve::Bezier(_) => out.formula(Formula::ClosedFormCurve),
                Curve::RationalBezier(_) => out.formula(Formula::ClosedFormRationalCurve),
                _ => {}
            }
            if matches!(curve, Curve::Bezier(_) | Curve::RationalBezier(_)) {
                for i in 0..=n {
                    out.value(
                        format!("B_{{{i}}}^{{{n}}}(t)"),
                        Exact::Poly(crate::value::exact_poly(&cagd_poly::bernstein::<S>(
                            i,
                            n,
                            Var::T,
                        ))),
                    );
                }
            }
        }
        let e = match curve {
            Curve::Bezier(c) => Exact::Map(exact_map(&c.closed_form(Var::T))),
            Curve::RationalBezier(c) => Exact::Rational(exact_rational(&c.closed_form(Var::T))),
            Curve::Map(e) => Exact::Map(exact_map(&e)),
            Curve::BSpline(_) | Curve::Nurbs(_) => {
                return crate::pieces::curve_closed_form(&curve, cf, out)
            }
        };
        return Ok(out.closed_form(e));
    }
    Err(ProblemError::at("", Surface::ClosedFormNeeds))
}

/// The Bernstein polynomials B_i^m(u) and B_j^n(v) of a closed form.
fn bernstein_polys<S: ExactScalar>(out: &mut Out, (m, n): (usize, usize)) {
    for (deg, var, name) in [(m, Var::U, "u"), (n, Var::V, "v")] {
        for i in 0..=deg {
            out.value(
                format!("B_{{{i}}}^{{{deg}}}({name})"),
                Exact::Poly(crate::value::exact_poly(&cagd_poly::bernstein::<S>(
                    i, deg, var,
                ))),
            );
        }
    }
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
                Surface::TwoIntegersFoundNumber {
                    found: n.0.to_string(),
                },
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
        crate::message::limited::Limited::Graph { m, n },
    )?;
    // chapter 5's construction itself (cagd-surface), in u and v
    let surface = BezierSurface::graph(&poly, m, n).map_err(at("f"))?;
    let closed = surface.closed_form().map_err(at("f"))?;
    let mut out = run.out();
    if out.steps_on() {
        out.formula(Formula::Graph);
        let hat: Vec<Vec<S>> = surface
            .mesh()
            .to_rows()
            .iter()
            .map(|r| {
                r.iter()
                    .map(|p| p.coords().last().cloned().unwrap_or_else(S::zero))
                    .collect()
            })
            .collect();
        out.value("\\hat{c}_{i,j}", Exact::matrix(&hat));
    }
    Ok(out
        .result(Quantity::Surface, Patch::Bezier(surface).to_exact())
        .closed_form(Exact::Map(exact_map(&closed))))
}
