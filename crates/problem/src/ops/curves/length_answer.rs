//! The answer of `arc_length`, for polynomial and rational curves alike, and a length's
//! refusal and "not exact" words in the problem's words.

use crate::message::curve::Curve as Say;
use crate::ops::out::Out;
use crate::value::Quantity;
use crate::value::{exact, Exact, ExactScalar};
use crate::ProblemError;
use cagd_bezier::{LengthError, NotExact};
use cagd_poly::SIGN_HALVINGS;

/// The answer of an arc length: c'·c' (one per piece), and the exact length, or the words
/// saying why it is not exact (`words`, from the first piece that is not).
pub(crate) fn length_answer<S: ExactScalar>(
    out: Out,
    mut speeds: Vec<Exact>,
    words: Option<Say>,
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

/// A length's refusal at `path`, in the problem's words.
pub(crate) fn refusal(e: LengthError, path: &str) -> ProblemError {
    match e {
        LengthError::WeightVanishesAtEnd => ProblemError::at(path, Say::WeightVanishesAtEnd),
        LengthError::Poly(e) => ProblemError::at(path, e),
        LengthError::Linalg(e) => ProblemError::at("", e),
    }
}

/// Why a length is not a number, in the problem's words.
pub(crate) fn not_exact<S: ExactScalar>(why: NotExact<S>) -> Say {
    match why {
        NotExact::SpeedChangesSign { sigma, from, to } => Say::SpeedChangesSign {
            sigma: sigma.to_text(),
            halvings: SIGN_HALVINGS,
            from: from.to_text(),
            to: to.to_text(),
        },
        NotExact::OutsideField { span, square } => {
            let root = format!("√({})", square.to_text());
            let value = if span == S::one() {
                root
            } else {
                format!("({}) {root}", span.to_text())
            };
            Say::LengthOutsideField { value }
        }
        NotExact::SpeedNotSquare { speed } => Say::SpeedNotSquare {
            speed: speed.to_text(),
        },
        NotExact::RationalSpeedNotSquare { numerator } => Say::RationalSpeedNotSquare {
            numerator: numerator.to_text(),
        },
        NotExact::RationalSpeedChangesSign { sigma, from, to } => Say::RationalSpeedChangesSign {
            sigma: sigma.to_text(),
            halvings: SIGN_HALVINGS,
            from: from.to_text(),
            to: to.to_text(),
        },
        NotExact::NoRationalAntiderivative { sigma, weight } => Say::NoRationalAntiderivative {
            sigma: sigma.to_text(),
            weight: weight.to_text(),
        },
    }
}
