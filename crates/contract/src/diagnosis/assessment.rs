//! The report on a student's answer: each result (and each step the student wrote) marked
//! entry by entry, its score, and the mistakes of the catalogue that explain it.

use super::catalogue::Catalogued;
use super::entry::{Entry, Mark};
use super::mistake::Mistake;
use crate::message::check::Check;
use crate::{Exact, Quantity};
use serde_json::{json, Value};

/// A mistake (or several, when they give the same values: ambiguous) that explains a
/// student's wrong entries: its exact answer equals the student's there.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnosis {
    /// The mistakes: one, or several that give the same values on these entries (exact
    /// arithmetic cannot tell them apart here).
    pub mistakes: Vec<Mistake>,
    /// The student's wrong entries the mistake explains.
    pub entries: Vec<Entry>,
    /// Whether the mistake explains the whole result: the student's answer is, entry by
    /// entry, the mistaken answer.
    pub whole: bool,
}

impl Diagnosis {
    /// Whether several mistakes give the same values.
    pub fn ambiguous(&self) -> bool {
        self.mistakes.len() > 1
    }
}

/// A result (or step) of the student's answer, assessed.
#[derive(Debug, Clone, PartialEq)]
pub struct Assessed {
    /// Which result or step.
    pub quantity: Quantity,
    /// Each entry, right or wrong.
    pub marks: Vec<Mark>,
    /// The mistakes that explain the wrong entries; empty for a correct result, and for a
    /// wrong one that no known mistake explains.
    pub diagnoses: Vec<Diagnosis>,
    /// Why the student's value could not be read (then every entry counts as wrong).
    pub unread: Option<Check>,
    /// The student wrote a key that is not a result of this operation.
    pub unknown: bool,
}

impl Assessed {
    /// How many entries are right.
    pub fn right(&self) -> usize {
        self.marks.iter().filter(|m| m.right).count()
    }

    /// How many entries the result has (at least one).
    pub fn total(&self) -> usize {
        self.marks.len().max(1)
    }

    /// Whether every entry is right.
    pub fn correct(&self) -> bool {
        self.unread.is_none() && !self.unknown && self.marks.iter().all(|m| m.right)
    }

    /// The wrong entries.
    pub fn wrong(&self) -> impl Iterator<Item = &Mark> {
        self.marks.iter().filter(|m| !m.right)
    }

    /// Its JSON: the result's name, `correct`, `right` of `entries`, the exact `score`, the
    /// wrong entries (`entry`, `expected`, `written`) and the `diagnoses` (`id`, `result`,
    /// `entries`, `whole`, `ambiguous_with`); `known_mistake` false for a wrong result no
    /// mistake explains.
    pub fn to_json(&self) -> Value {
        let name = self.quantity.name();
        let wrong: Vec<Value> = self
            .wrong()
            .map(|m| {
                json!({
                    "entry": m.entry.to_string(),
                    "expected": m.key.as_ref().map_or(Value::Null, Exact::to_json),
                    "written": m.written.as_ref().map_or(Value::Null, Exact::to_json),
                })
            })
            .collect();
        let mut diagnoses = Vec::new();
        for d in &self.diagnoses {
            for m in &d.mistakes {
                let others: Vec<&str> = d
                    .mistakes
                    .iter()
                    .filter(|o| *o != m)
                    .map(Catalogued::id)
                    .collect();
                diagnoses.push(json!({
                    "id": m.id(),
                    "result": name,
                    "entries": d.entries.iter().map(ToString::to_string).collect::<Vec<_>>(),
                    "whole": d.whole,
                    "ambiguous_with": others,
                }));
            }
        }
        let mut out = json!({
            "result": name,
            "correct": self.correct(),
            "right": self.right(),
            "entries": self.total(),
            "score": score(self.right(), self.total()),
        });
        if let Some(o) = out.as_object_mut() {
            if !self.correct() {
                o.insert("wrong".into(), Value::Array(wrong));
                o.insert("diagnoses".into(), Value::Array(diagnoses));
                o.insert(
                    "known_mistake".into(),
                    Value::Bool(!self.diagnoses.is_empty()),
                );
            }
            if let Some(u) = &self.unread {
                o.insert("unread".into(), Value::String(u.to_string()));
            }
            if self.unknown {
                o.insert("unknown".into(), Value::Bool(true));
            }
        }
        out
    }
}

/// A score as an exact fraction `right/total`, reduced (`7/9`, `1`, `0`).
pub fn score(right: usize, total: usize) -> String {
    fn gcd(a: usize, b: usize) -> usize {
        if b == 0 {
            a
        } else {
            gcd(b, a % b)
        }
    }
    let g = gcd(right, total).max(1);
    match (right / g, total / g) {
        (r, 1) => r.to_string(),
        (r, t) => format!("{r}/{t}"),
    }
}

/// The report on a student's answer to one problem.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Assessment {
    /// The student, when the answer names one (`"student"`, or the file's name).
    pub student: Option<String>,
    /// Each result the student wrote, in the answer's order.
    pub results: Vec<Assessed>,
    /// Each step the student wrote (c_c, c_d, c_cd; the De Casteljau levels; the elevated
    /// polygons), in the key's order.
    pub steps: Vec<Assessed>,
    /// The first step, in the key's order, where the student's values leave the key's.
    pub first_departure: Option<Quantity>,
}

impl Assessment {
    /// How many entries of the results are right.
    pub fn right(&self) -> usize {
        self.results.iter().map(Assessed::right).sum()
    }

    /// How many entries the results have.
    pub fn total(&self) -> usize {
        self.results.iter().map(Assessed::total).sum()
    }

    /// Whether every result is correct (the steps written count too).
    pub fn correct(&self) -> bool {
        !self.results.is_empty()
            && self.results.iter().all(Assessed::correct)
            && self.steps.iter().all(Assessed::correct)
    }

    /// Every mistake diagnosed, once each, in the order met.
    pub fn mistakes(&self) -> Vec<Mistake> {
        let mut out: Vec<Mistake> = Vec::new();
        for a in self.results.iter().chain(&self.steps) {
            for d in &a.diagnoses {
                for m in &d.mistakes {
                    if !out.contains(m) {
                        out.push(*m);
                    }
                }
            }
        }
        out
    }

    /// Its JSON (docs/format.md, "Checking a student's answer").
    pub fn to_json(&self) -> Value {
        let mut out = json!({
            "correct": self.correct(),
            "right": self.right(),
            "entries": self.total(),
            "score": score(self.right(), self.total()),
            "results": self.results.iter().map(Assessed::to_json).collect::<Vec<_>>(),
        });
        if let Some(o) = out.as_object_mut() {
            if let Some(s) = &self.student {
                o.insert("student".into(), Value::String(s.clone()));
            }
            if !self.steps.is_empty() {
                o.insert(
                    "steps".into(),
                    Value::Array(self.steps.iter().map(Assessed::to_json).collect()),
                );
            }
            if let Some(q) = &self.first_departure {
                o.insert(
                    "first_departure".into(),
                    Value::String(q.name().into_owned()),
                );
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn scores_are_exact_fractions() {
        assert_eq!(score(7, 9), "7/9");
        assert_eq!(score(6, 9), "2/3");
        assert_eq!(score(9, 9), "1");
        assert_eq!(score(0, 4), "0");
    }
}
