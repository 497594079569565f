//! Operations on patches through `solve`: the continuity of Bézier patches of different
//! degrees, iso-parametric and boundary curves of Bézier, B-spline and NURBS surfaces,
//! subdivision, and triangular patches (evaluation with its steps, closed form, elevation,
//! directional derivatives, the blossom, subdivision, boundary curves and the normal), each
//! against an independent derivation.

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

/// Regression (issue 16): two Bézier patches of different degrees along their common border
/// were refused with "the patches do not share a border"; the lower one is now elevated first.
#[test]
fn continuity_of_patches_of_different_degrees_along_the_border() {
    // first: (2u, 2v, 0) as a (2, 1) patch; second: (2 + 2u, 2v, u^2) as a (2, 2) patch
    let first =
        json!({"bezier": [[[0, 0, 0], [0, 2, 0]], [[1, 0, 0], [1, 2, 0]], [[2, 0, 0], [2, 2, 0]]]});
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
fn triangle_evaluate_closed_form_and_steps() {
    // z = u v over the domain triangle: b_{011} = (1/2, 1/2, 1/2)
    let t = json!({"triangle": [[[0, 0, 0]], [["1/2", 0, 0], [0, "1/2", 0]], [[1, 0, 0], ["1/2", "1/2", "1/2"], [0, 1, 0]]]});
    assert_eq!(
        eval(
            "triangle",
            &t,
            json!([["1/2", "1/3"], ["1/6", "1/2", "1/3"]])
        ),
        json!([["1/2", "1/3", "1/6"], ["1/2", "1/3", "1/6"]])
    );
    assert_eq!(
        result(&json!({"op": "closed_form", "triangle": t}), "closed_form"),
        json!("(u, v, u*v)")
    );
    // elevated, the same patch
    let e = result(
        &json!({"op": "elevate", "triangle": t, "by": 2}),
        "triangle",
    );
    assert_eq!(e["triangle"].as_array().unwrap().len(), 5);
    assert_eq!(
        result(&json!({"op": "closed_form", "triangle": e}), "closed_form"),
        json!("(u, v, u*v)")
    );
    // ∂/∂v = (0, 1, u); ∂²/∂u∂v along (1, 1) twice: D_d D_d (u v) = 2
    let d = json!({"op": "derivative", "triangle": t, "direction": [0, 1]});
    assert_eq!(result(&d, "closed_form"), json!("(0, 1, u)"));
    let d2 = json!({"op": "derivative", "triangle": t, "direction": [1, 1], "order": 2});
    assert_eq!(result(&d2, "closed_form"), json!("(0, 0, 2)"));
    // with steps: the De Casteljau levels
    let a = solve(&json!({"op": "evaluate", "triangle": t, "params": [["1/2", "1/3"]]})).unwrap();
    let steps = format!("{:?}", a.derivation);
    assert!(steps.contains("b_{0,0,0}^{2}"), "{steps}");
    // a bad net: row 1 of three points
    let bad = json!({"op": "evaluate", "triangle": {"triangle": [[[0]], [[1], [2], [3]]]}, "params": [[0, 0]]});
    assert_eq!(
        solve(&bad).unwrap_err().to_string(),
        "field `triangle.triangle[1]`: row 1 of a triangular net holds 2 points (b_{n-1,1-k,k}, k = 0, ..., 1), found 3"
    );
}

#[test]
fn triangle_blossom_subdivide_boundary() {
    let t = json!({"triangle": [[[0, 0, 0]], [["1/2", 0, 0], [0, "1/2", 0]], [[1, 0, 0], ["1/2", "1/2", "1/2"], [0, 1, 0]]]});
    // b[e2, e3] = b_{011}
    let b = json!({"op": "blossom", "triangle": t, "params": [[1, 0], [0, 1]]});
    assert_eq!(result(&b, "point"), json!(["1/2", "1/2", "1/2"]));
    // on the diagonal, the patch
    let b = json!({"op": "blossom", "triangle": t, "params": [["1/2", "1/3"], ["1/2", "1/3"]]});
    assert_eq!(result(&b, "point"), json!(["1/2", "1/3", "1/6"]));
    let s = result(
        &json!({"op": "subdivide", "triangle": t, "u": "1/3", "v": "1/3"}),
        "triangles",
    );
    assert_eq!(s.as_array().unwrap().len(), 3);
    // the first piece, over (x, e2, e3), at its vertex 1 is b(x)
    assert_eq!(
        eval("triangle", &s[0], json!([[0, 0]])),
        json!([["1/3", "1/3", "1/9"]])
    );
    let bd = json!({"op": "boundary", "triangle": t});
    assert_eq!(
        result(&bd, "curve_v0"),
        json!({"bezier": [["0", "0", "0"], ["1/2", "0", "0"], ["1", "0", "0"]]})
    );
    assert_eq!(
        result(&bd, "curve_uv1"),
        json!({"bezier": [["1", "0", "0"], ["1/2", "1/2", "1/2"], ["0", "1", "0"]]})
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// A triangular patch's split reproduces it: the piece over (x, e2, e3) at (ρ, σ, τ) is the
    /// patch at ρ x + σ e2 + τ e3, computed here from its closed form (substitution).
    #[test]
    fn split_triangles_reproduce_the_patch(zs in proptest::collection::vec(-9i64..10, 6), sn in 0i64..4, tn in 0i64..4) {
        let n = 2;
        let mut rows = Vec::new();
        let mut it = zs.iter();
        for m in 0..=n {
            let row: Vec<Value> = (0..=m).map(|k| json!([q((m - k) as i64, 2), q(k as i64, 2), it.next().unwrap()])).collect();
            rows.push(Value::Array(row));
        }
        let t = json!({"triangle": rows});
        let (xu, xv) = (rat("1/5"), rat("2/7"));
        let parts = result(&json!({"op": "subdivide", "triangle": t, "u": "1/5", "v": "2/7"}), "triangles");
        let (s, tt) = (rat(&q(sn, 7)), rat(&q(tn, 7)));
        let one = cagd_scalar::BigRational::from_integer(1.into());
        let rho = &one - &s - &tt;
        // ρ x + σ e2 + τ e3 in (u, v): u = ρ xu + σ, v = ρ xv + τ
        let u = (&rho * &xu + &s).to_string();
        let v = (&rho * &xv + &tt).to_string();
        prop_assert_eq!(
            eval("triangle", &parts[0], json!([[s.to_string(), tt.to_string()]])),
            eval("surface", &json!({"expr": result(&json!({"op": "closed_form", "triangle": t}), "closed_form")}), json!([[u, v]]))
        );
    }

    /// The iso-parametric curve u = u0 of a patch is the patch at (u0, v).
    #[test]
    fn isocurves_lie_on_the_patch(zs in proptest::collection::vec(-9i64..10, 6), un in 0i64..5, vn in 0i64..5) {
        let rows: Vec<Value> = (0..2).map(|i| Value::Array((0..3).map(|j| json!([i, j, zs[i * 3 + j]])).collect())).collect();
        let s = json!({"bezier": rows});
        let (u, v) = (q(un, 4), q(vn, 4));
        let c = result(&json!({"op": "isocurve", "surface": s, "u": u}), "curve");
        prop_assert_eq!(eval("curve", &c, json!([v.clone()])), eval("surface", &s, json!([[u.clone(), v.clone()]])));
        let d = result(&json!({"op": "isocurve", "surface": s, "v": v}), "curve");
        prop_assert_eq!(eval("curve", &d, json!([u.clone()])), eval("surface", &s, json!([[u, v]])));
    }

    /// Subdividing a patch at (u0, v0): the piece [0, u0] × [0, v0] at (s, t) is the patch at
    /// (u0 s, v0 t).
    #[test]
    fn subdivided_patches_reproduce_the_patch(zs in proptest::collection::vec(-9i64..10, 6), sn in 0i64..4, tn in 0i64..4) {
        let rows: Vec<Value> = (0..2).map(|i| Value::Array((0..3).map(|j| json!([i, j, zs[i * 3 + j]])).collect())).collect();
        let s = json!({"bezier": rows});
        let parts = result(&json!({"op": "subdivide", "surface": s, "u": "1/3", "v": "3/5"}), "surfaces");
        let (a, b) = (rat(&q(sn, 3)), rat(&q(tn, 3)));
        let one = cagd_scalar::BigRational::from_integer(1.into());
        let u = (rat("1/3") * &a).to_string();
        let v = (rat("3/5") + (&one - rat("3/5")) * &b).to_string();
        prop_assert_eq!(
            eval("surface", &parts[1], json!([[a.to_string(), b.to_string()]])),
            eval("surface", &s, json!([[u, v]]))
        );
    }
}

/// The boundary and iso-parametric curves of B-spline and NURBS surfaces lie on them: c(a, v),
/// c(u, d), c(u0, v) evaluated as curves equal the surface.
#[test]
fn boundary_and_isocurves_of_spline_surfaces() {
    let mesh = json!([
        [[0, 0, 0], [0, 1, 1], [0, 2, 0], [0, 3, 2]],
        [[1, 0, 1], [1, 1, 2], [1, 2, 1], [1, 3, 0]],
        [[2, 0, 0], [2, 1, 1], [2, 2, 3], [2, 3, 1]]
    ]);
    let weights = json!([[1, 2, 1, 1], [1, 1, 3, 1], [2, 1, 1, 1]]);
    // degree (1, 2), u knots [0, 1, 2] (domain [0, 2]), v knots [0, 0, 1, 2, 2]... notes' form
    let b = json!({"bspline": mesh, "degree": [1, 2], "knots": [[0, 1, 2], [0, 1, 3, 4, 6]]});
    let n = json!({"bspline": mesh, "degree": [1, 2], "knots": [[0, 1, 2], [0, 1, 3, 4, 6]], "weights": weights});
    for s in [&b, &n] {
        let bd = json!({"op": "boundary", "surface": s});
        // the domain: u in [0, 2], v in [1, 4]
        for (name, fixed, free) in [
            ("curve_u0", ("u", "0"), "v"),
            ("curve_u1", ("u", "2"), "v"),
            ("curve_v0", ("v", "1"), "u"),
            ("curve_v1", ("v", "4"), "u"),
        ] {
            let c = result(&bd, name);
            let x = if free == "v" { "5/2" } else { "1/3" };
            let (u, v) = if fixed.0 == "u" {
                (fixed.1, x)
            } else {
                (x, fixed.1)
            };
            assert_eq!(
                eval("curve", &c, json!([x])),
                eval("surface", s, json!([[u, v]])),
                "{name} of {s}"
            );
        }
        let iso = result(
            &json!({"op": "isocurve", "surface": s, "u": "3/2"}),
            "curve",
        );
        assert_eq!(
            eval("curve", &iso, json!(["7/3"])),
            eval("surface", s, json!([["3/2", "7/3"]]))
        );
        let iso = result(
            &json!({"op": "isocurve", "surface": s, "v": "3/2"}),
            "curve",
        );
        assert_eq!(
            eval("curve", &iso, json!(["1/5"])),
            eval("surface", s, json!([["1/5", "3/2"]]))
        );
    }
}

/// The normal of a triangular patch: b_u × b_v as a closed form and at points, equal to the
/// cross product of the derivatives taken from the closed form (z = u v: n = (-v, -u, 1)).
#[test]
fn triangle_normal() {
    let t = json!({"triangle": [[[0, 0, 0]], [["1/2", 0, 0], [0, "1/2", 0]], [[1, 0, 0], ["1/2", "1/2", "1/2"], [0, 1, 0]]]});
    let p = json!({"op": "normal", "triangle": t, "params": [["1/2", "1/3"]]});
    assert_eq!(result(&p, "closed_form"), json!("(-v, -u, 1)"));
    assert_eq!(result(&p, "normals"), json!([["-1/3", "-1/2", "1"]]));
    let flat = json!({"triangle": [[[0, 0]], [[1, 0], [0, 1]]]});
    assert!(solve(&json!({"op": "normal", "triangle": flat}))
        .unwrap_err()
        .to_string()
        .contains("R³"));
}
