//! The keys in Spanish leave no English behind: every worked example (the fixtures), every
//! operation (the runnable examples of `docs/format.md`, with and without steps), and a
//! representative error of every kind (reading, numbers, shapes, operations, limits, batches,
//! checks), in text, LaTeX and Markdown, are scanned for common English words.

use cagd_keys::{example_latex, example_markdown, example_text, Lang};
use cagd_problem::{check_batch, check_with_settings, Limits, Settings, Verdict};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The words of a key, without what is quoted (`identifiers`, "the user's strings") and,
/// in LaTeX, without the commands and environments.
fn words(key: &str) -> Vec<String> {
    let mut plain = String::new();
    let mut quote: Option<char> = None;
    let mut chars = key.chars().peekable();
    while let Some(c) = chars.next() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), _) => {}
            (None, '`' | '"') => quote = Some(c),
            (None, '\\') => {
                // a LaTeX command: its name, and the name of an environment it opens or closes
                let mut name = String::new();
                while let Some(n) = chars.peek().filter(|n| n.is_ascii_alphabetic()) {
                    name.push(*n);
                    chars.next();
                }
                if name == "begin" || name == "end" || name == "texttt" {
                    for n in chars.by_ref() {
                        if n == '}' {
                            break;
                        }
                    }
                }
                plain.push(' ');
            }
            (None, c) => plain.push(c),
        }
    }
    plain
        .split(|c: char| !c.is_alphabetic())
        .filter(|w| !w.is_empty())
        .map(str::to_lowercase)
        .collect()
}

/// The English words of a key ([`cagd_words::ENGLISH`], [`cagd_words::ENGLISH_IN_KEYS`]), but
/// JSON's own words, which a key shows as data (`se encontró true`).
fn english(key: &str) -> Vec<String> {
    let mut found: Vec<String> = words(key)
        .into_iter()
        .filter(|w| {
            let w = w.as_str();
            (cagd_words::ENGLISH.contains(&w) || cagd_words::ENGLISH_IN_KEYS.contains(&w))
                && !matches!(w, "true" | "false" | "null")
        })
        .collect();
    found.dedup();
    found
}

/// Every format of a verdict's key, in Spanish; each English line found is kept in `leaks`
/// with the English words it has.
fn scan(what: &str, v: &Verdict, leaks: &mut Vec<String>) {
    // a fixture's name is an identifier (`ch5-bidegree-2-3-closed-form`)
    let name = v
        .problem
        .as_ref()
        .and_then(|p| p.meta.name.clone())
        .unwrap_or_default();
    for key in [
        example_text(v, Lang::Es),
        example_latex(v, Lang::Es),
        example_markdown(v, Lang::Es),
    ] {
        let key = if name.is_empty() {
            key
        } else {
            key.replace(&name, "")
        };
        for line in key.lines() {
            let en = english(line);
            if !en.is_empty() {
                leaks.push(format!("{what}: {en:?} in: {line}"));
            }
        }
    }
}

/// Fails with every English line found.
fn assert_none(leaks: &[String]) {
    let mut leaks = leaks.to_vec();
    leaks.dedup();
    assert!(
        leaks.is_empty(),
        "{} English lines:\n{}",
        leaks.len(),
        leaks.join("\n")
    );
}

fn settings(steps: bool) -> Settings {
    Settings {
        limits: Limits::DEFAULT,
        steps,
    }
}

#[test]
fn every_example_in_spanish() {
    let mut n = 0;
    let mut leaks = Vec::new();
    for dir in ["ch5", "ch6", "slides", "triangle"] {
        let mut files: Vec<_> = std::fs::read_dir(root().join("fixtures").join(dir))
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        files.sort();
        for f in files {
            let fixture: Value =
                serde_json::from_str(&std::fs::read_to_string(&f).unwrap()).unwrap();
            for steps in [false, true] {
                let v = check_with_settings(&fixture, &settings(steps));
                scan(&f.display().to_string(), &v, &mut leaks);
            }
            n += 1;
        }
    }
    assert!(n >= 22, "every fixture: {n}");
    assert_none(&leaks);
}

#[test]
fn every_operation_in_spanish() {
    let format = std::fs::read_to_string(root().join("docs/format.md")).unwrap();
    let problems: Vec<Value> = format
        .lines()
        .filter(|l| l.starts_with("{\"op\":"))
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let mut ops: Vec<&str> = problems.iter().filter_map(|p| p["op"].as_str()).collect();
    ops.sort_unstable();
    ops.dedup();
    assert_eq!(
        ops.len(),
        cagd_problem::operations().len(),
        "one example per operation"
    );
    let mut leaks = Vec::new();
    for p in &problems {
        for steps in [false, true] {
            let v = check_with_settings(p, &settings(steps));
            assert!(v.answer.is_ok(), "{p}: {:?}", v.answer);
            scan(&p["op"].to_string(), &v, &mut leaks);
        }
    }
    assert_none(&leaks);
}

/// A representative problem of every kind of error a teacher can meet.
fn bad_problems() -> Vec<Value> {
    let square = json!([[[0, 0, 0], [1, 0, 0]], [[0, 1, 0], [1, 1, 1]]]);
    vec![
        json!({}),
        json!([1, 2]),
        json!({"op": 3}),
        json!({"op": "coonz"}),
        json!({"op": "rotate"}),
        json!({"op": "coons"}),
        json!({"op": "circle", "radus": 1}),
        json!({"op": "circle", "radius": -1}),
        json!({"op": "circle", "radius": "1/0"}),
        json!({"op": "circle", "radius": "sqrt(-2)"}),
        json!({"op": "circle", "radius": 0.5}),
        json!({"op": "circle", "radius": format!("1{}", "0".repeat(1200))}),
        json!({"op": "circle", "radius": "x"}),
        json!({"op": "coons", "c1": {"bezier": [[0, 0, 0], [1, 2]]}}),
        json!({"op": "elevate", "surface": {"bezier": [[[0, 0, 0], [1, 0, 0]], [[0, 1, 0]]]}, "by": [1, 0]}),
        json!({"op": "elevate", "surface": {"bezier": square}, "by": "two"}),
        json!({"op": "elevate", "curve": {"expr": "(u, u^2)"}, "by": 1}),
        json!({"op": "elevate", "curve": {"bezier": [[0, 0], [1, 1]]}, "by": 5000}),
        json!({"op": "evaluate", "surface": {"bezier": square}, "params": [[2, 0]]}),
        json!({"op": "evaluate", "surface": {"bezier": square}, "params": [0]}),
        json!({"op": "arc_length", "curve": {"bezier": [[0, 0], [1, 1]], "weights": [1, 0]}}),
        json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 1]], "weights": [1, 0]}, "params": [1]}),
        json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 1]], "weights": [0, 0]}, "params": [0]}),
        json!({"op": "evaluate", "curve": {"bspline": [[0, 0], [1, 1], [2, 0]], "degree": 2, "knots": [0, 0, 1, 1], "weights": [1, 0, 1]}, "params": [0]}),
        json!({"op": "evaluate", "curve": {"bezier": [[0, 0, 1], [1, 1, 1]], "homogeneous": true, "weights": [1, 1]}, "params": [0]}),
        json!({"op": "evaluate", "curve": {"bezier": [[0], [1]], "homogeneous": true}, "params": [0]}),
        json!({"op": "evaluate", "curve": {"expr": "(t, t)", "homogeneous": true}, "params": [0]}),
        json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 1]], "weights": [1]}, "params": [0]}),
        json!({"op": "evaluate", "curve": {"bspline": [[0, 0], [1, 1], [2, 0]], "degree": 2, "knots": [0, 1, 0, 1]}, "params": [0]}),
        json!({"op": "evaluate", "curve": {"bspline": [[0, 0], [1, 1], [2, 0]], "degree": 2, "knots": [0, 0, 0, 1, 1, 1, 1]}, "params": [0]}),
        json!({"op": "closed_form", "surface": {"bezier": square, "weights": [[1, 1], [1]]}}),
        json!({"op": "closed_form", "surface": {"expr": "(u, v, u/v)"}}),
        json!({"op": "closed_form", "surface": {"expr": "(u, v, q)"}}),
        json!({"op": "closed_form", "surface": {"expr": "(u, v, sqrt2 + sqrt3)"}}),
        json!({"op": "restrict", "surface": {"bezier": square}, "u": [1, 1], "v": [0, 1]}),
        json!({"op": "coons",
            "c1": {"bezier": [[0, 0, 0], [1, 0, 0]]}, "c2": {"bezier": [[0, 1, 0], [1, 1, 0]]},
            "d1": {"bezier": [[0, 0, 1], [0, 1, 0]]}, "d2": {"bezier": [[1, 0, 0], [1, 1, 0]]}}),
        json!({"op": "continuity", "first": {"bezier": square}, "second": {"bezier": square, "weights": [[1, 1], [1, 1]]}}),
        json!({"op": "interpolate", "basis": "bezier", "u": [0, 0], "v": [0, 1],
            "points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]]}),
        json!({"op": "interpolate", "basis": "bspline", "degree": 5, "end": "clamped",
            "tangents": [[1, 1], [1, -1]], "params": [0, 1, 2], "points": [[0, 0], [1, 1], [2, 0]]}),
        json!({"op": "interpolate", "basis": "bspline", "degree": 2, "end": "clamped",
            "tangents": [[1, 1], [1, -1, 0]], "params": [0, 1, 2], "points": [[0, 0], [1, 1], [2, 0]]}),
        json!({"op": "interpolate", "basis": "bspline", "degree": 2, "end": "clamped",
            "tangents": [[1, 1, 0], [1, -1, 0]], "params": [0, 1, 2], "points": [[0, 0], [1, 1], [2, 0]]}),
        json!({"op": "interpolate", "basis": "bspline", "degree": 2, "end": "natural",
            "params": [0, 1, 2], "points": [[0, 0], [1, 1], [2, 0]]}),
        json!({"op": "interpolate", "basis": "bspline", "degree": 2, "end": "clamped",
            "tangents": [[1, 1]], "params": [0, 1, 2], "points": [[0, 0], [1, 1], [2, 0]]}),
        json!({"op": "insert_knot", "curve": {"bezier": [[0, 0], [1, 1]]}, "knot": "1/2"}),
        json!({"op": "insert_knot", "curve": {"bspline": [[0, 0], [1, 2], [3, 2], [4, 0]], "degree": 2, "knots": [0, 0, 1, 2, 2]}, "knot": 7}),
        json!({"op": "ruled", "c1": {"expr": "(u, 0, u)"}, "c2": {"bspline": [[0, 0, 0], [1, 1, 1]], "degree": 1, "knots": [0, 1]}}),
        json!({"op": "revolution", "curve": {"bezier": [[1, 0, 0], [1, 0, 1]]}, "arcs": 4, "quadrant": true}),
        json!({"op": "graph", "f": "x^3*y", "degree": [1, 1]}),
        json!({"op": "closed_form", "surface": {"bezier": square}, "expected": {"closed_form": "(u, v, 0)"}}),
        json!({"op": "closed_form", "surface": {"bezier": square}, "expected": {"surface": {"bezier": square}}}),
        // a step the operation does not record (a typo), and an operation with no named steps
        json!({"op": "coons", "c1": {"bezier": [[0, 0, 0], [1, 0, 0]]}, "c2": {"bezier": [[0, 1, 0], [1, 1, 0]]},
            "d1": {"bezier": [[0, 0, 0], [0, 1, 0]]}, "d2": {"bezier": [[1, 0, 0], [1, 1, 0]]},
            "expected": {"steps": {"c_CD": 0}}}),
        json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 2]]}, "params": [0], "expected": {"steps": {"c_hat": 0}}}),
        // malformed expectations: steps, remarks and derivation in the wrong shape, a list of
        // steps that is not the computed one, an `expected` of words alone
        json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 2]]}, "params": [0],
            "expected": {"steps": "x", "remarks": 1, "derivation": "y"}}),
        json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 2]]}, "params": [0],
            "expected": {"steps": {}}}),
        json!({"op": "coons", "c1": {"bezier": [[0, 0, 0], [1, 0, 0]]}, "c2": {"bezier": [[0, 1, 0], [1, 1, 0]]},
            "d1": {"bezier": [[0, 0, 0], [0, 1, 0]]}, "d2": {"bezier": [[1, 0, 0], [1, 1, 0]]},
            "expected": {"steps": [{"name": "c_d", "value": 0}, {"value": 1}]}}),
        json!({"op": "coons", "c1": {"bezier": [[0, 0, 0], [1, 0, 0]]}, "c2": {"bezier": [[0, 1, 0], [1, 1, 0]]},
            "d1": {"bezier": [[0, 0, 0], [0, 1, 0]]}, "d2": {"bezier": [[1, 0, 0], [1, 1, 0]]},
            "expected": {"steps": [{"name": "c_d", "value": 0}]}}),
        json!({"op": "circle", "expected": {"remarks": []}}),
        // letters
        json!({"op": "circle", "radius": "2 r", "parameters": ["R"]}),
        json!({"op": "circle", "radius": "R"}),
        json!({"op": "circle", "radius": "R", "parameters": ["R"], "values": {"S": 1}}),
        json!({"op": "circle", "radius": "R", "parameters": ["RR"]}),
        json!({"op": "circle", "radius": "R", "parameters": ["R", "R"]}),
        json!({"op": "restrict", "curve": {"bezier": [[0], [1], [2]]}, "t": ["a", "b"], "parameters": ["a", "b"]}),
        json!({"op": "evaluate", "curve": {"bspline": [[0], [1], [2], [3]], "degree": 2, "knots": [0, "a", 1, 1, 1]}, "params": ["1/2"], "parameters": ["a"]}),
        json!({"op": "closed_form", "curve": {"expr": "(f, 0, g)"}, "functions": ["f", "g"]}),
        json!({"op": "elevate", "surface": {"generic": "c", "degree": [9, 2]}, "by": [1, 0]}),
        json!({"op": "elevate", "surface": {"generic": "cc", "degree": [2, 2]}, "by": [1, 0]}),
        // --- triangle column ---
        json!({"op": "restrict", "triangle": {"triangle": [[[0]], [[1], [2]]]}, "u": [0, 1]}),
        json!({"op": "restrict", "triangle": {"triangle": [[[0]], [[1], [2]]]}, "vertices": [[0, 0]]}),
        json!({"op": "isocurve", "surface": {"bezier": [[[0], [1]], [[2], [3]]]}, "w": 0}),
        json!({"op": "isocurve", "triangle": {"triangle": [[[0]], [[1], [2]]]}}),
        json!({"op": "isocurve", "triangle": {"triangle": [[[0]], [[1], [2]]]}, "u": 0, "v": 0}),
        json!({"op": "reverse", "triangle": {"triangle": [[[0]], [[1], [2]]]}, "order": [1, 1, 2]}),
        json!({"op": "reverse", "surface": {"bezier": [[[0], [1]], [[2], [3]]]}}),
        json!({"op": "graph", "f": "x", "domain": [[0, 0], [1, 1]]}),
        json!({"op": "graph", "f": "x", "domain": [[0, 0], [1, 1], [2, 2]]}),
        json!({"op": "graph", "f": "x", "domain": [[0, 0], [1, 0], [0, 1]], "degree": [1, 1]}),
        json!({"op": "graph", "f": "x^2", "domain": [[0, 0], [1, 0], [0, 1]], "degree": 1}),
        json!({"op": "evaluate", "triangle": {"triangle": [[[0]], [[1], [2]]], "weights": [[1]]}, "params": [[0, 0]]}),
        json!({"op": "evaluate", "triangle": {"triangle": [[[0]], [[1], [2]]], "weights": [[1], [1]]}, "params": [[0, 0]]}),
        json!({"op": "evaluate", "triangle": {"triangle": [[[0]], [[1], [2]]], "weights": [[1], [0, 1]]}, "params": [[0, 0]]}),
        json!({"op": "evaluate", "triangle": {"triangle": [[[0]], [[1], [2]]], "weights": [[1], [1, -1]]}, "params": [["1/2", "1/2"]]}),
        json!({"op": "derivative", "triangle": {"triangle": [[[0]], [[1], [2]]], "weights": [[1], [1, 2]]}}),
        json!({"op": "reduce_degree", "triangle": {"triangle": [[[0]], [[1], [2]]]}, "by": 2}),
        json!({"op": "reduce_degree", "triangle": {"triangle": [[[0]], [[1], [2]]]}}),
        json!({"op": "reduce_degree", "triangle": {"triangle": [[[0]], [[1], [2]]], "weights": [[1], [1, 2]]}}),
        // breadth: a knot of a surface that cannot be removed, a split outside the domain
        json!({"op": "remove_knot", "surface": {"bspline": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]], [[2, 0, 0], [2, 1, 0]]], "degree": [1, 1], "knots": [[0, 1, 2], [0, 1]]}, "knot": 1}),
        json!({"op": "remove_knot", "surface": {"bspline": [[[0, 0, 0], [1, 0, 0], [2, 0, 0]], [[0, 1, 0], [1, 1, 1], [2, 1, 0]]], "degree": [1, 1], "knots": [[0, 1], [0, 1, 2]]}, "knot": 1, "direction": "v"}),
        json!({"op": "subdivide", "surface": {"bspline": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]], [[2, 0, 0], [2, 1, 0]]], "degree": [1, 1], "knots": [[0, 1, 2], [0, 1]]}, "u": 2}),
        // breadth: degree reduction refused, two B-spline surfaces over different intervals
        json!({"op": "reduce_degree", "curve": {"bezier": [[1, 0], [1, 1], [0, 1]], "weights": [1, 2, 1]}}),
        json!({"op": "reduce_degree", "curve": {"bspline": [[0, 0], [1, 0], [2, 0], [3, 1]], "degree": 2, "knots": [0, 0, 1, 2, 2]}}),
        json!({"op": "reduce_degree", "curve": {"bspline": [[0, 0], [1, 0], [2, 0]], "degree": 1, "knots": [0, 1, 2]}}),
        json!({"op": "reduce_degree", "curve": {"bspline": [[0, 0], [1, 0], [2, 0], [3, 1]], "degree": 2, "knots": [0, 0, 1, 2, 2], "weights": [1, 2, 1, 1]}}),
        json!({"op": "continuity", "first": {"bspline": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]], "degree": [1, 1], "knots": [[0, 1], [0, 1]]}, "second": {"bspline": [[[1, 0, 0], [1, 1, 0]], [[2, 0, 0], [2, 1, 0]]], "degree": [1, 1], "knots": [[0, 1], [0, 2]]}}),
        json!({"op": "continuity", "first": {"bspline": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]], "degree": [1, 1], "knots": [[0, 1], [0, 1]]}, "second": {"bspline": [[[1, 0, 0], [1, 1, 0]], [[2, 0, 0], [2, 1, 0]]], "degree": [1, 1], "knots": [[0, 1], [0, 1]]}, "lengths": [1, 2]}),
        // every fit with too few data points (what needs them, in words), chord lengths in two fields
        json!({"op": "approximate", "degree": [1, 1], "knots_u": [0, 1, 2], "knots_v": [0, 1], "params": [[0, 0], [1, 0]], "points": [[0, 0, 0], [1, 0, 1]]}),
        json!({"op": "approximate", "degree": [1, 1], "points": [[0, 0, 1], [1, 0, 1]], "params": [[0, 0], [1, 0]]}),
        json!({"op": "approximate", "degree": 2, "params": [0, 1], "points": [[0, 0], [1, 1]]}),
        json!({"op": "approximate", "degree": 2, "knots": [0, 0, 1, 2, 2], "params": [0, 1], "points": [[0, 0], [1, 1]]}),
        json!({"op": "interpolate", "basis": "bicubic", "end": "bessel", "params": [0, 1], "points": [[0, 0], [1, 1]]}),
        json!({"op": "interpolate", "basis": "bicubic", "end": "natural", "params": [0], "points": [[0, 0]]}),
        json!({"op": "interpolate", "basis": "bicubic", "end": "bessel", "u": [0, 1], "v": [0, 1, 2], "points": [[[0, 0, 0], [0, 1, 1], [0, 2, 0]], [[1, 0, 1], [1, 1, 2], [1, 2, 1]]]}),
        json!({"op": "interpolate", "basis": "bicubic", "end": "natural", "u": [0], "v": [0, 1, 2], "points": [[[0, 0, 0], [0, 1, 1], [0, 2, 0]]]}),
        json!({"op": "interpolate", "basis": "bezier", "u": [0, "1/2", 1], "v": [0, 1], "points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 1], [1, 1, 1]]]}),
        json!({"op": "interpolate", "degree": [1, 1], "params": [[0, 0], [1, 0]], "points": [[0, 0, 1], [1, 0, 1]]}),
        json!({"op": "interpolate", "basis": "bspline", "degree": 3, "parametrization": "chord_length", "points": [[0, 0], [1, 1], [2, 1], [3, 1]]}),
        json!({"op": "interpolate", "basis": "bspline", "degree": 3, "parametrization": "chord_length", "points": [[0, 0], [1, 0], [2, 1], [3, 2]]}),
        json!({"op": "interpolate", "basis": "bspline", "degree": 3, "parametrization": "chord_length", "points": [[0, 0], [1, 1], [2, 3], [3, 5]]}),
    ]
}

#[test]
fn every_kind_of_error_in_spanish() {
    let mut failed = 0;
    let mut leaks = Vec::new();
    for p in bad_problems() {
        let v = check_with_settings(&p, &settings(false));
        if !v.passed() {
            failed += 1;
        }
        scan(&p.to_string(), &v, &mut leaks);
    }
    assert_eq!(failed, bad_problems().len(), "every problem is bad");
    // past each limit
    let tight = Limits {
        max_degree: 3,
        max_points: 4,
        max_digits: 10,
        max_depth: 4,
        max_exponent: 20,
        ..Limits::DEFAULT
    };
    for p in [
        json!({"op": "elevate", "curve": {"bezier": [[0, 0], [1, 1]]}, "by": 5}),
        json!({"op": "evaluate", "curve": {"bezier": [[0], [1], [2], [3], [4], [5]]}, "params": [0]}),
        json!({"op": "circle", "radius": "123456789012345"}),
        json!({"op": "circle", "radius": "((((((1))))))"}),
        json!({"op": "closed_form", "surface": {"expr": "(u, v, u^99)"}}),
        json!({"op": "circle", "radius": "10^99"}),
        json!({"op": "closed_form", "surface": {"expr": "(u, v, (u + 1)^19 * (u + 1)^19)"}}),
    ] {
        let v = check_with_settings(
            &p,
            &Settings {
                limits: tight,
                steps: false,
            },
        );
        assert!(v.answer.is_err(), "{p}");
        scan(&p.to_string(), &v, &mut leaks);
    }
    // in a batch, numbered from 1; past the batch's limit
    let batch = Value::Array(bad_problems().into_iter().take(8).collect());
    let limits = Limits {
        max_batch: 5,
        ..Limits::DEFAULT
    };
    let vs = check_batch(
        &batch,
        &Settings {
            limits,
            steps: false,
        },
        1,
    );
    for v in &vs {
        scan("batch", v, &mut leaks);
    }
    assert_none(&leaks);
    let first = example_text(&vs[0], Lang::Es);
    assert!(
        first.starts_with("== Problema 1\nerror: problema 1: campo `op`: falta"),
        "{first}"
    );
}

/// The remark of a join of two B-spline surfaces of which the second was moved, in Spanish.
#[test]
fn a_moved_second_surface_is_said_in_spanish() {
    let first = json!({"bspline": [[[0, 0, 0], [0, 1, 1]], [[1, 0, 0], [1, 1, 2]]], "degree": [1, 1], "knots": [[0, 1], [0, 1]]});
    let second = json!({"bspline": [[[0, 1, 1], [0, 2, 0]], [[1, 1, 2], [1, 2, 0]]], "degree": [1, 1], "knots": [[0, 1], [5, 6]]});
    let v = check_with_settings(
        &json!({"op": "continuity", "first": first, "second": second, "border": "v"}),
        &Settings::default(),
    );
    let key = example_text(&v, Lang::Es);
    assert!(
        key.contains("  (la segunda superficie empieza en v = 5 y la primera acaba en v = 1: la segunda se ha trasladado -4 en v para que sean consecutivas; las derivadas son en los parámetros propios de las superficies)\n"),
        "{key}"
    );
}

/// The keys of problems above the thresholds of the worked steps (a big patch evaluated, big
/// elevations, an (8, 8) grid, a least-squares fit of twelve points: what is left out said in
/// words, matrices by their first rows), in Spanish.
#[test]
fn big_problems_in_spanish() {
    let problems: Vec<(String, Value)> = serde_json::from_str(include_str!(
        "../../../problem/tests/problem/big_steps.json"
    ))
    .unwrap();
    assert!(problems.len() >= 6);
    let mut leaks = Vec::new();
    for (name, p) in &problems {
        let v = check_with_settings(p, &settings(true));
        assert!(v.answer.is_ok(), "{name}: {:?}", v.answer);
        scan(name, &v, &mut leaks);
    }
    assert_none(&leaks);
}

/// A step named in `expected` that the operation does not record is said in each language,
/// with the steps it records (the names as typed, in code).
#[test]
fn a_step_not_recorded_is_said_in_each_language() {
    let coons = json!({"op": "coons", "c1": {"bezier": [[0, 0, 0], [1, 0, 0]]}, "c2": {"bezier": [[0, 1, 0], [1, 1, 0]]},
        "d1": {"bezier": [[0, 0, 0], [0, 1, 0]]}, "d2": {"bezier": [[1, 0, 0], [1, 1, 0]]},
        "expected": {"steps": {"c_CD": 0}}});
    let evaluate = json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 2]]}, "params": [0],
        "expected": {"steps": {"c_hat": 0}}});
    let cases = [
        (
            &coons,
            "step `c_CD`: `coons` records no step named `c_CD` (its steps: `c_c`, `c_d`, `c_cd`)",
            "paso `c_CD`: `coons` no registra ningún paso llamado `c_CD` (sus pasos: `c_c`, `c_d`, `c_cd`)",
        ),
        (
            &evaluate,
            "step `c_hat`: `evaluate` records no named steps to check",
            "paso `c_hat`: `evaluate` no registra pasos con nombre que comprobar",
        ),
    ];
    for (problem, en, es) in cases {
        let v = check_with_settings(problem, &settings(false));
        assert!(!v.passed());
        for (lang, line) in [(Lang::En, en), (Lang::Es, es)] {
            let text = example_text(&v, lang);
            assert!(text.contains(line), "{line} in\n{text}");
        }
    }
}

/// The sentences the English-matching translation left half in English, each rendered in
/// Spanish with no English word: a revolution of a plane curve, a profile off the XZ plane,
/// two curves in spaces of different dimension, three errors of triangular patches, a root
/// the operation needs, and the grammar's "an operator or the end" and "the end".
#[test]
fn the_sentences_once_half_in_english_are_spanish() {
    let triangle = json!({"triangle": [[[0, 0]], [[1, 0], [0, 1]]]});
    let cases = [
        (
            json!({"op": "revolution", "curve": {"bezier": [[1, 0], [1, 1]]}}),
            "una superficie de revolución alrededor de Z necesita puntos de R^3, pero la curva tiene 2 coordenadas",
        ),
        (
            json!({"op": "revolution", "curve": {"bezier": [[1, 1, 0], [1, 0, 1]]}}),
            "el punto de control c_0 = (1, 1, 0) no está en el plano XZ (y ≠ 0): una superficie de revolución alrededor del eje Z gira una curva del plano XZ",
        ),
        (
            json!({"op": "ruled", "c1": {"bezier": [[0, 0], [1, 0]]}, "c2": {"bezier": [[0, 1, 0], [1, 1, 0]]}}),
            "c1 tiene 2 coordenadas, pero c2 tiene 3: han de estar en el mismo espacio",
        ),
        (
            json!({"op": "blossom", "triangle": triangle, "params": [[1, 0, 0], [0, 1, 0]]}),
            "la forma polar de una superficie de grado 1 toma 1 argumento, se encontraron 2",
        ),
        (
            json!({"op": "blossom", "triangle": triangle, "params": [["1/2", "1/2", "1/2"]]}),
            "las coordenadas baricéntricas (1/2, 1/2, 1/2) suman 3/2, no 1 (se necesita r + s + t = 1)",
        ),
        (
            json!({"op": "normal", "triangle": triangle, "params": [["1/3", "1/3", "1/3"]]}),
            "el vector normal b_u × b_v necesita puntos de R³, se encontró dimensión 2",
        ),
        (
            json!({"op": "circle", "radius": "sqrt3"}),
            "este número necesita √3, pero la operación necesita √2: un problema se resuelve en un solo cuerpo a + b√d",
        ),
        (
            json!({"op": "circle", "radius": "1 + 2)"}),
            "se esperaba un operador o el final de la expresión (¿falta cerrar un paréntesis?), se encontró ')'",
        ),
        (
            json!({"op": "circle", "radius": "1 +"}),
            "se esperaba un número, una variable, 'sqrt' o '(', se encontró el final de la expresión",
        ),
    ];
    let mut leaks = Vec::new();
    for (problem, spanish) in cases {
        let v = check_with_settings(&problem, &settings(false));
        assert!(v.answer.is_err(), "{problem}");
        let key = example_text(&v, Lang::Es);
        assert!(key.contains(spanish), "{spanish}\nin\n{key}");
        scan(&problem.to_string(), &v, &mut leaks);
    }
    assert_none(&leaks);
}

/// A student's answer assessed (`cagd check`): every result's score, wrong entries of every
/// kind (a point, a weight, the knots, entries beyond the key's, an entry not written, a value
/// that could not be read), every mistake of the catalogue (ambiguous, and alone), a result no
/// mistake explains, a correct result and the first step off the key, in Spanish.
#[test]
fn an_assessment_in_spanish() {
    use cagd_problem::diagnosis::{Assessed, Diagnosis, Entry, Mark};
    use cagd_problem::message::check::Check;
    use cagd_problem::{Assessment, Exact, Mistake};
    let coons = json!({"op": "coons", "student": "Ana",
        "c1": {"bezier": [[0, 0, 0], [1, 0, 1], [2, 0, 0]]}, "c2": {"bezier": [[0, 2, 0], [1, 2, 1], [2, 2, 0]]},
        "d1": {"bezier": [[0, 0, 0], [0, 2, 0]]}, "d2": {"bezier": [[2, 0, 0], [2, 2, 0]]},
        "expected": {"surface": {"bezier": [[[0, 0, 0]]]}}});
    let mut v = check_with_settings(&coons, &settings(true));
    let answer = v.answer.as_ref().unwrap();
    let (q, x) = answer.result[0].clone();
    let (step, _) = answer.steps[0].clone();
    let entries = x.entries();
    let (e0, k0) = entries[0].clone();
    let wrong = |entry: Entry, key: Option<Exact>, written: Option<Exact>| Mark {
        entry,
        key,
        written,
        right: false,
    };
    let mut marks: Vec<Mark> = entries
        .iter()
        .map(|(e, k)| Mark {
            entry: e.clone(),
            key: Some(k.clone()),
            written: Some(k.clone()),
            right: true,
        })
        .collect();
    marks[0] = wrong(e0.clone(), Some(k0.clone()), Some(Exact::Text("x".into())));
    marks.push(wrong(Entry::Weight(1), Some(k0.clone()), None));
    marks.push(wrong(Entry::Knots, Some(k0.clone()), Some(k0.clone())));
    marks.push(wrong(
        Entry::Item(0, Box::new(Entry::Degree)),
        Some(k0.clone()),
        Some(k0),
    ));
    marks.push(wrong(Entry::Extra, None, None));
    let all = Mistake::all();
    let wrong_result = Assessed {
        quantity: q.clone(),
        marks: marks.clone(),
        diagnoses: vec![
            Diagnosis {
                mistakes: all.clone(),
                entries: vec![e0.clone(), Entry::Knots],
                whole: false,
            },
            Diagnosis {
                mistakes: all[..1].to_vec(),
                entries: vec![e0],
                whole: true,
            },
        ],
        unread: None,
        unknown: false,
    };
    let unexplained = Assessed {
        diagnoses: Vec::new(),
        unknown: true,
        ..wrong_result.clone()
    };
    let unread = Assessed {
        unread: Some(Check::ComputedList {
            expected: "1".into(),
        }),
        ..unexplained.clone()
    };
    let right = Assessed {
        quantity: step.clone(),
        marks: marks.into_iter().filter(|m| m.right).collect(),
        diagnoses: Vec::new(),
        unread: None,
        unknown: false,
    };
    v.assessment = Some(Box::new(Assessment {
        student: Some("Ana".into()),
        results: vec![wrong_result, unexplained, unread],
        steps: vec![
            right.clone(),
            Assessed {
                quantity: step.clone(),
                ..right
            },
        ],
        first_departure: Some(step),
    }));
    let mut leaks = Vec::new();
    scan("an assessment", &v, &mut leaks);
    assert_none(&leaks);
    let text = example_text(&v, Lang::Es);
    for said in [
        "veredicto: respuesta incorrecta",
        "entradas correctas",
        "ambiguo:",
        "ningún error conocido explica estas entradas",
        "primer paso que se aparta de la clave",
        "apuntes:",
        "usada:",
        "estudiante: Ana",
    ] {
        assert!(text.contains(said), "{said} in:\n{text}");
    }
}
