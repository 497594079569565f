//! The answers of the circle mistakes (`cagd_problem::diagnosis::CircleMistake`): the key's
//! circle (a quadratic NURBS curve with weights {1, w, 1, w, ..., 1}, w = cos(θ/2)) with its
//! weights, middle vertices or knots changed as the student wrote them. The center is read
//! back from the key: with M the midpoint of the ends b_{j−1}, b_{j+1} of an arc and b_j its
//! middle vertex, M − c = w² (b_j − c), so c = (M − w² b_j)/(1 − w²).

use crate::change::int;
use crate::{Context, Mistaken};
use cagd_linalg::Point;
use cagd_problem::diagnosis::CircleMistake;
use cagd_problem::input::CurveIn;
use cagd_problem::{Exact, Number, Op, Quantity};
use cagd_scalar::FieldOps;

/// The answer a student who made `m` writes, or `None` where it does not apply.
pub(crate) fn mistaken(m: CircleMistake, cx: &Context) -> Option<Mistaken> {
    if !matches!(cx.problem.op, Op::Circle(_)) {
        return None;
    }
    let Exact::Curve(CurveIn::BSpline {
        points,
        degree: 2,
        knots,
        weights: Some(weights),
    }) = cx.result(&Quantity::Curve)?
    else {
        return None;
    };
    let (points, weights) = match m {
        CircleMistake::WeightsLeftOut => {
            return Some(curve_answer(CurveIn::BSpline {
                points: points.clone(),
                degree: 2,
                knots: knots.clone(),
                weights: None,
            }));
        }
        CircleMistake::MiddleWeightOne => (points.clone(), vec![int(1); weights.len()]),
        CircleMistake::WeightWholeAngle => {
            // cos θ = 2 cos²(θ/2) − 1 at the middle vertices (weight ≠ 1)
            let w = weights
                .iter()
                .map(|w| {
                    if *w == int(1) {
                        w.clone()
                    } else {
                        int(2) * w.mul_ref(w) - int(1)
                    }
                })
                .collect();
            (points.clone(), w)
        }
        CircleMistake::MiddleVertexOnCircle => {
            let c = center(points, weights)?;
            // b_j − c scaled by w_j: the middle vertices (w < 1) pulled onto the circle
            let moved = points
                .iter()
                .zip(weights)
                .map(|(b, w)| {
                    let mut q = c.clone();
                    q.add_scaled(&b.checked_sub(&c).ok()?, w);
                    Some(q)
                })
                .collect::<Option<Vec<_>>>()?;
            (moved, weights.clone())
        }
        CircleMistake::SingleKnots => {
            let curve = CurveIn::BSpline {
                points: points.clone(),
                degree: 2,
                knots: single_knots(knots, points.len())?,
                weights: Some(weights.clone()),
            };
            return Some(curve_answer(curve));
        }
    };
    Some(curve_answer(CurveIn::BSpline {
        points,
        degree: 2,
        knots: knots.clone(),
        weights: Some(weights),
    }))
}

/// The answer of one curve.
fn curve_answer(curve: CurveIn<Number>) -> Mistaken {
    Mistaken {
        result: vec![(Quantity::Curve, Exact::Curve(curve))],
        steps: Vec::new(),
    }
}

/// The center of the circle of the first arc, b_0, b_1, b_2 with middle weight w:
/// c = (M − w² b_1)/(1 − w²), M = (b_0 + b_2)/2.
fn center(points: &[Point<Number>], weights: &[Number]) -> Option<Point<Number>> {
    let (b0, b1, b2) = (points.first()?, points.get(1)?, points.get(2)?);
    let w = weights.get(1)?;
    let w2 = w.mul_ref(w);
    let inv = int(1).checked_div(&(int(1) - w2.clone()))?;
    let half = int(1).checked_div(&int(2))?;
    let mut c = Point::zero(b0.dim());
    c.add_scaled(b0, &half.mul_ref(&inv));
    c.add_scaled(b2, &half.mul_ref(&inv));
    c.add_scaled(b1, &(-(w2 * inv)));
    Some(c)
}

/// The knot vector of a circle of `points` = 2N + 1 vertices on the key's interval [a, b]
/// with every knot single and equally spaced, in the key's convention: the notes'
/// {a, a, a + h, ..., b − h, b, b} (2N + 2 knots) or the full one, each end once more;
/// h = (b − a)/(2N − 1).
fn single_knots(knots: &[Number], points: usize) -> Option<Vec<Number>> {
    let (a, b) = (knots.first()?, knots.last()?);
    // points + p − 1 knots in the notes' convention, two more in the full one
    let ends = match knots.len().checked_sub(points + 1)? {
        0 => 2,
        2 => 3,
        _ => return None,
    };
    let spans = i64::try_from(points.checked_sub(2)?).ok()?;
    let h = b.sub_ref(a).checked_div(&int(spans))?;
    let mut out = vec![a.clone(); ends];
    for j in 1..spans {
        out.push(a.add_ref(&h.mul_ref(&int(j))));
    }
    out.extend(std::iter::repeat_n(b.clone(), ends));
    Some(out)
}
