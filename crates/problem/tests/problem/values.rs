//! A problem in letters with `"values"` is solved at the values: its answer (results, steps,
//! worked solution) is the answer of the problem with the numbers written in, every verdict
//! (developable, exact, an order of continuity) decided there; where the answer in letters,
//! decided for general values, differs, a remark says so.

use cagd_problem::{solve, Answer};
use proptest::prelude::*;
use serde_json::{json, Value};

/// The problem with every string holding the letter `k` (or `h`) written with `value` in its
/// place, and without `parameters` and `values`: the problem with the numbers written in.
fn written_in(problem: &Value, letter: &str, value: &str) -> Value {
    fn put(x: &Value, letter: &str, value: &str) -> Value {
        match x {
            Value::String(s) if s.contains(letter) => {
                Value::String(s.replace(letter, &format!("({value})")))
            }
            Value::Array(xs) => Value::Array(xs.iter().map(|x| put(x, letter, value)).collect()),
            Value::Object(m) => Value::Object(
                m.iter()
                    .filter(|(k, _)| *k != "parameters" && *k != "values")
                    .map(|(k, x)| {
                        let keep = k == "op" || k == "border";
                        (
                            k.clone(),
                            if keep {
                                x.clone()
                            } else {
                                put(x, letter, value)
                            },
                        )
                    })
                    .collect(),
            ),
            other => other.clone(),
        }
    }
    put(problem, letter, value)
}

/// The problem in the letter `letter` with `"values": {letter: value}`.
fn with_value(problem: &Value, letter: &str, value: &str) -> Value {
    let mut p = problem.clone();
    p["parameters"] = json!([letter]);
    p["values"] = json!({ letter: value });
    p
}

/// The remarks an answer has besides those on the values (the values put in, the verdicts
/// they change).
fn own_remarks(a: &Answer) -> Vec<&cagd_problem::Message> {
    a.remarks
        .iter()
        .filter(|r| {
            !r.to_string().starts_with("the problem solved with ")
                && !r.to_string().starts_with("for general values of ")
        })
        .collect()
}

/// The remarks on the verdicts the values change.
fn changed(a: &Answer) -> Vec<&cagd_problem::Message> {
    a.remarks
        .iter()
        .filter(|r| r.to_string().starts_with("for general values of "))
        .collect()
}

/// Solves `problem` at `letter = value` and with the number written in, and asserts the two
/// answers equal: results, named steps, worked solution and the remarks of the operation; the
/// answer at the values says they were put in. Returns it.
fn equals_written_in(problem: &Value, letter: &str, value: &str) -> Answer {
    let special = solve(&with_value(problem, letter, value))
        .unwrap_or_else(|e| panic!("{problem} at {letter} = {value}: {e}"));
    let numeric = solve(&written_in(problem, letter, value)).unwrap();
    assert_eq!(
        special.result, numeric.result,
        "{problem} at {letter} = {value}"
    );
    assert_eq!(
        special.steps, numeric.steps,
        "{problem} at {letter} = {value}"
    );
    assert_eq!(
        special.derivation, numeric.derivation,
        "{problem} at {letter} = {value}"
    );
    assert_eq!(own_remarks(&special), own_remarks(&numeric), "{problem}");
    assert!(
        special
            .remarks
            .iter()
            .any(|r| *r == format!("the problem solved with {letter} = {value} put in").as_str()),
        "{:?}",
        special.remarks
    );
    special
}

/// The bilinear patch through (0, 0, 0), (0, 1, 0), (1, 0, 0), (1, 1, k): planar (and
/// developable, of zero Gaussian curvature) only at k = 0.
fn patch() -> Value {
    json!({"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, "k"]]]})
}

/// One problem of each operation whose verdict an equality in letters decides, the letter, a
/// value that changes the verdict, the remarks that must say so, and a value that does not.
fn cases() -> Vec<(
    Value,
    &'static str,
    &'static str,
    Vec<&'static str>,
    &'static str,
)> {
    vec![
        (
            json!({"op": "developable", "surface": patch()}),
            "k",
            "0",
            vec![
                "for general values of k, `first_cell_planar` is no; at k = 0 it is yes",
                "for general values of k, `last_cell_planar` is no; at k = 0 it is yes",
                "for general values of k, `developable` is no; at k = 0 it is yes",
            ],
            "5",
        ),
        (
            json!({"op": "reduce_degree", "curve": {"bezier": [[0, 0], [1, "k"], [2, 0]]}, "by": 1}),
            "k",
            "0",
            vec!["for general values of k, `exact` is no; at k = 0 it is yes"],
            "3",
        ),
        (
            json!({"op": "gaussian_curvature", "surface": patch()}),
            "k",
            "0",
            vec!["for general values of k, `developable` is no; at k = 0 it is yes"],
            "2",
        ),
        (
            // a straight line at constant speed when k = 0
            json!({"op": "curve_continuity", "first": {"bezier": [[0, 0], [1, 0], [2, 0]]}, "second": {"bezier": [[2, 0], [3, "k"], [4, 0]]}}),
            "k",
            "0",
            vec![
                "for general values of k, `order` is 0; at k = 0 it is infinite",
                "for general values of k, `geometric` is 0; at k = 0 it is 2",
            ],
            "1",
        ),
        (
            // c'·c' = 16 k² t² - 16 k² t + 4 k² + 4, a square only at k = 0
            json!({"op": "arc_length", "curve": {"bezier": [[0, 0], [1, "k"], [2, 0]]}}),
            "k",
            "0",
            vec!["for general values of k, `exact` is no; at k = 0 it is yes"],
            "1",
        ),
        (
            // the join of docs/format.md, C^1 at h = -1
            json!({"op": "continuity", "first": {"bezier": [[[-1, -2, 0], [0, -1, 1], [1, -2, 0]], [[-1, -1, 0], [0, 0, 1], [1, -1, 0]], [[-1, 0, 0], [0, 0, 0], [1, 0, 0]]]}, "second": {"bezier": [[[-1, 0, 0], [0, 0, 0], [1, 0, 0]], [[-1, 1, 0], [0, 0, "h"], [1, 1, 0]], [[-1, 2, 0], [0, 1, -2], [1, 2, 0]]]}, "border": "u"}),
            "h",
            "-1",
            vec!["for general values of h, `order` is 0; at h = -1 it is 1"],
            "3",
        ),
    ]
}

#[test]
fn a_special_value_decides_the_verdict_at_that_value() {
    for (problem, letter, value, remarks, _) in cases() {
        let special = equals_written_in(&problem, letter, value);
        assert_eq!(changed(&special), remarks, "{problem}");
    }
}

#[test]
fn a_value_that_changes_no_verdict_adds_no_remark() {
    for (problem, letter, _, _, value) in cases() {
        let special = equals_written_in(&problem, letter, value);
        assert!(
            changed(&special).is_empty(),
            "{problem}: {:?}",
            special.remarks
        );
    }
}

#[test]
fn the_condition_that_fails_is_written_at_the_value() {
    let (problem, ..) = cases().remove(5);
    let special = solve(&with_value(&problem, "h", "3")).unwrap();
    let Some(cagd_problem::Exact::Sentence(fails)) = special.get("fails") else {
        panic!("{:?}", special.result)
    };
    let fails = fails.to_string();
    assert!(fails.ends_with("= (0, 0, 3)"), "{fails}");
    assert!(!fails.contains('h'), "{fails}");
}

#[test]
fn a_sign_in_letters_is_decided_at_the_values() {
    // in letters the interval [a, b] needs a sign; at the values it has one
    let p = json!({"op": "restrict", "curve": {"bezier": [[0], [1], [2]]}, "t": ["a", "b"], "parameters": ["a", "b"], "values": {"a": 0, "b": "1/2"}});
    let answer = solve(&p).unwrap();
    let numeric =
        solve(&json!({"op": "restrict", "curve": {"bezier": [[0], [1], [2]]}, "t": [0, "1/2"]}))
            .unwrap();
    assert_eq!(answer.result, numeric.result);
    // a value in letters keeps the problem in letters (b - a = 1 there, a sign known)
    let p = json!({"op": "restrict", "curve": {"bezier": [[0], [1], [2]]}, "t": ["a", "b"], "parameters": ["a", "b"], "values": {"b": "a + 1"}});
    assert!(solve(&p).is_err());
}

/// A small rational.
fn value() -> impl Strategy<Value = String> {
    prop_oneof![
        (-2i64..3).prop_map(|p| p.to_string()),
        (-3i64..4, 1i64..4).prop_map(|(p, q)| format!("{p}/{q}")),
    ]
}

/// A small integer.
fn small() -> std::ops::Range<i64> {
    -2i64..3
}

/// The numbers `xs` (texts) with the one at `at` replaced by the letter k, and the number it
/// replaced: the special value where the construction's property (planar, C^1, exact) holds.
fn with_k(xs: Vec<String>, at: usize) -> (Vec<Value>, String) {
    let at = at % xs.len();
    let special = xs[at].clone();
    let out = xs
        .into_iter()
        .enumerate()
        .map(|(i, x)| if i == at { json!("k") } else { json!(x) })
        .collect();
    (out, special)
}

/// Points of `dim` coordinates from a flat list.
fn points(xs: &[Value], dim: usize) -> Vec<Value> {
    xs.chunks(dim).map(|p| json!(p)).collect()
}

/// A problem of one of six operations in small numbers built to have its property (a planar
/// patch, a C^1 join, a curve of lower degree, one at constant speed), one of its numbers
/// replaced by the letter k, and the number k replaced: at that value the property holds, at
/// most others it fails.
fn problem() -> impl Strategy<Value = (Value, String)> {
    // the plane z = a x + b y + c over the unit square
    let planar = (small(), small(), small(), 0usize..12).prop_map(|(a, b, c, at)| {
        let corner = |x: i64, y: i64| [x, y, a * x + b * y + c];
        let xs = [corner(0, 0), corner(0, 1), corner(1, 0), corner(1, 1)]
            .concat()
            .iter()
            .map(i64::to_string)
            .collect();
        let (xs, special) = with_k(xs, at);
        let p = points(&xs, 3);
        (json!([[p[0], p[1]], [p[2], p[3]]]), special)
    });
    let developable = planar
        .clone()
        .prop_map(|(m, k)| (json!({"op": "developable", "surface": {"bezier": m}}), k));
    let gaussian = planar.prop_map(|(m, k)| {
        (
            json!({"op": "gaussian_curvature", "surface": {"bezier": m}}),
            k,
        )
    });
    // a patch of bidegree (1, 2) and its mirror image across the common border u: C^1
    let continuity = (proptest::collection::vec(small(), 6), 0usize..9).prop_map(|(yz, at)| {
        let first_row: Vec<[i64; 3]> = (0..3)
            .map(|j| [j - 1, yz[2 * j as usize] - 2, yz[2 * j as usize + 1]])
            .collect();
        let border: Vec<[i64; 3]> = (0..3).map(|j| [j - 1, 0, 0]).collect();
        let mirror: Vec<String> = first_row
            .iter()
            .zip(&border)
            .flat_map(|(p, q)| (0..3).map(move |i| (2 * q[i] - p[i]).to_string()))
            .collect();
        let (mirror, special) = with_k(mirror, at);
        let problem = json!({"op": "continuity",
            "first": {"bezier": [first_row, border]},
            "second": {"bezier": [json!(border), json!(points(&mirror, 3))]},
            "border": "u"});
        (problem, special)
    });
    // a quadratic elevated to degree 3: reduced exactly
    let reduce = (proptest::collection::vec(small(), 6), 0usize..8).prop_map(|(q, at)| {
        let third = |a: i64, b: i64| format!("{}/3", a + 2 * b);
        let xs = vec![
            q[0].to_string(),
            q[1].to_string(),
            third(q[0], q[2]),
            third(q[1], q[3]),
            third(q[4], q[2]),
            third(q[5], q[3]),
            q[4].to_string(),
            q[5].to_string(),
        ];
        let (xs, special) = with_k(xs, at);
        (
            json!({"op": "reduce_degree", "curve": {"bezier": points(&xs, 2)}, "by": 1}),
            special,
        )
    });
    // equally spaced points on a line: constant speed, the length exact
    let length = (small(), small(), 1i64..3, small(), 0usize..6).prop_map(|(x, y, dx, dy, at)| {
        let xs = (0..3)
            .flat_map(|i| [(x + i * dx).to_string(), (y + i * dy).to_string()])
            .collect();
        let (xs, special) = with_k(xs, at);
        (
            json!({"op": "arc_length", "curve": {"bezier": points(&xs, 2)}}),
            special,
        )
    });
    // a quadratic, and one that starts where it ends, its first point mirrored: C^1
    let join = (proptest::collection::vec(small(), 8), 0usize..4).prop_map(|(c, at)| {
        let a: Vec<String> = c[..6].iter().map(i64::to_string).collect();
        let mirror = |i: usize| (2 * c[4 + i] - c[2 + i]).to_string();
        let (rest, special) = with_k(vec![mirror(0), mirror(1), c[6].to_string(), c[7].to_string()], at);
        let first = points(&a.iter().map(|x| json!(x)).collect::<Vec<_>>(), 2);
        let mut second = vec![first[2].clone()];
        second.extend(points(&rest, 2));
        (json!({"op": "curve_continuity", "first": {"bezier": first}, "second": {"bezier": second}}), special)
    });
    prop_oneof![developable, gaussian, continuity, reduce, length, join]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 48, ..ProptestConfig::default() })]

    /// The answer at the values equals the answer of the problem with the numbers written
    /// in, whatever the values decide: results, steps, worked solution, remarks. The value is
    /// the special one (where the construction's property holds) or a random small rational.
    #[test]
    fn the_answer_at_the_values_is_the_answer_with_the_numbers_written_in(
        (p, k) in problem().prop_flat_map(|(p, special)| (Just(p), prop_oneof![Just(special), value()]))
    ) {
        let special = solve(&with_value(&p, "k", &k));
        let numeric = solve(&written_in(&p, "k", &k));
        match (special, numeric) {
            (Ok(s), Ok(n)) => {
                prop_assert_eq!(&s.result, &n.result, "{} at k = {}", p, k);
                prop_assert_eq!(&s.steps, &n.steps, "{} at k = {}", p, k);
                prop_assert_eq!(&s.derivation, &n.derivation, "{} at k = {}", p, k);
                prop_assert_eq!(own_remarks(&s), own_remarks(&n), "{} at k = {}", p, k);
            }
            (Err(s), Err(n)) => prop_assert_eq!(s.to_string(), n.to_string()),
            (s, n) => prop_assert!(false, "{} at k = {}: {:?} but {:?}", p, k, s.err(), n.err()),
        }
    }
}
