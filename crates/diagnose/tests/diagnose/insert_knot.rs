//! Knot insertion mistakes over random B-spline and NURBS curves and surfaces (small
//! integer polygons, clamped knots on integer breakpoints in either convention, a knot
//! t = a/2 inserted once or more), with Boehm's step worked by hand on the example of The
//! NURBS Book's kind.

use crate::common::{holds_over, key, report};
use cagd_problem::diagnosis::InsertKnotMistake;
use cagd_problem::input::CurveIn;
use cagd_problem::{Exact, Mistake, Number};
use cagd_scalar::FieldOps;
use proptest::prelude::*;
use serde_json::{json, Value};

/// Clamped knots of degree p on the breakpoints 0, 1, ..., s: the notes' convention (each
/// end p times) or the full one (p + 1 times).
fn clamped(p: usize, s: usize, full: bool) -> Vec<Value> {
    let ends = p + usize::from(full);
    let mut k = vec![json!(0); ends];
    k.extend((1..s).map(|i| json!(i)));
    k.extend(std::iter::repeat_n(json!(s), ends));
    k
}

/// The knot a/2 (a in 1..2s) and how many times (1..=p − its multiplicity); a knot already
/// there with degree 1 moves to the next half.
fn knot_and_times(p: usize, s: usize, a: usize, r: usize) -> (Value, usize) {
    let a = if a % 2 == 0 && p == 1 { a + 1 } else { a };
    let a = a.min(2 * s - 1);
    let mult = usize::from(a % 2 == 0);
    (json!(format!("{a}/2")), 1 + r % (p - mult))
}

/// A random curve or surface and knot: a problem of `insert_knot`.
fn problem() -> impl Strategy<Value = Value> {
    (
        1usize..=3,
        1usize..=3,
        1usize..=3,
        proptest::collection::vec(-4i64..=4, 60),
        proptest::collection::vec(1i64..=3, 30),
        any::<bool>(),
        any::<bool>(),
        (1usize..12, 0usize..3),
        any::<bool>(),
        any::<bool>(),
    )
        .prop_map(|(p, q, s, coords, ws, rational, surface, (a, r), in_u, full)| {
            let (knot, times) = knot_and_times(if surface && !in_u { q } else { p }, s, a % (2 * s) + 1, r);
            let mut c = coords.into_iter().cycle();
            let mut w = ws.into_iter().cycle();
            if surface {
                let (rows, cols) = (s + p, s + q);
                let mesh: Vec<Vec<Value>> = (0..rows)
                    .map(|_| (0..cols).map(|_| json!([c.next(), c.next(), c.next()])).collect())
                    .collect();
                let mut sf = json!({"bspline": mesh, "degree": [p, q], "knots": [clamped(p, s, full), clamped(q, s, full)]});
                if rational {
                    let weights: Vec<Vec<i64>> = (0..rows)
                        .map(|_| (0..cols).map(|_| w.next().unwrap_or(1)).collect())
                        .collect();
                    sf["weights"] = json!(weights);
                }
                json!({"op": "insert_knot", "surface": sf, "knot": knot, "times": times,
                       "direction": if in_u { "u" } else { "v" }})
            } else {
                let n = s + p;
                let points: Vec<Value> = (0..n).map(|_| json!([c.next(), c.next()])).collect();
                let mut cv = json!({"bspline": points, "degree": p, "knots": clamped(p, s, full)});
                if rational {
                    let weights: Vec<i64> = (0..n).map(|_| w.next().unwrap_or(1)).collect();
                    cv["weights"] = json!(weights);
                }
                json!({"op": "insert_knot", "curve": cv, "knot": knot, "times": times})
            }
        })
}

/// The mistaken curve of `m` on `problem`.
fn mistaken_curve(problem: &Value, m: InsertKnotMistake) -> Option<CurveIn<Number>> {
    let k = key(problem);
    let (_, x) = k
        .mistaken
        .iter()
        .find(|(k, _)| *k == Mistake::InsertKnot(m))?;
    match x.result.first() {
        Some((_, Exact::Curve(c))) => Some(c.clone()),
        _ => None,
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4))]

    #[test]
    fn every_insert_knot_mistake_is_diagnosed(problems in proptest::collection::vec(problem(), 80)) {
        for m in InsertKnotMistake::ALL {
            holds_over(&problems, Mistake::InsertKnot(*m));
        }
    }

    /// Without weights, the swapped combination and the right one add up to d_{i−1} + d_i
    /// at each new point of one insertion: α + (1 − α) = 1 on both sides.
    #[test]
    fn swapped_and_right_add_up_to_the_neighbours(problems in proptest::collection::vec(problem(), 8)) {
        for p in problems.iter().filter(|p| p.get("curve").is_some() && p["curve"].get("weights").is_none() && p["times"] == 1) {
            let Some(CurveIn::BSpline { points: wrong, .. }) = mistaken_curve(p, InsertKnotMistake::AlphaSwapped) else {
                continue;
            };
            let k = key(p);
            let Some((_, Exact::Curve(CurveIn::BSpline { points: right, .. }))) =
                k.answer.as_ref().ok().and_then(|a| a.result.first()) else {
                panic!("a curve");
            };
            let Ok(cagd_problem::Op::InsertKnot(a)) = cagd_problem::Problem::read(p, &cagd_problem::Limits::DEFAULT).map(|x| x.op) else {
                panic!("insert_knot");
            };
            let Some(CurveIn::BSpline { points: d, .. }) = a.curve else { panic!("a B-spline") };
            for (i, (r, w)) in right.iter().zip(&wrong).enumerate() {
                if r == w {
                    continue;
                }
                let sum = r.checked_add(w).unwrap();
                let neighbours = d[i - 1].checked_add(&d[i]).unwrap();
                prop_assert_eq!(sum, neighbours, "point {} of {}", i, p);
            }
        }
    }

    /// Combining points and weights apart changes the points only: the weights are the
    /// same combinations in both forms.
    #[test]
    fn not_homogeneous_keeps_the_weights(problems in proptest::collection::vec(problem(), 8)) {
        for p in problems.iter().filter(|p| p.get("curve").is_some()) {
            let Some(CurveIn::BSpline { weights: wrong, .. }) = mistaken_curve(p, InsertKnotMistake::NotHomogeneous) else {
                continue;
            };
            let k = key(p);
            let Some((_, Exact::Curve(CurveIn::BSpline { weights: right, .. }))) =
                k.answer.as_ref().ok().and_then(|a| a.result.first()) else {
                panic!("a curve");
            };
            prop_assert_eq!(wrong, right.clone());
        }
    }
}

fn ratio(n: i64, d: i64) -> Number {
    <Number as FieldOps>::from_ratio(n, d)
}

/// The quadratic of knots {0, 0, 1, 2, 2}, polygon (0, 0), (1, 2), (3, 2), (4, 0), t = 1/2:
/// α_1 = 1/2, α_2 = 1/4 (right: (1/2, 1), (3/2, 2)). Swapped: d̂_2 = 1/4 d_1 + 3/4 d_2 =
/// (5/2, 2). Order for degree: α_1 = (1/2 − 0)/(2 − 0) = 1/4, d̂_1 = (1/4, 1/2); α_2 = 1/4
/// as before.
#[test]
fn boehm_by_hand() {
    let p = json!({"op": "insert_knot", "curve": {"bspline": [[0, 0], [1, 2], [3, 2], [4, 0]],
        "degree": 2, "knots": [0, 0, 1, 2, 2]}, "knot": "1/2"});
    let points = |m| match mistaken_curve(&p, m) {
        Some(CurveIn::BSpline { points, .. }) => points
            .iter()
            .map(|q| q.coords().to_vec())
            .collect::<Vec<_>>(),
        other => panic!("{other:?}"),
    };
    let pt = |x: Number, y: Number| vec![x, y];
    let i = |n| ratio(n, 1);
    assert_eq!(
        points(InsertKnotMistake::AlphaSwapped),
        [
            pt(i(0), i(0)),
            pt(ratio(1, 2), i(1)),
            pt(ratio(5, 2), i(2)),
            pt(i(3), i(2)),
            pt(i(4), i(0))
        ]
    );
    assert_eq!(
        points(InsertKnotMistake::OrderForDegree),
        [
            pt(i(0), i(0)),
            pt(ratio(1, 4), ratio(1, 2)),
            pt(ratio(3, 2), i(2)),
            pt(i(3), i(2)),
            pt(i(4), i(0))
        ]
    );
}

/// The report of the snapshot tests: a student who swapped α and 1 − α.
#[test]
fn the_report_is_diagnosed() {
    assert_eq!(
        report(include_str!("../reports/insert_knot.json")).mistakes(),
        [Mistake::InsertKnot(InsertKnotMistake::AlphaSwapped)]
    );
}
