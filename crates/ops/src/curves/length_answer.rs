//! The answer of `arc_length`, for polynomial and rational curves alike, and a length's
//! refusal at its path; the words of both are cagd-bezier's.

use crate::out::Out;
use crate::value::Quantity;
use crate::value::{exact, Exact, ExactScalar};
use crate::ProblemError;
use cagd_bezier::{LengthError, LengthNotGiven};

/// The answer of an arc length: c'·c' (one per piece), and the exact length, or the words
/// saying why it is not exact (`words`, from the first piece that is not).
pub(crate) fn length_answer<S: ExactScalar>(
    out: Out,
    mut speeds: Vec<Exact>,
    words: Option<LengthNotGiven>,
    total: &S,
) -> Out {
    let out = out.result(
        Quantity::SpeedSquared,
        if speeds.len() == 1 {
            speeds.remove(0)
        } else {
            Exact::List(speeds)
        },
    );
    match words {
        None => out
            .result(Quantity::IsExact, Exact::Bool(true))
            .result(Quantity::Length, Exact::Number(exact(total))),
        Some(w) => out
            .result(Quantity::IsExact, Exact::Bool(false))
            .result(Quantity::Length, Exact::Sentence(w.into())),
    }
}

/// A length's refusal at `path`: cagd-bezier's words, an inner refusal of the polynomials or
/// of the antiderivative's system as its own.
pub(crate) fn refusal(e: LengthError, path: &str) -> ProblemError {
    match e {
        LengthError::Poly(e) => ProblemError::at(path, e),
        LengthError::Linalg(e) => ProblemError::at("", e),
        e => ProblemError::at(path, e),
    }
}
