//! The JSON Schemas of problems and answers (`docs/problem.schema.json`,
//! `docs/answer.schema.json`): the files in `docs/` are the ones the types generate, every
//! fixture and every example of `docs/format.md` is a valid problem, their answers are valid
//! answers, and what the reading refuses for a wrong key or a float the schema refuses too.
//! (`crates/exercises/tests/schema.rs` checks the problems of `cagd generate`.)

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

use cagd_problem::schema::{answer_schema, problem_schema, schema_files};
use cagd_problem::{error_json, solve, solve_batch, Limits, Problem};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

/// A compiled schema (boon checks it against the 2020-12 meta-schema as it compiles it).
struct Validator {
    schemas: boon::Schemas,
    index: boon::SchemaIndex,
}

impl Validator {
    fn new(schema: Value) -> Validator {
        let url = "file:///schema.json";
        let mut schemas = boon::Schemas::new();
        let mut compiler = boon::Compiler::new();
        compiler.add_resource(url, schema).expect("a schema");
        let index = compiler
            .compile(url, &mut schemas)
            .unwrap_or_else(|e| panic!("the schema does not compile: {e:#}"));
        Validator { schemas, index }
    }

    /// Why `v` is invalid, or `None`.
    fn errors(&self, v: &Value) -> Option<String> {
        self.schemas
            .validate(v, self.index)
            .err()
            .map(|e| format!("{e:#}"))
    }

    fn accepts(&self, v: &Value) -> bool {
        self.errors(v).is_none()
    }
}

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn fixture_files() -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let mut entries: Vec<_> = std::fs::read_dir(dir)
            .expect("fixtures folder")
            .filter_map(Result::ok)
            .map(|e| e.path())
            .collect();
        entries.sort();
        for p in entries {
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|e| e == "json") {
                out.push(p);
            }
        }
    }
    let mut out = Vec::new();
    walk(&root().join("fixtures"), &mut out);
    out
}

fn fixtures() -> Vec<(String, Value)> {
    fixture_files()
        .iter()
        .map(|p| {
            let text = std::fs::read_to_string(p).unwrap();
            let v = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
            (p.display().to_string(), v)
        })
        .collect()
}

/// The examples of `docs/format.md` (code blocks tagged `json problem`), as
/// `tests/format_doc.rs` reads them.
fn doc_examples() -> Vec<(String, Value)> {
    let doc = std::fs::read_to_string(root().join("docs/format.md")).expect("docs/format.md");
    let mut out = Vec::new();
    let mut current: Option<(usize, String)> = None;
    for (n, line) in doc.lines().enumerate() {
        let fence = line.trim();
        current = match current {
            None if fence == "```json problem" => Some((n + 1, String::new())),
            None => None,
            Some((start, text)) if fence == "```" => {
                let v = serde_json::from_str(&text)
                    .unwrap_or_else(|e| panic!("docs/format.md:{start}: {e}"));
                out.push((format!("docs/format.md:{start}"), v));
                None
            }
            Some((start, mut text)) => {
                text.push_str(line);
                text.push('\n');
                Some((start, text))
            }
        };
    }
    out
}

fn problems() -> Vec<(String, Value)> {
    let mut all = fixtures();
    all.extend(doc_examples());
    all
}

#[test]
fn the_schemas_in_docs_are_the_generated_ones() {
    for (path, text) in schema_files() {
        let committed = std::fs::read_to_string(root().join(path)).unwrap_or_default();
        assert!(
            committed == text,
            "{path} differs from the schema the types generate: run `cargo run -p cagd-problem --example schema` and commit it"
        );
    }
}

#[test]
fn the_schemas_say_nothing_of_null() {
    for (path, text) in schema_files() {
        assert!(!text.contains("\"null\""), "{path} allows null");
    }
}

#[test]
fn every_operation_is_in_the_schema_with_the_fixture_keys() {
    let schema = problem_schema();
    let defs = schema["$defs"].as_object().unwrap();
    let branches = defs["problem"]["oneOf"].as_array().unwrap();
    assert_eq!(branches.len(), cagd_problem::operations().len());
    for op in cagd_problem::operations() {
        let branch = &defs[*op];
        assert_eq!(branch["properties"]["op"]["const"], *op);
        assert_eq!(branch["additionalProperties"], false);
        for key in [
            "name", "title", "source", "equation", "note", "expected", "errata",
        ] {
            assert!(branch["properties"].get(key).is_some(), "{op} lacks {key}");
        }
    }
}

#[test]
fn every_fixture_and_example_is_a_valid_problem() {
    let problems = problems();
    assert!(problems.len() >= 40, "{} problems", problems.len());
    let v = Validator::new(problem_schema());
    let mut failures = Vec::new();
    for (place, p) in &problems {
        if let Some(e) = v.errors(p) {
            failures.push(format!("{place}: {e}"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
    // a batch is a list of problems
    let batch = Value::Array(problems.into_iter().map(|(_, p)| p).collect());
    assert!(v.accepts(&batch), "{:?}", v.errors(&batch));
}

#[test]
fn every_answer_is_a_valid_answer() {
    let v = Validator::new(answer_schema());
    let mut failures = Vec::new();
    let mut answers = Vec::new();
    for (place, p) in problems() {
        let a = solve(&p).unwrap_or_else(|e| panic!("{place}: {e}"));
        for steps in [false, true] {
            let json = a.to_json(steps);
            if let Some(e) = v.errors(&json) {
                failures.push(format!("{place} (steps: {steps}): {e}\n{json}"));
            }
            answers.push(json);
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
    assert!(v.accepts(&Value::Array(answers)));
    // errors, alone and in a batch
    let batch = json!([{"op": "circle"}, {"op": "coons", "blned": "cubic"}, {"op": "nope"}]);
    let answers: Vec<Value> = solve_batch(&batch)
        .iter()
        .map(|a| match a {
            Ok(a) => a.to_json(false),
            Err(e) => error_json(e),
        })
        .collect();
    assert_eq!(answers[1]["ok"], false);
    for a in &answers {
        assert!(v.accepts(a), "{a}: {:?}", v.errors(a));
    }
}

/// A valid problem changed by `change`.
fn changed(p: &Value, change: impl FnOnce(&mut Value)) -> Value {
    let mut p = p.clone();
    change(&mut p);
    p
}

#[test]
fn what_the_reading_refuses_the_schema_refuses() {
    let v = Validator::new(problem_schema());
    let coons = json!({
        "op": "coons",
        "c1": {"bezier": [[0, 0, 0], ["1/2", 0, 2], [2, 0, 0]]},
        "c2": {"bezier": [[0, 3, 0], [1, 3, 1], [2, 4, 0]]},
        "d1": {"expr": "(0, 3 t, 0)"},
        "d2": {"bspline": [[2, 0, 0], [2, 2, 1], [2, 4, 0]], "degree": 2, "knots": [0, 0, 1, 1]},
        "blend": "cubic",
        "name": "coons-1",
        "expected": {"surface": {"bezier": [[[0, 0, 0]]]}},
    });
    assert!(v.accepts(&coons), "{:?}", v.errors(&coons));
    let read = |p: &Value| Problem::read(p, &Limits::DEFAULT);
    assert!(read(&coons).is_ok());
    let wrong = [
        // a misspelled key
        changed(&coons, |p| {
            let b = p.as_object_mut().unwrap().remove("blend").unwrap();
            p["blned"] = b;
        }),
        // a JSON number with a fraction part
        changed(&coons, |p| p["c1"]["bezier"][1][0] = json!(0.5)),
        changed(&coons, |p| p["d2"]["knots"][1] = json!(0.5)),
        // a word that is not one
        changed(&coons, |p| p["blend"] = json!("quintic")),
        // an unknown operation, or none
        changed(&coons, |p| p["op"] = json!("cons")),
        changed(&coons, |p| {
            p.as_object_mut().unwrap().remove("op");
        }),
        // a key of another operation
        changed(&coons, |p| p["surface"] = json!({"expr": "(u, v, 0)"})),
        // a misspelled key of a curve, a point that is not a list, a negative degree
        changed(&coons, |p| p["c1"]["wieghts"] = json!([1, 1, 1])),
        changed(&coons, |p| p["c2"]["bezier"][0] = json!("origin")),
        changed(&coons, |p| p["d2"]["degree"] = json!(-2)),
        // a B-spline without its knots
        changed(&coons, |p| {
            p["d2"].as_object_mut().unwrap().remove("knots");
        }),
        // a string that is not a number (a letter is a parameter's, which the schema allows
        // and the reading refuses when undeclared)
        changed(&coons, |p| p["c1"]["bezier"][0][0] = json!("1/2 = a")),
        // a misspelled fixture key
        changed(&coons, |p| p["tilte"] = json!("Coons")),
    ];
    for p in &wrong {
        assert!(!v.accepts(p), "the schema accepts {p}");
        assert!(read(p).is_err(), "the reading accepts {p}");
    }
    // the error names the misspelled key
    let e = v.errors(&wrong[0]).unwrap();
    assert!(e.contains("blned"), "{e}");
    // a float elsewhere: an elevation, a parameter
    let elevate = json!({"op": "elevate", "curve": {"bezier": [[0, 0], [1, 2]]}, "by": 1});
    let evaluate = json!({"op": "evaluate", "curve": {"expr": "(t, t^2)"}, "params": [0, "1/2"]});
    for p in [&elevate, &evaluate] {
        assert!(v.accepts(p), "{:?}", v.errors(p));
    }
    for p in [
        changed(&elevate, |p| p["by"] = json!(1.5)),
        changed(&evaluate, |p| p["params"][1] = json!(0.5)),
    ] {
        assert!(!v.accepts(&p), "the schema accepts {p}");
        assert!(read(&p).is_err(), "the reading accepts {p}");
    }
}

#[test]
fn where_the_reading_is_lenient_the_schema_keeps_to_the_format() {
    // docs/format.md, Schema: what cagd reads but the format does not document
    let v = Validator::new(problem_schema());
    let quad = json!([[0, 0], [1, 2], [3, 3]]);
    let lenient = [
        json!({"op": "circle", "radius": null}),
        json!({"op": "coons", "c1": {"bezier": quad}, "blend": "bilinear"}),
        json!({"op": "interpolate", "basis": "spline", "points": quad, "params": [0, "1/2", 1]}),
        json!({"op": "elevate", "curve": {"bezier": quad, "expr": "(t, t)"}, "by": 1}),
        json!({"op": "elevate", "curve": {"bezier": quad, "degree": 2}, "by": 1}),
    ];
    for p in &lenient {
        assert!(Problem::read(p, &Limits::DEFAULT).is_ok(), "{p}");
        assert!(!v.accepts(p), "the schema accepts {p}");
    }
}
