use std::fmt;

/// What can go wrong with numbers: reading them, or asking a number type for a value it cannot
/// hold exactly.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum ScalarError {
    /// The text is not a number (or expression) of the grammar.
    Parse {
        /// 1-based column (in characters) where the problem was found.
        column: usize,
        /// What the parser expected there, in words.
        expected: String,
        /// What it found instead.
        found: String,
    },
    /// A division by zero, e.g. `1/0`.
    DivisionByZero {
        /// 1-based column of the division, when known from parsing.
        column: Option<usize>,
    },
    /// `sqrt` of a negative number.
    NegativeSqrt {
        /// The argument of the square root.
        value: String,
    },
    /// Two different square roots in one computation, e.g. `sqrt2 + sqrt3`: a + b√d holds one d.
    MixedRoots {
        /// The first root's radicand.
        first: u64,
        /// The second root's radicand.
        second: u64,
    },
    /// A number with a square root where only rationals are allowed.
    NotRational {
        /// The number, as text.
        value: String,
    },
    /// A resource limit of the parser (exponent, digits, depth).
    Limit {
        /// Which limit, and its value.
        what: String,
    },
}

impl fmt::Display for ScalarError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ScalarError::Parse {
                column,
                expected,
                found,
            } => write!(f, "at column {column}: expected {expected}, found {found}"),
            ScalarError::DivisionByZero { column: Some(c) } => {
                write!(f, "at column {c}: division by zero")
            }
            ScalarError::DivisionByZero { column: None } => write!(f, "division by zero"),
            ScalarError::NegativeSqrt { value } => {
                write!(f, "square root of a negative number ({value}) is not real")
            }
            ScalarError::MixedRoots { first, second } => write!(
                f,
                "numbers with √{first} and √{second} cannot be mixed: a problem runs in one field a + b√d"
            ),
            ScalarError::NotRational { value } => write!(
                f,
                "{value} is not a rational number (it has a square root) where a rational is required"
            ),
            ScalarError::Limit { what } => write!(f, "limit exceeded: {what}"),
        }
    }
}

impl std::error::Error for ScalarError {}
