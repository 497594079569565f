//! Degree elevation mistakes over random problems: the exercises' patches (rational and
//! B-spline ones too) and curves drawn from small integers (polynomial and rational), each
//! mistaken answer also checked against an independent computation.

// test helpers: a problem the test builds has an answer, a result its shape
#![allow(clippy::expect_used, clippy::panic, clippy::indexing_slicing)]

use crate::common::{generated, holds_over, key};
use cagd_problem::diagnosis::ElevateMistake;
use cagd_problem::input::CurveIn;
use cagd_problem::{Exact, Mistake, Quantity};
use proptest::prelude::*;
use serde_json::{json, Value};

/// The Bézier curve of `points` (and `weights`) elevated by `by`.
fn curve(points: &[(i64, i64)], weights: Option<&[i64]>, by: usize) -> Value {
    let mut c = json!({ "bezier": points.iter().map(|(x, y)| json!([x, y])).collect::<Vec<_>>() });
    if let Some(w) = weights {
        c["weights"] = json!(w);
    }
    json!({ "op": "elevate", "curve": c, "by": by })
}

/// The mistaken curve of `m` on `problem` (`None` when it does not apply).
fn mistaken(problem: &Value, m: ElevateMistake) -> Option<Exact> {
    let key = key(problem);
    let (_, x) = key
        .mistaken
        .iter()
        .find(|(k, _)| *k == Mistake::Elevate(m))?;
    x.result
        .iter()
        .find(|(k, _)| *k == Quantity::Curve)
        .map(|(_, x)| x.clone())
}

/// The key's curve.
fn solved(problem: &Value) -> Exact {
    let a = key(problem).answer.expect("an answer");
    a.result
        .into_iter()
        .find(|(k, _)| *k == Quantity::Curve)
        .expect("the curve")
        .1
}

/// A curve's points and weights.
fn parts(
    x: &Exact,
) -> (
    Vec<cagd_linalg::Point<cagd_problem::Number>>,
    Option<Vec<cagd_problem::Number>>,
) {
    match x {
        Exact::Curve(CurveIn::Bezier { points, weights }) => (points.clone(), weights.clone()),
        _ => panic!("not a Bézier curve: {x:?}"),
    }
}

fn points() -> impl Strategy<Value = Vec<(i64, i64)>> {
    prop::collection::vec((-3i64..=3, -3i64..=3), 2..=4)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4))]

    #[test]
    fn every_elevation_mistake_is_diagnosed(
        seed in 0u64..1_000_000,
        ps in points(),
        ws in prop::collection::vec(1i64..=3, 4),
        by in 1usize..=2,
    ) {
        let mut problems = generated("elevate", 3, seed);
        // weights not all equal (equal weights make a polynomial curve)
        let mut w = ws[..ps.len()].to_vec();
        w[1] = w[0] + 1;
        let w = w.as_slice();
        problems.push(curve(&ps, None, by));
        problems.push(curve(&ps, Some(w), by));
        // a patch elevated in u only: the other direction is v
        let mut patch = json!({
            "op": "elevate",
            "surface": {"bezier": [[[0, 0, ps[0].0], [0, 1, ps[0].1]], [[1, 0, ps[1].0], [1, 1, ps[1].1]]]},
            "by": [by, 0],
        });
        problems.push(patch.clone());
        patch["surface"]["weights"] = json!([[w[0], w[1]], [1, 1]]);
        problems.push(patch);
        for m in ElevateMistake::ALL {
            holds_over(&problems, Mistake::Elevate(*m));
        }
    }

    #[test]
    fn the_elevation_mistakes_are_what_they_say(
        ps in points(),
        ws in prop::collection::vec(1i64..=3, 4),
    ) {
        let n = ps.len() - 1;
        let p = curve(&ps, None, 1);
        let (key, _) = parts(&solved(&p));
        let c: Vec<cagd_linalg::Point<cagd_problem::Number>> =
            ps.iter().map(|(x, y)| cagd_linalg::Point::from_ints(&[*x, *y])).collect();
        // divided by n: the coefficient n/n puts c_{n−1} at place n
        if let Some(x) = mistaken(&p, ElevateMistake::DividedByM) {
            let (x, _) = parts(&x);
            prop_assert_eq!(&x[n], &c[n - 1]);
            prop_assert_eq!(x.len(), n + 2);
        }
        // swapped coefficients: the two answers add up to c_{i−1} + c_i inside
        if let Some(x) = mistaken(&p, ElevateMistake::CoefficientsSwapped) {
            let (x, _) = parts(&x);
            for i in 1..=n {
                let sum = x[i].checked_add(&key[i]).unwrap();
                prop_assert_eq!(sum, c[i - 1].checked_add(&c[i]).unwrap());
            }
        }
        // points and weights apart: the polynomial curve's points, the right weights
        let mut w = ws[..ps.len()].to_vec();
        w[1] = w[0] + 1;
        let w = w.as_slice();
        let rational = curve(&ps, Some(w), 1);
        if let Some(x) = mistaken(&rational, ElevateMistake::WeightsApart) {
            let (points, weights) = parts(&x);
            prop_assert_eq!(points, key.clone());
            prop_assert_eq!(weights, parts(&solved(&rational)).1);
        }
    }
}

/// The student's report of `tests/reports/elevate.json` is diagnosed as its mistake, alone.
#[test]
fn the_students_report_is_diagnosed() {
    let text = include_str!("../reports/elevate.json");
    let problem: Value = serde_json::from_str(text).expect("the report reads");
    let verdict = cagd_diagnose::diagnose(&problem, &crate::common::settings());
    let a = verdict.assessment.expect("an assessment");
    assert!(!a.correct());
    assert_eq!(
        a.mistakes(),
        [Mistake::Elevate(ElevateMistake::CoefficientsSwapped)]
    );
}
