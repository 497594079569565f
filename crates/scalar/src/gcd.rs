//! Greatest common divisors, the cost of every exact reduction: Stein's binary gcd on machine
//! words, one remainder step from 128 bits down to a word, and Lehmer's algorithm on big
//! naturals (Knuth, TAOCP vol. 2, 4.5.2), whose multiprecision steps replace many of the
//! divisions (or, in num-integer's binary gcd, the shifts of the whole number) of the others.
//! [`gcd`] picks the one that fits the sizes of its operands.

use num_bigint::{BigInt, BigUint};
use num_traits::{ToPrimitive, Zero};

/// gcd(a, b) ≥ 0 of two big integers, gcd(0, b) = |b|: one remainder and a machine-word gcd
/// when the smaller fits 128 bits (`gcd(x, y) = gcd(y, x mod y)`, linear in the length of x),
/// [`gcd_lehmer`] when both are longer.
///
/// ```
/// use cagd_scalar::{gcd::gcd, BigInt};
/// let g = BigInt::from(3u8).pow(100);
/// assert_eq!(gcd(&(&g * 10u8), &(-&g * 4u8)), &g * 2u8);
/// assert_eq!(gcd(&BigInt::from(0), &BigInt::from(-7)), BigInt::from(7));
/// ```
pub fn gcd(a: &BigInt, b: &BigInt) -> BigInt {
    BigInt::from(gcd_natural(a.magnitude(), b.magnitude()))
}

/// gcd(x, y) of two big naturals, as [`gcd`].
pub fn gcd_natural(x: &BigUint, y: &BigUint) -> BigUint {
    let (x, y) = if x >= y { (x, y) } else { (y, x) };
    if y.is_zero() {
        return x.clone();
    }
    match y.to_u128() {
        Some(w) => {
            // x mod w < w fits 128 bits
            let r = (x % w).to_u128().unwrap_or(0);
            BigUint::from(gcd_u128(w, r))
        }
        None => gcd_lehmer(x, y).into_parts().1,
    }
}

/// gcd(a, b) of two machine words by Stein's binary algorithm; gcd(0, b) = b.
pub fn gcd_u64(a: u64, b: u64) -> u64 {
    if a == 0 {
        return b;
    }
    if b == 0 {
        return a;
    }
    if a == 1 || b == 1 {
        // an integer's denominator: no loop
        return 1;
    }
    let shift = (a | b).trailing_zeros();
    let mut a = a >> a.trailing_zeros();
    let mut b = b;
    loop {
        b >>= b.trailing_zeros();
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        b -= a;
        if b == 0 {
            return a << shift;
        }
    }
}

/// gcd(a, b) of two 128-bit words: one remainder step down to a machine word, then
/// [`gcd_u64`]; gcd(0, b) = b.
pub fn gcd_u128(a: u128, b: u128) -> u128 {
    let (mut a, mut b) = (a, b);
    while a > u128::from(u64::MAX) || b > u128::from(u64::MAX) {
        if b == 0 {
            return a;
        }
        let r = a % b;
        a = b;
        b = r;
    }
    // both fit a word now
    u128::from(gcd_u64(a as u64, b as u64))
}

/// The gcd of two big naturals by Lehmer's algorithm (Knuth, TAOCP vol. 2, 4.5.2, Algorithm
/// L): the Euclidean quotients are found on the leading 64 bits, and one multiprecision step
/// `(u, v) ← (A u + B v, C u + D v)` replaces many divisions.
pub fn gcd_lehmer(u: &BigUint, v: &BigUint) -> BigInt {
    let (mut u, mut v) = if u >= v {
        (u.to_u64_digits(), v.to_u64_digits())
    } else {
        (v.to_u64_digits(), u.to_u64_digits())
    };
    // u ≥ v, little-endian limbs without leading zeros; the multiprecision step is done in
    // place, limb by limb, with no allocation
    let mut t = Vec::with_capacity(u.len());
    let mut w = Vec::with_capacity(u.len());
    while limb_bits(&v) > 64 {
        crate::cancel::checkpoint();
        // the leading 62 bits, so that x + a and y + d stay below 2^63
        let shift = limb_bits(&u) - 62;
        let mut x = leading(&u, shift);
        let mut y = leading(&v, shift);
        let (mut a, mut b, mut c, mut d) = (1i64, 0i64, 0i64, 1i64);
        while y + c != 0 && y + d != 0 {
            let q = (x + a) / (y + c);
            if q != (x + b) / (y + d) {
                break;
            }
            // the cofactors stay below x in size; checked all the same (a step that would
            // overflow is left to the multiprecision step)
            let step = |s: i64, t: i64| q.checked_mul(t).and_then(|qt| s.checked_sub(qt));
            let (Some(c2), Some(d2), Some(y2)) = (step(a, c), step(b, d), step(x, y)) else {
                break;
            };
            (a, c) = (c, c2);
            (b, d) = (d, d2);
            (x, y) = (y, y2);
        }
        let combined = b != 0
            && combine(&u, &v, a, b, &mut t)
            && combine(&u, &v, c, d, &mut w)
            && limbs_at_least(&t, &w);
        if combined {
            std::mem::swap(&mut u, &mut t);
            std::mem::swap(&mut v, &mut w);
        } else {
            // one Euclidean division step
            let (bu, bv) = (from_limbs(&u), from_limbs(&v));
            let r = bu % &bv;
            u = v;
            v = r.to_u64_digits();
        }
    }
    // v fits in 64 bits: one division, then machine integers
    let big_u = from_limbs(&u);
    let small = v.first().copied().unwrap_or(0);
    if small == 0 {
        return BigInt::from(big_u);
    }
    let r = (big_u % small).to_u64().unwrap_or(0);
    BigInt::from(gcd_u64(small, r))
}

/// Little-endian limbs as a big natural.
fn from_limbs(limbs: &[u64]) -> BigUint {
    let digits: Vec<u32> = limbs
        .iter()
        .flat_map(|&l| [l as u32, (l >> 32) as u32])
        .collect();
    BigUint::new(digits)
}

/// `x ≥ y` for naturals given by their limbs (no leading zero limbs).
fn limbs_at_least(x: &[u64], y: &[u64]) -> bool {
    x.len() > y.len() || (x.len() == y.len() && x.iter().rev().ge(y.iter().rev()))
}

/// The number of bits of a natural given by its limbs (no leading zero limbs).
fn limb_bits(limbs: &[u64]) -> u64 {
    match limbs.last() {
        Some(&top) => 64 * (limbs.len() as u64 - 1) + u64::from(64 - top.leading_zeros()),
        None => 0,
    }
}

/// `⌊n / 2^shift⌋` for a natural below 2^(shift + 62), as a machine integer.
fn leading(limbs: &[u64], shift: u64) -> i64 {
    let i = usize::try_from(shift / 64).unwrap_or(usize::MAX);
    let lo = u128::from(limbs.get(i).copied().unwrap_or(0));
    let hi = u128::from(limbs.get(i.saturating_add(1)).copied().unwrap_or(0));
    let x = ((hi << 64) | lo) >> (shift % 64);
    i64::try_from(x & ((1u128 << 62) - 1)).unwrap_or(0)
}

/// `out = a u + b v` limb by limb (|a|, |b| < 2^62, so every partial sum fits an i128);
/// `false` when the result is negative (then `out` is not used).
fn combine(u: &[u64], v: &[u64], a: i64, b: i64, out: &mut Vec<u64>) -> bool {
    const LIMIT: i64 = 1 << 62;
    if !(-LIMIT < a && a < LIMIT && -LIMIT < b && b < LIMIT) {
        return false;
    }
    out.clear();
    let (a, b) = (i128::from(a), i128::from(b));
    let mut carry: i128 = 0;
    for k in 0..u.len().max(v.len()) {
        let uk = i128::from(u.get(k).copied().unwrap_or(0));
        let vk = i128::from(v.get(k).copied().unwrap_or(0));
        let s = a * uk + b * vk + carry;
        out.push(s as u64);
        carry = s >> 64;
    }
    if carry < 0 {
        return false;
    }
    if carry > 0 {
        out.push(carry as u64);
    }
    while out.last() == Some(&0) {
        out.pop();
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_bigint::Sign;
    use proptest::prelude::*;

    /// A big natural from little-endian limbs.
    fn natural(limbs: &[u64]) -> BigUint {
        from_limbs(limbs)
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(300))]

        #[test]
        fn word_gcd_equals_euclid(a in any::<u64>(), b in any::<u64>(), k in 0u32..20) {
            let (a, b) = (a >> k, b >> (k / 2));
            let expected = num_integer::Integer::gcd(&a, &b);
            prop_assert_eq!(gcd_u64(a, b), expected);
            let wide = u128::from(a) << 64 | u128::from(b);
            prop_assert_eq!(gcd_u128(wide, u128::from(b)),
                num_integer::Integer::gcd(&wide, &u128::from(b)));
        }

        /// Lehmer's gcd, done in place on limbs, against Stein's (num-integer), on big numbers
        /// with a big common factor, of any relative sizes.
        #[test]
        fn lehmer_gcd_equals_steins(
            g in proptest::collection::vec(any::<u64>(), 0..6),
            a in proptest::collection::vec(any::<u64>(), 1..12),
            b in proptest::collection::vec(any::<u64>(), 1..12),
        ) {
            let g = natural(&g) + 1u8;
            let (a, b) = (natural(&a) * &g, natural(&b) * &g);
            let expected = BigInt::from(num_integer::Integer::gcd(&a, &b));
            prop_assert_eq!(gcd_lehmer(&a, &b), expected.clone());
            prop_assert_eq!(gcd_lehmer(&b, &a), expected);
        }

        /// [`gcd`] against num-integer's on signed operands of every size, zero included.
        #[test]
        fn gcd_equals_num_integer(
            g in proptest::collection::vec(any::<u64>(), 0..4),
            a in proptest::collection::vec(any::<u64>(), 0..8),
            b in proptest::collection::vec(any::<u64>(), 0..8),
            signs in (any::<bool>(), any::<bool>()),
        ) {
            let g = natural(&g) + 1u8;
            let sign = |neg: bool| if neg { Sign::Minus } else { Sign::Plus };
            let a = BigInt::from_biguint(sign(signs.0), natural(&a) * &g);
            let b = BigInt::from_biguint(sign(signs.1), natural(&b));
            let expected = num_integer::Integer::gcd(&a, &b);
            prop_assert_eq!(gcd(&a, &b), expected.clone());
            prop_assert_eq!(gcd(&b, &a), expected);
        }
    }

    #[test]
    fn gcds_of_known_numbers() {
        assert_eq!(gcd_u128(1 << 100, 3 << 90), 1 << 90);
        assert_eq!(gcd_u128(0, 5), 5);
        let g = BigInt::from(3u8).pow(300) * BigInt::from(7u8).pow(100);
        let a = &g * (BigInt::from(2u8).pow(500) + 1u8);
        let b = &g * (BigInt::from(5u8).pow(200) - 2u8);
        assert_eq!(gcd_lehmer(a.magnitude(), b.magnitude()), g);
        assert_eq!(gcd(&a, &-b), g);
        let x = BigInt::from(10u8).pow(90);
        assert_eq!(
            gcd_lehmer(x.magnitude(), BigInt::from(1u8).magnitude()),
            BigInt::from(1u8)
        );
    }
}
