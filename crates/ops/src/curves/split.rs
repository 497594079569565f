//! A B-spline curve split at a parameter (`subdivide` of a curve, and of a spline surface
//! column by column).

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

/// A refusal of a curve's split at `key`: cagd-bspline's words, an inner refusal of the
/// B-spline algorithms as its own.
pub(crate) fn split_refusal(e: cagd_bspline::SplitError, key: &str) -> ProblemError {
    match e {
        cagd_bspline::SplitError::BSpline(e) => ProblemError::at(key, e),
        e => ProblemError::at(key, e),
    }
}
