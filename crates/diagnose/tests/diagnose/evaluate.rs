//! De Casteljau evaluation mistakes over random problems: the exercises' patches (rational
//! ones too) and curves drawn from small integers (polynomial and rational), each mistaken
//! answer also checked against an independent computation.

// test helpers: a problem the test builds has an answer, a result its shape
#![allow(clippy::expect_used, clippy::panic, clippy::indexing_slicing)]

use crate::common::{generated, holds_over, key};
use cagd_problem::diagnosis::EvaluateMistake;
use cagd_problem::{Exact, Mistake, Quantity};
use proptest::prelude::*;
use serde_json::{json, Value};

/// A Bézier curve of the points `points` (and `weights`), evaluated at `k/5` for each k.
fn curve(points: &[(i64, i64)], weights: Option<&[i64]>, ks: &[i64]) -> Value {
    let mut c = json!({ "bezier": points.iter().map(|(x, y)| json!([x, y])).collect::<Vec<_>>() });
    if let Some(w) = weights {
        c["weights"] = json!(w);
    }
    json!({
        "op": "evaluate",
        "curve": c,
        "params": ks.iter().map(|k| format!("{k}/5")).collect::<Vec<_>>(),
    })
}

/// The mistaken result `q` of `m` on `problem` (`None` when it does not apply).
fn mistaken(problem: &Value, m: EvaluateMistake, q: &Quantity) -> Option<Exact> {
    let key = key(problem);
    let (_, x) = key
        .mistaken
        .iter()
        .find(|(k, _)| *k == Mistake::Evaluate(m))?;
    x.result
        .iter()
        .find(|(k, _)| k == q)
        .map(|(_, x)| x.clone())
}

/// The key's result `q`.
fn solved(problem: &Value, q: &Quantity) -> Exact {
    let key = key(problem);
    let a = key.answer.expect("an answer");
    a.result
        .into_iter()
        .find(|(k, _)| k == q)
        .expect("the result")
        .1
}

fn points() -> impl Strategy<Value = Vec<(i64, i64)>> {
    prop::collection::vec((-3i64..=3, -3i64..=3), 3..=4)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4))]

    #[test]
    fn every_evaluation_mistake_is_diagnosed(
        seed in 0u64..1_000_000,
        ps in points(),
        ws in prop::collection::vec(1i64..=3, 4),
        ks in prop::collection::vec(1i64..=4, 1..=2),
    ) {
        let mut problems = generated("evaluate", 3, seed);
        let w = &ws[..ps.len()];
        problems.push(curve(&ps, None, &ks));
        problems.push(curve(&ps, Some(w), &ks));
        for m in EvaluateMistake::ALL {
            holds_over(&problems, Mistake::Evaluate(*m));
        }
    }

    #[test]
    fn the_evaluation_mistakes_are_what_they_say(
        ps in points(),
        ws in prop::collection::vec(1i64..=3, 4),
        ks in prop::collection::vec(1i64..=4, 1..=2),
    ) {
        let w = &ws[..ps.len()];
        let q = Quantity::Points;
        for weights in [None, Some(w)] {
            // t ↔ 1 − t: the reversed polygon evaluated at t
            let rev: Vec<_> = ps.iter().rev().copied().collect();
            let wrev: Vec<i64> = w.iter().rev().copied().collect();
            let p = curve(&ps, weights, &ks);
            let reversed = curve(&rev, weights.map(|_| wrev.as_slice()), &ks);
            if let Some(x) = mistaken(&p, EvaluateMistake::OneMinusT, &q) {
                prop_assert_eq!(x, solved(&reversed, &q));
            }
        }
        // the weights ignored: the polynomial curve of the same points
        let rational = curve(&ps, Some(w), &ks);
        if let Some(x) = mistaken(&rational, EvaluateMistake::WeightsIgnored, &q) {
            prop_assert_eq!(x, solved(&curve(&ps, None, &ks), &q));
        }
        // not divided: the numerator Σ w_i c_i B_i, the polynomial curve of the points w_i c_i
        let scaled: Vec<_> = ps.iter().zip(w).map(|((x, y), w)| (x * w, y * w)).collect();
        if let Some(x) = mistaken(&rational, EvaluateMistake::NotDivided, &q) {
            prop_assert_eq!(x, solved(&curve(&scaled, None, &ks), &q));
        }
        // binomials forgotten, on a quadratic: Σ t^i (1 − t)^{2−i} c_i = B-form of c_0, c_1/2, c_2
        let quadratic = &ps[..3];
        let doubled: Vec<_> = quadratic
            .iter()
            .enumerate()
            .map(|(i, (x, y))| if i == 1 { (*x, *y) } else { (2 * x, 2 * y) })
            .collect();
        let p = curve(quadratic, None, &ks);
        if let (Some(Exact::Points(x)), Exact::Points(y)) = (
            mistaken(&p, EvaluateMistake::BinomialsForgotten, &q),
            solved(&curve(&doubled, None, &ks), &q),
        ) {
            // the curve of 2c_0, c_1, 2c_2 is twice the one of c_0, c_1/2, c_2
            let two = <cagd_problem::Number as cagd_scalar::FieldOps>::from_i64(2);
            let x: Vec<_> = x.iter().map(|p| p.scale(&two)).collect();
            prop_assert_eq!(x, y);
        }
    }
}

/// The student's report of `tests/reports/evaluate.json` is diagnosed as its mistake, alone.
#[test]
fn the_students_report_is_diagnosed() {
    let text = include_str!("../reports/evaluate.json");
    let problem: Value = serde_json::from_str(text).expect("the report reads");
    let verdict = cagd_diagnose::diagnose(&problem, &crate::common::settings());
    let a = verdict.assessment.expect("an assessment");
    assert!(!a.correct());
    assert_eq!(
        a.mistakes(),
        [Mistake::Evaluate(EvaluateMistake::NotDivided)]
    );
}
