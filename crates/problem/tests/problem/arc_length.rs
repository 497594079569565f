//! Arc lengths through `solve`: exact where the speed has a rational antiderivative (a line, a
//! Pythagorean-hodograph cubic, a rational parametrization of a segment, a B-spline piece by
//! piece, a length in Q(√2)), and otherwise said why (a circle arc, a parabola, a speed that
//! changes sign).

use cagd_problem::solve;
use serde_json::{json, Value};

proptest::proptest! {
    #![proptest_config(proptest::test_runner::Config { cases: 16, ..Default::default() })]

    /// A rational curve whose control points run forwards along the line of direction
    /// (3, 4) is a monotone parametrization of the segment, whatever its positive weights:
    /// its length is 5 (s_n - s_0) exactly, found through the rational antiderivative; as a
    /// NURBS curve of two pieces too.
    #[test]
    fn the_length_of_a_rational_segment_is_the_distance(
        steps in proptest::collection::vec(1i64..4, 3), ws in proptest::collection::vec(1i64..5, 4),
    ) {
        let mut s = vec![0i64];
        for d in &steps {
            s.push(s.last().unwrap() + d);
        }
        let pts: Vec<Value> = s.iter().map(|k| json!([3 * k, 4 * k])).collect();
        let c = json!({"bezier": pts, "weights": ws});
        let a = solve(&json!({"op": "arc_length", "curve": c})).unwrap();
        proptest::prop_assert_eq!(a.get("exact").unwrap().to_json(), json!(true));
        proptest::prop_assert_eq!(a.get("length").unwrap().to_json(), json!((5 * s[3]).to_string()));
        let n = json!({"bspline": pts, "weights": ws, "degree": 2, "knots": [0, 0, 1, 2, 2]});
        let a = solve(&json!({"op": "arc_length", "curve": n})).unwrap();
        proptest::prop_assert_eq!(a.get("length").unwrap().to_json(), json!((5 * s[3]).to_string()));
    }
}

/// σ = 1320 t³ - 2220 t² + 1200 t - 360 < 0 on [0, 1], but its Bernstein coefficients there
/// (-360, 40, -300, -60) have both signs: the halvings decide it (a proptest found this case).
#[test]
fn a_sign_the_bernstein_coefficients_leave_open_is_decided_by_halving() {
    let c = json!({"bezier": [[0, 0], [9, 12], [12, 16], [15, 20]], "weights": [2, 4, 1, 4]});
    let a = solve(&json!({"op": "arc_length", "curve": c})).unwrap();
    assert_eq!(a.get("exact").unwrap().to_json(), json!(true));
    assert_eq!(a.get("length").unwrap().to_json(), json!("25"));
    // a speed σ = 2t - 1 that changes sign is still refused, with its reason
    let p = json!({"bezier": [[0, 0], [1, 0], [0, 0]]});
    let a = solve(&json!({"op": "arc_length", "curve": p})).unwrap();
    let Some(cagd_problem::Exact::Sentence(t)) = a.get("length") else {
        panic!("no words")
    };
    let t = t.to_string();
    assert!(t.contains("changing sign"), "{t}");
}

#[test]
fn a_circle_arc_has_no_rational_length_and_says_why() {
    let c = json!({"bezier": [[1, 0], [1, 1], [0, 1]], "weights": [1, "sqrt2/2", 1]});
    let a = solve(&json!({"op": "arc_length", "curve": c})).unwrap();
    assert_eq!(a.get("exact").unwrap().to_json(), json!(false));
    let Some(cagd_problem::Exact::Sentence(t)) = a.get("length") else {
        panic!("no words")
    };
    let t = t.to_string();
    assert!(t.contains("has no rational antiderivative"), "{t}");
    assert!(t.contains("a circle arc's length R θ"), "{t}");
    // a parabola written as a rational curve with equal weights: N is not a square
    let p = json!({"bezier": [[0, 0], [1, 2], [2, 0]], "weights": [2, 2, 2]});
    let a = solve(&json!({"op": "arc_length", "curve": p})).unwrap();
    let Some(cagd_problem::Exact::Sentence(t)) = a.get("length") else {
        panic!("no words")
    };
    let t = t.to_string();
    assert!(t.contains("not the square of a polynomial"), "{t}");
}

#[test]
fn arc_lengths_where_exact_and_said_otherwise() {
    let length = |p: Value| {
        let a = solve(&p).unwrap();
        (
            a.get("exact").unwrap().to_json(),
            a.get("length").unwrap().to_json(),
        )
    };
    assert_eq!(
        length(json!({"op": "arc_length", "curve": {"bezier": [[0, 0], [3, 4]]}})),
        (json!(true), json!("5"))
    );
    // a Pythagorean-hodograph cubic: c' = (1 - t², 2t), |c'| = 1 + t², length 4/3 on [0, 1]
    assert_eq!(
        length(json!({"op": "arc_length", "curve": {"expr": "(t - 1/3 t^3, t^2)"}})),
        (json!(true), json!("4/3"))
    );
    // on [-1, 1] twice that, and a B-spline line piece by piece
    assert_eq!(
        length(json!({"op": "arc_length", "curve": {"expr": "(t - 1/3 t^3, t^2)"}, "t": [-1, 1]})),
        (json!(true), json!("8/3"))
    );
    assert_eq!(
        length(
            json!({"op": "arc_length", "curve": {"bspline": [[0, 0], [1, 0], [3, 0], [4, 0]], "degree": 2, "knots": [0, 0, 1, 2, 2]}})
        ),
        (json!(true), json!("4"))
    );
    // √2 in Q(√2); in Q it is said
    assert_eq!(
        length(json!({"op": "arc_length", "curve": {"bezier": [[0, 0], ["sqrt2", "sqrt2"]]}})),
        (json!(true), json!("2"))
    );
    let (exact, words) = length(json!({"op": "arc_length", "curve": {"bezier": [[0, 0], [1, 1]]}}));
    assert_eq!(exact, json!(false));
    assert!(words.as_str().unwrap().contains("√(2)"), "{words}");
    // a parabola: not given, said why
    let (exact, words) = length(json!({"op": "arc_length", "curve": {"expr": "(t, t^2)"}}));
    assert_eq!(exact, json!(false));
    assert!(
        words
            .as_str()
            .unwrap()
            .contains("4 t^2 + 1 is not the square"),
        "{words}"
    );
}
