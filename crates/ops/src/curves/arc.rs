//! Circular arcs of exact angles, built by cagd-bspline ([`cagd_bspline::exact_arc`]: N
//! rational quadratic arcs whose numbers stay in Q or one Q(√d), the angles all multiples of
//! 30° or all of 45°); here the angles read from the problem and the refusals in its words.

use crate::message::curve::Curve as Say;
use crate::out::num;
use crate::spec::Num;
use crate::value::ExactScalar;
use crate::ProblemError;
use cagd_bspline::{ArcError, NurbsCurve};
use cagd_scalar::BigRational;

/// An angle in degrees as a rational number.
pub(crate) fn degrees<S: ExactScalar>(x: &Num, path: &str) -> Result<BigRational, ProblemError> {
    let v = num::<S>(x, path)?;
    v.as_rational()
        .map(|q| q.into_owned())
        .ok_or_else(|| ProblemError::at(path, Say::AngleNotRational { found: v.to_text() }))
}

/// The arc of `radius` about the origin of the XY plane from `start` through `sweep` degrees,
/// in `arcs` arcs, on `domain` (double knots at the joints), as a NURBS curve in R²
/// ([`cagd_bspline::exact_arc`]); a refusal at `path`.
pub(crate) fn arc<S: ExactScalar>(
    radius: &S,
    start: &BigRational,
    sweep: &BigRational,
    arcs: usize,
    domain: (S, S),
    path: &str,
) -> Result<NurbsCurve<S>, ProblemError> {
    cagd_bspline::exact_arc(radius, start, sweep, arcs, domain).map_err(|e| match e {
        ArcError::BSpline(e) => ProblemError::at(path, e),
        e => ProblemError::at(path, e),
    })
}
