//! `arc_length` of a rational curve c = p/w on [a, b], exact where it exists: each piece's
//! length is cagd-bezier's ([`cagd_bezier::rational_length`]: `|g(b)/w(b) - g(a)/w(a)|` when
//! `c'·c' = σ²/w⁴` and σ/w² has a rational antiderivative g/w, or why it is not given); here
//! the pieces and the answer, with `c'·c' = N/w⁴` per piece.

use crate::out::at;
use crate::value::ExactScalar;
use crate::ProblemError;
use cagd_bezier::rational_length;
use cagd_poly::{RationalMap, Var};
use std::cmp::Ordering;

/// `arc_length` of a rational Bézier or NURBS curve (piece by piece) on [lo, hi]: `exact`,
/// `length` (a number, or the words why not) and `speed_squared` = N/w⁴ per piece.
pub(crate) fn rational_arc_length<S: ExactScalar>(
    curve: &crate::any::AnyCurve<S>,
    (lo, hi): (S, S),
    run: crate::out::Run<'_>,
) -> Result<crate::out::Out, ProblemError> {
    use crate::any::AnyCurve as Curve;
    use crate::pieces::PieceForm;
    use crate::value::{exact_rational, Exact};
    let cf = "curve";
    let less = |x: &S, y: &S| x.compare(y) == Some(Ordering::Less);
    let pieces: Vec<((S, S), RationalMap<S>)> = match curve {
        Curve::RationalBezier(b) => vec![((lo.clone(), hi.clone()), b.closed_form(Var::T))],
        _ => crate::pieces::curve_forms(curve, cf)?
            .unwrap_or_default()
            .into_iter()
            .filter_map(|((x, y), f)| match f {
                PieceForm::Rational(r) => {
                    // the part of the span inside [lo, hi]
                    let x = if less(&x, &lo) { lo.clone() } else { x };
                    let y = if less(&hi, &y) { hi.clone() } else { y };
                    less(&x, &y).then_some(((x, y), r))
                }
                PieceForm::Polynomial(_) => None,
            })
            .collect(),
    };
    let mut out = run.out();
    out.formula(crate::steps::Formula::ArcLengthRational);
    let mut total = S::zero();
    let mut speeds = Vec::new();
    let mut words = None;
    for ((x, y), r) in &pieces {
        let piece =
            rational_length(r, Var::T, (x, y)).map_err(|e| super::length_answer::refusal(e, cf))?;
        let w2 = r.denominator() * r.denominator();
        let speed = RationalMap::new(
            cagd_poly::VecPoly::new(vec![piece.speed_squared]),
            &w2 * &w2,
        )
        .map_err(at(cf))?;
        speeds.push(Exact::Rational(exact_rational(&speed)));
        match piece.length {
            Ok(l) => total += l,
            Err(why) => {
                words = Some(cagd_bezier::LengthNotGiven::from(why));
                break;
            }
        }
    }
    Ok(crate::curves::length_answer::length_answer(
        out, speeds, words, &total,
    ))
}
