//! The answer to one problem ([`Answer`]) and the JSON of an answer and of an error.

use crate::{steps, Exact, Message, NumberField, Problem, ProblemError, Quantity};
use serde::ser::{Serialize, SerializeMap, Serializer};
use serde_json::Value;
use std::sync::Arc;

/// A result or step: what it is ([`Quantity`], written in JSON by its name) and its exact
/// value.
pub type Named = (Quantity, Exact);

/// The answer to one problem: the typed problem it answers, and what was computed.
#[derive(Debug, Clone, PartialEq)]
pub struct Answer {
    /// The operation.
    pub op: String,
    /// The field the problem ran in: with `values`, the field of its numbers once the values
    /// are put in (Q or Q(√d) when every letter has a number).
    pub field: NumberField,
    /// The results, by kind (`surface`, `closed_form`, `points`...).
    pub result: Vec<Named>,
    /// The intermediate values, in order, by kind (`c_hat`, `c_c`...): empty unless the steps
    /// were asked for.
    pub steps: Vec<Named>,
    /// The steps as a teacher writes them: the formula (with the notes' equation number), the
    /// substitution, the intermediate values and tables ([`steps::Step`]); empty unless the
    /// steps were asked for. cagd-keys writes them in each language.
    pub derivation: Vec<steps::Step>,
    /// Remarks, typed (e.g. "c2 was elevated from degree 2 to 3").
    pub remarks: Vec<Message>,
    /// The problem, as read.
    pub problem: Arc<Problem>,
}

impl Answer {
    /// The result called `name` in the JSON answer ([`Quantity::name`]): for a name given
    /// from outside (a fixture's `expected`, a Python user's key).
    pub fn get(&self, name: &str) -> Option<&Exact> {
        self.result
            .iter()
            .find(|(k, _)| k.name() == name)
            .map(|(_, v)| v)
    }

    /// The step called `name` in the JSON answer ([`Quantity::name`]).
    pub fn step(&self, name: &str) -> Option<&Exact> {
        self.steps
            .iter()
            .find(|(k, _)| k.name() == name)
            .map(|(_, v)| v)
    }

    /// The result of kind `quantity`.
    pub fn result_of(&self, quantity: &Quantity) -> Option<&Exact> {
        self.result
            .iter()
            .find(|(k, _)| k == quantity)
            .map(|(_, v)| v)
    }

    /// The JSON answer `{"ok": true, "op": ..., "result": {...}}`; with `steps`, the result
    /// also has `steps`: a list of `{"name", "value"}`, and `derivation`: the typed steps
    /// ([`steps::Step`], tagged by `kind`). [`AnswerJson`] writes the same JSON
    /// straight to a writer.
    pub fn to_json(&self, steps: bool) -> Value {
        serde_json::to_value(AnswerJson {
            answer: self,
            steps,
            checked: None,
            assessment: None,
        })
        .unwrap_or(Value::Null)
    }
}

/// The JSON of an answer, `{"ok": true, "op": ..., "result": {...}}`, as a [`Serialize`]
/// value: `serde_json::to_writer` writes it without building a `Value`. When the problem was
/// checked (its verdict), it also says whether the answer `passed` and its `mismatches`.
pub struct AnswerJson<'a> {
    /// The answer.
    pub answer: &'a Answer,
    /// Whether to write the steps.
    pub steps: bool,
    /// The verdict, when the problem said what to expect: whether the answer passed, and
    /// the mismatches.
    pub checked: Option<(bool, &'a [Message])>,
    /// The report on a student's answer, when one was diagnosed.
    pub assessment: Option<&'a crate::Assessment>,
}

impl Serialize for AnswerJson<'_> {
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        let mut m = s.serialize_map(None)?;
        m.serialize_entry("ok", &true)?;
        m.serialize_entry("op", &self.answer.op)?;
        if !self.answer.problem.parameters.is_empty() {
            // an answer in letters names them, so that it feeds back as a problem
            let names: Vec<&str> = self
                .answer
                .problem
                .parameters
                .iter()
                .filter(|n| n.argument().is_none())
                .map(cagd_param::Name::as_str)
                .collect();
            m.serialize_entry("parameters", &names)?;
        }
        crate::value::json::with_homogeneous(self.answer.problem.homogeneous, || {
            m.serialize_entry("result", &ResultJson(self.answer, self.steps))
        })?;
        if let Some((passed, mismatches)) = self.checked {
            m.serialize_entry("passed", &passed)?;
            m.serialize_entry("mismatches", mismatches)?;
        }
        if let Some(a) = self.assessment {
            m.serialize_entry("assessment", &a.to_json())?;
        }
        m.end()
    }
}

/// The `result` object of an answer: the results by name, the remarks, the steps.
struct ResultJson<'a>(&'a Answer, bool);

impl Serialize for ResultJson<'_> {
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        /// A step, `{"name": ..., "value": ...}`.
        struct Step<'a>(&'a Named);
        impl Serialize for Step<'_> {
            fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
                let mut m = s.serialize_map(Some(2))?;
                m.serialize_entry("name", &self.0 .0.name())?;
                m.serialize_entry("value", &self.0 .1)?;
                m.end()
            }
        }
        let ResultJson(a, steps) = *self;
        let mut m = s.serialize_map(None)?;
        for (k, v) in &a.result {
            m.serialize_entry(&k.name(), v)?;
        }
        if !a.remarks.is_empty() {
            m.serialize_entry("remarks", &a.remarks)?;
        }
        if steps {
            m.serialize_entry("steps", &VecSeq(&a.steps, Step))?;
            if !a.derivation.is_empty() {
                m.serialize_entry("derivation", &a.derivation)?;
            }
        }
        m.end()
    }
}

/// A slice written as a JSON list of its items seen through `f`.
struct VecSeq<'a, T, F>(&'a [T], F);

impl<'a, T, F, U> Serialize for VecSeq<'a, T, F>
where
    F: Fn(&'a T) -> U,
    U: Serialize,
{
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        s.collect_seq(self.0.iter().map(&self.1))
    }
}

/// The JSON of a failed problem, `{"ok": false, "error": "..."}`, as a [`Serialize`] value.
pub struct ErrorJson<'a>(pub &'a ProblemError);

impl Serialize for ErrorJson<'_> {
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        let mut m = s.serialize_map(Some(2))?;
        m.serialize_entry("ok", &false)?;
        m.serialize_entry("error", &self.0.to_string())?;
        m.end()
    }
}

/// The JSON of a failed problem: `{"ok": false, "error": "..."}`.
pub fn error_json(e: &ProblemError) -> Value {
    serde_json::to_value(ErrorJson(e)).unwrap_or(Value::Null)
}
