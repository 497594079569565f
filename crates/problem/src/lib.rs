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

mod batch;
mod check;
pub mod errata;
mod specialize;

// The contract (cagd-contract), by the paths this crate has always given it.
pub use batch::{check_batch, check_stream, solve_batch, solve_batch_with, ProblemSource};
pub use cagd_contract::{
    answer, any, any_curve, any_surface, convert, diagnosis, error, expected_schema, field,
    formula, input, limit, limits, message, pretty, problem, schema, spec, steps, triangle, value,
    values, verdict,
};
pub use cagd_contract::{
    error_json, read_number, Answer, AnswerJson, AnyCurve, AnySurface, Assessment, Catalogued,
    Erratum, ErratumKind, ErrorJson, Exact, ExactScalar, Limit, Limits, Message, Meta, Mistake,
    Named, Number, NumberField, Op, Pretty, Problem, ProblemError, Quantity, Verdict, VerdictJson,
};
use cagd_ops as ops;
pub use check::{check, check_problem, check_with, check_with_settings, compare_expected};
use message::contract::Contract;

use serde_json::Value;
use std::sync::Arc;

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

/// Solves a problem already read; one with `values` at those values (its verdicts decided
/// there, and those the answer in letters decides otherwise named in remarks).
///
/// Bad input is an error, never a panic; should a bug of an algorithm panic all the same, the
/// panic is caught here and this problem's answer is an error saying so (the other problems
/// of a batch are still answered).
pub fn solve_problem(problem: &Arc<Problem>, settings: &Settings) -> Result<Answer, ProblemError> {
    let limits = &settings.limits;
    // with values, the problem runs with them put into its numbers, in the field they give
    let field = if problem.values.is_empty() {
        problem.field
    } else {
        specialize::field(problem)?
    };
    let run = std::panic::AssertUnwindSafe(|| {
        cagd_scalar::cancel::with_memory_budget(Some(limits.memory_bytes()), || {
            cagd_scalar::cancel::with_deadline(limits.max_seconds, || {
                if problem.values.is_empty() {
                    return ops::dispatch::solve(problem, field, limits, settings.steps)
                        .map(|out| (out, None));
                }
                let out = values::with_values(&problem.values, || {
                    ops::dispatch::solve(problem, field, limits, settings.steps)
                })?;
                // the answer in letters, to say which results the values changed: without its
                // steps, under the same deadline and memory budget, and not compared when it
                // is refused or stopped by either
                let general = cagd_scalar::cancel::with_memory_budget(None, || {
                    cagd_scalar::cancel::with_deadline(None, || {
                        ops::dispatch::solve(problem, problem.field, limits, false)
                    })
                });
                Ok((out, general.ok().and_then(Result::ok).and_then(Result::ok)))
            })
        })
    });
    let (mut out, general) = match std::panic::catch_unwind(run) {
        Ok(Ok(Ok(out))) => out,
        Ok(Ok(Err(cagd_scalar::cancel::Cancelled))) => Err(deadline_error(limits)),
        Ok(Err(over)) => Err(memory_error(&over, limits)),
        Err(payload) => {
            let what = payload
                .downcast_ref::<&str>()
                .map(|s| (*s).to_string())
                .or_else(|| payload.downcast_ref::<String>().cloned())
                .unwrap_or_default();
            Err(ProblemError::at("", Contract::InternalError { what }))
        }
    }?;
    if !problem.values.is_empty() {
        out.remark(specialize::solved_with(&problem.values));
        if let Some(general) = general {
            out.remarks.extend(
                specialize::differences(&general.result, &out.result, problem)
                    .into_iter()
                    .map(Message::from),
            );
        }
    }
    if matches!(field, NumberField::Letters(_))
        && matches!(
            problem.op,
            Op::Continuity(_)
                | Op::CurveContinuity(_)
                | Op::Developable(_)
                | Op::GaussianCurvature(_)
                | Op::ReduceDegree(_)
                | Op::ArcLength(_)
        )
    {
        // a verdict decided by an equality in letters
        out.remark(Contract::LettersIdentity);
    }
    past_the_digit_limit(&mut out, limits);
    Ok(Answer {
        op: problem.op.name().to_string(),
        field,
        result: out.result,
        steps: out.steps,
        derivation: out.derivation,
        remarks: problem.hints.iter().cloned().chain(out.remarks).collect(),
        problem: Arc::clone(problem),
    })
}

/// A remark when a result holds a number longer than the digit limit the problem was read
/// under: such an answer cannot be fed back as a problem under the same limits (a problem's
/// numbers are read within the limit, an answer's are computed exactly and are not cut), so
/// the answer says so, with the digit limit that reads it back.
fn past_the_digit_limit(out: &mut ops::out::Out, limits: &Limits) {
    let most = out
        .result
        .iter()
        .filter_map(|(_, x)| x.digits_past(limits.max_digits))
        .max();
    if let Some(most) = most {
        out.remark(Contract::DigitsPast {
            most,
            limit: limits.max_digits,
        });
    }
}

/// The error of a problem stopped at its deadline.
pub(crate) fn deadline_error(limits: &Limits) -> ProblemError {
    let seconds = limits.max_seconds.unwrap_or_default();
    ProblemError::limit("", Contract::Deadline { seconds }, Limit::Seconds)
}

/// Megabytes (10^6 bytes), rounded up.
fn megabytes(bytes: u64) -> u64 {
    bytes.div_ceil(1_000_000)
}

/// The error of a problem past its memory budget: what it was about to build and its size
/// (estimated before the work), or what it held when a checkpoint stopped it.
pub(crate) fn memory_error(
    over: &cagd_scalar::cancel::OverMemory,
    limits: &Limits,
) -> ProblemError {
    let message = match &over.what {
        Some(what) => Message::from(Contract::MemoryRefused {
            what: what.clone(),
            needs: megabytes(over.bytes),
            limit: limits.max_memory,
        }),
        None => Message::from(Contract::MemoryStopped {
            limit: limits.max_memory,
            held: megabytes(over.bytes),
        }),
    };
    ProblemError::limit("", message, Limit::Memory)
}

/// The error of a problem whose key was not written within its deadline or its memory budget
/// (`None`: the deadline), the solving and the writing counted together.
pub(crate) fn writing_error(
    over: Option<&cagd_scalar::cancel::OverMemory>,
    limits: &Limits,
) -> ProblemError {
    match over {
        None => {
            let seconds = limits.max_seconds.unwrap_or_default();
            ProblemError::limit("", Contract::WritingDeadline { seconds }, Limit::Seconds)
        }
        Some(over) => ProblemError::limit(
            "",
            Contract::WritingMemory {
                limit: limits.max_memory,
                held: megabytes(over.bytes),
            },
            Limit::Memory,
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::{not_a_step, STEP_NAMES_LISTED};
    use serde::ser::Serialize;

    /// The JSON files under `dir`, recursively.
    fn json_files(dir: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
        for entry in std::fs::read_dir(dir).expect("fixtures").flatten() {
            let path = entry.path();
            if path.is_dir() {
                json_files(&path, out);
            } else if path.extension().is_some_and(|e| e == "json") {
                out.push(path);
            }
        }
    }

    /// `VerdictJson::write_pretty` writes the bytes serde_json writes from the `Serialize`
    /// impls with `Pretty`, for every fixture (results of every kind, steps, derivations,
    /// verdicts, errors), with and without steps, at the top level and nested in a batch.
    #[test]
    fn the_pretty_writer_writes_what_serde_json_writes() {
        let mut files = Vec::new();
        json_files(
            &std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures"),
            &mut files,
        );
        assert!(files.len() > 40, "fixtures found: {}", files.len());
        let mut problems: Vec<Value> = files
            .iter()
            .map(|f| {
                serde_json::from_str(&std::fs::read_to_string(f).expect("read")).expect("json")
            })
            .collect();
        // a problem that fails, and one with an error message to escape
        problems.push(
            serde_json::json!({"op": "elevate", "surface": {"bezier": [[[0, 0]]]}, "by": "x\"\n"}),
        );
        problems.push(serde_json::json!({"op": "nothing"}));
        for problem in &problems {
            for steps in [false, true] {
                let settings = Settings {
                    limits: Limits::DEFAULT,
                    steps,
                };
                let verdict = check_with_settings(problem, &settings);
                let json = VerdictJson {
                    verdict: &verdict,
                    steps,
                };
                for level in [0, 1] {
                    let mut by_serde = Vec::new();
                    let mut ser =
                        serde_json::Serializer::with_formatter(&mut by_serde, Pretty::at(level));
                    json.serialize(&mut ser).expect("serialize");
                    let mut written = Vec::new();
                    json.write_pretty(&mut written, level);
                    assert_eq!(
                        String::from_utf8_lossy(&written),
                        String::from_utf8_lossy(&by_serde),
                        "{problem}"
                    );
                }
            }
        }
    }

    /// Past [`STEP_NAMES_LISTED`] step names, a mismatch lists the first ones and says how
    /// many more there are; a name recorded twice is listed once.
    #[test]
    fn a_long_list_of_steps_is_cut_with_how_many_more() {
        let problem = serde_json::json!({"op": "evaluate",
            "curve": {"bezier": [[0, 0], [1, 2]]}, "params": [0]});
        let mut a = check_with_settings(&problem, &Settings::default())
            .answer
            .expect("answer");
        a.steps = (0..STEP_NAMES_LISTED + 3)
            .chain([0])
            .map(|i| (Quantity::Symbol(format!("s_{i}")), Exact::Int(0)))
            .collect();
        let listed: Vec<String> = (0..STEP_NAMES_LISTED).map(|i| format!("`s_{i}`")).collect();
        assert_eq!(
            not_a_step(&a, "t").to_string(),
            format!(
                "step `t`: `evaluate` records no step named `t` (its steps: {} and 3 more)",
                listed.join(", ")
            )
        );
        a.steps.truncate(2);
        a.steps
            .push((Quantity::Symbol("s_1".into()), Exact::Int(1)));
        assert_eq!(
            not_a_step(&a, "t").to_string(),
            "step `t`: `evaluate` records no step named `t` (its steps: `s_0`, `s_1`)"
        );
    }
}
