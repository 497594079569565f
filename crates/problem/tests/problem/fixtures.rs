//! Every worked example of the notes, from `fixtures/`: solved, compared exactly with its
//! expected answer, and its answer key pinned by an insta snapshot in `snapshots/`.

use cagd_keys::{example_text, Lang};
use cagd_problem::{check, solve};
use std::path::{Path, PathBuf};

pub fn fixture_files() -> Vec<PathBuf> {
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
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures");
    let mut out = Vec::new();
    walk(&root, &mut out);
    out
}

fn read(path: &Path) -> serde_json::Value {
    let text = std::fs::read_to_string(path).expect("readable fixture");
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

#[test]
fn there_are_fixtures_for_both_chapters() {
    let files = fixture_files();
    assert!(
        files
            .iter()
            .filter(|p| p.to_string_lossy().contains("/ch5/"))
            .count()
            >= 9
    );
    assert!(
        files
            .iter()
            .filter(|p| p.to_string_lossy().contains("/ch6/"))
            .count()
            >= 11
    );
}

#[test]
fn every_fixture_reproduces_its_exact_answer() {
    let mut failures = Vec::new();
    for path in fixture_files() {
        let fixture = read(&path);
        let verdict = check(&fixture);
        // a fixture without an exact answer (expected, errata or formula) checks nothing
        if !verdict.checked {
            failures.push(format!("{}: no expected answer to check", path.display()));
        }
        if !verdict.passed() {
            failures.push(format!(
                "{}: {}",
                path.display(),
                cagd_keys::verdict_text(&verdict, Lang::En)
            ));
        }
    }
    assert!(
        failures.is_empty(),
        "fixtures that fail:\n{}",
        failures.join("\n")
    );
}

#[test]
fn every_fixture_answer_key_is_pinned() {
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path("../../../../snapshots");
    settings.set_prepend_module_to_snapshot(false);
    settings.bind(|| {
        for path in fixture_files() {
            let fixture = read(&path);
            let name = fixture["name"].as_str().expect("fixture name").to_string();
            let verdict = check(&fixture);
            insta::assert_snapshot!(format!("example__{name}"), example_text(&verdict, Lang::En));
            // and in Spanish, as the notes write it
            insta::assert_snapshot!(
                format!("example_es__{name}"),
                example_text(&verdict, Lang::Es)
            );
        }
    });
}

#[test]
fn answers_feed_back_as_problems() {
    // A surface in an answer has the input shape: solving closed_form on it gives the same
    // closed form as on the original problem.
    for path in fixture_files() {
        let fixture = read(&path);
        let Ok(answer) = solve(&fixture) else {
            continue;
        };
        let json = answer.to_json(false);
        if let Some(surface) = json["result"].get("surface") {
            if surface.get("bspline").is_some() {
                continue;
            }
            let mut problem = serde_json::json!({"op": "closed_form", "surface": surface});
            if let Some(parameters) = json.get("parameters") {
                problem["parameters"] = parameters.clone();
            }
            let again = solve(&problem).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            assert!(again.get("closed_form").is_some(), "{}", path.display());
        }
    }
}

/// A formula fixture's errata are the ones found by computing, compared as values: a recorded
/// erratum written another way passes; an unrecorded difference, or a recorded erratum the
/// computation does not find, is a mismatch. The (25) erratum is one of scale: recorded in the
/// notes' factored form, its factor mn = 4 is what the check verifies.
#[test]
fn formula_errata_are_found_by_computing_and_compared_as_values() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures");
    let fixture = read(&root.join("ch5/14-formula-corner-normal.json"));
    let verdict = check(&fixture);
    assert!(verdict.passed(), "{:?}", verdict.mismatches);
    assert_eq!(fixture["errata"][0]["kind"], "scale");

    // the same erratum recorded as a wrong value, with the expanded values, its terms in
    // another order and with `*`: the same values
    let printed = "(y_{0,0} z_{1,0} - y_{0,0} z_{0,1} + y_{0,1} z_{0,0} - y_{0,1} z_{1,0} - y_{1,0} z_{0,0} + y_{1,0} z_{0,1}, x_{0,0} z_{0,1} - x_{0,0} z_{1,0} - x_{0,1} z_{0,0} + x_{0,1} z_{1,0} + x_{1,0} z_{0,0} - x_{1,0} z_{0,1}, x_{0,0} y_{1,0} - x_{0,0} y_{0,1} + x_{0,1} y_{0,0} - x_{0,1} y_{1,0} - x_{1,0} y_{0,0} + x_{1,0} y_{0,1})";
    let exact = "(4 y_{0,0} z_{1,0} - 4 y_{0,0} z_{0,1} + 4 y_{0,1} z_{0,0} - 4 y_{0,1} z_{1,0} - 4 y_{1,0} z_{0,0} + 4 y_{1,0} z_{0,1}, 4 x_{0,0} z_{0,1} - 4 x_{0,0} z_{1,0} - 4 x_{0,1} z_{0,0} + 4 x_{0,1} z_{1,0} + 4 x_{1,0} z_{0,0} - 4 x_{1,0} z_{0,1}, 4 x_{0,0} y_{1,0} - 4 x_{0,0} y_{0,1} + 4 x_{0,1} y_{0,0} - 4 x_{0,1} y_{1,0} - 4 x_{1,0} y_{0,0} + 4 x_{1,0} y_{0,1})";
    let mut reordered = fixture.clone();
    reordered["errata"][0]["kind"] = serde_json::Value::String("value".into());
    reordered["errata"][0]["printed"] = serde_json::Value::String(printed.into());
    let inner = exact.trim_start_matches('(').trim_end_matches(')');
    let coordinates: Vec<String> = inner
        .split(", ")
        .map(|c| {
            let mut terms: Vec<String> = c
                .replace(" - ", " + -")
                .split(" + ")
                .map(|t| t.replace("4 ", "4*"))
                .collect();
            terms.reverse();
            terms.join(" + ")
        })
        .collect();
    let rewritten = format!("({})", coordinates.join(", "));
    assert_ne!(rewritten, exact);
    reordered["errata"][0]["exact"] = serde_json::Value::String(rewritten);
    let verdict = check(&reordered);
    assert!(verdict.passed(), "{:?}", verdict.mismatches);

    // an erratum of scale recorded with another factor is not the one found
    let mut scale = fixture.clone();
    scale["errata"][0]["factor"] = serde_json::Value::String("2".into());
    assert!(!check(&scale).passed());

    // the erratum not recorded: the difference is found and reported
    let mut unrecorded = fixture.clone();
    unrecorded["errata"] = serde_json::json!([]);
    let verdict = check(&unrecorded);
    assert!(!verdict.passed());
    assert!(
        verdict
            .mismatches
            .iter()
            .any(|m| m.to_string().contains("that the fixture does not record")),
        "{:?}",
        verdict.mismatches
    );

    // the formula printed right (with the factor m n = 4): the recorded erratum is not found
    let mut corrected = fixture.clone();
    for k in 0..3 {
        let f = corrected["formula"]["printed"][k]
            .as_str()
            .expect("formula")
            .to_string();
        corrected["formula"]["printed"][k] = serde_json::Value::String(format!("4*({f})"));
    }
    let verdict = check(&corrected);
    assert!(!verdict.passed());
    assert!(
        verdict.mismatches.iter().any(|m| m
            .to_string()
            .contains("recorded as an erratum, but the formula as printed gives")),
        "{:?}",
        verdict.mismatches
    );

    // an erratum recorded with a wrong value is not the one found
    let mut wrong = reordered;
    wrong["errata"][0]["exact"] = serde_json::Value::String("(0, 0, 0)".into());
    assert!(!check(&wrong).passed());
}
