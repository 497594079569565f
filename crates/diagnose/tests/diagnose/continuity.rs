//! Continuity mistakes over random joins of two patches (the exercises' generator, some C^1
//! by construction, some with interval lengths), the same joins given lengths, the notes'
//! example (§6), and joins of two Bézier curves of small integers, whose order without the
//! degree factors is also computed here by hand.

use crate::common::{diagnosed_as, generated, holds_over, key};
use cagd_problem::diagnosis::ContinuityMistake;
use cagd_problem::{Exact, Mistake, Quantity};
use proptest::prelude::*;
use serde_json::{json, Value};

/// The notes' two biquadratic patches (chapter 5, §6): C^0, with parallel but unequal
/// differences across the border.
fn notes_example() -> Value {
    let text = include_str!("../../../../fixtures/ch5/07-c1-join.json");
    let mut p: Value = serde_json::from_str(text).expect("the fixture reads");
    if let Value::Object(o) = &mut p {
        o.remove("expected");
    }
    p
}

/// The problem given interval lengths [Δu_0, Δu_1] (where it has none).
fn with_lengths(mut p: Value, lengths: [i64; 2]) -> Value {
    if p.get("lengths").is_none() {
        p["lengths"] = json!(lengths);
    }
    p
}

/// The mistaken order of `m` on `problem`.
fn mistaken_order(problem: &Value, m: Mistake) -> Option<Exact> {
    let key = key(problem);
    let (_, x) = key.mistaken.iter().find(|(k, _)| *k == m)?;
    x.result
        .iter()
        .find(|(q, _)| *q == Quantity::Order)
        .map(|(_, v)| v.clone())
}

/// The order of two integer polygons compared by their differences Δ^k b_{n−k}, Δ^k c_0
/// (zero past the degree), k = 0, 1, ...: the first k that differ, less one; `None` when
/// they agree up to the higher degree.
fn order_of_differences(b: &[Vec<i64>], c: &[Vec<i64>]) -> Option<i64> {
    let diffs = |points: &[Vec<i64>], k: usize| -> Vec<Vec<i64>> {
        let mut d = points.to_vec();
        for _ in 0..k {
            d = d
                .windows(2)
                .map(|w| w[1].iter().zip(&w[0]).map(|(a, b)| a - b).collect())
                .collect();
        }
        d
    };
    let top = b.len().max(c.len()) - 1;
    for k in 0..=top {
        let x = diffs(b, k).last().cloned().unwrap_or(vec![0, 0]);
        let y = diffs(c, k).first().cloned().unwrap_or(vec![0, 0]);
        if x != y {
            return Some(k as i64 - 1);
        }
    }
    None
}

fn point() -> impl Strategy<Value = Vec<i64>> {
    prop::collection::vec(-3i64..=3, 2)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4))]

    #[test]
    fn every_patch_join_mistake_is_diagnosed(seed in 0u64..1_000_000) {
        let problems = generated("continuity", 8, seed);
        let mut lengths: Vec<Value> = problems.iter().cloned().map(|p| with_lengths(p, [1, 2])).collect();
        lengths.extend(problems.iter().cloned().map(|p| with_lengths(p, [2, 1])));
        for m in [ContinuityMistake::LengthsIgnored, ContinuityMistake::LengthsSwapped] {
            holds_over(&lengths, Mistake::Continuity(m));
        }
        let mut parallel = problems.clone();
        parallel.push(notes_example());
        holds_over(&parallel, Mistake::Continuity(ContinuityMistake::ParallelTakenForC1));
    }

    /// Two Bézier curves of degrees 1 to 3 that meet (the second starts at the first's end,
    /// and often leaves along its last difference, doubled or as it is): the mistakes that
    /// apply are diagnosed, and the order without the degree factors is the one of the
    /// differences computed here.
    #[test]
    fn curve_joins(
        first in prop::collection::vec(point(), 2..=4),
        rest in prop::collection::vec(point(), 1..=3),
        tangent in 0usize..3,
    ) {
        let end = first[first.len() - 1].clone();
        let last = {
            let before = &first[first.len() - 2];
            vec![end[0] - before[0], end[1] - before[1]]
        };
        let mut second = vec![end.clone()];
        match tangent {
            // G^1: the same direction, twice as long
            0 => second.push(vec![end[0] + 2 * last[0], end[1] + 2 * last[1]]),
            1 => second.push(vec![end[0] + last[0], end[1] + last[1]]),
            _ => {}
        }
        second.extend(rest);
        let problem = json!({"op": "curve_continuity", "first": {"bezier": first}, "second": {"bezier": second}});
        let parallel = diagnosed_as(&problem, Mistake::Continuity(ContinuityMistake::ParallelTakenForC1));
        // leaving along the last difference doubled: G^1 (α = 2m/n > 0) but never C^1 (α ≠ 1)
        if tangent == 0 && last != [0, 0] {
            prop_assert!(parallel);
            let order = mistaken_order(&problem, Mistake::Continuity(ContinuityMistake::ParallelTakenForC1));
            prop_assert!(matches!(order, Some(Exact::Int(k)) if k >= 1), "{:?}", order);
        }
        diagnosed_as(&problem, Mistake::Continuity(ContinuityMistake::DegreeFactorsLeftOut));
        let by_hand = order_of_differences(&first, &second);
        let left_out = mistaken_order(&problem, Mistake::Continuity(ContinuityMistake::DegreeFactorsLeftOut));
        let key_order = key(&problem).answer.ok().and_then(|a| a.result_of(&Quantity::Order).cloned());
        match by_hand {
            // the same order as the key's: the mistake shows (if at all) in the lists only
            Some(k) if Some(Exact::Int(k)) != key_order => {
                prop_assert_eq!(left_out, Some(Exact::Int(k)));
            }
            _ => {}
        }
    }
}

/// The notes' example: a student who takes the parallel differences (0, 0, −1), (0, 0, −2)
/// for equal ones writes C^1.
#[test]
fn the_notes_example_taken_for_c1() {
    let m = Mistake::Continuity(ContinuityMistake::ParallelTakenForC1);
    assert_eq!(mistaken_order(&notes_example(), m), Some(Exact::Int(1)));
    assert!(diagnosed_as(&notes_example(), m));
}

/// Curves of degrees 2 and 3 whose differences agree but whose derivatives do not: the
/// factors 2 and 3 left out make the join look C^1.
#[test]
fn degree_factors_left_out_over_curves_of_two_degrees() {
    let problem = json!({
        "op": "curve_continuity",
        "first": {"bezier": [[0, 0], [1, 1], [2, 1]]},
        "second": {"bezier": [[2, 1], [3, 1], [4, 2], [5, 2]]}
    });
    let m = Mistake::Continuity(ContinuityMistake::DegreeFactorsLeftOut);
    assert_eq!(mistaken_order(&problem, m), Some(Exact::Int(1)));
    holds_over(&[problem], m);
}

/// The student's report of tests/reports/continuity.json (the notes' example taken for
/// C^1): the differences right, the order 1 diagnosed as parallel taken for C^1 alone.
#[test]
fn the_report_is_diagnosed() {
    let report: Value =
        serde_json::from_str(include_str!("../reports/continuity.json")).expect("it reads");
    let verdict = cagd_diagnose::diagnose(&report, &crate::common::settings());
    let a = verdict.assessment.expect("an assessment");
    let parallel = Mistake::Continuity(ContinuityMistake::ParallelTakenForC1);
    assert_eq!(a.results.len(), 3);
    for r in &a.results {
        if r.quantity != Quantity::Order {
            assert!(r.correct(), "{}", r.quantity.name());
            continue;
        }
        assert!(!r.correct());
        assert_eq!(r.diagnoses.len(), 1);
        assert!(r.diagnoses[0].whole && r.diagnoses[0].mistakes == [parallel]);
    }
}
