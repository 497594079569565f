//! The parts of an answer key (heading, source, note, inputs, steps, result, remarks, error,
//! verdict), each input, step and result an [`Item`] with its label and its value, shared by
//! the text, LaTeX and Markdown writers.

use crate::knot_convention::{full_knots, in_full_convention};
use crate::names::{self, Label};
use crate::said::{self, Sentence};
use crate::sentences::{self, CurvatureSign, KeyRemark, Keyword};
use crate::source::Source;
use crate::verdict::{error_sentence_with, verdict_sentence, RaiseWith};
use crate::vocabulary::{op_words, Word};
use crate::Lang;
use cagd_contract::{Argument, Exact, Meta, Quantity, Verdict};

/// The fixture's fields of a verdict's problem (empty when it could not be read).
pub(crate) fn meta(v: &Verdict) -> (Meta, String) {
    match &v.problem {
        Some(p) => (p.meta.clone(), p.op.name().to_string()),
        None => (Meta::default(), String::new()),
    }
}

impl Item {
    /// Between the label and the value: ` = `, or `: ` before equations (`at: u = 1`).
    pub(crate) fn sep(&self) -> &'static str {
        match self.value {
            Exact::Object(_) => ": ",
            _ => " = ",
        }
    }
}

/// One input, step or result of a key: its label and its value.
pub(crate) struct Item {
    pub(crate) label: Label,
    pub(crate) value: Exact,
    /// The value written as data points (an interpolation's grid), not as a control mesh.
    pub(crate) data: bool,
    /// The value in words, after the label (`parameters from the data = chord length`): a
    /// sentence, a keyword, a sign, or text.
    pub(crate) words: Option<Sentence>,
}

/// The parts of an answer key, shared by the text, LaTeX and Markdown writers.
pub(crate) struct KeyParts {
    pub(crate) heading: String,
    pub(crate) source: String,
    pub(crate) note: Option<String>,
    pub(crate) op: String,
    pub(crate) inputs: Vec<Item>,
    pub(crate) steps: Vec<Item>,
    pub(crate) result: Vec<Item>,
    pub(crate) remarks: Vec<Sentence>,
    pub(crate) error: Option<Sentence>,
    pub(crate) verdict: Sentence,
}

/// The items of the problem's arguments, by kind.
fn inputs(named: &[(Argument, Exact)], verdict: &Verdict, lang: Lang) -> Vec<Item> {
    let problem = verdict.problem.as_deref();
    let op = problem.map(|p| p.op.name()).unwrap_or_default();
    let fit = matches!(op, "interpolate" | "approximate");
    named
        .iter()
        .map(|(argument, given)| {
            let value = curvature_sign_words(false, given, op, lang);
            let keyword = matches!(
                argument,
                Argument::Basis
                    | Argument::EndConditions
                    | Argument::Blend
                    | Argument::Direction
                    | Argument::Convention
                    | Argument::Spacing
            ) || (*argument == Argument::Parametrization && fit);
            // a degree of two numbers is a surface's bidegree (m, n)
            let bidegree =
                *argument == Argument::Degree && matches!(&value, Exact::Point(p) if p.dim() == 2);
            Item {
                label: match bidegree {
                    true => Label::words("bidegree", "bigrado", lang),
                    false => names::argument_label(argument, problem, lang),
                },
                words: item_words(keyword, &value, lang),
                value,
                data: *argument == Argument::Points && fit,
            }
        })
        .collect()
}

/// The items of the answer's results or steps, by kind.
fn items(named: &[(Quantity, Exact)], verdict: &Verdict, lang: Lang) -> Vec<Item> {
    let problem = verdict.problem.as_deref();
    let op = problem.map(|p| p.op.name()).unwrap_or_default();
    let fit = matches!(op, "interpolate" | "approximate");
    named
        .iter()
        .map(|(quantity, given)| {
            let value = curvature_sign_words(*quantity == Quantity::CurvatureSign, given, op, lang);
            let keyword = *quantity == Quantity::Parametrization && fit;
            Item {
                label: names::label(quantity, problem, lang),
                words: item_words(keyword, &value, lang),
                value,
                data: (*quantity == Quantity::Points && fit)
                    || matches!(quantity, Quantity::CTildeMesh | Quantity::DTilde),
            }
        })
        .collect()
}

/// The words of an item's value, when it is said in words: a sentence of the engine in the
/// language asked, a `keyword` argument of a problem (`basis`, `end`, `blend`, `direction`, an
/// interpolation's `parametrization`) as words (`chord_length` is "chord length", `bessel`
/// "Bessel", in Spanish where it has words of its own: [`Keyword`]), other text as it is.
fn item_words(keyword: bool, value: &Exact, lang: Lang) -> Option<Sentence> {
    match value {
        Exact::Sentence(m) => Some(said::message(m, lang)),
        Exact::Text(k) if keyword => Some(match Keyword::of(k) {
            Some(w) => said::said(&w, lang),
            None => Sentence::data(&sentences::keyword_text(k)),
        }),
        Exact::Text(t) => Some(Sentence::data(t)),
        _ => None,
    }
}

/// The `sign` of `gaussian_curvature` (1, -1, or 0 when G vanishes somewhere on the domain,
/// docs/format.md), in words: "positive (G > 0)", "negative (G < 0)", "none (G vanishes on
/// the domain)" ([`CurvatureSign`]), also in each piece of a B-spline surface's `pieces`. A
/// bare 0 read as if G vanished everywhere. `sign`: whether the value is the sign.
fn curvature_sign_words(sign: bool, value: &Exact, op: &str, lang: Lang) -> Exact {
    if op != "gaussian_curvature" {
        return value.clone();
    }
    match (sign, value) {
        (true, Exact::Int(s)) => {
            let words = CurvatureSign::of(*s);
            Exact::Text(cagd_words::Message::phrase(&words, lang).text())
        }
        (_, Exact::List(xs)) => Exact::List(
            xs.iter()
                .map(|x| curvature_sign_words(false, x, op, lang))
                .collect(),
        ),
        (_, Exact::Object(fields)) => Exact::Object(
            fields
                .iter()
                .map(|(k, x)| {
                    let sign = *k == Quantity::CurvatureSign;
                    (k.clone(), curvature_sign_words(sign, x, op, lang))
                })
                .collect(),
        ),
        (_, v) => v.clone(),
    }
}

pub(crate) fn key_parts(verdict: &Verdict, lang: Lang, raise: RaiseWith) -> KeyParts {
    let (meta, op) = meta(verdict);
    let es = meta.es.clone().unwrap_or_default();
    let name = meta.name.clone().unwrap_or_default();
    let title = match lang {
        Lang::Es => es.title.clone().or(meta.title.clone()),
        Lang::En => meta.title.clone(),
    }
    .unwrap_or_default();
    let problem = match verdict.index {
        Some(i) => format!("{} {}", lang.word("Problem"), i + 1),
        None => lang.word("Problem"),
    };
    // the title alone (numbered in a set): a name is an internal id, shown only when there is
    // neither a title nor a number
    let heading = match (verdict.index.is_some(), title.is_empty(), name.is_empty()) {
        (true, false, _) => format!("{problem}: {title}"),
        (false, false, _) => title,
        (false, true, false) => name,
        (_, true, _) if op.is_empty() => problem,
        (_, true, _) => format!("{problem} ({})", op_words(&op, lang)),
    };
    let source = Source::of(&meta).words(lang);
    let note = match lang {
        Lang::Es => es.note.clone().or(meta.note.clone()),
        Lang::En => meta.note.clone(),
    }
    .filter(|n| !n.is_empty());
    let none = Vec::new();
    let (steps, result, remarks, error) = match &verdict.answer {
        Ok(a) => (
            items(&a.steps, verdict, lang),
            items(&a.result, verdict, lang),
            a.remarks.iter().map(|r| said::message(r, lang)).collect(),
            None,
        ),
        Err(e) => (
            none,
            Vec::new(),
            Vec::new(),
            Some(error_sentence_with(e, lang, raise)),
        ),
    };
    let problem_inputs = verdict
        .problem
        .as_ref()
        .map(|p| p.inputs())
        .unwrap_or_default();
    let (mut steps, mut result, mut remarks) = (steps, result, remarks);
    if full_knots(&problem_inputs) {
        // the knots in the convention the problem gave them, and a word to say so
        let mut converted = false;
        for it in steps.iter_mut().chain(result.iter_mut()) {
            if let Some(v) = in_full_convention(&it.value) {
                it.value = v;
                converted = true;
            }
        }
        if converted {
            remarks.push(said::said(&KeyRemark::FullKnots, lang));
        }
    }
    KeyParts {
        heading,
        source,
        note,
        op,
        inputs: inputs(&problem_inputs, verdict, lang),
        steps,
        result,
        remarks,
        error,
        verdict: verdict_sentence(verdict, lang, raise),
    }
}
