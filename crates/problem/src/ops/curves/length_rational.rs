//! `arc_length` of a rational curve c = p/w on [a, b], exact where it exists (issue 16).
//!
//! The velocity is c' = (p' w - p w')/w², so `c'·c' = N/w⁴` with the polynomial
//! `N = |p' w - p w'|²`. When N = σ² for a polynomial σ (the curve is a rational
//! Pythagorean-hodograph curve: every conic arc of a circle, every line) the speed is
//! `|σ|/w²`, and the length `∫_a^b |σ|/w² dt` is exact when σ/w² has a rational
//! antiderivative g/w: `g' w - g w' = σ`, solved exactly for the coefficients of g with
//! g(a) = 0 (the solutions differ by multiples of w). Then, σ keeping its sign on [a, b]
//! (its Bernstein coefficients there), the length is `|g(b)/w(b)|`. Otherwise the integral
//! has a logarithm or an arctangent in its partial fractions: a circle arc's length is R θ,
//! with θ in radians, which is no number of Q or of one Q(√d); it is not given (neither
//! rounded nor written with π), and the answer says why.

use crate::message::curve::Curve as Say;
use crate::ops::curves::length::{poly_sqrt, sign_on};
use crate::ops::out::at;
use crate::value::ExactScalar;
use crate::ProblemError;
use cagd_linalg::{Matrix, NormalEquations};
use cagd_poly::{Poly, RationalMap, Var};
use std::cmp::Ordering;

/// The length of a rational piece `r` in `var` on [a, b], or the words why it is not given;
/// with N, the numerator of c'·c' = N/w⁴.
pub(crate) fn rational_length<S: ExactScalar>(
    r: &RationalMap<S>,
    var: Var,
    (a, b): (&S, &S),
    path: &str,
) -> Result<(Poly<S>, Result<S, Say>), ProblemError> {
    let (p, w) = (r.numerator(), r.denominator());
    // N = Σ_k (p_k' w - p_k w')²
    let dw = w.partial(var);
    let n = p.components().iter().fold(Poly::zero(), |acc, pk| {
        let qk = &(&pk.partial(var) * w) - &(pk * &dw);
        &acc + &(&qk * &qk)
    });
    if n.is_zero() {
        return Ok((n, Ok(S::zero())));
    }
    let Some(sigma) = poly_sqrt(&n, var) else {
        return Ok((
            n.clone(),
            Err(Say::RationalSpeedNotSquare {
                numerator: n.to_text(),
            }),
        ));
    };
    let Some(sign) = sign_on(&sigma, var, a, b) else {
        return Ok((
            n,
            Err(Say::RationalSpeedChangesSign {
                sigma: sigma.to_text(),
                halvings: crate::ops::curves::length::SIGN_HALVINGS,
                from: a.to_text(),
                to: b.to_text(),
            }),
        ));
    };
    match antiderivative(&sigma, w, var, a)? {
        Some(g) => {
            let at_b = |x: &S| -> Result<S, ProblemError> {
                let gx = g.eval(&[(var, x.clone())]).map_err(at(path))?;
                let wx = w.eval(&[(var, x.clone())]).map_err(at(path))?;
                gx.checked_div(&wx)
                    .ok_or_else(|| ProblemError::at(path, Say::WeightVanishesAtEnd))
            };
            let length = at_b(b)? - at_b(a)?;
            Ok((
                n,
                Ok(if sign == Ordering::Less {
                    -length
                } else {
                    length
                }),
            ))
        }
        None => Ok((
            n,
            Err(Say::NoRationalAntiderivative {
                sigma: sigma.to_text(),
                weight: w.to_text(),
            }),
        )),
    }
}

/// g with g' w - g w' = σ and g(a) = 0, when one exists: (g/w)' = σ/w².
fn antiderivative<S: ExactScalar>(
    sigma: &Poly<S>,
    w: &Poly<S>,
    var: Var,
    a: &S,
) -> Result<Option<Poly<S>>, ProblemError> {
    let ds = usize::try_from(sigma.degree_in(var)).unwrap_or(usize::MAX);
    let dw = usize::try_from(w.degree_in(var)).unwrap_or(usize::MAX);
    let dg = (ds + 1).max(dw);
    let rows = dg + dw + 1;
    // column k: the image of t^k, (t^k)' w - t^k w'
    let mut columns = Vec::with_capacity(dg + 1);
    for k in 0..=dg {
        let tk = Poly::monomial(S::one(), &[(var, u32::try_from(k).unwrap_or(0))]);
        let image = &tk.partial(var) * w - &tk * &w.partial(var);
        let mut col: Vec<S> = (0..rows)
            .map(|i| image.coeff_of(&[(var, u32::try_from(i).unwrap_or(0))]))
            .collect();
        // the row g(a) = 0
        col.push(a.powi(u32::try_from(k).unwrap_or(0)));
        columns.push(col);
    }
    let matrix = crate::ops::curves::reduce::rows_of_columns(&columns, rows + 1);
    let mut rhs: Vec<S> = (0..rows)
        .map(|i| sigma.coeff_of(&[(var, u32::try_from(i).unwrap_or(0))]))
        .collect();
    rhs.push(S::zero());
    let m = Matrix::from_rows(matrix).map_err(at(""))?;
    let Ok(g) = NormalEquations::new(&m).and_then(|ne| ne.solve(&rhs)) else {
        return Ok(None);
    };
    let g = g.iter().enumerate().fold(Poly::zero(), |acc, (k, c)| {
        &acc + &Poly::monomial(c.clone(), &[(var, u32::try_from(k).unwrap_or(0))])
    });
    // the least-squares solution solves the system only when it is consistent
    let check = &(&g.partial(var) * w) - &(&g * &w.partial(var));
    Ok((&check - sigma).is_zero().then_some(g))
}

/// `arc_length` of a rational Bézier or NURBS curve (piece by piece) on [lo, hi]: `exact`,
/// `length` (a number, or the words why not) and `speed_squared` = N/w⁴ per piece.
pub(crate) fn rational_arc_length<S: ExactScalar>(
    curve: &crate::any::AnyCurve<S>,
    (lo, hi): (S, S),
    run: crate::ops::out::Run<'_>,
) -> Result<crate::ops::out::Out, ProblemError> {
    use crate::any::AnyCurve as Curve;
    use crate::ops::pieces::PieceForm;
    use crate::value::{exact_rational, Exact};
    let cf = "curve";
    let less = |x: &S, y: &S| x.compare(y) == Some(Ordering::Less);
    let pieces: Vec<((S, S), RationalMap<S>)> = match curve {
        Curve::RationalBezier(b) => vec![((lo.clone(), hi.clone()), b.closed_form(Var::T))],
        _ => crate::ops::pieces::curve_forms(curve, cf)?
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
        let (n, length) = rational_length(r, Var::T, (x, y), cf)?;
        let w2 = r.denominator() * r.denominator();
        let speed =
            RationalMap::new(cagd_poly::VecPoly::new(vec![n]), &w2 * &w2).map_err(at(cf))?;
        speeds.push(Exact::Rational(exact_rational(&speed)));
        match length {
            Ok(l) => total += l,
            Err(w) => {
                words = Some(w);
                break;
            }
        }
    }
    Ok(crate::ops::curves::length_answer::length_answer(
        out, speeds, words, &total,
    ))
}
