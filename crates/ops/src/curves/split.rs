//! A B-spline curve split at a parameter (`subdivide` of a curve, and of a spline surface
//! column by column).

use crate::message::fitting::Fitting;
use crate::value::ExactScalar;
use crate::ProblemError;
use cagd_bspline::BSplineCurve;

/// A B-spline curve split at `t` strictly inside its domain ([`BSplineCurve::split_at`]): the
/// curves on [a, t] and [t, b], each on its own knots; a refusal at `key`.
pub(crate) fn split_bspline<S: ExactScalar>(
    c: &BSplineCurve<S>,
    t: &S,
    key: &str,
) -> Result<(BSplineCurve<S>, BSplineCurve<S>), ProblemError> {
    c.split_at(t).map_err(|e| split_refusal(e, key))
}

/// A refusal of a curve's split at `key`, in the problem's words.
pub(crate) fn split_refusal(e: cagd_bspline::SplitError, key: &str) -> ProblemError {
    use cagd_bspline::SplitError;
    match e {
        SplitError::NotInsideCurve { t, a, b } => {
            ProblemError::at(key, Fitting::NotInsideCurve { t, a, b })
        }
        SplitError::KnotNotFound => ProblemError::at(key, Fitting::KnotNotFound),
        SplitError::KnotVectorShort => ProblemError::at(key, Fitting::KnotVectorShort),
        SplitError::PolygonShort => ProblemError::at(key, Fitting::PolygonShort),
        SplitError::BSpline(e) => ProblemError::at(key, e),
    }
}
