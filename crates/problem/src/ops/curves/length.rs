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

use crate::any::AnyCurve as Curve;
use crate::any_curve::curve_var;
use crate::message::curve::Curve as Say;
use crate::ops::curves::length_answer::length_answer;
use crate::ops::out::{at, pair, req, Out, Run};
use crate::problem::ArcLength;
use crate::steps::Formula;
use crate::value::{exact_poly, Exact, ExactScalar};
use crate::ProblemError;
use cagd_poly::{to_bernstein_1d, Poly, Var, VecPoly};
use std::cmp::Ordering;

/// σ with σ² = f, when f is the square of a polynomial in `var`: from the top coefficient
/// down, or, when the top coefficient's root is not found in the field (the scalar's
/// `sqrt_exact` of an a + b√d), from the constant term up (the same on t^d f(1/t)).
pub(crate) fn poly_sqrt<S: ExactScalar>(f: &Poly<S>, var: Var) -> Option<Poly<S>> {
    sqrt_from_top(f, var).or_else(|| {
        let d = f.degree_in(var);
        let reversed = |g: &Poly<S>, n: u32| {
            (0..=n).fold(Poly::zero(), |acc, i| {
                &acc + &Poly::monomial(g.coeff_of(&[(var, i)]), &[(var, n - i)])
            })
        };
        let s = sqrt_from_top(&reversed(f, d), var)?;
        let sigma = reversed(&s, d / 2);
        (&(&sigma * &sigma) - f).is_zero().then_some(sigma)
    })
}

fn sqrt_from_top<S: ExactScalar>(f: &Poly<S>, var: Var) -> Option<Poly<S>> {
    let d = f.degree_in(var);
    if d % 2 == 1 {
        return None;
    }
    let k = d / 2;
    let c = |i: u32| f.coeff_of(&[(var, i)]);
    let top = c(d).sqrt_exact()?;
    let two_top = top.clone() + top.clone();
    let mut s: Vec<S> = vec![S::zero(); usize::try_from(k).ok()? + 1];
    *s.last_mut()? = top;
    for j in (0..k).rev() {
        let mut rest = c(k + j);
        for i in (j + 1)..k {
            let l = k + j - i;
            rest -=
                s.get(usize::try_from(i).ok()?)?.clone() * s.get(usize::try_from(l).ok()?)?.clone();
        }
        *s.get_mut(usize::try_from(j).ok()?)? = rest.checked_div(&two_top)?;
    }
    let sigma = s.iter().enumerate().fold(Poly::zero(), |acc, (i, x)| {
        &acc + &Poly::monomial(x.clone(), &[(var, u32::try_from(i).unwrap_or(0))])
    });
    (&(&sigma * &sigma) - f).is_zero().then_some(sigma)
}

/// ∫_a^b p(var) d var.
fn integral<S: ExactScalar>(p: &Poly<S>, var: Var, a: &S, b: &S) -> S {
    let mut total = S::zero();
    for i in 0..=p.degree_in(var) {
        let c = p.coeff_of(&[(var, i)]);
        let e = i + 1;
        let n = S::from_i64(i64::from(e));
        total += c * (b.powi(e) - a.powi(e)) / n;
    }
    total
}

/// How many times [`sign_on`] halves an interval where the Bernstein coefficients of σ have
/// both signs: at depth k the pieces are 2^-k of [a, b] long. A sign still undecided there
/// (σ with a root in [a, b], or one so close that the pieces cannot separate it) is `None`.
pub(crate) const SIGN_HALVINGS: u32 = 8;

/// The sign σ keeps on [a, b]: `Greater` when σ ≥ 0 there, `Less` when σ ≤ 0, decided by the
/// Bernstein coefficients of σ on [a, b] (the convex hull property), halving the pieces whose
/// coefficients have both signs by De Casteljau at 1/2, at most [`SIGN_HALVINGS`] deep. `None`
/// when σ changes sign (a piece ≥ 0 beside a piece ≤ 0) or a piece is still undecided.
pub(crate) fn sign_on<S: ExactScalar>(sigma: &Poly<S>, var: Var, a: &S, b: &S) -> Option<Ordering> {
    let on_unit = sigma.affine_substitute(var, &(b.clone() - a.clone()), a);
    let n = usize::try_from(on_unit.degree_in(var)).ok()?;
    let mut pieces = vec![(to_bernstein_1d(&on_unit, var, n).ok()?, 0)];
    let (mut positive, mut negative) = (false, false);
    while let Some((coefs, depth)) = pieces.pop() {
        let signs: Vec<Ordering> = coefs
            .iter()
            .map(|x| x.compare(&S::zero()))
            .collect::<Option<_>>()?;
        let up = signs.contains(&Ordering::Greater);
        let down = signs.contains(&Ordering::Less);
        if up && down {
            if depth == SIGN_HALVINGS {
                return None;
            }
            let (left, right) = crate::ops::zeros::halves(&coefs);
            pieces.push((right, depth + 1));
            pieces.push((left, depth + 1));
            continue;
        }
        positive |= up;
        negative |= down;
        if positive && negative {
            return None;
        }
    }
    Some(if negative {
        Ordering::Less
    } else {
        Ordering::Greater
    })
}

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
        Curve::BSpline(_) => crate::ops::pieces::curve_forms(&curve, cf)?
            .unwrap_or_default()
            .into_iter()
            .filter_map(|((x, y), f)| match f {
                crate::ops::pieces::PieceForm::Polynomial(m) => {
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
                crate::ops::pieces::PieceForm::Rational(_) => None,
            })
            .collect(),
        Curve::RationalBezier(_) | Curve::Nurbs(_) => {
            return crate::ops::curves::length_rational::rational_arc_length(&curve, (lo, hi), run)
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
        if let Some(sigma) = poly_sqrt(&f, *var) {
            out.value("\\sigma(t)", Exact::Poly(exact_poly(&sigma)));
            match sign_on(&sigma, *var, x, y) {
                Some(Ordering::Less) => total -= integral(&sigma, *var, x, y),
                Some(_) => total += integral(&sigma, *var, x, y),
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
