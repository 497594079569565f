//! Parameters of a fit computed from the data (uniform, chord length, centripetal) and the
//! averaged knots of a B-spline interpolant: computed by cagd-fit ([`cagd_fit::parameters`],
//! [`cagd_fit::averaged_knots`]); here the problem's words and fields of a refusal.

use crate::message::curve::Curve as Say;
use crate::problem::Parametrization;
use crate::value::ExactScalar;
use crate::ProblemError;
use cagd_fit::ParameterError;
use cagd_linalg::Point;

pub(crate) use cagd_fit::averaged_knots;

/// The parameters of `points` by `how`, on [0, 1] ([`cagd_fit::parameters`]).
pub(crate) fn parameters<S: ExactScalar>(
    how: Parametrization,
    points: &[Point<S>],
) -> Result<Vec<S>, ProblemError> {
    let how = match how {
        Parametrization::Uniform => cagd_fit::Parametrization::Uniform,
        Parametrization::ChordLength => cagd_fit::Parametrization::ChordLength,
        Parametrization::Centripetal => cagd_fit::Parametrization::Centripetal,
    };
    cagd_fit::parameters(how, points).map_err(refusal)
}

/// A refusal of the parameters, at the data point it names, in the door's words.
fn refusal(e: ParameterError) -> ProblemError {
    let point = |k: usize| format!("points[{k}]");
    match e {
        ParameterError::ChordNeedsRational { point: k } => {
            ProblemError::at(point(k), Say::ChordNeedsRational)
        }
        ParameterError::PointsCoincide { first, second } => {
            ProblemError::at(point(second), Say::PointsCoincide { first, second })
        }
        ParameterError::CentripetalFourthRoot { to, from, square } => {
            ProblemError::at(point(to), Say::CentripetalFourthRoot { to, from, square })
        }
        ParameterError::SegmentRational {
            from,
            to,
            first_root,
        } => ProblemError::at(
            point(to),
            Say::SegmentRational {
                from,
                to,
                first_root,
            },
        ),
        ParameterError::SegmentAfterRational { from, to, root } => {
            ProblemError::at(point(to), Say::SegmentAfterRational { from, to, root })
        }
        ParameterError::SegmentOtherRoot {
            from,
            to,
            root,
            first_root,
        } => ProblemError::at(
            point(to),
            Say::SegmentOtherRoot {
                from,
                to,
                root,
                first_root,
            },
        ),
        ParameterError::TooFewPoints => ProblemError::at("points", Say::ParametersNeedTwoPoints),
    }
}
