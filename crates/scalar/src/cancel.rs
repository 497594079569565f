//! Cooperative cancellation: a per-thread deadline that the long loops of the algorithms check.
//!
//! A problem is solved under [`with_deadline`]; every long loop of the engine (De Casteljau,
//! eliminations, polynomial products, gcds, evaluation grids...) calls [`checkpoint`], which,
//! once the deadline has passed, unwinds with [`Cancelled`]. This is how salsa cancels a query
//! in rust-analyzer (`Cancelled::throw`): no algorithm's error type has to carry a variant for
//! it and no loop has to return a `Result` it would otherwise not need, yet a problem that slips
//! past every estimate of its size stops at its deadline, gets its own error, and the other
//! problems of a batch are answered. [`with_deadline`] turns the unwinding back into a value;
//! any other panic passes through it unchanged.
//!
//! [`checkpoint`] also counts: [`work`] is the number of checkpoints passed on this thread, a
//! measure of work that does not depend on the machine's load (the test of the largest legal
//! problems asserts budgets in it, never in seconds).
//!
//! **Memory.** [`with_memory_budget`] bounds the bytes a piece of work may hold, two ways:
//! - before the work, where its size is known: an algorithm that is about to build something
//!   large whose size it can bound (the normal equations of a least-squares fit, say) states
//!   it with [`claim`], which unwinds with [`OverMemory`] naming it when it does not fit;
//! - during the work, at the checkpoints, when the program counts its allocations: a
//!   program's global allocator (the `cagd` binary's) reports every allocation and release to
//!   [`count_bytes`], which keeps the bytes this thread holds, and a checkpoint past the budget
//!   unwinds with [`OverMemory`]. Without such an allocator (a library's user), only the
//!   claims are checked.
//!
//! ```
//! use cagd_scalar::cancel::{claim, with_memory_budget, Claimed};
//! // 8 GB, stated before the work, do not fit in 1 GB: refused at once, with the figure
//! let what = Claimed::NormalEquations { unknowns: 900, digits: 50 };
//! let r = with_memory_budget(Some(1_000_000_000), || {
//!     claim(8_000_000_000, || what.clone());
//!     unreachable!()
//! });
//! let e = r.unwrap_err();
//! assert_eq!((e.bytes, e.limit), (8_000_000_000, 1_000_000_000));
//! assert_eq!(e.what, Some(what));
//! ```
//!
//! ```
//! use cagd_scalar::cancel::{checkpoint, with_deadline, Cancelled};
//! use std::time::Duration;
//! // a loop that would never end stops at its deadline
//! let r = with_deadline(Some(Duration::from_millis(20)), || loop { checkpoint() });
//! assert_eq!(r, Err(Cancelled));
//! // without a deadline, checkpoints only count
//! let r = with_deadline(None, || { (0..10).for_each(|_| checkpoint()); 7 });
//! assert_eq!(r, Ok(7));
//! ```

use std::cell::Cell;
use std::time::{Duration, Instant};

thread_local! {
    static DEADLINE: Cell<Option<Instant>> = const { Cell::new(None) };
    static WORK: Cell<u64> = const { Cell::new(0) };
    static WORK_LIMIT: Cell<u64> = const { Cell::new(u64::MAX) };
    /// The bytes this thread holds, as the program's allocator reported them
    /// ([`count_bytes`]): allocated less released (released on this thread, whoever
    /// allocated them, so it may go below zero).
    static HELD: Cell<i64> = const { Cell::new(0) };
    /// The memory budget in force: the most [`HELD`] may reach, and the budget as given.
    static CEILING: Cell<Option<(i64, u64)>> = const { Cell::new(None) };
}

/// Tells this thread's count of held bytes that `delta` bytes were allocated (positive) or
/// released (negative) on it. Meant for a program's global allocator, and so never allocates
/// nor panics (a thread being torn down is not counted). A checkpoint past the memory budget
/// of [`with_memory_budget`] then stops the work.
///
/// ```
/// use cagd_scalar::cancel::{checkpoint, count_bytes, with_memory_budget};
/// // as an allocator would report 5 MB taken while the work runs
/// let r = with_memory_budget(Some(1_000_000), || {
///     count_bytes(5_000_000);
///     (0..64).for_each(|_| checkpoint());
/// });
/// count_bytes(-5_000_000);
/// assert!(r.is_err_and(|e| e.bytes >= 5_000_000 && e.what.is_none()));
/// ```
#[inline]
pub fn count_bytes(delta: isize) {
    let _ = HELD.try_with(|h| h.set(h.get().wrapping_add(delta as i64)));
}

/// The bytes this thread holds, as counted by [`count_bytes`] (0 without a counting
/// allocator).
pub fn held() -> i64 {
    HELD.with(Cell::get)
}

/// The payload a checkpoint or a [`claim`] unwinds with past the memory budget, and the error
/// of [`with_memory_budget`]: the bytes needed (held at the checkpoint, or claimed), the budget,
/// and what was claimed (none at a checkpoint).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct OverMemory {
    /// The bytes held by the work at the checkpoint that stopped it, or the bytes claimed.
    pub bytes: u64,
    /// The budget, in bytes.
    pub limit: u64,
    /// What the claim was for; `None` when a checkpoint found the budget spent.
    pub what: Option<Claimed>,
}

/// What a [`claim`] is for: the subject of the sentence of a refusal.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Claimed {
    /// The normal equations of a least-squares fit, on integers (cagd-fit's exact kernel).
    NormalEquations {
        /// The unknowns: the equations are `unknowns x unknowns`.
        unknowns: usize,
        /// The least digits of each integer.
        digits: u64,
    },
    /// Work of no name (a test's).
    #[default]
    Work,
}

impl cagd_words::Message for Claimed {
    fn phrase(&self, lang: cagd_words::Lang) -> cagd_words::Phrase {
        use cagd_words::said;
        match self {
            Claimed::NormalEquations { unknowns, digits } => said(
                lang,
                "the normal equations of the least squares (‹› x ‹› integers of at least ‹› digits each)",
                "las ecuaciones normales de los mínimos cuadrados (‹› x ‹› enteros de al menos ‹› cifras cada uno)",
                [unknowns.into(), unknowns.into(), digits.into()],
            ),
            Claimed::Work => said(lang, "the work", "el cálculo", []),
        }
    }
}

cagd_words::display_english!(Claimed);

impl std::fmt::Display for OverMemory {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.what {
            Some(what) => write!(
                f,
                "{what} would take {} bytes, more than the budget of {} bytes",
                self.bytes, self.limit
            ),
            None => write!(
                f,
                "the work held {} bytes, more than the budget of {} bytes",
                self.bytes, self.limit
            ),
        }
    }
}

impl std::error::Error for OverMemory {}

/// The bytes the work of the innermost [`with_memory_budget`] holds now, and its budget.
fn spent() -> Option<(u64, u64, i64)> {
    let (ceiling, limit) = CEILING.with(Cell::get)?;
    let base = ceiling.saturating_sub(i64::try_from(limit).unwrap_or(i64::MAX));
    let used = u64::try_from(held().saturating_sub(base)).unwrap_or(0);
    Some((used, limit, ceiling))
}

/// States that the work is about to hold `bytes` more (an estimate made before the work, from
/// sizes known then): when that would take the work past its memory budget
/// ([`with_memory_budget`]), unwinds with [`OverMemory`] naming `what` and the bytes claimed,
/// before anything is built. Without a budget, does nothing.
pub fn claim(bytes: u64, what: impl FnOnce() -> Claimed) {
    if let Some((used, limit, _)) = spent() {
        if used.saturating_add(bytes) > limit {
            std::panic::resume_unwind(Box::new(OverMemory {
                bytes: used.saturating_add(bytes),
                limit,
                what: Some(what()),
            }));
        }
    }
}

/// Runs `f` on this thread with a budget of `limit` bytes (none: no budget): `Err` with the
/// figures when a [`claim`] does not fit, or when a checkpoint finds this thread holding more
/// than `limit` bytes above what it held when `f` began (counted by [`count_bytes`]). The
/// budget of an enclosing call also holds inside (the lower ceiling applies) and is restored
/// afterwards. A panic other than [`OverMemory`] (such as [`Cancelled`]) is resumed.
pub fn with_memory_budget<R>(limit: Option<u64>, f: impl FnOnce() -> R) -> Result<R, OverMemory> {
    let outer = CEILING.with(Cell::get);
    let mine = limit.map(|l| {
        let ceiling = held().saturating_add(i64::try_from(l).unwrap_or(i64::MAX));
        match outer {
            Some((c, outer_limit)) if c < ceiling => (c, outer_limit),
            _ => (ceiling, l),
        }
    });
    CEILING.with(|c| c.set(mine.or(outer)));
    let _restore = Restore(|| CEILING.with(|c| c.set(outer)));
    let run = std::panic::catch_unwind(std::panic::AssertUnwindSafe(f));
    match run {
        Ok(r) => Ok(r),
        Err(payload) => match payload.downcast::<OverMemory>() {
            Ok(over) => Err(*over),
            Err(payload) => std::panic::resume_unwind(payload),
        },
    }
}

/// The clock is read once every this many checkpoints (reading it costs about as much as a
/// small big-integer product; a checkpoint between two reads is an add and a test).
const CLOCK_EVERY: u64 = 16;

/// The payload a checkpoint unwinds with once the deadline has passed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Cancelled;

impl std::fmt::Display for Cancelled {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("stopped at its deadline")
    }
}

impl std::error::Error for Cancelled {}

/// A point of a long loop where the work may stop: counts one unit of [`work`] and, when the
/// thread's deadline has passed, unwinds with [`Cancelled`] (caught by [`with_deadline`]).
#[inline]
pub fn checkpoint() {
    let n = WORK.with(|w| {
        let n = w.get().wrapping_add(1);
        w.set(n);
        n
    });
    if n % CLOCK_EVERY == 0 {
        check_clock();
    }
    if n > WORK_LIMIT.with(Cell::get) {
        std::panic::resume_unwind(Box::new(Cancelled));
    }
}

/// The clock and the memory budget, checked every [`CLOCK_EVERY`] checkpoints.
#[cold]
fn check_clock() {
    if let Some(at) = DEADLINE.with(Cell::get) {
        if Instant::now() >= at {
            std::panic::resume_unwind(Box::new(Cancelled));
        }
    }
    if let Some((used, limit, ceiling)) = spent() {
        if held() > ceiling {
            std::panic::resume_unwind(Box::new(OverMemory {
                bytes: used,
                limit,
                what: None,
            }));
        }
    }
}

/// The checkpoints passed on this thread so far.
pub fn work() -> u64 {
    WORK.with(Cell::get)
}

/// Runs `f` on this thread with at most `budget` checkpoints of [`work`]: `Err(Cancelled)`
/// past it. The deterministic twin of [`with_deadline`], for tests that bound work without a
/// clock (the same input gives the same verdict on any machine, under any load).
///
/// ```
/// use cagd_scalar::cancel::{checkpoint, with_work_budget, Cancelled};
/// assert_eq!(with_work_budget(100, || (0..50).for_each(|_| checkpoint())), Ok(()));
/// assert_eq!(with_work_budget(100, || (0..150).for_each(|_| checkpoint())), Err(Cancelled));
/// ```
pub fn with_work_budget<R>(budget: u64, f: impl FnOnce() -> R) -> Result<R, Cancelled> {
    let outer = WORK_LIMIT.with(Cell::get);
    let mine = work().saturating_add(budget).min(outer);
    WORK_LIMIT.with(|l| l.set(mine));
    // restored however `f` ends, also when another panic passes through
    let _restore = Restore(|| WORK_LIMIT.with(|l| l.set(outer)));
    catch(f)
}

/// Runs its closure when dropped: a thread-local setting restored on every way out of a
/// scope, unwinding included (a payload that a `with_*` does not catch passes through it and
/// must not leave its setting behind for the next problem of the thread).
struct Restore<F: FnMut()>(F);

impl<F: FnMut()> Drop for Restore<F> {
    fn drop(&mut self) {
        (self.0)();
    }
}

/// `f`, with a [`Cancelled`] unwinding turned into `Err`; any other panic resumed.
fn catch<R>(f: impl FnOnce() -> R) -> Result<R, Cancelled> {
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)) {
        Ok(r) => Ok(r),
        Err(payload) if payload.is::<Cancelled>() => Err(Cancelled),
        Err(payload) => std::panic::resume_unwind(payload),
    }
}

/// Runs `f` on this thread with `budget` as its deadline (none: no deadline, the checkpoints
/// only count): `Err(Cancelled)` when a checkpoint stopped it. The deadline of an enclosing
/// call is restored afterwards (the nearer of the two applies inside). A panic other than
/// [`Cancelled`] is resumed.
pub fn with_deadline<R>(budget: Option<Duration>, f: impl FnOnce() -> R) -> Result<R, Cancelled> {
    let outer = DEADLINE.with(Cell::get);
    let mine = budget.and_then(|b| Instant::now().checked_add(b));
    let nearest = match (outer, mine) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    };
    DEADLINE.with(|d| d.set(nearest));
    let _restore = Restore(|| DEADLINE.with(|d| d.set(outer)));
    catch(f)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_deadline_stops_a_loop_and_is_restored() {
        let before = work();
        let r = with_deadline(Some(Duration::from_millis(5)), || loop {
            checkpoint();
        });
        assert_eq!(r, Err(Cancelled));
        assert!(work() > before);
        // the deadline is gone afterwards: a long count finishes
        let r = with_deadline(None, || {
            for _ in 0..100_000 {
                checkpoint();
            }
            1
        });
        assert_eq!(r, Ok(1));
    }

    #[test]
    fn the_nearer_deadline_applies_inside() {
        let r = with_deadline(Some(Duration::from_secs(3600)), || {
            with_deadline(Some(Duration::from_millis(5)), || loop {
                checkpoint();
            })
        });
        assert_eq!(r, Ok(Err(Cancelled)));
    }

    /// A payload a `with_*` does not catch (here the memory budget's, through a deadline and
    /// a work budget) leaves no setting behind: the next work on the thread runs free.
    #[test]
    fn settings_are_restored_when_another_payload_passes_through() {
        let r = with_memory_budget(Some(10), || {
            with_deadline(Some(Duration::from_millis(1)), || {
                with_work_budget(5, || claim(100, || Claimed::Work))
            })
        });
        assert!(r.is_err_and(|e| e.what == Some(Claimed::Work)));
        std::thread::sleep(Duration::from_millis(5));
        // no deadline nor work budget nor memory budget left over
        let r = with_deadline(None, || {
            (0..1000).for_each(|_| checkpoint());
            claim(u64::MAX, Claimed::default);
        });
        assert_eq!(r, Ok(()));
    }

    #[test]
    fn other_panics_pass_through() {
        let r = std::panic::catch_unwind(|| {
            with_deadline(None, || std::panic::resume_unwind(Box::new(42_u8)))
        });
        assert!(r.is_err_and(|p| p.downcast_ref::<u8>() == Some(&42)));
    }
}
