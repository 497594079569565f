//! Normal mistakes over random normal problems (the exercises' generator: Bézier, rational
//! and B-spline patches), and the corner normals of meshes of small integers checked
//! against (25) computed here by hand.

use crate::common::{diagnosed_as, generated, holds_over, key};
use cagd_problem::diagnosis::NormalMistake;
use cagd_problem::Mistake;
use proptest::prelude::*;
use serde_json::{json, Value};

/// a × b of integer vectors.
fn cross(a: &[i64], b: &[i64]) -> [i64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// b − a.
fn minus(b: &[i64], a: &[i64]) -> Vec<i64> {
    b.iter().zip(a).map(|(x, y)| x - y).collect()
}

/// A point as the answer's JSON writes it (numbers as strings).
fn point_json(p: &[i64]) -> Value {
    p.iter().map(|c| c.to_string()).collect()
}

/// The mistaken corner normal `corner` (`corner_10`) of `m` on `problem`, as JSON.
fn mistaken_corner(problem: &Value, m: Mistake, corner: &str) -> Option<Value> {
    let key = key(problem);
    let (_, x) = key.mistaken.iter().find(|(k, _)| *k == m)?;
    x.result
        .iter()
        .find(|(k, _)| k.name() == corner)
        .map(|(_, v)| v.to_json())
}

fn point() -> impl Strategy<Value = Vec<i64>> {
    prop::collection::vec(-3i64..=3, 3)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4))]

    #[test]
    fn every_normal_mistake_is_diagnosed(seed in 0u64..1_000_000) {
        let problems = generated("normal", 8, seed);
        for m in NormalMistake::ALL {
            holds_over(&problems, Mistake::Normal(*m));
        }
    }

    /// A biquadratic mesh of small integers: at c_{0,0} the factors left out give
    /// Δ^{1,0}c_{0,0} × Δ^{0,1}c_{0,0}, the cross product reversed its opposite times mn = 4,
    /// and at c_{m,0} the outward differences 4 (c_{1,0} − c_{2,0}) × (c_{2,1} − c_{2,0}).
    #[test]
    fn corner_normals_by_hand(mesh in prop::collection::vec(prop::collection::vec(point(), 3), 3)) {
        let problem = json!({"op": "normal", "surface": {"bezier": mesh}});
        let n00 = cross(&minus(&mesh[1][0], &mesh[0][0]), &minus(&mesh[0][1], &mesh[0][0]));
        let outward = cross(&minus(&mesh[1][0], &mesh[2][0]), &minus(&mesh[2][1], &mesh[2][0]));
        let (factors, reversed, outward_differences) = (
            Mistake::Normal(NormalMistake::DegreeFactorsLeftOut),
            Mistake::Normal(NormalMistake::CrossReversed),
            Mistake::Normal(NormalMistake::OutwardDifferences),
        );
        if n00 != [0, 0, 0] {
            prop_assert_eq!(mistaken_corner(&problem, factors, "corner_00"), Some(point_json(&n00)));
            let minus4: Vec<i64> = n00.iter().map(|c| -4 * c).collect();
            prop_assert_eq!(mistaken_corner(&problem, reversed, "corner_00"), Some(point_json(&minus4)));
            prop_assert!(diagnosed_as(&problem, factors));
        }
        if outward != [0, 0, 0] {
            let times4: Vec<i64> = outward.iter().map(|c| 4 * c).collect();
            prop_assert_eq!(
                mistaken_corner(&problem, outward_differences, "corner_10"),
                Some(point_json(&times4))
            );
            prop_assert!(diagnosed_as(&problem, outward_differences));
        }
    }
}

/// The student's report of tests/reports/normal.json ((25) as the notes print it, without
/// mn = 4): the closed form right, the four corners wrong, each diagnosed as the factors
/// left out alone.
#[test]
fn the_report_is_diagnosed() {
    let report: Value =
        serde_json::from_str(include_str!("../reports/normal.json")).expect("it reads");
    let verdict = cagd_diagnose::diagnose(&report, &crate::common::settings());
    let a = verdict.assessment.expect("an assessment");
    let left_out = Mistake::Normal(NormalMistake::DegreeFactorsLeftOut);
    assert_eq!(a.results.len(), 5);
    for r in &a.results {
        if r.quantity.name() == "closed_form" {
            assert!(r.correct());
            continue;
        }
        assert!(!r.correct(), "{}", r.quantity.name());
        assert_eq!(r.diagnoses.len(), 1);
        assert!(r.diagnoses[0].whole && r.diagnoses[0].mistakes == [left_out]);
    }
}
