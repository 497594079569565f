//! Batches: every problem of a JSON array, or of a stream, answered and checked on threads,
//! each on its own (an error names its index).

use crate::message::contract::Contract;
use crate::{
    check_problem, check_with_settings, deadline_error, memory_error, problem, writing_error,
    Answer, Limit, Limits, Problem, ProblemError, Settings, Verdict,
};
use serde_json::value::RawValue;
use serde_json::Value;
use std::sync::Arc;

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
