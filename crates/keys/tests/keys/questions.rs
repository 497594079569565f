//! The statement sheet asks each problem as a sentence in the notes' language: every
//! operation (the runnable examples of `docs/format.md`) and every worked example (the
//! fixtures), in English and in Spanish, gets a question that starts with a capital or `¿`,
//! ends with `.` or `?`, has no English left in Spanish, lists no result keys or labels, and
//! the sheet around it shows no value of the answer.

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

use cagd_keys::{latex, statement_latex, Lang, Question, Sentence};
use cagd_problem::{check_with_settings, Exact, Quantity, Settings, Verdict};
use cagd_words::Message;
use serde_json::Value;
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The runnable examples of docs/format.md (one line each) and the fixtures.
fn problems() -> Vec<Value> {
    let format = std::fs::read_to_string(root().join("docs/format.md")).unwrap();
    let mut out: Vec<Value> = format
        .lines()
        .filter(|l| l.starts_with("{\"op\":"))
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    let mut files = Vec::new();
    for dir in std::fs::read_dir(root().join("fixtures")).unwrap() {
        for f in std::fs::read_dir(dir.unwrap().path()).unwrap() {
            files.push(f.unwrap().path());
        }
    }
    files.sort();
    for f in files
        .iter()
        .filter(|f| f.extension().is_some_and(|e| e == "json"))
    {
        out.push(serde_json::from_str(&std::fs::read_to_string(f).unwrap()).unwrap());
    }
    out
}

fn verdicts() -> Vec<Verdict> {
    problems()
        .iter()
        .map(|p| {
            let mut v = check_with_settings(p, &Settings::default());
            v.index = Some(0);
            assert!(v.answer.is_ok(), "{p}: {:?}", v.answer);
            v
        })
        .collect()
}

/// A question of a problem, in `lang`.
fn question(v: &Verdict, lang: Lang) -> (Question, Sentence) {
    let q = Question::of(v.problem.as_deref().unwrap());
    let s = cagd_keys::said::said(&q, lang);
    (q, s)
}

/// Whether `word` is in `text` as a whole word.
fn has_word(text: &str, word: &str) -> bool {
    text.split(|c: char| !(c.is_alphanumeric() || c == '_'))
        .any(|w| w == word)
}

#[test]
fn every_operation_is_asked_as_a_sentence_in_both_languages() {
    let vs = verdicts();
    let mut ops: Vec<&str> = vs
        .iter()
        .map(|v| v.problem.as_ref().unwrap().op.name())
        .collect();
    ops.sort_unstable();
    ops.dedup();
    assert_eq!(
        ops.len(),
        cagd_problem::operations().len(),
        "every operation"
    );
    for v in &vs {
        let op = v.problem.as_ref().unwrap().op.name();
        let (q, _) = question(v, Lang::En);
        assert_eq!(cagd_words::check_both(&q), Ok(()), "{op}: {q:?}");
        for lang in [Lang::En, Lang::Es] {
            let text = q.phrase(lang).text();
            let first = text.chars().next().unwrap();
            assert!(
                first.is_uppercase() || first == '¿',
                "{op} {lang:?}: {text}"
            );
            assert!(text.ends_with('.') || text.ends_with('?'), "{op}: {text}");
            assert!(
                !text.contains("Find:") && !text.contains("Calcula:"),
                "{text}"
            );
            let english = cagd_words::english_in(&q.phrase(Lang::Es));
            assert!(english.is_empty(), "{op}: {english:?} in {text}");
            let answer = v.answer.as_ref().unwrap();
            for (quantity, value) in answer.result.iter().chain(&answer.steps) {
                // never a result key (an identifier of the JSON) ...
                let name = quantity.name();
                assert!(
                    !(name.contains('_') && text.contains(name.as_ref() as &str)),
                    "{op}: {name} in {text}"
                );
                if lang == Lang::Es {
                    assert!(!has_word(&text, &name), "{op}: {name} in {text}");
                }
                // ... and never a worded answer (the condition that fails a join)
                if let Exact::Sentence(m) = value {
                    let said = cagd_keys::said::message(m, lang).text;
                    assert!(!text.contains(&said), "{op}: {said} in {text}");
                }
            }
            // never the old list of labels: two labels of results in a row
            let labels: Vec<String> = answer
                .result
                .iter()
                .map(|(q, _)| label_text(q, v, lang))
                .collect();
            for a in &labels {
                for b in &labels {
                    if a != b {
                        let listed = format!("{a}, {b}");
                        assert!(!text.contains(&listed), "{op}: {listed} in {text}");
                    }
                }
            }
        }
    }
}

/// The text of a result's label in a key.
fn label_text(q: &Quantity, v: &Verdict, lang: Lang) -> String {
    cagd_keys::names::label(q, v.problem.as_deref(), lang).text
}

#[test]
fn the_sheet_shows_no_value_of_the_answer() {
    for v in verdicts() {
        let op = v.problem.as_ref().unwrap().op.name();
        let inputs: Vec<String> = v
            .problem
            .as_ref()
            .unwrap()
            .inputs()
            .iter()
            .map(|(_, x)| latex(x, Lang::Es))
            .collect();
        for lang in [Lang::En, Lang::Es] {
            let sheet = statement_latex(&v, lang);
            let answer = v.answer.as_ref().unwrap();
            for (quantity, value) in answer.result.iter().chain(&answer.steps) {
                let shown = latex(value, lang);
                // a value long enough to be an answer of its own, and not one of the data
                if shown.len() < 16 || inputs.iter().any(|i| i.contains(&shown)) {
                    continue;
                }
                assert!(
                    !sheet.contains(&shown),
                    "{op} {lang:?}: the value of {quantity:?} ({shown}) is in the sheet"
                );
            }
            // the sheet is the question and the data: no key's headings
            for word in [
                "Find:",
                "Calcula:",
                "verdict",
                "veredicto",
                "result",
                "resultado",
            ] {
                assert!(!sheet.contains(word), "{op}: {word} in {sheet}");
            }
        }
    }
}

#[test]
fn data_are_described_as_the_notes_describe_them() {
    let problems = problems();
    let sheet = |op: &str, lang: Lang| -> Vec<String> {
        problems
            .iter()
            .filter(|p| p["op"] == op)
            .map(|p| {
                let mut v = check_with_settings(p, &Settings::default());
                v.index = Some(0);
                statement_latex(&v, lang)
            })
            .collect()
    };
    let coons = sheet("coons", Lang::Es).join("\n");
    assert!(
        coons.contains("la curva de Bézier de polígono de control"),
        "{coons}"
    );
    assert!(coons.contains("superficie de Coons bilineal de las curvas borde"));
    let revolution = sheet("revolution", Lang::Es).join("\n");
    assert!(!revolution.contains("arcos ="), "{revolution}");
    assert!(!revolution.contains("\\text{arcos}"), "{revolution}");
    assert!(revolution.contains("un cuadrante") || revolution.contains("vuelta completa"));
    let interpolate = sheet("interpolate", Lang::Es).join("\n");
    assert!(!interpolate.contains("\\text{base}"), "{interpolate}");
    let all: String = problems
        .iter()
        .map(|p| {
            let mut v = check_with_settings(p, &Settings::default());
            v.index = Some(0);
            statement_latex(&v, Lang::Es)
        })
        .collect();
    assert!(
        all.contains("con pesos"),
        "a rational shape says its weights"
    );
    assert!(all.contains("con nudos"), "a B-spline says its knots");
    assert!(all.contains("la superficie de Bézier de malla de control"));
    assert!(!all.contains("bezier"), "no raw keyword");
}

/// The Markdown statement (the web page's) asks the LaTeX sheet's question with the same
/// data: no value of the answer, no raw HTML, its mathematics in `$...$`.
#[test]
fn the_markdown_statement_is_the_sheets() {
    use pulldown_cmark::{Event, Options, Parser};
    let mut all = String::new();
    for v in verdicts() {
        let op = v.problem.as_ref().unwrap().op.name();
        let inputs: Vec<String> = v
            .problem
            .as_ref()
            .unwrap()
            .inputs()
            .iter()
            .map(|(_, x)| latex(x, Lang::Es))
            .collect();
        for lang in [Lang::En, Lang::Es] {
            let md = cagd_keys::statement_markdown(&v, lang);
            let question = Question::of(v.problem.as_ref().unwrap())
                .phrase(lang)
                .words()
                .concat();
            let first = question.split_whitespace().next().unwrap_or_default();
            assert!(md.contains(first), "{op} {lang:?}: {first:?} not in {md}");
            let answer = v.answer.as_ref().unwrap();
            for (quantity, value) in answer.result.iter().chain(&answer.steps) {
                let shown = latex(value, lang);
                if shown.len() < 16 || inputs.iter().any(|i| i.contains(&shown)) {
                    continue;
                }
                assert!(!md.contains(&shown), "{op}: {quantity:?} ({shown}) in {md}");
            }
            let mut math = 0;
            for event in Parser::new_ext(&md, Options::ENABLE_MATH) {
                match event {
                    Event::Html(h) | Event::InlineHtml(h) => panic!("{op}: HTML {h} in {md}"),
                    Event::InlineMath(_) | Event::DisplayMath(_) => math += 1,
                    _ => {}
                }
            }
            assert!(math > 0 || !md.contains('$'), "{op}: {md}");
            if lang == Lang::Es {
                all += &md;
            }
        }
    }
    assert!(
        all.contains("la curva de Bézier de polígono de control"),
        "{all}"
    );
    assert!(all.contains("con pesos") && all.contains("con nudos"));
    assert!(!all.contains("bezier"), "no raw keyword");
}
