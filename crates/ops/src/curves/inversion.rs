//! `invert_point`: the parameters t of a curve's domain with c(t) = P, exactly (The NURBS
//! Book §6.1 asks for them by Newton's method; here they are the common roots of the
//! coordinates' numerators x_i(t) - P_i w(t), found by cagd-poly's [`common_roots`]: in the
//! field, in Q(√d) for a quadratic factor, or refused saying why). A B-spline or NURBS curve
//! is inverted piece by piece, on each span's closed form.

use crate::any::AnyCurve as Curve;
use crate::any_curve::curve_var;
use crate::convert::convert_points;
use crate::message::curve::Curve as Say;
use crate::out::{at, req, Out, Run};
use crate::pieces::{curve_forms, PieceForm};
use crate::problem::InvertPoint;
use crate::steps::Formula;
use crate::value::quantity::Quantity;
use crate::value::{exact, exact_poly, Exact, ExactScalar};
use crate::ProblemError;
use cagd_poly::{common_roots, sign_on, ExactRoot, Poly, Var};
use cagd_scalar::Quadratic;
use std::cmp::Ordering;

/// One piece to invert on: its span, the numerators x_i(t) - P_i w(t), and its variable.
type Numerators<S> = ((S, S), Vec<Poly<S>>, Var);

/// The numerators x_i - P_i w of a closed form against the point P.
fn numerators<S: ExactScalar>(form: &PieceForm<S>, p: &[S]) -> Vec<Poly<S>> {
    match form {
        PieceForm::Polynomial(m) => m
            .components()
            .iter()
            .zip(p)
            .map(|(x, pi)| x.clone() - Poly::constant(pi.clone()))
            .collect(),
        PieceForm::Rational(r) => r
            .numerator()
            .components()
            .iter()
            .zip(p)
            .map(|(x, pi)| x.clone() - r.denominator().scale(pi))
            .collect(),
    }
}

/// Whether `x` lies in [a, b] (a root in letters, whose order is not decided, is kept).
fn within<T: ExactScalar>(x: &T, (a, b): (&T, &T)) -> bool {
    x.compare(a) != Some(Ordering::Less) && x.compare(b) != Some(Ordering::Greater)
}

/// `invert_point`: the parameters of `point` on `curve`.
pub(crate) fn invert_point<S: ExactScalar>(
    a: &InvertPoint,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let cf = "curve";
    let curve = Curve::<S>::read_with_vectors(req(&a.curve, cf)?, cf)?;
    let written = req(&a.point, "point")?;
    let p = convert_points::<S>(std::slice::from_ref(&written.0), "point")?
        .pop()
        .ok_or_else(|| ProblemError::at("point", Say::InvertDimension { point: 0, curve: 0 }))?;
    let whole = curve.domain();
    let pieces: Vec<Numerators<S>> = match &curve {
        Curve::Bezier(b) => {
            let form = PieceForm::Polynomial(b.closed_form(Var::T));
            vec![(whole, numerators(&form, p.coords()), Var::T)]
        }
        Curve::RationalBezier(r) => {
            let form = PieceForm::Rational(r.closed_form(Var::T));
            vec![(whole, numerators(&form, p.coords()), Var::T)]
        }
        Curve::Map(e) => {
            let form = PieceForm::Polynomial(e.clone());
            vec![(whole, numerators(&form, p.coords()), curve_var(e))]
        }
        Curve::BSpline(_) | Curve::Nurbs(_) => curve_forms(&curve, cf)?
            .unwrap_or_default()
            .into_iter()
            .map(|(span, form)| (span, numerators(&form, p.coords()), Var::T))
            .collect(),
    };
    let dim = match &curve {
        Curve::Map(e) => e.dim(),
        Curve::Bezier(b) => b.dim(),
        Curve::RationalBezier(r) => r.dim(),
        Curve::BSpline(b) => b.dim(),
        Curve::Nurbs(n) => n.points().first().map_or(0, |x| x.dim()),
    };
    if p.dim() != dim {
        return Err(ProblemError::at(
            "point",
            Say::InvertDimension {
                point: p.dim(),
                curve: dim,
            },
        ));
    }
    let mut out = run.out();
    out.formula(Formula::PointInversion);
    let mut found: Vec<Exact> = Vec::new();
    let mut seen: Vec<Quadratic> = Vec::new();
    for ((lo, hi), polys, var) in &pieces {
        if out.steps_on() {
            for (i, x) in polys.iter().enumerate() {
                out.value(
                    format!("x_{}(t) - P_{} w(t)", i + 1, i + 1),
                    Exact::Poly(exact_poly(x)),
                );
            }
        }
        let roots = common_roots(polys, *var).map_err(at(cf))?;
        if out.steps_on() {
            out.value("g(t)", Exact::Poly(exact_poly(&roots.gcd)));
        }
        if let Some((rest, why)) = roots.rest {
            // a factor whose roots are no numbers of the field: refused unless it has no root
            // on the span (one sign there, by its Bernstein coefficients, and not zero at the
            // ends)
            let at_end = |x: &S| rest.eval(&[(*var, x.clone())]).map(|v| v.is_zero());
            let clear = sign_on(&rest, *var, lo, hi).is_some()
                && at_end(lo) == Ok(false)
                && at_end(hi) == Ok(false);
            if !clear {
                return Err(ProblemError::at(cf, why));
            }
        }
        for root in roots.found {
            let (inside, value) = match &root {
                ExactRoot::Field(t) => (within(t, (lo, hi)), exact(t)),
                ExactRoot::Surd(q) => {
                    let ends = (lo.to_number(), hi.to_number());
                    let inside = match ends {
                        (Some(x), Some(y)) => within(q, (&x, &y)),
                        _ => true,
                    };
                    (inside, exact(q))
                }
            };
            if !inside {
                continue;
            }
            // a root at a knot shared by two pieces is one parameter
            if let Some(n) = root.to_number() {
                if seen.contains(&n) {
                    continue;
                }
                seen.push(n);
            }
            found.push(Exact::Number(value));
        }
    }
    let on = !found.is_empty();
    if !on {
        out.remark(Say::NotOnCurve);
    }
    Ok(out
        .result(Quantity::Inverse, Exact::List(found))
        .result(Quantity::OnCurve, Exact::Bool(on)))
}
