//! Knot vectors as objects through `solve`: the span of a parameter and the multiplicity of
//! each knot (The NURBS Book, Ex. 2.3 and A2.1), indexed in the vector as written; uniform and
//! open uniform vectors built; a curve and a vector normalized onto [0, 1].

use cagd_problem::solve;
use serde_json::{json, Value};

fn result(p: &Value, name: &str) -> Value {
    let a = solve(p).unwrap_or_else(|e| panic!("{p}: {e}"));
    a.get(name)
        .unwrap_or_else(|| panic!("no {name} in the answer of {p}"))
        .to_json()
}

fn spans(p: &Value) -> Vec<i64> {
    result(p, "spans")
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["span"].as_i64().unwrap())
        .collect()
}

#[test]
fn the_nurbs_book_spans_and_multiplicities() {
    // U = {0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5}, p = 2: u = 5/2 in span 4; u = 5 in the last, 7
    let full = json!({"op": "knot_vector", "knots": [0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5], "degree": 2,
                      "convention": "nurbs_book", "params": ["5/2", 0, 4, 5]});
    assert_eq!(spans(&full), vec![4, 2, 7, 7]);
    assert_eq!(
        result(&full, "multiplicities"),
        json!([{"knot": "0", "multiplicity": 3}, {"knot": "1", "multiplicity": 1},
               {"knot": "2", "multiplicity": 1}, {"knot": "3", "multiplicity": 1},
               {"knot": "4", "multiplicity": 2}, {"knot": "5", "multiplicity": 3}])
    );
    assert_eq!(result(&full, "domain"), json!(["0", "5"]));
    // the same vector in the notes' convention: one index less, ends p times
    let notes = json!({"op": "knot_vector", "knots": [0, 0, 1, 2, 3, 4, 4, 5, 5], "degree": 2,
                       "params": ["5/2", 0, 4, 5]});
    assert_eq!(spans(&notes), vec![3, 1, 6, 6]);
    assert_eq!(
        result(&notes, "multiplicities")[0],
        json!({"knot": "0", "multiplicity": 2})
    );
    // a curve's knots tell their convention by their length
    let pts: Vec<Value> = (0..8).map(|k| json!([k, k * k])).collect();
    let curve = json!({"bspline": pts, "degree": 2, "knots": [0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5]});
    let p = json!({"op": "knot_vector", "curve": curve, "params": ["5/2"]});
    assert_eq!(spans(&p), vec![4]);
    let e =
        solve(&json!({"op": "knot_vector", "curve": curve, "convention": "notes"})).unwrap_err();
    assert_eq!(e.field, "convention");
    // outside the domain: the parameter named
    let e = solve(&json!({"op": "knot_vector", "knots": [0, 0, 1, 1], "degree": 2, "params": [2]}))
        .unwrap_err();
    assert_eq!(e.field, "params[0]");
    let e = solve(&json!({"op": "knot_vector", "degree": 2})).unwrap_err();
    assert!(e.to_string().contains("`knot_vector` needs"), "{e}");
}

#[test]
fn uniform_and_open_uniform_vectors() {
    let p = json!({"op": "knot_vector", "spacing": "open_uniform", "degree": 2, "control_points": 5,
                   "convention": "nurbs_book"});
    assert_eq!(
        result(&p, "knots"),
        json!(["0", "0", "0", "1/3", "2/3", "1", "1", "1"])
    );
    let p = json!({"op": "knot_vector", "spacing": "open_uniform", "degree": 2, "control_points": 5,
                   "interval": [1, 4]});
    assert_eq!(result(&p, "knots"), json!(["1", "1", "2", "3", "4", "4"]));
    let p = json!({"op": "knot_vector", "spacing": "uniform", "degree": 2, "control_points": 4,
                   "convention": "nurbs_book", "params": ["5/2"]});
    assert_eq!(
        result(&p, "knots"),
        json!(["0", "1", "2", "3", "4", "5", "6"])
    );
    assert_eq!(result(&p, "domain"), json!(["2", "4"]));
    assert_eq!(spans(&p), vec![2]);
    let p = json!({"op": "knot_vector", "spacing": "uniform", "degree": 2, "control_points": 4});
    assert_eq!(result(&p, "knots"), json!(["1", "2", "3", "4", "5"]));
    let e = solve(
        &json!({"op": "knot_vector", "spacing": "uniform", "degree": 3, "control_points": 3}),
    )
    .unwrap_err();
    assert!(e.to_string().contains("at least 4 control points"), "{e}");
}

#[test]
fn normalized_curves_and_vectors() {
    // on [2, 6]: the knots (u - 2)/4, the same control points and weights
    let c = json!({"bspline": [[0, 0], [1, 2], [3, 2], [4, 0]], "degree": 2, "knots": [2, 2, 3, 6, 6],
                   "weights": [1, 2, 1, 1]});
    let n = result(&json!({"op": "normalize", "curve": c}), "curve");
    assert_eq!(n["knots"], json!(["0", "0", "1/4", "1", "1"]));
    assert_eq!(
        n["bspline"],
        json!([["0", "0"], ["1", "2"], ["3", "2"], ["4", "0"]])
    );
    assert_eq!(n["weights"], json!(["1", "2", "1", "1"]));
    // the same point set: c̃(s) = c(2 + 4 s)
    for (s, t) in [("0", "2"), ("1/8", "5/2"), ("3/8", "7/2"), ("1", "6")] {
        let old = result(
            &json!({"op": "evaluate", "curve": c, "params": [t]}),
            "points",
        );
        let new = result(
            &json!({"op": "evaluate", "curve": n, "params": [s]}),
            "points",
        );
        assert_eq!(old, new, "s = {s}");
    }
    // a NURBS surface on [2, 6] x [-1, 1]: both directions onto [0, 1]
    let sf = json!({"bspline": [[[0, 0, 0], [0, 1, 1]], [[1, 0, 2], [1, 1, 0]], [[3, 0, 1], [3, 1, 1]], [[4, 0, 0], [4, 1, 2]]],
                    "degree": [2, 1], "knots": [[2, 2, 3, 6, 6], [-1, 1]], "weights": [[1, 2], [1, 1], [3, 1], [1, 1]]});
    let m = result(&json!({"op": "normalize", "surface": sf}), "surface");
    assert_eq!(m["knots"], json!([["0", "0", "1/4", "1", "1"], ["0", "1"]]));
    for ((u, v), (s, r)) in [
        (("5/2", "0"), ("1/8", "1/2")),
        (("5", "1/2"), ("3/4", "3/4")),
    ] {
        let old = result(
            &json!({"op": "evaluate", "surface": sf, "params": [[u, v]]}),
            "points",
        );
        let new = result(
            &json!({"op": "evaluate", "surface": m, "params": [[s, r]]}),
            "points",
        );
        assert_eq!(old, new, "(s, r) = ({s}, {r})");
    }
    // a vector alone, in its convention
    let k = json!({"op": "normalize", "knots": [-1, 1, 1, 3, 5, 7, 9], "degree": 2,
                   "convention": "nurbs_book"});
    // domain [u_2, u_4] = [1, 5]: (u - 1)/4, the knots outside the domain mapped too
    assert_eq!(
        result(&k, "knots"),
        json!(["-1/2", "0", "0", "1/2", "1", "3/2", "2"])
    );
    let e = solve(&json!({"op": "normalize", "curve": {"bezier": [[0, 0], [1, 1]]}})).unwrap_err();
    assert_eq!(e.field, "curve");
}

/// The point of `curve` at `t`, as JSON.
fn points(curve: &Value, t: &str) -> Value {
    result(
        &json!({"op": "evaluate", "curve": curve, "params": [t]}),
        "points",
    )
}

#[test]
fn insertion_up_to_p_plus_one_splits_the_curve() {
    // the quadratic on {0, 0, 1, 2, 2}: 1 inserted twice more (multiplicity 3 = p + 1) splits it
    let c =
        json!({"bspline": [[0, 0], [1, 2], [3, 2], [4, 0]], "degree": 2, "knots": [0, 0, 1, 2, 2]});
    let a = solve(&json!({"op": "insert_knot", "curve": c, "knot": 1, "times": 2})).unwrap();
    let curves = a.get("curves").unwrap().to_json();
    assert_eq!(
        curves,
        json!([{"bspline": [["0", "0"], ["1", "2"], ["2", "2"]], "degree": 2, "knots": ["0", "0", "1", "1"]},
               {"bspline": [["2", "2"], ["3", "2"], ["4", "0"]], "degree": 2, "knots": ["1", "1", "2", "2"]}])
    );
    assert!(
        a.remarks[0].to_string().contains("splits the curve in two"),
        "{:?}",
        a.remarks
    );
    // past p + 1: refused with the reason
    let e = solve(&json!({"op": "insert_knot", "curve": c, "knot": 1, "times": 3})).unwrap_err();
    assert_eq!(e.field, "times");
    assert!(
        e.to_string().contains("splits in two at multiplicity 3"),
        "{e}"
    );
    // at p only: one curve, as before
    let a = solve(&json!({"op": "insert_knot", "curve": c, "knot": 1, "times": 1})).unwrap();
    assert!(a.get("curve").is_some());
    // a NURBS curve, through its homogeneous points
    let w = json!({"bspline": [[0, 0], [1, 2], [3, 2], [4, 0]], "degree": 2, "knots": [0, 0, 1, 2, 2],
                   "weights": [1, 2, 1, 1]});
    let a = solve(&json!({"op": "insert_knot", "curve": w, "knot": "1/2", "times": 3})).unwrap();
    let halves = a.get("curves").unwrap().to_json();
    assert_eq!(points(&halves[0], "1/4"), points(&w, "1/4"));
    assert_eq!(points(&halves[1], "3/2"), points(&w, "3/2"));
}

proptest::proptest! {
    #![proptest_config(proptest::test_runner::Config { cases: 12, ..Default::default() })]

    /// Splitting by insertion up to p + 1 gives two curves that meet at the knot and equal the
    /// curve piece by piece.
    #[test]
    fn split_by_insertion_is_the_curve_piece_by_piece(
        p in 1usize..=3, gaps in proptest::collection::vec(1i64..4, 1..4),
        ys in proptest::collection::vec(-5i64..6, 8), at in 1i64..8, lambdas in proptest::collection::vec(0i64..=6, 2),
    ) {
        // clamped knots in the notes' convention: 0 p times, the breakpoints, the end p times
        let mut breaks = vec![0i64];
        for g in &gaps {
            breaks.push(breaks.last().unwrap() + g);
        }
        let end = *breaks.last().unwrap();
        let mut knots: Vec<i64> = vec![0; p];
        knots.extend(&breaks[1..breaks.len() - 1]);
        knots.extend(std::iter::repeat_n(end, p));
        let n = knots.len() + 1 - p;
        let pts: Vec<Value> = (0..n).map(|i| json!([i, ys[i % ys.len()]])).collect();
        let c = json!({"bspline": pts, "degree": p, "knots": knots});
        // an interior parameter: t = end at/8
        let t = format!("{}/8", end * at);
        let mult = knots.iter().filter(|k| 8 * **k == end * at).count();
        let times = p + 1 - mult;
        let a = solve(&json!({"op": "insert_knot", "curve": c, "knot": t, "times": times})).unwrap();
        let halves = a.get("curves").unwrap().to_json();
        // they meet at t
        proptest::prop_assert_eq!(points(&halves[0], &t), points(&halves[1], &t));
        proptest::prop_assert_eq!(points(&halves[0], &t), points(&c, &t));
        // and each is the curve on its side
        for l in &lambdas {
            // t l/6 and t + (end - t) l/6
            let left = format!("{}/48", end * at * l);
            let right = format!("{}/288", 36 * end * at + (48 * end - 6 * end * at) * l);
            proptest::prop_assert_eq!(points(&halves[0], &left), points(&c, &left));
            proptest::prop_assert_eq!(points(&halves[1], &right), points(&c, &right));
        }
    }
}
