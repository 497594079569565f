//! The worked solution of every operation (`cagd solve --steps`), pinned in each language:
//! one problem per operation (and per kind where the steps differ: curve or patch, Bézier,
//! B-spline, rational), its key as text, Markdown and LaTeX, in English and in Spanish.

use cagd_keys::{example_latex, example_markdown, example_text, Lang};
use cagd_problem::{check_with_settings, Settings};
use serde_json::Value;

fn problems() -> Vec<(String, Value)> {
    let text = include_str!("steps.json");
    let list: Vec<(String, Value)> = serde_json::from_str(text).expect("steps.json");
    list
}

#[test]
fn every_operation_shows_its_steps() {
    let ops: std::collections::BTreeSet<String> = problems()
        .iter()
        .map(|(_, p)| p["op"].as_str().expect("op").to_string())
        .collect();
    for op in cagd_problem::operations() {
        assert!(ops.contains(*op), "no steps problem for {op}");
    }
    for (name, problem) in problems() {
        let verdict = check_with_settings(&problem, &Settings::default());
        let answer = verdict
            .answer
            .as_ref()
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(!answer.derivation.is_empty(), "{name}: no worked solution");
        assert!(
            answer
                .derivation
                .iter()
                .any(|s| matches!(s, cagd_problem::steps::Step::Formula { .. })),
            "{name}: no formula"
        );
        let json = answer.to_json(true);
        assert!(
            json["result"]["derivation"].is_array(),
            "{name}: no derivation in JSON"
        );
    }
}

#[test]
fn no_steps_without_steps() {
    let settings = Settings {
        steps: false,
        ..Settings::default()
    };
    for (name, problem) in problems() {
        let verdict = check_with_settings(&problem, &settings);
        let answer = verdict
            .answer
            .as_ref()
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(answer.derivation.is_empty(), "{name}: steps recorded");
        // the result is the same with and without steps
        let with = check_with_settings(&problem, &Settings::default());
        assert_eq!(
            with.answer.as_ref().map(|a| &a.result).ok(),
            Some(&answer.result),
            "{name}"
        );
    }
}

#[test]
fn every_operation_key_is_pinned_in_each_language() {
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path("../../../../snapshots");
    settings.set_prepend_module_to_snapshot(false);
    settings.bind(|| {
        for (name, problem) in problems() {
            let verdict = check_with_settings(&problem, &Settings::default());
            for (lang, code) in [(Lang::En, "en"), (Lang::Es, "es")] {
                let key = format!(
                    "{}\n---- markdown ----\n{}\n---- latex ----\n{}",
                    example_text(&verdict, lang),
                    example_markdown(&verdict, lang),
                    example_latex(&verdict, lang)
                );
                insta::assert_snapshot!(format!("steps__{name}__{code}"), key);
            }
        }
    });
}

/// `evaluate` at a long list of parameters works the steps of the first three points and says
/// once that the others are found in the same way; every point is still in the result.
#[test]
fn a_long_list_of_points_is_worked_for_the_first_three() {
    let problems = [
        serde_json::json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 2], [3, 3]]},
            "params": [0, "1/5", "2/5", "3/5", "4/5", 1]}),
        serde_json::json!({"op": "evaluate", "surface": {"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]},
            "params": [[0, 0], ["1/2", 0], [1, 0], [0, 1], ["1/2", 1], [1, 1]]}),
        serde_json::json!({"op": "evaluate", "triangle": {"triangle": [[[0, 0, 0]], [[1, 0, 0], [0, 1, 0]]]},
            "params": [[0, 0], ["1/2", 0], [1, 0], [0, 1], ["1/2", "1/2"], [0, "1/2"]]}),
    ];
    for problem in problems {
        let verdict = check_with_settings(&problem, &Settings::default());
        let text = example_text(&verdict, Lang::En);
        assert_eq!(text.matches("At the parameter").count(), 3, "{text}");
        assert!(
            text.contains(
                "The other 3 points are found in the same way (the steps are worked for the first 3)."
            ),
            "{text}"
        );
        let answer = verdict.answer.as_ref().expect("answered");
        let json = answer.to_json(false);
        assert_eq!(json["result"]["points"].as_array().map(Vec::len), Some(6));
        let es = example_text(&verdict, Lang::Es);
        assert!(
            es.contains("Los otros 3 puntos se obtienen del mismo modo"),
            "{es}"
        );
    }
}
