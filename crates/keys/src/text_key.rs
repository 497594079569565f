//! The plain-text answer key of a problem: name, source, input, steps, result and verdict.

use crate::assessment;
use crate::escape::escape_text;
use crate::parts::{key_parts, Item};
use crate::steps;
use crate::values::text;
use crate::verdict::{no_raise, RaiseWith};
use crate::vocabulary::{operation_words, Word};
use crate::Lang;
use cagd_contract::input::SurfaceIn;
use cagd_contract::{Exact, Verdict};

/// The plain text of an item's value.
fn item_text(it: &Item, lang: Lang) -> String {
    match (&it.value, it.data) {
        (
            Exact::Surface(SurfaceIn::Bezier {
                mesh,
                weights: None,
            }),
            true,
        ) => mesh.to_text(),
        (v, _) => match &it.words {
            Some(w) => escape_text(&w.text),
            None => text(v, lang),
        },
    }
}

/// The plain-text answer key of one problem (or checked example): name, source, input,
/// steps, result and verdict.
pub fn example_text(verdict: &Verdict, lang: Lang) -> String {
    example_text_with(verdict, lang, no_raise)
}

/// [`example_text`] written by a front end that says how to raise a limit.
pub fn example_text_with(verdict: &Verdict, lang: Lang, raise: RaiseWith) -> String {
    let k = key_parts(verdict, lang, raise);
    let mut out = String::new();
    out += &format!("== {}\n", escape_text(&k.heading));
    if !k.source.is_empty() {
        out += &format!("{}: {}\n", lang.word("source"), escape_text(&k.source));
    }
    if let Some(n) = &k.note {
        out += &format!("{}: {}\n", lang.word("note"), escape_text(n));
    }
    if verdict.problem.is_some() {
        out += &format!(
            "{}: {}\n",
            lang.word("operation"),
            escape_text(&operation_words(&k.op, lang))
        );
        out += &format!("{}:\n", lang.word("input"));
        for it in &k.inputs {
            out += &format!("  {}{}{}\n", it.label.text, it.sep(), item_text(it, lang));
        }
    }
    if verdict.answer.is_ok() {
        out += &steps::text_block(verdict, lang);
        if !k.steps.is_empty() {
            out += &format!("{}:\n", lang.word("steps"));
            for it in &k.steps {
                out += &format!("  {} = {}\n", it.label.text, value_lines(it, lang));
            }
        }
        out += &format!("{}:\n", lang.word("result"));
        for it in &k.result {
            out += &format!("  {} = {}\n", it.label.text, value_lines(it, lang));
        }
        for r in &k.remarks {
            out += &format!("  ({})\n", escape_text(&r.text));
        }
    }
    if let Some(e) = &k.error {
        out += &format!("{}: {}\n", lang.word("error"), escape_text(&e.text));
    }
    if verdict.checked {
        out += &format!(
            "{}: {}\n",
            lang.word("verdict"),
            escape_text(&k.verdict.text)
        );
        if let Some(a) = assessment::of(verdict) {
            out += &assessment::text_block(a, verdict.problem.as_deref(), lang);
        }
    }
    out
}

/// The text of an item's value, a mesh (or matrix) with one row per line; a sentence as it is.
fn value_lines(it: &Item, lang: Lang) -> String {
    match &it.words {
        Some(_) => item_text(it, lang),
        None => rows_on_lines(&item_text(it, lang)),
    }
}

/// A value of the text key with one mesh (or matrix) row per line, as the notes print them:
/// rows are the only things separated by `;`.
fn rows_on_lines(text: &str) -> String {
    text.replace("; ", ";\n      ")
}
