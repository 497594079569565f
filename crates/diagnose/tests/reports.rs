//! One diagnosed report per operation family: every `tests/reports/*.json` (a student's
//! problem, the student's wrong answer under `expected`) is diagnosed, and its key pinned in
//! English and Spanish (text) and in Spanish (Markdown); each report names at least one
//! mistake. The LaTeX of each, in both languages, compiles with pdflatex with no overfull box
//! where pdflatex is installed (`.ci/latex-check` installs it).

// the helpers beside the tests panic with what failed, as tests do
#![allow(
    clippy::indexing_slicing,
    clippy::panic,
    clippy::expect_used,
    clippy::unwrap_used
)]

use cagd_diagnose::diagnose;
use cagd_keys::{example_latex, example_markdown, example_text, latex_document, Lang};
use cagd_problem::{Limits, Settings, Verdict};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

/// Every report's problem, by its file's name (`coons`), in the order of the names.
fn reports() -> Vec<(String, Value)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/reports");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("tests/reports")
        .map(|e| e.expect("an entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    files
        .into_iter()
        .map(|f| {
            let name = f.file_stem().unwrap().to_string_lossy().into_owned();
            let text = std::fs::read_to_string(&f).unwrap();
            let problem = serde_json::from_str(&text)
                .unwrap_or_else(|e| panic!("{}: not JSON: {e}", f.display()));
            (name, problem)
        })
        .collect()
}

/// The diagnosed verdict of a report.
fn diagnosed(name: &str, problem: &Value) -> Verdict {
    let settings = Settings {
        limits: Limits::DEFAULT,
        steps: false,
    };
    let v = diagnose(problem, &settings);
    assert!(v.answer.is_ok(), "{name}: the problem has no answer: {v:?}");
    v
}

#[test]
fn every_report_names_a_mistake_and_is_pinned() {
    let reports = reports();
    assert!(
        reports.iter().any(|(name, _)| name == "coons"),
        "the Coons report"
    );
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path("../../../snapshots");
    settings.set_prepend_module_to_snapshot(false);
    settings.bind(|| {
        for (name, problem) in &reports {
            let v = diagnosed(name, problem);
            let a = v.assessment.as_deref().expect("an assessment");
            assert!(!a.correct(), "{name}: the student's answer is correct");
            assert!(
                !a.mistakes().is_empty(),
                "{name}: no diagnosis: {}",
                example_text(&v, Lang::En)
            );
            insta::assert_snapshot!(format!("report__{name}__en"), example_text(&v, Lang::En));
            insta::assert_snapshot!(format!("report__{name}__es"), example_text(&v, Lang::Es));
            insta::assert_snapshot!(
                format!("report__{name}__es_md"),
                example_markdown(&v, Lang::Es)
            );
        }
    });
}

/// Whether pdflatex can be run here.
fn pdflatex() -> bool {
    Command::new("pdflatex")
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

/// Compiles `doc` in a fresh folder named after `name`; the folder, or pdflatex's errors and
/// overfull boxes.
fn compile(name: &str, doc: &str) -> Result<PathBuf, String> {
    let dir = std::env::temp_dir().join(format!("cagd-report-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("report.tex"), doc).unwrap();
    let run = Command::new("pdflatex")
        .args(["-interaction=nonstopmode", "-halt-on-error", "report.tex"])
        .current_dir(&dir)
        .output()
        .unwrap();
    let log = std::fs::read_to_string(dir.join("report.log")).unwrap_or_default();
    if !run.status.success() {
        let errors: Vec<&str> = log
            .lines()
            .skip_while(|l| !l.starts_with('!'))
            .take(20)
            .collect();
        return Err(format!("{name}: pdflatex failed:\n{}", errors.join("\n")));
    }
    let overfull: Vec<&str> = log
        .lines()
        .filter(|l| l.starts_with("Overfull \\hbox"))
        .collect();
    if !overfull.is_empty() {
        return Err(format!(
            "{name}: overfull boxes in {}:\n{}",
            dir.display(),
            overfull.join("\n")
        ));
    }
    Ok(dir)
}

#[test]
fn every_report_compiles_without_an_overfull_box() {
    if !pdflatex() {
        eprintln!("pdflatex is not installed: the reports' LaTeX is not compiled");
        return;
    }
    let mut failures = Vec::new();
    for (name, problem) in reports() {
        let v = diagnosed(&name, &problem);
        for (code, lang) in [("en", Lang::En), ("es", Lang::Es)] {
            let doc = latex_document(&name, &[example_latex(&v, lang)], lang);
            if let Err(e) = compile(&format!("{name}-{code}"), &doc) {
                failures.push(e);
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}

#[test]
fn the_keys_own_answer_is_correct_with_no_diagnosis() {
    for (name, mut problem) in reports() {
        let v = diagnosed(&name, &problem);
        let answer = v.answer.as_ref().unwrap();
        let mut expected = serde_json::Map::new();
        for (q, x) in &answer.result {
            expected.insert(q.name().into_owned(), x.to_json());
        }
        problem["expected"] = Value::Object(expected);
        let v = diagnosed(&name, &problem);
        let a = v.assessment.as_deref().expect("an assessment");
        assert!(a.correct() && a.mistakes().is_empty(), "{name}: {a:?}");
        for (lang, correct, mistake) in [
            (Lang::En, "verdict: correct answer: ", "mistake"),
            (Lang::Es, "veredicto: respuesta correcta: ", "error"),
        ] {
            let key = example_text(&v, lang);
            assert!(key.contains(correct), "{name}:\n{key}");
            let report = key.split(correct).nth(1).unwrap();
            assert!(!report.contains(mistake), "{name}: diagnosed:\n{report}");
        }
    }
}
