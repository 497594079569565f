//! Problems in letters: for every operation that accepts them, the answer in letters
//! specialized to values equals the answer of the problem with the values put in.

use cagd_problem::solve;
use proptest::prelude::*;
use serde_json::{json, Value};

/// One problem per operation, its points (and weights) in the letters a, b, c, h. (Not
/// `continuity`, `curve_continuity` or `arc_length`: their verdicts in letters hold for general
/// values, and the test's random values could be special.)
fn problems() -> Vec<Value> {
    vec![
        json!({"op": "closed_form", "surface": {"bezier": [[[0, 0, "a"], [1, "b", 0], [2, 0, 0]], [[0, 0, 1], [1, 1, "c"], [2, 0, "a+b"]]]}}),
        json!({"op": "evaluate", "surface": {"bezier": [[[0, 0, 0], [0, "a", 0]], [["b", 0, 0], [1, 1, "c"]]]}, "params": [[0, 0], ["1/2", "1/3"]]}),
        json!({"op": "evaluate", "curve": {"bezier": [[0, "a"], ["b", 2], [3, "c"]], "weights": [1, "h", 1]}, "params": ["1/3"]}),
        json!({"op": "restrict", "curve": {"bezier": [[0, 0], ["a", 3], [3, "b"], [4, "c"]]}, "t": ["1/3", "3/4"]}),
        json!({"op": "restrict", "surface": {"bezier": [[[0, 0, "a"], [1, 0, 4], [2, 0, 3]], [[0, 2, 1], [1, "b", 5], [2, 2, 4]], [[0, 4, 0], [1, 4, 4], [2, "c", 3]]]}, "u": ["1/2", 1], "v": ["1/3", 1]}),
        json!({"op": "elevate", "curve": {"bezier": [["a", 0], [1, "b"], [3, "c"]]}, "by": 1}),
        json!({"op": "elevate", "surface": {"bezier": [[[0, 0, "a"], [1, 0, 4], [2, 0, 3]], [[0, 2, 1], [1, 2, "b"], [2, 2, 4]], [[0, 4, 0], [1, 4, 4], [2, 4, "c"]]]}, "by": [1, 0]}),
        json!({"op": "derivative", "curve": {"bezier": [[0, 0], ["a", 2], [3, "b"]]}, "order": 1}),
        json!({"op": "derivative", "surface": {"bezier": [[[0, 0, "a"], [0, 1, 0]], [[1, 0, "b"], [1, 1, "c"]]]}, "order": [1, 0], "at": {"u": 0}}),
        json!({"op": "normal", "surface": {"bezier": [[[0, 0, "a"], [0, 1, 0]], [[1, 0, "b"], [1, 1, "c"]]]}}),
        json!({"op": "translational", "c": {"bezier": [[1, 0, 0], [2, 0, "a"], [3, 0, 0]]}, "d": {"bezier": [[1, 0, 0], [1, 1, "b"], [1, 2, 0]]}}),
        json!({"op": "ruled", "c1": {"bezier": [[0, 0, "a"], [1, 0, "b"]]}, "c2": {"bezier": [[0, 1, "c"], [1, 1, 0]]}}),
        json!({"op": "coons", "c1": {"bezier": [[0, 0, 0], ["1/2", 0, "a"], [2, 0, 0]]}, "c2": {"bezier": [[0, 3, 0], ["1/2", 3, "b"], [2, 3, 0]]}, "d1": {"bezier": [[0, 0, 0], [0, 1, "c"], [0, 3, 0]]}, "d2": {"bezier": [[2, 0, 0], [2, 1, 2], [2, 3, 0]]}}),
        json!({"op": "revolution", "curve": {"bezier": [["a", 0, 0], ["a", 0, "b"], [0, 0, "b"]], "weights": [1, "sqrt2/2", 1]}, "arcs": 1}),
        json!({"op": "revolution", "curve": {"bezier": [["a", 0, "b"], ["c", 0, "h"]]}, "arcs": 4}),
        json!({"op": "circle", "radius": "h", "arcs": 4}),
        json!({"op": "insert_knot", "curve": {"bspline": [[0, 0], ["a", 2], [3, "b"], [4, "c"]], "degree": 2, "knots": [0, 0, 1, 2, 2]}, "knot": "1/2", "times": 1}),
        json!({"op": "approximate", "degree": [1, 1], "points": [[0, 0, "a"], [1, 0, "1/3"], [0, 1, "b"], [1, 1, "3/4"], ["1/2", "1/2", "c"]], "params": [[0, 0], [1, 0], [0, 1], [1, 1], ["1/2", "1/2"]]}),
        json!({"op": "graph", "f": "a*x*y + b*x + c", "degree": [1, 1]}),
        // never developable, whatever a is (its polynomial has the coefficients -4a and 4 - 4a)
        json!({"op": "developable", "surface": {"bezier": [[[0, -1, 1], [0, -2, 0]], [[0, 0, 1], [0, 0, 0]], [["a", 0, 1], [1, 0, -1]]]}}),
        json!({"op": "blossom", "curve": {"bezier": [[0, "a"], ["b", 2], [3, "c"]]}, "params": ["1/3", "1/2"]}),
        json!({"op": "boundary", "surface": {"bezier": [[[0, 0, "a"], [0, 1, 0]], [["b", 0, 0], [1, 1, "c"]]]}}),
        json!({"op": "isocurve", "surface": {"bezier": [[[0, 0, "a"], [0, 1, 0]], [["b", 0, 0], [1, 1, "c"]]]}, "u": "1/3"}),
        json!({"op": "reduce_degree", "curve": {"bezier": [[0, "a"], ["b", 2], [3, "c"], [4, 0]]}, "by": 1}),
        json!({"op": "reverse", "curve": {"bezier": [[0, "a"], ["b", 2], [3, "c"]]}}),
        json!({"op": "subdivide", "curve": {"bezier": [[0, "a"], ["b", 2], [3, "c"]]}, "t": "1/3"}),
        json!({"op": "extract", "curve": {"bspline": [[0, 0], ["a", 2], [3, "b"], [4, "c"]], "degree": 2, "knots": [0, 0, 1, 2, 2]}}),
        json!({"op": "evaluate", "triangle": {"triangle": [[[0, 0, "a"]], [["b", 0, 0], [0, "1/2", 0]], [[1, 0, 0], ["1/2", "1/2", "c"], [0, 1, 0]]]}, "params": [["1/2", "1/3"]]}),
        json!({"op": "gaussian_curvature", "surface": {"bezier": [[[0, 0, "a"], [0, 1, 0]], [["b", 0, 0], [1, 1, "c"]]]}}),
        json!({"op": "tangent_developable", "curve": {"bezier": [[0, 0, "a"], [1, "b", 0], [2, 0, "c"]]}}),
        json!({"op": "interpolate", "basis": "bezier", "u": [0, "1/2", 1], "v": [0, 1], "points": [[[0, 0, "a"], [1, 0, 1]], [[0, 1, "b"], [1, 1, 2]], [[0, 2, 0], [1, 2, "c"]]]}),
    ]
}

const LETTERS: [&str; 4] = ["a", "b", "c", "h"];

/// The problem with every letter of its number strings replaced by `(value)`.
fn put_in(problem: &Value, values: &[(&str, String)]) -> Value {
    match problem {
        Value::String(s) if s.chars().any(|c| LETTERS.iter().any(|l| l.starts_with(c))) => {
            let mut t = s.clone();
            for (name, v) in values {
                t = t.replace(name, &format!("({v})"));
            }
            Value::String(t)
        }
        Value::Array(xs) => Value::Array(xs.iter().map(|x| put_in(x, values)).collect()),
        Value::Object(m) => Value::Object(
            m.iter()
                .map(|(k, x)| {
                    let keep = k == "op" || k == "basis" || k == "end";
                    (k.clone(), if keep { x.clone() } else { put_in(x, values) })
                })
                .collect(),
        ),
        other => other.clone(),
    }
}

fn with_parameters(problem: &Value, values: Option<&[(&str, String)]>) -> Value {
    let mut p = problem.clone();
    p["parameters"] = json!(LETTERS);
    if let Some(values) = values {
        p["values"] = Value::Object(
            values
                .iter()
                .map(|(k, v)| (k.to_string(), json!(v)))
                .collect(),
        );
    }
    p
}

#[test]
fn every_operation_answers_in_letters() {
    for problem in problems() {
        let answer =
            solve(&with_parameters(&problem, None)).unwrap_or_else(|e| panic!("{problem}: {e}"));
        let text = answer.to_json(false).to_string();
        assert!(
            LETTERS.iter().any(|l| text.contains(l)),
            "{problem}: the answer has no letter: {text}"
        );
    }
}

fn rational() -> impl Strategy<Value = String> {
    (-9i64..10, 1i64..6).prop_map(|(p, q)| format!("{p}/{q}"))
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 6, ..ProptestConfig::default() })]

    /// Substituting values into the answer in letters equals the answer of the problem with
    /// the values put in, for every operation above.
    #[test]
    fn specializing_the_answer_equals_solving_with_the_values(
        a in rational(), b in rational(), c in rational(), h in (1i64..9, 1i64..4).prop_map(|(p, q)| format!("{p}/{q}"))
    ) {
        let values = [("a", a), ("b", b), ("c", c), ("h", h)];
        let mut compared = 0;
        for problem in problems() {
            let numeric = solve(&put_in(&problem, &values));
            let special = solve(&with_parameters(&problem, Some(&values)));
            match (numeric, special) {
                (Ok(n), Ok(s)) => {
                    let result = |a: &cagd_problem::Answer| {
                        let mut r = a.to_json(false)["result"].clone();
                        if let Some(m) = r.as_object_mut() {
                            m.remove("remarks");
                            // the Gaussian curvature's verdicts (developable, where G vanishes)
                            // hold in letters for general values; its numerator is compared
                            if problem["op"] == "gaussian_curvature" {
                                for k in ["developable", "sign", "zero", "sign_change", "zeros"] {
                                    m.remove(k);
                                }
                            }
                        }
                        r
                    };
                    prop_assert_eq!(result(&n), result(&s), "{}", problem);
                    compared += 1;
                }
                // a value can make the problem degenerate (an interpolation matrix singular, a
                // denominator zero): then the numeric problem is refused too
                (Err(_), _) => {}
                (Ok(_), Err(e)) => prop_assert!(false, "{}: specialized answer refused: {}", problem, e),
            }
        }
        // the degenerate values are rare: nearly every operation is compared
        prop_assert!(compared + 3 >= problems().len(), "only {} of {} compared", compared, problems().len());
    }
}

#[test]
fn a_sign_that_is_needed_is_refused_with_the_expression() {
    let e = solve(&json!({"op": "restrict", "curve": {"bezier": [[0], [1], [2]]}, "t": ["a", "b"], "parameters": ["a", "b"]}))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("needs a < b: the sign of b - a is not known"),
        "{e}"
    );
    let e = solve(&json!({"op": "evaluate", "curve": {"bspline": [[0], [1], [2], [3]], "degree": 2, "knots": [0, "a", 1, 1, 1]}, "params": ["1/2"], "parameters": ["a"]}))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("the knots must not decrease: the sign of a"),
        "{e}"
    );
    // with values the same problems are answered (solved at the values, a sign known there)
    assert!(solve(&json!({"op": "restrict", "curve": {"bezier": [[0], [1], [2]]}, "t": ["a", "b"], "parameters": ["a", "b"], "values": {"a": 0, "b": 1}})).is_ok());
}

#[test]
fn an_undeclared_letter_is_named_and_a_typo_caught() {
    let e = solve(&json!({"op": "circle", "radius": "2 r", "parameters": ["R"]}))
        .unwrap_err()
        .to_string();
    assert!(e.contains("'r', which is not a declared parameter"), "{e}");
    let e = solve(&json!({"op": "circle", "radius": "R"}))
        .unwrap_err()
        .to_string();
    assert!(e.contains("declare letters in \"parameters\""), "{e}");
    let e = solve(&json!({"op": "circle", "radius": "R", "parameters": ["R"], "values": {"S": 1}}))
        .unwrap_err()
        .to_string();
    assert!(e.contains("\"S\" is not a declared parameter"), "{e}");
}
