//! The one error type of cagd-bezier.

use cagd_poly::PolyError;
use cagd_scalar::ScalarError;
use std::fmt;

/// What can go wrong with Bézier and rational Bézier curves.
///
/// Numbers inside the messages are written exactly (`3/2`, `√2/2`).
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum BezierError {
    /// A control polygon without points: a curve needs at least one control point.
    EmptyPolygon,
    /// Control point `index` has another dimension than control point 0.
    DimensionMismatch {
        /// The index of the offending control point.
        index: usize,
        /// The dimension of control point 0.
        expected: usize,
        /// The dimension of control point `index`.
        found: usize,
    },
    /// The blossom of a degree-n curve takes exactly n arguments.
    BlossomArguments {
        /// The degree n of the curve.
        degree: usize,
        /// How many arguments were given.
        found: usize,
    },
    /// An interval [a, b] with a = b (or a > b where an increasing interval is required).
    DegenerateInterval {
        /// The left end, as text.
        a: String,
        /// The right end, as text.
        b: String,
    },
    /// A sign that a rule needs but that cannot be decided (the values are in letters).
    SignUnknown {
        /// The expression whose sign is needed, as text (`b - a`).
        expression: String,
        /// The rule that needs it.
        rule: String,
    },
    /// A parameter outside the domain of a typed curve.
    OutsideDomain {
        /// The parameter, as text.
        t: String,
        /// The left end of the domain.
        a: String,
        /// The right end of the domain.
        b: String,
    },
    /// A subdivision parameter at (or beyond) an end of the domain: one piece would be empty.
    NotInterior {
        /// The parameter, as text.
        t: String,
        /// The left end of the domain.
        a: String,
        /// The right end of the domain.
        b: String,
    },
    /// A rational curve with a different number of weights than control points.
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
    /// The denominator w(t) of a rational curve vanishes: c(t) is a point at infinity.
    VanishingDenominator {
        /// The parameter, as text.
        t: String,
    },
    /// The construction needs a number the scalar type cannot hold exactly (√2/2 asked of
    /// exact rationals).
    Number {
        /// What was being built.
        what: String,
        /// The underlying error of the number type.
        source: ScalarError,
    },
    /// Homogeneous control points need at least one coordinate: the weight, last.
    HomogeneousWithoutWeight,
    /// A value that must be positive is not.
    NotPositive {
        /// What the value is.
        what: String,
        /// The value, as text.
        value: String,
    },
    /// An error of the polynomial crate, e.g. a closed form of too high a degree for the
    /// Bernstein basis asked for, or in another variable.
    Poly(PolyError),
    /// The data of a circular arc (or conic) are inconsistent.
    NotACircle {
        /// What is wrong, in words, with the exact values.
        reason: String,
    },
}

impl fmt::Display for BezierError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BezierError::EmptyPolygon => {
                write!(f, "the control polygon is empty: a Bézier curve needs at least one control point")
            }
            BezierError::DimensionMismatch {
                index,
                expected,
                found,
            } => write!(
                f,
                "control point {index} has dimension {found} but control point 0 has dimension {expected}"
            ),
            BezierError::BlossomArguments { degree, found } => write!(
                f,
                "the blossom of a curve of degree {degree} takes {degree} arguments, but {found} were given"
            ),
            BezierError::DegenerateInterval { a, b } => write!(
                f,
                "the interval [{a}, {b}] is degenerate: its ends must satisfy a < b"
            ),
            BezierError::SignUnknown { expression, rule } => write!(
                f,
                "{rule}: the sign of {expression} is not known (it is in letters; give the \
                 letters values, or numbers here)"
            ),
            BezierError::OutsideDomain { t, a, b } => {
                write!(f, "parameter t = {t} is outside the domain [{a}, {b}]")
            }
            BezierError::NotInterior { t, a, b } => write!(
                f,
                "subdivision parameter t = {t} must lie strictly inside the domain ({a}, {b})"
            ),
            BezierError::WeightCount { points, weights } => write!(
                f,
                "a rational curve needs one weight per control point: {points} control points but {weights} weights"
            ),
            BezierError::ZeroWeight { index } => write!(
                f,
                "weight {index} is zero: the control point would be a point at infinity"
            ),
            BezierError::VanishingDenominator { t } => write!(
                f,
                "the denominator w(t) of the rational curve vanishes at t = {t}: c(t) is a point at infinity"
            ),
            BezierError::HomogeneousWithoutWeight => write!(
                f,
                "homogeneous control points need at least one coordinate: the weight, written last"
            ),
            BezierError::NotPositive { what, value } => {
                write!(f, "{what} must be positive, but it is {value}")
            }
            BezierError::Number { what, source } => write!(f, "{what}: {source}"),
            BezierError::Poly(e) => write!(f, "{e}"),
            BezierError::NotACircle { reason } => write!(f, "not a circular arc: {reason}"),
        }
    }
}

impl std::error::Error for BezierError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            BezierError::Number { source, .. } => Some(source),
            BezierError::Poly(e) => Some(e),
            _ => None,
        }
    }
}

impl From<PolyError> for BezierError {
    fn from(e: PolyError) -> Self {
        BezierError::Poly(e)
    }
}
