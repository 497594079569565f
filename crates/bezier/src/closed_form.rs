//! Closed forms: a Bézier curve as a polynomial map, a rational one as a rational map, and back.
//!
//! The change of basis Bernstein ↔ monomial is the polynomial crate's
//! ([`cagd_poly::from_bernstein_1d`], [`cagd_poly::control_polygon`]); this file only maps the
//! curves' domains and homogeneous forms onto it.

use crate::{BezierCurve, BezierError, RationalBezierCurve};
use cagd_poly::{control_polygon, from_bernstein_1d, RationalMap, Var, VecPoly};
use cagd_scalar::Scalar;

/// `Σ c_i B_i^n(u)` with `u = (var - a)/(b - a)` (no substitution on [0, 1]).
fn polynomial<S: Scalar>(
    points: &[cagd_linalg::Point<S>],
    var: Var,
    a: &S,
    b: &S,
) -> Result<VecPoly<S>, BezierError> {
    let c = from_bernstein_1d(points, var)?;
    if a.is_zero() && b.is_one() {
        Ok(c)
    } else {
        Ok(c.reparametrize_affine(var, a, b)?)
    }
}

impl<S: Scalar> BezierCurve<S> {
    /// The closed form `c(var) = Σ_{i=0}^{n} c_i B_i^n(var)` in the monomial basis (on a
    /// domain [a, b], `B_i^n((var - a)/(b - a))`).
    ///
    /// ```
    /// use cagd_bezier::BezierCurve;
    /// use cagd_linalg::Point;
    /// use cagd_poly::Var;
    /// use cagd_scalar::BigRational;
    /// let c = BezierCurve::<BigRational>::try_new(vec![
    ///     Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2]), Point::from_ints(&[3, 3]),
    /// ]).unwrap();
    /// assert_eq!(c.closed_form(Var::T).to_text(), "(t^2 + 2 t, -t^2 + 4 t)");
    /// ```
    pub fn closed_form(&self, var: Var) -> VecPoly<S> {
        let (a, b) = self.domain();
        // the polygon is validated and a < b, so the conversion cannot fail
        polynomial(self.points(), var, a, b).unwrap_or_else(|_| VecPoly::zero(self.dim()))
    }

    /// The Bézier curve of degree `degree` on [0, 1] of a polynomial map in `var`: its control
    /// points are the Bernstein coefficients of the components. An error if the map has a
    /// higher degree in `var`, uses another variable, or has no component.
    ///
    /// ```
    /// use cagd_bezier::BezierCurve;
    /// use cagd_poly::{parse_vec_poly, Var};
    /// use cagd_scalar::BigRational;
    /// let c = parse_vec_poly::<BigRational>("(t, t^2)").unwrap();
    /// let b = BezierCurve::from_closed_form(&c, Var::T, 3).unwrap();
    /// assert_eq!(b.to_text(), "(0, 0), (1/3, 0), (2/3, 1/3), (1, 1)");
    /// assert!(BezierCurve::from_closed_form(&c, Var::T, 1).is_err());
    /// ```
    pub fn from_closed_form(c: &VecPoly<S>, var: Var, degree: usize) -> Result<Self, BezierError> {
        BezierCurve::try_new(control_polygon(c, var, degree)?)
    }
}

impl<S: Scalar> RationalBezierCurve<S> {
    /// The closed form as a rational map: the homogeneous closed form `Σ (w_i c_i, w_i) B_i^n`
    /// projected, numerator `Σ w_i c_i B_i^n` over the weight polynomial `Σ w_i B_i^n`.
    ///
    /// ```
    /// use cagd_bezier::RationalBezierCurve;
    /// use cagd_linalg::Point;
    /// use cagd_poly::Var;
    /// use cagd_scalar::{q, BigRational};
    /// let c = RationalBezierCurve::<BigRational>::try_new(
    ///     vec![Point::from_ints(&[1, 0]), Point::from_ints(&[1, 1]), Point::from_ints(&[0, 1])],
    ///     vec![q!(1), q!(1), q!(2)],
    /// ).unwrap();
    /// // the quarter circle of the tangent half-angle substitution
    /// assert_eq!(c.closed_form(Var::T).to_text(), "(-t^2 + 1, 2 t) / (t^2 + 1)");
    /// ```
    pub fn closed_form(&self, var: Var) -> RationalMap<S> {
        let (a, b) = self.domain();
        let h = polynomial(&self.homogeneous(), var, a, b)
            .unwrap_or_else(|_| VecPoly::zero(self.dim() + 1));
        // weights not all zero make a nonzero weight polynomial (the B_i^n are independent)
        RationalMap::from_homogeneous(&h)
            .unwrap_or_else(|_| RationalMap::from_polynomial(VecPoly::zero(self.dim())))
    }

    /// The first derivative as a rational map, by the quotient rule on the closed form:
    /// `c' = (N' D - N D') / D^2` with `c = N / D` from [`RationalBezierCurve::closed_form`].
    pub fn derivative_closed_form(&self, var: Var) -> RationalMap<S> {
        self.closed_form(var).partial(var)
    }

    /// The rational Bézier curve of degree `degree` on [0, 1] of a rational map: the Bernstein
    /// coefficients of its homogeneous form `(N, D)`, projected. An error if the degree is too
    /// high, another variable occurs, or every weight comes out zero (a zero weight is a
    /// control vector).
    ///
    /// ```
    /// use cagd_bezier::RationalBezierCurve;
    /// use cagd_poly::{parse_vec_poly, RationalMap, Var};
    /// use cagd_scalar::BigRational;
    /// let h = parse_vec_poly::<BigRational>("(1 - t^2, 2 t, 1 + t^2)").unwrap();
    /// let map = RationalMap::from_homogeneous(&h).unwrap();
    /// let c = RationalBezierCurve::from_closed_form(&map, Var::T, 2).unwrap();
    /// assert_eq!(c.to_text(), "(1, 0) w = 1; (1, 1) w = 1; (0, 1) w = 2");
    /// ```
    pub fn from_closed_form(
        c: &RationalMap<S>,
        var: Var,
        degree: usize,
    ) -> Result<Self, BezierError> {
        let h = control_polygon(&c.to_homogeneous(), var, degree)?;
        RationalBezierCurve::from_homogeneous(&h)
    }
}
