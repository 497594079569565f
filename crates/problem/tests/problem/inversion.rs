//! Point inversion through `solve` (`invert_point`): the parameters t of the domain with
//! c(t) = P, exact, for every kind of curve; a point off the curve; roots in Q(√d); a refusal
//! where the parameter is no number of the field; and the property that inverting c(t0) finds
//! t0, and every parameter found gives P exactly.

use cagd_problem::solve;
use proptest::prelude::*;
use serde_json::{json, Value};

/// The parameters found for `point` on `curve`.
fn params(curve: &Value, point: Value) -> Vec<String> {
    let p = json!({"op": "invert_point", "curve": curve, "point": point});
    let a = solve(&p).unwrap_or_else(|e| panic!("{p}: {e}"));
    let on = a.get("on_curve").unwrap().to_json();
    let ts: Vec<String> = a
        .get("params")
        .unwrap()
        .to_json()
        .as_array()
        .unwrap()
        .iter()
        .map(|t| t.as_str().unwrap().to_string())
        .collect();
    assert_eq!(on, json!(!ts.is_empty()), "{p}");
    ts
}

#[test]
fn parameters_of_points_of_each_kind_of_curve() {
    // the cubic (0,0), (1,3), (3,3), (4,0): c(1/3) = (34/27, 2); y = 2 also at t = 2/3,
    // where x differs
    let cubic = json!({"bezier": [[0, 0], [1, 3], [3, 3], [4, 0]]});
    assert_eq!(params(&cubic, json!(["34/27", 2])), ["1/3"]);
    assert_eq!(params(&cubic, json!([0, 0])), ["0"]);
    // a point off the curve: no parameter, said in a remark
    let p = json!({"op": "invert_point", "curve": cubic, "point": [1, 1]});
    let a = solve(&p).unwrap();
    assert_eq!(a.get("params").unwrap().to_json(), json!([]));
    assert_eq!(a.get("on_curve").unwrap().to_json(), json!(false));
    assert!(a.remarks[0]
        .to_string()
        .contains("not a point of the curve"));
    // the quarter circle (1,0), (1,1), (0,1) with weights 1, 1, 2: (3/5, 4/5) at t = 1/2
    let arc = json!({"bezier": [[1, 0], [1, 1], [0, 1]], "weights": [1, 1, 2]});
    assert_eq!(params(&arc, json!(["3/5", "4/5"])), ["1/2"]);
    // the semicircle with a control vector: (0, 1) at t = 1/2
    let semi = json!({"bezier": [[1, 0], [0, 1], [-1, 0]], "weights": [1, 0, 1]});
    assert_eq!(params(&semi, json!([0, 1])), ["1/2"]);
    // a B-spline curve, piece by piece: a knot shared by two pieces counts once
    let spline =
        json!({"bspline": [[0, 0], [1, 2], [3, 2], [4, 0]], "degree": 2, "knots": [0, 0, 1, 2, 2]});
    assert_eq!(params(&spline, json!([2, 2])), ["1"]);
    // an expression: the parabola (t, t²) meets (1/2, 1/4) at t = 1/2 only
    let parabola = json!({"expr": "(t, t^2)"});
    assert_eq!(params(&parabola, json!(["1/2", "1/4"])), ["1/2"]);
    // a double point: the loop (t² - 1, t³ - t) passes the origin at t = -1 and 1; on the
    // domain [0, 1] of an expression only t = 1 is kept
    let node = json!({"expr": "(t^2 - 1, t^3 - t)"});
    assert_eq!(params(&node, json!([0, 0])), ["1"]);
}

#[test]
fn roots_in_a_quadratic_field_and_refusals() {
    // the line (2t, 0) squared: (4 t², 0) = (2, 0) at t = √2/2
    let c = json!({"bezier": [[0, 0], [0, 0], [4, 0]]});
    assert_eq!(params(&c, json!([2, 0])), ["sqrt2/2"]);
    // (t³, 0) = (1/2, 0): t is the cube root of 1/2, no number of the field: refused
    let cube = json!({"expr": "(t^3, 0)"});
    let e = solve(&json!({"op": "invert_point", "curve": cube, "point": ["1/2", 0]})).unwrap_err();
    assert!(e.to_string().contains("no rational root"), "{e}");
    // the point's dimension must be the curve's
    let e = solve(
        &json!({"op": "invert_point", "curve": {"bezier": [[0, 0], [1, 1]]}, "point": [0, 0, 0]}),
    )
    .unwrap_err();
    assert!(
        e.to_string()
            .starts_with("field `point`: the point has dimension 3"),
        "{e}"
    );
    // a curve that is the point itself: every parameter
    let e = solve(
        &json!({"op": "invert_point", "curve": {"bezier": [[1, 1], [1, 1]]}, "point": [1, 1]}),
    )
    .unwrap_err();
    assert!(e.to_string().contains("every parameter"), "{e}");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// A random cubic and a random rational t0 of [0, 1]: inverting c(t0) finds t0, and every
    /// parameter found evaluates to the point exactly.
    #[test]
    fn inverting_a_point_of_the_curve_finds_its_parameter(
        cs in proptest::collection::vec(-9i64..=9, 8),
        num in 0i64..=12,
        den in 1i64..=12,
    ) {
        prop_assume!(num <= den);
        let pts: Vec<Value> = cs.chunks(2).map(|p| json!([p[0], p[1]])).collect();
        let curve = json!({"bezier": pts});
        let t0 = format!("{num}/{den}");
        let point = solve(&json!({"op": "evaluate", "curve": curve, "params": [t0]}))
            .unwrap()
            .get("points")
            .unwrap()
            .to_json()[0]
            .clone();
        let p = json!({"op": "invert_point", "curve": curve, "point": point});
        match solve(&p) {
            Ok(a) => {
                let ts = a.get("params").unwrap().to_json();
                let ts = ts.as_array().unwrap();
                let t0 = solve(&json!({"op": "evaluate", "curve": {"expr": "(t, 0)"}, "params": [t0]}))
                    .unwrap().get("points").unwrap().to_json()[0][0].clone();
                prop_assert!(ts.contains(&t0), "{p}: {ts:?} lacks {t0}");
                for t in ts {
                    let back = solve(&json!({"op": "evaluate", "curve": curve, "params": [t]}))
                        .unwrap().get("points").unwrap().to_json()[0].clone();
                    prop_assert_eq!(&back, &point);
                }
            }
            // a constant curve (every control point equal) is every parameter
            Err(e) => prop_assert!(e.to_string().contains("every parameter"), "{p}: {e}"),
        }
    }
}
