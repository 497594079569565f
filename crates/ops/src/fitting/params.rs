//! Parameters of a fit computed from the data (uniform, chord length, centripetal) and the
//! averaged knots of a B-spline interpolant: computed by cagd-fit ([`cagd_fit::parameters`],
//! [`cagd_fit::averaged_knots`]); here the field of a refusal.

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

/// A refusal of the parameters, at the data point it names.
fn refusal(e: ParameterError) -> ProblemError {
    let path = match &e {
        ParameterError::ChordNeedsRational { point } => format!("points[{point}]"),
        ParameterError::PointsCoincide { second, .. } => format!("points[{second}]"),
        ParameterError::CentripetalFourthRoot { to, .. }
        | ParameterError::SegmentRational { to, .. }
        | ParameterError::SegmentAfterRational { to, .. }
        | ParameterError::SegmentOtherRoot { to, .. } => format!("points[{to}]"),
        ParameterError::TooFewPoints => "points".to_string(),
    };
    ProblemError::at(path, e)
}
