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

#[cold]
fn check_clock() {
    if let Some(at) = DEADLINE.with(Cell::get) {
        if Instant::now() >= at {
            std::panic::resume_unwind(Box::new(Cancelled));
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
    let run = catch(f);
    WORK_LIMIT.with(|l| l.set(outer));
    run
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
    let run = catch(f);
    DEADLINE.with(|d| d.set(outer));
    run
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

    #[test]
    fn other_panics_pass_through() {
        let r = std::panic::catch_unwind(|| {
            with_deadline(None, || std::panic::resume_unwind(Box::new(42_u8)))
        });
        assert!(r.is_err_and(|p| p.downcast_ref::<u8>() == Some(&42)));
    }
}
