//! `RationalMap<S>`: a vector of polynomials over one common scalar denominator (rational
//! curves and surfaces).

use crate::{Poly, PolyError, Var, VecPoly};
use cagd_linalg::Point;
use cagd_scalar::Scalar;
use std::fmt;

/// A rational map `N(u, v, ...) / D(u, v, ...)`, with a vector numerator and a common scalar
/// denominator that is not the zero polynomial: the projection of a homogeneous polynomial map
/// `(w x, w y, w z, w)` (weight last, as [`Point::to_homogeneous`]).
///
/// ```
/// use cagd_poly::{parse_vec_poly, RationalMap, Var};
/// use cagd_scalar::{q, BigRational};
/// // the quarter circle (1 - t^2, 2t) / (1 + t^2) from its homogeneous form
/// let h = parse_vec_poly::<BigRational>("(1 - t^2, 2 t, 1 + t^2)").unwrap();
/// let c = RationalMap::from_homogeneous(&h).unwrap();
/// assert_eq!(c.eval(&[(Var::T, q!(1/2))]).unwrap().to_text(), "(3/5, 4/5)");
/// assert_eq!(c.to_text(), "(-t^2 + 1, 2 t) / (t^2 + 1)");
/// ```
#[derive(Clone, PartialEq)]
pub struct RationalMap<S> {
    numer: VecPoly<S>,
    denom: Poly<S>,
}

impl<S: Scalar> RationalMap<S> {
    /// The map `numer / denom`; fails when `denom` is the zero polynomial.
    pub fn new(numer: VecPoly<S>, denom: Poly<S>) -> Result<Self, PolyError> {
        if denom.is_zero() {
            return Err(PolyError::ZeroDenominator {
                at: "everywhere: it is the zero polynomial".into(),
            });
        }
        Ok(RationalMap { numer, denom })
    }

    /// The polynomial map `c` as a rational map with denominator 1.
    pub fn from_polynomial(c: VecPoly<S>) -> Self {
        RationalMap {
            numer: c,
            denom: Poly::one(),
        }
    }

    /// The projection of a homogeneous map `(X_1, ..., X_d, W)` of R^{d+1} (weight last):
    /// `(X_1, ..., X_d) / W`. Fails when there is no component or `W` is zero.
    pub fn from_homogeneous(h: &VecPoly<S>) -> Result<Self, PolyError> {
        let Some((w, xs)) = h.components().split_last() else {
            return Err(PolyError::Empty {
                what: "the homogeneous map".into(),
            });
        };
        RationalMap::new(VecPoly::new(xs.to_vec()), w.clone())
    }

    /// The homogeneous map `(N_1, ..., N_d, D)` (weight last).
    pub fn to_homogeneous(&self) -> VecPoly<S> {
        let mut comps = self.numer.components().to_vec();
        comps.push(self.denom.clone());
        VecPoly::new(comps)
    }

    /// The numerator.
    pub fn numerator(&self) -> &VecPoly<S> {
        &self.numer
    }

    /// The denominator.
    pub fn denominator(&self) -> &Poly<S> {
        &self.denom
    }

    /// The dimension of the points.
    pub fn dim(&self) -> usize {
        self.numer.dim()
    }

    /// The point `N(point) / D(point)`; fails where the denominator vanishes.
    pub fn eval(&self, point: &[(Var, S)]) -> Result<Point<S>, PolyError> {
        let d = self.denom.eval(point)?;
        let n = self.numer.eval(point)?;
        let at = || {
            let parts: Vec<String> = point
                .iter()
                .map(|(v, x)| format!("{v} = {}", x.to_text()))
                .collect();
            format!("at ({})", parts.join(", "))
        };
        let coords = n
            .coords()
            .iter()
            .map(|x| {
                x.checked_div(&d)
                    .ok_or_else(|| PolyError::ZeroDenominator { at: at() })
            })
            .collect::<Result<Vec<S>, _>>()?;
        if coords.is_empty() && d.is_zero() {
            return Err(PolyError::ZeroDenominator { at: at() });
        }
        Ok(Point::new(coords))
    }

    /// The partial derivative by the quotient rule, `(N' D - N D') / D^2` (not reduced).
    pub fn partial(&self, var: Var) -> Self {
        let dn = self.numer.partial(var);
        let dd = self.denom.partial(var);
        let top = VecPoly::new(
            dn.components()
                .iter()
                .zip(self.numer.components())
                .map(|(dni, ni)| dni * &self.denom - ni * &dd)
                .collect(),
        );
        RationalMap {
            numer: top,
            denom: &self.denom * &self.denom,
        }
    }

    /// Plain text: `(N_1, ..., N_d) / (D)`, or the numerator alone when `D = 1`.
    pub fn to_text(&self) -> String {
        if self.denom == Poly::one() {
            self.numer.to_text()
        } else {
            format!("{} / ({})", self.numer.to_text(), self.denom.to_text())
        }
    }

    /// LaTeX: `\frac{1}{D} \left(N_1, ..., N_d\right)`, or the numerator alone when `D = 1`.
    pub fn to_latex(&self) -> String {
        if self.denom == Poly::one() {
            self.numer.to_latex()
        } else {
            format!(
                "\\frac{{1}}{{{}}} {}",
                self.denom.to_latex(),
                self.numer.to_latex()
            )
        }
    }
}

impl<S: Scalar> fmt::Display for RationalMap<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}

impl<S: Scalar> fmt::Debug for RationalMap<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "RationalMap({})", self.to_text())
    }
}
