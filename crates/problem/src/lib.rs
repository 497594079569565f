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
pub mod formula;
pub mod input;
mod limits;
pub mod message;
mod ops;
mod pretty;
pub mod problem;
pub mod schema;
pub mod spec;
pub mod steps;
pub mod triangle;
pub mod value;
mod values;

pub use any::{AnyCurve, AnySurface};
pub use error::ProblemError;
pub use field::NumberField;
pub use limits::{read_number, Limit, Limits};
use message::contract::Contract;
pub use message::Message;
pub use pretty::Pretty;
pub use problem::{Erratum, Meta, Op, Problem};
pub use value::{Exact, ExactScalar, Number};

use message::check::Check;
use message::contract::Found;
use serde::ser::{Serialize, SerializeMap, Serializer};
use serde_json::value::RawValue;
use serde_json::Value;
use std::sync::Arc;

/// A named exact value.
pub type Named = (String, Exact);

/// The answer to one problem: the typed problem it answers, and what was computed.
#[derive(Debug, Clone, PartialEq)]
pub struct Answer {
    /// The operation.
    pub op: String,
    /// The field the problem ran in: with `values`, the field of its numbers once the values
    /// are put in (Q or Q(√d) when every letter has a number).
    pub field: NumberField,
    /// The results, by name (`surface`, `closed_form`, `points`...).
    pub result: Vec<Named>,
    /// The intermediate values, in order, by name (`c_hat`, `c_c`...): empty unless the steps
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
    /// The result called `name`.
    pub fn get(&self, name: &str) -> Option<&Exact> {
        self.result.iter().find(|(k, _)| k == name).map(|(_, v)| v)
    }

    /// The step called `name`.
    pub fn step(&self, name: &str) -> Option<&Exact> {
        self.steps.iter().find(|(k, _)| k == name).map(|(_, v)| v)
    }

    /// The JSON answer `{"ok": true, "op": ..., "result": {...}}`; with `steps`, the result
    /// also has `steps`: a list of `{"name", "value"}`, and `derivation`: the typed steps
    /// ([`steps::Step`], tagged by `kind`). [`AnswerJson`] writes the same JSON
    /// straight to a writer.
    pub fn to_json(&self, steps: bool) -> Value {
        serde_json::to_value(AnswerJson {
            answer: self,
            steps,
            verdict: None,
        })
        .unwrap_or(Value::Null)
    }
}

/// The JSON of an answer, `{"ok": true, "op": ..., "result": {...}}`, as a [`Serialize`]
/// value: `serde_json::to_writer` writes it without building a `Value`. With a verdict, it
/// also says whether the answer `passed` and its `mismatches`.
pub struct AnswerJson<'a> {
    /// The answer.
    pub answer: &'a Answer,
    /// Whether to write the steps.
    pub steps: bool,
    /// The verdict, when the problem said what to expect.
    pub verdict: Option<&'a Verdict>,
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
        m.serialize_entry("result", &ResultJson(self.answer, self.steps))?;
        if let Some(v) = self.verdict {
            m.serialize_entry("passed", &v.passed())?;
            m.serialize_entry("mismatches", &v.mismatches)?;
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
                m.serialize_entry("name", &self.0 .0)?;
                m.serialize_entry("value", &self.0 .1)?;
                m.end()
            }
        }
        let ResultJson(a, steps) = *self;
        let mut m = s.serialize_map(None)?;
        for (k, v) in &a.result {
            m.serialize_entry(k, v)?;
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
                verdict: v.checked.then_some(v),
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
            o.key("result").object(|r| {
                for (k, x) in &answer.result {
                    r.key(k).exact(x);
                }
                if !answer.remarks.is_empty() {
                    r.key("remarks")
                        .seq(&answer.remarks, |w, m| w.string(&m.to_string()));
                }
                if self.steps {
                    r.key("steps").seq(&answer.steps, |w, (name, x)| {
                        w.object(|s| {
                            s.key("name").string(name);
                            s.key("value").exact(x);
                        });
                    });
                    if !answer.derivation.is_empty() {
                        r.key("derivation").serde(&answer.derivation);
                    }
                }
            });
            if v.checked {
                o.key("passed").bool(v.passed());
                o.key("mismatches")
                    .seq(&v.mismatches, |w, m| w.string(&m.to_string()));
            }
        });
    }
}

/// The JSON of a failed problem: `{"ok": false, "error": "..."}`.
pub fn error_json(e: &ProblemError) -> Value {
    serde_json::to_value(ErrorJson(e)).unwrap_or(Value::Null)
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
        values::field(problem)?
    };
    let run = std::panic::AssertUnwindSafe(|| {
        cagd_scalar::cancel::with_memory_budget(Some(limits.memory_bytes()), || {
            cagd_scalar::cancel::with_deadline(limits.max_seconds, || {
                if problem.values.is_empty() {
                    return ops::solve(problem, field, limits, settings.steps)
                        .map(|out| (out, None));
                }
                let out = values::with_values(&problem.values, || {
                    ops::solve(problem, field, limits, settings.steps)
                })?;
                // the answer in letters, to say which results the values changed: without its
                // steps, under the same deadline and memory budget, and not compared when it
                // is refused or stopped by either
                let general = cagd_scalar::cancel::with_memory_budget(None, || {
                    cagd_scalar::cancel::with_deadline(None, || {
                        ops::solve(problem, problem.field, limits, false)
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
        out.remark(values::solved_with(&problem.values));
        if let Some(general) = general {
            out.remarks.extend(
                values::differences(&general.result, &out.result, problem)
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
fn past_the_digit_limit(out: &mut ops::Out, limits: &Limits) {
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
fn deadline_error(limits: &Limits) -> ProblemError {
    let seconds = limits.max_seconds.unwrap_or_default();
    ProblemError::limit("", Contract::Deadline { seconds }, Limit::Seconds)
}

/// Megabytes (10^6 bytes), rounded up.
fn megabytes(bytes: u64) -> u64 {
    bytes.div_ceil(1_000_000)
}

/// The error of a problem past its memory budget: what it was about to build and its size
/// (estimated before the work), or what it held when a checkpoint stopped it.
fn memory_error(over: &cagd_scalar::cancel::OverMemory, limits: &Limits) -> ProblemError {
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
fn writing_error(over: Option<&cagd_scalar::cancel::OverMemory>, limits: &Limits) -> ProblemError {
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
    let mut out = Vec::with_capacity(problems.len());
    let kept: Result<(), std::convert::Infallible> = check_stream(
        problems,
        settings,
        threads,
        |v| v,
        |v| {
            out.push(v);
            Ok(())
        },
    );
    match kept {
        Ok(()) => out,
    }
}

/// A problem of a batch before it is read: a JSON value, or its text (a batch read element
/// by element, or split into its problems without reading them).
pub trait ProblemSource {
    /// The problem, read under `limits`.
    fn read(&self, limits: &Limits) -> Result<Problem, ProblemError>;
}

impl ProblemSource for Value {
    fn read(&self, limits: &Limits) -> Result<Problem, ProblemError> {
        Problem::read(self, limits)
    }
}

impl ProblemSource for str {
    /// The text of one problem, read straight into the typed problem
    /// ([`Problem::read_text`]).
    fn read(&self, limits: &Limits) -> Result<Problem, ProblemError> {
        Problem::read_text(self, limits, |e| {
            ProblemError::at(
                "",
                Contract::CannotRead {
                    why: Box::new(problem::serde_error(&e)),
                },
            )
        })
    }
}

impl ProblemSource for String {
    fn read(&self, limits: &Limits) -> Result<Problem, ProblemError> {
        self.as_str().read(limits)
    }
}

impl ProblemSource for RawValue {
    fn read(&self, limits: &Limits) -> Result<Problem, ProblemError> {
        self.get().read(limits)
    }
}

impl<T: ProblemSource + ?Sized> ProblemSource for &T {
    fn read(&self, limits: &Limits) -> Result<Problem, ProblemError> {
        (**self).read(limits)
    }
}

/// Problems per thread that may be answered ahead of the next one written, in
/// [`check_stream`].
const AHEAD_PER_THREAD: usize = 64;

/// The problems of a batch as they are handed out: each with its index, and, past
/// [`Limits::max_batch`], only the size of the batch (the rest of it counted, not kept).
struct Feed<I> {
    problems: I,
    next: usize,
    max_batch: usize,
    /// The size of the batch, once the problems past the limit were counted.
    total: Option<usize>,
}

/// A problem handed out by a [`Feed`].
enum Fed<P> {
    /// A problem to read and solve.
    Problem(P),
    /// A problem past the batch limit, in a batch of this many.
    PastLimit(usize),
}

impl<I: Iterator> Feed<I> {
    fn new(problems: I, max_batch: usize) -> Self {
        Feed {
            problems,
            next: 0,
            max_batch,
            total: None,
        }
    }

    /// The next problem and its index.
    fn take(&mut self) -> Option<(usize, Fed<I::Item>)> {
        let i = self.next;
        let fed = if i < self.max_batch {
            Fed::Problem(self.problems.next()?)
        } else {
            let total = match self.total {
                Some(total) => total,
                None => {
                    let total = i + (&mut self.problems).count();
                    self.total = Some(total);
                    total
                }
            };
            if i >= total {
                return None;
            }
            Fed::PastLimit(total)
        };
        self.next += 1;
        Some((i, fed))
    }
}

/// Reads, solves and checks the problems of a batch on `threads` threads (at least one), as
/// [`check_batch`]: `each` turns a verdict into what the caller keeps (its output, say), on
/// the solver thread, and `sink` receives them in the order of the problems, whatever the
/// number of threads; the first error of `sink` stops the batch.
///
/// The problems are taken from `problems` as they are solved, never all at once: a batch
/// read element by element from a file (`cagd solve`) is held one problem per solver thread
/// at a time, so memory does not grow with the batch. With more than one thread, the solver
/// threads live for the whole batch and each takes the next problem not yet taken (a slow
/// problem holds up no other thread), while the calling thread hands the answers to `sink`
/// in order. At most 64 problems per thread are answered ahead of the next one written. The
/// multimodular solves of cagd-linalg stay on their solver thread
/// ([`cagd_linalg::on_this_thread`]): the batch already keeps the cores busy. The problems
/// past [`Limits::max_batch`] are counted (to say how large the batch is), not read.
pub fn check_stream<I, T, E>(
    problems: I,
    settings: &Settings,
    threads: usize,
    each: impl Fn(Verdict) -> T + Sync,
    mut sink: impl FnMut(T) -> Result<(), E>,
) -> Result<(), E>
where
    I: IntoIterator,
    I::IntoIter: Send,
    I::Item: ProblemSource + Send,
    T: Send,
{
    let problems = problems.into_iter();
    let solve_one = |i: usize, p: Fed<I::Item>| within_limits(i, p, settings, &each);
    let mut feed = Feed::new(problems, settings.limits.max_batch);
    if threads <= 1 {
        while let Some((i, p)) = feed.take() {
            sink(solve_one(i, p))?;
        }
        return Ok(());
    }
    let failed = |i: usize, why: Contract| {
        each(Verdict::failed_at(
            ProblemError::at("", why).in_problem(i),
            i,
        ))
    };
    let queue = Queue::new(feed, AHEAD_PER_THREAD * threads);
    let (send, answers) = std::sync::mpsc::channel::<(usize, T)>();
    std::thread::scope(|scope| {
        let mut started = 0;
        for _ in 0..threads {
            let send = send.clone();
            let (queue, solve_one, failed) = (&queue, &solve_one, &failed);
            let work = move || {
                cagd_linalg::on_this_thread(|| {
                    while let Some((i, p)) = queue.take() {
                        let solved = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                            solve_one(i, p)
                        }));
                        let t = solved.unwrap_or_else(|_| failed(i, Contract::SolverThreadFailed));
                        if send.send((i, t)).is_err() {
                            break;
                        }
                    }
                });
            };
            let spawned = std::thread::Builder::new()
                .stack_size(SOLVER_STACK)
                .spawn_scoped(scope, work);
            started += usize::from(spawned.is_ok());
        }
        drop(send);
        if started == 0 {
            // no solver thread: this one solves
            while let Some((i, p)) = queue.take() {
                sink(solve_one(i, p))?;
                queue.written(i + 1);
            }
            return Ok(());
        }
        // the answers in the order of the problems: those that came early wait their turn
        let mut early: std::collections::BTreeMap<usize, T> = std::collections::BTreeMap::new();
        let mut next = 0;
        let mut write = |t: T, next: &mut usize| -> Result<(), E> {
            sink(t)?;
            *next += 1;
            queue.written(*next);
            Ok(())
        };
        let mut result = Ok(());
        'answers: for (i, t) in &answers {
            early.insert(i, t);
            while let Some(t) = early.remove(&next) {
                result = write(t, &mut next);
                if result.is_err() {
                    break 'answers;
                }
            }
        }
        // every solver thread is gone; a problem taken but not answered (a thread that
        // failed) leaves a gap, said in its place
        while result.is_ok() && !early.is_empty() {
            let t = early
                .remove(&next)
                .unwrap_or_else(|| failed(next, Contract::SolverThreadFailed));
            result = write(t, &mut next);
        }
        queue.stop();
        result
    })
}

/// `each` of the verdict on problem `i`, the reading, solving and checking of the problem
/// and `each` (writing its key, for `cagd solve`) under one deadline and one memory budget,
/// the problem's ([`Limits::max_seconds`], [`Limits::max_memory`]): a key that takes too long
/// or too much memory to write is stopped at its next checkpoint, and `each` then writes the
/// problem's error instead (outside the limits: an error is short).
fn within_limits<P: ProblemSource, T>(
    i: usize,
    p: Fed<P>,
    settings: &Settings,
    each: &impl Fn(Verdict) -> T,
) -> T {
    let limits = &settings.limits;
    let answered = std::cell::Cell::new(false);
    let run = || {
        cagd_scalar::cancel::with_memory_budget(Some(limits.memory_bytes()), || {
            cagd_scalar::cancel::with_deadline(limits.max_seconds, || {
                let v = verdict_at(i, p, settings);
                answered.set(true);
                each(v)
            })
        })
    };
    let stopped = match (run(), answered.get()) {
        (Ok(Ok(t)), _) => return t,
        (Ok(Err(cagd_scalar::cancel::Cancelled)), true) => writing_error(None, limits),
        (Ok(Err(cagd_scalar::cancel::Cancelled)), false) => deadline_error(limits),
        (Err(over), true) => writing_error(Some(&over), limits),
        (Err(over), false) => memory_error(&over, limits),
    };
    each(Verdict::failed_at(stopped.in_problem(i), i))
}

/// The verdict on problem `i` of a batch.
fn verdict_at<P: ProblemSource>(i: usize, p: Fed<P>, settings: &Settings) -> Verdict {
    let limits = &settings.limits;
    let p = match p {
        Fed::Problem(p) => p,
        Fed::PastLimit(total) => {
            return Verdict::failed_at(
                ProblemError::limit(
                    "",
                    Contract::BatchPastLimit {
                        total,
                        limit: limits.max_batch,
                    },
                    Limit::Batch,
                )
                .in_problem(i),
                i,
            )
        }
    };
    let mut v = match p.read(limits) {
        Ok(problem) => check_problem(&Arc::new(problem), settings),
        Err(e) => Verdict::failed(e),
    };
    if let Err(e) = &mut v.answer {
        e.index = Some(i);
    }
    v.index = Some(i);
    v
}

/// The problems of a batch handed out to solver threads in order, at most `ahead` past the
/// next answer written.
struct Queue<I> {
    state: std::sync::Mutex<QueueState<I>>,
    turn: std::sync::Condvar,
    ahead: usize,
}

struct QueueState<I> {
    /// The problems not yet handed out.
    feed: Feed<I>,
    /// The answers written so far.
    written: usize,
    /// The batch stopped (an error writing): hand out nothing more.
    stopped: bool,
}

impl<I: Iterator> Queue<I> {
    fn new(feed: Feed<I>, ahead: usize) -> Self {
        Queue {
            state: std::sync::Mutex::new(QueueState {
                feed,
                written: 0,
                stopped: false,
            }),
            turn: std::sync::Condvar::new(),
            ahead: ahead.max(1),
        }
    }

    /// The next problem to solve, once it is within `ahead` of the answers written; `None`
    /// when all are handed out or the batch stopped. The problem is taken from the feed
    /// (read from its file, for `cagd solve`) here, one thread at a time.
    fn take(&self) -> Option<(usize, Fed<I::Item>)> {
        let mut s = self.state.lock().ok()?;
        loop {
            if s.stopped {
                return None;
            }
            if s.feed.next < s.written + self.ahead {
                return s.feed.take();
            }
            s = self.turn.wait(s).ok()?;
        }
    }

    /// `count` answers are written.
    fn written(&self, count: usize) {
        if let Ok(mut s) = self.state.lock() {
            s.written = count;
        }
        self.turn.notify_all();
    }

    /// No more problems are handed out.
    fn stop(&self) {
        if let Ok(mut s) = self.state.lock() {
            s.stopped = true;
        }
        self.turn.notify_all();
    }
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

/// The differences between an answer and what its problem expects: each key of `expected`
/// must name a result (or `steps`, steps by name) and equal it exactly. An `expected` that is
/// not an object of results, or is empty, checks nothing and is itself a mismatch, naming the
/// results the operation gives.
///
/// The `result` of an answer (`cagd solve --format json`, with or without `--steps`) reads
/// back whole as `expected`: its `steps`, a list of `{"name", "value"}`, is compared whole (the
/// same names in the same order, each value exactly); its `remarks` and `derivation`, the
/// words and layout of the key ([`WORDS_NOT_COMPARED`]), must have their shape (a list of
/// strings, a list of objects) and are not compared. A key that is not a result, and a
/// malformed `steps`, `remarks` or `derivation`, is a mismatch naming it.
fn compare(a: &Answer, expected: &Value) -> Vec<Check> {
    let names = || {
        let names: Vec<String> = a.result.iter().map(|(k, _)| format!("`{k}`")).collect();
        names.join(", ")
    };
    let op = || a.op.clone();
    let Some(obj) = expected.as_object() else {
        return vec![Check::NotAnObject {
            op: op(),
            names: names(),
            found: Found::of(expected),
        }];
    };
    if obj.is_empty() {
        return vec![Check::EmptyExpected {
            op: op(),
            names: names(),
        }];
    }
    if obj.keys().all(|k| WORDS_NOT_COMPARED.contains(&k.as_str())) {
        return vec![Check::OnlyWords {
            op: op(),
            names: names(),
        }];
    }
    let mut mismatches = Vec::new();
    for (key, e) in obj {
        match key.as_str() {
            "steps" => compare_steps(a, e, &mut mismatches),
            "remarks" => {
                let words = e.as_array().is_some_and(|l| l.iter().all(Value::is_string));
                if !words {
                    mismatches.push(Check::RemarksShape {
                        found: Found::of(e),
                    });
                }
            }
            "derivation" => {
                let steps = e.as_array().is_some_and(|l| l.iter().all(Value::is_object));
                if !steps {
                    mismatches.push(Check::DerivationShape {
                        found: Found::of(e),
                    });
                }
            }
            _ => match a.get(key) {
                None => mismatches.push(Check::NotAResult {
                    key: key.clone(),
                    op: op(),
                    names: names(),
                }),
                Some(x) => {
                    if let Err(m) = x.check_in(e, &a.problem.parameters) {
                        mismatches.push(Check::Result {
                            key: key.clone(),
                            inner: Box::new(m),
                        });
                    }
                }
            },
        }
    }
    mismatches
}

/// The keys of an answer's `result` that are words and layout, not values: read back in
/// `expected` (so that a result feeds back whole) and not compared.
pub const WORDS_NOT_COMPARED: [&str; 2] = ["remarks", "derivation"];

/// The mismatches of the `steps` of `expected`: an object of steps by name (each compared
/// with the step of that name), or the list of `{"name", "value"}` an answer writes (compared
/// whole: the same steps in the same order). Anything else, an empty object, or an item of the
/// list without a string `name` and a `value`, is a mismatch naming `steps`.
fn compare_steps(a: &Answer, e: &Value, mismatches: &mut Vec<Check>) {
    let params = &a.problem.parameters;
    let step = |name: &str, m: Check| Check::Step {
        name: name.to_string(),
        inner: Box::new(m),
    };
    match e {
        Value::Object(by_name) if by_name.is_empty() => mismatches.push(Check::EmptySteps),
        Value::Object(by_name) => {
            for (name, es) in by_name {
                match a.step(name) {
                    None => mismatches.push(not_a_step(a, name)),
                    Some(x) => {
                        if let Err(m) = x.check_in(es, params) {
                            mismatches.push(step(name, m));
                        }
                    }
                }
            }
        }
        Value::Array(list) => {
            let mut named = Vec::with_capacity(list.len());
            for (i, item) in list.iter().enumerate() {
                let name = item.get("name").and_then(Value::as_str);
                match (name, item.get("value")) {
                    (Some(name), Some(value)) if item.as_object().is_some_and(|o| o.len() == 2) => {
                        named.push((name, value));
                    }
                    _ => mismatches.push(Check::StepItem {
                        index: i,
                        found: Found::of(item),
                    }),
                }
            }
            if named.len() < list.len() {
                return;
            }
            if named.len() != a.steps.len() {
                mismatches.push(Check::StepCount {
                    expected: named.len(),
                    computed: a.steps.len(),
                });
            }
            for (i, ((name, es), (k, x))) in named.iter().zip(&a.steps).enumerate() {
                if name != k {
                    mismatches.push(Check::StepName {
                        index: i,
                        expected: (*name).to_string(),
                        computed: k.clone(),
                    });
                } else if let Err(m) = x.check_in(es, params) {
                    mismatches.push(step(name, m));
                }
            }
        }
        other => mismatches.push(Check::StepsShape {
            found: Found::of(other),
        }),
    }
}

/// The most step names a mismatch lists: past it, how many more.
const STEP_NAMES_LISTED: usize = 20;

/// The mismatch of a step named in `expected` that the answer does not record (a typo, or a
/// step of another operation): that the operation records no step of that name, and the
/// names of the steps it records here, which `expected` can check, in the order recorded
/// (the first [`STEP_NAMES_LISTED`], then how many more), so that the name can be corrected.
fn not_a_step(a: &Answer, name: &str) -> Check {
    let mut names: Vec<&str> = Vec::new();
    for (k, _) in &a.steps {
        if !names.contains(&k.as_str()) {
            names.push(k);
        }
    }
    let (name, op) = (name.to_string(), a.op.clone());
    if names.is_empty() {
        return Check::NoNamedSteps { name, op };
    }
    let listed: Vec<String> = names
        .iter()
        .take(STEP_NAMES_LISTED)
        .map(|k| format!("`{k}`"))
        .collect();
    let listed = listed.join(", ");
    match names.len().saturating_sub(STEP_NAMES_LISTED) {
        0 => Check::NoSuchStep { name, op, listed },
        more => Check::NoSuchStepOfMany {
            name,
            op,
            listed,
            more,
        },
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

/// The errata the formula check found against the ones the fixture records: each found one
/// must be recorded (same place and values), and each recorded one of the formula found.
fn errata_agree(found: &[Erratum], recorded: &[Erratum], names: &[cagd_param::Name]) -> Vec<Check> {
    let mut out = Vec::new();
    for f in found {
        let ok = recorded.iter().any(|r| {
            r.place == f.place
                && formula::same_values(&r.printed, &f.printed, names)
                && formula::same_values(&r.exact, &f.exact, names)
        });
        if !ok {
            out.push(Check::Unrecorded {
                place: f.place.clone(),
                printed: f.printed.clone(),
                exact: f.exact.clone(),
            });
        }
    }
    for r in recorded {
        let formula_place = found.iter().any(|f| f.place == r.place);
        let of_formula = problem_formula_place(&r.place);
        if !formula_place && of_formula {
            out.push(Check::NotAnErratum {
                place: r.place.clone(),
            });
        }
    }
    out
}

/// Whether an erratum's place is one the formula check writes (`(14) at (1, 0)`, `(25)
/// (corner_00)`).
fn problem_formula_place(place: &str) -> bool {
    place.contains(" at (")
        || (place.starts_with('(') && place.ends_with(')') && place.contains(") ("))
}

/// Solves and checks a problem already read (a front end that reads a problem once and
/// solves it again, as the Python module's `Problem.solve`, pays the reading once). A problem
/// whose `expected` names steps is solved with its steps whatever `settings` says.
pub fn check_problem(problem: &Arc<Problem>, settings: &Settings) -> Verdict {
    let expected = problem.meta.expected.as_ref();
    let wants_steps =
        expected.is_some_and(|e| e.get("steps").is_some()) || problem.meta.formula.is_some();
    let settings = if wants_steps && !settings.steps {
        std::borrow::Cow::Owned(Settings {
            steps: true,
            ..settings.clone()
        })
    } else {
        std::borrow::Cow::Borrowed(settings)
    };
    let answer = solve_problem(problem, &settings);
    let mut mismatches: Vec<Message> = match (&answer, expected) {
        (Ok(a), Some(expected)) => compare(a, expected)
            .into_iter()
            .map(Message::from)
            .collect(),
        _ => Vec::new(),
    };
    if let (Ok(a), Some(fs)) = (&answer, &problem.meta.formula) {
        let equation = problem.meta.equation.as_deref().unwrap_or("the formula");
        let mut found = Vec::new();
        for f in fs.list() {
            match formula::derived_errata(a, f, equation) {
                Ok(errata) => found.extend(errata),
                Err(m) => mismatches.push(m.into()),
            }
        }
        mismatches.extend(
            errata_agree(&found, &problem.meta.errata, &problem.parameters)
                .into_iter()
                .map(Message::from),
        );
    }
    let checked =
        expected.is_some() || !problem.meta.errata.is_empty() || problem.meta.formula.is_some();
    Verdict {
        errata: problem.meta.errata.clone(),
        problem: Some(Arc::clone(problem)),
        answer,
        mismatches,
        checked,
        index: None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
            .map(|i| (format!("s_{i}"), Exact::Int(0)))
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
        a.steps.push(("s_1".into(), Exact::Int(1)));
        assert_eq!(
            not_a_step(&a, "t").to_string(),
            "step `t`: `evaluate` records no step named `t` (its steps: `s_0`, `s_1`)"
        );
    }
}
