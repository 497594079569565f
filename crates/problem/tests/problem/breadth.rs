//! Issue 16, first half: triangular patches, blossoms, subdivision, Bézier extraction, knot
//! removal, reversal, degree reduction, iso-parametric and boundary curves through `solve`,
//! and the bugs met on the way, each against an independent derivation.

use cagd_problem::solve;
use serde_json::{json, Value};

/// The JSON of result `name` of the problem `p`.
fn result(p: &Value, name: &str) -> Value {
    let a = solve(p).unwrap_or_else(|e| panic!("{p}: {e}"));
    a.get(name)
        .unwrap_or_else(|| panic!("no {name} in the answer of {p}"))
        .to_json()
}

/// Regression (issue 16): two Bézier patches of different degrees along their common border
/// were refused with "the patches do not share a border"; the lower one is now elevated first.
#[test]
fn continuity_of_patches_of_different_degrees_along_the_border() {
    // first: (2u, 2v, 0) as a (2, 1) patch; second: (2 + 2u, 2v, u^2) as a (2, 2) patch
    let first = json!({"bezier": [[[0, 0, 0], [0, 2, 0]], [[1, 0, 0], [1, 2, 0]], [[2, 0, 0], [2, 2, 0]]]});
    let second = json!({"bezier": [
        [[2, 0, 0], [2, 1, 0], [2, 2, 0]],
        [[3, 0, 0], [3, 1, 0], [3, 2, 0]],
        [[4, 0, 0], [4, 1, 0], [4, 2, 1]]]});
    let p = json!({"op": "continuity", "first": first, "second": second, "border": "u"});
    let a = solve(&p).unwrap();
    assert_eq!(a.get("order").unwrap().to_json(), json!(1));
    assert_eq!(
        a.remarks,
        ["the first patch has degree 1 along the border (v) and the second 2: the first was elevated to degree 2 in v before comparing (the border u = 1 is the same curve)"]
    );
    // the other way round, across v
    let t = |m: &Value| -> Value {
        let rows = m["bezier"].as_array().unwrap();
        let cols = rows[0].as_array().unwrap().len();
        let out: Vec<Value> = (0..cols)
            .map(|j| Value::Array(rows.iter().map(|r| r[j].clone()).collect()))
            .collect();
        json!({"bezier": out})
    };
    let q = json!({"op": "continuity", "first": t(&second), "second": t(&first), "border": "v"});
    assert_eq!(result(&q, "order"), json!(-1));
    let q = json!({"op": "continuity", "first": t(&first), "second": t(&second), "border": "v"});
    assert_eq!(result(&q, "order"), json!(1));
}
