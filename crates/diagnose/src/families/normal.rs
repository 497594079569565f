//! The answers of the mistakes of this family (`cagd_problem::diagnosis::NormalMistake`).

use crate::{Context, Mistaken};
use cagd_problem::diagnosis::NormalMistake;

/// The answer a student who made `m` writes, or `None` where it does not apply.
pub(crate) fn mistaken(m: NormalMistake, _cx: &Context) -> Option<Mistaken> {
    match m {}
}
