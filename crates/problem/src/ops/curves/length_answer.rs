//! The answer of `arc_length`, for polynomial and rational curves alike.

use crate::message::curve::Curve as Say;
use crate::ops::out::Out;
use crate::value::{exact, Exact, ExactScalar};

/// The answer of an arc length: c'·c' (one per piece), and the exact length, or the words
/// saying why it is not exact (`words`, from the first piece that is not).
pub(crate) fn length_answer<S: ExactScalar>(
    out: Out,
    mut speeds: Vec<Exact>,
    words: Option<Say>,
    total: &S,
) -> Out {
    let out = out.result(
        "speed_squared",
        if speeds.len() == 1 {
            speeds.remove(0)
        } else {
            Exact::List(speeds)
        },
    );
    match words {
        None => out
            .result("exact", Exact::Bool(true))
            .result("length", Exact::Number(exact(total))),
        Some(w) => out
            .result("exact", Exact::Bool(false))
            .result("length", Exact::Sentence(w.into())),
    }
}
