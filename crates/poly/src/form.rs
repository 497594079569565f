//! The closed form of a piece of a curve or a surface: a polynomial map, or a rational map
//! (numerator over a common denominator), with its derivatives, its restriction to a line, and
//! the order of contact of two pieces across the line where they meet (the notes' continuity
//! conditions (21)-(23) read on the closed forms).

use crate::{Poly, RationalMap, Var, VecPoly};
use cagd_scalar::Scalar;

/// The closed form of one piece: a polynomial or a rational map (in t for a curve, in u and v
/// for a surface).
#[derive(Debug, Clone, PartialEq)]
pub enum ClosedForm<S: Scalar> {
    /// A polynomial map (Bézier and B-spline pieces).
    Polynomial(VecPoly<S>),
    /// A rational map (rational Bézier and NURBS pieces).
    Rational(RationalMap<S>),
}

impl<S: Scalar> ClosedForm<S> {
    /// `∂^{r+s}/∂u^r ∂v^s` of the form (for a rational map the quotient rule, written over
    /// `w^{r+s+1}`).
    ///
    /// ```
    /// use cagd_poly::{parse_vec_poly, ClosedForm};
    /// use cagd_scalar::BigRational;
    /// let f = ClosedForm::Polynomial(parse_vec_poly::<BigRational>("(u^2 v, v)").unwrap());
    /// assert_eq!(f.partial(1, 1), ClosedForm::Polynomial(parse_vec_poly("(2 u, 0)").unwrap()));
    /// ```
    pub fn partial(&self, r: usize, s: usize) -> Self {
        self.mixed(Var::U, r, Var::V, s)
    }

    /// The r-th derivative in `var` (a curve's t).
    pub fn derivative_in(&self, var: Var, r: usize) -> Self {
        self.mixed(var, r, Var::U, 0)
    }

    /// `∂^{r+s}/∂x^r ∂y^s`.
    fn mixed(&self, x: Var, r: usize, y: Var, s: usize) -> Self {
        match self {
            ClosedForm::Polynomial(m) => {
                let mut d = m.clone();
                for var in std::iter::repeat_n(x, r).chain(std::iter::repeat_n(y, s)) {
                    if d.is_zero() {
                        break;
                    }
                    d = d.partial(var);
                }
                ClosedForm::Polynomial(d)
            }
            ClosedForm::Rational(f) => ClosedForm::Rational(f.mixed_partial(x, r, y, s)),
        }
    }

    /// The form with `var` = x; `None` where a denominator vanishes identically there.
    pub fn substitute(&self, var: Var, x: &S) -> Option<Self> {
        match self {
            ClosedForm::Polynomial(m) => Some(ClosedForm::Polynomial(m.substitute_value(var, x))),
            ClosedForm::Rational(f) => {
                let numer = f.numerator().substitute_value(var, x);
                let denom = f.denominator().substitute_value(var, x);
                RationalMap::new(numer, denom)
                    .ok()
                    .map(ClosedForm::Rational)
            }
        }
    }

    /// Exact equality of two forms as maps (`p/q = r/s` when `p s = r q`).
    pub fn same(&self, other: &Self) -> bool {
        match (self, other) {
            (ClosedForm::Polynomial(a), ClosedForm::Polynomial(b)) => a == b,
            _ => {
                let (na, da) = self.parts();
                let (nb, db) = other.parts();
                na.mul_poly(&db) == nb.mul_poly(&da)
            }
        }
    }

    /// The numerator and the denominator (1 for a polynomial map).
    pub fn parts(&self) -> (VecPoly<S>, Poly<S>) {
        match self {
            ClosedForm::Polynomial(m) => (m.clone(), Poly::one()),
            ClosedForm::Rational(f) => (f.numerator().clone(), f.denominator().clone()),
        }
    }

    /// The form with `var` replaced by `var - delta`: the piece moved by `delta` along `var`.
    pub fn shifted(&self, var: Var, delta: &S) -> Self {
        let minus = -delta.clone();
        match self {
            ClosedForm::Polynomial(m) => {
                ClosedForm::Polynomial(m.affine_substitute(var, &S::one(), &minus))
            }
            ClosedForm::Rational(f) => {
                let numer = f.numerator().affine_substitute(var, &S::one(), &minus);
                let denom = f.denominator().affine_substitute(var, &S::one(), &minus);
                RationalMap::new(numer, denom).map_or_else(|_| self.clone(), ClosedForm::Rational)
            }
        }
    }
}

/// The order of contact of pairs of pieces across the line `var` = ξ: the highest r such that
/// the derivatives `∂^k/∂var^k`, k = 0..=r, of the two forms of every pair agree on the line
/// (the notes' (21)-(23) on the closed forms); `None` (C^∞: the pieces are one map) when they
/// agree up to `top`, past which agreement means identity; `Some(-1)` when not even the values
/// agree. `var` is U or V.
///
/// ```
/// use cagd_poly::{contact_order, parse_vec_poly, ClosedForm, Var};
/// use cagd_scalar::{q, BigRational};
/// let f = |s: &str| ClosedForm::Polynomial(parse_vec_poly::<BigRational>(s).unwrap());
/// // u² and 2u - 1 meet at u = 1 with the same value and slope, not the same curvature: C¹
/// let pair = (f("(u^2, v)"), f("(2 u - 1, v)"));
/// assert_eq!(contact_order(&[pair], Var::U, &q!(1), 2), Some(1));
/// ```
pub fn contact_order<S: Scalar>(
    pairs: &[(ClosedForm<S>, ClosedForm<S>)],
    var: Var,
    xi: &S,
    top: usize,
) -> Option<isize> {
    for k in 0..=top {
        for (left, right) in pairs {
            let d = |f: &ClosedForm<S>| {
                let f = if var == Var::U {
                    f.partial(k, 0)
                } else {
                    f.partial(0, k)
                };
                f.substitute(var, xi)
            };
            let agree = match (d(left), d(right)) {
                (Some(a), Some(b)) => a.same(&b),
                _ => false,
            };
            if !agree {
                return Some(isize::try_from(k).unwrap_or(isize::MAX) - 1);
            }
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{parse_poly, parse_vec_poly};
    use cagd_scalar::{q, BigRational};

    fn poly_form(s: &str) -> ClosedForm<BigRational> {
        ClosedForm::Polynomial(parse_vec_poly(s).unwrap())
    }

    fn rational(n: &str, d: &str) -> ClosedForm<BigRational> {
        ClosedForm::Rational(
            RationalMap::new(parse_vec_poly(n).unwrap(), parse_poly(d).unwrap()).unwrap(),
        )
    }

    #[test]
    fn derivatives_and_lines() {
        let f = poly_form("(u^3, u v^2)");
        assert_eq!(f.partial(2, 0), poly_form("(6 u, 0)"));
        assert_eq!(f.partial(1, 2), poly_form("(0, 2)"));
        assert_eq!(f.substitute(Var::U, &q!(2)), Some(poly_form("(8, 2 v^2)")));
        assert_eq!(
            poly_form("(t^2, t)").derivative_in(Var::T, 1),
            poly_form("(2 t, 1)")
        );
        // (u - 1)² moved by 1: u²
        assert_eq!(
            poly_form("(u^2 - 2 u + 1, v)").shifted(Var::U, &q!(-1)),
            poly_form("(u^2, v)")
        );
    }

    #[test]
    fn rational_forms_compared_as_maps() {
        // (2u, 2v)/2 is the map (u, v)
        assert!(rational("(2 u, 2 v)", "2").same(&poly_form("(u, v)")));
        assert!(!rational("(u, v)", "1 + u").same(&poly_form("(u, v)")));
        // 1/(u - 1) at u = 1 has no value
        assert_eq!(rational("(1, v)", "u - 1").substitute(Var::U, &q!(1)), None);
    }

    #[test]
    fn contact_of_pieces() {
        let same = (poly_form("(u, v u)"), poly_form("(u, v u)"));
        assert_eq!(contact_order(&[same], Var::U, &q!(1), 1), None);
        let jump = (poly_form("(u, v)"), poly_form("(u + 1, v)"));
        assert_eq!(contact_order(&[jump], Var::U, &q!(0), 1), Some(-1));
        // across v = 0: v² and 0 agree in value and first derivative
        let c1 = (poly_form("(u, v^2)"), poly_form("(u, 0)"));
        assert_eq!(contact_order(&[c1], Var::V, &q!(0), 2), Some(1));
    }
}
