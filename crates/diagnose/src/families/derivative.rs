//! The answers of the derivative mistakes (`cagd_problem::diagnosis::DerivativeMistake`): the
//! key's derivative of a Bézier patch or curve times a number (the factor of (18) left out
//! or taken as a power, the sign of reversed differences), or the problem solved with the
//! orders exchanged (the other parameter).

use crate::change::{comparable, falling, int, times};
use crate::{Context, Mistaken};
use cagd_problem::diagnosis::DerivativeMistake;
use cagd_problem::input::{CurveIn, SurfaceIn};
use cagd_problem::problem::Derivative;
use cagd_problem::spec::Orders;
use cagd_problem::{Exact, Number, Op};
use cagd_scalar::FieldOps;

/// The answer a student who made `m` writes, or `None` where it does not apply.
pub(crate) fn mistaken(m: DerivativeMistake, cx: &Context) -> Option<Mistaken> {
    let Op::Derivative(a) = &cx.problem.op else {
        return None;
    };
    if a.triangle.is_some() {
        return None;
    }
    match m {
        DerivativeMistake::DegreeFactorLeftOut => {
            let (f, _) = factors(a)?;
            scaled(cx, &Number::from_ratio(1, f))
        }
        DerivativeMistake::PowerForFalling => {
            let (f, power) = factors(a)?;
            scaled(cx, &Number::from_ratio(power, f))
        }
        DerivativeMistake::DifferencesReversed => {
            let (r, s) = polynomial_orders(a)?;
            // Δ reversed r + s times: (−1)^{r+s}
            ((r + s) % 2 == 1).then_some(())?;
            scaled(cx, &int(-1))
        }
        DerivativeMistake::OtherDirection => cx
            .solve_changed(|op| match op {
                Op::Derivative(d) => match d.order {
                    Some(Orders::Two(r, s)) if d.surface.is_some() && r != s => {
                        d.order = Some(Orders::Two(s, r));
                        true
                    }
                    _ => false,
                },
                _ => false,
            })
            .map(|x| as_key(cx, x)),
    }
}

/// The orders (r, s) (s = 0 for a curve) and the degrees (m, n) (n = 0 for a curve) of the
/// derivative of a Bézier patch or curve without weights; `None` otherwise.
fn bezier_orders(a: &Derivative) -> Option<((usize, usize), (usize, usize))> {
    let order = |k: u64| usize::try_from(k).ok();
    match (&a.surface, &a.curve, a.order.as_ref()?) {
        (
            Some(SurfaceIn::Bezier {
                mesh,
                weights: None,
            }),
            None,
            Orders::Two(r, s),
        ) => Some((
            (order(r.0)?, order(s.0)?),
            (mesh.rows().checked_sub(1)?, mesh.cols().checked_sub(1)?),
        )),
        (
            None,
            Some(CurveIn::Bezier {
                points,
                weights: None,
            }),
            Orders::One(r),
        ) => Some(((order(r.0)?, 0), (points.len().checked_sub(1)?, 0))),
        _ => None,
    }
}

/// The orders (r, s) (s = 0 for a curve) of the derivative of a Bézier or B-spline patch or
/// curve without weights, whose control points are differences; `None` otherwise.
fn polynomial_orders(a: &Derivative) -> Option<(usize, usize)> {
    if let Some((orders, _)) = bezier_orders(a) {
        return Some(orders);
    }
    let order = |k: u64| usize::try_from(k).ok();
    match (&a.surface, a.order.as_ref()?) {
        (Some(SurfaceIn::BSpline { weights: None, .. }), Orders::Two(r, s)) => {
            Some((order(r.0)?, order(s.0)?))
        }
        _ => None,
    }
}

/// The factor m!/(m−r)! n!/(n−s)! of (18) and the power m^r n^s taken for it, of a Bézier
/// patch (or curve) without weights whose derivative is not zero.
fn factors(a: &Derivative) -> Option<(i64, i64)> {
    let ((r, s), (m, n)) = bezier_orders(a)?;
    let f = falling(m, r)?.checked_mul(falling(n, s)?)?;
    let power = |b: usize, e: usize| i64::try_from(b).ok()?.checked_pow(u32::try_from(e).ok()?);
    let p = power(m, r)?.checked_mul(power(n, s)?)?;
    (f != 0).then_some((f, p))
}

/// The key's results (the derivative polygon or mesh, the closed form) times `c` (a list of
/// pieces left out).
fn scaled(cx: &Context, c: &Number) -> Option<Mistaken> {
    let out = cx.map_results(|_, x: &Exact| times(x, c));
    (!out.result.is_empty()).then_some(out)
}

/// A changed problem's answer as the student writes it: the results the key's can be
/// compared with, under the key's names.
fn as_key(cx: &Context, x: Mistaken) -> Mistaken {
    Mistaken {
        result: comparable(&cx.answer.result, x.result),
        steps: x.steps,
    }
}
