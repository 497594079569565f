//! The answers of the continuity mistakes (`cagd_problem::diagnosis::ContinuityMistake`): the
//! join of two patches solved again with the interval lengths of (22) dropped or exchanged;
//! the order read from parallel differences (or from the geometric order of two curves); the
//! order of two Bézier curves from their differences without the degree factors.

use crate::change::comparable;
use crate::{Context, Mistaken};
use cagd_linalg::Point;
use cagd_problem::diagnosis::ContinuityMistake;
use cagd_problem::input::CurveIn;
use cagd_problem::spec::Pair;
use cagd_problem::value::quantity::Side;
use cagd_problem::{Exact, Number, Op, Quantity};
use cagd_scalar::FieldOps;
use std::cmp::Ordering;

/// The answer a student who made `m` writes, or `None` where it does not apply.
pub(crate) fn mistaken(m: ContinuityMistake, cx: &Context) -> Option<Mistaken> {
    // the join solved with other lengths, as the student writes it: the results comparable
    // with the key's (the order, the derivatives and normals along the border)
    let as_key = |x: Mistaken| Mistaken {
        result: comparable(&cx.answer.result, x.result),
        steps: x.steps,
    };
    match m {
        ContinuityMistake::LengthsIgnored => cx
            .solve_changed(|op| match op {
                Op::Continuity(c) if c.first.is_some() && c.lengths.is_some() => {
                    c.lengths = None;
                    true
                }
                _ => false,
            })
            .map(as_key),
        ContinuityMistake::LengthsSwapped => cx
            .solve_changed(|op| match op {
                Op::Continuity(c) if c.first.is_some() => match c.lengths.take() {
                    Some(Pair(du0, du1)) => {
                        c.lengths = Some(Pair(du1, du0));
                        true
                    }
                    None => false,
                },
                _ => false,
            })
            .map(as_key),
        ContinuityMistake::ParallelTakenForC1 => parallel_taken_for_c1(cx),
        ContinuityMistake::DegreeFactorsLeftOut => degree_factors_left_out(cx),
    }
}

/// Whether `y = λ x` with λ > 0 (x ≠ 0).
fn positive_multiple(y: &Point<Number>, x: &Point<Number>) -> bool {
    let zero = Number::from_i64(0);
    let Some((i, xi)) = x.coords().iter().enumerate().find(|(_, c)| **c != zero) else {
        return false;
    };
    let Some(lambda) = y.coords().get(i).and_then(|yi| yi.checked_div(xi)) else {
        return false;
    };
    x.scale(&lambda) == *y && lambda.compare(&zero) == Some(Ordering::Greater)
}

/// The order a student who takes parallel differences for equal ones writes: for two patches
/// that the key finds C^0, 1 when every pair Δ^{1,0}c_{m−1,j}, Δ^{1,0}c̃_{0,j} is parallel
/// with the same sense; for two curves, the geometric order where it exceeds the parametric
/// one.
fn parallel_taken_for_c1(cx: &Context) -> Option<Mistaken> {
    let order = match &cx.problem.op {
        Op::Continuity(c) if c.first.is_some() => {
            if cx.result(&Quantity::Order)? != &Exact::Int(0) {
                return None;
            }
            let differences = |side| match cx.result(&Quantity::BorderDifferences(side)) {
                Some(Exact::Points(ps)) => Some(ps),
                _ => None,
            };
            let (first, second) = (differences(Side::First)?, differences(Side::Second)?);
            let parallel = !first.is_empty()
                && first.len() == second.len()
                && first
                    .iter()
                    .zip(second)
                    .all(|(x, y)| positive_multiple(y, x));
            parallel.then_some(1)?
        }
        Op::CurveContinuity(_) => {
            let (Exact::Int(k), Exact::Int(g)) = (
                cx.result(&Quantity::Order)?,
                cx.result(&Quantity::GeometricOrder)?,
            ) else {
                return None;
            };
            (g > k).then_some(*g)?
        }
        _ => return None,
    };
    Some(Mistaken {
        result: vec![(Quantity::Order, Exact::Int(order))],
        steps: Vec::new(),
    })
}

/// Two Bézier curves b_0..b_n, c_0..c_m without weights compared by their differences
/// Δ^k b_{n−k} and Δ^k c_0 for k = 0, 1, ... (no factors n!/(n−k)!, m!/(m−k)!; zero past the
/// degree), up to the first that differ, as the key compares the derivatives: the order and
/// the two lists. `None` when they never differ up to max(n, m) (the key's "infinite").
fn degree_factors_left_out(cx: &Context) -> Option<Mistaken> {
    let Op::CurveContinuity(c) = &cx.problem.op else {
        return None;
    };
    let polygon = |x: &Option<CurveIn<Number>>| match x {
        Some(CurveIn::Bezier {
            points,
            weights: None,
        }) => Some(points.clone()),
        _ => None,
    };
    let (b, c) = (polygon(&c.first)?, polygon(&c.second)?);
    let dim = b.first()?.dim();
    let (n, m) = (b.len().checked_sub(1)?, c.len().checked_sub(1)?);
    let difference = |points: &[Point<Number>], k: usize, last: bool| -> Option<Point<Number>> {
        let d = cagd_bezier::forward_differences(points, k).ok()?;
        if last { d.last() } else { d.first() }
            .cloned()
            .or_else(|| Some(Point::zero(dim)))
    };
    let (mut first, mut second) = (Vec::new(), Vec::new());
    for k in 0..=n.max(m) {
        let x = if k <= n {
            difference(&b, k, true)?
        } else {
            Point::zero(dim)
        };
        let y = if k <= m {
            difference(&c, k, false)?
        } else {
            Point::zero(dim)
        };
        let agree = x == y;
        first.push(x);
        second.push(y);
        if !agree {
            let order = i64::try_from(k).ok()? - 1;
            let mut result = vec![(Quantity::Order, Exact::Int(order))];
            // the lists where they are as long as the key's (compared point by point)
            for (side, list) in [(Side::First, first), (Side::Second, second)] {
                let q = Quantity::JoinDerivatives(side);
                if let Some(Exact::Points(key)) = cx.result(&q) {
                    if key.len() == list.len() {
                        result.push((q, Exact::Points(list)));
                    }
                }
            }
            return Some(Mistaken {
                result,
                steps: Vec::new(),
            });
        }
    }
    None
}
