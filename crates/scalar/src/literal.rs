//! The literal fast path of the number grammar: a one-pass reader for the numbers that need
//! no grammar (`-3`, `5/6`, `0.125`, `-.5`), and the exact, cheap reduction of a decimal or
//! a fraction that the grammar's tokenizer shares with it.
//!
//! [`parse_literal`] answers only for a literal it reads within the limits; anything else
//! (`sqrt2/2`, spaces, a literal past a limit, `1/0`) is left to the grammar, which gives the
//! same value for what both read and the one set of error messages.

use crate::{Limits, Quadratic, Rat};
use num_bigint::{BigInt, BigUint, Sign};
use num_rational::BigRational;
use num_traits::Zero;

/// The digits of an ASCII decimal run as a natural number (the run may be empty: 0).
///
/// `digits` must hold ASCII digits only.
pub(crate) fn natural(digits: &str) -> BigUint {
    if digits.is_empty() {
        return BigUint::zero();
    }
    // at most 19 digits fit a u64: no big-integer work
    if digits.len() <= 19 {
        if let Ok(n) = digits.parse::<u64>() {
            return BigUint::from(n);
        }
    }
    BigUint::parse_bytes(digits.as_bytes(), 10).unwrap_or_default()
}

/// `n / d` in lowest terms, `d > 0`, reduced cheaply when either side is a machine word.
///
/// num-integer's binary gcd shifts the whole of the larger operand about once per bit of it,
/// so reducing a long numerator by a short denominator (`10^999000 / 7`, or any integer
/// over 1) costs its length squared; [`crate::gcd::gcd_natural`] takes one linear remainder
/// by the short side, and Lehmer's steps when both are long.
pub(crate) fn ratio(sign: Sign, n: BigUint, d: BigUint) -> BigRational {
    let g = if d.is_zero() {
        BigUint::from(1u32)
    } else {
        crate::gcd::gcd_natural(&n, &d)
    };
    let (n, d) = if g == BigUint::from(1u32) {
        (n, d)
    } else {
        (n / &g, d / &g)
    };
    let sign = if n.is_zero() { Sign::NoSign } else { sign };
    BigRational::new_raw(BigInt::from_biguint(sign, n), BigInt::from(d))
}

/// The exact value of a decimal literal `int.frac` (`0.125` is 1/8); both runs ASCII digits.
pub(crate) fn decimal(int_part: &str, frac_part: &str) -> BigRational {
    // trailing zeros of the fraction change nothing: 1.50 = 1.5
    let frac_part = frac_part.trim_end_matches('0');
    if frac_part.is_empty() {
        return ratio(Sign::Plus, natural(int_part), BigUint::from(1u32));
    }
    let mut digits = String::with_capacity(int_part.len() + frac_part.len());
    digits.push_str(int_part);
    digits.push_str(frac_part);
    let den = num_traits::pow(BigUint::from(10u32), frac_part.len());
    ratio(Sign::Plus, natural(&digits), den)
}

/// The most digits of a numerator or denominator that [`word_literal`] reads: 10^18 < 2^63.
const WORD_DIGITS: usize = 18;

/// The value of a run of ASCII digits at the start of `bytes` when it has 1 to `most`
/// digits (`most` ≤ 18, so the value fits a `u64`), with the bytes after it; `None` for an
/// empty or longer run.
fn digit_run(bytes: &[u8], most: usize) -> Option<(u64, &[u8])> {
    let mut n = 0u64;
    let mut len = 0usize;
    for &b in bytes {
        let d = b.wrapping_sub(b'0');
        if d > 9 {
            break;
        }
        if len == most {
            return None;
        }
        n = n * 10 + u64::from(d);
        len += 1;
    }
    (len > 0).then(|| (n, bytes.get(len..).unwrap_or_default()))
}

/// The fast path of the number grammar: `text` when it is `±p` or `±p/q` (`-9`, `3/4`,
/// `0/9`), p and q runs of at most 18 digits and of at most `max_digits` digits, q ≠ 0,
/// reduced in machine words (Stein's gcd on `u64`): one pass over the bytes, no tokens, no
/// big integers. `None` for anything else (`1/0`, `0.25`, `sqrt2/2`, a longer run), which
/// [`parse_literal`] or the grammar reads to the same value or refuses with its message.
/// Such a value is within every limit: reduced, its parts have no more digits (and so no
/// more bits) than written, and the text is at most 38 characters long.
///
/// ```
/// use cagd_scalar::{word_literal, Print};
/// assert_eq!(word_literal("-10/4", 1000).unwrap().to_text(), "-5/2");
/// assert_eq!(word_literal("0/9", 1000).unwrap().to_text(), "0");
/// assert!(word_literal("1/0", 1000).is_none()); // the grammar's error
/// assert!(word_literal("123", 2).is_none()); // past the digit limit: the grammar's error
/// ```
pub fn word_literal(text: &str, max_digits: usize) -> Option<Rat> {
    let most = WORD_DIGITS.min(max_digits);
    let (minus, body) = match text.as_bytes() {
        [b'-', rest @ ..] => (true, rest),
        all => (false, all),
    };
    let (p, rest) = digit_run(body, most)?;
    let q = match rest {
        [] => 1,
        [b'/', den @ ..] => match digit_run(den, most)? {
            (q, []) if q != 0 => q,
            _ => return None,
        },
        _ => return None,
    };
    // an integer (q = 1) and zero (0/q = 0/1) are reduced already: no gcd, no division
    let (p, q) = match (p, q) {
        (_, 1) => (p, 1),
        (0, _) => (0, 1),
        _ => match crate::gcd::gcd_u64(p, q) {
            1 => (p, q),
            g => (p / g, q / g),
        },
    };
    // p < 10^18 < i64::MAX, and so is q
    let n = i64::try_from(p).ok()?;
    let q = i64::try_from(q).ok()?;
    Some(Rat::from_reduced_words(if minus { -n } else { n }, q))
}

/// Reads `text` when it is a plain literal — `-?D+`, `-?D+/D+`, `-?D*.D*` (with a digit) —
/// whose value is within `limits`, with the value the grammar gives it; `None` for anything
/// else, which the grammar reads (or refuses, with its message).
///
/// ```
/// use cagd_scalar::{parse_literal, Limits, Print};
/// let l = Limits::default();
/// assert_eq!(parse_literal("-10/4", &l).unwrap().to_text(), "-5/2");
/// assert_eq!(parse_literal("0.125", &l).unwrap().to_text(), "1/8");
/// assert!(parse_literal("sqrt2/2", &l).is_none()); // the grammar's
/// assert!(parse_literal("1/0", &l).is_none()); // the grammar's error
/// ```
pub fn parse_literal(text: &str, limits: &Limits) -> Option<Quadratic> {
    // ASCII only below, so bytes are characters
    if text.len() > limits.max_length {
        return None;
    }
    if let Some(x) = word_literal(text, limits.max_digits) {
        return Some(Quadratic::from_rat(x));
    }
    let (sign, body) = match text.strip_prefix('-') {
        Some(rest) => (Sign::Minus, rest),
        None => (Sign::Plus, text),
    };
    let digits = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
    let fits = |count: usize| count <= limits.max_digits;
    let x = if let Some((int_part, frac_part)) = body.split_once('.') {
        let ok = digits(int_part)
            && digits(frac_part)
            && !(int_part.is_empty() && frac_part.is_empty())
            && fits(int_part.len() + frac_part.len());
        if !ok {
            return None;
        }
        let q = decimal(int_part, frac_part);
        if sign == Sign::Minus {
            -q
        } else {
            q
        }
    } else if let Some((p, q)) = body.split_once('/') {
        let ok = !p.is_empty()
            && !q.is_empty()
            && digits(p)
            && digits(q)
            && fits(p.len())
            && fits(q.len());
        if !ok {
            return None;
        }
        let d = natural(q);
        if d.is_zero() {
            return None;
        }
        ratio(sign, natural(p), d)
    } else {
        if body.is_empty() || !digits(body) || !fits(body.len()) {
            return None;
        }
        ratio(sign, natural(body), BigUint::from(1u32))
    };
    let x = Quadratic::from_rational(x);
    // the grammar's checks of a value read: its bits, then its exact digits
    if crate::grammar::too_many_bits(&x, limits) || limits.check_digits(&x).is_err() {
        return None;
    }
    Some(x)
}
