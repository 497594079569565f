//! The one error type of cagd-bspline.

use cagd_bezier::BezierError;
use cagd_scalar::ScalarError;
use std::fmt;

/// What can go wrong with knot vectors, B-spline and NURBS curves.
///
/// Numbers inside the messages are written exactly (`3/2`, `√2/2`). Knot indices are those of
/// the vector as it was given (in the convention it was read in); control-point indices are the
/// same in both conventions.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum BSplineError {
    /// A degree below 1.
    InvalidDegree {
        /// The degree given.
        degree: usize,
    },
    /// Fewer than `degree + 1` control points.
    TooFewPoints {
        /// The degree of the curve.
        degree: usize,
        /// How many control points were given.
        found: usize,
    },
    /// A knot vector of neither accepted length.
    KnotCount {
        /// The degree of the curve.
        degree: usize,
        /// The number of control points.
        points: usize,
        /// How many knots were given.
        found: usize,
    },
    /// `knots[index - 1] > knots[index]`.
    DecreasingKnots {
        /// The index of the knot that is smaller than the one before it.
        index: usize,
        /// The knot before, as text.
        before: String,
        /// The knot at `index`, as text.
        after: String,
    },
    /// Two knots whose order cannot be decided (they are in letters).
    KnotOrderUnknown {
        /// The index of the second knot.
        index: usize,
        /// The difference whose sign is needed, as text.
        difference: String,
    },
    /// A knot repeated more than `degree + 1` times (in the notes' convention).
    Multiplicity {
        /// The knot, as text.
        knot: String,
        /// How many times it appears.
        multiplicity: usize,
        /// The degree of the curve.
        degree: usize,
    },
    /// The domain `[u_{p-1}, u_{n-1}]` has no length.
    EmptyDomain {
        /// Its left end, as text.
        start: String,
        /// Its right end, as text.
        end: String,
    },
    /// A parameter outside the domain.
    OutsideDomain {
        /// The parameter, as text.
        t: String,
        /// The left end of the domain.
        start: String,
        /// The right end of the domain.
        end: String,
    },
    /// A knot to insert or remove that lies outside the domain (or, for removal, on its ends).
    KnotOutsideDomain {
        /// The knot, as text.
        knot: String,
        /// The left end of the domain.
        start: String,
        /// The right end of the domain.
        end: String,
    },
    /// The number of control points does not fit the knot vector.
    PointCount {
        /// The number the knot vector is made for.
        expected: usize,
        /// The number given.
        found: usize,
    },
    /// Control point `index` has another dimension than control point 0.
    DimensionMismatch {
        /// The index of the offending control point.
        index: usize,
        /// The dimension of control point 0.
        expected: usize,
        /// The dimension of control point `index`.
        found: usize,
    },
    /// A NURBS curve with a different number of weights than control points.
    WeightCount {
        /// Number of control points.
        points: usize,
        /// Number of weights.
        weights: usize,
    },
    /// A zero weight: the control point would be a point at infinity.
    ZeroWeight {
        /// The index of the zero weight.
        index: usize,
    },
    /// The denominator of a rational curve vanishes: the point is at infinity.
    PointAtInfinity {
        /// The parameter, as text.
        t: String,
    },
    /// An index that is not a non-empty span of the domain.
    InvalidSpan {
        /// The index given (full convention, Piegl and Tiller's `k` with `u_k <= t < u_{k+1}`).
        span: usize,
    },
    /// Inserting a knot that many times would exceed the multiplicity `degree`.
    NotInsertable {
        /// The knot, as text.
        knot: String,
        /// Its multiplicity before insertion.
        multiplicity: usize,
        /// How many insertions were asked for.
        times: usize,
        /// The degree of the curve.
        degree: usize,
    },
    /// The value to remove is not a knot of the curve (or not that many times).
    NotAKnot {
        /// The value, as text.
        knot: String,
        /// Its multiplicity.
        multiplicity: usize,
        /// How many removals were asked for.
        times: usize,
    },
    /// Removing the knot would change the curve.
    NotRemovable {
        /// The knot, as text.
        knot: String,
        /// How many copies were removed before the one that fails.
        removed: usize,
    },
    /// The derivative of the curve is not a B-spline curve of this crate.
    NoDerivativeCurve {
        /// Why, in words.
        reason: String,
    },
    /// A construction needs a square root the scalar type does not hold exactly.
    NeedsRoot {
        /// What was being built.
        what: String,
        /// The radicand d of the quadratic field Q(√d) needed.
        radicand: u64,
    },
    /// The data of a circle are inconsistent (number of arcs, cosine and sine).
    NotACircle {
        /// What is wrong, in words, with the exact values.
        reason: String,
    },
    /// An error of a Bézier piece.
    Bezier(BezierError),
    /// An error of the number type.
    Number {
        /// What was being done.
        what: String,
        /// The underlying error.
        source: ScalarError,
    },
}

impl fmt::Display for BSplineError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use BSplineError as E;
        match self {
            E::InvalidDegree { degree } => write!(
                f,
                "degree {degree} is not allowed: a B-spline curve needs degree at least 1"
            ),
            E::TooFewPoints { degree, found } => write!(
                f,
                "a B-spline curve of degree {degree} needs at least {} control points, found {found}",
                degree + 1
            ),
            E::KnotCount {
                degree,
                points,
                found,
            } => write!(
                f,
                "a curve of degree {degree} with {points} control points needs {} knots (the notes' \
                 convention, without end knots) or {} (with one more knot at each end, as in The \
                 NURBS Book); found {found}",
                (points + degree).saturating_sub(1),
                points + degree + 1
            ),
            E::DecreasingKnots {
                index,
                before,
                after,
            } => write!(f, "knot vector decreases at index {index}: {before} > {after}"),
            E::KnotOrderUnknown { index, difference } => write!(
                f,
                "the knots must not decrease: the sign of {difference} (knots {} and {index}) is \
                 not known (it is in letters; give the letters values, or numbers here)",
                index.saturating_sub(1)
            ),
            E::Multiplicity {
                knot,
                multiplicity,
                degree,
            } => write!(
                f,
                "knot {knot} appears {multiplicity} times, but a curve of degree {degree} allows at \
                 most {} (the notes' convention, without end knots)",
                degree + 1
            ),
            E::EmptyDomain { start, end } => write!(
                f,
                "the domain [{start}, {end}] of the knot vector is empty: its ends must differ"
            ),
            E::OutsideDomain { t, start, end } => {
                write!(f, "parameter t = {t} is outside the domain [{start}, {end}]")
            }
            E::KnotOutsideDomain { knot, start, end } => write!(
                f,
                "knot {knot} is not inside the domain [{start}, {end}] of the curve"
            ),
            E::PointCount { expected, found } => write!(
                f,
                "the knot vector is made for {expected} control points, but {found} were given"
            ),
            E::DimensionMismatch {
                index,
                expected,
                found,
            } => write!(
                f,
                "control point {index} has dimension {found} but control point 0 has dimension {expected}"
            ),
            E::WeightCount { points, weights } => write!(
                f,
                "a NURBS curve needs one weight per control point: {points} control points but {weights} weights"
            ),
            E::ZeroWeight { index } => write!(
                f,
                "weight {index} is zero: the control point would be a point at infinity"
            ),
            E::PointAtInfinity { t } => write!(
                f,
                "the denominator of the rational curve vanishes at t = {t}: the point is at infinity"
            ),
            E::InvalidSpan { span } => write!(
                f,
                "{span} is not the index of a non-empty span [u_k, u_(k+1)] of the domain"
            ),
            E::NotInsertable {
                knot,
                multiplicity,
                times,
                degree,
            } => write!(
                f,
                "knot {knot} cannot be inserted {times} more time(s): it already has multiplicity \
                 {multiplicity}, and insertion stops at multiplicity {degree} (the degree)"
            ),
            E::NotAKnot {
                knot,
                multiplicity,
                times,
            } => write!(
                f,
                "knot {knot} cannot be removed {times} time(s): it has multiplicity {multiplicity}"
            ),
            E::NotRemovable { knot, removed } => write!(
                f,
                "knot {knot} cannot be removed (after {removed} removal(s)) without changing the curve"
            ),
            E::NoDerivativeCurve { reason } => {
                write!(f, "the derivative is not a B-spline curve: {reason}")
            }
            E::NeedsRoot { what, radicand } => write!(
                f,
                "{what} needs the quadratic field √{radicand}: compute over a + b√{radicand}, not \
                 over the rationals"
            ),
            E::NotACircle { reason } => write!(f, "not a circle: {reason}"),
            E::Bezier(e) => write!(f, "{e}"),
            E::Number { what, source } => write!(f, "{what}: {source}"),
        }
    }
}

impl std::error::Error for BSplineError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            BSplineError::Bezier(e) => Some(e),
            BSplineError::Number { source, .. } => Some(source),
            _ => None,
        }
    }
}

impl From<BezierError> for BSplineError {
    fn from(e: BezierError) -> Self {
        BSplineError::Bezier(e)
    }
}
