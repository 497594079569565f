//! Where the numerator G of the Gaussian curvature vanishes, in words: the zero set is decided
//! exactly by cagd-poly ([`cagd_poly::zero_set`], the Bernstein coefficients of G on the
//! domain, halved at most [`cagd_poly::ZERO_SET_LEVELS`] times); this is its verdict.

use crate::message::surface::Surface;
use crate::value::ExactScalar;
use cagd_poly::{ZeroSet, ZERO_SET_LEVELS};
use std::cmp::Ordering;

/// The verdict on a zero set in words, G being the numerator of the Gaussian curvature (K has
/// its sign).
pub(crate) fn verdict<S: ExactScalar>(z: &ZeroSet<S>) -> Surface {
    let point = |(u, v): (&S, &S)| format!("({}, {})", u.to_text(), v.to_text());
    match z {
        ZeroSet::Everywhere => Surface::GEverywhere,
        ZeroSet::Sign {
            sign,
            rectangles,
            levels,
        } => match (*sign == Ordering::Less, *levels == 0) {
            (true, true) => Surface::GNegative,
            (false, true) => Surface::GPositive,
            (true, false) => Surface::GNegativeCut {
                rectangles: *rectangles,
            },
            (false, false) => Surface::GPositiveCut {
                rectangles: *rectangles,
            },
        },
        ZeroSet::Mixed => Surface::GMixed,
        ZeroSet::Zero(u, v) => Surface::GZeroAt { at: point((u, v)) },
        ZeroSet::SignChange((a, b), (c, d)) => Surface::GSignChange {
            positive: point((a, b)),
            negative: point((c, d)),
        },
        ZeroSet::Undecided { letters: true } => Surface::GUndecidedLetters,
        ZeroSet::Undecided { letters: false } => Surface::GUndecided {
            halvings: ZERO_SET_LEVELS,
        },
    }
}
