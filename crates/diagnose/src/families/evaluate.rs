//! The answers of the mistakes of this family (`cagd_problem::diagnosis::EvaluateMistake`).

use crate::{Context, Mistaken};
use cagd_problem::diagnosis::EvaluateMistake;

/// The answer a student who made `m` writes, or `None` where it does not apply.
pub(crate) fn mistaken(m: EvaluateMistake, _cx: &Context) -> Option<Mistaken> {
    match m {}
}
