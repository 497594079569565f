//! `Poly<S, M>`: sparse multivariate polynomials and their ring operations.
//!
//! The ring operations are generic over the monomial type ([`Term`]): [`Monomial`], the
//! exponents of the curve and surface variables `u, v, w, t, s, x, y, z` (the default), and
//! any other set of exponents, such as the named parameters `R, a, b, c_{1,0}` of a problem in
//! letters (cagd-param). Calculus, substitution, parsing and printing are for [`Monomial`].

use crate::terms::Terms;
use crate::{Monomial, PolyError, Unconvertible, Var};
use cagd_scalar::Scalar;
use std::cmp::Ordering;
use std::collections::BTreeMap;
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};

/// A polynomial in the variables `u, v, w, t, s, x, y, z` with coefficients in `S`.
///
/// Stored sparsely, monomial → coefficient, never holding a zero coefficient, so `==` is exact
/// structural equality: two polynomials are equal exactly when they have the same terms.
///
/// ```
/// use cagd_poly::{Poly, Var};
/// use cagd_scalar::BigRational;
/// let u = Poly::<BigRational>::var(Var::U);
/// let v = Poly::var(Var::V);
/// let one = Poly::one();
/// // (1 - v) u^3 + v u^2, the third coordinate of the ruled example of chapter 6
/// let z = (&one - &v) * u.pow(3) + &v * u.pow(2);
/// assert_eq!(z.to_text(), "-u^3 v + u^3 + u^2 v");
/// assert_eq!(z.degree(), 4);
/// assert_eq!(z.degree_in(Var::V), 1);
/// ```
#[derive(Clone, PartialEq)]
pub struct Poly<S, M = Monomial> {
    pub(crate) terms: Terms<M, S>,
}

/// The exponents of one term of a [`Poly`]: a commutative monoid (`1`, products) with a total
/// degree, ordered so that the order refines the total degree (graded orders).
///
/// [`Monomial`] is the monomial of the variables `u, v, ...`; cagd-param implements it for
/// products of named parameters.
pub trait Term: Clone + Ord + fmt::Debug + Send + Sync + 'static {
    /// The monomial `1`.
    fn one() -> Self;
    /// Whether this is `1`.
    fn is_one(&self) -> bool;
    /// The product (exponents add).
    fn mul(&self, other: &Self) -> Self;
    /// `self / other` when `other` divides `self`, else `None`.
    fn checked_div(&self, other: &Self) -> Option<Self>;
    /// The total degree.
    fn degree(&self) -> u32;
    /// A faster product of two polynomials, when the monomial type has one (`None`: the
    /// schoolbook product runs).
    fn fast_product<S: Scalar>(a: &Poly<S, Self>, b: &Poly<S, Self>) -> Option<Poly<S, Self>> {
        let _ = (a, b);
        None
    }
}

impl Term for Monomial {
    fn one() -> Self {
        Monomial::one()
    }
    fn is_one(&self) -> bool {
        Monomial::is_one(self)
    }
    fn mul(&self, other: &Self) -> Self {
        Monomial::mul(self, other)
    }
    fn checked_div(&self, other: &Self) -> Option<Self> {
        Monomial::checked_div(self, other)
    }
    fn degree(&self) -> u32 {
        Monomial::degree(self)
    }
    fn fast_product<S: Scalar>(a: &Poly<S>, b: &Poly<S>) -> Option<Poly<S>> {
        crate::fast::product(a, b)
    }
}

impl<S: Scalar + Eq, M: Term> Eq for Poly<S, M> {}

impl<S: Scalar, M: Term> Default for Poly<S, M> {
    fn default() -> Self {
        Poly::zero()
    }
}

impl<S: Scalar, M: Term> Poly<S, M> {
    /// The zero polynomial.
    pub fn zero() -> Self {
        Poly {
            terms: Terms::new(),
        }
    }

    /// The constant polynomial `1`.
    pub fn one() -> Self {
        Poly::constant(S::one())
    }

    /// The constant polynomial `c`.
    pub fn constant(c: S) -> Self {
        Poly::term(c, M::one())
    }

    /// The single term `c · m` (the zero polynomial when `c = 0`).
    pub fn term(c: S, m: M) -> Self {
        let terms = if c.is_zero() {
            Vec::new()
        } else {
            vec![(m, c)]
        };
        Poly {
            terms: Terms::from_sorted(terms),
        }
    }

    /// The sum of the given terms (repeated monomials add up; zeros are dropped).
    pub fn from_terms(terms: impl IntoIterator<Item = (M, S)>) -> Self {
        // sorted, like terms merged, zeros dropped: the run is the terms
        let mut terms: Vec<(M, S)> = terms.into_iter().collect();
        terms.sort_by(|a, b| a.0.cmp(&b.0));
        let mut merged: Vec<(M, S)> = Vec::with_capacity(terms.len());
        for (m, c) in terms {
            match merged.last_mut() {
                Some((last, sum)) if *last == m => *sum += &c,
                _ => {
                    if merged.last().is_some_and(|(_, sum)| sum.is_zero()) {
                        merged.pop();
                    }
                    merged.push((m, c));
                }
            }
        }
        if merged.last().is_some_and(|(_, sum)| sum.is_zero()) {
            merged.pop();
        }
        Poly {
            terms: Terms::from_sorted(merged),
        }
    }

    /// The polynomial of terms already in increasing monomial order, with distinct monomials
    /// and no zero coefficient (the fast paths build their terms so): taken as they are, with
    /// no sort or merge (both checked in debug builds).
    pub(crate) fn from_ordered_terms(terms: Vec<(M, S)>) -> Self {
        debug_assert!(terms.iter().all(|(_, c)| !c.is_zero()));
        Poly {
            terms: Terms::from_sorted(terms),
        }
    }

    /// `self += c · m`, keeping no zero coefficient.
    pub fn add_term(&mut self, m: M, c: &S) {
        if c.is_zero() {
            return;
        }
        match self.terms.get_mut(&m) {
            Some(a) => {
                *a += c;
                if a.is_zero() {
                    self.terms.remove(&m);
                }
            }
            None => {
                self.terms.insert(m, c.clone());
            }
        }
    }

    /// The terms in increasing monomial order (graded lexicographic, see [`Monomial`]); the
    /// printers list them in reverse.
    pub fn terms(&self) -> impl DoubleEndedIterator<Item = (&M, &S)> + '_ {
        self.terms.iter()
    }

    /// The number of (nonzero) terms.
    pub fn num_terms(&self) -> usize {
        self.terms.len()
    }

    /// The coefficient of the monomial `m` (zero when absent).
    pub fn coeff(&self, m: &M) -> S {
        self.terms.get(m).cloned().unwrap_or_else(S::zero)
    }

    /// Whether this is the zero polynomial (exact: no term is stored).
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// The value when the polynomial is a constant (`Some(0)` for the zero polynomial), `None`
    /// when it depends on a variable.
    pub fn as_constant(&self) -> Option<S> {
        match self.terms.last() {
            None => Some(S::zero()),
            Some((m, c)) if Term::is_one(m) => Some(c.clone()),
            Some(_) => None,
        }
    }

    /// The total degree (the largest total degree of a term); 0 for constants, and also for the
    /// zero polynomial (whose degree is conventionally −∞).
    pub fn degree(&self) -> u32 {
        // graded order: the last monomial has the largest total degree
        self.terms.keys().next_back().map_or(0, Term::degree)
    }

    /// `c · self`.
    pub fn scale(&self, c: &S) -> Self {
        if c.is_zero() {
            return Poly::zero();
        }
        Poly::from_terms(self.terms.iter().map(|(m, a)| (m.clone(), a.mul_ref(c))))
    }

    /// `self^n`, by repeated squaring (`p^0 = 1`).
    pub fn pow(&self, n: u32) -> Self {
        let mut acc = Poly::one();
        let mut base = self.clone();
        let mut n = n;
        while n > 0 {
            if n & 1 == 1 {
                acc = &acc * &base;
            }
            n >>= 1;
            if n > 0 {
                base = &base * &base;
            }
        }
        acc
    }

    /// The polynomial with every coefficient mapped by `f` (terms mapped to zero are dropped).
    pub fn map_coeffs<T: Scalar>(&self, mut f: impl FnMut(&S) -> T) -> Poly<T, M> {
        // the monomials stay distinct and in order: no sort or merge, only zeros dropped
        Poly {
            terms: Terms::from_sorted(
                self.terms
                    .iter()
                    .filter_map(|(m, c)| {
                        let t = f(c);
                        (!t.is_zero()).then(|| (m.clone(), t))
                    })
                    .collect(),
            ),
        }
    }

    /// Like [`Poly::map_coeffs`] with a fallible map: the first error is returned.
    pub fn try_map_coeffs<T: Scalar, E>(
        &self,
        mut f: impl FnMut(&S) -> Result<T, E>,
    ) -> Result<Poly<T, M>, E> {
        let mut p = Poly::zero();
        for (m, c) in &self.terms {
            p.add_term(m.clone(), &f(c)?);
        }
        Ok(p)
    }

    /// The same polynomial over another number type, exactly: each coefficient goes through
    /// [`ExactRational::to_number`](cagd_scalar::ExactRational::to_number) and
    /// [`ExactRational::try_from_number`](cagd_scalar::ExactRational::try_from_number). Fails
    /// when a coefficient has a root the target cannot hold (`√2` into `BigRational`) or when
    /// `S` is not exact (`f64`).
    ///
    /// ```
    /// use cagd_poly::parse_poly;
    /// use cagd_scalar::{BigRational, Quadratic};
    /// let p = parse_poly::<Quadratic>("u/2 + 1").unwrap();
    /// assert_eq!(p.convert::<BigRational>().unwrap().to_text(), "1/2 u + 1");
    /// let r = parse_poly::<Quadratic>("sqrt2 u").unwrap();
    /// assert!(r.convert::<BigRational>().is_err());
    /// ```
    pub fn convert<T: Scalar>(&self) -> Result<Poly<T, M>, PolyError> {
        self.try_map_coeffs(|c| {
            let x = c.to_number().ok_or_else(|| PolyError::Conversion {
                value: c.to_text(),
                reason: Unconvertible::NotExact,
            })?;
            T::try_from_number(&x).map_err(|e| PolyError::Conversion {
                value: c.to_text(),
                reason: Unconvertible::Scalar(e),
            })
        })
    }

    fn add_poly(self, rhs: &Self) -> Self {
        self.merge(rhs, false)
    }

    fn sub_poly(self, rhs: &Self) -> Self {
        self.merge(rhs, true)
    }

    /// `self + rhs` (`self − rhs` when `subtract`): the two runs of terms merged in order,
    /// like monomials' coefficients added and zeros dropped, in one pass.
    fn merge(self, rhs: &Self, subtract: bool) -> Self {
        cagd_scalar::cancel::checkpoint();
        let theirs = |c: &S| if subtract { -c.clone() } else { c.clone() };
        let mut out: Vec<(M, S)> = Vec::with_capacity(self.terms.len() + rhs.terms.len());
        let mut ours = self.terms.into_iter().peekable();
        let mut other = rhs.terms.iter().peekable();
        loop {
            let order = match (ours.peek(), other.peek()) {
                (Some((a, _)), Some((b, _))) => a.cmp(b),
                (Some(_), None) => Ordering::Less,
                (None, Some(_)) => Ordering::Greater,
                (None, None) => break,
            };
            match order {
                Ordering::Less => out.extend(ours.next()),
                Ordering::Greater => out.extend(other.next().map(|(m, c)| (m.clone(), theirs(c)))),
                Ordering::Equal => {
                    if let (Some((m, mut a)), Some((_, b))) = (ours.next(), other.next()) {
                        if subtract {
                            a -= b;
                        } else {
                            a += b;
                        }
                        if !a.is_zero() {
                            out.push((m, a));
                        }
                    }
                }
            }
        }
        Poly {
            terms: Terms::from_sorted(out),
        }
    }

    fn mul_poly(&self, rhs: &Self) -> Self {
        if let Some(product) = M::fast_product(self, rhs) {
            return product;
        }
        let mut out: BTreeMap<M, S> = BTreeMap::new();
        for (ma, a) in &self.terms {
            cagd_scalar::cancel::checkpoint();
            for (mb, b) in &rhs.terms {
                let m = Term::mul(ma, mb);
                let ab = a.mul_ref(b);
                match out.get_mut(&m) {
                    Some(c) => *c += ab,
                    None => {
                        out.insert(m, ab);
                    }
                }
            }
        }
        out.retain(|_, c| !c.is_zero());
        Poly {
            terms: Terms::from_sorted(out.into_iter().collect()),
        }
    }
}

impl<S: Scalar> Poly<S> {
    /// The polynomial `var`.
    pub fn var(var: Var) -> Self {
        Poly::term(S::one(), Monomial::var(var))
    }

    /// The term `c · Π var^e`, e.g. `Poly::monomial(q!(3), &[(Var::U, 2), (Var::V, 1)])` is
    /// `3 u^2 v`.
    pub fn monomial(c: S, powers: &[(Var, u32)]) -> Self {
        Poly::term(c, Monomial::from_powers(powers))
    }

    /// The degree in one variable (0 when the variable does not occur).
    pub fn degree_in(&self, var: Var) -> u32 {
        self.terms.keys().map(|m| m.exp(var)).max().unwrap_or(0)
    }

    /// The variables that occur, in canonical order.
    pub fn vars(&self) -> Vec<Var> {
        Monomial::vars_of(self.support())
    }

    /// The variables that occur, as bits ([`Monomial::support`] of every term).
    pub(crate) fn support(&self) -> u8 {
        self.terms.keys().fold(0, |bits, m| bits | m.support())
    }
}

impl<S: Scalar, M: Term> From<S> for Poly<S, M> {
    fn from(c: S) -> Self {
        Poly::constant(c)
    }
}

impl<S: Scalar, M: Term> Neg for Poly<S, M> {
    type Output = Poly<S, M>;
    fn neg(mut self) -> Poly<S, M> {
        for c in self.terms.values_mut() {
            *c = -c.clone();
        }
        self
    }
}

impl<S: Scalar, M: Term> Neg for &Poly<S, M> {
    type Output = Poly<S, M>;
    fn neg(self) -> Poly<S, M> {
        -self.clone()
    }
}

/// The by-value and by-reference forms of `+`, `-`, `*` on polynomials.
macro_rules! forward_ops {
    ($Op:ident, $op:ident, |$a:ident, $b:ident| $owned:expr, |$ra:ident, $rb:ident| $borrowed:expr) => {
        impl<S: Scalar, M: Term> $Op<Poly<S, M>> for Poly<S, M> {
            type Output = Poly<S, M>;
            fn $op(self, rhs: Poly<S, M>) -> Poly<S, M> {
                let ($a, $b) = (self, &rhs);
                $owned
            }
        }
        impl<'a, S: Scalar, M: Term> $Op<&'a Poly<S, M>> for Poly<S, M> {
            type Output = Poly<S, M>;
            fn $op(self, rhs: &'a Poly<S, M>) -> Poly<S, M> {
                let ($a, $b) = (self, rhs);
                $owned
            }
        }
        impl<'a, 'b, S: Scalar, M: Term> $Op<&'b Poly<S, M>> for &'a Poly<S, M> {
            type Output = Poly<S, M>;
            fn $op(self, rhs: &'b Poly<S, M>) -> Poly<S, M> {
                let ($ra, $rb) = (self, rhs);
                $borrowed
            }
        }
        impl<'a, S: Scalar, M: Term> $Op<Poly<S, M>> for &'a Poly<S, M> {
            type Output = Poly<S, M>;
            fn $op(self, rhs: Poly<S, M>) -> Poly<S, M> {
                let ($ra, $rb) = (self, &rhs);
                $borrowed
            }
        }
    };
}

// (Σ a_m x^m) + (Σ b_m x^m) = Σ (a_m + b_m) x^m
forward_ops!(Add, add, |a, b| a.add_poly(b), |a, b| a.clone().add_poly(b));
// (Σ a_m x^m) - (Σ b_m x^m) = Σ (a_m - b_m) x^m
forward_ops!(Sub, sub, |a, b| a.sub_poly(b), |a, b| a.clone().sub_poly(b));
// (Σ a_m x^m)(Σ b_n x^n) = Σ_k (Σ_{m+n=k} a_m b_n) x^k
forward_ops!(Mul, mul, |a, b| a.mul_poly(b), |a, b| a.mul_poly(b));

impl<S: Scalar> fmt::Display for Poly<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}

impl<S: Scalar> fmt::Debug for Poly<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Poly({})", self.to_text())
    }
}
