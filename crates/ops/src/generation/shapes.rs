//! Curves and surfaces built from few data: conics from a shape factor, and the tangent
//! developable of a curve with its edge of regression.

use crate::any::AnyCurve as Curve;
use crate::any::AnySurface as Patch;
use crate::message::curve::Curve as Say;
use crate::out::{at, num, req, Out, Run};
use crate::problem::{Conic, TangentDevelopable};
use crate::spec::Points;
use crate::steps::Formula;
use crate::value::Quantity;
use crate::value::{exact_map, exact_rational, Exact, ExactScalar};
use crate::ProblemError;
use cagd_bezier::conic_arc;
use cagd_poly::{Poly, Var, VecPoly};
use std::cmp::Ordering;

/// `conic`: the conic arc from `points` = [c_0, c_1, c_2] (c_1 where the end tangents meet)
/// with the weights (1, w, 1), w the `weight` (Farin, ch. 12): the shape factor
/// `w_1² / (w_0 w_2) = w²` says which conic, an ellipse below 1 (a circle when the polygon is
/// isosceles with w = cos of half the arc), a parabola at 1, a hyperbola above.
pub(crate) fn conic<S: ExactScalar>(a: &Conic, run: Run<'_>) -> Result<Out, ProblemError> {
    let Points(pts) = req(&a.points, "points")?;
    let pts = crate::convert::convert_points::<S>(pts, "points")?;
    let [c0, c1, c2] = pts.as_slice() else {
        return Err(ProblemError::at(
            "points",
            Say::ConicThreePoints { found: pts.len() },
        ));
    };
    let w = num::<S>(req(&a.weight, "weight")?, "weight")?;
    if w == S::zero() {
        return Err(ProblemError::at("weight", Say::ConicZeroWeight));
    }
    let curve = conic_arc(c0.clone(), c1.clone(), c2.clone(), w.clone()).map_err(at("points"))?;
    let mut out = run.out();
    out.formula(Formula::ConicShape);
    let factor = w.clone() * w.clone();
    out.value(
        "w_1^2 / (w_0 w_2)",
        Exact::Number(crate::value::exact(&factor)),
    );
    let kind = match factor.compare(&S::one()) {
        Some(Ordering::Less) => Say::Ellipse,
        Some(Ordering::Equal) => Say::Parabola,
        Some(Ordering::Greater) => Say::Hyperbola,
        None => Say::ConicUndecided,
    };
    let closed = curve.closed_form(Var::T);
    Ok(out
        .result(Quantity::Curve, Curve::RationalBezier(curve).to_exact())
        .result(
            Quantity::ShapeFactor,
            Exact::Number(crate::value::exact(&factor)),
        )
        .result(Quantity::ConicKind, Exact::Sentence(kind.into()))
        .closed_form(Exact::Rational(exact_rational(&closed))))
}

/// `tangent_developable`: the surface ruled by the tangents of a polynomial curve c(u),
/// `c(u, v) = c(u) + v c'(u)` (the slides' "superficies tangentes"), as a Bézier patch of
/// bidegree (m, 1) for a Bézier curve (columns c_i and c_i + h_i, h_i the hodograph raised to
/// degree m). Its normal is `c_u × c_v = v c''(u) × c'(u)`, which vanishes on v = 0: the curve
/// itself is the edge of regression, where the surface is singular (`edge_of_regression`).
/// The Gaussian curvature's numerator (eq. (8)) is zero: `developable`.
pub(crate) fn tangent_developable<S: ExactScalar>(
    a: &TangentDevelopable,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let cf = "curve";
    let curve = Curve::<S>::read(req(&a.curve, cf)?, cf)?;
    let mut out = run.out();
    out.formula(Formula::TangentDevelopable);
    let (c, surface): (VecPoly<S>, Option<Patch<S>>) = match curve {
        Curve::Bezier(b) => {
            let s = cagd_generate::tangent_bezier(&b).map_err(at(cf))?;
            (b.closed_form(Var::U), Some(Patch::Bezier(s)))
        }
        Curve::Map(e) => {
            let var = crate::any_curve::curve_var(&e);
            let e = if var == Var::U {
                e
            } else {
                e.substitute(var, &Poly::var(Var::U))
            };
            (e, None)
        }
        _ => return Err(ProblemError::at(cf, Say::TangentDevelopablePolynomial)),
    };
    if c.dim() != 3 {
        return Err(ProblemError::at(cf, Say::TangentDevelopableR3));
    }
    let closed = cagd_generate::tangent_surface(&c).map_err(at(cf))?;
    let d1 = c.partial(Var::U);
    let d2 = d1.partial(Var::U);
    let normal = d2.cross(&d1).map_err(at(cf))?.mul_poly(&Poly::var(Var::V));
    if out.steps_on() {
        out.value("c'(u)", Exact::Map(exact_map(&d1)));
        out.value("c''(u)", Exact::Map(exact_map(&d2)));
    }
    let g = crate::surfaces::curvature::numerator_polynomial(&closed, cf)?;
    if let Some(s) = surface {
        out = out.result(Quantity::Surface, s.to_exact());
    }
    Ok(out
        .closed_form(Exact::Map(exact_map(&closed)))
        .result(Quantity::Normal, Exact::Map(exact_map(&normal)))
        .result(Quantity::EdgeOfRegression, Exact::Map(exact_map(&c)))
        .result(Quantity::Developable, Exact::Bool(g.is_zero())))
}
