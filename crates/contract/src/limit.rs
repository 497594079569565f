//! Which limit of a run a refusal is about (its name, which the front ends spell as a flag).

use cagd_poly::{PolyError, TooLarge, Unconvertible};
use cagd_scalar::{Exceeded, ScalarError};

/// Which of the [`crate::Limits`] a refusal is about.
#[non_exhaustive]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Limit {
    /// [`crate::Limits::max_degree`].
    Degree,
    /// [`crate::Limits::max_points`].
    Points,
    /// [`crate::Limits::max_digits`].
    Digits,
    /// [`crate::Limits::max_batch`].
    Batch,
    /// [`crate::Limits::max_depth`].
    Depth,
    /// [`crate::Limits::max_exponent`].
    Exponent,
    /// [`crate::Limits::max_seconds`].
    Seconds,
    /// [`crate::Limits::max_memory`].
    Memory,
}

impl Limit {
    /// The name of the limit: its field of [`crate::Limits`] (`max_degree`), which the front ends
    /// spell as a flag (`--max-degree`) or a keyword (`max_degree=`).
    pub fn name(self) -> &'static str {
        match self {
            Limit::Degree => "max_degree",
            Limit::Points => "max_points",
            Limit::Digits => "max_digits",
            Limit::Batch => "max_batch",
            Limit::Depth => "max_depth",
            Limit::Exponent => "max_exponent",
            Limit::Seconds => "max_seconds",
            Limit::Memory => "max_memory",
        }
    }

    /// The limit a grammar's refusal is about: "exponent 1001 at column 6 is larger than 1000"
    /// is about [`Limit::Exponent`].
    pub(crate) fn of_scalar(e: &ScalarError) -> Option<Limit> {
        match e {
            ScalarError::Limit { what } => Limit::of_exceeded(what),
            _ => None,
        }
    }

    /// The limit of what the grammar found too large (a length, a radicand or a power of letters
    /// above 64 are the grammar's own bounds, no setting's).
    pub(crate) fn of_exceeded(what: &Exceeded) -> Option<Limit> {
        match what {
            Exceeded::Digits { .. }
            | Exceeded::DigitsCounted { .. }
            | Exceeded::Literal { .. }
            | Exceeded::Power { .. } => Some(Limit::Digits),
            Exceeded::Depth { .. } => Some(Limit::Depth),
            Exceeded::Exponent { .. } => Some(Limit::Exponent),
            _ => None,
        }
    }

    /// The limit an expression's refusal is about: a power of a variable above the exponent
    /// limit, a coefficient of too many digits, or the grammar's own.
    pub(crate) fn of_poly(e: &PolyError) -> Option<Limit> {
        match e {
            PolyError::Scalar(s) => Limit::of_scalar(s),
            PolyError::TooLarge {
                what: TooLarge::Power { .. },
                ..
            } => Some(Limit::Exponent),
            PolyError::TooLarge {
                what:
                    TooLarge::CoefficientDigits(
                        Exceeded::Digits { .. } | Exceeded::DigitsCounted { .. },
                    ),
                ..
            } => Some(Limit::Digits),
            PolyError::Conversion {
                reason: Unconvertible::Scalar(s),
                ..
            } => Limit::of_scalar(s),
            _ => None,
        }
    }
}
