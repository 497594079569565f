//! The decimal printing of exact numbers, fast for the common case: a numerator and a
//! denominator that fit a machine word are written from a 20-byte buffer, with no big-integer
//! division and no formatting machinery; longer ones by num-bigint's printer, which divides by
//! 10^19 a machine word at a time.

use num_bigint::{BigInt, Sign};
use num_rational::BigRational;
use num_traits::{One, ToPrimitive};

/// Appends the decimal digits of `n` to `out` (itoa: two digits a division, no formatting
/// machinery, no check of the bytes as UTF-8).
fn push_u64(out: &mut String, n: u64) {
    out.push_str(itoa::Buffer::new().format(n));
}

/// Appends the machine integer `n` in decimal (with its sign) to `out`.
pub(crate) fn push_i64(out: &mut String, n: i64) {
    if n < 0 {
        out.push('-');
    }
    push_u64(out, n.unsigned_abs());
}

/// Appends `n` in decimal (with its sign) to `out`, as `n.to_string()` writes it.
pub fn push_integer(out: &mut String, n: &BigInt) {
    if let Some(m) = n.magnitude().to_u64() {
        if n.sign() == Sign::Minus {
            out.push('-');
        }
        push_u64(out, m);
    } else {
        out.push_str(&n.to_str_radix(10));
    }
}

/// Appends `q` to `out` as its `Display` writes it: `-5/6`, `3`.
pub fn push_rational(out: &mut String, q: &BigRational) {
    push_integer(out, q.numer());
    if !q.denom().is_one() {
        out.push('/');
        push_integer(out, q.denom());
    }
}

/// Appends `|q|` to `out` as its `Display` writes it: `5/6`, `3`.
pub fn push_abs_rational(out: &mut String, q: &BigRational) {
    push_natural(out, q.numer().magnitude());
    if !q.denom().is_one() {
        out.push('/');
        push_natural(out, q.denom().magnitude());
    }
}

/// Appends the natural number `n` in decimal to `out`.
fn push_natural(out: &mut String, n: &num_bigint::BigUint) {
    match n.to_u64() {
        Some(m) => push_u64(out, m),
        None => out.push_str(&n.to_str_radix(10)),
    }
}

/// `q` as its `Display` writes it, fast.
pub fn rational_text(q: &BigRational) -> String {
    // room for a numerator and a denominator of a machine word each
    let mut out = String::with_capacity(42);
    push_rational(&mut out, q);
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        /// The same digits as num-bigint's printer, at every length around a machine word.
        #[test]
        fn integers_print_as_num_bigint_prints_them(
            words in proptest::collection::vec(any::<u32>(), 0..6),
            negative in any::<bool>(),
        ) {
            let sign = if negative { Sign::Minus } else { Sign::Plus };
            let n = BigInt::from_slice(sign, &words);
            let mut out = String::new();
            push_integer(&mut out, &n);
            prop_assert_eq!(out, n.to_string());
        }

        #[test]
        fn rationals_print_as_their_display(n in any::<i64>(), d in 1i64..i64::MAX, big in any::<u64>()) {
            let q = BigRational::new(BigInt::from(n), BigInt::from(d));
            prop_assert_eq!(rational_text(&q), q.to_string());
            let q = BigRational::new(BigInt::from(n) * BigInt::from(big) * BigInt::from(big), BigInt::from(d));
            prop_assert_eq!(rational_text(&q), q.to_string());
            // the printers built on it
            let x = crate::Quadratic::from_rational(q.clone());
            prop_assert_eq!(x.to_string(), q.to_string());
            prop_assert_eq!(crate::Print::to_text(&q), q.to_string());
        }
    }

    #[test]
    fn the_ends_of_a_machine_word() {
        for n in [0u64, 1, 9, 10, 99, 100, u64::MAX - 1, u64::MAX] {
            let mut out = String::new();
            push_integer(&mut out, &BigInt::from(n));
            assert_eq!(out, n.to_string());
            let mut out = String::new();
            push_integer(&mut out, &-BigInt::from(n));
            assert_eq!(out, (-BigInt::from(n)).to_string());
        }
    }
}
