//! Resource limits of `solve`: hostile or mistyped input is refused quickly, with an error
//! that names the problem, the field and the limit. The error carries the [`Limit`] it is
//! about ([`crate::ProblemError::limit`]); a front end says how to raise it (the `cagd`
//! command names its flag).
//!
//! Numbers are read by cagd-scalar's grammar under [`Limits::grammar`], so that a power or a
//! product never grows past [`Limits::max_digits`]: `(10^1000)^1000` is refused before it is
//! computed.

pub use crate::limit::Limit;
use crate::message::read::Read;
use cagd_scalar::{parse_number_with, Exceeded, Quadratic, ScalarError};
use std::time::Duration;

/// The limits of one run of `solve`.
///
/// ```
/// use cagd_contract::{Limit, Limits, Problem};
/// use serde_json::json;
/// let tight = Limits { max_degree: 2, ..Limits::default() };
/// let p = json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 2], [3, 3], [4, 0]]}, "params": [0]});
/// let e = Problem::read(&p, &tight).unwrap_err();
/// assert_eq!(e.limit, Some(Limit::Degree));
/// assert_eq!(
///     e.to_string(),
///     "field `curve.bezier`: 4 control points make a Bézier curve of degree 3, above the limit of 2 for degrees"
/// );
/// ```
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
    /// The time one problem may take to solve (`None`: no deadline). Past it, the work stops
    /// at its next checkpoint (`cagd_scalar::cancel`) and the problem's answer is an error; the
    /// other problems of a batch are answered. Every size the work depends on is checked
    /// before the work against the other limits; this deadline is for what slips past them.
    pub max_seconds: Option<Duration>,
    /// The memory one problem may hold while it is solved and its key written, in megabytes
    /// (10^6 bytes). What an operation is about to build, where its size is known before the
    /// work (the normal equations of a least-squares fit), is estimated and refused at once
    /// when it does not fit; the rest is measured at the checkpoints of the work
    /// (`cagd_scalar::cancel`), as the bytes the problem's thread holds, when the program
    /// counts its allocations (the `cagd` command does; a library's user without such an
    /// allocator gets the estimates only).
    pub max_memory: usize,
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
        max_seconds: Some(Duration::from_secs(5)),
        max_memory: 1000,
    };

    /// The deepest nesting any setting allows: the parser is recursive, and deeper input
    /// would overflow the stack instead of being refused.
    pub const DEPTH_CEILING: usize = 1000;

    /// [`Limits::max_memory`] in bytes.
    pub fn memory_bytes(&self) -> u64 {
        u64::try_from(self.max_memory)
            .unwrap_or(u64::MAX)
            .saturating_mul(1_000_000)
    }

    /// The grammar's limits for reading numbers and expressions under these limits.
    pub fn grammar(&self) -> cagd_scalar::Limits {
        cagd_scalar::Limits {
            max_exponent: self.max_exponent,
            max_depth: self.max_depth.min(Self::DEPTH_CEILING),
            max_digits: self.max_digits,
            ..cagd_scalar::Limits::default()
        }
    }

    /// `Err` naming the digits when a part of `x` has more than `max_digits` digits (the
    /// grammar's count, [`cagd_scalar::Limits::check_digits`], said typed).
    pub fn check_digits(&self, x: &Quadratic) -> Result<(), Read> {
        self.grammar().check_digits(x).map_err(|e| match e {
            ScalarError::Limit {
                what: what @ Exceeded::DigitsCounted { .. },
            } => Read::Digits { what },
            _ => Read::Digits {
                what: Exceeded::Digits {
                    max: self.max_digits,
                },
            },
        })
    }
}

impl Default for Limits {
    fn default() -> Self {
        Limits::DEFAULT
    }
}

/// Reads an exact number of the grammar (as `cagd_scalar::parse_number`) under `limits`: no
/// literal, intermediate value or result has more than `max_digits` digits, and powers are
/// refused before they are computed when they would; a limit's error names the flag that
/// raises it ([`crate::Message::limit`]).
pub fn read_number(text: &str, limits: &Limits) -> Result<Quadratic, ScalarError> {
    parse_number_with(text, &limits.grammar())
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::Print;

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
        for text in [
            "((10^1000)^1000)^1000",
            "(10^500)^3",
            "2^1000 * 2^1000 * 2^1000 * 2^1000",
        ] {
            let e = read_number(text, &l).unwrap_err().to_string();
            assert!(e.contains("more than 1000 digits"), "{text}: {e}");
        }
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
            "limit exceeded: a number of 11 digits is longer than the limit of 10 digits"
        );
        assert_eq!(
            read_number("1/99999999999", &l).unwrap_err().to_string(),
            "limit exceeded: number at column 3 has more than 10 digits"
        );
    }

    /// Found by fuzzing: towers of powers, also inside an exponent, are refused with the
    /// column of the power and the flag.
    #[test]
    fn towers_are_refused_with_the_flag_that_raises_the_limit() {
        let l = Limits::default();
        assert_eq!(
            read_number("((10^3)^1000)^1000", &l)
                .unwrap_err()
                .to_string(),
            "limit exceeded: the power at column 8 would have more than 1000 digits"
        );
        assert_eq!(
            read_number("2^(((10^3)^1000)^1000)", &l)
                .unwrap_err()
                .to_string(),
            "limit exceeded: the power at column 11 would have more than 1000 digits"
        );
        assert_eq!(read_number("2^(2*5) - 2^(3^2)", &l), read_number("512", &l));
    }
}
