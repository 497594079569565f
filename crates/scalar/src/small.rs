//! [`Rat`], the fast exact rational: a numerator and a denominator kept inline as machine
//! words while they fit, a [`BigRational`] when they do not.
//!
//! Every value is normalised: `p/q` with `q > 0` and `gcd(p, q) = 1`, stored inline when
//! `|p| ≤ i64::MAX` and `q ≤ i64::MAX`, and as a big rational only otherwise, so one value has
//! one representation and equality compares representations. The arithmetic of two inline
//! values runs in 128-bit integers and reduces with a binary gcd on machine words
//! (Knuth, TAOCP vol. 2, 4.5.1: the gcd of the denominators first, so the products stay
//! small); a result too long for a word falls back to [`BigRational`], and the big path
//! reduces as `num_rational` does. `BigRational` stays the reference: [`Rat::to_big`] and
//! [`Rat::from_big`] convert exactly, and the property tests compare every operation with it.
//!
//! ```
//! use cagd_scalar::{FieldOps, Print, Rat};
//! let x = Rat::from_ratio(1, 2) + Rat::from_ratio(5, 6);
//! assert_eq!(x.to_text(), "4/3");
//! let big = Rat::from_i64(i64::MAX) * Rat::from_i64(4); // spills to a big integer
//! assert_eq!(big.to_text(), "36893488147419103228");
//! assert_eq!((big / Rat::from_i64(4)).to_text(), i64::MAX.to_string());
//! ```

use crate::gcd::{gcd, gcd_u128, gcd_u64};
use crate::{latex_fraction, ExactRational, FieldOps, Print, Quadratic, ScalarError, SquareRoot};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};
use std::borrow::Cow;
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// An exact rational number, inline while numerator and denominator fit a machine word.
///
/// Invariants: `Small { num, den }` has `den ≥ 1`, `gcd(|num|, den) = 1` and
/// `num ≠ i64::MIN` (so `-num` fits); `Big` holds only values that do not fit `Small`.
#[derive(Clone)]
pub struct Rat(Repr);

#[derive(Clone)]
enum Repr {
    Small { num: i64, den: i64 },
    Big(Box<BigRational>),
}

impl Rat {
    /// The normalised value of `num/den` from 128-bit words, `den > 0` and already reduced;
    /// inline when both fit.
    fn from_reduced(num: i128, den: i128) -> Self {
        match (i64::try_from(num), i64::try_from(den)) {
            (Ok(n), Ok(d)) if n != i64::MIN => Rat(Repr::Small { num: n, den: d }),
            _ => Rat(Repr::Big(Box::new(BigRational::new_raw(
                BigInt::from(num),
                BigInt::from(den),
            )))),
        }
    }

    /// `num/den` from 128-bit words with `den > 0`, reduced.
    fn reduce(num: i128, den: i128) -> Self {
        if den == 1 {
            return Self::from_reduced(num, 1);
        }
        if let (Ok(n), Ok(d)) = (i64::try_from(num), i64::try_from(den)) {
            // machine words (den > 0): a word gcd and word divisions, no 128-bit division
            return Self::from_ratio(n, d);
        }
        let g = gcd_u128(num.unsigned_abs(), den.unsigned_abs());
        if g <= 1 {
            return Self::from_reduced(num, den);
        }
        // g divides both and is at most den ≤ i128::MAX
        let g = g as i128;
        Self::from_reduced(num / g, den / g)
    }

    /// The exact value of a big rational (normalised by `num_rational`), inline when it fits.
    pub fn from_big(q: BigRational) -> Self {
        match (q.numer().to_i64(), q.denom().to_i64()) {
            (Some(n), Some(d)) if n != i64::MIN => Rat(Repr::Small { num: n, den: d }),
            _ => Rat(Repr::Big(Box::new(q))),
        }
    }

    /// The value as a big rational.
    pub fn to_big(&self) -> BigRational {
        match &self.0 {
            Repr::Small { num, den } => {
                BigRational::new_raw(BigInt::from(*num), BigInt::from(*den))
            }
            Repr::Big(q) => (**q).clone(),
        }
    }

    /// The value as a big rational, without a clone when it is one.
    fn into_big(self) -> BigRational {
        match self.0 {
            Repr::Small { num, den } => BigRational::new_raw(BigInt::from(num), BigInt::from(den)),
            Repr::Big(q) => *q,
        }
    }

    /// Numerator and denominator when the value is inline.
    pub fn as_small(&self) -> Option<(i64, i64)> {
        match self.0 {
            Repr::Small { num, den } => Some((num, den)),
            Repr::Big(_) => None,
        }
    }

    /// The numerator p of p/q (negative for a negative value), as a big integer.
    pub fn numer(&self) -> Cow<'_, BigInt> {
        match &self.0 {
            Repr::Small { num, .. } => Cow::Owned(BigInt::from(*num)),
            Repr::Big(q) => Cow::Borrowed(q.numer()),
        }
    }

    /// The denominator q ≥ 1 of p/q, as a big integer.
    pub fn denom(&self) -> Cow<'_, BigInt> {
        match &self.0 {
            Repr::Small { den, .. } => Cow::Owned(BigInt::from(*den)),
            Repr::Big(q) => Cow::Borrowed(q.denom()),
        }
    }

    /// The bits of the longer of |p| and q (0 for zero), without building a big integer.
    pub fn bits(&self) -> u64 {
        match &self.0 {
            Repr::Small { num, den } => {
                let longer = num.unsigned_abs().max(den.unsigned_abs());
                u64::from(u64::BITS - longer.leading_zeros())
            }
            Repr::Big(q) => q.numer().bits().max(q.denom().bits()),
        }
    }

    /// `num/den` for machine words already reduced (`den ≥ 1`, `gcd(|num|, den) = 1`).
    pub(crate) fn from_reduced_words(num: i64, den: i64) -> Self {
        if num == i64::MIN {
            // its magnitude fits no i64: kept big, as `from_reduced` keeps it
            return Self::from_reduced(i128::from(num), i128::from(den));
        }
        Rat(Repr::Small { num, den })
    }

    /// Whether the value is negative.
    pub fn is_negative(&self) -> bool {
        match &self.0 {
            Repr::Small { num, .. } => *num < 0,
            Repr::Big(q) => q.is_negative(),
        }
    }

    // a/b + c/d with g = gcd(b, d): (a (d/g) + c (b/g)) / (b/g · d), reduced by gcd(t, g), on
    // big integers (Knuth 4.5.1): two gcds, the second of short numbers, where num-rational
    // takes the lcm of b and d and then the gcd of the whole result.
    fn add_big(a: &BigInt, b: &BigInt, c: &BigInt, d: &BigInt) -> BigRational {
        let g = gcd(b, d);
        if g.is_one() {
            // gcd(a d + c b, b d) = 1 when gcd(b, d) = 1 and both fractions are reduced
            return BigRational::new_raw(a * d + c * b, b * d);
        }
        let (bg, dg) = (b / &g, d / &g);
        let t = a * &dg + c * &bg;
        if t.is_zero() {
            return BigRational::zero();
        }
        let g2 = gcd(&t, &g);
        if g2.is_one() {
            return BigRational::new_raw(t, bg * d);
        }
        BigRational::new_raw(t / &g2, bg * (d / &g2))
    }

    // (a/b)(c/d) = (a/g1)(c/g2) / ((b/g2)(d/g1)) with g1 = gcd(a, d), g2 = gcd(c, b): reduced,
    // on big integers (num-rational reduces the product once more).
    fn mul_big(a: &BigInt, b: &BigInt, c: &BigInt, d: &BigInt) -> BigRational {
        if a.is_zero() || c.is_zero() {
            return BigRational::zero();
        }
        let (g1, g2) = (gcd(a, d), gcd(c, b));
        let part = |x: &BigInt, g: &BigInt| if g.is_one() { x.clone() } else { x / g };
        BigRational::new_raw(part(a, &g1) * part(c, &g2), part(b, &g2) * part(d, &g1))
    }

    /// A big-rational operation on the two values, normalised back.
    fn big_op(&self, rhs: &Self, op: impl Fn(&BigRational, &BigRational) -> BigRational) -> Self {
        let a: Cow<'_, BigRational> = match &self.0 {
            Repr::Big(q) => Cow::Borrowed(&**q),
            Repr::Small { .. } => Cow::Owned(self.to_big()),
        };
        let b: Cow<'_, BigRational> = match &rhs.0 {
            Repr::Big(q) => Cow::Borrowed(&**q),
            Repr::Small { .. } => Cow::Owned(rhs.to_big()),
        };
        Self::from_big(op(&a, &b))
    }

    // a/b + c/d with g = gcd(b, d): (a (d/g) + c (b/g)) / (b/g · d), reduced by gcd(t, g)
    // (Knuth 4.5.1): the products fit 128 bits.
    fn add_small(a: i64, b: i64, c: i64, d: i64) -> Self {
        if b == d {
            return Self::reduce(i128::from(a) + i128::from(c), i128::from(b));
        }
        let g = gcd_u64(b.unsigned_abs(), d.unsigned_abs()) as i64;
        if g == 1 {
            // gcd(ad + cb, bd) = 1 when gcd(b, d) = 1 and both fractions are reduced
            let num = i128::from(a) * i128::from(d) + i128::from(c) * i128::from(b);
            return Self::from_reduced(num, i128::from(b) * i128::from(d));
        }
        let (bg, dg) = (b / g, d / g);
        let t = i128::from(a) * i128::from(dg) + i128::from(c) * i128::from(bg);
        let g2 = gcd_u128(t.unsigned_abs(), g.unsigned_abs().into()) as i128;
        if g2 == 1 {
            return Self::from_reduced(t, i128::from(bg) * i128::from(d));
        }
        Self::from_reduced(t / g2, i128::from(bg) * (i128::from(d) / g2))
    }

    // (a/b)(c/d) = (a/g1)(c/g2) / ((b/g2)(d/g1)) with g1 = gcd(a, d), g2 = gcd(c, b): reduced.
    fn mul_small(a: i64, b: i64, c: i64, d: i64) -> Self {
        if a == 0 || c == 0 {
            return Self::zero();
        }
        // x / g, skipping the division by 1 (an integer factor)
        let quot = |x: i64, g: u64| if g == 1 { x } else { x / g as i64 };
        let g1 = gcd_u64(a.unsigned_abs(), d.unsigned_abs());
        let g2 = gcd_u64(c.unsigned_abs(), b.unsigned_abs());
        let (a, b, c, d) = (quot(a, g1), quot(b, g2), quot(c, g2), quot(d, g1));
        // in one word when both products fit it, else in 128 bits
        match (a.checked_mul(c), b.checked_mul(d)) {
            (Some(num), Some(den)) if num != i64::MIN => Rat(Repr::Small { num, den }),
            _ => Self::from_reduced(i128::from(a) * i128::from(c), i128::from(b) * i128::from(d)),
        }
    }

    /// `self + rhs`.
    fn add_impl(&self, rhs: &Self) -> Self {
        match (&self.0, &rhs.0) {
            (Repr::Small { num: a, den: b }, Repr::Small { num: c, den: d }) => {
                Self::add_small(*a, *b, *c, *d)
            }
            _ => self.big_op(rhs, |x, y| {
                Self::add_big(x.numer(), x.denom(), y.numer(), y.denom())
            }),
        }
    }

    /// `self - rhs`.
    fn sub_impl(&self, rhs: &Self) -> Self {
        match (&self.0, &rhs.0) {
            // -c fits: c ≠ i64::MIN
            (Repr::Small { num: a, den: b }, Repr::Small { num: c, den: d }) => {
                Self::add_small(*a, *b, -*c, *d)
            }
            _ => self.big_op(rhs, |x, y| {
                Self::add_big(x.numer(), x.denom(), &-y.numer(), y.denom())
            }),
        }
    }

    /// `self * rhs`.
    fn mul_impl(&self, rhs: &Self) -> Self {
        match (&self.0, &rhs.0) {
            (Repr::Small { num: a, den: b }, Repr::Small { num: c, den: d }) => {
                Self::mul_small(*a, *b, *c, *d)
            }
            _ => self.big_op(rhs, |x, y| {
                Self::mul_big(x.numer(), x.denom(), y.numer(), y.denom())
            }),
        }
    }

    /// `1 / self`, `None` for zero.
    pub fn checked_recip(&self) -> Option<Self> {
        match &self.0 {
            Repr::Small { num: 0, .. } => None,
            // the sign moves to the numerator; den ≤ i64::MAX so -den fits
            Repr::Small { num, den } => Some(Rat(Repr::Small {
                num: if *num < 0 { -*den } else { *den },
                den: num.abs(),
            })),
            Repr::Big(q) => Some(Self::from_big(q.recip())),
        }
    }

    /// `self / rhs`, panicking on a zero divisor as `num_rational` does.
    #[allow(clippy::panic)]
    fn div_impl(&self, rhs: &Self) -> Self {
        match rhs.checked_recip() {
            Some(r) => self.mul_impl(&r),
            None => panic!("Rat: division by zero"),
        }
    }

    /// The exact order.
    fn cmp_impl(&self, other: &Self) -> Ordering {
        match (&self.0, &other.0) {
            // a/b vs c/d with b, d > 0: ad vs cb, exact in 128 bits
            (Repr::Small { num: a, den: b }, Repr::Small { num: c, den: d }) => {
                (i128::from(*a) * i128::from(*d)).cmp(&(i128::from(*c) * i128::from(*b)))
            }
            _ => self.to_big().cmp(&other.to_big()),
        }
    }

    /// |p| of p/q in decimal, `None` when it is 1 (a coefficient that is not written).
    pub(crate) fn abs_numer_text(&self) -> Option<String> {
        match &self.0 {
            Repr::Small { num, .. } if num.unsigned_abs() == 1 => None,
            Repr::Small { num, .. } => Some(itoa::Buffer::new().format(num.unsigned_abs()).into()),
            Repr::Big(q) if q.numer().magnitude().is_one() => None,
            Repr::Big(q) => Some(q.numer().magnitude().to_str_radix(10)),
        }
    }

    /// The denominator q of p/q in decimal, `None` when it is 1.
    pub(crate) fn denom_text(&self) -> Option<String> {
        match &self.0 {
            Repr::Small { den: 1, .. } => None,
            Repr::Small { den, .. } => Some(itoa::Buffer::new().format(*den).into()),
            Repr::Big(q) if q.denom().is_one() => None,
            Repr::Big(q) => Some(q.denom().to_str_radix(10)),
        }
    }

    /// `p/q` as text: `-5/6`, `3`, as `BigRational` prints it.
    /// `f` applied to the text of the value as [`Rat::text`] writes it (`-5/6`, `3`), written
    /// in a buffer on the stack when numerator and denominator are machine words: printing an
    /// answer number by number allocates nothing.
    pub fn with_text<R>(&self, f: impl FnOnce(&str) -> R) -> R {
        use std::io::Write;
        if let Repr::Small { num, den } = &self.0 {
            if *den == 1 {
                return f(itoa::Buffer::new().format(*num));
            }
            // a sign, 19 digits, a slash and 19 digits
            let mut buf = [0u8; 48];
            let mut cursor = std::io::Cursor::new(&mut buf[..]);
            let written = cursor
                .write_all(itoa::Buffer::new().format(*num).as_bytes())
                .is_ok()
                && cursor.write_all(b"/").is_ok()
                && cursor
                    .write_all(itoa::Buffer::new().format(*den).as_bytes())
                    .is_ok();
            let len = usize::try_from(cursor.position()).unwrap_or(0);
            if let Some(text) = buf
                .get(..len)
                .filter(|_| written)
                .and_then(|b| std::str::from_utf8(b).ok())
            {
                return f(text);
            }
        }
        f(&self.text())
    }

    /// Appends the text of the value as [`Rat::text`] writes it (`-5/6`, `3`) to `out`: for
    /// machine words, the digits straight into the bytes (itoa), with no `String` between.
    pub fn push_text(&self, out: &mut Vec<u8>) {
        match &self.0 {
            Repr::Small { num, den } => {
                out.extend_from_slice(itoa::Buffer::new().format(*num).as_bytes());
                if *den != 1 {
                    out.push(b'/');
                    out.extend_from_slice(itoa::Buffer::new().format(*den).as_bytes());
                }
            }
            Repr::Big(q) => out.extend_from_slice(crate::rational_text(q).as_bytes()),
        }
    }

    /// Whether numerator and denominator are machine words (then each has at most 19
    /// decimal digits).
    pub fn is_word(&self) -> bool {
        matches!(self.0, Repr::Small { .. })
    }

    pub(crate) fn text(&self) -> String {
        match &self.0 {
            Repr::Small { num, den } => {
                // room for a numerator and a denominator of a machine word each: no reallocation
                let mut out = String::with_capacity(42);
                crate::decimal::push_i64(&mut out, *num);
                if *den != 1 {
                    out.push('/');
                    crate::decimal::push_i64(&mut out, *den);
                }
                out
            }
            Repr::Big(q) => crate::rational_text(q),
        }
    }
}

impl PartialEq for Rat {
    fn eq(&self, other: &Self) -> bool {
        // one representation per value
        match (&self.0, &other.0) {
            (Repr::Small { num: a, den: b }, Repr::Small { num: c, den: d }) => a == c && b == d,
            (Repr::Big(x), Repr::Big(y)) => x == y,
            _ => false,
        }
    }
}

impl Eq for Rat {}

impl PartialOrd for Rat {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Rat {
    fn cmp(&self, other: &Self) -> Ordering {
        self.cmp_impl(other)
    }
}

impl std::hash::Hash for Rat {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        match &self.0 {
            Repr::Small { num, den } => {
                num.hash(state);
                den.hash(state);
            }
            Repr::Big(q) => q.hash(state),
        }
    }
}

impl fmt::Display for Rat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text())
    }
}

impl fmt::Debug for Rat {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Rat({self})")
    }
}

impl From<BigRational> for Rat {
    fn from(q: BigRational) -> Self {
        Rat::from_big(q)
    }
}

impl From<&BigRational> for Rat {
    fn from(q: &BigRational) -> Self {
        <Rat as ExactRational>::from_rational(q)
    }
}

impl From<&Rat> for BigRational {
    fn from(q: &Rat) -> Self {
        q.to_big()
    }
}

impl From<Rat> for BigRational {
    fn from(q: Rat) -> Self {
        q.into_big()
    }
}

impl Zero for Rat {
    fn zero() -> Self {
        Rat(Repr::Small { num: 0, den: 1 })
    }
    fn is_zero(&self) -> bool {
        matches!(self.0, Repr::Small { num: 0, .. })
    }
}

impl One for Rat {
    fn one() -> Self {
        Rat(Repr::Small { num: 1, den: 1 })
    }
}

impl Neg for Rat {
    type Output = Rat;
    fn neg(self) -> Rat {
        match self.0 {
            // num ≠ i64::MIN
            Repr::Small { num, den } => Rat(Repr::Small { num: -num, den }),
            Repr::Big(q) => Rat::from_big(-*q),
        }
    }
}

impl Neg for &Rat {
    type Output = Rat;
    fn neg(self) -> Rat {
        -self.clone()
    }
}

forward_op!(
    Rat,
    std::convert::identity,
    Add,
    add,
    AddAssign,
    add_assign,
    add_impl
);
forward_op!(
    Rat,
    std::convert::identity,
    Sub,
    sub,
    SubAssign,
    sub_assign,
    sub_impl
);
forward_op!(
    Rat,
    std::convert::identity,
    Mul,
    mul,
    MulAssign,
    mul_assign,
    mul_impl
);
forward_op!(
    Rat,
    std::convert::identity,
    Div,
    div,
    DivAssign,
    div_assign,
    div_impl
);

impl FieldOps for Rat {
    fn from_i64(n: i64) -> Self {
        if n == i64::MIN {
            return Rat::from_big(BigRational::from_integer(BigInt::from(n)));
        }
        Rat(Repr::Small { num: n, den: 1 })
    }

    #[allow(clippy::panic)]
    fn from_ratio(num: i64, den: i64) -> Self {
        if den == 0 {
            panic!("Rat::from_ratio: zero denominator");
        }
        // in machine words: the gcd of the magnitudes (den ≠ 0, so g ≥ 1) after one
        // remainder, gcd(n, d) = gcd(n mod d, d), so that the binary steps run on the
        // denominator's length (a long numerator over a short common denominator: the
        // coefficients of closed forms); then the exact divisions, and the sign on the numerator
        let (n, d) = (num.unsigned_abs(), den.unsigned_abs());
        let g = gcd_u64(n % d, d);
        let (p, q) = (n / g, d / g);
        let negative = (num < 0) != (den < 0);
        if let (Ok(p), Ok(q)) = (i64::try_from(p), i64::try_from(q)) {
            // |p| ≤ i64::MAX, so −p ≠ i64::MIN: inline
            let num = if negative { -p } else { p };
            return Rat(Repr::Small { num, den: q });
        }
        let p = if negative {
            -i128::from(p)
        } else {
            i128::from(p)
        };
        Self::from_reduced(p, i128::from(q))
    }

    fn checked_div(&self, rhs: &Self) -> Option<Self> {
        rhs.checked_recip().map(|r| self.mul_impl(&r))
    }

    fn compare(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp_impl(other))
    }

    fn add_ref(&self, rhs: &Self) -> Self {
        self.add_impl(rhs)
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        self.sub_impl(rhs)
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        self.mul_impl(rhs)
    }
}

impl ExactRational for Rat {
    fn is_exact() -> bool {
        true
    }

    fn from_rational(q: &BigRational) -> Self {
        match (q.numer().to_i64(), q.denom().to_i64()) {
            (Some(n), Some(d)) if n != i64::MIN => Rat(Repr::Small { num: n, den: d }),
            _ => Rat(Repr::Big(Box::new(q.clone()))),
        }
    }

    fn from_rational_owned(q: BigRational) -> Self {
        Rat::from_big(q)
    }

    fn from_small_ratio(num: i128, den: i128) -> Self {
        match (num.checked_neg(), den.checked_neg()) {
            _ if den > 0 => Rat::reduce(num, den),
            (Some(n), Some(d)) => Rat::reduce(n, d),
            // i128::MIN: through big integers
            _ => Rat::from_big(BigRational::new(BigInt::from(num), BigInt::from(den))),
        }
    }

    fn try_from_number(x: &Quadratic) -> Result<Self, ScalarError> {
        x.to_rat()
            .ok_or_else(|| ScalarError::NotRational { value: x.to_text() })
    }

    fn to_number(&self) -> Option<Quadratic> {
        Some(Quadratic::from_rat(self.clone()))
    }

    fn as_rational(&self) -> Option<Cow<'_, BigRational>> {
        Some(match &self.0 {
            Repr::Big(q) => Cow::Borrowed(&**q),
            Repr::Small { .. } => Cow::Owned(self.to_big()),
        })
    }

    #[inline]
    fn as_small_ratio(&self) -> Option<(i128, i128)> {
        match &self.0 {
            Repr::Small { num, den } => Some((i128::from(*num), i128::from(*den))),
            Repr::Big(q) => Some((q.numer().to_i128()?, q.denom().to_i128()?)),
        }
    }

    fn to_f64(&self) -> f64 {
        match &self.0 {
            // both exact in f64 below 2^53; otherwise the nearest quotient of the two
            Repr::Small { num, den } => *num as f64 / *den as f64,
            Repr::Big(q) => crate::rational::rational_to_f64(q),
        }
    }
}

impl SquareRoot for Rat {
    fn sqrt_exact(&self) -> Option<Self> {
        match &self.0 {
            Repr::Small { num, den } if *num >= 0 => {
                let (n, d) = (num.unsigned_abs().isqrt(), den.unsigned_abs().isqrt());
                (n * n == num.unsigned_abs() && d * d == den.unsigned_abs())
                    .then(|| Rat::from_reduced(i128::from(n), i128::from(d)))
            }
            Repr::Small { .. } => None,
            Repr::Big(q) => q.sqrt_exact().map(Rat::from_big),
        }
    }

    fn sqrt_of(n: u64) -> Option<Self> {
        let root = n.isqrt();
        (root * root == n).then(|| Rat::from_reduced(i128::from(root), 1))
    }
}

impl Print for Rat {
    fn to_text(&self) -> String {
        self.text()
    }

    fn to_latex(&self) -> String {
        match &self.0 {
            Repr::Small { num, den } => {
                let sign = if *num < 0 { "-" } else { "" };
                if *den == 1 {
                    format!("{sign}{}", num.unsigned_abs())
                } else {
                    format!("{sign}\\frac{{{}}}{{{den}}}", num.unsigned_abs())
                }
            }
            Repr::Big(q) => {
                let sign = if q.is_negative() { "-" } else { "" };
                format!(
                    "{sign}{}",
                    latex_fraction(&q.numer().abs().to_string(), q.denom())
                )
            }
        }
    }

    fn to_json_string(&self) -> String {
        self.text()
    }
}

#[cfg(test)]
pub(crate) mod tests;
