//! A student's answer diagnosed. The problem is solved once, with its steps, into the key;
//! every mistake of the catalogue that applies to the problem (`cagd_problem::Mistake`, one
//! enum per operation family) is computed once too, exactly, as a student who made it would
//! have computed the answer ([`Key`]). A student's answer is then read in the shapes of the
//! key's, marked entry by entry, scored, and compared with each mistaken answer: a mistake
//! whose values equal the student's where the student leaves the key explains those
//! entries; several that give the same values are ambiguous; none is "no known mistake",
//! never a guess ([`Key::assess`]).
//!
//! The family modules (`families/`) say, for each mistake, how the mistaken answer is
//! computed: most change the problem as the student misread it and solve it again
//! ([`Context::solve_changed`]), or recombine the key's own steps ([`change`]); the rest are
//! a one-line change of the notes' formula, written beside it.

pub mod change;
pub mod class;
mod families;

use cagd_problem::diagnosis::{marks, Assessed, Assessment, Diagnosis, Entry, Mark};
use cagd_problem::{
    solve_problem, Answer, Exact, Meta, Mistake, Named, Op, Problem, ProblemError, Quantity,
    Settings, Verdict,
};
use serde_json::Value;
use std::sync::Arc;

/// What a student who made a mistake writes: the results and the steps of the mistaken
/// computation, named as the key's.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Mistaken {
    /// The results.
    pub result: Vec<Named>,
    /// The intermediate values (c_c, c_d, c_cd; the De Casteljau levels), where the
    /// mistaken computation has them.
    pub steps: Vec<Named>,
}

impl Mistaken {
    /// The mistaken result of kind `q`.
    fn result_of(&self, q: &Quantity) -> Option<&Exact> {
        self.result.iter().find(|(k, _)| k == q).map(|(_, x)| x)
    }

    /// The mistaken step of kind `q`.
    fn step_of(&self, q: &Quantity) -> Option<&Exact> {
        self.steps.iter().find(|(k, _)| k == q).map(|(_, x)| x)
    }
}

/// What a family's mistake is computed from: the problem, its key (with steps), and the
/// settings to solve a changed problem under.
pub struct Context<'a> {
    /// The problem, as the teacher wrote it.
    pub problem: &'a Arc<Problem>,
    /// The key: the problem's answer, with its steps.
    pub answer: &'a Answer,
    /// The limits (and steps on) of the solves.
    pub settings: &'a Settings,
}

impl Context<'_> {
    /// The answer to the problem as the student misread it: `change` changes the operation's
    /// arguments (a curve reversed, the other blending, the parameters swapped) and says
    /// whether it applies; the changed problem is solved with its steps. `None` when the
    /// change does not apply or the changed problem has no answer.
    pub fn solve_changed(&self, change: impl FnOnce(&mut Op) -> bool) -> Option<Mistaken> {
        let mut op = self.problem.op.clone();
        if !change(&mut op) {
            return None;
        }
        let changed = Problem {
            op,
            ..Problem::clone(self.problem)
        };
        let a = solve_problem(&Arc::new(changed), self.settings).ok()?;
        Some(Mistaken {
            result: a.result,
            steps: a.steps,
        })
    }

    /// The key's result of kind `q`.
    pub fn result(&self, q: &Quantity) -> Option<&Exact> {
        self.answer.result_of(q)
    }

    /// The key's step called `name` (`c_cd`).
    pub fn step(&self, name: &str) -> Option<&Exact> {
        self.answer.step(name)
    }

    /// The key's results, each changed by `f` (`None` leaves a result out: the student's
    /// mistake says nothing of it).
    pub fn map_results(&self, f: impl Fn(&Quantity, &Exact) -> Option<Exact>) -> Mistaken {
        Mistaken {
            result: self
                .answer
                .result
                .iter()
                .filter_map(|(q, x)| f(q, x).map(|y| (q.clone(), y)))
                .collect(),
            steps: Vec::new(),
        }
    }
}

/// A problem's key and the answers of every mistake that applies to it, computed once and
/// compared with any number of students' answers.
pub struct Key {
    /// The problem as the teacher wrote it (without a student's `expected`).
    pub problem: Arc<Problem>,
    /// Its answer, with the steps (or why it has none).
    pub answer: Result<Answer, ProblemError>,
    /// Each mistake of the catalogue that applies, with its answer (distinct from the key's).
    pub mistaken: Vec<(Mistake, Mistaken)>,
}

impl Key {
    /// Solves `problem` (its `expected` and `student` set aside) with its steps, and computes
    /// every mistake of its family.
    pub fn new(problem: &Problem, settings: &Settings) -> Key {
        let problem = Arc::new(Problem {
            meta: Meta {
                expected: None,
                student: None,
                ..problem.meta.clone()
            },
            ..problem.clone()
        });
        let settings = Settings {
            steps: true,
            ..settings.clone()
        };
        let answer = solve_problem(&problem, &settings);
        let mistaken = match &answer {
            Ok(a) => {
                let cx = Context {
                    problem: &problem,
                    answer: a,
                    settings: &settings,
                };
                Mistake::all()
                    .into_iter()
                    .filter_map(|m| families::mistaken(m, &cx).map(|x| (m, x)))
                    .filter(|(_, x)| x.result != a.result || x.steps != a.steps)
                    .collect()
            }
            Err(_) => Vec::new(),
        };
        Key {
            problem,
            answer,
            mistaken,
        }
    }

    /// The student's answer `written` (an object of results by name, as `expected`, with
    /// `steps` by name or as the answer's list) assessed: each result and step marked entry by
    /// entry, scored, and diagnosed by the mistakes whose values equal the student's where
    /// the student leaves the key. A key that is not a result, or words (`remarks`), is not
    /// assessed (the verdict's mismatches name it).
    pub fn assess(&self, written: &Value) -> Assessment {
        let mut out = Assessment::default();
        let (Ok(answer), Some(obj)) = (&self.answer, written.as_object()) else {
            return out;
        };
        let params = &self.problem.parameters;
        for (q, x) in &answer.result {
            if let Some(w) = obj.get(q.name().as_ref()) {
                let candidates = self
                    .mistaken
                    .iter()
                    .filter_map(|(m, mv)| mv.result_of(q).map(|v| (*m, v)));
                out.results.push(assess_value(q, x, w, params, candidates));
            }
        }
        if let Some(steps) = obj.get("steps") {
            let named = steps_by_name(steps);
            for (q, x) in &answer.steps {
                let name = q.name();
                let Some((_, w)) = named.iter().find(|(n, _)| *n == name.as_ref()) else {
                    continue;
                };
                let candidates = self
                    .mistaken
                    .iter()
                    .filter_map(|(m, mv)| mv.step_of(q).map(|v| (*m, v)));
                let a = assess_value(q, x, w, params, candidates);
                if !a.correct() && out.first_departure.is_none() {
                    out.first_departure = Some(q.clone());
                }
                out.steps.push(a);
            }
        }
        out
    }
}

/// The steps a student wrote: an object of steps by name, or the answer's list of
/// `{"name", "value"}`.
fn steps_by_name(steps: &Value) -> Vec<(&str, &Value)> {
    match steps {
        Value::Object(o) => o.iter().map(|(k, v)| (k.as_str(), v)).collect(),
        Value::Array(list) => list
            .iter()
            .filter_map(|item| Some((item.get("name")?.as_str()?, item.get("value")?)))
            .collect(),
        _ => Vec::new(),
    }
}

/// One result (or step) of the student's assessed against the key's value `key` and the
/// mistaken values `candidates`.
fn assess_value<'a>(
    q: &Quantity,
    key: &Exact,
    written: &Value,
    params: &[cagd_param::Name],
    candidates: impl Iterator<Item = (Mistake, &'a Exact)>,
) -> Assessed {
    let written = decimals_as_written(written);
    let written = match key.read_like(&written, params) {
        Ok(w) => w,
        Err(e) => {
            return Assessed {
                quantity: q.clone(),
                marks: key
                    .entries()
                    .into_iter()
                    .map(|(entry, k)| Mark {
                        entry,
                        key: Some(k),
                        written: None,
                        right: false,
                    })
                    .collect(),
                diagnoses: Vec::new(),
                unread: Some(e),
                unknown: false,
            };
        }
    };
    let key_marks = marks(key, &written);
    let mut assessed = Assessed {
        quantity: q.clone(),
        marks: key_marks,
        diagnoses: Vec::new(),
        unread: None,
        unknown: false,
    };
    if assessed.correct() {
        return assessed;
    }
    let mut found: Vec<Diagnosis> = Vec::new();
    for (m, value) in candidates {
        let against = marks(value, &written);
        let whole = against.iter().all(|k| k.right);
        // a wrong entry is explained where the mistaken answer has the student's value, or
        // where neither writes it (the weights a student who forgot them did not write)
        let explained: Vec<Entry> = assessed
            .wrong()
            .filter(|w| match against.iter().find(|k| k.entry == w.entry) {
                Some(k) => k.right,
                None => w.written.is_none() && w.entry != Entry::Extra,
            })
            .map(|w| w.entry.clone())
            .collect();
        if explained.is_empty() {
            continue;
        }
        match found
            .iter_mut()
            .find(|d| d.entries == explained && d.whole == whole)
        {
            Some(d) => d.mistakes.push(m),
            None => found.push(Diagnosis {
                mistakes: vec![m],
                entries: explained,
                whole,
            }),
        }
    }
    // a mistake that explains the whole result makes the partial ones noise
    if found.iter().any(|d| d.whole) {
        found.retain(|d| d.whole);
    }
    found.sort_by_key(|d| std::cmp::Reverse(d.entries.len()));
    assessed.diagnoses = found;
    assessed
}

/// A student's answer with every JSON number that has a fraction part or an exponent
/// (`0.5`) as the string of its digits (`"0.5"`), which the grammar reads exactly as
/// written: a problem's reader asks for the string, so that a float is never taken for what
/// it approximates, but a student who writes 0.5 means the decimal written.
fn decimals_as_written(v: &Value) -> Value {
    match v {
        Value::Number(n) if !(n.is_i64() || n.is_u64()) => Value::String(n.to_string()),
        Value::Array(xs) => Value::Array(xs.iter().map(decimals_as_written).collect()),
        Value::Object(o) => Value::Object(
            o.iter()
                .map(|(k, x)| (k.clone(), decimals_as_written(x)))
                .collect(),
        ),
        other => other.clone(),
    }
}

/// Reads, solves and diagnoses one student's problem (`expected` is the student's answer):
/// the verdict of `cagd check` with its assessment.
pub fn diagnose(problem: &Value, settings: &Settings) -> Verdict {
    match Problem::read(problem, &settings.limits) {
        Ok(p) => {
            let key = Key::new(&p, settings);
            diagnose_with(&key, &Arc::new(p), settings)
        }
        Err(e) => Verdict::failed(e),
    }
}

/// The verdict on a student's problem `student` (its `expected` is the student's answer)
/// against a key already computed for the same problem: the mismatches of the check and the
/// assessment. A fixture of the notes (with a `formula` or `errata`) is checked as
/// `cagd_problem::check_problem` checks it, its formula and errata too, with the assessment.
pub fn diagnose_with(key: &Key, student: &Arc<Problem>, settings: &Settings) -> Verdict {
    let expected = student.meta.expected.as_ref();
    let mismatches = match (&key.answer, expected) {
        (Ok(a), Some(e)) => cagd_problem::compare_expected(a, e),
        _ => Vec::new(),
    };
    let mut assessment = expected.map(|e| key.assess(e));
    if let Some(a) = assessment.as_mut() {
        a.student = student.meta.student.clone();
    }
    let assessment = assessment.map(Box::new);
    if student.meta.formula.is_some() || !student.meta.errata.is_empty() {
        return Verdict {
            assessment,
            ..cagd_problem::check_problem(student, settings)
        };
    }
    Verdict {
        problem: Some(Arc::clone(student)),
        answer: key.answer.clone(),
        mismatches,
        errata: Vec::new(),
        checked: true,
        index: None,
        assessment,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn a_decimal_is_read_as_written() {
        let v: Value = serde_json::from_str(r#"[0.5, 2, "1/3", {"x": 1e-1}]"#).unwrap();
        assert_eq!(
            decimals_as_written(&v),
            json!(["0.5", 2, "1/3", {"x": "1e-1"}])
        );
    }
}
