//! The one error type of the crate.

use std::fmt;

/// What can go wrong with a triangular Bézier patch.
///
/// Every message names the offending value so that a student can find it in the input.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum TriangleError {
    /// The control net does not have (n + 1)(n + 2)/2 points.
    WrongPointCount {
        /// The degree n asked for.
        degree: usize,
        /// (n + 1)(n + 2)/2.
        needed: usize,
        /// How many points were given.
        found: usize,
    },
    /// The degree is so large that (n + 1)(n + 2)/2 does not fit in memory addresses.
    DegreeTooLarge {
        /// The degree asked for (as text, since it may be the sum of two degrees).
        degree: String,
    },
    /// Two control points have different dimensions.
    MixedDimensions {
        /// The multi-index (i, j, k) of the first point whose dimension differs.
        index: (usize, usize, usize),
        /// Its dimension.
        found: usize,
        /// The dimension of b_{n,0,0}, the first point.
        expected: usize,
    },
    /// Barycentric coordinates (r, s, t) must satisfy r + s + t = 1.
    BarycentricSum {
        /// The coordinates, as text.
        coords: String,
        /// Their sum, as text.
        sum: String,
    },
    /// A direction (a barycentric vector) must have components summing to 0.
    DirectionSum {
        /// The components, as text.
        components: String,
        /// Their sum, as text.
        sum: String,
    },
    /// (i, j, k) is not a multi-index of the degree: i + j + k ≠ n.
    NotAnIndex {
        /// The multi-index asked for.
        index: (usize, usize, usize),
        /// The degree n of the patch.
        degree: usize,
    },
    /// The blossom of a degree-n patch takes exactly n arguments.
    BlossomArity {
        /// The degree n of the patch.
        degree: usize,
        /// How many arguments were given.
        found: usize,
    },
    /// A computation that needs points of R^3 (the normal vector, a cross product) was asked
    /// of a patch in another dimension.
    DimensionNotThree {
        /// What was being computed.
        what: String,
        /// The dimension of the control points.
        found: usize,
    },
    /// A closed form given to build a patch uses variables other than u and v.
    NotInUV {
        /// The other variables, comma-separated.
        vars: String,
    },
    /// A closed form has a total degree higher than the degree asked for.
    DegreeTooHigh {
        /// The total degree of the polynomial map.
        found: usize,
        /// The degree n of the patch asked for.
        degree: usize,
    },
}

impl fmt::Display for TriangleError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            TriangleError::WrongPointCount {
                degree,
                needed,
                found,
            } => write!(
                f,
                "a triangular patch of degree {degree} needs ({degree} + 1)({degree} + 2)/2 = \
                 {needed} control points, found {found}"
            ),
            TriangleError::DegreeTooLarge { degree } => write!(
                f,
                "degree {degree} is too large: its (n + 1)(n + 2)/2 control points cannot be stored"
            ),
            TriangleError::MixedDimensions {
                index: (i, j, k),
                found,
                expected,
            } => write!(
                f,
                "control point b_{{{i},{j},{k}}} has dimension {found}, but the first control \
                 point has dimension {expected}: all control points need the same dimension"
            ),
            TriangleError::BarycentricSum { coords, sum } => write!(
                f,
                "barycentric coordinates {coords} sum to {sum}, not 1 (r + s + t = 1 is needed)"
            ),
            TriangleError::DirectionSum { components, sum } => write!(
                f,
                "direction {components} has components summing to {sum}, not 0 \
                 (a direction is a difference of two barycentric points)"
            ),
            TriangleError::NotAnIndex {
                index: (i, j, k),
                degree,
            } => write!(
                f,
                "b_{{{i},{j},{k}}} is not a control point of a patch of degree {degree}: \
                 {i} + {j} + {k} = {}, not {degree}",
                i + j + k
            ),
            TriangleError::BlossomArity { degree, found } => write!(
                f,
                "the blossom of a patch of degree {degree} takes {degree} argument{}, found {found}",
                if *degree == 1 { "" } else { "s" }
            ),
            TriangleError::DimensionNotThree { what, found } => write!(
                f,
                "{what} needs control points in R^3, but they have dimension {found}"
            ),
            TriangleError::NotInUV { vars } => write!(
                f,
                "a triangular patch is a polynomial map in u and v only, but the map also uses {vars}"
            ),
            TriangleError::DegreeTooHigh { found, degree } => write!(
                f,
                "the polynomial map has total degree {found}, more than the degree {degree} of the \
                 patch asked for (ask for degree {found} or more)"
            ),
        }
    }
}

impl std::error::Error for TriangleError {}
