//! The keys of the notes' examples go to students as they are: no internal id or file name of
//! the notes in any key (every example, both languages, every format), sources worded as the
//! notes' chapters ("Tema 6, §5 (ec. 19)"), the notation legend once a document, not once an
//! example, and no subscript of several letters that TeX would set as one letter and the rest
//! (`$c_cd$` is c_c d).

use cagd_keys::{
    example_latex, example_markdown, example_text, legend_latex, legend_markdown, legend_text, Lang,
};
use cagd_problem::{check_with_settings, Limits, Settings, Verdict};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// Every worked example (fixtures/), with its steps and without, with its fixture.
fn examples() -> Vec<(PathBuf, Value, Verdict)> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures");
    let mut out = Vec::new();
    for dir in ["ch5", "ch6", "slides", "beyond", "triangle"] {
        let mut files: Vec<PathBuf> = std::fs::read_dir(root.join(dir))
            .into_iter()
            .flatten()
            .flatten()
            .map(|e| e.path())
            .collect();
        files.sort();
        for f in files {
            let text = std::fs::read_to_string(&f).unwrap_or_default();
            let fixture: Value = serde_json::from_str(&text).unwrap_or_default();
            for steps in [false, true] {
                let settings = Settings {
                    limits: Limits::DEFAULT,
                    steps,
                };
                let v = check_with_settings(&fixture, &settings);
                out.push((f.clone(), fixture.clone(), v));
            }
        }
    }
    assert!(out.len() >= 80, "{} examples", out.len());
    out
}

fn keys(v: &Verdict, lang: Lang) -> [String; 3] {
    [
        example_text(v, lang),
        example_latex(v, lang),
        example_markdown(v, lang),
    ]
}

#[test]
fn no_id_or_file_name_in_any_key() {
    for (path, fixture, v) in examples() {
        let name = fixture["name"].as_str().unwrap();
        for lang in [Lang::En, Lang::Es] {
            for key in keys(&v, lang) {
                for machinery in [name, ".txt", "000_", "001_", "002_", "003_", "004_"] {
                    assert!(
                        !key.contains(machinery),
                        "{machinery} in the key of {}:\n{key}",
                        path.display()
                    );
                }
                for internal in ["docs/format.md", "\\texttt{", "(`"] {
                    assert!(
                        !key.contains(internal),
                        "{internal} in the key of {}:\n{key}",
                        path.display()
                    );
                }
            }
        }
    }
}

#[test]
fn sources_are_the_notes_chapters() {
    let mut worded = 0;
    for (path, fixture, v) in examples() {
        let source = fixture["source"].as_str().unwrap_or_default();
        let chapter = match source.get(..4) {
            Some("002_") => 5,
            Some("000_" | "001_" | "003_" | "004_") => 6,
            _ => continue,
        };
        let text = example_text(&v, Lang::Es);
        let line = text.lines().find(|l| l.starts_with("fuente: ")).unwrap();
        let opening = match source.get(..4) {
            Some("001_") => format!("fuente: Transparencias del tema {chapter}"),
            _ => format!("fuente: Tema {chapter}"),
        };
        assert!(line.starts_with(&opening), "{}: {line}", path.display());
        let en = example_text(&v, Lang::En);
        assert!(
            en.contains("source: Chapter ") || en.contains("source: Slides of chapter "),
            "{}: {en}",
            path.display()
        );
        if let Some(eq) = fixture["equation"].as_str().filter(|e| !e.is_empty()) {
            let number = eq.trim_matches(['(', ')']).replace(")-(", "-");
            assert!(
                line.contains(&format!("(ec. {number})"))
                    || line.contains(&format!("(ecs. {number})")),
                "{}: {line}",
                path.display()
            );
        }
        worded += 1;
    }
    assert!(worded >= 30, "{worded}");
    // a section of chapter 6 with its equation, in both languages
    let coons = examples()
        .into_iter()
        .find(|(p, _, _)| p.ends_with("ch6/07-coons-bezier.json"))
        .unwrap()
        .2;
    assert!(example_text(&coons, Lang::Es).contains("\nfuente: Tema 6, §5 (ecs. 18-19)\n"));
    assert!(example_text(&coons, Lang::En).contains("\nsource: Chapter 6, §5 (eqs. 18-19)\n"));
}

#[test]
fn the_notation_legend_once_a_document() {
    let all = examples();
    let verdicts: Vec<&Verdict> = all.iter().map(|(_, _, v)| v).collect();
    let sentences = [
        "Farin writes",
        "Farin escribe",
        "The notes' knots are Farin's",
        "Los nudos de los apuntes son los de Farin",
    ];
    for (path, _, v) in &all {
        for lang in [Lang::En, Lang::Es] {
            for key in keys(v, lang) {
                for s in sentences {
                    assert!(!key.contains(s), "{}: {s}", path.display());
                }
            }
        }
    }
    for lang in [Lang::En, Lang::Es] {
        for legend in [
            legend_text(verdicts.iter().copied(), lang),
            legend_latex(verdicts.iter().copied(), lang),
            legend_markdown(verdicts.iter().copied(), lang),
        ] {
            // the sentences the examples need (patches, B-splines; Bézier curves when a
            // formula of curves is used), each once
            let n = legend.matches("Farin").count();
            assert!((2..=3).contains(&n), "{legend}");
        }
    }
    assert_eq!(legend_text([] as [&Verdict; 0], Lang::Es), "");
}

/// A `_` not escaped (`\_`) followed by two letters or digits without braces.
fn unbraced_subscript(latex: &str) -> Option<&str> {
    latex.match_indices('_').find_map(|(i, _)| {
        let escaped = latex[..i].ends_with('\\');
        let after = &latex[i + 1..];
        let run = after
            .find(|c: char| !c.is_ascii_alphanumeric())
            .unwrap_or(after.len());
        let boundary = |k: usize| (k..=i).find(|k| latex.is_char_boundary(*k)).unwrap_or(i);
        let end = (i + 1 + run..=latex.len())
            .find(|k| latex.is_char_boundary(*k))
            .unwrap_or(latex.len());
        (!escaped && run >= 2).then(|| &latex[boundary(i.saturating_sub(20))..end])
    })
}

#[test]
fn no_subscript_of_two_letters_without_braces() {
    assert!(unbraced_subscript("$c_cd$").is_some());
    assert!(unbraced_subscript("$c_{cd}$ $b_i$ \\_ab").is_none());
    for (path, _, v) in examples() {
        for lang in [Lang::En, Lang::Es] {
            let tex = example_latex(&v, lang);
            if let Some(at) = unbraced_subscript(&tex) {
                panic!("{}: `{at}`", path.display());
            }
        }
    }
    for lang in [Lang::En, Lang::Es] {
        let verdicts: Vec<Verdict> = examples().into_iter().map(|(_, _, v)| v).collect();
        assert_eq!(unbraced_subscript(&legend_latex(&verdicts, lang)), None);
    }
}
