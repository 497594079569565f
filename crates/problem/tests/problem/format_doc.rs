//! Every example problem in `docs/format.md` (code blocks tagged `json problem`) is solved,
//! and must be answered without error.

use cagd_problem::solve;

pub fn doc_examples() -> Vec<(usize, String)> {
    let doc = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/format.md"))
        .expect("docs/format.md");
    let mut out = Vec::new();
    let mut current: Option<(usize, String)> = None;
    for (n, line) in doc.lines().enumerate() {
        let fence = line.trim();
        current = match current {
            None if fence == "```json problem" => Some((n + 1, String::new())),
            None => None,
            Some(block) if fence == "```" => {
                out.push(block);
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

#[test]
fn format_doc_has_one_example_per_operation() {
    let examples = doc_examples();
    for op in cagd_problem::operations() {
        assert!(
            examples
                .iter()
                .any(|(_, text)| text.contains(&format!("\"op\": \"{op}\""))),
            "docs/format.md has no runnable example of {op}"
        );
    }
}

#[test]
fn every_example_of_the_format_doc_is_answered() {
    let mut failures = Vec::new();
    for (line, text) in doc_examples() {
        let problem: serde_json::Value = match serde_json::from_str(&text) {
            Ok(v) => v,
            Err(e) => {
                failures.push(format!("docs/format.md:{line}: not JSON: {e}"));
                continue;
            }
        };
        if let Err(e) = solve(&problem) {
            failures.push(format!("docs/format.md:{line}: {e}"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The round trip of `cagd check`: the `result` of every example's answer, as `cagd solve
/// --format json` writes it (with its `remarks`, and with `--steps` its `steps` list and
/// `derivation`), fed back whole as the example's `expected`, passes. (A result with
/// `remarks` used to be refused: "`remarks`: not a result of this problem".)
#[test]
fn every_answer_of_the_format_doc_feeds_back_as_its_expected() {
    use cagd_problem::{check_with_settings, Limits, Settings};
    let mut failures = Vec::new();
    let mut with_remarks = 0;
    for (line, text) in doc_examples() {
        let problem: serde_json::Value = serde_json::from_str(&text).expect("example is JSON");
        for steps in [false, true] {
            let settings = Settings {
                limits: Limits::DEFAULT,
                steps,
            };
            let answer = check_with_settings(&problem, &settings)
                .answer
                .expect("answered");
            let result = answer.to_json(steps)["result"].clone();
            with_remarks += usize::from(result.get("remarks").is_some());
            let mut again = problem.clone();
            again["expected"] = result;
            let v = check_with_settings(&again, &Settings::default());
            if !v.passed() || !v.checked {
                failures.push(format!(
                    "docs/format.md:{line} (steps: {steps}): {:?} {:?}",
                    v.mismatches,
                    v.answer.err()
                ));
            }
        }
    }
    assert!(with_remarks >= 10, "results with remarks: {with_remarks}");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// What `expected` must hold: each key a result of the problem (or `steps`, `remarks`,
/// `derivation` in their shapes); anything else is a mismatch naming the key. (`"steps":
/// "x"` used to pass, checking nothing.)
#[test]
fn malformed_expectations_are_mismatches_naming_the_key() {
    use serde_json::json;
    let coons = json!({"op": "coons",
        "c1": {"bezier": [[0, 0, 0], [1, 0, 0]]}, "c2": {"bezier": [[0, 1, 0], [1, 1, 0]]},
        "d1": {"bezier": [[0, 0, 0], [0, 1, 0]]}, "d2": {"bezier": [[1, 0, 0], [1, 1, 0]]}});
    let surface =
        cagd_problem::solve(&coons).expect("coons").to_json(false)["result"]["surface"].clone();
    let mismatches = |expected: serde_json::Value| {
        let mut p = coons.clone();
        p["expected"] = expected;
        let v = cagd_problem::check(&p);
        assert!(v.checked && v.answer.is_ok());
        v.mismatches
    };
    let with = |k: &str, x: serde_json::Value| json!({"surface": surface.clone(), k: x});
    assert_eq!(
        mismatches(with("steps", json!("x"))),
        ["`steps`: the steps by name (an object) or the list an answer writes, found the string \"x\""]
    );
    assert_eq!(
        mismatches(with("steps", json!({}))),
        ["`steps`: an empty object checks no step; name the steps to check"]
    );
    assert_eq!(
        mismatches(with("steps", json!([{"name": "c_c"}]))),
        ["`steps[0]`: a step {\"name\": ..., \"value\": ...}, found an object"]
    );
    assert_eq!(
        mismatches(with("steps", json!([]))),
        ["`steps`: 0 steps expected, 3 computed (a list of steps is compared whole; an object of steps by name checks some)"]
    );
    assert_eq!(
        mismatches(with("remarks", json!("words"))),
        ["`remarks`: a list of strings (the answer's remarks, not compared), found the string \"words\""]
    );
    assert_eq!(
        mismatches(with("derivation", json!([1]))),
        ["`derivation`: a list of objects (the answer's worked solution, not compared), found a list of 1"]
    );
    assert_eq!(
        mismatches(with("sufrace", json!(1))),
        ["`sufrace`: not a result of this problem (`coons` gives `surface`, `closed_form`, `corners`)"]
    );
    assert_eq!(
        mismatches(json!({"remarks": ["any words"]})),
        ["`expected`: `remarks` and `derivation` are not compared, so this checks nothing; name the results to check (`coons` gives `surface`, `closed_form`, `corners`)"]
    );
    // remarks are words, not compared; the list of steps is compared name by name
    assert!(mismatches(with("remarks", json!(["other words"]))).is_empty());
    let steps = cagd_problem::check_with_settings(
        &coons,
        &cagd_problem::Settings {
            steps: true,
            ..Default::default()
        },
    )
    .answer
    .expect("coons")
    .to_json(true)["result"]["steps"]
        .clone();
    assert!(mismatches(with("steps", steps.clone())).is_empty());
    let mut swapped = steps.clone();
    swapped[0]["name"] = json!("c_d");
    assert_eq!(
        mismatches(with("steps", swapped)),
        ["`steps[0]`: expected the step `c_d`, computed `c_c`"]
    );
}
