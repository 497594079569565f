use std::fmt;

/// What can go wrong in linear algebra.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum LinalgError {
    /// Two operands have different dimensions (points of R^2 and R^3, matrices that do not fit).
    DimensionMismatch {
        /// What was being done.
        what: String,
        /// The dimension expected.
        expected: usize,
        /// The dimension found.
        found: usize,
    },
    /// The system has no unique solution.
    Singular {
        /// Why, in words (the first column without a pivot, its size...).
        detail: String,
    },
    /// A least-squares problem with fewer equations (data) than unknowns: the normal matrix
    /// BᵗB is singular whatever the data.
    Underdetermined {
        /// The number of equations (rows of B, data points).
        equations: usize,
        /// The number of unknowns (columns of B, coefficients).
        unknowns: usize,
    },
    /// A matrix given as rows has rows of different lengths.
    Ragged {
        /// The row that differs.
        row: usize,
        /// Its length.
        len: usize,
        /// The length of the first row.
        expected: usize,
    },
}

impl fmt::Display for LinalgError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            LinalgError::DimensionMismatch {
                what,
                expected,
                found,
            } => write!(f, "{what}: expected dimension {expected}, found {found}"),
            LinalgError::Singular { detail } => {
                write!(f, "the linear system is singular (no unique solution): {detail}")
            }
            LinalgError::Underdetermined {
                equations,
                unknowns,
            } => write!(
                f,
                "least squares with {equations} equations for {unknowns} unknowns: the normal \
                 matrix BᵗB is singular; give at least {unknowns} data"
            ),
            LinalgError::Ragged { row, len, expected } => write!(
                f,
                "row {row} has {len} entries but row 0 has {expected}: a matrix needs rows of equal length"
            ),
        }
    }
}

impl std::error::Error for LinalgError {}
