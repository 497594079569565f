//! The step recorder: how an algorithm hands its intermediate values to a worked answer.
//!
//! An algorithm that the notes work step by step (Boehm's knot insertion, De Casteljau on a
//! patch, the two passes of a grid interpolation, the constructions of chapter 6) takes a
//! recorder `rec: &mut impl Record<Step>`, with `Step` its own typed step (generic over the
//! scalar), and calls `rec.record(|| step)` at each step. There is one implementation of the
//! algorithm: with [`NoSteps`] the recorder is a zero-sized no-op, so after monomorphization
//! the closures are never called and no step is built or allocated; with a `Vec` every step
//! is kept, in order. Work that only a step needs (a whole De Casteljau triangle where the
//! point suffices) is guarded by [`Record::on`].
//!
//! ```
//! use cagd_record::{NoSteps, Record};
//! /// The partial sums `s_k = x_1 + ... + x_k`, each recorded; the total returned.
//! fn total(xs: &[i64], rec: &mut impl Record<i64>) -> i64 {
//!     let mut s = 0;
//!     for x in xs {
//!         s += x;
//!         rec.record(|| s);
//!     }
//!     s
//! }
//! assert_eq!(total(&[1, 2, 3], &mut NoSteps), 6);
//! let mut steps = Vec::new();
//! assert_eq!(total(&[1, 2, 3], &mut steps), 6);
//! assert_eq!(steps, [1, 3, 6]);
//! ```

/// Where an algorithm puts its steps of type `T`.
pub trait Record<T> {
    /// Whether the steps are kept: when false, an algorithm skips the work only a step needs.
    fn on(&self) -> bool;

    /// Keeps the step `step()`; the closure is called only when the steps are kept.
    fn record(&mut self, step: impl FnOnce() -> T);
}

/// The recorder of an answer without steps: keeps nothing, builds nothing.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct NoSteps;

impl<T> Record<T> for NoSteps {
    #[inline(always)]
    fn on(&self) -> bool {
        false
    }

    #[inline(always)]
    fn record(&mut self, _step: impl FnOnce() -> T) {}
}

/// Every step, in the order they are made.
impl<T> Record<T> for Vec<T> {
    #[inline]
    fn on(&self) -> bool {
        true
    }

    #[inline]
    fn record(&mut self, step: impl FnOnce() -> T) {
        self.push(step());
    }
}

/// A recorder chosen at run time: `None` keeps nothing (a test of the option per step, no step
/// built), `Some(r)` records into `r`. For a caller that decides only when it runs whether the
/// steps are asked, without instantiating the algorithm twice.
///
/// ```
/// use cagd_record::Record;
/// let mut off: Option<Vec<u8>> = None;
/// off.record(|| 1);
/// assert!(!off.on());
/// let mut on = Some(Vec::new());
/// on.record(|| 1);
/// assert_eq!(on, Some(vec![1]));
/// ```
impl<T, R: Record<T>> Record<T> for Option<R> {
    #[inline]
    fn on(&self) -> bool {
        self.as_ref().is_some_and(Record::on)
    }

    #[inline]
    fn record(&mut self, step: impl FnOnce() -> T) {
        if let Some(r) = self {
            r.record(step);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A recorder that counts the steps asked and the steps built.
    struct Counting {
        on: bool,
        asked: usize,
        built: usize,
    }

    impl Record<Vec<u64>> for Counting {
        fn on(&self) -> bool {
            self.on
        }

        fn record(&mut self, step: impl FnOnce() -> Vec<u64>) {
            self.asked += 1;
            if self.on {
                let _ = step();
                self.built += 1;
            }
        }
    }

    /// An algorithm whose steps allocate: the levels `x, 2x, 4x, ...` as vectors.
    fn doubling(x: u64, levels: usize, rec: &mut impl Record<Vec<u64>>) -> u64 {
        let mut y = x;
        for _ in 0..levels {
            y *= 2;
            rec.record(|| vec![y; 1000]);
        }
        y
    }

    #[test]
    fn no_steps_builds_nothing() {
        assert_eq!(std::mem::size_of::<NoSteps>(), 0);
        let mut off = Counting {
            on: false,
            asked: 0,
            built: 0,
        };
        assert_eq!(doubling(3, 4, &mut off), 48);
        assert_eq!((off.asked, off.built), (4, 0));
        let mut on = Counting {
            on: true,
            asked: 0,
            built: 0,
        };
        assert_eq!(doubling(3, 4, &mut on), 48);
        assert_eq!((on.asked, on.built), (4, 4));
        assert_eq!(doubling(3, 4, &mut NoSteps), 48);
        let mut kept = Vec::new();
        doubling(1, 2, &mut kept);
        assert_eq!(kept, [vec![2; 1000], vec![4; 1000]]);
    }
}
