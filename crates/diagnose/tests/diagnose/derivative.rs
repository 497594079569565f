//! Derivative mistakes over random derivative problems (the exercises' generator: patches,
//! orders (1, 0) to (0, 2), sometimes on a border), over Bézier curves and twists of small
//! integers, and checked against the differences computed here by hand.

use crate::common::{generated, holds_over, key};
use cagd_problem::diagnosis::DerivativeMistake;
use cagd_problem::{Mistake, Quantity};
use proptest::prelude::*;
use serde_json::{json, Value};

/// The r-th forward differences Δ^r b_i of a polygon of integer points.
fn differences(points: &[Vec<i64>], r: usize) -> Vec<Vec<i64>> {
    let mut d = points.to_vec();
    for _ in 0..r {
        d = d
            .windows(2)
            .map(|w| w[1].iter().zip(&w[0]).map(|(a, b)| a - b).collect())
            .collect();
    }
    d
}

/// The mistaken result `q` of `m` on `problem`, as JSON.
fn mistaken_json(problem: &Value, m: Mistake, q: &Quantity) -> Option<Value> {
    let key = key(problem);
    let (_, x) = key.mistaken.iter().find(|(k, _)| *k == m)?;
    x.result
        .iter()
        .find(|(k, _)| k == q)
        .map(|(_, v)| v.to_json())
}

/// Points written as the answer's JSON writes them (numbers as strings).
fn points_json(points: &[Vec<i64>]) -> Value {
    points
        .iter()
        .map(|p| Value::from(p.iter().map(|c| c.to_string()).collect::<Vec<_>>()))
        .collect()
}

/// A Bézier polygon written as the answer's JSON writes it.
fn polygon_json(points: &[Vec<i64>]) -> Value {
    json!({ "bezier": points_json(points) })
}

fn point() -> impl Strategy<Value = Vec<i64>> {
    prop::collection::vec(-4i64..=4, 2)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4))]

    #[test]
    fn every_derivative_mistake_is_diagnosed(seed in 0u64..1_000_000) {
        let mut problems = generated("derivative", 12, seed);
        // a first derivative of a Bézier patch, where every mistake but the power applies
        problems.push(json!({
            "op": "derivative",
            "surface": {"bezier": [[[0, 0, 0], [0, 1, 1]], [[1, 0, 2], [1, 1, -1]], [[2, 0, 1], [2, 2, 0]]]},
            "order": [1, 0]
        }));
        for m in [
            DerivativeMistake::DegreeFactorLeftOut,
            DerivativeMistake::DifferencesReversed,
            DerivativeMistake::OtherDirection,
        ] {
            holds_over(&problems, Mistake::Derivative(m));
        }
    }

    /// A Bézier curve of degree 2 to 4 with its derivative of order 1 to 3: every mistake but
    /// the other direction (a curve has one) applies where it changes the answer, and the
    /// factor left out gives the differences Δ^r b_i themselves.
    #[test]
    fn curve_derivatives(points in prop::collection::vec(point(), 3..=5), r in 1usize..=3) {
        let problem = json!({"op": "derivative", "curve": {"bezier": points}, "order": r});
        for m in [
            DerivativeMistake::DegreeFactorLeftOut,
            DerivativeMistake::PowerForFalling,
            DerivativeMistake::DifferencesReversed,
        ] {
            let m = Mistake::Derivative(m);
            crate::common::diagnosed_as(&problem, m);
        }
        let left_out = Mistake::Derivative(DerivativeMistake::DegreeFactorLeftOut);
        let d = differences(&points, r);
        if d.iter().any(|p| p.iter().any(|c| *c != 0)) && r < points.len() {
            prop_assert_eq!(
                mistaken_json(&problem, left_out, &Quantity::Curve),
                Some(polygon_json(&d))
            );
        }
        let other = Mistake::Derivative(DerivativeMistake::OtherDirection);
        prop_assert!(key(&problem).mistaken.iter().all(|(k, _)| *k != other));
    }

    /// The twist c_uv of a Bézier patch of small integers: its factor mn left out is the mesh
    /// of the differences Δ^{1,1}c_{i,j} = c_{i+1,j+1} − c_{i+1,j} − c_{i,j+1} + c_{i,j}.
    #[test]
    fn twists(mesh in prop::collection::vec(prop::collection::vec(point(), 3), 3)) {
        let problem = json!({"op": "derivative", "surface": {"bezier": mesh}, "order": [1, 1]});
        let left_out = Mistake::Derivative(DerivativeMistake::DegreeFactorLeftOut);
        let twist: Vec<Vec<Vec<i64>>> = (0..2)
            .map(|i| {
                (0..2)
                    .map(|j| {
                        (0..2)
                            .map(|k| {
                                mesh[i + 1][j + 1][k] - mesh[i + 1][j][k] - mesh[i][j + 1][k]
                                    + mesh[i][j][k]
                            })
                            .collect()
                    })
                    .collect()
            })
            .collect();
        if twist.iter().flatten().flatten().any(|c| *c != 0) {
            prop_assert!(crate::common::diagnosed_as(&problem, left_out));
            let rows: Vec<Value> = twist.iter().map(|row| points_json(row)).collect();
            prop_assert_eq!(
                mistaken_json(&problem, left_out, &Quantity::Surface),
                Some(json!({ "bezier": rows }))
            );
        }
    }
}

/// The power for the falling factorial, over second derivatives of random patches and
/// curves: n² Δ²b_i for n(n − 1) Δ²b_i.
#[test]
fn power_for_falling_over_second_derivatives() {
    let mut problems: Vec<Value> = generated("derivative", 40, 7)
        .into_iter()
        .filter(|p| p["order"] == json!([2, 0]) || p["order"] == json!([0, 2]))
        .collect();
    problems.push(json!({"op": "derivative", "curve": {"bezier": [[0, 0], [1, 2], [3, 1], [4, 4]]}, "order": 2}));
    holds_over(
        &problems,
        Mistake::Derivative(DerivativeMistake::PowerForFalling),
    );
    // n = 3, r = 2: 9 Δ²b_i for 6 Δ²b_i; Δ²b_0 = (1, -3), Δ²b_1 = (-1, 4)
    let curve = json!({"op": "derivative", "curve": {"bezier": [[0, 0], [1, 2], [3, 1], [4, 4]]}, "order": 2});
    assert_eq!(
        mistaken_json(
            &curve,
            Mistake::Derivative(DerivativeMistake::PowerForFalling),
            &Quantity::Curve
        ),
        Some(polygon_json(&[vec![9, -27], vec![-9, 36]]))
    );
}

/// The student's report of tests/reports/derivative.json (the factor m = 2 of (19) left
/// out): both results wrong, each diagnosed as that mistake alone.
#[test]
fn the_report_is_diagnosed() {
    let report: Value =
        serde_json::from_str(include_str!("../reports/derivative.json")).expect("it reads");
    let verdict = cagd_diagnose::diagnose(&report, &crate::common::settings());
    let a = verdict.assessment.expect("an assessment");
    let left_out = Mistake::Derivative(DerivativeMistake::DegreeFactorLeftOut);
    assert_eq!(a.results.len(), 2);
    for r in &a.results {
        assert!(!r.correct(), "{}", r.quantity.name());
        assert_eq!(r.diagnoses.len(), 1);
        assert!(r.diagnoses[0].whole && r.diagnoses[0].mistakes == [left_out]);
    }
}
