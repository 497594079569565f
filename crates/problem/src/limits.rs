//! Resource limits of `solve`: hostile or mistyped input is refused quickly, with an error
//! that names the problem, the field and the limit (and the `cagd solve` flag that raises it).
//!
//! Numbers are read with a builder of their own ([`read_number`]) rather than with
//! `cagd_scalar::parse_number`, so that a power or a product never grows past
//! [`Limits::max_digits`]: `(10^1000)^1000` is refused before it is computed.

use cagd_poly::parenthesized_exponents;
use cagd_scalar::{parse_with, BigInt, Builder, NumberBuilder, Quadratic, ScalarError, Span};
use num_traits::{One, Zero};

/// The limits of one run of `solve`.
///
/// ```
/// use cagd_problem::{solve_with, Limits};
/// use serde_json::json;
/// let tight = Limits { max_degree: 2, ..Limits::default() };
/// let p = json!({"op": "elevate", "curve": {"bezier": [[0, 0], [1, 2], [3, 3]]}, "by": 1});
/// let e = solve_with(&p, &tight).unwrap_err();
/// assert_eq!(
///     e.to_string(),
///     "field `by`: elevating degree 2 by 1 gives degree 3, above the limit of 2 (raise it with --max-degree)"
/// );
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Limits {
    /// Highest degree of a curve or surface (in each direction), given or computed (an
    /// elevation, a graph, a least-squares patch), and of an expression; also the highest
    /// derivative order and knot multiplicity asked for.
    pub max_degree: usize,
    /// Most items in one list (control points, knots, weights, parameters, points to fit) and
    /// most points in one mesh (rows × columns), given or computed.
    pub max_points: usize,
    /// Most decimal digits in one number: in each literal, and in the numerator and the
    /// denominator of every value computed while reading it (`2^5000` has 1506).
    pub max_digits: usize,
    /// Most problems in one batch; the problems past it are answered with an error.
    pub max_batch: usize,
    /// Deepest nesting of parentheses and signs in a number or an expression (at most
    /// [`Limits::DEPTH_CEILING`]).
    pub max_depth: usize,
    /// Largest |e| in `x^e`.
    pub max_exponent: u32,
}

impl Limits {
    /// The defaults: generous for teaching, small enough that each problem is answered in
    /// about a second or less.
    pub const DEFAULT: Limits = Limits {
        max_degree: 50,
        max_points: 1000,
        max_digits: 1000,
        max_batch: 10_000,
        max_depth: 200,
        max_exponent: 1000,
    };

    /// The deepest nesting any setting allows: the parser is recursive, and deeper input
    /// would overflow the stack instead of being refused.
    pub const DEPTH_CEILING: usize = 1000;

    /// The grammar's limits for reading numbers and expressions under these limits.
    pub fn grammar(&self) -> cagd_scalar::Limits {
        cagd_scalar::Limits {
            max_exponent: self.max_exponent,
            max_depth: self.max_depth.min(Self::DEPTH_CEILING),
            max_digits: self.max_digits,
            ..cagd_scalar::Limits::default()
        }
    }

    /// The most bits a numerator or denominator may have: at least `max_digits` decimal
    /// digits' worth (the exact digit count is checked by [`Limits::check_digits`]).
    fn max_bits(&self) -> u64 {
        // log2(10) < 3.3220; one more bit for rounding.
        let digits = u64::try_from(self.max_digits).unwrap_or(u64::MAX);
        digits.saturating_mul(33_220) / 10_000 + 1
    }

    /// `Err` naming the digits when a part of `x` has more than `max_digits` digits.
    pub fn check_digits(&self, x: &Quadratic) -> Result<(), String> {
        let parts = [
            x.rational_part().numer(),
            x.rational_part().denom(),
            x.root_part().numer(),
            x.root_part().denom(),
        ];
        for n in parts {
            if let Some(d) = self.too_many_digits(n) {
                return Err(self.digits_message(d));
            }
        }
        Ok(())
    }

    /// The number of digits of `n` when it is more than `max_digits`.
    fn too_many_digits(&self, n: &BigInt) -> Option<usize> {
        // bits - 1 <= log2|n| < bits, so the digits are about bits · log10(2); only a
        // borderline case needs the exact count.
        let bits = n.bits();
        let low = self.max_bits().saturating_sub(8);
        if bits <= low {
            return None;
        }
        let digits = n.magnitude().to_string().len();
        (digits > self.max_digits).then_some(digits)
    }

    fn digits_message(&self, digits: usize) -> String {
        format!(
            "a number of {digits} digits is longer than the limit of {} digits (raise it with --max-digits)",
            self.max_digits
        )
    }
}

impl Default for Limits {
    fn default() -> Self {
        Limits::DEFAULT
    }
}

/// A parser's limit message with the flag that raises the limit, when it does not say so
/// already: "exponent 1001 at column 6 is larger than 1000 (raise it with --max-exponent)".
pub(crate) fn with_flag(message: String) -> String {
    if !message.contains("limit exceeded") || message.contains("(raise") {
        return message;
    }
    let flag = if message.contains("exponent") {
        "--max-exponent"
    } else if message.contains("nested deeper") {
        "--max-depth"
    } else if message.contains("digits") {
        "--max-digits"
    } else {
        return message;
    };
    format!("{message} (raise it with {flag})")
}

/// The limits a plain [`crate::solve`] runs with.
pub(crate) static DEFAULT_LIMITS: Limits = Limits::DEFAULT;

/// Reads an exact number of the grammar (as `cagd_scalar::parse_number`) under `limits`: no
/// literal, intermediate value or result has more than `max_digits` digits, and powers are
/// refused before they are computed when they would.
pub fn read_number(text: &str, limits: &Limits) -> Result<Quadratic, ScalarError> {
    // The grammar evaluates a parenthesized exponent with cagd-scalar's own builder, which
    // bounds no value: read each one here first (innermost first), within 1000 digits.
    let tight = Limits {
        max_digits: limits.max_digits.min(EXPONENT_DIGITS),
        ..*limits
    };
    for (column, exponent) in parenthesized_exponents(text) {
        let mut b = BoundedNumbers { limits: &tight };
        if let Err(ScalarError::Limit { what }) = parse_with(exponent, &mut b, &tight.grammar()) {
            return Err(ScalarError::Limit {
                what: format!("in the exponent at column {column}: {what}"),
            });
        }
    }
    let mut b = BoundedNumbers { limits };
    let x = parse_with(text, &mut b, &limits.grammar())?;
    b.checked(x)
}

/// The most digits a value may reach while a parenthesized exponent is read, whatever
/// [`Limits::max_digits`] is: an exponent is an integer of a few digits in the end.
const EXPONENT_DIGITS: usize = 1000;

/// The number builder of the grammar with a bound on the size of every value.
struct BoundedNumbers<'l> {
    limits: &'l Limits,
}

/// The largest bit length of the parts of `x`.
fn bits(x: &Quadratic) -> u64 {
    [
        x.rational_part().numer(),
        x.rational_part().denom(),
        x.root_part().numer(),
        x.root_part().denom(),
    ]
    .iter()
    .map(|n| n.bits())
    .max()
    .unwrap_or(0)
}

impl BoundedNumbers<'_> {
    fn limit(&self, digits: Option<usize>) -> ScalarError {
        ScalarError::Limit {
            what: match digits {
                Some(d) => self.limits.digits_message(d),
                None => format!(
                    "a number of more than {} digits (raise the limit with --max-digits)",
                    self.limits.max_digits
                ),
            },
        }
    }

    fn checked(&self, x: Quadratic) -> Result<Quadratic, ScalarError> {
        if bits(&x) > self.limits.max_bits() {
            return Err(self.limit(None));
        }
        self.limits
            .check_digits(&x)
            .map_err(|what| ScalarError::Limit { what })?;
        Ok(x)
    }

    /// Cheap check for intermediate values: bit length only.
    fn small(&self, x: Quadratic) -> Result<Quadratic, ScalarError> {
        if bits(&x) > self.limits.max_bits() {
            return Err(self.limit(None));
        }
        Ok(x)
    }
}

impl Builder for BoundedNumbers<'_> {
    type Value = Quadratic;

    fn number(&mut self, x: Quadratic, span: Span) -> Result<Quadratic, ScalarError> {
        NumberBuilder.number(x, span).and_then(|x| self.small(x))
    }
    fn name(&mut self, name: &str, span: Span) -> Result<Quadratic, ScalarError> {
        NumberBuilder.name(name, span)
    }
    fn sqrt(&mut self, x: Quadratic, span: Span) -> Result<Quadratic, ScalarError> {
        NumberBuilder.sqrt(x, span).and_then(|x| self.small(x))
    }
    fn add(&mut self, a: Quadratic, b: Quadratic, span: Span) -> Result<Quadratic, ScalarError> {
        NumberBuilder.add(a, b, span).and_then(|x| self.small(x))
    }
    fn sub(&mut self, a: Quadratic, b: Quadratic, span: Span) -> Result<Quadratic, ScalarError> {
        NumberBuilder.sub(a, b, span).and_then(|x| self.small(x))
    }
    fn mul(&mut self, a: Quadratic, b: Quadratic, span: Span) -> Result<Quadratic, ScalarError> {
        NumberBuilder.mul(a, b, span).and_then(|x| self.small(x))
    }
    fn div(&mut self, a: Quadratic, b: Quadratic, span: Span) -> Result<Quadratic, ScalarError> {
        NumberBuilder.div(a, b, span).and_then(|x| self.small(x))
    }
    fn neg(&mut self, a: Quadratic, span: Span) -> Result<Quadratic, ScalarError> {
        NumberBuilder.neg(a, span)
    }
    /// `a^e` by repeated squaring, refused before it starts when the result would be longer
    /// than the limit: |parts of a^e| ≤ (|a| + |b|√d)^e has at most e · (bits + bits(d)/2 + 1)
    /// bits.
    fn pow(&mut self, a: Quadratic, e: i64, span: Span) -> Result<Quadratic, ScalarError> {
        let base = if e < 0 {
            a.checked_inv().map_err(|_| ScalarError::DivisionByZero {
                column: Some(span.column),
            })?
        } else {
            a
        };
        let n = e.unsigned_abs();
        let root_bits = if base.root_part().is_zero() {
            0
        } else {
            64 - base.radicand().leading_zeros() as u64 + 2
        };
        let base_bits = bits(&base).saturating_sub(1) + root_bits;
        if base_bits.saturating_mul(n) > self.limits.max_bits() {
            return Err(ScalarError::Limit {
                what: format!(
                    "the power at column {} would have more than {} digits (raise the limit with --max-digits)",
                    span.column, self.limits.max_digits
                ),
            });
        }
        let mut acc = Quadratic::one();
        let mut square = base;
        let mut k = n;
        while k > 0 {
            if k & 1 == 1 {
                acc = acc.checked_mul(&square)?;
            }
            k >>= 1;
            if k > 0 {
                square = square.checked_mul(&square)?;
            }
        }
        self.small(acc)
    }
    fn tuple(&mut self, items: Vec<Quadratic>, span: Span) -> Result<Quadratic, ScalarError> {
        NumberBuilder.tuple(items, span)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::Scalar;

    #[test]
    fn numbers_within_the_limits_read_as_the_grammar_reads_them() {
        let l = Limits::default();
        for text in [
            "5/6",
            "-3",
            "0.125",
            "sqrt2/2",
            "1/2 + 3/4*sqrt(2)",
            "(sqrt2/2)^2",
            "2^-1",
        ] {
            assert_eq!(
                read_number(text, &l),
                cagd_scalar::parse_number(text),
                "{text}"
            );
        }
        // 1/2^1000: "1/" and the 302 digits of 2^1000
        assert_eq!(read_number("(1/2)^1000", &l).unwrap().to_text().len(), 304);
        assert_eq!(
            read_number("(1 + sqrt2)^3", &l).unwrap().to_text(),
            "7 + 5√2"
        );
    }

    #[test]
    fn huge_powers_are_refused_before_they_are_computed() {
        let l = Limits::default();
        let start = std::time::Instant::now();
        for text in [
            "((10^1000)^1000)^1000",
            "(10^500)^3",
            "2^1000 * 2^1000 * 2^1000 * 2^1000",
        ] {
            let e = read_number(text, &l).unwrap_err().to_string();
            assert!(e.contains("more than 1000 digits"), "{text}: {e}");
        }
        assert!(start.elapsed().as_secs() < 2);
        assert_eq!(
            read_number("(1/3)^(10^9)", &l).unwrap_err().to_string(),
            "limit exceeded: exponent 1000000000 at column 6 is larger than 1000"
        );
    }

    #[test]
    fn digits_are_counted_exactly_at_the_border() {
        let l = Limits {
            max_digits: 10,
            ..Limits::default()
        };
        assert!(read_number("9999999999", &l).is_ok());
        assert_eq!(
            read_number("10^10", &l).unwrap_err().to_string(),
            "limit exceeded: a number of 11 digits is longer than the limit of 10 digits (raise it with --max-digits)"
        );
        assert_eq!(
            read_number("1/99999999999", &l).unwrap_err().to_string(),
            "limit exceeded: number at column 3 has more than 10 digits"
        );
    }
}
