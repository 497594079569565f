//! The notes' terminology in everything a Spanish reader gets: every worked example (the
//! fixtures), every operation of `docs/format.md` and the sample problems of
//! `examples/problemas.json`, with and without steps, as text, LaTeX
//! and Markdown keys; a refusal of every operation whose words name a surface, a fit or a
//! criterion; every Spanish message template of the sources, and every string of them. None
//! may use a word the glossary of the notes replaces ([`FORBIDDEN`]).

use crate::format_doc::doc_examples;
use cagd_keys::{example_latex, example_markdown, example_text, Lang};
use cagd_problem::{check_with_settings, Limits, Settings, Verdict};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};

/// The words the notes never use, each with the notes' word a Spanish text says instead.
///
/// From the glossary of the course notes (their `README.md`, section "Glossary", kept beside
/// this repository as `../shared/notes/README.md`: superficie, malla de
/// control, sucesión de nudos, tramos, envoltura convexa, derivada transversal, semiesfera,
/// recinto...) and the notes' own wording (a surface is a "superficie", a piece of a B-spline
/// surface a "trozo" or "tramo"; the formula of a surface its "parametrización"; interpolated
/// points "puntos dato"; the condition (9) of a developable surface a "criterio"). The notes
/// are not part of this repository, so the list is written here. English words of the same
/// things are listed too: a Spanish text that says them has left English behind.
const FORBIDDEN: &[(&str, &str)] = &[
    (
        "parche",
        "superficie (un trozo o tramo de una superficie a trozos)",
    ),
    ("parches", "superficies (trozos, tramos)"),
    ("forma cerrada", "parametrización"),
    ("formas cerradas", "parametrizaciones"),
    ("puntos de datos", "puntos dato"),
    ("punto de datos", "punto dato"),
    ("test", "criterio (el criterio de desarrollabilidad)"),
    ("tests", "criterios"),
    ("envolvente convexa", "envoltura convexa"),
    ("vector de nudos", "sucesión de nudos"),
    ("derivada cruzada", "derivada transversal"),
    ("hemisferio", "semiesfera"),
    ("nodo", "nudo"),
    ("nodos", "nudos"),
    ("patch", "superficie"),
    ("patches", "superficies"),
    ("closed form", "parametrización"),
    ("data points", "puntos dato"),
    ("knot vector", "sucesión de nudos"),
    ("convex hull", "envoltura convexa"),
    ("blossom", "forma polar"),
];

/// The words of [`FORBIDDEN`] that are Spanish: no string of the sources, in any language,
/// says them.
const SPANISH: &[&str] = &[
    "parche",
    "parches",
    "forma cerrada",
    "formas cerradas",
    "puntos de datos",
    "punto de datos",
    "test de",
    "envolvente convexa",
    "vector de nudos",
    "derivada cruzada",
    "hemisferio",
];

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

/// The words of one line of a key, lower case, without what is quoted (`identifiers`, "the
/// user's strings") and, in LaTeX, without commands, environments' names and `\texttt{...}`.
fn words(line: &str) -> Vec<String> {
    let mut plain = String::new();
    let mut quote: Option<char> = None;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match (quote, c) {
            (Some(q), c) if c == q => quote = None,
            (Some(_), _) => {}
            (None, '`' | '"') => quote = Some(c),
            (None, '\\') => {
                let mut name = String::new();
                while let Some(n) = chars.peek().filter(|n| n.is_ascii_alphabetic()) {
                    name.push(*n);
                    chars.next();
                }
                if matches!(name.as_str(), "begin" | "end" | "texttt") {
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

/// The forbidden words of `text`, line by line, with the words that replace them.
fn forbidden_in(text: &str) -> Vec<String> {
    let mut found = Vec::new();
    for line in text.lines() {
        let ws = words(line);
        for (bad, good) in FORBIDDEN {
            let bad: Vec<&str> = bad.split(' ').collect();
            if ws
                .windows(bad.len())
                .any(|w| w.iter().zip(&bad).all(|(a, b)| a == b))
            {
                found.push(format!("«{}» (say: {good}) in: {line}", bad.join(" ")));
            }
        }
    }
    found
}

/// Every format of a verdict's key in Spanish; each line with a forbidden word is kept in
/// `found`.
fn scan(what: &str, v: &Verdict, found: &mut Vec<String>) {
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
        found.extend(
            forbidden_in(&key)
                .into_iter()
                .map(|f| format!("{what}: {f}")),
        );
    }
}

fn assert_none(found: &[String]) {
    let mut found = found.to_vec();
    found.sort();
    found.dedup();
    assert!(
        found.is_empty(),
        "{} lines not in the notes' words:\n{}",
        found.len(),
        found.join("\n")
    );
}

fn settings(steps: bool) -> Settings {
    Settings {
        limits: Limits::DEFAULT,
        steps,
    }
}

/// The list finds what it forbids, in text and in LaTeX, and leaves quoted names alone.
#[test]
fn the_list_finds_what_it_forbids() {
    for bad in SPANISH {
        assert!(FORBIDDEN.iter().any(|(f, _)| bad.starts_with(f)), "{bad}");
    }
    assert_eq!(forbidden_in("el parche de Coons").len(), 1);
    assert_eq!(forbidden_in("Dos Parches bicuadráticos").len(), 1);
    assert_eq!(forbidden_in("la forma\\,cerrada").len(), 1);
    assert_eq!(forbidden_in("\\textbf{test de desarrollabilidad}").len(), 1);
    assert_eq!(forbidden_in("por 3 puntos de datos").len(), 1);
    assert!(forbidden_in("la forma polar (`blossom`) y \\texttt{blossom}").is_empty());
    assert!(forbidden_in("la superficie de Coons, sus trozos, sus puntos dato").is_empty());
    assert!(forbidden_in("\"parche\" es un dato").is_empty());
}

#[test]
fn every_example_in_the_notes_words() {
    let mut n = 0;
    let mut found = Vec::new();
    for dir in ["ch5", "ch6", "slides", "triangle", "beyond"] {
        let mut files: Vec<_> = std::fs::read_dir(root().join("fixtures").join(dir))
            .unwrap()
            .map(|e| e.unwrap().path())
            .filter(|p| p.extension().is_some_and(|e| e == "json"))
            .collect();
        files.sort();
        for f in files {
            let fixture: Value =
                serde_json::from_str(&std::fs::read_to_string(&f).unwrap()).unwrap();
            for steps in [false, true] {
                let v = check_with_settings(&fixture, &settings(steps));
                scan(&f.display().to_string(), &v, &mut found);
            }
            n += 1;
        }
    }
    assert!(n >= 40, "every fixture: {n}");
    assert_none(&found);
}

#[test]
fn every_operation_in_the_notes_words() {
    let examples = doc_examples();
    assert!(examples.len() >= cagd_problem::operations().len());
    let mut found = Vec::new();
    for (line, text) in &examples {
        let p: Value = serde_json::from_str(text).unwrap();
        for steps in [false, true] {
            let v = check_with_settings(&p, &settings(steps));
            scan(&format!("docs/format.md:{line}"), &v, &mut found);
        }
    }
    for p in sample_problems() {
        for steps in [false, true] {
            let v = check_with_settings(&p, &settings(steps));
            scan("examples/problemas.json", &v, &mut found);
        }
    }
    assert_none(&found);
}

/// The sample problems the README and `docs/guia.md` point to.
fn sample_problems() -> Vec<Value> {
    let text = std::fs::read_to_string(root().join("examples/problemas.json")).unwrap();
    serde_json::from_str(&text).unwrap()
}

/// The sample problems are answered; their keys in Spanish are scanned with the operations'.
#[test]
fn the_sample_problems_are_answered() {
    let problems = sample_problems();
    assert!(problems.len() >= 3);
    for p in &problems {
        let v = check_with_settings(p, &settings(true));
        assert!(v.answer.is_ok(), "{p}: {:?}", v.answer);
    }
}

/// A problem refused by each message that speaks of a surface, a
/// fit's data points, a parametrization or a criterion.
fn refused_problems() -> Vec<Value> {
    let square = json!([[[0, 0, 0], [1, 0, 0]], [[0, 1, 0], [1, 1, 1]]]);
    let spline = json!({"bspline": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]], [[2, 0, 0], [2, 1, 0]]],
        "degree": [1, 1], "knots": [[0, 1, 2], [0, 1]]});
    let quarter = json!({"bezier": [[1, 0, 0], [1, 1, 0], [0, 1, 0]], "weights": [1, 1, 2]});
    vec![
        json!({"op": "restrict", "surface": spline, "u": [0, 1], "v": [0, 1]}),
        json!({"op": "continuity", "first": {"bezier": square}, "second": {"bezier": square, "weights": [[1, 1], [1, 1]]}}),
        json!({"op": "developable", "surface": {"bezier": [[[0, 0, 0], [0, 1, 0], [0, 2, 1]], [[1, 0, 0], [1, 1, 0], [1, 2, 1]]]}}),
        json!({"op": "developable", "c1": {"bezier": [[0, 0, 0], [1, 0, 0]], "weights": [1, 2]}, "c2": {"expr": "(u, 1, 0)"}}),
        json!({"op": "coons", "c1": quarter, "c2": {"bezier": [[1, 0, 1], [1, 1, 1], [0, 1, 1]]},
            "d1": {"bezier": [[1, 0, 0], [1, 0, 1]]}, "d2": {"bezier": [[0, 1, 0], [0, 1, 1]]}}),
        json!({"op": "blossom", "surface": spline, "u": [0], "v": [0]}),
        json!({"op": "subdivide", "surface": {"bezier": square}}),
        json!({"op": "subdivide", "surface": {"bezier": square}, "u": 2}),
        json!({"op": "extract", "surface": {"bezier": square}}),
        json!({"op": "interpolate", "basis": "bspline", "degree": 2, "u": [0, 1], "v": [0, 1],
            "points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]]}),
        json!({"op": "interpolate", "degree": [1, 1], "params": [[0, 0], [1, 0]], "points": [[0, 0, 1], [1, 0, 1]]}),
        json!({"op": "approximate", "degree": [1, 1], "params": [[0, 0], [1, 0]], "points": [[0, 0, 1], [1, 0, 1]]}),
        json!({"op": "approximate", "degree": 2, "params": [0, 1], "points": [[0, 0], [1, 1]]}),
        json!({"op": "approximate", "degree": 2, "params": [0, 1, 2], "points": [[0, 0], [1, 1]]}),
        json!({"op": "interpolate", "basis": "bspline", "degree": 2, "end": "natural",
            "params": [0, 1, 2], "points": [[0, 0], [1, 1], [2, 0]]}),
        json!({"op": "graph", "f": "x^3*y", "degree": [1, 1]}),
        json!({"op": "reduce_degree", "triangle": {"triangle": [[[0]], [[1], [2]]]}, "by": 2}),
        json!({"op": "derivative", "triangle": {"triangle": [[[0]], [[1], [2]]]}, "at": {"u": 0}}),
    ]
}

/// The Spanish sentence of each refusal.
#[test]
fn every_refusal_in_the_notes_words() {
    let mut found = Vec::new();
    for p in refused_problems() {
        let v = check_with_settings(&p, &settings(false));
        let e = v.answer.as_ref().err();
        let e = e.unwrap_or_else(|| panic!("{p} is refused"));
        let es = cagd_words::Message::phrase(&e.message, Lang::Es).text();
        found.extend(forbidden_in(&es).into_iter().map(|f| format!("{p}: {f}")));
    }
    assert_none(&found);
}

/// The keys of the refusals, with the operation's name and the data's labels.
#[test]
fn every_refused_key_in_the_notes_words() {
    let mut found = Vec::new();
    for p in refused_problems() {
        let v = check_with_settings(&p, &settings(false));
        scan(&p.to_string(), &v, &mut found);
    }
    assert_none(&found);
}

/// The sources of the engine and the command line, or of `crates/keys` (read apart:
/// [`the_keys_templates_in_the_notes_words`]), each with its path.
fn sources(keys: bool) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut dirs = vec![root().join("crates")];
    while let Some(dir) = dirs.pop() {
        for entry in std::fs::read_dir(&dir).unwrap() {
            let path = entry.unwrap().path();
            let rel = path.strip_prefix(root()).unwrap().display().to_string();
            if path.is_dir() {
                // a test says what it forbids; the fuzz corpora and builds are not sources
                if !matches!(
                    path.file_name().and_then(|n| n.to_str()),
                    Some("tests" | "target" | "benches")
                ) {
                    dirs.push(path);
                }
            } else if path.extension().is_some_and(|e| e == "rs")
                && rel.starts_with("crates/keys/") == keys
            {
                let source = std::fs::read_to_string(&path).unwrap();
                out.push((rel, source));
            }
        }
    }
    out
}

/// The string literals of a source, in order: the text between unescaped
/// double quotes outside comments and character literals (no raw strings hold a message).
fn literals(source: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut chars = source.chars().peekable();
    let mut current: Option<String> = None;
    while let Some(c) = chars.next() {
        match (&mut current, c) {
            (Some(s), '\\') => {
                if let Some(n) = chars.next() {
                    s.push('\\');
                    s.push(n);
                }
            }
            (Some(_), '"') => out.extend(current.take()),
            (Some(s), c) => s.push(c),
            (None, '"') => current = Some(String::new()),
            (None, '/') if chars.peek() == Some(&'/') => {
                for n in chars.by_ref() {
                    if n == '\n' {
                        break;
                    }
                }
            }
            // a character literal ('"', '\'', 'a'); a lifetime has no closing quote
            (None, '\'') => {
                let mut ahead = chars.clone();
                let first = ahead.next();
                let skip = match (first, ahead.next(), ahead.next()) {
                    (Some('\\'), Some(_), Some('\'')) => 3,
                    (Some(_), Some('\''), _) => 2,
                    _ => 0,
                };
                for _ in 0..skip {
                    chars.next();
                }
            }
            (None, _) => {}
        }
    }
    out
}

/// The Spanish template of each `said(lang, "...", "...", ...)` of a source: the literal after
/// the English one.
fn said_templates(source: &str) -> Vec<String> {
    let mut out = Vec::new();
    for (n, piece) in source.split("said(").enumerate() {
        // a call: its first argument a language, its second a literal
        let call = piece.trim_start();
        let after_lang = call
            .trim_start_matches(|c: char| c.is_alphanumeric() || c == '_')
            .strip_prefix(',')
            .map(str::trim_start);
        if n == 0 || !after_lang.is_some_and(|rest| rest.starts_with('"')) {
            continue;
        }
        let ls = literals(piece);
        if let Some(es) = ls.get(1) {
            out.push(es.replace("\\n", " ").replace("\\\n", " "));
        }
    }
    out
}

/// Every Spanish template of the sources (the second string of each `said(lang, "English",
/// "Spanish", ...)`) without a forbidden word, and every string of the sources without a
/// forbidden Spanish word (the keys' labels and vocabulary are pairs of strings, not `said`).
fn templates_in_the_notes_words(keys: bool) {
    let mut found = Vec::new();
    let mut templates = 0;
    for (file, source) in sources(keys) {
        for t in said_templates(&source) {
            templates += 1;
            found.extend(forbidden_in(&t).into_iter().map(|f| format!("{file}: {f}")));
        }
        for literal in literals(&source) {
            let ws = format!(" {} ", words(&literal.replace("\\n", " ")).join(" "));
            for bad in SPANISH {
                if ws.contains(&format!(" {bad} ")) {
                    found.push(format!("{file}: «{bad}» in: {literal}"));
                }
            }
        }
    }
    assert!(templates >= if keys { 10 } else { 500 }, "{templates}");
    assert_none(&found);
}

#[test]
fn every_message_template_in_the_notes_words() {
    templates_in_the_notes_words(false);
}

#[test]
fn the_keys_templates_in_the_notes_words() {
    templates_in_the_notes_words(true);
}
