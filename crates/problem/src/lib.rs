//! Problems and answers of cagd-exact, in JSON (the format of `docs/format.md`).
//!
//! A problem is an object `{"op": NAME, ...arguments}`. [`solve`] reads it, picks the scalar it
//! runs in ([`field::choose`]), runs the operation over that scalar, and returns an
//! [`Answer`]: the named exact results, and the intermediate steps the notes show. A batch is
//! a list of problems, each answered on its own ([`solve_batch`]): a bad problem gives an error
//! naming its index and field, and the others are still answered.
//!
//! A lecture example (a *fixture*) is a problem plus `name`, `source`, `expected` and `errata`;
//! [`check`] compares the computed answer with `expected`, exactly. `expected` holds the exact
//! values, also where the notes misprint them; `errata` records what the notes print instead.

pub mod any;
mod error;
pub mod field;
pub mod input;
mod limits;
mod ops;
pub mod problem;
pub mod schema;
pub mod spec;
pub mod value;

pub use any::{AnyCurve, AnySurface};
pub use error::ProblemError;
pub use field::NumberField;
pub use limits::{read_number, Limit, Limits};
pub use problem::{Erratum, Meta, Op, Problem};
pub use value::{Exact, ExactScalar};

use serde_json::{json, Value};
use std::sync::Arc;

/// A named exact value.
pub type Named = (String, Exact);

/// The answer to one problem: the typed problem it answers, and what was computed.
#[derive(Debug, Clone, PartialEq)]
pub struct Answer {
    /// The operation.
    pub op: String,
    /// The field the problem ran in.
    pub field: NumberField,
    /// The results, by name (`surface`, `closed_form`, `points`...).
    pub result: Vec<Named>,
    /// The intermediate values, in order, by name (`c_hat`, `c_c`...): empty unless the steps
    /// were asked for.
    pub steps: Vec<Named>,
    /// Remarks in words (e.g. "c2 was elevated from degree 2 to 3").
    pub remarks: Vec<String>,
    /// The problem, as read.
    pub problem: Arc<Problem>,
}

impl Answer {
    /// The result called `name`.
    pub fn get(&self, name: &str) -> Option<&Exact> {
        self.result.iter().find(|(k, _)| k == name).map(|(_, v)| v)
    }

    /// The step called `name`.
    pub fn step(&self, name: &str) -> Option<&Exact> {
        self.steps.iter().find(|(k, _)| k == name).map(|(_, v)| v)
    }

    /// The JSON answer `{"ok": true, "op": ..., "result": {...}}`; with `steps`, the result
    /// also has `steps`: a list of `{"name", "value"}`.
    pub fn to_json(&self, steps: bool) -> Value {
        let mut result = serde_json::Map::new();
        for (k, v) in &self.result {
            result.insert(k.clone(), v.to_json());
        }
        if !self.remarks.is_empty() {
            result.insert("remarks".into(), json!(self.remarks));
        }
        if steps {
            result.insert(
                "steps".into(),
                Value::Array(
                    self.steps
                        .iter()
                        .map(|(k, v)| json!({"name": k, "value": v.to_json()}))
                        .collect(),
                ),
            );
        }
        json!({"ok": true, "op": self.op, "result": Value::Object(result)})
    }
}

/// The JSON of a failed problem: `{"ok": false, "error": "..."}`.
pub fn error_json(e: &ProblemError) -> Value {
    json!({"ok": false, "error": e.to_string()})
}

/// The operations `solve` knows, for `--help` and error messages.
pub fn operations() -> &'static [&'static str] {
    problem::NAMES
}

/// What a run computes: under which limits, with or without the steps.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Settings {
    /// The limits problems are read and solved under.
    pub limits: Limits,
    /// Whether the intermediate values are recorded (the step-by-step routes); without, the
    /// fast kernels run.
    pub steps: bool,
}

impl Default for Settings {
    /// The default limits, with the steps.
    fn default() -> Self {
        Settings {
            limits: Limits::DEFAULT,
            steps: true,
        }
    }
}

/// Answers one problem, under the default [`Limits`], with its steps.
pub fn solve(problem: &Value) -> Result<Answer, ProblemError> {
    solve_with(problem, &Limits::DEFAULT)
}

/// Answers one problem under `limits`, with its steps: a degree, a list, a number... past a
/// limit is an error naming the field and the limit.
pub fn solve_with(problem: &Value, limits: &Limits) -> Result<Answer, ProblemError> {
    let settings = Settings {
        limits: *limits,
        steps: true,
    };
    let problem = Problem::read(problem, &settings.limits)?;
    solve_problem(&Arc::new(problem), &settings)
}

/// Solves a problem already read.
///
/// Bad input is an error, never a panic; should a bug of an algorithm panic all the same, the
/// panic is caught here and this problem's answer is an error saying so (the other problems
/// of a batch are still answered).
pub fn solve_problem(problem: &Arc<Problem>, settings: &Settings) -> Result<Answer, ProblemError> {
    let run =
        std::panic::AssertUnwindSafe(|| ops::solve(problem, &settings.limits, settings.steps));
    let out = std::panic::catch_unwind(run).unwrap_or_else(|payload| {
        let what = payload
            .downcast_ref::<&str>()
            .map(|s| (*s).to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_default();
        Err(ProblemError::at(
            "",
            format!(
                "internal error (a bug of cagd-exact, please report it with this problem): {what}"
            ),
        ))
    })?;
    Ok(Answer {
        op: problem.op.name().to_string(),
        field: problem.field,
        result: out.result,
        steps: out.steps,
        remarks: out.remarks,
        problem: Arc::clone(problem),
    })
}

/// Answers every problem of a batch (a JSON array) or the one problem of an object, under
/// the default [`Limits`], with the steps. Each answer is independent: errors carry the
/// problem's index.
pub fn solve_batch(input: &Value) -> Vec<Result<Answer, ProblemError>> {
    solve_batch_with(input, &Limits::DEFAULT, 1)
}

/// [`solve_batch`] under `limits`, on `threads` threads, with the steps.
pub fn solve_batch_with(
    input: &Value,
    limits: &Limits,
    threads: usize,
) -> Vec<Result<Answer, ProblemError>> {
    let settings = Settings {
        limits: *limits,
        steps: true,
    };
    check_batch(input, &settings, threads)
        .into_iter()
        .map(|v| v.answer)
        .collect()
}

/// Reads, solves and checks every problem of a batch (a JSON array) or the one problem of an
/// object, on `threads` threads (at least one): each problem with `expected` is compared with
/// it. The verdicts come in the order of the problems and do not depend on the number of
/// threads. The problems past [`Limits::max_batch`] are not solved: each gets an error naming
/// its index.
pub fn check_batch(input: &Value, settings: &Settings, threads: usize) -> Vec<Verdict> {
    let Value::Array(problems) = input else {
        return vec![check_with_settings(input, settings)];
    };
    let limits = &settings.limits;
    let solve_one = |i: usize, p: &Value| -> Verdict {
        if i >= limits.max_batch {
            return Verdict::failed(
                ProblemError::limit(
                    "",
                    format!(
                        "not solved: the batch holds {} problems, more than the limit of {}",
                        problems.len(),
                        limits.max_batch
                    ),
                    Limit::Batch,
                )
                .in_problem(i),
            );
        }
        let mut v = check_with_settings(p, settings);
        if let Err(e) = &mut v.answer {
            e.index = Some(i);
        }
        v
    };
    let threads = threads.clamp(1, problems.len().max(1));
    if threads == 1 {
        return problems
            .iter()
            .enumerate()
            .map(|(i, p)| solve_one(i, p))
            .collect();
    }
    // Contiguous chunks, one per thread, joined in order: the same answers in the same
    // order whatever the number of threads.
    let chunk = problems.len().div_ceil(threads);
    std::thread::scope(|scope| {
        let handles: Vec<_> = problems
            .chunks(chunk)
            .enumerate()
            .map(|(c, part)| {
                let first = c * chunk;
                let work = move || {
                    part.iter()
                        .enumerate()
                        .map(|(k, p)| solve_one(first + k, p))
                        .collect::<Vec<_>>()
                };
                let handle = std::thread::Builder::new()
                    .stack_size(SOLVER_STACK)
                    .spawn_scoped(scope, work);
                (first..first + part.len(), handle)
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|(range, handle)| {
                let failed = |why: String| {
                    range
                        .clone()
                        .map(|i| Verdict::failed(ProblemError::at("", why.clone()).in_problem(i)))
                        .collect::<Vec<_>>()
                };
                match handle {
                    Ok(h) => h
                        .join()
                        .unwrap_or_else(|_| failed("the solver thread failed".into())),
                    Err(e) => failed(format!("cannot start a solver thread: {e}")),
                }
            })
            .collect()
    })
}

/// The stack of a solver thread: the parser and the readers recurse (to
/// [`Limits::DEPTH_CEILING`] and [`field::MAX_NESTING`]).
const SOLVER_STACK: usize = 64 * 1024 * 1024;

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
    pub mismatches: Vec<String>,
    /// The errata the fixture records (the notes print something else; the engine keeps the
    /// exact value).
    pub errata: Vec<Erratum>,
    /// Whether the problem says what to expect (`expected` or `errata`): only then is there a
    /// verdict to print.
    pub checked: bool,
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
        if problem.get("expected").is_none() {
            self.mismatches
                .push("nothing to check: the problem has no \"expected\" answer".into());
        }
        self
    }

    /// The JSON answer of `cagd solve --format json`: [`Answer::to_json`], or [`error_json`]
    /// when the problem failed; a problem that says what to expect also gets `passed` and its
    /// `mismatches`.
    pub fn to_json(&self, steps: bool) -> Value {
        let mut out = match &self.answer {
            Ok(a) => a.to_json(steps),
            Err(e) => return error_json(e),
        };
        if self.checked {
            if let Some(obj) = out.as_object_mut() {
                obj.insert("passed".into(), Value::Bool(self.passed()));
                obj.insert("mismatches".into(), json!(self.mismatches));
            }
        }
        out
    }
}

/// Solves a fixture (or a teacher's problem with `expected`) and compares with `expected`:
/// each key of `expected` must equal the result of that name (`steps` compares steps by
/// name), exactly.
pub fn check(fixture: &Value) -> Verdict {
    check_with(fixture, &Limits::DEFAULT)
}

/// [`check`] under `limits`.
pub fn check_with(fixture: &Value, limits: &Limits) -> Verdict {
    check_with_settings(
        fixture,
        &Settings {
            limits: *limits,
            steps: true,
        },
    )
}

/// Reads, solves and checks one problem. A problem whose `expected` names steps is solved
/// with its steps whatever `settings` says: the comparison needs them.
pub fn check_with_settings(problem: &Value, settings: &Settings) -> Verdict {
    match Problem::read(problem, &settings.limits) {
        Ok(p) => check_problem(&Arc::new(p), settings),
        Err(e) => Verdict::failed(e),
    }
}

/// Solves and checks a problem already read (a front end that reads a problem once and
/// solves it again, as the Python module's `Problem.solve`, pays the reading once). A problem
/// whose `expected` names steps is solved with its steps whatever `settings` says.
pub fn check_problem(problem: &Arc<Problem>, settings: &Settings) -> Verdict {
    let expected = problem.meta.expected.as_ref();
    let wants_steps = expected.is_some_and(|e| e.get("steps").is_some());
    let settings = if wants_steps && !settings.steps {
        std::borrow::Cow::Owned(Settings {
            steps: true,
            ..settings.clone()
        })
    } else {
        std::borrow::Cow::Borrowed(settings)
    };
    let answer = solve_problem(problem, &settings);
    let mut mismatches = Vec::new();
    if let (Ok(a), Some(expected)) = (&answer, expected) {
        if let Some(obj) = expected.as_object() {
            for (key, e) in obj {
                if key == "steps" {
                    for (name, es) in e.as_object().into_iter().flatten() {
                        match a.step(name) {
                            None => mismatches.push(format!("step {name}: not computed")),
                            Some(x) => {
                                if let Err(m) = x.check(es) {
                                    mismatches.push(format!("step {name}: {m}"));
                                }
                            }
                        }
                    }
                } else {
                    match a.get(key) {
                        None => mismatches.push(format!("{key}: not computed")),
                        Some(x) => {
                            if let Err(m) = x.check(e) {
                                mismatches.push(format!("{key}: {m}"));
                            }
                        }
                    }
                }
            }
        } else {
            mismatches.push(format!(
                "expected: an object of results by name, found {}",
                input::kind(expected)
            ));
        }
    }
    let checked = expected.is_some() || !problem.meta.errata.is_empty();
    Verdict {
        errata: problem.meta.errata.clone(),
        problem: Some(Arc::clone(problem)),
        answer,
        mismatches,
        checked,
    }
}
