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
    /// An error from a curve algorithm applied to a row or column.
    Curve(String),
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
            SurfaceError::Curve(e) => write!(f, "{e}"),
            SurfaceError::Linalg(e) => write!(f, "{e}"),
            SurfaceError::Invalid(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for SurfaceError {}
