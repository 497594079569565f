//! The verdict on a problem ([`Verdict`]: its answer and the comparison with what it expects)
//! and its JSON.

use crate::message::check::Check;
use crate::{pretty, Answer, AnswerJson, Erratum, ErrorJson, Message, Problem, ProblemError};
use serde::ser::{Serialize, Serializer};
use serde_json::Value;
use std::sync::Arc;

/// The JSON of a verdict as `cagd solve --format json` writes it: the answer (with `passed`
/// and `mismatches` when the problem said what to expect), or the error.
pub struct VerdictJson<'a> {
    /// The verdict.
    pub verdict: &'a Verdict,
    /// Whether to write the steps.
    pub steps: bool,
}

impl Serialize for VerdictJson<'_> {
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        let v = self.verdict;
        match &v.answer {
            Ok(answer) => AnswerJson {
                answer,
                steps: self.steps,
                checked: v.checked.then(|| (v.passed(), v.mismatches.as_slice())),
                assessment: v.assessment.as_deref(),
            }
            .serialize(s),
            Err(e) => ErrorJson(e).serialize(s),
        }
    }
}

impl VerdictJson<'_> {
    /// Appends the pretty JSON of the verdict (two spaces a level, from `level`) to `out`:
    /// the bytes `serde_json` writes with [`Pretty`] from the [`Serialize`] impl, written
    /// without serde's machinery (the numbers' digits straight into `out`).
    pub fn write_pretty(&self, out: &mut Vec<u8>, level: usize) {
        let mut w = pretty::JsonWriter::new(out, level);
        let v = self.verdict;
        let answer = match &v.answer {
            Ok(answer) => answer,
            Err(e) => {
                w.object(|o| {
                    o.key("ok").bool(false);
                    o.key("error").string(&e.to_string());
                });
                return;
            }
        };
        w.object(|o| {
            o.key("ok").bool(true);
            o.key("op").string(&answer.op);
            let parameters = &answer.problem.parameters;
            if !parameters.is_empty() {
                let names = parameters.iter().filter(|n| n.argument().is_none());
                o.key("parameters").seq(names, |w, n| w.string(n.as_str()));
            }
            let homogeneous = answer.problem.homogeneous;
            o.key("result").object(|r| {
                crate::value::json::with_homogeneous(homogeneous, || {
                    for (k, x) in &answer.result {
                        r.key(&k.name()).exact(x);
                    }
                    if !answer.remarks.is_empty() {
                        r.key("remarks")
                            .seq(&answer.remarks, |w, m| w.string(&m.to_string()));
                    }
                    if self.steps {
                        r.key("steps").seq(&answer.steps, |w, (name, x)| {
                            w.object(|s| {
                                s.key("name").string(&name.name());
                                s.key("value").exact(x);
                            });
                        });
                        if !answer.derivation.is_empty() {
                            r.key("derivation").serde(&answer.derivation);
                        }
                    }
                })
            });
            if v.checked {
                o.key("passed").bool(v.passed());
                o.key("mismatches")
                    .seq(&v.mismatches, |w, m| w.string(&m.to_string()));
            }
            if let Some(a) = &v.assessment {
                o.key("assessment").serde(&a.to_json());
            }
        });
    }
}

/// The verdict on a problem: the problem as read, its answer, and — when it says what to
/// expect — the comparison.
#[derive(Debug, Clone, PartialEq)]
pub struct Verdict {
    /// The problem, when it could be read.
    pub problem: Option<Arc<Problem>>,
    /// The answer computed (or why it failed).
    pub answer: Result<Answer, ProblemError>,
    /// Differences between the computed answer and the problem's `expected` (empty when
    /// exact, or when nothing was expected).
    pub mismatches: Vec<Message>,
    /// The errata the fixture records (the notes print something else; the engine keeps the
    /// exact value).
    pub errata: Vec<Erratum>,
    /// Whether the problem says what to expect (`expected` or `errata`): only then is there a
    /// verdict to print.
    pub checked: bool,
    /// The problem's index in its batch (counted from 0; keys number problems from 1), `None`
    /// for a single problem.
    pub index: Option<usize>,
    /// The report on a student's answer (`cagd check`): every entry of each result right or
    /// wrong, a score, and the mistakes of the catalogue that explain it. `None` for a
    /// fixture, and where nothing was diagnosed.
    pub assessment: Option<Box<crate::Assessment>>,
}

impl Verdict {
    /// The verdict of a problem that could not be read.
    pub fn failed(e: ProblemError) -> Self {
        Verdict {
            problem: None,
            answer: Err(e),
            mismatches: Vec::new(),
            errata: Vec::new(),
            checked: false,
            index: None,
            assessment: None,
        }
    }

    /// The verdict of problem `index` of a batch, which could not be read or solved.
    pub fn failed_at(e: ProblemError, index: usize) -> Self {
        Verdict {
            index: Some(index),
            ..Verdict::failed(e)
        }
    }

    /// The computed answer equals the fixture's exact expectation.
    pub fn passed(&self) -> bool {
        self.answer.is_ok() && self.mismatches.is_empty()
    }

    /// The notes print exactly what the engine computes (no errata).
    pub fn matches_notes(&self) -> bool {
        self.passed() && self.errata.is_empty()
    }

    /// The verdict of `cagd check`, where a problem must say what to expect: when `problem`
    /// (the JSON it was read from) has no `expected`, a mismatch "nothing to check".
    pub fn require_expected(mut self, problem: &Value) -> Self {
        if problem.get("expected").is_none() && problem.get("formula").is_none() {
            self.mismatches.push(Check::NothingToCheck.into());
        }
        self
    }

    /// The JSON answer of `cagd solve --format json`: [`Answer::to_json`], or [`error_json`]
    /// when the problem failed; a problem that says what to expect also gets `passed` and its
    /// `mismatches`.
    pub fn to_json(&self, steps: bool) -> Value {
        serde_json::to_value(VerdictJson {
            verdict: self,
            steps,
        })
        .unwrap_or(Value::Null)
    }
}
