//! `curve_continuity`: the order of contact of two curves at their joint, parametric (C^r)
//! and geometric (G^1, G^2), checked exactly.
//!
//! The first curve ends at t = b, the second starts at t = a (each in its own parameter and
//! domain). They meet C^r when `c_1^{(k)}(b) = c_2^{(k)}(a)` for k = 0, ..., r (Farin, §11.1;
//! in the notes, chapter 5 (21)-(23) for patches, with unit parameter lengths). They meet G^1
//! when moreover, for a regular joint, `c_2'(a) = α c_1'(b)` with α > 0, and G^2 when also
//! `c_2''(a) = α² c_1''(b) + β c_1'(b)` for some β (the chain rule of a reparametrization
//! t ↦ φ(t) with φ' = α, φ'' = β: Farin, §11.2, the "β-constraints" of Barsky).

use crate::any::AnyCurve as Curve;
use crate::any_curve::curve_var;
use crate::message::curve::Curve as Say;
use crate::out::{at, req, Out, Run};
use crate::pieces::{curve_forms, PieceForm};
use crate::problem::CurveContinuity;
use crate::steps::Formula;
use crate::value::quantity::{Quantity, Side};
use crate::value::{exact_points, Exact, ExactScalar};
use crate::ProblemError;
use cagd_linalg::Point;
use cagd_poly::{RationalMap, Var};
use std::cmp::Ordering;

/// The closed form of the piece of `c` at its start (`end` false) or its end, its variable,
/// the parameter there and the degree of the piece.
fn piece_at<S: ExactScalar>(
    c: &Curve<S>,
    end: bool,
    path: &str,
) -> Result<(PieceForm<S>, Var, S, usize), ProblemError> {
    let (a, b) = c.domain();
    let t = if end { b } else { a };
    Ok(match c {
        Curve::Bezier(x) => (
            PieceForm::Polynomial(x.closed_form(Var::T)),
            Var::T,
            t,
            x.degree(),
        ),
        Curve::RationalBezier(x) => (
            PieceForm::Rational(x.closed_form(Var::T)),
            Var::T,
            t,
            x.degree(),
        ),
        Curve::Map(e) => {
            let var = curve_var(e);
            let degree = usize::try_from(e.degree()).unwrap_or(usize::MAX);
            (PieceForm::Polynomial(e.clone()), var, t, degree)
        }
        Curve::BSpline(_) | Curve::Nurbs(_) => {
            let forms = curve_forms(c, path)?.unwrap_or_default();
            let piece = if end { forms.last() } else { forms.first() };
            let (_, form) = piece
                .cloned()
                .ok_or_else(|| ProblemError::at(path, Say::NoPiece))?;
            (form, Var::T, t, c.degree())
        }
    })
}

/// The k-th derivative of a form at t.
fn derivative_at<S: ExactScalar>(
    f: &PieceForm<S>,
    var: Var,
    k: usize,
    t: &S,
    path: &str,
) -> Result<Point<S>, ProblemError> {
    let other = if var == Var::U { Var::V } else { Var::U };
    match f {
        PieceForm::Polynomial(m) => {
            let mut d = m.clone();
            for _ in 0..k {
                d = d.partial(var);
            }
            d.eval(&[(var, t.clone())]).map_err(at(path))
        }
        PieceForm::Rational(r) => {
            let d: RationalMap<S> = r.mixed_partial(var, k, other, 0);
            d.eval(&[(var, t.clone())]).map_err(at(path))
        }
    }
}

/// The scalar λ with `y = λ x` when there is one (x ≠ 0); `None` otherwise.
fn ratio<S: ExactScalar>(y: &Point<S>, x: &Point<S>) -> Option<S> {
    let (i, xi) = x
        .coords()
        .iter()
        .enumerate()
        .find(|(_, c)| **c != S::zero())?;
    let lambda = y.coords().get(i)?.clone() / xi.clone();
    (x.scale(&lambda) == *y).then_some(lambda)
}

/// `curve_continuity` of `first` (at its end) and `second` (at its start): `order` (C^r, -1
/// when the curves do not meet, `"infinite"` when the two pieces at the joint are one map),
/// `geometric` (0, 1 or 2: G^2 is the highest tested), `alpha` and `beta` of the G^1 and G^2
/// conditions when found, and the derivatives c_1^{(k)}(b), c_2^{(k)}(a) compared.
pub(crate) fn curve_continuity<S: ExactScalar>(
    a: &CurveContinuity,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let first = Curve::<S>::read(req(&a.first, "first")?, "first")?;
    let second = Curve::<S>::read(req(&a.second, "second")?, "second")?;
    let (f1, v1, t1, n1) = piece_at(&first, true, "first")?;
    let (f2, v2, t2, n2) = piece_at(&second, false, "second")?;
    let rational = matches!(f1, PieceForm::Rational(_)) || matches!(f2, PieceForm::Rational(_));
    // past this order, agreement means the two pieces are one map (their difference has a
    // numerator of degree at most top)
    let top = if rational {
        n1.max(n2).saturating_mul(2)
    } else {
        n1.max(n2)
    };
    let mut out = run.out();
    out.formula(Formula::CurveJoinC);
    let (mut d1, mut d2) = (Vec::new(), Vec::new());
    let mut order: Option<isize> = None;
    for k in 0..=top {
        let x = derivative_at(&f1, v1, k, &t1, "first")?;
        let y = derivative_at(&f2, v2, k, &t2, "second")?;
        let agree = x == y;
        d1.push(x);
        d2.push(y);
        if !agree {
            order = Some(isize::try_from(k).unwrap_or(isize::MAX) - 1);
            break;
        }
    }
    // G^1 and G^2 from the first and second derivatives
    let zero = |p: &Point<S>| p.coords().iter().all(|c| *c == S::zero());
    let mut geometric: Exact = Exact::Int(-1);
    let mut notes = Vec::new();
    let mut found: Vec<(Quantity, Exact)> = Vec::new();
    let (p0, q0) = (
        derivative_at(&f1, v1, 0, &t1, "first")?,
        derivative_at(&f2, v2, 0, &t2, "second")?,
    );
    if p0 == q0 {
        geometric = Exact::Int(0);
        let (p1, q1) = (
            derivative_at(&f1, v1, 1, &t1, "first")?,
            derivative_at(&f2, v2, 1, &t2, "second")?,
        );
        if zero(&p1) || zero(&q1) {
            notes.push(Say::SingularJoint);
        } else if let Some(alpha) = ratio(&q1, &p1) {
            match alpha.compare(&S::zero()) {
                Some(Ordering::Greater) => {
                    geometric = Exact::Int(1);
                    found.push((Quantity::Alpha, Exact::Number(crate::value::exact(&alpha))));
                    let (p2, q2) = (
                        derivative_at(&f1, v1, 2, &t1, "first")?,
                        derivative_at(&f2, v2, 2, &t2, "second")?,
                    );
                    let rest = q2 - p2.scale(&(alpha.clone() * alpha.clone()));
                    let beta = if zero(&rest) {
                        Some(S::zero())
                    } else {
                        ratio(&rest, &p1)
                    };
                    if let Some(beta) = beta {
                        geometric = Exact::Int(2);
                        found.push((Quantity::Beta, Exact::Number(crate::value::exact(&beta))));
                    }
                }
                Some(_) => notes.push(Say::CuspJoint),
                None => notes.push(Say::AlphaInLetters),
            }
        }
    }
    out.formula(Formula::CurveJoinG);
    let order = match order {
        Some(k) => Exact::Int(i64::try_from(k).unwrap_or(i64::MAX)),
        None => Exact::Sentence(Say::Infinite.into()),
    };
    out.remarks
        .extend(notes.into_iter().map(crate::Message::from));
    out.value("c_1^{(k)}(b)", Exact::Points(exact_points(&d1)));
    out.value("c_2^{(k)}(a)", Exact::Points(exact_points(&d2)));
    out = out
        .result(Quantity::Order, order)
        .result(Quantity::GeometricOrder, geometric);
    for (name, x) in found {
        out = out.result(name, x);
    }
    Ok(out
        .result(
            Quantity::JoinDerivatives(Side::First),
            Exact::Points(exact_points(&d1)),
        )
        .result(
            Quantity::JoinDerivatives(Side::Second),
            Exact::Points(exact_points(&d2)),
        ))
}
