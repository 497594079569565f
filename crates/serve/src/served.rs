//! The problem set as served: each problem read once, its key computed once, its statement,
//! answer forms and figure written once in each language ([`ServedProblem`]); and the work of
//! the student's API on it (`/api/set`, `/api/read`, `/api/check`), as plain functions the
//! HTTP layer calls on its pool.

use crate::markdown;
use crate::message::ServeMessage;
use crate::template::{self, CellKind};
use crate::Reveal;
use cagd_diagnose::{diagnose_with, Key};
use cagd_keys::{assessment_markdown, example_markdown, statement_heading, statement_markdown};
use cagd_problem::diagnosis::{score, Assessed, Catalogued};
use cagd_problem::spec::{self, Num};
use cagd_problem::{Limits, Meta, Problem, ProblemError, Quantity, Settings, Verdict};
use cagd_render::{render_svg, Scene, SvgOptions};
use cagd_scalar::Print;
use cagd_words::{Lang, Message, Phrase};
use serde_json::{json, Map, Value};
use std::sync::Arc;

/// A value in each language.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct ByLang<T> {
    /// English.
    pub en: T,
    /// Spanish.
    pub es: T,
}

impl<T> ByLang<T> {
    /// Both, each made by `f`.
    pub fn make(f: impl Fn(Lang) -> T) -> ByLang<T> {
        ByLang {
            en: f(Lang::En),
            es: f(Lang::Es),
        }
    }

    /// The one in `lang`.
    pub fn get(&self, lang: Lang) -> &T {
        match lang {
            Lang::En => &self.en,
            Lang::Es => &self.es,
        }
    }
}

/// A set of problems as given: a title and each problem's JSON with a name for messages.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Set {
    /// The set's title (the default words when none).
    pub title: Option<String>,
    /// The problems: a name (for the startup report) and the problem's JSON.
    pub problems: Vec<(String, Value)>,
}

impl Set {
    /// A set from a document: an array of problems, an object `{"title", "problems": [...]}`,
    /// or one problem. Each problem is named by its `name`, else by its place (`problem 2`).
    pub fn from_json(doc: &Value) -> Set {
        let (title, list) = match doc {
            Value::Array(items) => (None, items.clone()),
            Value::Object(o)
                if !o.contains_key("op") && o.get("problems").is_some_and(Value::is_array) =>
            {
                (
                    o.get("title").and_then(Value::as_str).map(str::to_string),
                    o.get("problems")
                        .and_then(Value::as_array)
                        .cloned()
                        .unwrap_or_default(),
                )
            }
            one => (None, vec![one.clone()]),
        };
        let problems = list
            .into_iter()
            .enumerate()
            .map(|(i, p)| {
                let name = p
                    .get("name")
                    .and_then(Value::as_str)
                    .map_or_else(|| format!("problem {}", i + 1), str::to_string);
                (name, p)
            })
            .collect();
        Set { title, problems }
    }
}

/// One result the student answers: its kind, its label, and its form.
#[derive(Debug, Clone)]
pub struct ResultForm {
    /// Which result (its key in the answer: `surface`).
    pub quantity: Quantity,
    /// Its label in each language (plain text and LaTeX).
    pub label: ByLang<cagd_keys::Label>,
    /// The form (API.md: the answer's JSON, each leaf a cell).
    pub form: Value,
}

/// A problem as served: read once, its key once, its words and figure once.
pub struct ServedProblem {
    /// Its place in the set (from 0).
    pub index: usize,
    /// The problem, typed.
    pub problem: Arc<Problem>,
    /// Its key: the answer with steps, and every mistake's answer.
    pub key: Key,
    /// The results to answer.
    pub results: Vec<ResultForm>,
    /// Its title (the key's heading: "Problem 1: ...").
    pub title: ByLang<String>,
    /// The statement as HTML.
    pub statement_html: ByLang<String>,
    /// The figure of its data (SVG), or none.
    pub figure: ByLang<Option<String>>,
}

/// The set as served, and what was left out.
pub struct Served {
    /// The set's title.
    pub title: Option<String>,
    /// The problems served.
    pub problems: Vec<Arc<ServedProblem>>,
    /// The problems left out.
    pub left_out: Vec<LeftOut>,
}

/// A problem of the set left out: it does not read, or has no answer.
#[derive(Debug, Clone, PartialEq)]
pub struct LeftOut {
    /// Its place in the set as given (from 0).
    pub index: usize,
    /// Its name.
    pub name: String,
    /// Why.
    pub error: ProblemError,
}

/// The verdict of a key without a student: the key's answer on its problem, numbered.
fn key_verdict(key: &Key, index: usize) -> Verdict {
    Verdict {
        problem: Some(Arc::clone(&key.problem)),
        answer: key.answer.clone(),
        mismatches: Vec::new(),
        errata: Vec::new(),
        checked: false,
        index: Some(index),
        assessment: None,
    }
}

/// The figure of a problem's data in `lang`, or none (a problem in letters without values,
/// nothing to draw).
pub fn figure_svg(problem: &Problem, lang: Lang) -> Option<String> {
    let mut scene = Scene::from_problem(problem).ok()?;
    let title = match lang {
        Lang::Es => problem.meta.es.as_ref().and_then(|e| e.title.clone()),
        Lang::En => None,
    };
    if let Some(t) = title.or_else(|| problem.meta.title.clone()) {
        scene.title = Some(t);
    }
    render_svg(&scene, &SvgOptions::default()).ok()
}

impl ServedProblem {
    /// A problem read and keyed once; `None` with its error when it does not read or has no
    /// answer.
    pub fn new(index: usize, json: &Value, limits: &Limits) -> Result<ServedProblem, ProblemError> {
        let problem = Problem::read(json, limits)?;
        let settings = Settings {
            limits: *limits,
            steps: true,
        };
        let key = Key::new(&problem, &settings);
        let answer = key.answer.clone()?;
        let problem = Arc::clone(&key.problem);
        let results = answer
            .result
            .iter()
            .map(|(q, x)| ResultForm {
                quantity: q.clone(),
                label: ByLang::make(|lang| cagd_keys::names::label(q, Some(&problem), lang)),
                form: template::template(x),
            })
            .collect();
        let verdict = key_verdict(&key, index);
        let title = ByLang::make(|lang| statement_heading(&verdict, lang));
        let statement_html =
            ByLang::make(|lang| markdown::to_html(&statement_markdown(&verdict, lang)));
        let figure = ByLang::make(|lang| figure_svg(&problem, lang));
        Ok(ServedProblem {
            index,
            problem,
            key,
            results,
            title,
            statement_html,
            figure,
        })
    }

    /// The problem's JSON in `/api/set`; `figure` is its figure's URL when it has one.
    pub fn set_json(&self, lang: Lang, figure: Option<String>) -> Value {
        let results: Vec<Value> = self
            .results
            .iter()
            .map(|r| {
                let label = r.label.get(lang);
                json!({
                    "key": r.quantity.name(),
                    "label": label.text,
                    "label_tex": label.latex,
                    "template": r.form,
                })
            })
            .collect();
        json!({
            "index": self.index,
            "title": self.title.get(lang),
            "statement_html": self.statement_html.get(lang),
            "figure": figure,
            "results": results,
        })
    }

    /// The worked key (with steps) as HTML.
    pub fn solution_html(&self, lang: Lang) -> String {
        markdown::to_html(&example_markdown(&key_verdict(&self.key, self.index), lang))
    }
}

impl Served {
    /// Every problem of `set` read and keyed (in order), those that fail left out with their
    /// error.
    pub fn new(set: &Set, limits: &Limits) -> Served {
        let mut problems = Vec::new();
        let mut left_out = Vec::new();
        for (index, (name, json)) in set.problems.iter().enumerate() {
            match ServedProblem::new(problems.len(), json, limits) {
                Ok(p) => problems.push(Arc::new(p)),
                Err(error) => left_out.push(LeftOut {
                    index,
                    name: name.clone(),
                    error,
                }),
            }
        }
        Served {
            title: set.title.clone(),
            problems,
            left_out,
        }
    }

    /// The set's title in `lang`.
    pub fn title(&self, lang: Lang) -> String {
        cagd_keys::SheetHeader {
            title: self.title.clone(),
            ..Default::default()
        }
        .title_in(lang)
    }

    /// The JSON of `/api/set`; `figure(n)` is problem n's figure URL, when it has one.
    pub fn set_json(
        &self,
        lang: Lang,
        reveal: Reveal,
        figure: &dyn Fn(&ServedProblem) -> Option<String>,
    ) -> Value {
        let problems: Vec<Value> = self
            .problems
            .iter()
            .map(|p| p.set_json(lang, figure(p)))
            .collect();
        json!({
            "lang": lang_code(lang),
            "reveal": reveal.name(),
            "title": self.title(lang),
            "words": crate::words::all(lang),
            "problems": problems,
        })
    }

    /// Problem `index`, or the error that names it.
    pub fn problem(&self, index: usize) -> Result<&Arc<ServedProblem>, ServeMessage> {
        self.problems.get(index).ok_or(ServeMessage::NoSuchProblem {
            index,
            count: self.problems.len(),
        })
    }
}

/// `en` or `es`.
pub fn lang_code(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "en",
        Lang::Es => "es",
    }
}

/// What `/api/read` answers: the TeX of what the engine read, or the grammar's message.
pub fn read_cell(problem: &Problem, text: &str, kind: CellKind, lang: Lang) -> Value {
    match read_text(problem, text, kind) {
        Ok(tex) => json!({"ok": true, "tex": tex}),
        Err(e) => json!({"ok": false, "error": e.get(lang).text()}),
    }
}

/// A cell's text read by the engine's grammar as a value of `kind`: its LaTeX (none for a
/// yes/no or words), or the grammar's message in each language.
fn read_text(
    problem: &Problem,
    text: &str,
    kind: CellKind,
) -> Result<Option<String>, ByLang<Phrase>> {
    match kind {
        CellKind::Number => {
            let Num(x) =
                spec::read_value::<Num>(&Value::String(text.to_string()), &problem.parameters)
                    .map_err(|m| ByLang::make(|lang| m.phrase(lang)))?;
            Ok(Some(x.to_latex()))
        }
        CellKind::Expression => {
            let e = cagd_poly::parse_expr(text).map_err(|m| ByLang::make(|lang| m.phrase(lang)))?;
            Ok(Some(e.to_latex()))
        }
        CellKind::Bool | CellKind::Text => Ok(None),
    }
}

/// What `/api/check` answers for `answer` (an object of results by key, each in the shape of
/// its form, cells as typed).
pub fn check(
    served: &ServedProblem,
    answer: &Value,
    lang: Lang,
    reveal: Reveal,
    limits: &Limits,
) -> Value {
    let Some(obj) = answer.as_object() else {
        return unreadable(&ServeMessage::AnswerNotAnObject, lang, Vec::new());
    };
    // the results written, in the key's order; the empty ones left out
    let mut written = Map::new();
    let mut left_out = Vec::new();
    for key in obj.keys() {
        if !served
            .results
            .iter()
            .any(|r| r.quantity.name() == key.as_str())
        {
            return unreadable(
                &ServeMessage::NotAResult { key: key.clone() },
                lang,
                Vec::new(),
            );
        }
    }
    for r in &served.results {
        let name = r.quantity.name().into_owned();
        match obj.get(&name) {
            Some(v) if !template::is_empty(v) => {
                written.insert(name, v.clone());
            }
            _ => left_out.push(name),
        }
    }
    if written.is_empty() {
        return unreadable(&ServeMessage::NothingWritten, lang, Vec::new());
    }
    // each cell read by the grammar first, so that an error names its cell
    let mut errors = Vec::new();
    for r in &served.results {
        let name = r.quantity.name();
        let Some(w) = written.get(name.as_ref()) else {
            continue;
        };
        for (cell, kind, text) in template::written_cells(&r.form, w) {
            let empty = || ServeMessage::CellEmpty.phrase(lang);
            let unread = match (kind, text) {
                (CellKind::Bool, Some(Value::Bool(_))) => None,
                (_, Some(Value::String(t))) if t.trim().is_empty() => Some(empty()),
                (
                    CellKind::Number | CellKind::Expression | CellKind::Text,
                    Some(Value::String(t)),
                ) => read_text(&served.problem, t, kind)
                    .err()
                    .map(|e| e.get(lang).clone()),
                (CellKind::Number, Some(Value::Number(_))) => None,
                _ => Some(empty()),
            };
            if let Some(inner) = unread {
                errors.push((r, cell, inner));
            }
        }
    }
    if !errors.is_empty() {
        // said as the page shows them: the result's label, the cell's name in `lang`
        let first = errors
            .first()
            .map(|(r, cell, inner)| ServeMessage::CellUnread {
                result: r.label.get(lang).text.clone(),
                cell: template::cell_name(&r.form, cell, lang),
                inner: inner.clone(),
            })
            .unwrap_or(ServeMessage::NothingWritten);
        let listed = errors
            .into_iter()
            .map(|(r, cell, inner)| {
                json!({"result": r.quantity.name(), "cell": cell, "message": inner.text()})
            })
            .collect();
        return unreadable(&first, lang, listed);
    }
    // integers as JSON integers (a degree, an order), which every reader takes
    let written: Map<String, Value> = written
        .into_iter()
        .map(|(name, w)| {
            let form = served
                .results
                .iter()
                .find(|r| r.quantity.name() == name.as_str())
                .map(|r| &r.form);
            let w = match form {
                Some(f) => template::integers_as_numbers(f, &w),
                None => w,
            };
            (name, w)
        })
        .collect();
    let student = Problem {
        meta: Meta {
            expected: Some(Value::Object(written)),
            formula: None,
            errata: Vec::new(),
            student: None,
            ..served.problem.meta.clone()
        },
        ..Problem::clone(&served.problem)
    };
    let settings = Settings {
        limits: *limits,
        steps: true,
    };
    let student = Arc::new(student);
    let verdict = cagd_scalar::cancel::with_memory_budget(Some(limits.memory_bytes()), || {
        cagd_scalar::cancel::with_deadline(limits.max_seconds, || {
            diagnose_with(&served.key, &student, &settings)
        })
    });
    let mut verdict = match verdict {
        Ok(Ok(v)) => v,
        Ok(Err(_)) => return unreadable(&ServeMessage::Deadline, lang, Vec::new()),
        Err(_) => return unreadable(&ServeMessage::OverMemory, lang, Vec::new()),
    };
    verdict.index = Some(served.index);
    answer_of(served, &verdict, &left_out, lang, reveal)
}

/// An answer that could not be checked: `verdict: "unreadable"`, the reason.
fn unreadable(why: &ServeMessage, lang: Lang, errors: Vec<Value>) -> Value {
    json!({
        "verdict": "unreadable",
        "summary": why.phrase(lang).text(),
        "score": null,
        "marks": [],
        "diagnoses": [],
        "errors": errors,
        "report_html": null,
        "solution_html": null,
    })
}

/// The marks of an assessed result, one per cell of its form (the coordinate functions of a
/// closed form are one cell: right when all are).
fn marks(a: &Assessed) -> Vec<Value> {
    let mut cells: Vec<(String, bool)> = Vec::new();
    for m in &a.marks {
        let cell = template::cell_of(&m.entry).to_string();
        let right = m.right && a.unread.is_none();
        match cells.iter_mut().find(|(c, _)| *c == cell) {
            Some((_, r)) => *r = *r && right,
            None => cells.push((cell, right)),
        }
    }
    let result = a.quantity.name();
    cells
        .into_iter()
        .map(|(cell, right)| json!({"result": result, "cell": cell, "right": right}))
        .collect()
}

/// The answer of `/api/check` from the student's verdict.
fn answer_of(
    served: &ServedProblem,
    verdict: &Verdict,
    left_out: &[String],
    lang: Lang,
    reveal: Reveal,
) -> Value {
    let Some(a) = verdict.assessment.as_deref() else {
        return unreadable(&ServeMessage::NoKey, lang, Vec::new());
    };
    let (right, total) = (a.right(), a.total());
    let correct = a.correct() && left_out.is_empty();
    // a result as the page labels it (`esquinas`), never its JSON key (`corners`)
    let label = |key: &str| -> String {
        served
            .results
            .iter()
            .find(|r| r.quantity.name() == key)
            .map_or_else(|| key.to_string(), |r| r.label.get(lang).text.clone())
    };
    let mut summary = match correct {
        true => ServeMessage::Correct { right, total },
        false => ServeMessage::Wrong { right, total },
    }
    .phrase(lang)
    .text();
    for r in a.results.iter().chain(&a.steps) {
        if let Some(u) = &r.unread {
            summary += " ";
            summary += &ServeMessage::ResultUnread {
                result: label(&r.quantity.name()),
                inner: u.phrase(lang),
            }
            .phrase(lang)
            .text();
        }
    }
    if !left_out.is_empty() {
        summary += " ";
        summary += &ServeMessage::LeftOut {
            results: left_out
                .iter()
                .map(|k| label(k))
                .collect::<Vec<_>>()
                .join(", "),
        }
        .phrase(lang)
        .text();
    }
    let marks: Vec<Value> = a.results.iter().flat_map(marks).collect();
    let mut diagnoses = Vec::new();
    for r in &a.results {
        for d in &r.diagnoses {
            for m in &d.mistakes {
                let cells: Vec<String> = d
                    .entries
                    .iter()
                    .map(|e| template::cell_of(e).to_string())
                    .collect();
                diagnoses.push(json!({
                    "id": m.id(),
                    "said": m.phrase(lang).text(),
                    "place": m.place().phrase(lang).text(),
                    "result": r.quantity.name(),
                    "cells": cells,
                    "whole": d.whole,
                    "ambiguous": d.ambiguous(),
                }));
            }
        }
    }
    let solution = match reveal {
        Reveal::AfterCheck => Value::String(served.solution_html(lang)),
        Reveal::Never => Value::Null,
    };
    json!({
        "verdict": if correct { "correct" } else { "wrong" },
        "summary": summary,
        "score": score(right, total),
        "marks": marks,
        "diagnoses": diagnoses,
        "errors": [],
        "report_html": markdown::to_html(&assessment_markdown(
            verdict,
            lang,
            reveal == Reveal::AfterCheck
        )),
        "solution_html": solution,
    })
}
