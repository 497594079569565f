//! The teacher's check of an `expected` curve or surface: a rational answer written without
//! its weights is a mismatch (unless all its weights are equal: then it is the polynomial
//! curve of the same points), and knots are compared modulo the convention (the notes' or
//! The NURBS Book's, with one end knot more at each end).

use cagd_problem::check;
use cagd_words::{Lang, Message};
use serde_json::{json, Value};

/// The mismatches of `problem` checked against `expected`, in `lang`.
fn mismatches_in(lang: Lang, mut problem: Value, expected: Value) -> Vec<String> {
    problem["expected"] = expected;
    let v = check(&problem);
    assert!(v.answer.is_ok() && v.checked, "{problem}");
    v.mismatches.iter().map(|m| m.phrase(lang).text()).collect()
}

/// The mismatches of `problem` checked against `expected`, in English.
fn mismatches(problem: Value, expected: Value) -> Vec<String> {
    mismatches_in(Lang::En, problem, expected)
}

fn elevate(weights: Value) -> Value {
    json!({"op": "elevate", "curve": {"bezier": [[0, 0], [1, 2], [3, 3]], "weights": weights}, "by": 1})
}

#[test]
fn a_rational_curve_expected_without_its_weights_is_a_mismatch() {
    let points = json!([[0, 0], ["4/5", "8/5"], ["7/5", "11/5"], [3, 3]]);
    assert_eq!(
        mismatches(
            elevate(json!([1, 2, 1])),
            json!({"curve": {"bezier": points}})
        ),
        ["`curve`: the answer is rational: its weights {1, 5/3, 5/3, 1} are missing"]
    );
    // with its weights it matches
    assert!(mismatches(
        elevate(json!([1, 2, 1])),
        json!({"curve": {"bezier": points, "weights": [1, "5/3", "5/3", 1]}})
    )
    .is_empty());
}

#[test]
fn equal_weights_make_the_polynomial_curve_and_it_matches() {
    let points = json!([[0, 0], ["2/3", "4/3"], ["5/3", "7/3"], [3, 3]]);
    assert!(mismatches(
        elevate(json!([2, 2, 2])),
        json!({"curve": {"bezier": points}})
    )
    .is_empty());
}

#[test]
fn the_truncated_cone_quadrant_as_a_plain_mesh_is_a_mismatch() {
    let cone = json!({"op": "revolution", "curve": {"bezier": [[2, 0, 0], [1, 0, 1]]}, "arcs": 1});
    let mesh = json!([
        [[2, 0, 0], [2, 2, 0], [0, 2, 0]],
        [[1, 0, 1], [1, 1, 1], [0, 1, 1]]
    ]);
    assert_eq!(
        mismatches(cone.clone(), json!({"surface": {"bezier": mesh}})),
        ["`surface`: the answer is rational: its weights [1, √2/2, 1; 1, √2/2, 1] are missing"]
    );
    assert_eq!(
        mismatches_in(Lang::Es, cone.clone(), json!({"surface": {"bezier": mesh}})),
        ["`surface`: la respuesta es racional: faltan sus pesos [1, √2/2, 1; 1, √2/2, 1]"]
    );
    assert!(mismatches(
        cone,
        json!({"surface": {"bezier": mesh, "weights": [[1, "sqrt2/2", 1], [1, "sqrt2/2", 1]]}})
    )
    .is_empty());
}

fn insert_knot() -> Value {
    json!({"op": "insert_knot", "curve": {"bspline": [[0, 0], [1, 2], [3, 2], [4, 0]], "degree": 2, "knots": [0, 0, 1, 2, 2]}, "knot": "1/2", "times": 1})
}

fn inserted(knots: Value) -> Value {
    json!({"curve": {"bspline": [[0, 0], ["1/2", 1], ["3/2", 2], [3, 2], [4, 0]], "degree": 2, "knots": knots}})
}

#[test]
fn knots_match_in_either_convention() {
    // the notes' convention
    assert!(mismatches(insert_knot(), inserted(json!([0, 0, "1/2", 1, 2, 2]))).is_empty());
    // The NURBS Book's: one end knot more at each end
    assert!(mismatches(insert_knot(), inserted(json!([0, 0, 0, "1/2", 1, 2, 2, 2]))).is_empty());
}

#[test]
fn wrong_knots_are_a_mismatch() {
    assert_eq!(
        mismatches(insert_knot(), inserted(json!([0, 0, "1/3", 1, 2, 2]))),
        ["`curve`: expected knots {0, 0, 1/3, 1, 2, 2}, computed {0, 0, 1/2, 1, 2, 2}"]
    );
    assert_eq!(
        mismatches(insert_knot(), inserted(json!([0, 0, 0, "1/3", 1, 2, 2, 2]))).len(),
        1
    );
}
