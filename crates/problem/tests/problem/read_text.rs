//! `Problem::read_text` (a problem read straight from its text, as `cagd solve` and Python's
//! `solve(dict)` read it) agrees with `Problem::read` (from its JSON value) on every fixture,
//! every example of docs/format.md and many broken variants of them: the same problem, or the
//! same error with the same field path, under the default limits and under tight ones.

use crate::fixtures::fixture_files;
use crate::format_doc::doc_examples;
use cagd_problem::message::contract::Contract;
use cagd_problem::problem::serde_error;
use cagd_problem::{Limits, Problem, ProblemError};
use serde_json::{json, Value};

/// Both readings of `text` under `limits`.
fn both(text: &str, limits: &Limits) {
    let invalid = |e: serde_json::Error| {
        let why = Box::new(serde_error(&e));
        ProblemError::at("", Contract::CannotRead { why })
    };
    let from_text = Problem::read_text(text, limits, invalid);
    let from_value = match serde_json::from_str::<Value>(text) {
        Ok(v) => Problem::read(&v, limits),
        Err(e) => Err(invalid(e)),
    };
    assert_eq!(from_text, from_value, "{text}");
}

/// Variants of a problem: each top-level value replaced by other kinds, its lists lengthened
/// or shortened, its first number written in other ways, an unknown key, a key removed.
fn variants(p: &Value) -> Vec<String> {
    let mut out = vec![p.to_string()];
    let Some(map) = p.as_object() else {
        return out;
    };
    let others = [
        json!(null),
        json!(true),
        json!(1.5),
        json!("-0"),
        json!(-0.0),
        json!([]),
        json!([[1, 2, 3]]),
        json!({"bezier": [[1, 2]]}),
        json!("x^2"),
        json!(123456789012345678901234567890u128),
    ];
    for key in map.keys() {
        let mut q = map.clone();
        q.remove(key);
        out.push(Value::Object(q).to_string());
        for other in &others {
            let mut q = map.clone();
            q.insert(key.clone(), other.clone());
            out.push(Value::Object(q).to_string());
        }
        // the value with its lists changed at every depth
        let mut v = map[key].clone();
        for _ in 0..4 {
            let mut q = map.clone();
            if let Some(items) = v.as_array_mut() {
                let mut longer = items.clone();
                longer.extend(items.iter().cloned());
                q.insert(key.clone(), Value::Array(longer));
                out.push(Value::Object(q.clone()).to_string());
                items.truncate(items.len().saturating_sub(1));
                q.insert(key.clone(), Value::Array(items.clone()));
                out.push(Value::Object(q).to_string());
                let Some(first) = items.first().cloned() else {
                    break;
                };
                v = first;
            } else {
                break;
            }
        }
    }
    let mut q = map.clone();
    q.insert("surfase".into(), json!(1));
    out.push(Value::Object(q).to_string());
    // a key written twice (the value keeps the last)
    let text = p.to_string();
    if let Some(rest) = text.strip_prefix('{') {
        out.push(format!("{{\"op\": \"evaluate\", {rest}"));
    }
    // the numbers written as floats, and with a root
    out.push(text.replace("\"1/3\"", "0.3333").replace(", 1]", ", 1.0]"));
    out.push(
        text.replace("\"1/2\"", "\"sqrt3/2\"")
            .replace(", 2]", ", \"sqrt2\"]"),
    );
    out
}

#[test]
fn read_text_agrees_with_read() {
    let mut problems: Vec<Value> = fixture_files()
        .iter()
        .map(|p| serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap())
        .collect();
    problems.extend(
        doc_examples()
            .iter()
            .map(|(_, text)| serde_json::from_str::<Value>(text).unwrap()),
    );
    assert!(problems.len() > 80);
    let tight = Limits {
        max_points: 5,
        max_degree: 3,
        max_digits: 6,
        ..Limits::DEFAULT
    };
    let mut count = 0;
    for p in &problems {
        for text in variants(p) {
            both(&text, &Limits::DEFAULT);
            both(&text, &tight);
            count += 1;
        }
    }
    assert!(count > 2000, "{count}");
    // not objects, not JSON, nested deeper than the reader goes
    for text in [
        "[1]",
        "3",
        "\"op\"",
        "{\"op\": ",
        "{}",
        "{\"op\": null}",
        "{\"op\": \"evaluat\"}",
    ] {
        both(text, &Limits::DEFAULT);
    }
    let deep = |n: usize| format!("{}1{}", "[".repeat(n), "]".repeat(n));
    for n in [120, 125, 126, 127, 128, 129, 200] {
        let text = format!(
            "{{\"op\": \"closed_form\", \"surface\": {{\"expr\": \"(u, v, 0)\"}}, \"expected\": {}}}",
            deep(n)
        );
        both(&text, &Limits::DEFAULT);
        let text = format!(
            "{{\"op\": \"closed_form\", \"surface\": {{\"expr\": \"(u, v, 0)\"}}, \"values\": {{\"R\": {}}}, \"parameters\": [\"R\"]}}",
            deep(n)
        );
        both(&text, &Limits::DEFAULT);
    }
}
