//! The answers of the ruled-surface mistakes (`cagd_problem::diagnosis::RuledMistake`): the
//! problem solved with its curves exchanged, the second one reversed or the lower one padded
//! instead of raised (chapter 6, eq. (7)); or the key's mesh transposed.

use crate::change::{int, reverse_curve, swap_uv, transpose};
use crate::{Context, Mistaken};
use cagd_poly::Var;
use cagd_problem::diagnosis::RuledMistake;
use cagd_problem::input::CurveIn;
use cagd_problem::{Exact, Number, Op, Quantity};

/// The answer a student who made `m` writes, or `None` where it does not apply.
pub(crate) fn mistaken(m: RuledMistake, cx: &Context) -> Option<Mistaken> {
    if !matches!(cx.problem.op, Op::Ruled(_)) {
        return None;
    }
    match m {
        // (1 − v) c₂(u) + v c₁(u)
        RuledMistake::CurvesExchanged => cx.solve_changed(|op| match op {
            Op::Ruled(r) => {
                std::mem::swap(&mut r.c1, &mut r.c2);
                true
            }
            _ => false,
        }),
        // (1 − v) c₁(u) + v c₂(1 − u): c₂'s polygon (and weights) reversed, or its
        // parametrization composed with 1 − u
        RuledMistake::CurveReversed => cx.solve_changed(|op| match op {
            Op::Ruled(r) => match r.c2.as_ref().and_then(reversed) {
                Some(c) => {
                    r.c2 = Some(c);
                    true
                }
                None => false,
            },
            _ => false,
        }),
        // c_{0,i} = c_{1i}, c_{1,i} = c_{2i}: the mesh of bidegree (1, m), its closed form
        // c(v, u)
        RuledMistake::MeshTransposed => {
            cx.result(&Quantity::Surface)?;
            Some(cx.map_results(|q, x| match (q, x) {
                (Quantity::Surface, _) => transpose(x),
                (Quantity::ClosedForm(_), Exact::Map(m)) => Some(Exact::Map(swap_uv(m))),
                _ => None,
            }))
        }
        // the lower curve's last point repeated until the degrees match
        RuledMistake::LastPointRepeated => cx.solve_changed(|op| match op {
            Op::Ruled(r) => match (&mut r.c1, &mut r.c2) {
                (Some(a), Some(b)) => pad_lower(a, b),
                _ => false,
            },
            _ => false,
        }),
    }
}

/// The Bézier curve of lower degree of `a`, `b` padded with its last control point (and
/// weight) repeated until it has as many as the other: whether the degrees differed.
fn pad_lower(a: &mut CurveIn<Number>, b: &mut CurveIn<Number>) -> bool {
    let (CurveIn::Bezier { points: pa, .. }, CurveIn::Bezier { points: pb, .. }) = (&*a, &*b)
    else {
        return false;
    };
    let (na, nb) = (pa.len(), pb.len());
    let (low, to) = match na.cmp(&nb) {
        std::cmp::Ordering::Less => (a, nb),
        std::cmp::Ordering::Greater => (b, na),
        std::cmp::Ordering::Equal => return false,
    };
    let CurveIn::Bezier { points, weights } = low else {
        return false;
    };
    let (Some(last), from) = (points.last().cloned(), points.len()) else {
        return false;
    };
    points.resize(to, last);
    if let Some(w) = weights {
        let Some(wl) = w.last().cloned() else {
            return false;
        };
        w.resize(to, wl);
    }
    from < to
}

/// A curve in reverse order, c(1 − u): a Bézier polygon (and weights) reversed, or a
/// parametrization composed with 1 − u (`None` for a B-spline).
fn reversed(c: &CurveIn<Number>) -> Option<CurveIn<Number>> {
    match c {
        CurveIn::Expr(m) => Some(CurveIn::Expr(m.affine_substitute(
            Var::U,
            &int(-1),
            &int(1),
        ))),
        _ => reverse_curve(c),
    }
}
