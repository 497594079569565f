//! Interpolation and least squares through `solve`: a domain of parameters outside [0, 1] kept,
//! chord-length, uniform and centripetal parameters (The NURBS Book, Ex. 9.1; a grid's averaged
//! over its columns and rows), clamped cubic splines, and B-spline least squares of curves and
//! surfaces.

use cagd_linalg::Point;
use cagd_problem::{solve, Exact, Number};
use cagd_scalar::{FieldOps, Print};
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

/// Regression (issue 16, fitting): parameters outside [0, 1] were silently mapped onto
/// [0, 1]. The curve came back as a bare Bézier polygon (on [0, 1]), which does not pass
/// through the data at the given parameters; the least-squares patch printed its closed form
/// in the given parameters but its mesh on the mapped square. Now the domain is kept: the
/// answer, fed back, evaluates at the given parameters to the closed form's values.
#[test]
fn fits_outside_the_unit_interval_keep_their_domain() {
    let evaluate = |shape: &str, answer: &Value, params: Value| {
        let a = solve(&json!({"op": "evaluate", shape: answer, "params": params})).unwrap();
        a.get("points").unwrap().to_json()
    };
    // interpolation of a curve at t = 0, 1, 2: the curve fed back passes through the data
    let a = solve(&json!({"op": "interpolate", "basis": "bezier", "params": [0, 1, 2], "points": [[0, 0], [1, 1], [2, 0]]})).unwrap();
    let curve = a.get("curve").unwrap().to_json();
    assert_eq!(
        evaluate("curve", &curve, json!([0, 1, 2])),
        json!([["0", "0"], ["1", "1"], ["2", "0"]])
    );
    assert_eq!(a.get("domain").unwrap().to_json(), json!(["0", "2"]));
    // least squares of a line at t = 0, 2, 4
    let a = solve(&json!({"op": "approximate", "degree": 1, "points": [[0, 0], [2, 1], [4, 0]], "params": [0, 2, 4]})).unwrap();
    let curve = a.get("curve").unwrap().to_json();
    assert_eq!(evaluate("curve", &curve, json!([2])), json!([["2", "1/3"]]));
    // least squares of a patch on [0, 2] x [0, 1]: the mesh and the closed form agree
    let a = solve(&json!({"op": "approximate", "degree": [1, 1],
        "points": [[0, 0, 0], [2, 0, 1], [0, 1, 0], [2, 1, 1], [1, "1/2", 2]],
        "params": [[0, 0], [2, 0], [0, 1], [2, 1], [1, "1/2"]]}))
    .unwrap();
    assert_eq!(
        a.get("closed_form").unwrap().to_json(),
        json!("(u, v, 1/2*u + 3/10)")
    );
    let surface = a.get("surface").unwrap().to_json();
    assert_eq!(
        evaluate("surface", &surface, json!([[1, "1/2"], [2, 1]])),
        json!([["1", "1/2", "4/5"], ["2", "1", "13/10"]])
    );
    // interpolation of a grid at u = 0, 2
    let a = solve(
        &json!({"op": "interpolate", "basis": "bezier", "u": [0, 2], "v": [0, 1],
        "points": [[[0, 0, 0], [0, 1, 0]], [[2, 0, 1], [2, 1, 1]]]}),
    )
    .unwrap();
    let surface = a.get("surface").unwrap().to_json();
    assert_eq!(
        evaluate("surface", &surface, json!([[2, 0], [1, 1]])),
        json!([["2", "0", "1"], ["1", "1", "1/2"]])
    );
    // on [0, 1] nothing changes: a Bézier polygon, no domain
    let a = solve(&json!({"op": "interpolate", "basis": "bezier", "params": [0, "1/2", 1], "points": [[0, 0], [1, 1], [2, 0]]})).unwrap();
    assert_eq!(
        a.get("curve").unwrap().to_json(),
        json!({"bezier": [["0", "0"], ["1", "2"], ["2", "0"]]})
    );
    assert!(a.get("domain").is_none());
}

/// The points of a curve or surface answer evaluated at `params`.
fn points_of(shape: &str, answer: &Value, params: Value) -> Vec<Point<Number>> {
    let a = solve(&json!({"op": "evaluate", shape: answer, "params": params})).unwrap();
    let Some(Exact::Points(p)) = a.get("points") else {
        panic!("no points")
    };
    p.clone()
}

#[test]
fn the_nurbs_book_example_9_1_chord_length_and_averaged_knots() {
    // five points, degree 3, chord-length parameters 0, 5/17, 9/17, 14/17, 1 and the knot
    // 28/51 (The NURBS Book, Ex. 9.1)
    let pts = json!([[0, 0], [3, 4], [-1, 4], [-4, 0], [-4, -3]]);
    let a = solve(&json!({"op": "interpolate", "basis": "bspline", "degree": 3, "parametrization": "chord_length", "points": pts})).unwrap();
    let curve = a.get("curve").unwrap().to_json();
    assert_eq!(
        curve["knots"],
        json!(["0", "0", "0", "28/51", "1", "1", "1"])
    );
    // the interpolant passes through the data at its parameters
    let data: Vec<Point<Number>> = pts
        .as_array()
        .unwrap()
        .iter()
        .map(|p| {
            Point::new(
                p.as_array()
                    .unwrap()
                    .iter()
                    .map(|x| Number::from_i64(x.as_i64().unwrap()))
                    .collect(),
            )
        })
        .collect();
    assert_eq!(
        points_of("curve", &curve, json!([0, "5/17", "9/17", "14/17", 1])),
        data
    );
    assert!(
        a.remarks
            .iter()
            .any(|r| r.to_string().contains("0, 5/17, 9/17, 14/17, 1")),
        "{:?}",
        a.remarks
    );
    // the computed parameters are a result of their own, `parameters`, not only a remark
    assert_eq!(
        a.get("parameters").unwrap().to_json(),
        json!(["0", "5/17", "9/17", "14/17", "1"])
    );
    // given parameters are the problem's data: no such result
    let given = solve(
        &json!({"op": "interpolate", "params": [0, "1/2", 1], "points": [[0, 0], [1, 1], [2, 0]]}),
    )
    .unwrap();
    assert!(given.get("parameters").is_none());
    // a grid's averaged parameters: one list in u, one in v
    let grid = solve(&json!({"op": "interpolate", "parametrization": "uniform", "points": [[[0, 0, 0], [0, 1, 0], [0, 2, 1]], [[1, 0, 0], [1, 1, 1], [1, 2, 0]]]})).unwrap();
    assert_eq!(
        grid.get("parameters").unwrap().to_json(),
        json!({"u": ["0", "1"], "v": ["0", "1/2", "1"]})
    );
    // uniform and centripetal
    let u = solve(&json!({"op": "interpolate", "basis": "bicubic", "parametrization": "uniform", "points": pts})).unwrap();
    assert!(
        u.remarks
            .iter()
            .any(|r| r.to_string().contains("0, 1/4, 1/2, 3/4, 1")),
        "{:?}",
        u.remarks
    );
    // centripetal: square roots of 5, 4, 5, 3 are in different fields: refused with the reason
    let e = solve(&json!({"op": "interpolate", "basis": "bezier", "parametrization": "centripetal", "points": pts})).unwrap_err();
    assert!(e.to_string().contains("√"), "{e}");
    // chord lengths 1, 4, 9 (collinear points): centripetal steps 1, 2, 3
    let c = solve(&json!({"op": "interpolate", "basis": "bezier", "parametrization": "centripetal", "points": [[0, 0], [1, 0], [5, 0], [14, 0]]})).unwrap();
    assert!(
        c.remarks
            .iter()
            .any(|r| r.to_string().contains("0, 1/6, 1/2, 1")),
        "{:?}",
        c.remarks
    );
    // chord lengths √2 and 2√2: one field, rational ratio
    let c = solve(&json!({"op": "approximate", "degree": 1, "parametrization": "chord_length", "points": [[0, 0], [1, 1], [3, 3]]})).unwrap();
    assert_eq!(
        c.get("parameters").unwrap().to_json(),
        json!(["0", "1/3", "1"])
    );
    assert_eq!(
        c.get("curve").unwrap().to_json(),
        json!({"bezier": [["0", "0"], ["3", "3"]]})
    );
    // lengths 1 and √2: no common field
    let e = solve(&json!({"op": "approximate", "degree": 1, "parametrization": "chord_length", "points": [[0, 0], [1, 0], [2, 1]]})).unwrap_err();
    assert!(e.to_string().contains("no quadratic field"), "{e}");
}

#[test]
fn clamped_cubic_splines_and_bspline_least_squares() {
    // the parabola y = x² through x = 0, 1, 2 with its end derivatives (1, 0), (1, 4): the
    // clamped cubic spline reproduces it
    let a = solve(&json!({"op": "interpolate", "basis": "bicubic", "end": "clamped", "tangents": [[1, 0], [1, 4]], "params": [0, 1, 2], "points": [[0, 0], [1, 1], [2, 4]]})).unwrap();
    let curve = a.get("curve").unwrap().to_json();
    assert_eq!(
        points_of("curve", &curve, json!(["1/2", "3/2"])),
        vec![
            Point::new(vec![Number::from_ratio(1, 2), Number::from_ratio(1, 4)]),
            Point::new(vec![Number::from_ratio(3, 2), Number::from_ratio(9, 4)]),
        ]
    );
    // B-spline least squares with the knots {0, 0, 1, 2, 2} through four points: the doc
    // example of cagd-fit, (0, 0), (5/4, 4/3), (7/4, 4/3), (3, 0)
    let a = solve(&json!({"op": "approximate", "degree": 2, "knots": [0, 0, 1, 2, 2], "params": [0, "1/2", "3/2", 2], "points": [[0, 0], [1, 1], [2, 1], [3, 0]]})).unwrap();
    assert_eq!(
        a.get("curve").unwrap().to_json()["bspline"],
        json!([["0", "0"], ["5/4", "4/3"], ["7/4", "4/3"], ["3", "0"]])
    );
}

#[test]
fn least_squares_knots_say_their_convention() {
    // The NURBS Book's {0, 0, 0, 1, 2, 2, 2} read in the notes' convention makes 6 control
    // points, not 4: the error says so and how to write it the notes' way
    let pts = json!([[0, 0], [1, 1], [2, 1], [3, 0], [4, 1]]);
    let e = solve(&json!({"op": "approximate", "degree": 2, "knots": [0, 0, 0, 1, 2, 2, 2], "params": [0, "1/2", 1, "3/2", 2], "points": pts})).unwrap_err();
    assert_eq!(e.field, "knots");
    assert_eq!(
        e.to_string(),
        "field `knots`: the 7 knots of degree 2 are read in the notes' convention (without end knots, \
         n + p - 1 knots for n control points): they make 6 control points, which need at least \
         6 data points, found 5; the vector repeats each end knot 3 times, as The NURBS Book \
         does (n + p + 1 knots, one more at each end): without its first and last knot it is \
         the notes' vector of 5 knots, for 4 control points"
    );
    let es = cagd_words::Message::phrase(&e.message, cagd_words::Lang::Es).text();
    assert!(es.contains("como el libro de Piegl y Tiller"), "{es}");
    // without the look of The NURBS Book: only the convention
    let e = solve(&json!({"op": "approximate", "degree": 2, "knots": [0, 0, 1, 2, 3, 3], "params": [0, 1, 2], "points": [[0, 0], [1, 1], [2, 1]]})).unwrap_err();
    assert_eq!(
        e.to_string(),
        "field `knots`: the 6 knots of degree 2 are read in the notes' convention (without end knots, \
         n + p - 1 knots for n control points): they make 5 control points, which need at least \
         5 data points, found 3"
    );
}

#[test]
fn bspline_surface_least_squares_reproduces_a_bspline_surface() {
    // data sampled from a biquadratic B-spline surface with the knots {0, 0, 1, 2, 2} x
    // {0, 0, 1, 1}: least squares on the same knots gives it back exactly
    let s = json!({"bspline": [[[0, 0, 0], [0, 1, 1], [0, 2, 0]], [[1, 0, 2], [1, 1, 3], [1, 2, 1]],
                               [[2, 0, 0], [2, 1, -1], [2, 2, 2]], [[3, 0, 1], [3, 1, 0], [3, 2, 0]]],
                   "degree": [2, 2], "knots": [[0, 0, 1, 2, 2], [0, 0, 1, 1]]});
    let mut params = Vec::new();
    for i in 0..=4 {
        for j in 0..=3 {
            params.push(json!([format!("{i}/2"), format!("{j}/3")]));
        }
    }
    let pts = points_of("surface", &s, json!(params));
    let points: Vec<Value> = pts
        .iter()
        .map(|p| {
            json!(p
                .coords()
                .iter()
                .map(|x| x.to_json_string())
                .collect::<Vec<_>>())
        })
        .collect();
    let a = solve(&json!({"op": "approximate", "degree": [2, 2], "knots_u": [0, 0, 1, 2, 2], "knots_v": [0, 0, 1, 1], "params": params, "points": points})).unwrap();
    // the mesh given back, as the strings of the answers
    let expected: Vec<Value> = s["bspline"]
        .as_array()
        .unwrap()
        .iter()
        .map(|row| {
            json!(row
                .as_array()
                .unwrap()
                .iter()
                .map(|p| json!(p
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|x| x.to_string())
                    .collect::<Vec<_>>()))
                .collect::<Vec<_>>())
        })
        .collect();
    assert_eq!(
        a.get("surface").unwrap().to_json()["bspline"],
        json!(expected)
    );
}

#[test]
fn a_grid_gets_chord_length_parameters_averaged_over_its_columns_and_rows() {
    // the columns along u: x = 0, 1, 3 in the first column and 0, 2, 3 in the second, so
    // chord-length parameters [0, 1/3, 1] and [0, 2/3, 1], averaged: [0, 1/2, 1]; along v the
    // rows are (y = 0, 4) with one step each: [0, 1]
    let points = json!([
        [[0, 0, 0], [0, 4, 0]],
        [[1, 0, 0], [2, 4, 0]],
        [[3, 0, 0], [3, 4, 0]]
    ]);
    let a =
        solve(&json!({"op": "interpolate", "points": points, "parametrization": "chord_length"}))
            .unwrap();
    assert!(
        a.remarks
            .iter()
            .any(|r| r.to_string().contains("u = 0, 1/2, 1; v = 0, 1")),
        "{:?}",
        a.remarks
    );
    // the patch passes through every point at the averaged parameters
    let s = a.get("surface").unwrap().to_json();
    for (k, u) in ["0", "1/2", "1"].iter().enumerate() {
        for (l, v) in ["0", "1"].iter().enumerate() {
            let p = eval("surface", &s, json!([[u, v]]));
            let expected: Vec<String> = points[k][l]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.to_string())
                .collect();
            assert_eq!(p, json!([expected]));
        }
    }
    // uniform: k/m and l/n; both parameters and a parametrization refused
    let a = solve(&json!({"op": "interpolate", "points": points, "parametrization": "uniform"}))
        .unwrap();
    assert!(a
        .remarks
        .iter()
        .any(|r| r.to_string().contains("u = 0, 1/2, 1; v = 0, 1")));
    let e = solve(&json!({"op": "interpolate", "points": points, "parametrization": "uniform", "u": [0, "1/2", 1], "v": [0, 1]})).unwrap_err().to_string();
    assert!(
        e.contains("either `u` and `v` or a `parametrization`"),
        "{e}"
    );
    // a column whose chords are in two fields: refused, naming the column
    let bad = json!([
        [[0, 0, 0], [0, 1, 0]],
        [[1, 1, 0], [1, 2, 0]],
        [[2, 1, 0], [3, 2, 0]]
    ]);
    let e = solve(&json!({"op": "interpolate", "points": bad, "parametrization": "chord_length"}))
        .unwrap_err()
        .to_string();
    assert!(e.contains("the parameters of column 0"), "{e}");
}
