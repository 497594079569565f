//! `arc_length`: the length `∫_a^b |c'(t)| dt` of a polynomial curve where it is exact.
//!
//! The speed is `√(c'·c')`. When `c'·c' = σ(t)²` for a polynomial σ (a Pythagorean-hodograph
//! curve, Farouki; every line), the length is `∫_a^b |σ| dt`, exact: `|∫_a^b σ dt|` when σ keeps
//! its sign on [a, b], which the Bernstein coefficients of σ on [a, b] decide when they all
//! have one sign (the convex hull property). A line has a constant `c'·c' = q`: its length
//! `(b - a) √q` is exact in Q(√q) (written with the root when the problem's field has it not).
//! Otherwise the integral is in general no number of Q or of one Q(√d) (a parabola's has a
//! logarithm, most cubics' are elliptic integrals), and the answer says so, with `c'·c'`
//! exact: never a float.

use super::curve::{curve_var, Curve};
use super::{at, pair, req, Out, Run};
use crate::message::curve::Curve as Say;
use crate::problem::ArcLength;
use crate::steps::Formula;
use crate::value::{exact, exact_poly, Exact, ExactScalar};
use crate::ProblemError;
use cagd_poly::{sign_on, Var, VecPoly, SIGN_HALVINGS};
use std::cmp::Ordering;

/// `arc_length` of a polynomial `curve` (Bézier, expression or B-spline, piece by piece) on
/// its domain or on `t` = [a, b].
pub(crate) fn arc_length<S: ExactScalar>(a: &ArcLength, run: Run<'_>) -> Result<Out, ProblemError> {
    let cf = "curve";
    let curve = Curve::<S>::read(req(&a.curve, cf)?, cf)?;
    let (lo, hi) = match &a.t {
        Some(t) => pair::<S>(t, "t")?,
        None => curve.domain(),
    };
    // the polynomial pieces with their spans
    let pieces: Vec<((S, S), VecPoly<S>, Var)> = match &curve {
        Curve::Bezier(b) => vec![((lo.clone(), hi.clone()), b.closed_form(Var::T), Var::T)],
        Curve::Map(e) => vec![((lo.clone(), hi.clone()), e.clone(), curve_var(e))],
        Curve::BSpline(_) => super::pieces::curve_forms(&curve, cf)?
            .unwrap_or_default()
            .into_iter()
            .filter_map(|((x, y), f)| match f {
                super::pieces::PieceForm::Polynomial(m) => {
                    // the part of the span inside [lo, hi]
                    let x = if x.compare(&lo) == Some(Ordering::Less) {
                        lo.clone()
                    } else {
                        x
                    };
                    let y = if y.compare(&hi) == Some(Ordering::Greater) {
                        hi.clone()
                    } else {
                        y
                    };
                    (x.compare(&y) == Some(Ordering::Less)).then_some(((x, y), m, Var::T))
                }
                super::pieces::PieceForm::Rational(_) => None,
            })
            .collect(),
        Curve::RationalBezier(_) | Curve::Nurbs(_) => {
            return super::length_rational::rational_arc_length(&curve, (lo, hi), run)
        }
    };
    let mut out = run.out();
    out.formula(Formula::ArcLength);
    let mut total = S::zero();
    let mut speeds = Vec::new();
    let mut words: Option<Say> = None;
    for ((x, y), c, var) in &pieces {
        let d = c.partial(*var);
        let f = d.dot(&d).map_err(at(cf))?;
        speeds.push(Exact::Poly(exact_poly(&f)));
        if f.is_zero() {
            continue;
        }
        if let Some(sigma) = f.square_root(*var) {
            out.value("\\sigma(t)", Exact::Poly(exact_poly(&sigma)));
            match sign_on(&sigma, *var, x, y) {
                Some(Ordering::Less) => total -= sigma.definite_integral(*var, x, y),
                Some(_) => total += sigma.definite_integral(*var, x, y),
                None => {
                    words = Some(Say::SpeedChangesSign {
                        sigma: sigma.to_text(),
                        halvings: SIGN_HALVINGS,
                        from: x.to_text(),
                        to: y.to_text(),
                    });
                    break;
                }
            }
        } else if f.degree_in(*var) == 0 {
            // a line: (y - x) √q
            let q = f.as_constant().unwrap_or_else(S::zero);
            let len = y.clone() - x.clone();
            match q.sqrt_exact() {
                Some(r) => total += len * r,
                None => {
                    let root = format!("√({})", q.to_text());
                    let value = if len == S::one() {
                        root
                    } else {
                        format!("({}) {root}", len.to_text())
                    };
                    words = Some(Say::LengthOutsideField { value });
                    break;
                }
            }
        } else {
            words = Some(Say::SpeedNotSquare { speed: f.to_text() });
            break;
        }
    }
    Ok(length_answer(out, speeds, words, &total))
}

/// The answer of an arc length: c'·c' (one per piece), and the exact length, or the words
/// saying why it is not exact (`words`, from the first piece that is not).
pub(crate) fn length_answer<S: ExactScalar>(
    out: Out,
    mut speeds: Vec<Exact>,
    words: Option<Say>,
    total: &S,
) -> Out {
    let out = out.result(
        "speed_squared",
        if speeds.len() == 1 {
            speeds.remove(0)
        } else {
            Exact::List(speeds)
        },
    );
    match words {
        None => out
            .result("exact", Exact::Bool(true))
            .result("length", Exact::Number(exact(total))),
        Some(w) => out
            .result("exact", Exact::Bool(false))
            .result("length", Exact::Sentence(w.into())),
    }
}
