use cagd_bezier::BezierError;
use cagd_poly::PolyError;
use std::fmt;

/// What can go wrong with a surface.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum SurfaceError {
    /// A mesh with no rows or no columns.
    EmptyMesh,
    /// A mesh whose rows differ in length.
    RaggedMesh {
        /// The row that differs.
        row: usize,
        /// Its length.
        len: usize,
        /// The length of row 0.
        expected: usize,
    },
    /// Control points of different dimensions.
    MixedDimensions {
        /// Where the odd point is, `c_ij`.
        row: usize,
        /// Its column.
        col: usize,
        /// Its dimension.
        found: usize,
        /// The dimension of c_00.
        expected: usize,
    },
    /// A weight grid that does not have the mesh's shape.
    WeightShape {
        /// Mesh shape (rows, columns).
        mesh: (usize, usize),
        /// Weight grid shape.
        weights: (usize, usize),
    },
    /// A zero weight.
    ZeroWeight {
        /// Row of the weight.
        row: usize,
        /// Column of the weight.
        col: usize,
    },
    /// A parameter outside the patch's domain.
    OutOfDomain {
        /// Which parameter ("u" or "v").
        param: &'static str,
        /// Its value, as text.
        value: String,
        /// The domain, as text.
        domain: String,
    },
    /// The denominator of a rational patch vanishes at a parameter.
    ZeroDenominator {
        /// The parameter, as text.
        at: String,
    },
    /// A domain [a, b] x [c, d] with a >= b or c >= d.
    DegenerateDomain {
        /// Which parameter ("u" or "v").
        param: &'static str,
        /// The left end, as text.
        a: String,
        /// The right end, as text.
        b: String,
    },
    /// A subdivision parameter at (or beyond) an end of the domain: a piece would be empty.
    NotInterior {
        /// Which parameter ("u" or "v").
        param: &'static str,
        /// Its value, as text.
        value: String,
        /// The interval of that parameter, as text.
        interval: String,
    },
    /// The polar form of a patch of bidegree (m, n) takes m values of u and n values of v.
    BlossomArguments {
        /// Which group ("u" or "v").
        param: &'static str,
        /// The degree in that parameter.
        degree: usize,
        /// How many values were given.
        found: usize,
    },
    /// Forward differences Δ^{r,s} c_ij need r <= m and s <= n.
    DifferenceOrder {
        /// The order in u.
        r: usize,
        /// The order in v.
        s: usize,
        /// The bidegree (m, n).
        bidegree: (usize, usize),
    },
    /// The graph of f(x, y) as a patch of bidegree (m, n) needs f of degree <= m in x and
    /// <= n in y, and m, n >= 1.
    GraphDegree {
        /// The variable of f.
        var: String,
        /// The degree of f in it.
        degree: u32,
        /// The degree of the patch in the matching parameter.
        max: usize,
    },
    /// Something that needs points of a given dimension (the normal c_u x c_v needs R^3).
    Dimension {
        /// What was being computed.
        what: String,
        /// The dimension it needs.
        expected: usize,
        /// The dimension found.
        found: usize,
    },
    /// A value that must be positive is not (a parameter length Δu, a weight for the
    /// convex-hull property).
    NotPositive {
        /// What the value is.
        what: String,
        /// The value, as text.
        value: String,
    },
    /// Two patches that cannot be compared along a border: their borders have different
    /// degrees.
    BorderDegree {
        /// The parameter along the border ("u" or "v").
        param: &'static str,
        /// The degree of the first patch along it.
        first: usize,
        /// The degree of the second patch along it.
        second: usize,
    },
    /// An order of continuity or derivative that the patch cannot provide.
    Order {
        /// What is wrong, in words.
        reason: String,
    },
    /// An error from a curve algorithm applied to a row or column.
    Curve(String),
    /// An error from a polynomial (closed form) computation.
    Poly(String),
    /// An error from linear algebra (a singular interpolation problem...).
    Linalg(String),
    /// Anything else a student should read, in words.
    Invalid(String),
}

impl fmt::Display for SurfaceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SurfaceError::EmptyMesh => write!(f, "the control mesh is empty"),
            SurfaceError::RaggedMesh { row, len, expected } => write!(
                f,
                "row {row} of the control mesh has {len} points but row 0 has {expected}: a mesh needs rows of equal length"
            ),
            SurfaceError::MixedDimensions {
                row,
                col,
                found,
                expected,
            } => write!(
                f,
                "control point c_{row},{col} has {found} coordinates but c_0,0 has {expected}"
            ),
            SurfaceError::WeightShape { mesh, weights } => write!(
                f,
                "the weights form a {}x{} grid but the mesh is {}x{}",
                weights.0, weights.1, mesh.0, mesh.1
            ),
            SurfaceError::ZeroWeight { row, col } => {
                write!(f, "weight w_{row},{col} is zero: weights must be nonzero")
            }
            SurfaceError::OutOfDomain {
                param,
                value,
                domain,
            } => write!(f, "parameter {param} = {value} is outside the domain {domain}"),
            SurfaceError::ZeroDenominator { at } => write!(
                f,
                "the denominator of the rational patch vanishes at {at}: the point is at infinity"
            ),
            SurfaceError::DegenerateDomain { param, a, b } => write!(
                f,
                "the interval [{a}, {b}] of {param} is degenerate: its ends must satisfy {a} < {b}"
            ),
            SurfaceError::NotInterior {
                param,
                value,
                interval,
            } => write!(
                f,
                "subdivision parameter {param} = {value} must lie strictly inside {interval}"
            ),
            SurfaceError::BlossomArguments {
                param,
                degree,
                found,
            } => write!(
                f,
                "the polar form takes {degree} values of {param} (the degree in {param}), but {found} were given"
            ),
            SurfaceError::DifferenceOrder { r, s, bidegree } => write!(
                f,
                "the differences Δ^{{{r},{s}}} need bidegree at least ({r}, {s}), but the patch has bidegree ({}, {})",
                bidegree.0, bidegree.1
            ),
            SurfaceError::GraphDegree { var, degree, max } => {
                let param = if var == "x" || var == "u" { "u" } else { "v" };
                let needed = (*degree).max(1);
                write!(
                    f,
                    "f has degree {degree} in {var}: its graph needs degree at least {needed} in {param}, but the patch has degree {max}"
                )
            }
            SurfaceError::Dimension {
                what,
                expected,
                found,
            } => write!(
                f,
                "{what} needs points with {expected} coordinates, but they have {found}"
            ),
            SurfaceError::NotPositive { what, value } => {
                write!(f, "{what} must be positive, but it is {value}")
            }
            SurfaceError::BorderDegree {
                param,
                first,
                second,
            } => write!(
                f,
                "the patches do not share a border: along {param} the first has degree {first} and the second degree {second}"
            ),
            SurfaceError::Order { reason } => write!(f, "{reason}"),
            SurfaceError::Curve(e) => write!(f, "{e}"),
            SurfaceError::Poly(e) => write!(f, "{e}"),
            SurfaceError::Linalg(e) => write!(f, "{e}"),
            SurfaceError::Invalid(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for SurfaceError {}

impl From<BezierError> for SurfaceError {
    fn from(e: BezierError) -> Self {
        SurfaceError::Curve(e.to_string())
    }
}

impl From<PolyError> for SurfaceError {
    fn from(e: PolyError) -> Self {
        SurfaceError::Poly(e.to_string())
    }
}
