//! The numbers of cagd-exact.
//!
//! Every algorithm of the engine is generic over one trait, [`Scalar`]: a field with its
//! arithmetic by value and by reference, exact equality and order, and conversions. Three types
//! implement it:
//!
//! - [`BigRational`] (`num_rational`), the default: every control point such as
//!   `(1/2, 5/6, 31/6)` is reproduced exactly;
//! - [`Quadratic`], the quadratic field `a + b√d` with rational `a, b`, so that the weights of
//!   circles and spheres (`√2/2`, `√3/2`) stay exact;
//! - `f64`, for figures and speed comparisons only ([`Scalar::is_exact`] is `false`).
//!
//! The crate also owns the one grammar for exact numbers used everywhere (command line, JSON,
//! fixtures), see [`parse_number`] and `docs/format.md`, and the three printers of a number:
//! plain text (`5/6`, `√2/2`), LaTeX (`\frac{5}{6}`, `\frac{\sqrt{2}}{2}`) and JSON (a string that
//! [`parse_number`] reads back to the same value).
//!
//! ```
//! use cagd_scalar::{parse_number, Scalar};
//! let x = parse_number("1/2 + 3/4*sqrt(2)").unwrap();
//! assert_eq!(x.to_text(), "1/2 + 3√2/4");
//! assert_eq!(x.to_latex(), r"\frac{1}{2} + \frac{3\sqrt{2}}{4}");
//! assert_eq!(parse_number(&x.to_json_string()).unwrap(), x);
//! let half_root = parse_number("sqrt2/2").unwrap();
//! assert_eq!((half_root.clone() * &half_root).to_text(), "1/2");
//! ```

mod error;
mod float;
mod grammar;
mod quadratic;
mod rational;

pub use error::ScalarError;
pub use grammar::{
    parse_number, parse_number_with, parse_with, Builder, Limits, NumberBuilder, Span, Token,
    TokenKind, Tokens,
};
pub use num_bigint::BigInt;
pub use num_rational::BigRational;
pub use quadratic::Quadratic;

use num_traits::{One, Zero};
use std::borrow::Cow;
use std::fmt::{Debug, Display};
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// The one bound every algorithm of cagd-exact is generic over: an ordered field.
///
/// All arithmetic is available by value (`a + b`) and with a borrowed right-hand side
/// (`a + &b`), plus the by-reference helpers [`Scalar::add_ref`], [`Scalar::sub_ref`],
/// [`Scalar::mul_ref`] for inner loops that must not clone. Equality is exact for the exact
/// types; the order is exact too (a + b√d is compared without rounding).
///
/// Division by zero follows the number type (it panics for the exact types, as `num_rational`
/// does); code that may divide by a value coming from input uses [`Scalar::checked_div`].
pub trait Scalar:
    Clone
    + Debug
    + Display
    + PartialEq
    + PartialOrd
    + Send
    + Sync
    + 'static
    + Zero
    + One
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
    + for<'a> Add<&'a Self, Output = Self>
    + for<'a> Sub<&'a Self, Output = Self>
    + for<'a> Mul<&'a Self, Output = Self>
    + for<'a> Div<&'a Self, Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
    + DivAssign
    + for<'a> AddAssign<&'a Self>
    + for<'a> SubAssign<&'a Self>
    + for<'a> MulAssign<&'a Self>
    + for<'a> DivAssign<&'a Self>
{
    /// The integer `n`.
    fn from_i64(n: i64) -> Self;

    /// The rational `num/den`.
    ///
    /// # Panics
    /// If `den == 0`. Meant for constants of the algorithms (such as `i/(m+1)`), never for input.
    fn from_ratio(num: i64, den: i64) -> Self;

    /// The value of an exact rational.
    fn from_rational(q: &BigRational) -> Self;

    /// The value of an exact number of the grammar, or an error if this type cannot hold it
    /// exactly (a `√2` asked of [`BigRational`], or of a quadratic field for another root).
    fn try_from_number(x: &Quadratic) -> Result<Self, ScalarError>;

    /// The exact value as a number of the grammar; `None` for `f64`.
    fn to_number(&self) -> Option<Quadratic>;

    /// Whether this type computes exactly (`false` only for `f64`).
    fn is_exact() -> bool;

    /// The exact rational value, borrowed where the type stores one: `Some` for a
    /// [`BigRational`] and for a [`Quadratic`] without root part, `None` for `a + b√d` with
    /// `b ≠ 0` and for `f64`. The integer fast paths of the algorithm crates (common
    /// denominators, machine integers) read their input through it without cloning.
    fn as_rational(&self) -> Option<Cow<'_, BigRational>> {
        if !Self::is_exact() {
            return None;
        }
        self.to_number()?.to_rational().map(Cow::Owned)
    }

    /// The value of an exact rational, taking ownership (no clone for [`BigRational`]).
    fn from_rational_owned(q: BigRational) -> Self {
        Self::from_rational(&q)
    }

    /// The nearest `f64` (for figures only).
    fn to_f64(&self) -> f64;

    /// `self / rhs`, or `None` when `rhs` is zero (or the roots of the two numbers differ).
    fn checked_div(&self, rhs: &Self) -> Option<Self>;

    /// The square root when it exists in this number type: exact for the exact types
    /// (`None` when the root is not in the field), approximate for `f64`.
    fn sqrt_exact(&self) -> Option<Self> {
        None
    }

    /// `self + rhs` without consuming either.
    fn add_ref(&self, rhs: &Self) -> Self {
        self.clone() + rhs
    }
    /// `self - rhs` without consuming either.
    fn sub_ref(&self, rhs: &Self) -> Self {
        self.clone() - rhs
    }
    /// `self * rhs` without consuming either.
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.clone() * rhs
    }

    /// `self^n` by repeated squaring.
    fn powi(&self, n: u32) -> Self {
        let mut base = self.clone();
        let mut acc = Self::one();
        let mut n = n;
        while n > 0 {
            if n & 1 == 1 {
                acc *= &base;
            }
            n >>= 1;
            if n > 0 {
                base = base.mul_ref(&base);
            }
        }
        acc
    }

    /// Plain text, as the notes write numbers: `5/6`, `-3`, `√2/2`, `1/2 + 3√2/4`.
    fn to_text(&self) -> String {
        self.to_string()
    }

    /// LaTeX: `\frac{5}{6}`, `\frac{\sqrt{2}}{2}`.
    fn to_latex(&self) -> String;

    /// The JSON form: a string in the grammar that [`parse_number`] reads back exactly
    /// (`"5/6"`, `"sqrt2/2"`). For `f64` it is the shortest decimal that round-trips.
    fn to_json_string(&self) -> String;
}

/// Writes `p/q` from an integer numerator and a positive denominator in LaTeX.
pub(crate) fn latex_fraction(num: &str, den: &BigInt) -> String {
    if den.is_one() {
        num.to_string()
    } else {
        format!("\\frac{{{num}}}{{{den}}}")
    }
}

/// Parses a rational number (no roots allowed); convenience for tests and constants.
///
/// ```
/// use cagd_scalar::{parse_rational, BigRational, BigInt};
/// assert_eq!(parse_rational("0.125").unwrap(), BigRational::new(BigInt::from(1), BigInt::from(8)));
/// assert!(parse_rational("sqrt2").is_err());
/// ```
pub fn parse_rational(text: &str) -> Result<BigRational, ScalarError> {
    let x = parse_number(text)?;
    x.to_rational()
        .ok_or_else(|| ScalarError::NotRational { value: x.to_text() })
}

/// An exact rational literal for tests and examples: `q!(-3/4)`, `q!(5)`, `q!(0.125)`.
///
/// # Panics
/// If the literal is not a rational number of the grammar.
#[macro_export]
macro_rules! q {
    ($($t:tt)*) => {
        $crate::parse_rational(stringify!($($t)*)).expect("q!: not a rational literal")
    };
}

/// Converts an exact rational to any scalar; a shorthand used across the engine.
pub fn cast<S: Scalar>(q: &BigRational) -> S {
    S::from_rational(q)
}

#[cfg(test)]
mod tests;
