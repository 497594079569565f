//! `arc_length`: the length `∫_a^b |c'(t)| dt` of a polynomial curve where it is exact,
//! piece by piece: each piece's length is cagd-bezier's ([`cagd_bezier::polynomial_length`]:
//! `|∫_a^b σ dt|` when `c'·c' = σ²`, a line's `(b - a) √q`, or why the length is no number of
//! the field); here the curve read, its pieces, and the answer written: `c'·c'`, the length
//! or the words why it is not given (never a float).

use crate::any::AnyCurve as Curve;
use crate::any_curve::curve_var;
use crate::curves::length_answer::{length_answer, refusal};
use crate::out::{pair, req, Out, Run};
use crate::problem::ArcLength;
use crate::steps::Formula;
use crate::value::{exact_poly, Exact, ExactScalar};
use crate::ProblemError;
use cagd_bezier::{polynomial_length, LengthNotGiven};
use cagd_poly::{Var, VecPoly};
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
        Curve::BSpline(_) => crate::pieces::curve_forms(&curve, cf)?
            .unwrap_or_default()
            .into_iter()
            .filter_map(|((x, y), f)| match f {
                crate::pieces::PieceForm::Polynomial(m) => {
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
                crate::pieces::PieceForm::Rational(_) => None,
            })
            .collect(),
        Curve::RationalBezier(_) | Curve::Nurbs(_) => {
            return crate::curves::length_rational::rational_arc_length(&curve, (lo, hi), run)
        }
    };
    let mut out = run.out();
    out.formula(Formula::ArcLength);
    let mut total = S::zero();
    let mut speeds = Vec::new();
    let mut words: Option<LengthNotGiven> = None;
    for ((x, y), c, var) in &pieces {
        let piece = polynomial_length(c, *var, (x, y)).map_err(|e| refusal(e, cf))?;
        speeds.push(Exact::Poly(exact_poly(&piece.speed_squared)));
        if let Some(sigma) = &piece.sigma {
            out.value("\\sigma(t)", Exact::Poly(exact_poly(sigma)));
        }
        match piece.length {
            Ok(l) => total += l,
            Err(why) => {
                words = Some(why.into());
                break;
            }
        }
    }
    Ok(length_answer(out, speeds, words, &total))
}
