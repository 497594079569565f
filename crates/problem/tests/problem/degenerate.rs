//! Degenerate but valid input is answered, exactly, not refused: repeated control points (the
//! sphere's pole), zero-length curves, degree 0 in one direction, knots of full multiplicity
//! inside the domain, parameters at the ends of the domain.

use cagd_problem::solve;
use cagd_scalar::Print;
use serde_json::{json, Value};

/// The JSON of result `name` of problem `p`.
fn result(p: Value, name: &str) -> Value {
    let a = solve(&p).unwrap_or_else(|e| panic!("{p}: {e}"));
    a.get(name)
        .unwrap_or_else(|| panic!("{p}: no {name}"))
        .to_json()
}

#[test]
fn repeated_control_points_the_pole_of_the_sphere() {
    // The octant of the unit sphere (notes ch. 6): its last row is the pole (0, 0, 1), three
    // times. Evaluation there, and the normal, are answered; the degenerate corners are said.
    let octant = json!({
        "bezier": [[[1, 0, 0], [1, 1, 0], [0, 1, 0]],
                   [[1, 0, 1], [1, 1, 1], [0, 1, 1]],
                   [[0, 0, 1], [0, 0, 1], [0, 0, 1]]],
        "weights": [[1, "sqrt2/2", 1], ["sqrt2/2", "1/2", "sqrt2/2"], [1, "sqrt2/2", 1]]
    });
    let a = solve(&json!({"op": "evaluate", "surface": octant, "params": [[1, 0], [1, "1/2"], [1, 1], [0, 0], ["1/2", "1/2"]]})).unwrap();
    let Some(cagd_problem::Exact::Points(points)) = a.get("points") else {
        panic!("no points");
    };
    let text: Vec<String> = points.iter().map(|p| p.to_text()).collect();
    assert_eq!(
        text[..4],
        ["(0, 0, 1)", "(0, 0, 1)", "(0, 0, 1)", "(1, 0, 0)"]
    );
    // every point on the unit sphere, exactly (in Q(√2))
    for p in points {
        let r2 = p.dot(p);
        assert_eq!(r2.to_text(), "1", "{}", p.to_text());
    }
    let a = solve(&json!({"op": "normal", "surface": octant})).unwrap();
    // c_u x c_v vanishes at the pole; its direction tends to the axis there (inwards, as at
    // the other corners: the octant's normal c_u x c_v points to the centre)
    assert_eq!(
        a.get("corner_10").unwrap().to_json(),
        json!("degenerate at (1, 0): the vertices c_{2,0} and c_{2,1} coincide, so a difference of (25) is the zero vector; the limit direction of the normal along v = 0 is (0, 0, -2√2)")
    );
    assert_eq!(
        a.get("corner_10_limit").unwrap().to_json(),
        json!(["0", "0", "-2*sqrt2"])
    );
    let pole = a.get("corner_11_limit").unwrap().to_json();
    assert_eq!((&pole[0], &pole[1]), (&json!("0"), &json!("0")), "{pole}");
    // at the regular corner (1, 0, 0): c_u x c_v = (0, 0, √2) x (0, √2, 0) = (-2, 0, 0), which
    // is m n = 4 times (25) with the weights' factor (√2/2)^2
    assert_eq!(
        a.get("corner_00").unwrap().to_json(),
        json!(["-2", "0", "0"])
    );
}

#[test]
fn zero_length_curves() {
    // All control points equal: a curve that stays at one point.
    let c = json!({"bezier": [[1, 2], [1, 2], [1, 2]]});
    assert_eq!(
        result(
            json!({"op": "evaluate", "curve": c, "params": [0, "1/3", 1]}),
            "points"
        ),
        json!([["1", "2"], ["1", "2"], ["1", "2"]])
    );
    assert_eq!(
        result(json!({"op": "closed_form", "curve": c}), "closed_form"),
        json!("(1, 2)")
    );
    assert_eq!(
        result(
            json!({"op": "derivative", "curve": c, "order": 1}),
            "closed_form"
        ),
        json!("(0, 0)")
    );
    assert_eq!(
        result(json!({"op": "elevate", "curve": c, "by": 1}), "curve"),
        json!({"bezier": [["1", "2"], ["1", "2"], ["1", "2"], ["1", "2"]]})
    );
    // a B-spline curve at one point
    let b = json!({"bspline": [[3, 3], [3, 3], [3, 3], [3, 3]], "degree": 2, "knots": [0, 0, "1/2", 1, 1]});
    assert_eq!(
        result(
            json!({"op": "evaluate", "curve": b, "params": [0, "1/4", "1/2", 1]}),
            "points"
        ),
        json!([["3", "3"], ["3", "3"], ["3", "3"], ["3", "3"]])
    );
    // a ruled surface between a curve and a point (a cone)
    let cone = json!({"op": "ruled", "c1": {"bezier": [[1, 0, 0], [0, 1, 0]]}, "c2": {"bezier": [[0, 0, 1], [0, 0, 1]]}});
    assert_eq!(
        result(cone, "closed_form"),
        json!("(u*v - u - v + 1, -u*v + u, v)")
    );
}

#[test]
fn degree_zero_in_one_direction() {
    // A patch of bidegree (2, 0): a curve (a line of points in v has one point).
    let s = json!({"bezier": [[[0, 0, 0]], [[1, 1, 0]], [[2, 0, 1]]]});
    assert_eq!(
        result(json!({"op": "closed_form", "surface": s}), "closed_form"),
        json!("(2*u, -2*u^2 + 2*u, u^2)")
    );
    assert_eq!(
        result(
            json!({"op": "evaluate", "surface": s, "params": [["1/2", 0], ["1/2", 1]]}),
            "points"
        ),
        json!([["1", "1/2", "1/4"], ["1", "1/2", "1/4"]])
    );
    assert_eq!(
        result(
            json!({"op": "derivative", "surface": s, "order": [0, 1]}),
            "closed_form"
        ),
        json!("(0, 0, 0)")
    );
    assert_eq!(
        result(
            json!({"op": "elevate", "surface": s, "by": [0, 1]}),
            "surface"
        ),
        json!({"bezier": [[["0", "0", "0"], ["0", "0", "0"]], [["1", "1", "0"], ["1", "1", "0"]], [["2", "0", "1"], ["2", "0", "1"]]]})
    );
    // a curve of degree 0: one point
    assert_eq!(
        result(
            json!({"op": "evaluate", "curve": {"bezier": [[5, 7]]}, "params": [0, 1]}),
            "points"
        ),
        json!([["5", "7"], ["5", "7"]])
    );
}

#[test]
fn knots_of_full_multiplicity_inside() {
    // Degree 2 with the inner knot 1 twice (multiplicity p): the curve passes through d_2
    // and is two Bézier pieces joined C^0.
    let c = json!({"bspline": [[0, 0], [1, 2], [2, 0], [3, 2], [4, 0]], "degree": 2, "knots": [0, 0, 1, 1, 2, 2]});
    assert_eq!(
        result(
            json!({"op": "evaluate", "curve": c, "params": [0, "1/2", 1, "3/2", 2]}),
            "points"
        ),
        json!([["0", "0"], ["1", "1"], ["2", "0"], ["3", "1"], ["4", "0"]])
    );
    // inserting another knot is fine
    assert_eq!(
        result(
            json!({"op": "insert_knot", "curve": c, "knot": "1/2", "times": 1}),
            "curve"
        )["knots"],
        json!(["0", "0", "1/2", "1", "1", "2", "2"])
    );
    // once more, to p + 1, splits the curve there; twice more is refused
    let halves = result(
        json!({"op": "insert_knot", "curve": c, "knot": 1, "times": 1}),
        "curves",
    );
    assert_eq!(halves[0]["knots"], json!(["0", "0", "1", "1"]));
    let over = solve(&json!({"op": "insert_knot", "curve": c, "knot": 1, "times": 2})).unwrap_err();
    assert!(over.to_string().starts_with("field `times`: "), "{over}");
}

#[test]
fn parameters_at_the_ends_of_the_domain() {
    let c =
        json!({"bspline": [[0, 0], [1, 2], [3, 2], [4, 0]], "degree": 2, "knots": [0, 0, 1, 2, 2]});
    assert_eq!(
        result(
            json!({"op": "evaluate", "curve": c, "params": [0, 2]}),
            "points"
        ),
        json!([["0", "0"], ["4", "0"]])
    );
    let s = json!({"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]});
    assert_eq!(
        result(
            json!({"op": "evaluate", "surface": s, "params": [[0, 0], [1, 0], [0, 1], [1, 1]]}),
            "points"
        ),
        json!([
            ["0", "0", "0"],
            ["1", "0", "0"],
            ["0", "1", "0"],
            ["1", "1", "1"]
        ])
    );
    // restriction to the whole domain and to a point of it
    let q = json!({"bezier": [[0, 0], [1, 3], [3, 3], [4, 0]]});
    assert_eq!(
        result(json!({"op": "restrict", "curve": q, "t": [0, 1]}), "curve"),
        json!({"bezier": [["0", "0"], ["1", "3"], ["3", "3"], ["4", "0"]]})
    );
    assert_eq!(
        result(
            json!({"op": "restrict", "curve": q, "t": ["1/2", 1]}),
            "curve"
        ),
        json!({"bezier": [["2", "9/4"], ["11/4", "9/4"], ["7/2", "3/2"], ["4", "0"]]})
    );
    // an interval of length zero is not a restriction (it is no curve on [0, 1])
    assert_eq!(
        solve(&json!({"op": "restrict", "curve": q, "t": [1, 1]}))
            .unwrap_err()
            .to_string(),
        "field `curve`: the interval [1, 1] is degenerate: its ends must satisfy a < b"
    );
    // a NURBS circle at both ends of its interval
    assert_eq!(
        result(
            json!({"op": "evaluate", "curve": {"bspline": [[1, 0], [1, 1], [0, 1]], "degree": 2, "knots": [0, 0, 1, 1], "weights": [1, "sqrt2/2", 1]}, "params": [0, 1]}),
            "points"
        ),
        json!([["1", "0"], ["0", "1"]])
    );
}

/// Found by the `solve_json` fuzz target (slow units of the instrumented build): the sphere
/// octant's normal with a weight of 53 digits, and with a corner vertex moved onto its
/// neighbour. Both are answered, exactly: the regular corners' normals, and the degenerate
/// corners named.
#[test]
fn normals_of_rational_patches_with_long_weights() {
    let mesh = json!([
        [[0, 0, 0], [0, 1, 0], [0, 1, 0]],
        [[1, 0, 1], [1, 1, 1], [0, 1, 1]],
        [[0, 0, 1], [0, 0, 1], [0, 0, 1]]
    ]);
    let tiny = format!("1/2{}", "0".repeat(52));
    let weights = json!([
        [1, "sqrt2/2", 1],
        ["sqrt2/2", tiny, "sqrt2/2"],
        [1, "sqrt2/2", 1]
    ]);
    let p = json!({"op": "normal", "surface": {"bezier": mesh, "weights": weights}});
    // c_u x c_v at (0, 0): m n = 4 times (25), (w_10 w_01 / w_00^2) Δ^{1,0} c_00 x Δ^{0,1} c_00
    // = (1/2) (1, 0, 1) x (0, 1, 0) = (-1/2, 0, 1/2)
    assert_eq!(result(p.clone(), "corner_00"), json!(["-2", "0", "2"]));
    assert_eq!(
        result(p.clone(), "corner_10"),
        json!(format!("degenerate at (1, 0): the vertices c_{{2,0}} and c_{{2,1}} coincide, so a difference of (25) is the zero vector; the limit direction of the normal along v = 0 is (0, 0, -√2/5{})", "0".repeat(51)))
    );
    // the closed form has the 53-digit weight in it, exactly (over w^3 since the normal
    // c_u x c_v = (w N_u x N_v + w_v N x N_u + w_u N_v x N) / w^3)
    let closed = result(p, "closed_form").to_string();
    assert!(
        closed.contains(&format!("5{}1/125{}", "0".repeat(51), "0".repeat(49))),
        "{closed}"
    );
}
