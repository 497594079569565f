//! The one error type of cagd-poly.

use cagd_scalar::ScalarError;
use std::fmt;

/// What can go wrong with polynomials: reading an expression, evaluating, changing basis.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum PolyError {
    /// An error of the number grammar (with its column), a division by zero, a negative square
    /// root, two different roots... as reported by `cagd-scalar`.
    Scalar(ScalarError),
    /// A name that is not a variable (nor a product of one-letter variables such as `uv`).
    UnknownVariable {
        /// The name as written.
        name: String,
        /// 1-based column, when it comes from parsing.
        column: Option<usize>,
    },
    /// An operation of the expression language that is not defined on these operands, such as
    /// a tuple times a tuple or a scalar plus a tuple.
    Operation {
        /// 1-based column of the operator.
        column: usize,
        /// What is wrong, in words.
        message: String,
    },
    /// A division by a non-constant polynomial (only constants can divide a polynomial).
    DivisionByPolynomial {
        /// 1-based column of the `/`.
        column: usize,
        /// The divisor, as text.
        divisor: String,
    },
    /// A square root that is not a square root of a non-negative rational constant.
    Sqrt {
        /// 1-based column of `sqrt`.
        column: usize,
        /// What is wrong, in words.
        message: String,
    },
    /// Numbers with two different square roots in one expression, e.g. `sqrt2 + sqrt3`.
    MixedRoots {
        /// 1-based column of the second root.
        column: usize,
        /// The first radicand met.
        first: u64,
        /// The radicand that differs.
        second: u64,
    },
    /// An expression too large to expand (degree or number of terms).
    TooLarge {
        /// 1-based column of the operation.
        column: usize,
        /// What limit, in words.
        what: String,
    },
    /// Evaluation without a value for a variable the polynomial uses.
    MissingVariable {
        /// The variable.
        var: String,
    },
    /// Two operands of different dimensions (tuples of 2 and 3 polynomials...).
    DimensionMismatch {
        /// What was being done.
        what: String,
        /// The dimension expected.
        expected: usize,
        /// The dimension found.
        found: usize,
    },
    /// A polynomial whose degree exceeds the degree of the Bernstein basis asked for.
    DegreeTooHigh {
        /// The variable.
        var: String,
        /// The degree of the polynomial in it.
        degree: u32,
        /// The degree of the basis.
        max: u32,
    },
    /// A polynomial that uses a variable outside the Bernstein basis asked for.
    ExtraVariable {
        /// The variable.
        var: String,
        /// The variables of the basis.
        basis: String,
    },
    /// A tensor-product basis asked for in one variable twice.
    SameVariable {
        /// The variable.
        var: String,
    },
    /// An empty control polygon or mesh.
    Empty {
        /// What is empty.
        what: String,
    },
    /// A control mesh whose rows have different lengths.
    Ragged {
        /// The row that differs.
        row: usize,
        /// Its length.
        len: usize,
        /// The length of row 0.
        expected: usize,
    },
    /// The denominator of a rational map vanishes where it is evaluated, or is the zero
    /// polynomial.
    ZeroDenominator {
        /// Where, as text.
        at: String,
    },
    /// An affine reparametrization onto an interval of length zero.
    DegenerateInterval {
        /// The end point `a = b`, as text.
        at: String,
    },
    /// A coefficient that the target number type cannot hold exactly.
    Conversion {
        /// The coefficient, as text.
        value: String,
        /// Why not.
        reason: String,
    },
    /// A scalar polynomial where a tuple was expected, or the other way round.
    Shape {
        /// What was expected.
        expected: String,
        /// What was found.
        found: String,
    },
}

impl fmt::Display for PolyError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PolyError::Scalar(e) => write!(f, "{e}"),
            PolyError::UnknownVariable { name, column } => {
                if let Some(c) = column {
                    write!(f, "at column {c}: ")?;
                }
                write!(
                    f,
                    "unknown variable '{name}' (the variables are u, v, w, t, s, x, y, z; 'uv' means u v)"
                )
            }
            PolyError::Operation { column, message } => write!(f, "at column {column}: {message}"),
            PolyError::DivisionByPolynomial { column, divisor } => write!(
                f,
                "at column {column}: division by a polynomial is not a polynomial (divisor {divisor}; only nonzero constants can divide)"
            ),
            PolyError::Sqrt { column, message } => write!(f, "at column {column}: {message}"),
            PolyError::MixedRoots {
                column,
                first,
                second,
            } => write!(
                f,
                "at column {column}: numbers with √{first} and √{second} cannot be mixed: an expression runs in one field a + b√d"
            ),
            PolyError::TooLarge { column, what } => {
                write!(f, "at column {column}: expression too large to expand: {what}")
            }
            PolyError::MissingVariable { var } => {
                write!(f, "no value given for the variable {var}")
            }
            PolyError::DimensionMismatch {
                what,
                expected,
                found,
            } => write!(f, "{what}: expected dimension {expected}, found {found}"),
            PolyError::DegreeTooHigh { var, degree, max } => write!(
                f,
                "the polynomial has degree {degree} in {var}, more than the degree {max} of the Bernstein basis"
            ),
            PolyError::ExtraVariable { var, basis } => write!(
                f,
                "the polynomial depends on {var}, but the Bernstein basis is in {basis} only"
            ),
            PolyError::SameVariable { var } => write!(
                f,
                "the two variables of a tensor-product Bernstein basis must differ, both are {var}"
            ),
            PolyError::Empty { what } => write!(f, "{what} is empty"),
            PolyError::Ragged { row, len, expected } => write!(
                f,
                "row {row} of the control mesh has {len} points but row 0 has {expected}"
            ),
            PolyError::ZeroDenominator { at } => write!(f, "the denominator vanishes {at}"),
            PolyError::DegenerateInterval { at } => write!(
                f,
                "the interval [{at}, {at}] has length zero: cannot reparametrize onto it"
            ),
            PolyError::Conversion { value, reason } => {
                write!(f, "coefficient {value} cannot be converted: {reason}")
            }
            PolyError::Shape { expected, found } => {
                write!(f, "expected {expected}, found {found}")
            }
        }
    }
}

impl std::error::Error for PolyError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            PolyError::Scalar(e) => Some(e),
            _ => None,
        }
    }
}

impl From<ScalarError> for PolyError {
    fn from(e: ScalarError) -> Self {
        PolyError::Scalar(e)
    }
}
