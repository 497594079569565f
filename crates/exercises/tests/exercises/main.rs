//! The problem sets of `cagd generate`: every topic solvable, deterministic, with small
//! numbers in the problems and friendly exact answers.

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

mod exam;
mod schema;
mod variety;

use cagd_exercises::{
    generate, generate_in, problem_set_files, problems_json, topic, topics, ExerciseError, Lang,
    MAX_ANSWER_DENOMINATOR, MAX_ANSWER_INTEGER,
};
use cagd_scalar::{parse_number, parse_rational, BigInt, Print};
use serde_json::{json, Value};

/// Operations not yet wired into `cagd_problem::solve` in this build: their problems are
/// generated but cannot be checked. Empty since every operation of the topics is wired;
/// add a topic here only while its operation is pending in cagd-problem.
const PENDING: &[&str] = &[];

const SEEDS: [u64; 3] = [0, 1, 20240601];
const COUNT: usize = 10;

/// The largest numerator and denominator allowed in a problem.
const MAX_PROBLEM_NUMERATOR: u64 = 9;
const MAX_PROBLEM_DENOMINATOR: u64 = 4;

fn set(topic: &str, count: usize, seed: u64) -> Vec<Value> {
    generate(topic, count, seed).unwrap_or_else(|e| panic!("{topic}, seed {seed}: {e}"))
}

// ---- Numbers: an independent reading of what a problem and an answer show ----

/// Every run of digits in `s`, with whether it follows a `/` (a denominator).
fn digit_runs(s: &str) -> Vec<(u64, bool)> {
    let bytes = s.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        if bytes[i].is_ascii_digit() {
            let start = i;
            while i < bytes.len() && bytes[i].is_ascii_digit() {
                i += 1;
            }
            let n: u64 = s[start..i].parse().unwrap_or(u64::MAX);
            let before = s[..start].trim_end_matches([' ', '(']);
            out.push((n, before.ends_with('/')));
        } else {
            i += 1;
        }
    }
    out
}

/// The largest denominator and numerator of every number in a JSON value.
fn sizes(v: &Value) -> (u64, u64) {
    let mut den = 1;
    let mut int = 0;
    fn walk(v: &Value, den: &mut u64, int: &mut u64) {
        match v {
            Value::Number(n) => *int = (*int).max(n.as_i64().unwrap().unsigned_abs()),
            Value::String(s) => {
                for (n, is_den) in digit_runs(s) {
                    if is_den {
                        *den = (*den).max(n);
                    } else {
                        *int = (*int).max(n);
                    }
                }
            }
            Value::Array(xs) => xs.iter().for_each(|x| walk(x, den, int)),
            Value::Object(m) => m.values().for_each(|x| walk(x, den, int)),
            _ => {}
        }
    }
    walk(v, &mut den, &mut int);
    (den, int)
}

/// Checks every number of a problem: JSON integers and number strings read with the
/// engine's own grammar (cagd-scalar), expressions by their digits.
fn assert_small_numbers(p: &Value) {
    fn walk(v: &Value, key: &str, p: &Value) {
        match v {
            // The angle of a partial turn is a setting in degrees, not data.
            Value::Number(_) if key == "sweep" => {}
            Value::Number(n) => {
                let x = n
                    .as_i64()
                    .unwrap_or_else(|| panic!("{key}: {n} is not an integer in {p}"));
                assert!(
                    x.unsigned_abs() <= MAX_PROBLEM_NUMERATOR,
                    "{key}: {x} in {p}"
                );
            }
            Value::String(s) if key == "f" || key == "expr" => {
                for (n, is_den) in digit_runs(s) {
                    assert!(!is_den, "{key}: a fraction in {s}");
                    assert!(n <= MAX_PROBLEM_NUMERATOR, "{key}: {n} in {s}");
                }
            }
            Value::String(s) if ["basis", "end", "border", "blend"].contains(&key) => {}
            Value::String(s) => {
                if s == "sqrt2/2" {
                    assert_eq!(parse_number(s).unwrap().to_text(), "√2/2");
                    return;
                }
                let q = parse_rational(s).unwrap_or_else(|e| panic!("{key}: {s:?}: {e} in {p}"));
                assert!(
                    q.numer().magnitude()
                        <= &BigInt::from(MAX_PROBLEM_NUMERATOR).magnitude().clone(),
                    "{key}: {s} in {p}"
                );
                assert!(
                    q.denom() <= &BigInt::from(MAX_PROBLEM_DENOMINATOR),
                    "{key}: {s} in {p}"
                );
                assert!(
                    q.denom() > &BigInt::from(1),
                    "{key}: the integer {s} written as a string"
                );
            }
            Value::Array(xs) => xs.iter().for_each(|x| walk(x, key, p)),
            Value::Object(m) => m.iter().for_each(|(k, x)| walk(x, k, p)),
            _ => panic!("{key}: unexpected {v} in {p}"),
        }
    }
    for (k, v) in p.as_object().unwrap() {
        if !["name", "title", "source", "op"].contains(&k.as_str()) {
            walk(v, k, p);
        }
    }
}

// ---- Every topic ----

#[test]
fn every_topic_generates_count_problems_that_solve() {
    assert_eq!(topics().len(), 15);
    for t in topics() {
        for seed in SEEDS {
            let problems = set(t.name, COUNT, seed);
            assert_eq!(problems.len(), COUNT, "{}", t.name);
            for (i, p) in problems.iter().enumerate() {
                assert_eq!(p["name"], format!("{}-{}", t.name, i + 1));
                assert_eq!(p["op"], t.op);
                assert_eq!(p["source"], t.source);
                assert!(p["title"].as_str().is_some_and(|s| s.len() > 20), "{p}");
                assert!(p.get("expected").is_none());
                match cagd_problem::solve(p) {
                    Ok(a) => assert_eq!(a.op, t.op),
                    Err(e) if PENDING.contains(&t.name) => {
                        assert!(e.to_string().contains("not available yet"), "{e}")
                    }
                    Err(e) => panic!("{} seed {seed}: {e}\n{p}", t.name),
                }
            }
        }
    }
}

#[test]
fn pending_list_only_names_topics() {
    for name in PENDING {
        assert!(topic(name).is_ok(), "{name}");
    }
}

#[test]
fn problems_use_small_numbers() {
    for t in topics() {
        for seed in SEEDS {
            for p in set(t.name, COUNT, seed) {
                assert_small_numbers(&p);
                let mut data = p.clone();
                for k in ["name", "title", "source", "sweep"] {
                    data.as_object_mut().unwrap().remove(k);
                }
                let (den, int) = sizes(&data);
                assert!(den <= MAX_PROBLEM_DENOMINATOR && int <= 9, "{p}");
            }
        }
    }
}

/// The promise of `--help`: numbers pleasant by hand, denominators at most 36 and integers
/// at most 100 in an answer and its steps.
const _: () = assert!(MAX_ANSWER_DENOMINATOR <= 36 && MAX_ANSWER_INTEGER <= 100);

#[test]
fn answers_stay_friendly() {
    for t in topics().iter().filter(|t| !PENDING.contains(&t.name)) {
        let mut largest = 1;
        for seed in SEEDS {
            for p in set(t.name, COUNT, seed) {
                let a = cagd_problem::solve(&p).unwrap().to_json(true);
                let (den, int) = sizes(&a);
                assert!(
                    den <= MAX_ANSWER_DENOMINATOR,
                    "{}: denominator {den} in {a}",
                    t.name
                );
                assert!(
                    int <= MAX_ANSWER_INTEGER,
                    "{}: integer {int} in {a}",
                    t.name
                );
                largest = largest.max(den);
            }
        }
        // Chapter 6 constructions from integer curves stay within small denominators (the
        // full turn's knots are quarters).
        if ["translational", "developable"].contains(&t.name) {
            assert!(largest <= 2, "{}: denominator {largest}", t.name);
        }
        if t.name == "revolution" {
            assert!(largest <= 4, "{}: denominator {largest}", t.name);
        }
    }
}

// ---- Determinism ----

#[test]
fn same_seed_same_bytes_different_seed_different_problems() {
    for t in topics() {
        let a = problems_json(&set(t.name, 6, 77));
        let b = problems_json(&set(t.name, 6, 77));
        assert_eq!(a, b, "{}", t.name);
        let c = problems_json(&set(t.name, 6, 78));
        assert_ne!(a, c, "{}", t.name);
        // A longer set starts with the problems of a shorter one.
        assert_eq!(
            set(t.name, 3, 77)[..],
            set(t.name, 6, 77)[..3],
            "{}",
            t.name
        );
        // The problems of a set differ from one another.
        let ps = set(t.name, 6, 77);
        let distinct: std::collections::BTreeSet<String> = ps
            .iter()
            .map(|p| {
                json!([
                    p["title"],
                    p.as_object()
                        .unwrap()
                        .iter()
                        .filter(|(k, _)| *k != "name")
                        .collect::<Vec<_>>()
                ])
                .to_string()
            })
            .collect();
        assert!(
            distinct.len() >= 5,
            "{}: {} distinct of 6",
            t.name,
            distinct.len()
        );
    }
}

#[test]
fn the_stream_is_pinned() {
    // SplitMix64 and the drawing order are part of the contract: a seed printed on a
    // problem sheet must give the same sheet in every later build.
    let p = set("graph", 3, 2024);
    let fs: Vec<(&str, &Value)> = p
        .iter()
        .map(|p| (p["f"].as_str().unwrap(), &p["degree"]))
        .collect();
    assert_eq!(
        fs,
        [
            ("-2*y", &json!([1, 1])),
            ("3*x^2 + y^2 - 2*y", &json!([2, 3])),
            ("3*x^2", &json!([2, 1])),
        ]
    );
}

#[test]
fn problems_json_round_trips() {
    let ps = set("coons", 4, 9);
    let text = problems_json(&ps);
    assert!(text.ends_with("]\n"));
    let back: Vec<Value> = serde_json::from_str(&text).unwrap();
    assert_eq!(back, ps);
    assert_eq!(problems_json(&[]), "[]\n");
}

// ---- Constructions ----

#[test]
fn continuity_has_c1_joins_by_construction_and_others() {
    let mut orders = std::collections::BTreeMap::new();
    for p in set("continuity", 60, 3) {
        let a = cagd_problem::solve(&p).unwrap().to_json(false);
        *orders.entry(a["result"]["order"].to_string()).or_insert(0) += 1;
        // The common border: first's last row (or column) is second's first.
        let (f, s) = (&p["first"]["bezier"], &p["second"]["bezier"]);
        let (last, first): (Vec<&Value>, Vec<&Value>) = if p["border"] == "u" {
            (
                f.as_array()
                    .unwrap()
                    .last()
                    .unwrap()
                    .as_array()
                    .unwrap()
                    .iter()
                    .collect(),
                s[0].as_array().unwrap().iter().collect(),
            )
        } else {
            (
                f.as_array()
                    .unwrap()
                    .iter()
                    .map(|r| r.as_array().unwrap().last().unwrap())
                    .collect(),
                s.as_array().unwrap().iter().map(|r| &r[0]).collect(),
            )
        };
        let shared = last.iter().zip(&first).filter(|(a, b)| a == b).count();
        if a["result"]["order"] == json!(-1) {
            assert_eq!(shared + 1, last.len(), "one border point moved: {p}");
        } else {
            assert_eq!(shared, last.len(), "{p}");
        }
    }
    for order in ["-1", "0", "1"] {
        assert!(
            orders.get(order).is_some_and(|n| *n >= 3),
            "order {order}: {orders:?}"
        );
    }
}

#[test]
fn developable_has_both_verdicts() {
    let mut verdicts = std::collections::BTreeMap::new();
    for p in set("developable", 40, 5) {
        let a = cagd_problem::solve(&p).unwrap().to_json(false);
        *verdicts
            .entry(a["result"]["developable"].to_string())
            .or_insert(0) += 1;
    }
    assert!(
        verdicts.get("true").is_some_and(|n| *n >= 10),
        "{verdicts:?}"
    );
    assert!(
        verdicts.get("false").is_some_and(|n| *n >= 5),
        "{verdicts:?}"
    );
}

#[test]
fn coons_curves_meet_at_the_corners() {
    let ends = |c: &Value| {
        let ps = c["bezier"].as_array().unwrap();
        (ps[0].clone(), ps[ps.len() - 1].clone())
    };
    let mut bezier = 0;
    for p in set("coons", 30, 8) {
        if p["c1"].get("bezier").is_none() {
            continue;
        }
        bezier += 1;
        let (c1, c2, d1, d2) = (
            ends(&p["c1"]),
            ends(&p["c2"]),
            ends(&p["d1"]),
            ends(&p["d2"]),
        );
        assert_eq!(c1.0, d1.0, "a = c1(0) = d1(0): {p}");
        assert_eq!(c1.1, d2.0, "b = c1(1) = d2(0): {p}");
        assert_eq!(c2.0, d1.1, "c = c2(0) = d1(1): {p}");
        assert_eq!(c2.1, d2.1, "d = c2(1) = d2(1): {p}");
    }
    assert!(bezier >= 10);
}

#[test]
fn translational_curves_start_at_the_same_point() {
    for p in set("translational", 30, 4) {
        if let Some(c) = p["c"].get("bezier") {
            assert_eq!(c[0], p["d"]["bezier"][0], "{p}");
        }
    }
}

#[test]
fn revolution_profiles_lie_in_the_xz_plane() {
    for p in set("revolution", 30, 6) {
        assert!(
            p["arcs"] == 1 || p["arcs"] == 4 || p["sweep"] == 180,
            "a quadrant, a half or a full turn: {p}"
        );
        let curve = &p["curve"];
        let points = curve
            .get("bezier")
            .or_else(|| curve.get("bspline"))
            .unwrap();
        for q in points.as_array().unwrap() {
            assert_eq!(q[1], 0, "{p}");
            assert!(q[0].as_i64().unwrap() >= 0, "{p}");
        }
    }
}

#[test]
fn parameters_come_from_the_friendly_set() {
    let friendly =
        ["0", "1/4", "1/3", "1/2", "2/3", "3/4", "1"].map(|s| parse_rational(s).unwrap());
    let read = |v: &Value| match v {
        Value::Number(n) => parse_rational(&n.to_string()).unwrap(),
        Value::String(s) => parse_rational(s).unwrap(),
        _ => panic!("{v}"),
    };
    for p in set("restrict", 30, 2) {
        let (u, v) = (
            (read(&p["u"][0]), read(&p["u"][1])),
            (read(&p["v"][0]), read(&p["v"][1])),
        );
        for (a, b) in [&u, &v] {
            assert!(a < b && friendly.contains(a) && friendly.contains(b), "{p}");
        }
        let whole = (read(&json!(0)), read(&json!(1)));
        assert!(
            u != whole || v != whole,
            "a restriction to the whole square: {p}"
        );
    }
    for p in set("evaluate", 30, 2) {
        for uv in p["params"].as_array().unwrap() {
            assert!(
                friendly.contains(&read(&uv[0])) && friendly.contains(&read(&uv[1])),
                "{p}"
            );
        }
    }
}

// ---- Files and errors ----

#[test]
fn problem_set_files_hold_problems_and_keys() {
    let files = problem_set_files("elevate", 3, 12, Lang::En).unwrap();
    let names: Vec<&str> = files.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(
        names,
        [
            "problems.json",
            "statements.tex",
            "key.txt",
            "key.md",
            "key.tex",
            "key.json"
        ]
    );
    let get = |n: &str| &files.iter().find(|(k, _)| k == n).unwrap().1;
    assert_eq!(get("problems.json"), &problems_json(&set("elevate", 3, 12)));
    let key: Vec<Value> = serde_json::from_str(get("key.json")).unwrap();
    assert_eq!(key.len(), 3);
    for (i, k) in key.iter().enumerate() {
        assert_eq!(k["ok"], true);
        assert_eq!(k["op"], "elevate");
        assert_eq!(k["name"], format!("elevate-{}", i + 1));
        let surface = &k["result"]["surface"];
        assert!(surface
            .get("bezier")
            .or(surface.get("bspline"))
            .is_some_and(Value::is_array));
    }
    let text = get("key.txt");
    assert!(text.starts_with("Answer key: Problem sheet\n"), "{text}");
    assert!(
        text.contains("Elevate the B-spline surface of bidegree"),
        "{text}"
    );
    assert!(
        !text.contains("verdict"),
        "a generated problem has no expectation to check"
    );
    let tex = get("key.tex");
    assert!(tex.starts_with("\\documentclass"));
    assert!(tex.trim_end().ends_with("\\end{document}"));
    assert_eq!(tex.matches("\\section*{").count(), 3);
    // the statement sheet: the problems numbered from 1, each a question and its data, no
    // answer
    let sheet = get("statements.tex");
    assert!(sheet.starts_with("\\documentclass"));
    assert!(sheet.contains("\\section*{Problem 1}\nRaise the degree of the surface as given"));
    assert_eq!(sheet.matches("\\section*{").count(), 3);
    assert!(!sheet.contains("Find:"));
    for k in &key {
        let mesh = k["result"]["surface"].to_string();
        assert!(!sheet.contains(&mesh));
    }
    assert!(get("key.md").starts_with("# Answer key: Problem sheet"));
    // The same bytes again.
    assert_eq!(
        files,
        problem_set_files("elevate", 3, 12, Lang::En).unwrap()
    );
}

#[test]
fn spanish_sets_have_the_same_numbers() {
    for t in topics() {
        let en = generate_in(t.name, 3, 31, Lang::En).unwrap();
        let es = generate_in(t.name, 3, 31, Lang::Es).unwrap();
        for (a, b) in en.iter().zip(&es) {
            assert_ne!(a["title"], b["title"], "{}", t.name);
            let strip = |p: &Value| {
                let mut p = p.clone();
                p.as_object_mut().unwrap().remove("title");
                p
            };
            assert_eq!(strip(a), strip(b));
        }
    }
    let files = problem_set_files("developable", 2, 1, Lang::Es).unwrap();
    assert!(files[1]
        .1
        .contains("\\section*{Problema 1}\n¿Es desarrollable la superficie reglada"));
    let files = &files[1..];
    assert!(files[1].1.starts_with("Soluciones: Hoja de problemas\n"));
    assert!(files[1].1.contains("¿Es desarrollable"));
}

#[test]
fn errors_name_what_is_wrong() {
    let e = generate("sphere", 2, 1).unwrap_err();
    assert_eq!(
        e,
        ExerciseError::UnknownTopic {
            name: "sphere".into()
        }
    );
    let msg = e.to_string();
    for t in topics() {
        assert!(msg.contains(t.name), "{msg}");
    }
    assert!(problem_set_files("sphere", 2, 1, Lang::En).is_err());
    assert!(matches!(
        generate("ruled", 5000, 1),
        Err(ExerciseError::TooMany { count: 5000 })
    ));
    assert_eq!(generate("ruled", 0, 1).unwrap(), Vec::<Value>::new());
}

#[test]
fn topics_describe_themselves() {
    let mut names: Vec<&str> = topics().iter().map(|t| t.name).collect();
    assert_eq!(names[..3], ["closed_form", "graph", "evaluate"]);
    names.sort_unstable();
    names.dedup();
    assert_eq!(names.len(), topics().len());
    for t in topics() {
        assert!(cagd_problem::operations().contains(&t.op), "{}", t.op);
        assert!(!t.describe(Lang::En).is_empty() && !t.describe(Lang::Es).is_empty());
        assert!(t.source.ends_with(char::is_numeric), "{}", t.source);
    }
}
