//! The answers of the mistakes of this family (`cagd_problem::diagnosis::InterpolateMistake`).

use crate::{Context, Mistaken};
use cagd_problem::diagnosis::InterpolateMistake;

/// The answer a student who made `m` writes, or `None` where it does not apply.
pub(crate) fn mistaken(m: InterpolateMistake, _cx: &Context) -> Option<Mistaken> {
    match m {}
}
