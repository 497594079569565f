//! The parameter domain [a, b] x [c, d] of a patch, and names for its borders and corners.

use crate::SurfaceError;
use cagd_scalar::Scalar;
use std::cmp::Ordering;
use std::fmt;

/// The parameter domain [a, b] x [c, d] of a patch (notes, chapter 5, §3): the mesh is the same
/// for every domain, the parametrization is
///
/// `c̃(ũ, ṽ) = c((ũ - a)/(b - a), (ṽ - c)/(d - c))`, `ũ ∈ [a, b]`, `ṽ ∈ [c, d]`,
///
/// where `c(u, v)` is the patch on [0, 1] x [0, 1] of eq. (1). Every method of a patch takes
/// parameters of its domain and maps them to the local (u, v) ∈ [0, 1]^2 with
/// [`Domain::local`].
///
/// ```
/// use cagd_surface::Domain;
/// use cagd_scalar::{q, BigRational};
/// let d = Domain::<BigRational>::new(q!(1), q!(3), q!(0), q!(1/2)).unwrap();
/// assert_eq!(d.to_text(), "[1, 3] x [0, 1/2]");
/// let (u, v) = d.local(&q!(2), &q!(1/4));
/// assert_eq!((u, v), (q!(1/2), q!(1/2)));
/// assert_eq!(
///     d.check(&q!(4), &q!(0)).unwrap_err().to_string(),
///     "parameter u = 4 is outside the domain [1, 3] x [0, 1/2]"
/// );
/// ```
#[derive(Clone, PartialEq, Eq, Debug)]
pub struct Domain<S> {
    a: S,
    b: S,
    c: S,
    d: S,
}

impl<S: Scalar> Default for Domain<S> {
    fn default() -> Self {
        Domain::unit()
    }
}

impl<S: Scalar> Domain<S> {
    /// The unit square [0, 1] x [0, 1] of eq. (1).
    pub fn unit() -> Self {
        Domain {
            a: S::zero(),
            b: S::one(),
            c: S::zero(),
            d: S::one(),
        }
    }

    /// The rectangle [a, b] x [c, d]; an error unless a < b and c < d.
    pub fn new(a: S, b: S, c: S, d: S) -> Result<Self, SurfaceError> {
        check_interval("u", &a, &b)?;
        check_interval("v", &c, &d)?;
        Ok(Domain { a, b, c, d })
    }

    /// The interval [a, b] of u.
    pub fn u_interval(&self) -> (&S, &S) {
        (&self.a, &self.b)
    }

    /// The interval [c, d] of v.
    pub fn v_interval(&self) -> (&S, &S) {
        (&self.c, &self.d)
    }

    /// The length b - a of the interval of u.
    pub fn u_length(&self) -> S {
        self.b.sub_ref(&self.a)
    }

    /// The length d - c of the interval of v.
    pub fn v_length(&self) -> S {
        self.d.sub_ref(&self.c)
    }

    /// Whether this is [0, 1] x [0, 1].
    pub fn is_unit(&self) -> bool {
        self.a.is_zero() && self.b.is_one() && self.c.is_zero() && self.d.is_one()
    }

    /// The local parameter `(ũ - a)/(b - a)` of any ũ (no check).
    pub fn local_u(&self, u: &S) -> S {
        local(u, &self.a, &self.b)
    }

    /// The local parameter `(ṽ - c)/(d - c)` of any ṽ (no check).
    pub fn local_v(&self, v: &S) -> S {
        local(v, &self.c, &self.d)
    }

    /// The local parameters `((ũ - a)/(b - a), (ṽ - c)/(d - c))` (no check: outside the domain
    /// they extrapolate).
    pub fn local(&self, u: &S, v: &S) -> (S, S) {
        (self.local_u(u), self.local_v(v))
    }

    /// The parameter ũ = a + u (b - a) of a local u (the inverse of [`Domain::local_u`]).
    pub fn global_u(&self, u: &S) -> S {
        self.a.add_ref(&u.mul_ref(&self.u_length()))
    }

    /// The parameter ṽ = c + v (d - c) of a local v (the inverse of [`Domain::local_v`]).
    pub fn global_v(&self, v: &S) -> S {
        self.c.add_ref(&v.mul_ref(&self.v_length()))
    }

    /// Whether (ũ, ṽ) lies in the domain (borders included).
    pub fn contains(&self, u: &S, v: &S) -> bool {
        *u >= self.a && *u <= self.b && *v >= self.c && *v <= self.d
    }

    /// The local parameters of a point (ũ, ṽ) of the domain, or the error naming the
    /// parameter that lies outside.
    pub fn check(&self, u: &S, v: &S) -> Result<(S, S), SurfaceError> {
        for (param, x, lo, hi) in [("u", u, &self.a, &self.b), ("v", v, &self.c, &self.d)] {
            if x < lo || x > hi {
                return Err(SurfaceError::OutOfDomain {
                    param,
                    value: x.to_text(),
                    domain: self.to_text(),
                });
            }
        }
        Ok(self.local(u, v))
    }

    /// The domain with another interval of u (the interval of v kept).
    pub(crate) fn with_u(&self, a: S, b: S) -> Self {
        Domain {
            a,
            b,
            c: self.c.clone(),
            d: self.d.clone(),
        }
    }

    /// The domain with another interval of v (the interval of u kept).
    pub(crate) fn with_v(&self, c: S, d: S) -> Self {
        Domain {
            a: self.a.clone(),
            b: self.b.clone(),
            c,
            d,
        }
    }

    /// Plain text: `[0, 1] x [0, 1]`.
    pub fn to_text(&self) -> String {
        format!(
            "[{}, {}] x [{}, {}]",
            self.a.to_text(),
            self.b.to_text(),
            self.c.to_text(),
            self.d.to_text()
        )
    }
}

impl<S: Scalar> fmt::Display for Domain<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}

/// `(x - lo)/(hi - lo)`; the domain guarantees `lo < hi`.
fn local<S: Scalar>(x: &S, lo: &S, hi: &S) -> S {
    if lo.is_zero() && hi.is_one() {
        return x.clone();
    }
    let len = hi.sub_ref(lo);
    x.sub_ref(lo).checked_div(&len).unwrap_or_else(S::zero)
}

/// An error unless `a < b` is decided (an order that cannot be decided is an error too).
pub(crate) fn check_interval<S: Scalar>(
    param: &'static str,
    a: &S,
    b: &S,
) -> Result<(), SurfaceError> {
    if a.compare(b) == Some(Ordering::Less) {
        Ok(())
    } else {
        Err(SurfaceError::DegenerateDomain {
            param,
            a: a.to_text(),
            b: b.to_text(),
        })
    }
}

/// One of the four borders of a patch (notes, chapter 5, §3: "the border of the mesh is the
/// border of the surface").
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug)]
pub enum Border {
    /// u = 0 (ũ = a): the curve `c(0, v)`, control polygon the first row `c_{0,0}, ..., c_{0,n}`.
    U0,
    /// u = 1 (ũ = b): the curve `c(1, v)`, control polygon the last row `c_{m,0}, ..., c_{m,n}`.
    U1,
    /// v = 0 (ṽ = c): the curve `c(u, 0)`, control polygon the first column
    /// `c_{0,0}, ..., c_{m,0}`.
    V0,
    /// v = 1 (ṽ = d): the curve `c(u, 1)`, control polygon the last column
    /// `c_{0,n}, ..., c_{m,n}`.
    V1,
}

impl Border {
    /// The four borders: u = 0, u = 1, v = 0, v = 1.
    pub const ALL: [Border; 4] = [Border::U0, Border::U1, Border::V0, Border::V1];

    /// The border as the notes write it: `u = 0`, `u = 1`, `v = 0`, `v = 1`.
    pub fn name(self) -> &'static str {
        match self {
            Border::U0 => "u = 0",
            Border::U1 => "u = 1",
            Border::V0 => "v = 0",
            Border::V1 => "v = 1",
        }
    }

    /// Whether the border is a curve in v (u fixed).
    pub fn is_u(self) -> bool {
        matches!(self, Border::U0 | Border::U1)
    }
}

impl fmt::Display for Border {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// One of the four corners of a patch, where it interpolates its mesh:
/// `c(0, 0) = c_{0,0}`, `c(1, 0) = c_{m,0}`, `c(0, 1) = c_{0,n}`, `c(1, 1) = c_{m,n}`.
#[derive(Clone, Copy, PartialEq, Eq, Hash, Debug, Default)]
pub enum Corner {
    /// (u, v) = (0, 0), the vertex `c_{0,0}`.
    #[default]
    U0V0,
    /// (u, v) = (1, 0), the vertex `c_{m,0}`.
    U1V0,
    /// (u, v) = (0, 1), the vertex `c_{0,n}`.
    U0V1,
    /// (u, v) = (1, 1), the vertex `c_{m,n}`.
    U1V1,
}

impl Corner {
    /// The four corners in the notes' order: (0, 0), (1, 0), (0, 1), (1, 1).
    pub const ALL: [Corner; 4] = [Corner::U0V0, Corner::U1V0, Corner::U0V1, Corner::U1V1];

    /// Whether the corner is at u = 1 and at v = 1.
    pub fn is_end(self) -> (bool, bool) {
        match self {
            Corner::U0V0 => (false, false),
            Corner::U1V0 => (true, false),
            Corner::U0V1 => (false, true),
            Corner::U1V1 => (true, true),
        }
    }

    /// The mesh index (i, j) of the corner vertex of a patch of bidegree (m, n).
    pub fn index(self, m: usize, n: usize) -> (usize, usize) {
        let (iu, iv) = self.is_end();
        (if iu { m } else { 0 }, if iv { n } else { 0 })
    }

    /// The corner as local parameters: `(0, 0)`, `(1, 0)`, `(0, 1)`, `(1, 1)`.
    pub fn name(self) -> &'static str {
        match self {
            Corner::U0V0 => "(0, 0)",
            Corner::U1V0 => "(1, 0)",
            Corner::U0V1 => "(0, 1)",
            Corner::U1V1 => "(1, 1)",
        }
    }
}

impl fmt::Display for Corner {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}
