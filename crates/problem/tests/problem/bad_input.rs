//! Each class of bad input gets a one-line error naming the field (and, in a batch, the
//! problem's index), never a panic.

use cagd_problem::{solve, solve_batch};
use serde_json::{json, Value};

fn err(p: Value) -> String {
    let e = solve(&p).unwrap_err().to_string();
    assert!(!e.contains('\n'), "not one line: {e}");
    e
}

fn quad() -> Value {
    json!([[0, 0, 0], [1, 0, 1], [2, 0, 0]])
}

/// The operations as errors list them.
fn ops() -> String {
    cagd_problem::operations()
        .iter()
        .map(|n| format!("`{n}`"))
        .collect::<Vec<_>>()
        .join(", ")
}

#[test]
fn not_a_problem() {
    assert_eq!(
        err(json!([1, 2])),
        "expected a problem object {\"op\": ...}, found a list of 2"
    );
    assert_eq!(
        err(json!({"curve": {}})),
        format!("field `op`: missing: name the operation, one of {}", ops())
    );
    assert_eq!(
        err(json!({"op": "rotate"})),
        format!(
            "field `op`: unknown operation \"rotate\"; the operations are: {}",
            ops()
        )
    );
    assert_eq!(
        err(json!({"op": 3})),
        "field `op`: expected a string, found the number 3"
    );
}

#[test]
fn missing_fields() {
    assert_eq!(
        err(json!({"op": "evaluate", "curve": {"bezier": quad()}})),
        "field `params`: missing (this operation needs it)"
    );
    assert_eq!(
        err(
            json!({"op": "evaluate", "curve": {"bspline": quad(), "knots": [0, 1]}, "params": [0]})
        ),
        "field `curve.degree`: missing (this operation needs it)"
    );
    assert_eq!(
        err(
            json!({"op": "coons", "c1": {"bezier": quad()}, "c2": {"bezier": quad()}, "d1": {"bezier": quad()}})
        ),
        "field `d2`: missing (this operation needs it)"
    );
}

#[test]
fn wrong_shapes() {
    assert_eq!(
        err(json!({"op": "closed_form", "surface": {"bezier": [1, 2, 3]}})),
        "field `surface.bezier[0]`: expected a list, found the number 1"
    );
    assert_eq!(
        err(json!({"op": "closed_form", "surface": {"bezier": [[[0, 0], [1, 0]], [[0, 1]]]}})),
        "field `surface.bezier[1]`: row 1 has 1 points but row 0 has 2: a mesh needs rows of equal length"
    );
    assert_eq!(
        err(json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 0, 0]]}, "params": [0]})),
        "field `curve.bezier[1]`: this point has 3 coordinates but the first has 2"
    );
    assert_eq!(
        err(json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 1]]}, "params": [0.5]})),
        "field `params[0]`: the number 0.5 has a fraction part; write it as a string (\"0.5\") so it is read exactly"
    );
    assert_eq!(
        err(json!({"op": "evaluate", "surface": {"bezier": [[[0, 0, 0]]]}, "params": [[0]]})),
        "field `params[0]`: expected two numbers [a, b], found 1"
    );
    assert_eq!(
        err(
            json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 1]], "weights": [1]}, "params": [0]})
        ),
        "field `curve.weights`: 1 weights for 2 control points"
    );
    assert_eq!(
        err(json!({"op": "closed_form", "curve": {"polygon": []}})),
        "field `curve.polygon`: unknown key: `curve` takes `bezier`, `bspline`, `degree`, `knots`, `weights`, `homogeneous`, `expr`, `generic`, `dim`"
    );
    assert_eq!(
        err(json!({"op": "closed_form", "curve": {}})),
        "field `curve`: expected a curve: {\"bezier\": [...]}, {\"bspline\": [...], \"degree\": p, \"knots\": [...]} or {\"expr\": \"(u, 0, u^2)\"}"
    );
    assert_eq!(
        err(json!({"op": "elevate", "curve": {"bezier": quad()}, "by": -1})),
        "field `by`: expected a non-negative integer, found the number -1"
    );
}

/// A misspelled key is refused, naming the nearest valid one (it used to be ignored, and the
/// default ran).
#[test]
fn unknown_keys_are_refused_with_the_nearest_valid_key() {
    let c = || json!({"bezier": quad()});
    assert_eq!(
        err(json!({"op": "coons", "c1": c(), "c2": c(), "d1": c(), "d2": c(), "blned": "cubic"})),
        "field `blned`: unknown key: did you mean `blend`? `coons` takes `c1`, `c2`, `d1`, `d2`, `blend`"
    );
    assert_eq!(
        err(json!({"op": "evaluate", "curve": {"bezier": quad(), "wieghts": [1, 1, 1]}, "params": [0]})),
        "field `curve.wieghts`: unknown key: did you mean `weights`? `curve` takes `bezier`, `bspline`, `degree`, `knots`, `weights`, `homogeneous`, `expr`, `generic`, `dim`"
    );
    assert_eq!(
        err(json!({"op": "evalute", "curve": {"bezier": quad()}})),
        format!("field `op`: unknown operation \"evalute\" (did you mean \"evaluate\"?); the operations are: {}", ops())
    );
    // the fixture's own fields are a block of their own, also checked
    assert_eq!(
        err(json!({"op": "circle", "titel": "a circle"})),
        "field `titel`: unknown key: did you mean `title`? `circle` takes `radius`, `arcs`, `center`, `interval`, `sweep`, `start`"
    );
}

/// A scalar expression with a root reads in Q(√2) (it used to be refused as "not a rational
/// number": the field was chosen by looking inside tuples only).
#[test]
fn a_root_in_a_scalar_expression_chooses_the_field() {
    let a = solve(&json!({"op": "graph", "f": "3/2*x*y^3 - sqrt2*y", "degree": [1, 3]})).unwrap();
    assert_eq!(a.field, cagd_problem::NumberField::Quadratic(2));
    assert_eq!(
        a.get("closed_form").unwrap().to_json(),
        json!("(u, v, 3/2*u*v^3 - sqrt2*v)")
    );
}

#[test]
fn curves_that_do_not_meet() {
    let e = err(json!({"op": "coons",
        "c1": {"bezier": [[0, 0, 0], [1, 0, 1], [2, 0, 0]]},
        "c2": {"bezier": [[0, 2, 0], [1, 2, 1], [2, 2, 0]]},
        "d1": {"bezier": [[0, 0, 1], [0, 1, 0], [0, 2, 0]]},
        "d2": {"bezier": [[2, 0, 0], [2, 1, 0], [2, 2, 0]]}}));
    assert!(
        e.starts_with("field `d1`: curves c1 and d1 do not meet at corner"),
        "{e}"
    );
    let t = err(json!({"op": "translational",
        "c": {"bezier": [[0, 0, 0], [1, 0, 1]]},
        "d": {"bezier": [[0, 0, 1], [0, 1, 1]]}}));
    assert!(t.starts_with("field `d`: the curves do not meet"), "{t}");
}

#[test]
fn zero_weights() {
    // a rational Bézier curve's zero weight is a control vector: taken where the operation
    // runs on the homogeneous form, refused naming it where points are needed
    assert_eq!(
        err(json!({"op": "arc_length", "curve": {"bezier": quad(), "weights": [1, 0, 1]}})),
        "field `curve`: weight 1 is zero: that entry is a control vector, not a point, and this needs every control point to be a point"
    );
    assert_eq!(
        err(
            json!({"op": "evaluate", "curve": {"bezier": quad(), "weights": [0, 0, 0]}, "params": [0]})
        ),
        "field `curve`: every weight is zero: the rational curve has no finite point"
    );
    assert_eq!(
        err(json!({"op": "evaluate", "curve": {"bezier": [[1, 0], [0, 0]], "weights": [0, 1]}, "params": [0]})),
        "field `params[0]`: the denominator w(t) of the rational curve vanishes at t = 0: c(t) is a point at infinity"
    );
    assert_eq!(
        err(
            json!({"op": "evaluate", "curve": {"bspline": quad(), "degree": 2, "knots": [0, 0, 1, 1], "weights": [1, 0, 1]}, "params": [0]})
        ),
        "field `curve`: weight 1 is zero: a control vector (weight zero) is taken in a rational Bézier curve, not in a NURBS curve"
    );
    assert_eq!(
        err(
            json!({"op": "closed_form", "surface": {"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], "weights": [[1, 1], [0, 1]]}})
        ),
        "field `surface`: weight w_1,0 is zero: weights must be nonzero"
    );
}

#[test]
fn singular_interpolation() {
    assert_eq!(
        err(json!({"op": "interpolate", "points": [[0, 0], [1, 1], [2, 0]], "params": [0, "1/2", "2/4"]})),
        "field `params[2]`: the parameter 1/2 repeats entry 1: the interpolation system is singular (the parameters must be distinct)"
    );
    assert_eq!(
        err(json!({"op": "interpolate", "u": [0, 0], "v": [0, 1], "points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]})),
        "field `u[1]`: the parameter 0 repeats entry 0: the interpolation system is singular (the parameters must be distinct)"
    );
    // least squares with too few distinct parameters
    let e = err(
        json!({"op": "approximate", "degree": [1, 1], "points": [[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 1]], "params": [[0, 0], [0, 0], [0, 0], [0, 0]]}),
    );
    assert_eq!(
        e,
        "field `params`: a patch of degree 1 in u needs at least 2 distinct values of u among the parameters (u_k, v_k), found 1: the columns of the collocation matrix B are linearly dependent whatever the data"
    );
}

#[test]
fn decreasing_knots() {
    assert_eq!(
        err(
            json!({"op": "evaluate", "curve": {"bspline": [[0, 0], [1, 2], [3, 2], [4, 0]], "degree": 2, "knots": [0, 0, 2, 1, 2]}, "params": [0]})
        ),
        "field `curve`: knot vector decreases at index 3: 2 > 1"
    );
}

#[test]
fn bad_numbers_and_expressions() {
    assert_eq!(
        err(json!({"op": "evaluate", "curve": {"bezier": [[0, "1/0"], [1, 1]]}, "params": [0]})),
        "field `curve.bezier[0][1]`: \"1/0\": at column 2: division by zero"
    );
    assert_eq!(
        err(json!({"op": "evaluate", "curve": {"bezier": [[0, "sqrt2"], [1, "sqrt3"]]}, "params": [0]})),
        "field `curve.bezier[1][1]`: this number needs √3, but curve.bezier[0][1] needs √2: a problem runs in one field a + b√d"
    );
    assert_eq!(
        err(json!({"op": "graph", "f": "x*(y"})),
        "field `f`: \"x*(y\": at column 5: expected ')' (unbalanced parenthesis), found the end of the input"
    );
    assert_eq!(
        err(json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 1]]}, "params": ["2"]})),
        "field `params[0]`: parameter t = 2 is outside the domain [0, 1]"
    );
}

#[test]
fn a_batch_names_the_index_and_answers_the_rest() {
    let good = json!({"op": "circle", "arcs": 4});
    let batch = json!([good, {"op": "evaluate"}, good, "nonsense"]);
    let answers = solve_batch(&batch);
    assert_eq!(answers.len(), 4);
    assert!(answers[0].is_ok() && answers[2].is_ok());
    assert_eq!(answers[0], answers[2]);
    assert_eq!(
        answers[1].as_ref().unwrap_err().to_string(),
        "problem 2: field `surface`: missing (this operation needs it)"
    );
    assert_eq!(
        answers[3].as_ref().unwrap_err().to_string(),
        "problem 4: expected a problem object {\"op\": ...}, found the string \"nonsense\""
    );
}

/// An `expected` that checks nothing is a mismatch that names the results to check, never a
/// silent "correct".
#[test]
fn an_expected_that_is_not_an_answer_is_refused() {
    let circle = |expected: Value| {
        let v = cagd_problem::check(&json!({"op": "circle", "arcs": 4, "expected": expected}));
        assert!(v.answer.is_ok());
        assert!(v.checked);
        v.mismatches
    };
    assert_eq!(
        circle(Value::Null),
        ["expected: an object of results by name (`circle` gives `curve`), found null"]
    );
    assert_eq!(
        circle(json!({})),
        ["expected: an empty object checks nothing; name the results to check (`circle` gives `curve`)"]
    );
    assert_eq!(
        circle(json!("garbage")),
        ["expected: an object of results by name (`circle` gives `curve`), found the string \"garbage\""]
    );
    assert_eq!(circle(json!([])).len(), 1);
    assert_eq!(circle(json!(42)).len(), 1);
    assert_eq!(
        circle(json!({"surface": "1"})),
        ["`surface`: not a result of this problem (`circle` gives `curve`)"]
    );
    // without `expected` there is nothing to compare, and no verdict
    let v = cagd_problem::check(&json!({"op": "circle", "arcs": 4}));
    assert!(!v.checked && v.mismatches.is_empty());
}

#[test]
fn a_quadrant_is_0_to_3_and_only_for_one_arc() {
    let profile = json!({"bezier": [[1, 0, 0], [1, 0, 1]]});
    assert!(
        solve(&json!({"op": "revolution", "curve": profile, "arcs": 1, "quadrant": 3})).is_ok()
    );
    assert_eq!(
        err(json!({"op": "revolution", "curve": profile, "arcs": 1, "quadrant": 9})),
        "field `quadrant`: 9 is not a quadrant: 0 to 3, counterclockwise from the x axis"
    );
    assert_eq!(
        err(json!({"op": "revolution", "curve": profile, "arcs": 4, "quadrant": 1})),
        "field `quadrant`: a quadrant is for `arcs` = 1; 4 arcs make the full turn"
    );
}

/// The weights given are nonzero; a zero weight of the restriction is named as its own.
#[test]
fn a_restriction_through_a_zero_of_the_weight_says_so() {
    let p = json!({"op": "restrict", "u": [0, 1], "v": ["1/2", 1], "surface": {
        "bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]], "weights": [[1, -1], [1, -1]]}});
    assert_eq!(
        err(p),
        "field `surface`: the restricted patch's weight w_0,0 is zero: the weight function of the patch vanishes at that corner of [0, 1] x [1/2, 1], so the restriction has a point at infinity there"
    );
}

/// Markdown passes HTML through: a title is shown, never run.
#[test]
fn markdown_keys_escape_html() {
    let v = cagd_problem::check(
        &json!({"op": "circle", "arcs": 4, "title": "<script>alert(1)</script> & co"}),
    );
    let md = cagd_keys::example_markdown(&v, cagd_keys::Lang::En);
    assert!(
        md.contains("&lt;script&gt;alert(1)&lt;/script&gt; &amp; co"),
        "{md}"
    );
    assert!(!md.contains("<script>"));
}
