//! Operations on curves through `solve`: the blossom, subdivision (of Bézier and B-spline
//! curves), Bézier extraction (of B-spline and NURBS curves and of B-spline surfaces), knot
//! removal, reversal and degree reduction (polynomial, rational, B-spline and NURBS), the sizes
//! they check against the limits and the operations in letters, each against an independent
//! derivation.

use cagd_problem::solve;
use proptest::prelude::*;
use serde_json::{json, Value};

/// The JSON of result `name` of the problem `p`.
fn result(p: &Value, name: &str) -> Value {
    let a = solve(p).unwrap_or_else(|e| panic!("{p}: {e}"));
    a.get(name)
        .unwrap_or_else(|| panic!("no {name} in the answer of {p}"))
        .to_json()
}

/// The points of `evaluate` on `shape` (`"curve"`, `"surface"` or `"triangle"`) at `params`.
fn eval(key: &str, shape: &Value, params: Value) -> Value {
    result(
        &json!({"op": "evaluate", key: shape, "params": params}),
        "points",
    )
}

/// A rational number as a string of the grammar.
fn q(n: i64, d: i64) -> String {
    format!("{n}/{d}")
}

/// A rational number of the tests (`"3/7"`, `"2"`).
fn rat(s: &str) -> cagd_scalar::BigRational {
    s.parse().unwrap()
}

#[test]
fn curve_operations_examples() {
    let c = json!({"bezier": [[0, 0], [1, 3], [3, 3], [4, 0]]});
    // blossom on the diagonal is the curve; c[0, 0, 1] = c_1
    let b = json!({"op": "blossom", "curve": c, "params": [0, 0, 1]});
    assert_eq!(result(&b, "point"), json!(["1", "3"]));
    let r = result(&json!({"op": "reverse", "curve": c}), "curve");
    assert_eq!(
        r,
        json!({"bezier": [["4", "0"], ["3", "3"], ["1", "3"], ["0", "0"]]})
    );
    // degree reduction: exact for an elevated quadratic, least squares otherwise
    let quad = json!({"bezier": [[0, 0], [1, 2], [3, 3]]});
    let up = result(&json!({"op": "elevate", "curve": quad, "by": 1}), "curve");
    let down = json!({"op": "reduce_degree", "curve": up});
    assert_eq!(
        result(&down, "curve"),
        json!({"bezier": [["0", "0"], ["1", "2"], ["3", "3"]]})
    );
    assert_eq!(result(&down, "exact"), json!(true));
    let ls = json!({"op": "reduce_degree", "curve": c});
    assert_eq!(result(&ls, "exact"), json!(false));
    let a = solve(&ls).unwrap();
    assert!(
        a.remarks[0].to_string().starts_with("not exact"),
        "{:?}",
        a.remarks
    );
}

/// A random Bézier polygon of 1 to 6 points in the plane, small integers.
fn polygon() -> impl proptest::strategy::Strategy<Value = Vec<(i64, i64)>> {
    proptest::collection::vec((-9i64..10, -9i64..10), 1..7)
}

fn points_json(ps: &[(i64, i64)]) -> Value {
    Value::Array(ps.iter().map(|(x, y)| json!([x, y])).collect())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// A subdivision reproduces the curve: left(s) = c(t s), right(s) = c(t + (1 - t) s).
    #[test]
    fn subdivided_curves_trace_the_curve(ps in polygon(), tn in 1i64..7, s in 0i64..5) {
        let t = q(tn, 7);
        let c = json!({"bezier": points_json(&ps)});
        let parts = result(&json!({"op": "subdivide", "curve": c, "t": t}), "curves");
        let (t, s) = (rat(&t), rat(&q(s, 4)));
        let one = cagd_scalar::BigRational::from_integer(1.into());
        let left = (&t * &s).to_string();
        let right = (&t + (&one - &t) * &s).to_string();
        prop_assert_eq!(eval("curve", &parts[0], json!([s.to_string()])), eval("curve", &c, json!([left])));
        prop_assert_eq!(eval("curve", &parts[1], json!([s.to_string()])), eval("curve", &c, json!([right])));
    }

    /// A reversed curve traces the same points backwards: c̃(t) = c(1 - t), for a Bézier curve,
    /// a rational one and a B-spline.
    #[test]
    fn reversed_curves_trace_the_same_points(ps in polygon(), tn in 0i64..9) {
        let t = rat(&q(tn, 8));
        let one = cagd_scalar::BigRational::from_integer(1.into());
        let back = (&one - &t).to_string();
        let c = json!({"bezier": points_json(&ps)});
        let r = result(&json!({"op": "reverse", "curve": c}), "curve");
        prop_assert_eq!(eval("curve", &r, json!([t.to_string()])), eval("curve", &c, json!([back.clone()])));
        let w: Vec<Value> = (0..ps.len()).map(|i| json!(i + 1)).collect();
        let cw = json!({"bezier": points_json(&ps), "weights": w});
        let rw = result(&json!({"op": "reverse", "curve": cw}), "curve");
        prop_assert_eq!(eval("curve", &rw, json!([t.to_string()])), eval("curve", &cw, json!([back.clone()])));
        if ps.len() >= 3 {
            // a quadratic B-spline with uneven knots (the notes' convention: n + p - 1 knots)
            let n = ps.len();
            let knots: Vec<Value> = (0..n + 1).map(|i| json!(q((i * i) as i64, (n * n) as i64))).collect();
            let b = json!({"bspline": points_json(&ps), "degree": 2, "knots": knots});
            let rb = result(&json!({"op": "reverse", "curve": b}), "curve");
            // the domain [u_1, u_{n-1}] (0-based, notes' convention) is kept
            let (a, e) = (rat(&q(1, (n * n) as i64)), rat(&q(((n - 1) * (n - 1)) as i64, (n * n) as i64)));
            let x = &a + (&e - &a) * &t;
            let y = (&a + &e - &x).to_string();
            prop_assert_eq!(eval("curve", &rb, json!([x.to_string()])), eval("curve", &b, json!([y])));
        }
    }

    /// Bézier extraction evaluates equal: piece k at s is the B-spline at a_k + (b_k - a_k) s.
    #[test]
    fn extracted_pieces_evaluate_equal(ps in proptest::collection::vec((-9i64..10, -9i64..10), 4..8), s in 0i64..4) {
        let n = ps.len();
        let knots: Vec<Value> = (0..n + 2).map(|i| json!(q((i * i) as i64, 4))).collect();
        let b = json!({"bspline": points_json(&ps), "degree": 3, "knots": knots});
        let p = json!({"op": "extract", "curve": b});
        let curves = result(&p, "curves");
        let intervals = result(&p, "intervals");
        let s = rat(&q(s, 3));
        for (c, iv) in curves.as_array().unwrap().iter().zip(intervals.as_array().unwrap()) {
            let (a, e) = (rat(iv[0].as_str().unwrap()), rat(iv[1].as_str().unwrap()));
            let x = (&a + (&e - &a) * &s).to_string();
            prop_assert_eq!(eval("curve", c, json!([s.to_string()])), eval("curve", &b, json!([x])));
        }
    }

    /// Degree reduction undoes an elevation exactly, and says so.
    #[test]
    fn reduction_undoes_elevation(ps in polygon(), r in 1u64..3) {
        let c = json!({"bezier": points_json(&ps)});
        let up = result(&json!({"op": "elevate", "curve": c, "by": r}), "curve");
        let down = json!({"op": "reduce_degree", "curve": up, "by": r});
        prop_assert_eq!(result(&down, "exact"), json!(true));
        prop_assert_eq!(
            eval("curve", &result(&down, "curve"), json!(["1/3"])),
            eval("curve", &c, json!(["1/3"]))
        );
    }

    /// Knot removal undoes an insertion.
    #[test]
    fn removal_undoes_insertion(ps in proptest::collection::vec((-9i64..10, -9i64..10), 3..7)) {
        let n = ps.len();
        let knots: Vec<Value> = (0..n + 1).map(|i| json!(i)).collect();
        let b = json!({"bspline": points_json(&ps), "degree": 2, "knots": knots});
        let ins = result(&json!({"op": "insert_knot", "curve": b, "knot": "3/2", "times": 2}), "curve");
        let back = result(&json!({"op": "remove_knot", "curve": ins, "knot": "3/2", "times": 2}), "curve");
        let expected: Vec<Value> = ps.iter().map(|(x, y)| json!([x.to_string(), y.to_string()])).collect();
        prop_assert_eq!(back, json!({"bspline": expected, "degree": 2, "knots": knots.iter().map(|k| k.to_string()).collect::<Vec<_>>()}));
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    /// The blossom is symmetric and gives the curve on the diagonal (polynomial and rational).
    #[test]
    fn blossoms_are_symmetric_and_diagonal(ps in proptest::collection::vec((-9i64..10, -9i64..10), 3..5), a in 0i64..5, b in 0i64..5, c in 0i64..5) {
        let n = ps.len() - 1;
        let w: Vec<Value> = (0..=n).map(|i| json!(i % 2 + 1)).collect();
        for c0 in [json!({"bezier": points_json(&ps)}), json!({"bezier": points_json(&ps), "weights": w})] {
            let args: Vec<String> = [a, b, c].iter().take(n).map(|x| q(*x, 4)).collect();
            let mut rev = args.clone();
            rev.reverse();
            let one = result(&json!({"op": "blossom", "curve": c0, "params": args}), "point");
            let two = result(&json!({"op": "blossom", "curve": c0, "params": rev}), "point");
            prop_assert_eq!(&one, &two);
            let t = q(a, 4);
            let diag = result(&json!({"op": "blossom", "curve": c0, "params": vec![t.clone(); n]}), "point");
            prop_assert_eq!(json!([diag]), eval("curve", &c0, json!([t])));
        }
    }

    /// Extraction of NURBS curves and of B-spline surfaces evaluates equal.
    #[test]
    fn extracted_nurbs_and_surfaces_evaluate_equal(zs in proptest::collection::vec(-9i64..10, 9), s in 0i64..4) {
        let ps: Vec<(i64, i64)> = zs.iter().enumerate().take(5).map(|(i, z)| (i as i64, *z)).collect();
        let w: Vec<Value> = (0..5).map(|i| json!(i % 3 + 1)).collect();
        let b = json!({"bspline": points_json(&ps), "degree": 2, "knots": [0, 0, 1, 3, 3, 4], "weights": w});
        let p = json!({"op": "extract", "curve": b});
        let (curves, intervals) = (result(&p, "curves"), result(&p, "intervals"));
        let s = rat(&q(s, 3));
        for (c, iv) in curves.as_array().unwrap().iter().zip(intervals.as_array().unwrap()) {
            let (a, e) = (rat(iv[0].as_str().unwrap()), rat(iv[1].as_str().unwrap()));
            let x = (&a + (&e - &a) * &s).to_string();
            prop_assert_eq!(eval("curve", c, json!([s.to_string()])), eval("curve", &b, json!([x])));
        }
        let rows: Vec<Value> = (0..3).map(|i| Value::Array((0..3).map(|j| json!([i, j, zs[i * 3 + j]])).collect())).collect();
        let sf = json!({"bspline": rows, "degree": [1, 1], "knots": [[0, 1, 3], [0, 2, 3]]});
        let p = json!({"op": "extract", "surface": sf});
        let grid = result(&p, "surfaces");
        let (us, vs) = (result(&p, "u_intervals"), result(&p, "v_intervals"));
        prop_assert_eq!(grid.as_array().unwrap().len(), 2);
        for (row, iu) in grid.as_array().unwrap().iter().zip(us.as_array().unwrap()) {
            for (patch, iv) in row.as_array().unwrap().iter().zip(vs.as_array().unwrap()) {
                let at = |iv: &Value| {
                    let (a, e) = (rat(iv[0].as_str().unwrap()), rat(iv[1].as_str().unwrap()));
                    (&a + (&e - &a) * &s).to_string()
                };
                prop_assert_eq!(
                    eval("surface", patch, json!([[s.to_string(), s.to_string()]])),
                    eval("surface", &sf, json!([[at(iu), at(iv)]]))
                );
            }
        }
    }
}

/// The new operations check the sizes they compute against the limits before the work, and
/// refuse what they cannot do with the reason.
#[test]
fn sizes_and_refusals() {
    // 300 points of degree 3: 297 spans of 4 points each, past 1000 points
    let pts: Vec<Value> = (0..300).map(|i| json!([i, i % 3])).collect();
    let knots: Vec<Value> = (0..302).map(|i| json!(i)).collect();
    let b = json!({"bspline": pts, "degree": 3, "knots": knots});
    let p = json!({"op": "extract", "curve": b});
    let e = solve(&p).unwrap_err();
    assert_eq!(
        e.to_string(),
        "field `curve`: the Bézier pieces would have 1188 control points, more than the limit of 1000"
    );
    assert_eq!(e.limit, Some(cagd_problem::Limit::Points));
    let err = |p: Value| solve(&p).unwrap_err().to_string();
    assert!(
        err(json!({"op": "blossom", "curve": b, "params": [1, 2, 3]}))
            .contains("`extract` its Bézier pieces first")
    );
    assert!(err(json!({"op": "subdivide", "curve": b, "t": 2})).contains("not strictly inside"));
    let quad = json!({"bezier": [[0, 0], [1, 2], [3, 3]], "weights": [1, 2, 1]});
    assert!(err(json!({"op": "reduce_degree", "curve": quad})).contains(
        "a least-squares reduction of the homogeneous points can make a weight zero or negative"
    ));
    let s = json!({"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]});
    assert!(err(json!({"op": "isocurve", "surface": s, "u": 0, "v": 0})).contains("not both"));
    assert!(err(json!({"op": "subdivide", "surface": s, "u": 1})).contains("strictly inside"));
    let t = json!({"triangle": [[[0]], [[1], [2]]]});
    assert!(err(json!({"op": "subdivide", "triangle": t, "t": "1/2"})).contains("give `u` and `v`"));
    assert!(
        err(json!({"op": "elevate", "triangle": t, "by": 50})).contains("above the limit of 50")
    );
    // a triangle of 52 rows: degree 51
    let rows: Vec<Value> = (0..52)
        .map(|m| Value::Array((0..=m).map(|_| json!([0])).collect()))
        .collect();
    assert!(
        err(json!({"op": "closed_form", "triangle": {"triangle": rows}}))
            .contains("degree 51, above the limit of 50")
    );
    // a barycentric point must sum to 1
    assert!(
        err(json!({"op": "evaluate", "triangle": t, "params": [[1, 1, 1]]})).contains("params[0]")
    );
}

/// The new operations run in letters: a triangle, a blossom, a reversal.
#[test]
fn new_operations_in_letters() {
    let t = json!({"triangle": [[[0, 0, 0]], [["a/2", 0, 0], [0, "1/2", 0]], [["a", 0, 0], ["a/2", "1/2", "h"], [0, 1, 0]]]});
    let p = json!({"op": "closed_form", "triangle": t, "parameters": ["a", "h"]});
    assert_eq!(result(&p, "closed_form"), json!("(a*u, v, 2*h*u*v)"));
    let b = json!({"op": "blossom", "curve": {"bezier": [[0, 0], ["a", "h"], [1, 0]]}, "params": [0, 1], "parameters": ["a", "h"]});
    assert_eq!(result(&b, "point"), json!(["a", "h"]));
    // a split at a letter is refused by the surface crate, which must order the interval
    let s = json!({"op": "subdivide", "surface": {"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]}, "u": "s", "parameters": ["s"]});
    assert!(solve(&s).unwrap_err().to_string().contains("degenerate"));
    let r = json!({"op": "reverse", "curve": {"bezier": [[0, 0], ["a", "h"]], "weights": [1, "h"]}, "parameters": ["a", "h"]});
    assert_eq!(
        result(&r, "curve"),
        json!({"bezier": [["a", "h"], ["0", "0"]], "weights": ["h", "1"]})
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// A B-spline (NURBS) curve split at t: the left piece is the curve on [a, t], the right on
    /// [t, b], evaluated at the same parameters (De Boor on each, against the curve's).
    #[test]
    fn split_bsplines_trace_the_curve(ps in proptest::collection::vec((-9i64..10, -9i64..10), 4..8), p in 1usize..4, tn in 1i64..12, xn in 0i64..5) {
        prop_assume!(ps.len() > p);
        let n = ps.len();
        // notes' convention: n + p - 1 knots, uneven, with a double knot
        let mut knots: Vec<i64> = (0..(n + p - 1) as i64).map(|i| i * i).collect();
        if knots.len() > 3 { knots[2] = knots[1]; }
        let w: Vec<Value> = (0..n).map(|i| json!(i % 2 + 1)).collect();
        for c in [
            json!({"bspline": points_json(&ps), "degree": p, "knots": knots}),
            json!({"bspline": points_json(&ps), "degree": p, "knots": knots, "weights": w}),
        ] {
            let (a, b) = (knots[p - 1], knots[n - 1]);
            let t = rat(&q(a * 12 + (b - a) * tn, 12));
            let parts = result(&json!({"op": "subdivide", "curve": c, "t": t.to_string()}), "curves");
            let s = rat(&q(xn, 4));
            let one = cagd_scalar::BigRational::from_integer(1.into());
            let (ra, rb) = (rat(&a.to_string()), rat(&b.to_string()));
            let left = (&ra + (&t - &ra) * &s).to_string();
            let right = (&t + (&rb - &t) * &s).to_string();
            let _ = &one;
            prop_assert_eq!(eval("curve", &parts[0], json!([left.clone()])), eval("curve", &c, json!([left])));
            prop_assert_eq!(eval("curve", &parts[1], json!([right.clone()])), eval("curve", &c, json!([right])));
        }
    }
}

// --- degree reduction of rational, B-spline and NURBS curves ---

proptest::proptest! {
    #![proptest_config(proptest::test_runner::Config { cases: 16, ..Default::default() })]

    /// Reducing an elevated rational curve gives back its points and weights; reducing an
    /// elevated B-spline or NURBS curve gives the same curve (at every parameter tried), of the
    /// degree it had, and elevating the reduction gives the elevated curve's points again.
    #[test]
    fn reduction_undoes_elevation_of_rational_and_spline_curves(
        ps in polygon(), ws in proptest::collection::vec(1i64..5, 8), r in 1u64..3, mults in proptest::collection::vec(1usize..=2, 0..=2), rational in proptest::bool::ANY,
    ) {
        let weights: Vec<Value> = ps.iter().zip(ws.iter().cycle()).map(|(_, w)| json!(w)).collect();
        let c = json!({"bezier": points_json(&ps), "weights": weights});
        let up = result(&json!({"op": "elevate", "curve": c, "by": r}), "curve");
        let down = json!({"op": "reduce_degree", "curve": up, "by": r});
        proptest::prop_assert_eq!(result(&down, "exact"), json!(true));
        let expected = json!({
            "bezier": ps.iter().map(|(x, y)| json!([x.to_string(), y.to_string()])).collect::<Vec<_>>(),
            "weights": ps.iter().zip(ws.iter().cycle()).map(|(_, w)| json!(w.to_string())).collect::<Vec<_>>(),
        });
        proptest::prop_assert_eq!(result(&down, "curve"), expected);
        // a B-spline (NURBS) of degree 2 with interior knots of multiplicity ≤ 2
        let p = 2usize;
        let mut knots = vec![json!(0); p];
        for (i, m) in mults.iter().enumerate() {
            knots.extend(std::iter::repeat_n(json!(i + 1), *m));
        }
        knots.extend(std::iter::repeat_n(json!(mults.len() + 1), p));
        let n = knots.len() + 1 - p;
        let pts: Vec<(i64, i64)> = (0..n).map(|i| { let (x, y) = ps[i % ps.len()]; (x + i as i64, y) }).collect();
        let mut b = json!({"bspline": points_json(&pts), "degree": p, "knots": knots});
        if rational {
            b["weights"] = json!((0..n).map(|i| ws[i % ws.len()]).collect::<Vec<_>>());
        }
        let up = result(&json!({"op": "elevate", "curve": b, "by": r}), "curve");
        let down = result(&json!({"op": "reduce_degree", "curve": up, "by": r}), "curve");
        proptest::prop_assert_eq!(&down["degree"], &json!(p));
        let end = mults.len() + 1;
        let ts: Vec<String> = (0..=4 * end).map(|k| q(k as i64, 4)).collect();
        proptest::prop_assert_eq!(eval("curve", &down, json!(ts)), eval("curve", &b, json!(ts)));
        let again = result(&json!({"op": "elevate", "curve": down, "by": r}), "curve");
        proptest::prop_assert_eq!(eval("curve", &again, json!(ts)), eval("curve", &up, json!(ts)));
    }
}

#[test]
fn reductions_that_are_not_exact_are_refused_with_the_reason() {
    let err = |p: Value| solve(&p).unwrap_err().to_string();
    // a C¹ quadratic B-spline whose second piece is not a line
    let b =
        json!({"bspline": [[0, 0], [1, 0], [2, 0], [3, 1]], "degree": 2, "knots": [0, 0, 1, 2, 2]});
    let e = err(json!({"op": "reduce_degree", "curve": b}));
    assert!(e.contains("the piece on [0, 1] is not of degree 1"), "{e}");
    // a polyline written as a quadratic B-spline: reduced to the polyline, its knot kept
    let b = json!({"bspline": [[0, 0], ["1/2", 0], [1, 0], ["3/2", 1], [2, 2]], "degree": 2, "knots": [0, 0, 1, 1, 2, 2]});
    let a = solve(&json!({"op": "reduce_degree", "curve": b})).unwrap();
    assert_eq!(
        a.get("curve").unwrap().to_json(),
        json!({"bspline": [["0", "0"], ["1", "0"], ["2", "2"]], "degree": 1, "knots": ["0", "1", "2"]})
    );
    let e = err(json!({"op": "reduce_degree", "curve": b, "by": 2}));
    assert!(e.contains("its degree must stay at least 1"), "{e}");
}
