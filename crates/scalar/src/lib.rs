//! The numbers of cagd-exact.
//!
//! Every algorithm of the engine is generic over one bound, [`Scalar`]. Four types implement
//! it:
//!
//! - [`BigRational`] (`num_rational`), the reference: every control point such as
//!   `(1/2, 5/6, 31/6)` is reproduced exactly;
//! - [`Rat`], the same numbers fast: numerator and denominator inline as machine words while
//!   they fit, a [`BigRational`] when they do not; problems without roots run over it;
//! - [`Quadratic`], the quadratic field `a + b√d` with rational `a, b`, so that the weights of
//!   circles and spheres (`√2/2`, `√3/2`) stay exact;
//! - `f64`, for figures and speed comparisons only ([`ExactRational::is_exact`] is `false`).
//!
//! # One bound, four jobs
//!
//! [`Scalar`] has no methods of its own: it is the four traits below, one per job, with a
//! blanket impl, so an algorithm names one bound (`fn blossom<S: Scalar>(...)`) and a number
//! type implements the jobs separately.
//!
//! | trait | job | holds |
//! |---|---|---|
//! | [`FieldOps`] | the arithmetic | `Clone`, `Debug`, `Display`, `PartialEq`, `PartialOrd`, `Send + Sync + 'static`, `Zero`, `One`, the operators by value and by reference and their assign forms; `from_i64`, `from_ratio`, `checked_div`, `add_ref`/`sub_ref`/`mul_ref`, `powi`, and `compare` (the order, `None` when it cannot be decided) |
//! | [`ExactRational`] | the hook of the integer fast paths and of the problem layer | `is_exact`, `as_rational`, `from_rational`, `from_rational_owned`, `try_from_number`, `to_number`, and `to_f64` for figures |
//! | [`SquareRoot`] | square roots where the field has them | `sqrt_exact`, and `sqrt_of(n)`, √n from the field: a quarter circle's weight is `S::sqrt_of(2)` over `S::from_i64(2)`, never the text `"sqrt2/2"` parsed |
//! | [`Print`] | the three printers | `to_text`, `to_latex`, `to_json_string` |
//!
//! Only [`ExactRational`] names [`BigRational`] and [`Quadratic`]. A new field (polynomials in
//! a named parameter, say) implements the arithmetic and the printers, says in its hook what
//! it cannot convert, and may leave [`SquareRoot`] to its defaults (no roots); its order may
//! be partial, which [`FieldOps::compare`] reports as `None`.
//! Generic code reaches every method through `S: Scalar`; code holding a concrete type imports
//! the trait of the method it calls (`use cagd_scalar::Print` for `x.to_text()` on a
//! `Quadratic`), and a method path names its own trait (`.map(Print::to_text)`).
//!
//! The crate also owns the one grammar for exact numbers used everywhere (command line, JSON,
//! fixtures), see [`parse_number`] and `docs/format.md`, and the three printers of a number:
//! plain text (`5/6`, `√2/2`), LaTeX (`\frac{5}{6}`, `\frac{\sqrt{2}}{2}`) and JSON (a string that
//! [`parse_number`] reads back to the same value).
//!
//! ```
//! use cagd_scalar::{parse_number, Print};
//! let x = parse_number("1/2 + 3/4*sqrt(2)").unwrap();
//! assert_eq!(x.to_text(), "1/2 + 3√2/4");
//! assert_eq!(x.to_latex(), r"\frac{1}{2} + \frac{3\sqrt{2}}{4}");
//! assert_eq!(parse_number(&x.to_json_string()).unwrap(), x);
//! let half_root = parse_number("sqrt2/2").unwrap();
//! assert_eq!((half_root.clone() * &half_root).to_text(), "1/2");
//! ```

/// The by-value and by-reference forms of one operator of the number type `$T` and its
/// assign forms, all from `$wrap(self.$imp(&rhs))` (`$imp` takes both by reference).
macro_rules! forward_op {
    ($T:ident, $wrap:path, $Op:ident, $op:ident, $OpAssign:ident, $op_assign:ident, $imp:ident) => {
        impl $Op<$T> for $T {
            type Output = $T;
            fn $op(self, rhs: $T) -> $T {
                $wrap(self.$imp(&rhs))
            }
        }
        impl<'a> $Op<&'a $T> for $T {
            type Output = $T;
            fn $op(self, rhs: &'a $T) -> $T {
                $wrap(self.$imp(rhs))
            }
        }
        impl<'a, 'b> $Op<&'b $T> for &'a $T {
            type Output = $T;
            fn $op(self, rhs: &'b $T) -> $T {
                $wrap(self.$imp(rhs))
            }
        }
        impl $OpAssign<$T> for $T {
            fn $op_assign(&mut self, rhs: $T) {
                *self = $wrap(self.$imp(&rhs));
            }
        }
        impl<'a> $OpAssign<&'a $T> for $T {
            fn $op_assign(&mut self, rhs: &'a $T) {
                *self = $wrap(self.$imp(rhs));
            }
        }
    };
}

pub mod cancel;
mod decimal;
mod error;
mod float;
pub mod gcd;
mod grammar;
mod literal;
mod quadratic;
mod rational;
mod small;

pub use decimal::{push_abs_rational, push_integer, push_rational, rational_text};
pub use error::{Exceeded, Expected, Found, ScalarError};
pub use gcd::gcd_u64;
pub use grammar::{
    parse_number, parse_number_with, parse_with, Builder, Limits, NumberBuilder, Span, Token,
    TokenKind, Tokens,
};
pub use literal::{parse_literal, word_literal};
pub use num_bigint::BigInt;
pub use num_rational::BigRational;
pub use quadratic::Quadratic;
pub use small::Rat;

use num_traits::{One, Zero};
use std::borrow::Cow;
use std::cmp::Ordering;
use std::fmt::{Debug, Display};
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// The arithmetic of a field: the job every algorithm needs.
///
/// All arithmetic is available by value (`a + b`) and with a borrowed right-hand side
/// (`a + &b`), plus the by-reference helpers [`FieldOps::add_ref`], [`FieldOps::sub_ref`],
/// [`FieldOps::mul_ref`] for inner loops that must not clone. Equality is exact for the exact
/// types.
///
/// Order: an algorithm that decides something from an order (an error for a radius that is not
/// positive, knots that decrease, an empty interval `a < b`) asks [`FieldOps::compare`], which
/// may answer `None`. `PartialOrd` is still a supertrait, so `a < b` compiles, but it answers
/// `false` where `compare` answers `None`; the order of a + b√d is exact (compared without
/// rounding).
///
/// Division by zero follows the number type (it panics for the exact types, as `num_rational`
/// does); code that may divide by a value coming from input uses [`FieldOps::checked_div`].
pub trait FieldOps:
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

    /// `self / rhs`, or `None` when `rhs` is zero (or the roots of the two numbers differ).
    fn checked_div(&self, rhs: &Self) -> Option<Self>;

    /// The order of `self` and `other`, or `None` when the order cannot be decided: two
    /// numbers with different roots (`√2` and `√3`), a NaN, or (in a field whose order is
    /// only partial) two values that no order of the field compares.
    ///
    /// ```
    /// use cagd_scalar::{parse_number, FieldOps};
    /// use std::cmp::Ordering;
    /// let (a, b) = (parse_number("sqrt2").unwrap(), parse_number("3/2").unwrap());
    /// assert_eq!(a.compare(&b), Some(Ordering::Less));
    /// assert_eq!(a.compare(&parse_number("sqrt3").unwrap()), None);
    /// ```
    fn compare(&self, other: &Self) -> Option<Ordering> {
        self.partial_cmp(other)
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
}

/// The exact-rational hook: how a number type meets the exact rationals and the numbers of the
/// grammar.
///
/// The integer fast paths of the algorithm crates (common denominators, machine integers) read
/// their input through [`ExactRational::as_rational`] and write their answer back with
/// [`ExactRational::from_rational_owned`]; the problem layer reads numbers once, as
/// [`Quadratic`]s, and converts them with [`ExactRational::try_from_number`]. Figures take
/// [`ExactRational::to_f64`].
pub trait ExactRational: Sized {
    /// Whether this type computes exactly (`false` only for `f64`).
    fn is_exact() -> bool;

    /// The value of an exact rational.
    fn from_rational(q: &BigRational) -> Self;

    /// The value of an exact rational, taking ownership (no clone for [`BigRational`]).
    fn from_rational_owned(q: BigRational) -> Self {
        Self::from_rational(&q)
    }

    /// The value of `num/den` (`den ≠ 0`) from machine integers, reduced: the
    /// machine-integer fast paths write their answers through it without building a big
    /// rational.
    fn from_small_ratio(num: i128, den: i128) -> Self {
        Self::from_rational_owned(BigRational::new(BigInt::from(num), BigInt::from(den)))
    }

    /// The value of an exact number of the grammar, or an error if this type cannot hold it
    /// exactly (a `√2` asked of [`BigRational`], or of a quadratic field for another root).
    fn try_from_number(x: &Quadratic) -> Result<Self, ScalarError>;

    /// The exact value as a number of the grammar; `None` for `f64`.
    fn to_number(&self) -> Option<Quadratic>;

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

    /// The exact rational value as `p/q` on machine integers (q > 0), when it is rational and
    /// both fit in `i128`: the machine-integer fast paths start from it without building a big
    /// rational. `None` otherwise.
    fn as_small_ratio(&self) -> Option<(i128, i128)> {
        let q = self.as_rational()?;
        Some((
            num_traits::ToPrimitive::to_i128(q.numer())?,
            num_traits::ToPrimitive::to_i128(q.denom())?,
        ))
    }

    /// The nearest `f64` (for figures only).
    fn to_f64(&self) -> f64;
}

/// Square roots, where the field has them.
///
/// Algorithms that need a root take it from the field, never by parsing text: the weight √2/2
/// of a quarter circle is `S::sqrt_of(2)` divided by `S::from_i64(2)`, and a field without √2
/// (the exact rationals) answers `None`, which the algorithm turns into its own error.
///
/// ```
/// use cagd_scalar::{BigRational, FieldOps, Print, Quadratic, SquareRoot};
/// let half_root = <Quadratic as SquareRoot>::sqrt_of(2).map(|r| r / Quadratic::from_i64(2));
/// assert_eq!(half_root.map(|w| w.to_text()).as_deref(), Some("√2/2"));
/// assert_eq!(<BigRational as SquareRoot>::sqrt_of(2), None);
/// assert_eq!(<BigRational as SquareRoot>::sqrt_of(9), Some(BigRational::from_i64(3)));
/// ```
///
/// (`Quadratic` also has an inherent [`Quadratic::sqrt_of`] of a rational, returning the error;
/// on a concrete `Quadratic` that one is found first, hence `<Quadratic as SquareRoot>` above.
/// Generic code writes `S::sqrt_of(2)`.)
pub trait SquareRoot: Sized {
    /// The square root when it exists in this number type: exact for the exact types
    /// (`None` when the root is not in the field), approximate for `f64`.
    fn sqrt_exact(&self) -> Option<Self> {
        None
    }

    /// √n in this number type: `None` when the field has no √n (√2 for the exact rationals,
    /// which have only the roots of squares), exact in the quadratic field (reduced: √8 = 2√2),
    /// rounded for `f64`.
    fn sqrt_of(n: u64) -> Option<Self> {
        let _ = n;
        None
    }
}

/// The three printers of a number.
pub trait Print: Display {
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

/// The one bound every algorithm of cagd-exact is generic over: an ordered field
/// ([`FieldOps`]) with its exact-rational hook ([`ExactRational`]), its square roots
/// ([`SquareRoot`]) and its printers ([`Print`]).
///
/// It has no methods of its own and a blanket impl: every type with the four jobs is a
/// `Scalar`, and `S: Scalar` is the one bound algorithms name. Generic code calls the methods
/// of all four traits through that bound; code holding a concrete type (`Quadratic`,
/// `BigRational`, `f64`) imports the trait of the method it calls (`use cagd_scalar::Print`
/// for `to_text`).
pub trait Scalar: FieldOps + ExactRational + SquareRoot + Print {}

impl<T: FieldOps + ExactRational + SquareRoot + Print> Scalar for T {}

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
