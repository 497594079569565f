//! The text of a problem never runs: LaTeX keys and statement sheets written from problems
//! whose words were written to do harm compile with pdflatex (default settings), write no
//! file but their own, read no file but TeX's own and the figures, and show the words as
//! written.
//!
//! These tests run pdflatex, which `cargo test --workspace` does not require: they are
//! `#[ignore]`d there and run by `.ci/latex-check` (after it installs TeX Live) with
//! `cargo test -p cagd-keys --test tex -- --ignored`. Without pdflatex or pdftotext they fail,
//! never skip.

// the helpers beside the tests index JSON and panic with pdflatex's log, as tests do
#![allow(
    clippy::indexing_slicing,
    clippy::panic,
    clippy::expect_used,
    clippy::unwrap_used
)]

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::atomic::{AtomicUsize, Ordering};

use cagd_keys::{example_latex, latex_document, statement_document, statement_latex, tex, Lang};
use cagd_problem::{check, check_with_settings, Settings, Verdict};
use proptest::prelude::*;
use serde_json::{json, Value};

mod attacks;
mod random;

/// What pdflatex did with a document.
struct Compiled {
    dir: PathBuf,
    /// The files pdflatex read (`INPUT` lines of its `-recorder` file).
    inputs: Vec<String>,
    /// The files it wrote (`OUTPUT` lines).
    outputs: Vec<String>,
    /// The PDF's text (pdftotext).
    text: String,
}

static RUN: AtomicUsize = AtomicUsize::new(0);

/// A fresh folder under the system's temporary folder.
fn temp_dir(name: &str) -> PathBuf {
    let n = RUN.fetch_add(1, Ordering::SeqCst);
    let dir = std::env::temp_dir().join(format!("cagd-tex-{}-{n}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("a temporary folder");
    dir
}

/// Compiles `doc` as `key.tex` in `dir` with pdflatex at its default settings (nonstop, so an
/// error ends the run instead of waiting); panics, with the log's errors, unless it compiles.
fn compile_in(dir: &Path, doc: &str) -> Compiled {
    std::fs::write(dir.join("key.tex"), doc).expect("key.tex written");
    let run = Command::new("pdflatex")
        .args([
            "-interaction=nonstopmode",
            "-halt-on-error",
            "-recorder",
            "key.tex",
        ])
        .current_dir(dir)
        .output()
        .unwrap_or_else(|e| {
            panic!("pdflatex could not be run ({e}): install TeX Live (.ci/latex-check does)")
        });
    let log = std::fs::read_to_string(dir.join("key.log")).unwrap_or_default();
    assert!(
        run.status.success(),
        "pdflatex failed in {}:\n{}",
        dir.display(),
        log.lines()
            .skip_while(|l| !l.starts_with('!'))
            .take(20)
            .collect::<Vec<_>>()
            .join("\n")
    );
    let fls = std::fs::read_to_string(dir.join("key.fls")).expect("the recorder's file");
    let lines = |kind: &str| -> Vec<String> {
        fls.lines()
            .filter_map(|l| l.strip_prefix(kind))
            .map(str::to_string)
            .collect()
    };
    let text = Command::new("pdftotext")
        .args(["-enc", "UTF-8", "key.pdf", "-"])
        .current_dir(dir)
        .output()
        .unwrap_or_else(|e| {
            panic!("pdftotext could not be run ({e}): install poppler-utils (.ci/latex-check does)")
        });
    assert!(text.status.success(), "pdftotext failed");
    Compiled {
        dir: dir.to_path_buf(),
        inputs: lines("INPUT "),
        outputs: lines("OUTPUT "),
        text: String::from_utf8_lossy(&text.stdout).into_owned(),
    }
}

fn compile(name: &str, doc: &str) -> Compiled {
    compile_in(&temp_dir(name), doc)
}

impl Compiled {
    /// pdflatex wrote its own files and no other; read nothing outside TeX's tree, the folder
    /// and the figures; the PDF does not show the machine's name.
    fn harmless(&self) {
        for o in &self.outputs {
            assert!(
                ["key.aux", "key.log", "key.pdf", "key.fls"]
                    .iter()
                    .any(|k| o.ends_with(k)),
                "pdflatex wrote {o}"
            );
        }
        let written: Vec<String> = std::fs::read_dir(&self.dir)
            .expect("the folder")
            .filter_map(|e| e.ok())
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .filter(|n| !n.starts_with("key.") && !n.starts_with("fig"))
            .collect();
        assert!(written.is_empty(), "files written: {written:?}");
        for i in &self.inputs {
            assert!(
                i.starts_with("/usr/share/")
                    || i.starts_with("/var/lib/texmf")
                    || i.starts_with("/etc/texmf")
                    || i.starts_with("/usr/local/texlive")
                    || i.contains("texmf")
                    || i.starts_with("key.")
                    || i.starts_with("./key.")
                    || i.contains(".png"),
                "pdflatex read {i}"
            );
            assert!(!i.contains("hostname"), "pdflatex read {i}");
        }
        if let Ok(host) = std::fs::read_to_string("/etc/hostname") {
            let host = host.trim();
            if host.len() >= 4 {
                assert!(
                    !self.text.contains(host),
                    "the PDF shows the hostname {host}"
                );
            }
        }
    }
}

/// A key of these problems in one language: the sections and the document, titled `title`.
fn key(verdicts: &[Verdict], title: &str, lang: Lang) -> String {
    let sections: Vec<String> = verdicts.iter().map(|v| example_latex(v, lang)).collect();
    latex_document(title, &sections, lang)
}

/// The statement sheet of these problems in one language.
fn sheet(verdicts: &[Verdict], title: &str, lang: Lang) -> String {
    let sections: Vec<String> = verdicts.iter().map(|v| statement_latex(v, lang)).collect();
    let header = cagd_keys::SheetHeader {
        title: Some(title.to_string()),
        ..Default::default()
    };
    statement_document(&header, &sections, lang)
}

/// A problem with its worked solution (steps) checked.
fn with_steps(problem: &Value) -> Verdict {
    check_with_settings(problem, &Settings::default())
}

/// The machine's own LaTeX escaper is used by the tests too: a figure of `tex::graphics`.
fn figure_line(path: &str) -> String {
    format!(
        "\\begin{{center}}{}\\end{{center}}\n",
        tex::graphics(path, "width=2cm")
    )
}

/// A small PNG (1 × 1 pixel, grey).
const PNG: [u8; 67] = [
    0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A, 0x00, 0x00, 0x00, 0x0D, 0x49, 0x48, 0x44, 0x52,
    0x00, 0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x00, 0x00, 0x00, 0x00, 0x3A, 0x7E, 0x9B,
    0x55, 0x00, 0x00, 0x00, 0x0A, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9C, 0x63, 0x68, 0x00, 0x00, 0x00,
    0x82, 0x00, 0x81, 0x77, 0xCD, 0x72, 0xB6, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4E, 0x44, 0xAE,
    0x42, 0x60, 0x82,
];

fn evaluate() -> Value {
    json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 2]]}, "params": ["1/2"]})
}

/// `evaluate` with `key` set to `value`.
fn evaluate_with(key: &str, value: Value) -> Value {
    let mut p = evaluate();
    p[key] = value;
    p
}

fn both_languages(name: &str, verdicts: &[Verdict], title: &str) -> Vec<Compiled> {
    let mut out = Vec::new();
    for lang in [Lang::En, Lang::Es] {
        out.push(compile(name, &key(verdicts, title, lang)));
        out.push(compile(name, &sheet(verdicts, title, lang)));
    }
    out
}
