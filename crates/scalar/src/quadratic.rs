//! The quadratic field Q(√d): numbers a + b√d with a, b rational and d a square-free integer ≥ 2.
//!
//! The weights of circles and spheres (`√2/2`, `√3/2`) live here, exactly. A value whose root
//! part is zero is a plain rational and belongs to every field: it carries `d = 0` ("no root
//! yet"), so `1/2` mixes freely with `√2` or with `√3`. Two different roots in one operation
//! (`√2 + √3`) are not in any one quadratic field: the `checked_*` operations return
//! [`ScalarError::MixedRoots`], and the operators panic rather than answer wrongly (the problem
//! layer picks one field per problem, so the operators never meet that case on valid input).

use crate::{latex_fraction, ExactRational, FieldOps, Print, ScalarError, SquareRoot};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use std::borrow::Cow;
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// An exact number a + b√d.
///
/// Invariants: `d` is 0 exactly when `b` is 0 (a rational); otherwise `d ≥ 2` is square-free.
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct Quadratic {
    a: BigRational,
    b: BigRational,
    d: u64,
}

/// Largest radicand accepted by [`Quadratic::sqrt_of`] (square-free reduction is by trial division).
pub const MAX_RADICAND: u64 = 1_000_000_000_000;

impl Quadratic {
    /// The number a + b√d, checking that d is a square-free integer ≥ 2 (when b ≠ 0).
    pub fn new(a: BigRational, b: BigRational, d: u64) -> Result<Self, ScalarError> {
        if b.is_zero() {
            return Ok(Self::from_rational(a));
        }
        if d < 2 || square_free_part(d) != (1, d) {
            return Err(ScalarError::Parse {
                column: 1,
                expected: "a square-free radicand d ≥ 2".into(),
                found: d.to_string(),
            });
        }
        Ok(Quadratic { a, b, d })
    }

    /// The rational `a`, as an element of every quadratic field.
    pub fn from_rational(a: BigRational) -> Self {
        Quadratic {
            a,
            b: BigRational::zero(),
            d: 0,
        }
    }

    /// √n for a non-negative rational n, reduced: √8 = 2√2, √(1/2) = √2/2, √4 = 2.
    pub fn sqrt_of(n: &BigRational) -> Result<Self, ScalarError> {
        if Signed::is_negative(n) {
            return Err(ScalarError::NegativeSqrt {
                value: n.to_string(),
            });
        }
        // √(p/q) = √(p q) / q
        let pq = n.numer() * n.denom();
        let pq: u64 = u64::try_from(&pq)
            .ok()
            .filter(|v| *v <= MAX_RADICAND)
            .ok_or_else(|| ScalarError::Limit {
                what: format!("square root argument {n} is larger than {MAX_RADICAND}"),
            })?;
        if pq == 0 {
            return Ok(Self::zero());
        }
        let (k, d) = square_free_part(pq);
        let coef = BigRational::new(BigInt::from(k), n.denom().clone());
        if d == 1 {
            Ok(Self::from_rational(coef))
        } else {
            Ok(Quadratic {
                a: BigRational::zero(),
                b: coef,
                d,
            })
        }
    }

    /// The rational part a.
    pub fn rational_part(&self) -> &BigRational {
        &self.a
    }
    /// The coefficient b of √d.
    pub fn root_part(&self) -> &BigRational {
        &self.b
    }
    /// The radicand d (0 for a rational).
    pub fn radicand(&self) -> u64 {
        self.d
    }

    /// The value as a rational, when it has no root part.
    pub fn to_rational(&self) -> Option<BigRational> {
        self.b.is_zero().then(|| self.a.clone())
    }

    /// The value as a [`crate::Rat`], when it has no root part.
    pub fn to_rat(&self) -> Option<crate::Rat> {
        self.b.is_zero().then(|| crate::Rat::from_rational(&self.a))
    }

    /// The rational `a` of a [`crate::Rat`], as an element of every quadratic field.
    pub fn from_rat(a: crate::Rat) -> Self {
        Self::from_rational(a.into())
    }

    /// The conjugate a - b√d.
    pub fn conjugate(&self) -> Self {
        Quadratic {
            a: self.a.clone(),
            b: -self.b.clone(),
            d: self.d,
        }
    }

    /// The field norm (a + b√d)(a - b√d) = a² - b² d, a rational.
    pub fn norm(&self) -> BigRational {
        &self.a * &self.a - &self.b * &self.b * BigRational::from_integer(BigInt::from(self.d))
    }

    /// The common radicand of two numbers, or the error naming both.
    fn common_d(&self, other: &Self) -> Result<u64, ScalarError> {
        match (self.d, other.d) {
            (0, d) | (d, 0) => Ok(d),
            (d, e) if d == e => Ok(d),
            (d, e) => Err(ScalarError::MixedRoots {
                first: d,
                second: e,
            }),
        }
    }

    fn normalized(a: BigRational, b: BigRational, d: u64) -> Self {
        if b.is_zero() {
            Self::from_rational(a)
        } else {
            Quadratic { a, b, d }
        }
    }

    // (a + b√d) + (c + e√d) = (a + c) + (b + e)√d
    /// The sum, or [`ScalarError::MixedRoots`].
    pub fn checked_add(&self, rhs: &Self) -> Result<Self, ScalarError> {
        let d = self.common_d(rhs)?;
        if d == 0 {
            // both rational: a + c
            return Ok(Self::from_rational(&self.a + &rhs.a));
        }
        Ok(Self::normalized(&self.a + &rhs.a, &self.b + &rhs.b, d))
    }

    // (a + b√d) - (c + e√d) = (a - c) + (b - e)√d
    /// The difference, or [`ScalarError::MixedRoots`].
    pub fn checked_sub(&self, rhs: &Self) -> Result<Self, ScalarError> {
        let d = self.common_d(rhs)?;
        if d == 0 {
            // both rational: a - c
            return Ok(Self::from_rational(&self.a - &rhs.a));
        }
        Ok(Self::normalized(&self.a - &rhs.a, &self.b - &rhs.b, d))
    }

    // (a + b√d)(c + e√d) = (ac + be·d) + (ae + bc)√d
    /// The product, or [`ScalarError::MixedRoots`].
    pub fn checked_mul(&self, rhs: &Self) -> Result<Self, ScalarError> {
        let d = self.common_d(rhs)?;
        // A rational factor needs two products, two rationals one:
        // a (c + e√d) = ac + ae√d, (a + b√d) c = ac + bc√d.
        match (self.d, rhs.d) {
            (0, 0) => return Ok(Self::from_rational(&self.a * &rhs.a)),
            (0, _) => return Ok(Self::normalized(&self.a * &rhs.a, &self.a * &rhs.b, d)),
            (_, 0) => return Ok(Self::normalized(&self.a * &rhs.a, &self.b * &rhs.a, d)),
            _ => {}
        }
        let dd = BigRational::from_integer(BigInt::from(d));
        let a = &self.a * &rhs.a + &self.b * &rhs.b * dd;
        let b = &self.a * &rhs.b + &self.b * &rhs.a;
        Ok(Self::normalized(a, b, d))
    }

    // 1 / (a + b√d) = (a - b√d) / (a² - b² d); the norm vanishes only at 0 since √d ∉ Q.
    /// The inverse, or [`ScalarError::DivisionByZero`].
    pub fn checked_inv(&self) -> Result<Self, ScalarError> {
        if self.d == 0 {
            // a rational: 1 / a
            if self.a.is_zero() {
                return Err(ScalarError::DivisionByZero { column: None });
            }
            return Ok(Self::from_rational(self.a.recip()));
        }
        let n = self.norm();
        if n.is_zero() {
            return Err(ScalarError::DivisionByZero { column: None });
        }
        Ok(Self::normalized(&self.a / &n, -(&self.b / &n), self.d))
    }

    /// The quotient, or an error for zero divisors and mixed roots.
    pub fn checked_quot(&self, rhs: &Self) -> Result<Self, ScalarError> {
        self.common_d(rhs)?;
        if self.d == 0 && rhs.d == 0 {
            // both rational: a / c
            if rhs.a.is_zero() {
                return Err(ScalarError::DivisionByZero { column: None });
            }
            return Ok(Self::from_rational(&self.a / &rhs.a));
        }
        self.checked_mul(&rhs.checked_inv()?)
    }

    /// The sign of a + b√d, exactly: compare a² with b²d when a and b differ in sign.
    pub fn signum(&self) -> Ordering {
        let sa = self.a.cmp(&BigRational::zero());
        let sb = self.b.cmp(&BigRational::zero());
        match (sa, sb) {
            (s, Ordering::Equal) => s,
            (Ordering::Equal, s) => s,
            (s, t) if s == t => s,
            (s, _) => {
                // a and b√d have opposite signs: the larger square wins.
                let a2 = &self.a * &self.a;
                let b2d = &self.b * &self.b * BigRational::from_integer(BigInt::from(self.d));
                match a2.cmp(&b2d) {
                    Ordering::Greater => s,
                    Ordering::Less => s.reverse(),
                    Ordering::Equal => Ordering::Equal,
                }
            }
        }
    }

    /// The result of an operator. The operators of `Scalar` cannot return an error, so two
    /// numbers with different roots (√2 + √3, outside every field a + b√d) are a bug of the
    /// caller: every problem runs in one field, which cagd-problem chooses before any
    /// arithmetic (`checked_add` and its siblings return the error instead).
    #[allow(clippy::panic)]
    fn expect<T>(r: Result<T, ScalarError>) -> T {
        // every operator passes here: the checkpoint of the long loops over Q(√d)
        crate::cancel::checkpoint();
        match r {
            Ok(v) => v,
            Err(e) => panic!("quadratic field: {e}"),
        }
    }

    /// Text of the root part b√d: `√2`, `-√2`, `3√2/4`, `√2/2`.
    fn root_text(b: &BigRational, d: u64, sep: &str) -> String {
        let num = b.numer().abs();
        let coef = if num.is_one() {
            String::new()
        } else {
            format!("{num}{sep}")
        };
        let den = if b.denom().is_one() {
            String::new()
        } else {
            format!("/{}", b.denom())
        };
        format!("{coef}{}{den}", Self::root_symbol(d, sep))
    }

    fn root_symbol(d: u64, sep: &str) -> String {
        if sep.is_empty() {
            format!("√{d}")
        } else {
            format!("sqrt{d}")
        }
    }

    fn join(
        a: &BigRational,
        b: &BigRational,
        root: String,
        plain: impl Fn(&BigRational) -> String,
    ) -> String {
        let neg = Signed::is_negative(b);
        if a.is_zero() {
            if neg {
                format!("-{root}")
            } else {
                root
            }
        } else {
            format!("{} {} {root}", plain(a), if neg { "-" } else { "+" })
        }
    }

    /// The exact value as f64.
    pub fn to_f64(&self) -> f64 {
        let a = crate::rational::rational_to_f64(&self.a);
        if self.b.is_zero() {
            a
        } else {
            a + crate::rational::rational_to_f64(&self.b) * (self.d as f64).sqrt()
        }
    }
}

/// Writes n = k² m with m square-free; returns (k, m).
fn square_free_part(n: u64) -> (u64, u64) {
    let mut k = 1u64;
    let mut m = 1u64;
    let mut rest = n;
    let mut p = 2u64;
    while p.saturating_mul(p) <= rest {
        let mut e = 0;
        while rest % p == 0 {
            rest /= p;
            e += 1;
        }
        for _ in 0..e / 2 {
            k *= p;
        }
        if e % 2 == 1 {
            m *= p;
        }
        p += if p == 2 { 1 } else { 2 };
    }
    (k, m * rest)
}

impl fmt::Display for Quadratic {
    /// `5/6`, `√2/2`, `1/2 + 3√2/4`, `-√3`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.b.is_zero() {
            // as num-rational's Display writes a rational, without its formatting machinery
            return f.write_str(&crate::rational_text(&self.a));
        }
        let root = Self::root_text(&self.b, self.d, "");
        f.write_str(&Self::join(&self.a, &self.b, root, crate::rational_text))
    }
}

impl fmt::Debug for Quadratic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Quadratic({self})")
    }
}

impl PartialOrd for Quadratic {
    /// Exact order; `None` when the two numbers have different roots.
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        self.checked_sub(other).ok().map(|diff| diff.signum())
    }
}

impl Zero for Quadratic {
    fn zero() -> Self {
        Self::from_rational(BigRational::zero())
    }
    fn is_zero(&self) -> bool {
        self.a.is_zero() && self.b.is_zero()
    }
}

impl One for Quadratic {
    fn one() -> Self {
        Self::from_rational(BigRational::one())
    }
}

impl Neg for Quadratic {
    type Output = Quadratic;
    // -(a + b√d) = -a - b√d
    fn neg(self) -> Quadratic {
        Quadratic {
            a: -self.a,
            b: -self.b,
            d: self.d,
        }
    }
}

forward_op!(
    Quadratic,
    Quadratic::expect,
    Add,
    add,
    AddAssign,
    add_assign,
    checked_add
);
forward_op!(
    Quadratic,
    Quadratic::expect,
    Sub,
    sub,
    SubAssign,
    sub_assign,
    checked_sub
);
forward_op!(
    Quadratic,
    Quadratic::expect,
    Mul,
    mul,
    MulAssign,
    mul_assign,
    checked_mul
);
forward_op!(
    Quadratic,
    Quadratic::expect,
    Div,
    div,
    DivAssign,
    div_assign,
    checked_quot
);

impl FieldOps for Quadratic {
    fn from_i64(n: i64) -> Self {
        Self::from_rational(BigRational::from_integer(BigInt::from(n)))
    }

    fn from_ratio(num: i64, den: i64) -> Self {
        Self::from_rational(BigRational::new(BigInt::from(num), BigInt::from(den)))
    }

    fn checked_div(&self, rhs: &Self) -> Option<Self> {
        self.checked_quot(rhs).ok()
    }

    fn add_ref(&self, rhs: &Self) -> Self {
        self + rhs
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        self - rhs
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        self * rhs
    }
}

impl ExactRational for Quadratic {
    fn is_exact() -> bool {
        true
    }

    fn from_rational(q: &BigRational) -> Self {
        Quadratic::from_rational(q.clone())
    }

    fn from_rational_owned(q: BigRational) -> Self {
        Quadratic::from_rational(q)
    }

    fn try_from_number(x: &Quadratic) -> Result<Self, ScalarError> {
        Ok(x.clone())
    }

    fn to_number(&self) -> Option<Quadratic> {
        Some(self.clone())
    }

    fn as_rational(&self) -> Option<Cow<'_, BigRational>> {
        self.b.is_zero().then_some(Cow::Borrowed(&self.a))
    }

    fn to_f64(&self) -> f64 {
        Quadratic::to_f64(self)
    }
}

impl SquareRoot for Quadratic {
    fn sqrt_exact(&self) -> Option<Self> {
        // Only roots of rationals: √(p/q) lands in Q(√d) for its own d.
        self.to_rational().and_then(|q| Quadratic::sqrt_of(&q).ok())
    }

    // √n = k√d with n = k² d, d square-free; `None` only above MAX_RADICAND.
    fn sqrt_of(n: u64) -> Option<Self> {
        Quadratic::sqrt_of(&BigRational::from_integer(BigInt::from(n))).ok()
    }
}

impl Print for Quadratic {
    fn to_latex(&self) -> String {
        let rat = |q: &BigRational| q.to_latex();
        if self.b.is_zero() {
            return rat(&self.a);
        }
        let num = self.b.numer().abs();
        let coef = if num.is_one() {
            String::new()
        } else {
            num.to_string()
        };
        let root = latex_fraction(&format!("{coef}\\sqrt{{{}}}", self.d), self.b.denom());
        Self::join(&self.a, &self.b, root, rat)
    }

    fn to_json_string(&self) -> String {
        if self.b.is_zero() {
            return crate::rational_text(&self.a);
        }
        let root = Self::root_text(&self.b, self.d, "*");
        Self::join(&self.a, &self.b, root, crate::rational_text)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn square_free_parts() {
        assert_eq!(square_free_part(8), (2, 2));
        assert_eq!(square_free_part(12), (2, 3));
        assert_eq!(square_free_part(49), (7, 1));
        assert_eq!(square_free_part(30), (1, 30));
        assert_eq!(square_free_part(1), (1, 1));
    }
}
