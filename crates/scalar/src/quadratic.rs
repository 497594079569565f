//! The quadratic field Q(√d): numbers a + b√d with a, b rational and d a square-free integer ≥ 2.
//!
//! The weights of circles and spheres (`√2/2`, `√3/2`) live here, exactly. A value whose root
//! part is zero is a plain rational and belongs to every field: it carries `d = 0` ("no root
//! yet"), so `1/2` mixes freely with `√2` or with `√3`. Two different roots in one operation
//! (`√2 + √3`) are not in any one quadratic field: the `checked_*` operations return
//! [`ScalarError::MixedRoots`], and the operators panic rather than answer wrongly (the problem
//! layer picks one field per problem, so the operators never meet that case on valid input).
//!
//! The parts a and b are [`Rat`]s: machine words while they fit, so the arithmetic of Q(√d)
//! runs in 128-bit integers and spills to big integers only for long parts. The property tests
//! compare every operation and printer with a + b√d computed on [`BigRational`]s.
//!
//! ```
//! use cagd_scalar::{BigRational, FieldOps, Print, Quadratic};
//! let w = Quadratic::sqrt_of(&BigRational::from_i64(2)).unwrap() / Quadratic::from_i64(2);
//! assert_eq!(w.to_text(), "√2/2");
//! assert_eq!(w.root_part().to_big(), BigRational::from_ratio(1, 2));
//! assert_eq!((&w * &w).to_text(), "1/2");
//! ```

use crate::{ExactRational, FieldOps, Print, Rat, ScalarError, SquareRoot};
use num_rational::BigRational;
use num_traits::{One, Zero};
use std::borrow::Cow;
use std::cmp::Ordering;
use std::fmt;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// An exact number a + b√d, its parts a and b [`Rat`]s (machine words while they fit).
///
/// Invariants: `d` is 0 exactly when `b` is 0 (a rational); otherwise `d ≥ 2` is square-free.
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct Quadratic {
    a: Rat,
    b: Rat,
    d: u64,
}

/// Largest radicand accepted by [`Quadratic::sqrt_of`] (square-free reduction is by trial division).
pub const MAX_RADICAND: u64 = 1_000_000_000_000;

impl Quadratic {
    /// The number a + b√d, checking that d is a square-free integer ≥ 2 (when b ≠ 0).
    pub fn new(a: impl Into<Rat>, b: impl Into<Rat>, d: u64) -> Result<Self, ScalarError> {
        let (a, b) = (a.into(), b.into());
        if b.is_zero() {
            return Ok(Self::from_rat(a));
        }
        if d < 2 || square_free_part(d) != (1, d) {
            return Err(ScalarError::Parse {
                column: 1,
                expected: crate::Expected::SquareFreeRadicand,
                found: crate::Found::Value(d.to_string()),
            });
        }
        Ok(Quadratic { a, b, d })
    }

    /// The rational `a`, as an element of every quadratic field.
    pub fn from_rational(a: impl Into<Rat>) -> Self {
        Self::from_rat(a.into())
    }

    /// The rational `a` of a [`Rat`], as an element of every quadratic field.
    pub fn from_rat(a: Rat) -> Self {
        Quadratic {
            a,
            b: Rat::zero(),
            d: 0,
        }
    }

    /// √n for a non-negative rational n, reduced: √8 = 2√2, √(1/2) = √2/2, √4 = 2.
    pub fn sqrt_of(n: &BigRational) -> Result<Self, ScalarError> {
        Self::sqrt_of_rat(&Rat::from(n))
    }

    /// √n for a non-negative [`Rat`] n, reduced, as [`Quadratic::sqrt_of`].
    pub fn sqrt_of_rat(n: &Rat) -> Result<Self, ScalarError> {
        if n.is_negative() {
            return Err(ScalarError::NegativeSqrt {
                value: n.to_string(),
            });
        }
        // √(p/q) = √(p q) / q
        let too_big = || ScalarError::Limit {
            what: crate::Exceeded::Radicand {
                value: n.to_string(),
                max: MAX_RADICAND,
            },
        };
        // p q ≤ MAX_RADICAND needs both p and q to be machine words
        let (p, q) = n.as_small().ok_or_else(too_big)?;
        let pq = u64::try_from(i128::from(p) * i128::from(q))
            .ok()
            .filter(|v| *v <= MAX_RADICAND)
            .ok_or_else(too_big)?;
        if pq == 0 {
            return Ok(Self::zero());
        }
        let (k, d) = square_free_part(pq);
        // k ≤ √(p q) ≤ 10^6: k/q, reduced
        let coef = Rat::from_ratio(i64::try_from(k).unwrap_or(i64::MAX), q);
        if d == 1 {
            Ok(Self::from_rat(coef))
        } else {
            Ok(Quadratic {
                a: Rat::zero(),
                b: coef,
                d,
            })
        }
    }

    /// The rational part a.
    pub fn rational_part(&self) -> &Rat {
        &self.a
    }
    /// The coefficient b of √d.
    pub fn root_part(&self) -> &Rat {
        &self.b
    }
    /// The radicand d (0 for a rational).
    pub fn radicand(&self) -> u64 {
        self.d
    }

    /// The value as a big rational, when it has no root part.
    pub fn to_rational(&self) -> Option<BigRational> {
        self.b.is_zero().then(|| self.a.to_big())
    }

    /// The value as a borrowed [`Rat`], when it has no root part.
    pub fn as_rat(&self) -> Option<&Rat> {
        self.b.is_zero().then_some(&self.a)
    }

    /// The value as a [`Rat`], when it has no root part.
    pub fn to_rat(&self) -> Option<Rat> {
        self.b.is_zero().then(|| self.a.clone())
    }

    /// The conjugate a - b√d.
    pub fn conjugate(&self) -> Self {
        Quadratic {
            a: self.a.clone(),
            b: -&self.b,
            d: self.d,
        }
    }

    /// The field norm (a + b√d)(a - b√d) = a² - b² d, a rational.
    pub fn norm(&self) -> Rat {
        &self.a * &self.a - &self.b * &self.b * Self::radicand_rat(self.d)
    }

    /// The radicand d as a rational (d ≤ [`MAX_RADICAND`] fits a word).
    fn radicand_rat(d: u64) -> Rat {
        Rat::from_i64(i64::try_from(d).unwrap_or(i64::MAX))
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

    fn normalized(a: Rat, b: Rat, d: u64) -> Self {
        if b.is_zero() {
            Self::from_rat(a)
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
            return Ok(Self::from_rat(&self.a + &rhs.a));
        }
        Ok(Self::normalized(&self.a + &rhs.a, &self.b + &rhs.b, d))
    }

    // (a + b√d) - (c + e√d) = (a - c) + (b - e)√d
    /// The difference, or [`ScalarError::MixedRoots`].
    pub fn checked_sub(&self, rhs: &Self) -> Result<Self, ScalarError> {
        let d = self.common_d(rhs)?;
        if d == 0 {
            // both rational: a - c
            return Ok(Self::from_rat(&self.a - &rhs.a));
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
            (0, 0) => return Ok(Self::from_rat(&self.a * &rhs.a)),
            (0, _) => return Ok(Self::normalized(&self.a * &rhs.a, &self.a * &rhs.b, d)),
            (_, 0) => return Ok(Self::normalized(&self.a * &rhs.a, &self.b * &rhs.a, d)),
            _ => {}
        }
        let a = &self.a * &rhs.a + &self.b * &rhs.b * Self::radicand_rat(d);
        let b = &self.a * &rhs.b + &self.b * &rhs.a;
        Ok(Self::normalized(a, b, d))
    }

    // 1 / (a + b√d) = (a - b√d) / (a² - b² d); the norm vanishes only at 0 since √d ∉ Q.
    /// The inverse, or [`ScalarError::DivisionByZero`].
    pub fn checked_inv(&self) -> Result<Self, ScalarError> {
        if self.d == 0 {
            // a rational: 1 / a
            return self
                .a
                .checked_recip()
                .map(Self::from_rat)
                .ok_or(ScalarError::DivisionByZero { column: None });
        }
        let n = self
            .norm()
            .checked_recip()
            .ok_or(ScalarError::DivisionByZero { column: None })?;
        Ok(Self::normalized(&self.a * &n, -(&self.b * &n), self.d))
    }

    /// The quotient, or an error for zero divisors and mixed roots.
    pub fn checked_quot(&self, rhs: &Self) -> Result<Self, ScalarError> {
        self.common_d(rhs)?;
        if self.d == 0 && rhs.d == 0 {
            // both rational: a / c
            return self
                .a
                .checked_div(&rhs.a)
                .map(Self::from_rat)
                .ok_or(ScalarError::DivisionByZero { column: None });
        }
        self.checked_mul(&rhs.checked_inv()?)
    }

    /// The sign of a + b√d, exactly: compare a² with b²d when a and b differ in sign.
    pub fn signum(&self) -> Ordering {
        let sa = self.a.cmp(&Rat::zero());
        let sb = self.b.cmp(&Rat::zero());
        match (sa, sb) {
            (s, Ordering::Equal) => s,
            (Ordering::Equal, s) => s,
            (s, t) if s == t => s,
            (s, _) => {
                // a and b√d have opposite signs: the larger square wins.
                let a2 = &self.a * &self.a;
                let b2d = &self.b * &self.b * Self::radicand_rat(self.d);
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

    /// Text of the root part b√d: `√2`, `-√2`, `3√2/4`, `√2/2` (without its sign).
    fn root_text(b: &Rat, d: u64, sep: &str) -> String {
        let mut out = String::new();
        if let Some(num) = b.abs_numer_text() {
            out.push_str(&num);
            out.push_str(sep);
        }
        out.push_str(&Self::root_symbol(d, sep));
        if let Some(den) = b.denom_text() {
            out.push('/');
            out.push_str(&den);
        }
        out
    }

    fn root_symbol(d: u64, sep: &str) -> String {
        if sep.is_empty() {
            format!("√{d}")
        } else {
            format!("sqrt{d}")
        }
    }

    /// `a + root` or `a - root` by the sign of b, or the root alone when a is 0.
    fn join(a: &Rat, b: &Rat, root: String, plain: impl Fn(&Rat) -> String) -> String {
        let neg = b.is_negative();
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
        let a = ExactRational::to_f64(&self.a);
        if self.b.is_zero() {
            a
        } else {
            a + ExactRational::to_f64(&self.b) * (self.d as f64).sqrt()
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
            return f.write_str(&self.a.text());
        }
        let root = Self::root_text(&self.b, self.d, "");
        f.write_str(&Self::join(&self.a, &self.b, root, Rat::text))
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
        Self::from_rat(Rat::zero())
    }
    fn is_zero(&self) -> bool {
        self.a.is_zero() && self.b.is_zero()
    }
}

impl One for Quadratic {
    fn one() -> Self {
        Self::from_rat(Rat::one())
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
        Self::from_rat(Rat::from_i64(n))
    }

    #[inline]
    fn from_ratio(num: i64, den: i64) -> Self {
        Self::from_rat(Rat::from_ratio(num, den))
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
        Quadratic::from_rat(Rat::from(q))
    }

    fn from_rational_owned(q: BigRational) -> Self {
        Quadratic::from_rat(Rat::from(q))
    }

    fn from_small_ratio(num: i128, den: i128) -> Self {
        Quadratic::from_rat(Rat::from_small_ratio(num, den))
    }

    fn try_from_number(x: &Quadratic) -> Result<Self, ScalarError> {
        Ok(x.clone())
    }

    fn to_number(&self) -> Option<Quadratic> {
        Some(self.clone())
    }

    fn as_rational(&self) -> Option<Cow<'_, BigRational>> {
        if self.b.is_zero() {
            self.a.as_rational()
        } else {
            None
        }
    }

    #[inline]
    fn as_small_ratio(&self) -> Option<(i128, i128)> {
        // the rational part's words, without building a big rational
        if self.b.is_zero() {
            self.a.as_small_ratio()
        } else {
            None
        }
    }

    fn to_f64(&self) -> f64 {
        Quadratic::to_f64(self)
    }
}

impl SquareRoot for Quadratic {
    fn sqrt_exact(&self) -> Option<Self> {
        // Only roots of rationals: √(p/q) lands in Q(√d) for its own d.
        self.to_rat().and_then(|q| Quadratic::sqrt_of_rat(&q).ok())
    }

    // √n = k√d with n = k² d, d square-free; `None` only above MAX_RADICAND.
    fn sqrt_of(n: u64) -> Option<Self> {
        let n = i64::try_from(n).ok()?;
        Quadratic::sqrt_of_rat(&Rat::from_i64(n)).ok()
    }
}

impl Print for Quadratic {
    fn to_latex(&self) -> String {
        if self.b.is_zero() {
            return self.a.to_latex();
        }
        let coef = self.b.abs_numer_text().unwrap_or_default();
        let root = format!("{coef}\\sqrt{{{}}}", self.d);
        let root = match self.b.denom_text() {
            Some(den) => format!("\\frac{{{root}}}{{{den}}}"),
            None => root,
        };
        Self::join(&self.a, &self.b, root, Print::to_latex)
    }

    fn to_json_string(&self) -> String {
        if self.b.is_zero() {
            return self.a.text();
        }
        let root = Self::root_text(&self.b, self.d, "*");
        Self::join(&self.a, &self.b, root, Rat::text)
    }
}

#[cfg(test)]
mod tests;
