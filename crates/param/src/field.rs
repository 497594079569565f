//! [`Param`]: the field of quotients of polynomials in named parameters.

use crate::letters::{Letters, Name};
use cagd_poly::{Poly, Term};
use cagd_scalar::{
    cancel, BigRational, ExactRational, FieldOps, Quadratic, ScalarError, SquareRoot,
};
use num_traits::{One, Zero};
use std::borrow::Cow;
use std::cmp::Ordering;
use std::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Sub, SubAssign};

/// A polynomial in named parameters with coefficients in Q or Q(√d).
pub type ParamPoly = Poly<Quadratic, Letters>;

/// A number in letters: a quotient p/q of polynomials in named parameters (`R`, `a`, `c_{1,0}`)
/// with coefficients in Q or one Q(√d); a constant is held as a plain [`Quadratic`].
///
/// # Normal form
/// - a value that does not depend on a parameter is `Const` (so `R/R` is `1`);
/// - otherwise the denominator is monic (its largest term, in graded order, has coefficient 1);
/// - the greatest common monomial of numerator and denominator is cancelled (`R^2/R` = `R`);
/// - when one of the two divides the other exactly, the division is done (`(a^2 - b^2)/(a - b)`
///   = `a + b`).
///
/// Not reduced: a common factor that divides neither side, such as `(a + b)(a - c)` over
/// `(a + b)(a + c)`; it stays (no multivariate gcd is computed). Equality is exact in every case:
/// `p/q = r/s` is decided by `p s = r q`.
///
/// # Order
/// Two constants compare as numbers; a value in letters has no sign, so
/// [`FieldOps::compare`] answers `None` and the algorithm that needed the sign says which.
#[derive(Clone)]
pub enum Param {
    /// A value without parameters.
    Const(Quadratic),
    /// A value in parameters, in normal form (never constant).
    Ratio(Box<Ratio>),
}

/// The numerator and denominator of a [`Param::Ratio`].
#[derive(Clone)]
pub struct Ratio {
    /// The numerator.
    pub num: ParamPoly,
    /// The denominator, monic; `1` for a polynomial.
    pub den: ParamPoly,
}

impl Param {
    /// The parameter `name`.
    pub fn var(name: &str) -> Param {
        Param::named(Name::new(name))
    }

    /// The parameter `name` (a function's name prints with its argument).
    pub fn named(name: Name) -> Param {
        Param::Ratio(Box::new(Ratio {
            num: Poly::term(Quadratic::one(), Letters::var(name)),
            den: Poly::one(),
        }))
    }

    /// The value `num / den`, in normal form; `None` when `den` is zero.
    pub fn ratio(num: ParamPoly, den: ParamPoly) -> Option<Param> {
        if den.is_zero() {
            return None;
        }
        Some(normalize(num, den))
    }

    /// The value as a constant, when it has no parameter.
    pub fn as_const(&self) -> Option<&Quadratic> {
        match self {
            Param::Const(x) => Some(x),
            Param::Ratio(_) => None,
        }
    }

    /// Numerator and denominator (`x/1` for a constant).
    pub fn parts(&self) -> (Cow<'_, ParamPoly>, Cow<'_, ParamPoly>) {
        match self {
            Param::Const(x) => (
                Cow::Owned(Poly::constant(x.clone())),
                Cow::Owned(Poly::one()),
            ),
            Param::Ratio(r) => (Cow::Borrowed(&r.num), Cow::Borrowed(&r.den)),
        }
    }

    /// The parameters that occur, in natural order.
    pub fn names(&self) -> Vec<Name> {
        let mut names: Vec<Name> = Vec::new();
        if let Param::Ratio(r) = self {
            for (m, _) in r.num.terms().chain(r.den.terms()) {
                for (n, _) in m.powers() {
                    if !names.contains(n) {
                        names.push(n.clone());
                    }
                }
            }
        }
        names.sort();
        names
    }

    /// The radicand of the square root in the coefficients (0 when all are rational).
    pub fn radicand(&self) -> u64 {
        match self {
            Param::Const(x) => x.radicand(),
            Param::Ratio(r) => r
                .num
                .terms()
                .chain(r.den.terms())
                .map(|(_, c)| c.radicand())
                .find(|&d| d != 0)
                .unwrap_or(0),
        }
    }

    /// The most bits of a numerator or denominator of its rational parts (of every coefficient
    /// for a value in letters): a cheap bound of its digits, 1 digit per 3 bits or more.
    pub fn max_bits(&self) -> u64 {
        let bits = |q: &Quadratic| q.rational_part().bits().max(q.root_part().bits());
        match self {
            Param::Const(x) => bits(x),
            Param::Ratio(r) => r
                .num
                .terms()
                .chain(r.den.terms())
                .map(|(_, c)| bits(c))
                .max()
                .unwrap_or(0),
        }
    }

    /// Whether the value depends on no parameter.
    pub fn is_const(&self) -> bool {
        matches!(self, Param::Const(_))
    }
}

/// The normal form of `num / den` (`den ≠ 0`); see [`Param`].
fn normalize(mut num: ParamPoly, mut den: ParamPoly) -> Param {
    if num.is_zero() {
        return Param::Const(Quadratic::zero());
    }
    if let Some(c) = den.as_constant() {
        if let Some(n) = num.as_constant() {
            return Param::Const(n / c);
        }
        let inv = Quadratic::one() / c;
        return Param::Ratio(Box::new(Ratio {
            num: num.scale(&inv),
            den: Poly::one(),
        }));
    }
    // the common monomial
    let g = num
        .terms()
        .chain(den.terms())
        .map(|(m, _)| m.clone())
        .reduce(|a, b| a.gcd(&b))
        .unwrap_or_else(Letters::one);
    if !g.is_one() {
        num = divide_monomial(&num, &g);
        den = divide_monomial(&den, &g);
    }
    if let Some(q) = exact_division(&num, &den) {
        return normalize(q, Poly::one());
    }
    if num.as_constant().is_none() {
        if let Some(q) = exact_division(&den, &num) {
            return normalize(Poly::one(), q);
        }
    }
    // monic denominator
    let lc = den.terms().next_back().map(|(_, c)| c.clone());
    if let Some(lc) = lc.filter(|c| !c.is_one()) {
        let inv = Quadratic::one() / &lc;
        num = num.scale(&inv);
        den = den.scale(&inv);
    }
    Param::Ratio(Box::new(Ratio { num, den }))
}

fn divide_monomial(p: &ParamPoly, g: &Letters) -> ParamPoly {
    Poly::from_terms(
        p.terms()
            .map(|(m, c)| (m.checked_div(g).unwrap_or_else(|| m.clone()), c.clone())),
    )
}

/// `p / q` when `q` divides `p` exactly (the division by leading terms in graded order leaves
/// no remainder), else `None`.
pub fn exact_division(p: &ParamPoly, q: &ParamPoly) -> Option<ParamPoly> {
    let (mq, cq) = q.terms().next_back()?;
    let (mq, cq) = (mq.clone(), cq.clone());
    let mut rest = p.clone();
    let mut quotient = ParamPoly::zero();
    loop {
        let Some((mr, cr)) = rest.terms().next_back() else {
            break;
        };
        cancel::checkpoint();
        let m = mr.checked_div(&mq)?;
        let c = cr.clone() / &cq;
        let t = ParamPoly::term(c.clone(), m.clone());
        quotient.add_term(m, &c);
        rest = rest - &t * q;
    }
    Some(quotient)
}

fn add(a: &Param, b: &Param) -> Param {
    match (a, b) {
        (Param::Const(x), Param::Const(y)) => Param::Const(x.add_ref(y)),
        (Param::Const(x), Param::Ratio(r)) | (Param::Ratio(r), Param::Const(x)) => normalize(
            &r.num + &(&r.den * &ParamPoly::constant(x.clone())),
            r.den.clone(),
        ),
        (Param::Ratio(r), Param::Ratio(s)) => {
            if r.den == s.den {
                normalize(&r.num + &s.num, r.den.clone())
            } else {
                normalize(&r.num * &s.den + &s.num * &r.den, &r.den * &s.den)
            }
        }
    }
}

fn mul(a: &Param, b: &Param) -> Param {
    match (a, b) {
        (Param::Const(x), Param::Const(y)) => Param::Const(x.mul_ref(y)),
        (Param::Const(x), Param::Ratio(r)) | (Param::Ratio(r), Param::Const(x)) => {
            if x.is_zero() {
                return Param::Const(Quadratic::zero());
            }
            Param::Ratio(Box::new(Ratio {
                num: r.num.scale(x),
                den: r.den.clone(),
            }))
        }
        (Param::Ratio(r), Param::Ratio(s)) => normalize(&r.num * &s.num, &r.den * &s.den),
    }
}

fn div(a: &Param, b: &Param) -> Option<Param> {
    if b.is_zero() {
        return None;
    }
    Some(match (a, b) {
        (Param::Const(x), Param::Const(y)) => Param::Const(x.clone() / y),
        (_, Param::Const(y)) => mul(a, &Param::Const(Quadratic::one() / y)),
        (_, Param::Ratio(s)) => {
            let (n, d) = a.parts();
            normalize(n.as_ref() * &s.den, d.as_ref() * &s.num)
        }
    })
}

fn neg(a: &Param) -> Param {
    match a {
        Param::Const(x) => Param::Const(-x.clone()),
        Param::Ratio(r) => Param::Ratio(Box::new(Ratio {
            num: -&r.num,
            den: r.den.clone(),
        })),
    }
}

impl PartialEq for Param {
    fn eq(&self, other: &Self) -> bool {
        match (self, other) {
            (Param::Const(x), Param::Const(y)) => x == y,
            (Param::Ratio(r), Param::Ratio(s)) => {
                if r.den == s.den {
                    r.num == s.num
                } else {
                    &r.num * &s.den == &s.num * &r.den
                }
            }
            _ => false,
        }
    }
}

impl PartialOrd for Param {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        match (self, other) {
            (Param::Const(x), Param::Const(y)) => x.partial_cmp(y),
            _ if self == other => Some(Ordering::Equal),
            _ => None,
        }
    }
}

impl std::fmt::Debug for Param {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Param({})", crate::print::text(self))
    }
}

impl std::fmt::Display for Param {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&crate::print::text(self))
    }
}

impl Zero for Param {
    fn zero() -> Self {
        Param::Const(Quadratic::zero())
    }
    fn is_zero(&self) -> bool {
        matches!(self, Param::Const(x) if x.is_zero())
    }
}

impl One for Param {
    fn one() -> Self {
        Param::Const(Quadratic::one())
    }
}

impl Neg for Param {
    type Output = Param;
    fn neg(self) -> Param {
        neg(&self)
    }
}

macro_rules! ops {
    ($Op:ident, $op:ident, $OpAssign:ident, $op_assign:ident, |$a:ident, $b:ident| $body:expr) => {
        impl $Op<Param> for Param {
            type Output = Param;
            fn $op(self, rhs: Param) -> Param {
                let ($a, $b) = (&self, &rhs);
                $body
            }
        }
        impl<'r> $Op<&'r Param> for Param {
            type Output = Param;
            fn $op(self, rhs: &'r Param) -> Param {
                let ($a, $b) = (&self, rhs);
                $body
            }
        }
        impl $OpAssign<Param> for Param {
            fn $op_assign(&mut self, rhs: Param) {
                let ($a, $b) = (&*self, &rhs);
                *self = $body;
            }
        }
        impl<'r> $OpAssign<&'r Param> for Param {
            fn $op_assign(&mut self, rhs: &'r Param) {
                let ($a, $b) = (&*self, rhs);
                *self = $body;
            }
        }
    };
}

ops!(Add, add, AddAssign, add_assign, |a, b| add(a, b));
ops!(Sub, sub, SubAssign, sub_assign, |a, b| add(a, &neg(b)));
ops!(Mul, mul, MulAssign, mul_assign, |a, b| mul(a, b));
// like the exact rationals, a division by zero panics; input goes through `checked_div`
#[allow(clippy::panic)]
fn div_or_panic(a: &Param, b: &Param) -> Param {
    match div(a, b) {
        Some(q) => q,
        None => panic!("cagd-param: division by zero"),
    }
}
ops!(Div, div, DivAssign, div_assign, |a, b| div_or_panic(a, b));

impl FieldOps for Param {
    fn from_i64(n: i64) -> Self {
        Param::Const(Quadratic::from_i64(n))
    }
    #[inline]
    fn from_ratio(num: i64, den: i64) -> Self {
        Param::Const(Quadratic::from_ratio(num, den))
    }
    fn checked_div(&self, rhs: &Self) -> Option<Self> {
        div(self, rhs)
    }
    fn add_ref(&self, rhs: &Self) -> Self {
        add(self, rhs)
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        add(self, &neg(rhs))
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        mul(self, rhs)
    }
}

impl ExactRational for Param {
    fn is_exact() -> bool {
        true
    }
    fn from_rational(q: &BigRational) -> Self {
        Param::Const(Quadratic::from_rational(q.clone()))
    }
    fn from_rational_owned(q: BigRational) -> Self {
        Param::Const(Quadratic::from_rational(q))
    }
    fn from_small_ratio(num: i128, den: i128) -> Self {
        Param::Const(Quadratic::from_small_ratio(num, den))
    }
    fn try_from_number(x: &Quadratic) -> Result<Self, ScalarError> {
        Ok(Param::Const(x.clone()))
    }
    /// The constant's value; `None` for a value in letters.
    fn to_number(&self) -> Option<Quadratic> {
        self.as_const().cloned()
    }
    fn as_rational(&self) -> Option<Cow<'_, BigRational>> {
        // borrowed from the constant, no clone
        ExactRational::as_rational(self.as_const()?)
    }
    #[inline]
    fn as_small_ratio(&self) -> Option<(i128, i128)> {
        // the constant's words, without building a big rational
        self.as_const()?.as_small_ratio()
    }
    /// The constant's nearest `f64`; NaN for a value in letters (figures need values).
    fn to_f64(&self) -> f64 {
        self.as_const().map_or(f64::NAN, Quadratic::to_f64)
    }
}

impl SquareRoot for Param {
    fn sqrt_exact(&self) -> Option<Self> {
        self.as_const()?.sqrt_exact().map(Param::Const)
    }
    fn sqrt_of(n: u64) -> Option<Self> {
        <Quadratic as SquareRoot>::sqrt_of(n).map(Param::Const)
    }
}
