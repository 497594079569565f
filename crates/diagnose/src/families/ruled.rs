//! The answers of the mistakes of this family (`cagd_problem::diagnosis::RuledMistake`).

use crate::{Context, Mistaken};
use cagd_problem::diagnosis::RuledMistake;

/// The answer a student who made `m` writes, or `None` where it does not apply.
pub(crate) fn mistaken(m: RuledMistake, _cx: &Context) -> Option<Mistaken> {
    match m {}
}
