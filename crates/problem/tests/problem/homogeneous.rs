//! Control points given homogeneous (`"homogeneous": true`, geomdl's `ctrlptsw`) and zero
//! weights (the control vector) through `solve`: read, solved, and written back in the form
//! the problem used.

use cagd_problem::solve;
use serde_json::{json, Value};

/// The JSON answer of `p`.
fn answer(p: &Value) -> Value {
    solve(p)
        .unwrap_or_else(|e| panic!("{p}: {e}"))
        .to_json(false)
}

#[test]
fn homogeneous_points_read_as_points_and_weights() {
    let by_weights = json!({"bezier": [[1, 0], [0, 1], [-1, 0]], "weights": [1, 0, 1]});
    let by_homogeneous = json!({"bezier": [[1, 0, 1], [0, 1, 0], [-1, 0, 1]], "homogeneous": true});
    for op in [
        json!({"op": "closed_form"}),
        json!({"op": "evaluate", "params": ["1/3", "1/2"]}),
    ] {
        let with = |c: &Value| {
            let mut p = op.clone();
            p["curve"] = c.clone();
            answer(&p)["result"].clone()
        };
        assert_eq!(with(&by_weights), with(&by_homogeneous), "{op}");
    }
    // a NURBS curve: (2, 0, 2) is the point (1, 0) of weight 2
    let nurbs = json!({"op": "evaluate", "curve": {"bspline": [[2, 0, 2], [1, 1, 1], [0, 2, 2]], "degree": 2, "knots": [0, 0, 1, 1], "homogeneous": true}, "params": ["1/2"]});
    assert_eq!(answer(&nurbs)["result"]["points"], json!([["2/3", "2/3"]]));
    // a surface's mesh
    let patch = json!({"op": "evaluate", "surface": {"bezier": [[[0, 0, 0, 1], [0, 2, 0, 2]], [[1, 0, 0, 1], [2, 2, 2, 2]]], "homogeneous": true}, "params": [["1/2", "1/2"]]});
    assert_eq!(
        answer(&patch)["result"]["points"],
        json!([["1/2", "2/3", "1/3"]])
    );
}

#[test]
fn answers_in_the_form_the_problem_used() {
    // the semicircle elevated: weights 1, 1/3, 1/3, 1 on (1, 0), (1, 2), (-1, 2), (-1, 0)
    let up = |c: Value| {
        answer(&json!({"op": "elevate", "curve": c, "by": 1}))["result"]["curve"].clone()
    };
    assert_eq!(
        up(json!({"bezier": [[1, 0], [0, 1], [-1, 0]], "weights": [1, 0, 1]})),
        json!({"bezier": [["1", "0"], ["1", "2"], ["-1", "2"], ["-1", "0"]], "weights": ["1", "1/3", "1/3", "1"]})
    );
    assert_eq!(
        up(json!({"bezier": [[1, 0, 1], [0, 1, 0], [-1, 0, 1]], "homogeneous": true})),
        json!({"bezier": [["1", "0", "1"], ["1/3", "2/3", "1/3"], ["-1/3", "2/3", "1/3"], ["-1", "0", "1"]], "homogeneous": true})
    );
    // a zero weight written back homogeneous is the control vector, last coordinate 0
    let rev = answer(
        &json!({"op": "reverse", "curve": {"bezier": [[1, 0, 1], [0, 1, 0], [-1, 0, 1]], "homogeneous": true}}),
    );
    assert_eq!(
        rev["result"]["curve"],
        json!({"bezier": [["-1", "0", "1"], ["0", "1", "0"], ["1", "0", "1"]], "homogeneous": true})
    );
    // the answer feeds back as a problem
    let again =
        answer(&json!({"op": "evaluate", "curve": rev["result"]["curve"], "params": ["1/2"]}));
    assert_eq!(again["result"]["points"], json!([["0", "1"]]));
}

#[test]
fn homogeneous_refusals() {
    let err = |p: Value| solve(&p).unwrap_err().to_string();
    assert_eq!(
        err(json!({"op": "evaluate", "curve": {"bezier": [[1, 0, 1], [0, 1, 1]], "homogeneous": true, "weights": [1, 1]}, "params": [0]})),
        "field `curve.weights`: with \"homogeneous\": true the weights are the last coordinates of the points: give them there or in \"weights\", not both"
    );
    assert_eq!(
        err(json!({"op": "evaluate", "curve": {"bezier": [[1], [2]], "homogeneous": true}, "params": [0]})),
        "field `curve.bezier[0]`: a homogeneous point (w x, ..., w) needs at least two coordinates, the weight last; found 1"
    );
    assert_eq!(
        err(json!({"op": "evaluate", "curve": {"expr": "(t, t)", "homogeneous": true}, "params": [0]})),
        "field `curve.homogeneous`: \"homogeneous\" is for control points written in \"bezier\" or \"bspline\""
    );
}
