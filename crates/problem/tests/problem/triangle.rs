//! Issue 16, the triangle column: `restrict` to a sub-triangle, `isocurve` u, v or w = const,
//! `reverse` (a relabelling of the vertices; and tensor-product patches in u or v) and `graph`
//! over a triangle, each against an independent route (evaluation at the mapped point, the
//! closed form of the graph written out by hand).

use cagd_problem::solve;
use cagd_scalar::BigRational;
use proptest::prelude::*;
use serde_json::{json, Value};

/// The JSON of result `name` of the problem `p`.
fn result(p: &Value, name: &str) -> Value {
    let a = solve(p).unwrap_or_else(|e| panic!("{p}: {e}"));
    a.get(name)
        .unwrap_or_else(|| panic!("no {name} in the answer of {p}"))
        .to_json()
}

/// The error of the problem `p`.
fn err(p: Value) -> String {
    match solve(&p) {
        Ok(_) => panic!("{p} was answered"),
        Err(e) => e.to_string(),
    }
}

/// The points of `evaluate` on `shape` (`"curve"`, `"surface"` or `"triangle"`) at `params`.
fn eval(key: &str, shape: &Value, params: Value) -> Value {
    result(
        &json!({"op": "evaluate", key: shape, "params": params}),
        "points",
    )
}

/// A net as answers write it (elevated by 0).
fn canonical(t: Value) -> Value {
    result(
        &json!({"op": "elevate", "triangle": t, "by": 0}),
        "triangle",
    )
}

fn rat(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

/// A triangular net of degree n in R³ from n + 1 choose 2 heights: b_{ijk} = (j/n, k/n, z).
fn net(n: usize, zs: &[i64]) -> Value {
    let mut it = zs.iter().cycle();
    let rows: Vec<Value> = (0..=n)
        .map(|m| {
            Value::Array(
                (0..=m)
                    .map(|k| {
                        let j = m - k;
                        json!([
                            format!("{j}/{n}"),
                            format!("{}/{n}", k * k),
                            it.next().unwrap()
                        ])
                    })
                    .collect(),
            )
        })
        .collect();
    json!({"triangle": rows})
}

/// The patch `t` at the point (u, v).
fn at(t: &Value, u: &BigRational, v: &BigRational) -> Value {
    eval("triangle", t, json!([[u.to_string(), v.to_string()]]))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// The restriction to (a, b, c) at (σ, τ) of its own domain is the patch at
    /// ρ a + σ b + τ c, ρ = 1 - σ - τ (a sub-triangle that may reach outside the domain).
    #[test]
    fn a_restriction_is_the_patch_at_the_mapped_point(
        zs in proptest::collection::vec(-9i64..10, 10),
        corners in proptest::collection::vec(-3i64..6, 6),
        sn in 0i64..5, tn in 0i64..5,
    ) {
        let t = net(3, &zs);
        let c: Vec<BigRational> = corners.iter().map(|&x| rat(x, 4)).collect();
        let vertices: Vec<Value> = c.chunks(2).map(|p| json!([p[0].to_string(), p[1].to_string()])).collect();
        let sub = result(&json!({"op": "restrict", "triangle": t, "vertices": vertices}), "triangle");
        let (s, tt) = (rat(sn, 7), rat(tn, 7));
        let rho = rat(1, 1) - &s - &tt;
        let u = &rho * &c[0] + &s * &c[2] + &tt * &c[4];
        let v = &rho * &c[1] + &s * &c[3] + &tt * &c[5];
        prop_assert_eq!(at(&sub, &s, &tt), at(&t, &u, &v));
    }

    /// The iso-line u = u0 at λ is the patch at (u0, λ (1 - u0)); v = v0 at (λ (1 - v0), v0);
    /// w = w0 at ((1 - λ)(1 - w0), λ (1 - w0)).
    #[test]
    fn iso_lines_lie_on_the_patch(
        zs in proptest::collection::vec(-9i64..10, 10),
        xn in -2i64..7, ln in 0i64..6,
    ) {
        let t = net(3, &zs);
        let (x0, lambda) = (rat(xn, 5), rat(ln, 5));
        let rest = rat(1, 1) - &x0;
        let points = [
            ("u", x0.clone(), &lambda * &rest),
            ("v", &lambda * &rest, x0.clone()),
            ("w", (rat(1, 1) - &lambda) * &rest, &lambda * &rest),
        ];
        for (key, u, v) in points {
            let c = result(&json!({"op": "isocurve", "triangle": t, key: x0.to_string()}), "curve");
            prop_assert_eq!(eval("curve", &c, json!([lambda.to_string()])), at(&t, &u, &v));
        }
    }

    /// A relabelled patch traces the same points: with new vertex m the old vertex σ_m, the
    /// new patch at x is the old one at y, y_{σm} = x_m.
    #[test]
    fn a_relabelled_triangle_traces_the_same_points(
        zs in proptest::collection::vec(-9i64..10, 6),
        sn in 0i64..5, tn in 0i64..5,
    ) {
        let t = net(2, &zs);
        let x = [rat(1, 1) - rat(sn, 5) - rat(tn, 5), rat(sn, 5), rat(tn, 5)];
        for order in [[1, 2, 3], [1, 3, 2], [2, 1, 3], [2, 3, 1], [3, 1, 2], [3, 2, 1]] {
            let r = result(&json!({"op": "reverse", "triangle": t, "order": order}), "triangle");
            let mut y = [rat(0, 1), rat(0, 1), rat(0, 1)];
            for (m, &sigma) in order.iter().enumerate() {
                y[sigma - 1] = x[m].clone();
            }
            prop_assert_eq!(at(&r, &x[1], &x[2]), at(&t, &y[1], &y[2]));
        }
    }

    /// A patch reversed in u at (u, v) is the patch at (a + b - u, v); in v, at (u, c + d - v):
    /// Bézier, rational and B-spline.
    #[test]
    fn a_reversed_patch_traces_the_same_points(
        zs in proptest::collection::vec(-9i64..10, 12),
        ws in proptest::collection::vec(1i64..5, 12),
        un in 0i64..9, vn in 0i64..9,
    ) {
        let mesh: Vec<Value> = (0..3)
            .map(|i| Value::Array((0..4).map(|j| json!([i, j * j, zs[i * 4 + j]])).collect()))
            .collect();
        let weights: Vec<Value> = (0..3).map(|i| json!(ws[i * 4..i * 4 + 4].to_vec())).collect();
        let surfaces = [
            (json!({"bezier": mesh}), (1, 1)),
            (json!({"bezier": mesh, "weights": weights}), (1, 1)),
            (json!({"bspline": mesh, "degree": [2, 2], "knots": [[0, 0, 3, 3], [0, 0, 1, 3, 3]]}), (3, 3)),
            (json!({"bspline": mesh, "degree": [2, 2], "knots": [[0, 0, 3, 3], [0, 0, 1, 3, 3]], "weights": weights}), (3, 3)),
        ];
        for (s, (bu, bv)) in surfaces {
            let (u, v) = (rat(un, 8) * rat(bu, 1), rat(vn, 8) * rat(bv, 1));
            let ru = result(&json!({"op": "reverse", "surface": s, "direction": "u"}), "surface");
            prop_assert_eq!(
                eval("surface", &ru, json!([[u.to_string(), v.to_string()]])),
                eval("surface", &s, json!([[(rat(bu, 1) - &u).to_string(), v.to_string()]]))
            );
            let rv = result(&json!({"op": "reverse", "surface": s, "direction": "v"}), "surface");
            prop_assert_eq!(
                eval("surface", &rv, json!([[u.to_string(), v.to_string()]])),
                eval("surface", &s, json!([[u.to_string(), (rat(bv, 1) - &v).to_string()]]))
            );
        }
    }

    /// The graph of f over the triangle (A, B, C) at (u, v) is (x, y, f(x, y)) at
    /// x = A + u (B - A) + v (C - A): against the expression written out and evaluated.
    #[test]
    fn a_triangular_graph_is_the_function(
        cs in proptest::collection::vec(-5i64..6, 6),
        corners in proptest::collection::vec(-3i64..4, 6),
        un in 0i64..4, vn in 0i64..4,
    ) {
        let [ax, ay, bx, by, cx, cy] = [0, 1, 2, 3, 4, 5].map(|i| corners[i]);
        prop_assume!((bx - ax) * (cy - ay) - (by - ay) * (cx - ax) != 0);
        let f = format!("{} + {}*x + {}*y + {}*x^2 + {}*x*y + {}*y^2", cs[0], cs[1], cs[2], cs[3], cs[4], cs[5]);
        let domain = json!([[ax, ay], [bx, by], [cx, cy]]);
        let t = result(&json!({"op": "graph", "f": f, "domain": domain}), "triangle");
        let x = format!("({ax} + u*({bx} - {ax}) + v*({cx} - {ax}))");
        let y = format!("({ay} + u*({by} - {ay}) + v*({cy} - {ay}))");
        let fx = f.replace('x', &x).replace('y', &y);
        let map = json!({"expr": format!("({x}, {y}, {fx})")});
        let (u, v) = (rat(un, 4), rat(vn, 4));
        prop_assert_eq!(at(&t, &u, &v), eval("surface", &map, json!([[u.to_string(), v.to_string()]])));
    }
}

#[test]
fn the_graph_of_x_y_over_the_unit_triangle() {
    // (j/2, k/2, f̂) with f̂_{011} = 1/2: the net of the crate's own example
    let t = result(
        &json!({"op": "graph", "f": "x*y", "domain": [[0, 0], [1, 0], [0, 1]]}),
        "triangle",
    );
    assert_eq!(
        t,
        canonical(
            json!({"triangle": [[[0, 0, 0]], [["1/2", 0, 0], [0, "1/2", 0]], [[1, 0, 0], ["1/2", "1/2", "1/2"], [0, 1, 0]]]})
        )
    );
    // elevated on request
    let t3 = result(
        &json!({"op": "graph", "f": "x*y", "domain": [[0, 0], [1, 0], [0, 1]], "degree": 3}),
        "triangle",
    );
    assert_eq!(t3["triangle"].as_array().unwrap().len(), 4);
}

#[test]
fn a_point_outside_the_triangle_is_said() {
    // u + v = 4/3 > 1: r = -1/3, outside the domain triangle; the value is still the
    // polynomial's (the patch z = u v: 4/9), and the answer says the point is outside
    let t = json!({"triangle": [[[0, 0, 0]], [["1/2", 0, 0], [0, "1/2", 0]], [[1, 0, 0], ["1/2", "1/2", "1/2"], [0, 1, 0]]]});
    let p = json!({"op": "evaluate", "triangle": t, "params": [["1/3", "1/3"], ["2/3", "2/3"]]});
    let a = solve(&p).unwrap();
    assert_eq!(
        a.get("points").unwrap().to_json(),
        json!([["1/3", "1/3", "1/9"], ["2/3", "2/3", "4/9"]])
    );
    let said: Vec<String> = a.remarks.iter().map(|r| r.to_string()).collect();
    assert_eq!(said.len(), 1, "{said:?}");
    assert!(
        said[0].starts_with("the point params[1] = (-1/3, 2/3, 2/3)")
            && said[0].contains("outside the domain triangle")
            && said[0].contains("-1/3 is negative"),
        "{said:?}"
    );
    // a point of an edge (r = 0) is inside; so is a vertex
    let a = solve(&json!({"op": "evaluate", "triangle": t, "params": [["1/2", "1/2"], [0, 1]]}))
        .unwrap();
    assert!(a.remarks.is_empty(), "{:?}", a.remarks);
    // the normal at a point outside says so too
    let n = solve(&json!({"op": "normal", "triangle": t, "params": [[1, 1]]})).unwrap();
    assert!(n
        .remarks
        .iter()
        .any(|r| r.to_string().contains("params[0]")));
}

#[test]
fn triangle_errors_name_the_field() {
    let t = net(2, &[0, 1, 2, 3, 4, 5]);
    assert_eq!(
        err(json!({"op": "graph", "f": "x^2 + y", "domain": [[0, 0], [2, 0], [0, 2]], "degree": 1})),
        "field `degree`: f has total degree 2, more than the degree 1 asked for: its graph is a triangular patch of degree 2 or more"
    );
    assert_eq!(
        err(json!({"op": "graph", "f": "x", "domain": [[0, 0], [1, 1], [2, 2]]})),
        "field `domain`: the three vertices are collinear: they bound no triangle"
    );
    assert!(
        err(json!({"op": "graph", "f": "x", "domain": [[0, 0], [1, 1]]}))
            .contains("expected the three vertices [x, y] of a triangle, found 2 points")
    );
    assert!(err(
        json!({"op": "graph", "f": "x", "domain": [[0, 0], [1, 0], [0, 1]], "degree": [1, 1]})
    )
    .contains("a triangular patch has one degree"));
    assert!(
        err(json!({"op": "reverse", "triangle": t, "order": [1, 1, 2]}))
            .contains("expected a permutation of [1, 2, 3]")
    );
    assert!(
        err(json!({"op": "isocurve", "triangle": t, "u": 0, "w": 0}))
            .starts_with("field `w`: give one of `u`, `v`, `w`")
    );
    assert!(err(json!({"op": "isocurve", "triangle": t})).starts_with("field `u`: missing"));
    assert!(err(
        json!({"op": "isocurve", "surface": {"bezier": [[[0], [1]], [[2], [3]]]}, "w": 0})
    )
    .contains("give `triangle`"));
    assert!(err(json!({"op": "restrict", "triangle": t, "u": [0, 1]})).contains("give `vertices`"));
    assert!(
        err(json!({"op": "restrict", "triangle": t, "vertices": [[0, 0], [1, 0]]}))
            .contains("found 2 points")
    );
    assert!(err(json!({"op": "restrict", "triangle": t, "vertices": [[0, 0], [1, 0], ["1/2", "1/2", "1/2"]]}))
        .contains("sum to 3/2"));
    assert!(
        err(json!({"op": "reverse", "surface": {"bezier": [[[0], [1]], [[2], [3]]]}}))
            .starts_with("field `direction`: missing")
    );
}

#[test]
fn the_default_relabelling_exchanges_u_and_v() {
    // b_{ijk} → b_{ikj}: the net's rows in reverse
    let t = canonical(net(2, &[0, 1, 2, 3, 4, 5]));
    let r = result(&json!({"op": "reverse", "triangle": t}), "triangle");
    let rows = t["triangle"].as_array().unwrap();
    let reversed: Vec<Value> = rows
        .iter()
        .map(|row| Value::Array(row.as_array().unwrap().iter().rev().cloned().collect()))
        .collect();
    assert_eq!(r, json!({"triangle": reversed}));
}

/// A rational net: `net(n, zs)` with weights from `ws` (positive), in its rows.
fn rational(n: usize, zs: &[i64], ws: &[i64]) -> Value {
    let mut t = net(n, zs);
    let mut it = ws.iter().cycle();
    let rows: Vec<Value> = (0..=n)
        .map(|m| Value::Array((0..=m).map(|_| json!(it.next().unwrap())).collect()))
        .collect();
    t["weights"] = Value::Array(rows);
    t
}

/// The x, y, z of a point of an answer as rationals.
fn coords(p: &Value) -> Vec<BigRational> {
    p.as_array()
        .unwrap()
        .iter()
        .map(|x| {
            let s = match x {
                Value::String(s) => s.clone(),
                other => other.to_string(),
            };
            let (n, d) = s.split_once('/').unwrap_or((&s, "1"));
            BigRational::new(n.parse().unwrap(), d.parse().unwrap())
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    /// A rational triangular patch at x is Σ w b B / Σ w B: the polynomial patch of the
    /// points w b divided by the scalar patch of the weights (both evaluated by `solve`).
    #[test]
    fn a_rational_triangle_is_the_quotient_of_two_patches(
        zs in proptest::collection::vec(-9i64..10, 6),
        ws in proptest::collection::vec(1i64..6, 6),
        sn in 0i64..5, tn in 0i64..5,
    ) {
        let t = rational(2, &zs, &ws);
        let (u, v) = (rat(sn, 5), rat(tn, 5));
        let got = coords(&at(&t, &u, &v)[0]);
        let mut numer = t.clone();
        let mut denom = t.clone();
        let w: Vec<Vec<BigRational>> = t["weights"].as_array().unwrap().iter()
            .map(|r| r.as_array().unwrap().iter().map(|x| rat(x.as_i64().unwrap(), 1)).collect())
            .collect();
        let rows = t["triangle"].as_array().unwrap();
        let scaled: Vec<Value> = rows.iter().zip(&w).map(|(row, wr)| {
            Value::Array(row.as_array().unwrap().iter().zip(wr).map(|(p, wi)| {
                Value::Array(coords(p).iter().map(|x| json!((x * wi).to_string())).collect())
            }).collect())
        }).collect();
        numer["triangle"] = Value::Array(scaled);
        numer.as_object_mut().unwrap().remove("weights");
        denom["triangle"] = Value::Array(w.iter().map(|r| Value::Array(r.iter().map(|x| json!([x.to_string()])).collect())).collect());
        denom.as_object_mut().unwrap().remove("weights");
        let n = coords(&at(&numer, &u, &v)[0]);
        let d = coords(&at(&denom, &u, &v)[0]);
        let expected: Vec<BigRational> = n.iter().map(|x| x / &d[0]).collect();
        prop_assert_eq!(got, expected);
    }

    /// Elevation, restriction, relabelling, the split, the iso-lines and the boundary of a
    /// rational triangular patch trace the same points as the patch (the weights travel with
    /// the homogeneous points).
    #[test]
    fn rational_triangle_operations_keep_the_surface(
        zs in proptest::collection::vec(-9i64..10, 6),
        ws in proptest::collection::vec(1i64..6, 6),
        sn in 0i64..5, tn in 0i64..5,
    ) {
        let t = rational(2, &zs, &ws);
        let (s, tt) = (rat(sn, 9), rat(tn, 9));
        let here = at(&t, &s, &tt);
        let e = result(&json!({"op": "elevate", "triangle": t, "by": 1}), "triangle");
        prop_assert!(e.get("weights").is_some());
        prop_assert_eq!(at(&e, &s, &tt), here.clone());
        // the restriction to (e1, e2, e3) relabelled is the patch itself
        let r = result(&json!({"op": "restrict", "triangle": t, "vertices": [[0, 0], [1, 0], [0, 1]]}), "triangle");
        prop_assert_eq!(at(&r, &s, &tt), here.clone());
        let x = result(&json!({"op": "reverse", "triangle": t}), "triangle");
        prop_assert_eq!(at(&x, &tt, &s), here.clone());
        // the piece over (e1, e2, x) of the split at x = (1/2, 1/3) at (σ, τ) is the patch at
        // σ e2 + τ x
        let parts = result(&json!({"op": "subdivide", "triangle": t, "u": "1/2", "v": "1/3"}), "triangles");
        let (pu, pv) = (&s + &tt * rat(1, 2), &tt * rat(1, 3));
        prop_assert_eq!(at(&parts[2], &s, &tt), at(&t, &pu, &pv));
        // the iso-line u = s at λ = 1/2
        let c = result(&json!({"op": "isocurve", "triangle": t, "u": s.to_string()}), "curve");
        let v = (rat(1, 1) - &s) * rat(1, 2);
        prop_assert_eq!(eval("curve", &c, json!(["1/2"])), at(&t, &s, &v));
        // the edge v = 0 at u = s
        let b = result(&json!({"op": "boundary", "triangle": t}), "curve_v0");
        prop_assert_eq!(eval("curve", &b, json!([s.to_string()])), at(&t, &s, &rat(0, 1)));
        // the closed form is a quotient
        let f = result(&json!({"op": "closed_form", "triangle": t}), "closed_form");
        prop_assert!(f.as_str().unwrap().contains(")/("), "{}", f);
    }
}

#[test]
fn rational_triangles_refuse_what_is_not_a_patch_of_their_form() {
    let t = rational(2, &[0, 1, 2, 3, 4, 5], &[1, 2, 1, 2, 1, 2]);
    for op in ["derivative", "normal"] {
        assert!(err(json!({"op": op, "triangle": t})).starts_with(&format!(
            "field `triangle.weights`: a rational triangular patch has no `{op}` here"
        )));
    }
    assert!(err(json!({"op": "evaluate", "triangle": {"triangle": [[[0]], [[1], [2]]], "weights": [[1], [0, 1]]}, "params": [[0, 0]]}))
        .contains("the weight w_{0,1,0} is zero"));
    assert!(err(json!({"op": "evaluate", "triangle": {"triangle": [[[0]], [[1], [2]]], "weights": [[1], [1]]}, "params": [[0, 0]]}))
        .contains("row 1 of the weights holds 2 numbers"));
    assert!(err(json!({"op": "evaluate", "triangle": {"triangle": [[[0]], [[1], [2]]], "weights": [[1], [1, -1]]}, "params": [["1/2", "1/2"]]}))
        .contains("the rational patch has no point there"));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    /// An elevated patch (polynomial or rational) reduces back to its net exactly.
    #[test]
    fn an_elevated_triangle_reduces_back(
        zs in proptest::collection::vec(-9i64..10, 6),
        ws in proptest::collection::vec(1i64..6, 6),
    ) {
        for t in [canonical(net(2, &zs)), result(&json!({"op": "elevate", "triangle": rational(2, &zs, &ws), "by": 0}), "triangle")] {
            let e = result(&json!({"op": "elevate", "triangle": t, "by": 2}), "triangle");
            let back = solve(&json!({"op": "reduce_degree", "triangle": e, "by": 2})).unwrap();
            prop_assert_eq!(back.get("triangle").unwrap().to_json(), t.clone());
            prop_assert_eq!(back.get("exact").unwrap().to_json(), json!(true));
        }
    }

    /// The numerator G of the Gaussian curvature of a triangular patch is that of its closed
    /// form read as a map in (u, v) (the tensor-product route of `gaussian_curvature`).
    #[test]
    fn triangle_gaussian_numerator_is_the_closed_form_s(
        zs in proptest::collection::vec(-9i64..10, 6),
    ) {
        let t = net(2, &zs);
        let f = result(&json!({"op": "closed_form", "triangle": t}), "closed_form");
        prop_assert_eq!(
            result(&json!({"op": "gaussian_curvature", "triangle": t}), "numerator"),
            result(&json!({"op": "gaussian_curvature", "surface": {"expr": f}}), "numerator")
        );
    }
}

#[test]
fn triangle_reduction_and_curvature_examples() {
    // z = x y over the triangle: n = (-v, -u, 1), L = N = 0, M = 1, G = -1 (hyperbolic)
    let g = json!({"op": "graph", "f": "x*y", "domain": [[0, 0], [1, 0], [0, 1]]});
    let t = result(&g, "triangle");
    let k = solve(&json!({"op": "gaussian_curvature", "triangle": t})).unwrap();
    assert_eq!(k.get("numerator").unwrap().to_json(), json!("-1"));
    assert_eq!(k.get("developable").unwrap().to_json(), json!(false));
    // a plane is developable, and reduces to degree 1
    let plane = result(
        &json!({"op": "graph", "f": "2*x - y", "domain": [[0, 0], [1, 0], [0, 1]], "degree": 3}),
        "triangle",
    );
    let k = solve(&json!({"op": "gaussian_curvature", "triangle": plane})).unwrap();
    assert_eq!(k.get("developable").unwrap().to_json(), json!(true));
    let r = result(
        &json!({"op": "reduce_degree", "triangle": plane, "by": 2}),
        "triangle",
    );
    assert_eq!(
        r,
        canonical(json!({"triangle": [[[0, 0, 0]], [[1, 0, 2], [0, 1, -1]]]}))
    );
    // a true quadratic is not of degree 1
    assert_eq!(
        err(json!({"op": "reduce_degree", "triangle": t})),
        "field `by`: the closed form has total degree 2, more than 1: no patch of degree 1 is the same surface, so there is no exact reduction (a least-squares reduction of triangular nets is not available)"
    );
    assert!(err(json!({"op": "reduce_degree", "triangle": t, "by": 3}))
        .contains("cannot be reduced by 3"));
}

/// The figure of a rational triangular patch (a rational Bézier patch of bidegree (n, n) on the
/// unit square) at (u, v) is the patch at (u (1 - v), v).
#[test]
fn the_figure_of_a_rational_triangle_traces_it() {
    use cagd_problem::AnySurface;
    let t = rational(2, &[0, 1, 2, 3, 4, 5], &[1, 2, 3, 1, 2, 3]);
    let e = solve(&json!({"op": "elevate", "triangle": t, "by": 0})).unwrap();
    let Some(AnySurface::RationalBezier(s)) =
        cagd_problem::triangle::square_surface(e.get("triangle").unwrap())
    else {
        panic!("no rational figure");
    };
    for (u, v) in [
        (rat(1, 3), rat(1, 4)),
        (rat(0, 1), rat(1, 2)),
        (rat(1, 1), rat(0, 1)),
    ] {
        let p = s
            .eval(
                &<cagd_problem::Number as cagd_scalar::ExactRational>::from_rational_owned(
                    u.clone(),
                ),
                &<cagd_problem::Number as cagd_scalar::ExactRational>::from_rational_owned(
                    v.clone(),
                ),
            )
            .unwrap();
        let expected = at(&t, &(&u * (rat(1, 1) - &v)), &v);
        assert_eq!(
            json!(p.coords().iter().map(|x| x.to_string()).collect::<Vec<_>>()),
            expected[0]
        );
    }
}
