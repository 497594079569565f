//! `VecPoly<S>`: polynomial maps into R^d (curves, surfaces, homogeneous R^4).

use crate::{Operands, Poly, PolyError, Var};
use cagd_linalg::Point;
use cagd_scalar::Scalar;
use std::fmt;
use std::ops::Neg;

/// A vector-valued polynomial map `(p_1, ..., p_d)`: a polynomial curve or surface in R^2,
/// R^3, or a homogeneous one in R^4 (weight last, as [`Point::to_homogeneous`]).
///
/// ```
/// use cagd_poly::{parse_vec_poly, Var};
/// use cagd_scalar::{q, BigRational};
/// let c = parse_vec_poly::<BigRational>("(1 - v)*(u, 0, u^3) + v*(u, 1, u^2)").unwrap();
/// assert_eq!(c.to_text(), "(u, v, -u^3 v + u^3 + u^2 v)");
/// let p = c.eval(&[(Var::U, q!(1/2)), (Var::V, q!(1/2))]).unwrap();
/// assert_eq!(p.to_text(), "(1/2, 1/2, 3/16)");
/// ```
#[derive(Clone, PartialEq)]
pub struct VecPoly<S> {
    comps: Vec<Poly<S>>,
}

impl<S: Scalar + Eq> Eq for VecPoly<S> {}

impl<S: Scalar> VecPoly<S> {
    /// The map with these components.
    pub fn new(comps: Vec<Poly<S>>) -> Self {
        VecPoly { comps }
    }

    /// The zero map into R^dim.
    pub fn zero(dim: usize) -> Self {
        VecPoly::new(vec![Poly::zero(); dim])
    }

    /// The constant map with value `p`.
    pub fn constant(p: &Point<S>) -> Self {
        VecPoly::new(p.coords().iter().cloned().map(Poly::constant).collect())
    }

    /// The number of components.
    pub fn dim(&self) -> usize {
        self.comps.len()
    }

    /// The components.
    pub fn components(&self) -> &[Poly<S>] {
        &self.comps
    }

    /// The components, consuming the map.
    pub fn into_components(self) -> Vec<Poly<S>> {
        self.comps
    }

    /// The component `i` (from 0), if there is one.
    pub fn component(&self, i: usize) -> Option<&Poly<S>> {
        self.comps.get(i)
    }

    /// Every component is the zero polynomial (exact).
    pub fn is_zero(&self) -> bool {
        self.comps.iter().all(Poly::is_zero)
    }

    /// The largest total degree of a component.
    pub fn degree(&self) -> u32 {
        self.comps.iter().map(Poly::degree).max().unwrap_or(0)
    }

    /// The largest degree of a component in `var`.
    pub fn degree_in(&self, var: Var) -> u32 {
        self.comps
            .iter()
            .map(|p| p.degree_in(var))
            .max()
            .unwrap_or(0)
    }

    /// The variables that occur in some component, in canonical order.
    pub fn vars(&self) -> Vec<Var> {
        crate::Monomial::vars_of(self.comps.iter().fold(0, |bits, p| bits | p.support()))
    }

    fn same_dim(&self, other: &Self, what: Operands) -> Result<(), PolyError> {
        if self.dim() == other.dim() {
            Ok(())
        } else {
            Err(PolyError::DimensionMismatch {
                what,
                expected: self.dim(),
                found: other.dim(),
            })
        }
    }

    /// `self + other`, componentwise; an error when the dimensions differ.
    pub fn checked_add(&self, other: &Self) -> Result<Self, PolyError> {
        self.same_dim(other, Operands::Adding)?;
        Ok(self.zip(other, |a, b| a + b))
    }

    /// `self - other`, componentwise; an error when the dimensions differ.
    pub fn checked_sub(&self, other: &Self) -> Result<Self, PolyError> {
        self.same_dim(other, Operands::Subtracting)?;
        Ok(self.zip(other, |a, b| a - b))
    }

    fn zip(&self, other: &Self, f: impl Fn(&Poly<S>, &Poly<S>) -> Poly<S>) -> Self {
        VecPoly::new(
            self.comps
                .iter()
                .zip(&other.comps)
                .map(|(a, b)| f(a, b))
                .collect(),
        )
    }

    /// The product `f · self` by a scalar polynomial `f` (as `(1 - v) c1(u)` in a ruled surface).
    pub fn mul_poly(&self, f: &Poly<S>) -> Self {
        VecPoly::new(self.comps.iter().map(|p| p * f).collect())
    }

    /// `c · self` for a constant `c`.
    pub fn scale(&self, c: &S) -> Self {
        VecPoly::new(self.comps.iter().map(|p| p.scale(c)).collect())
    }

    /// `self + p`, adding the constant point `p`; an error when the dimensions differ.
    pub fn add_point(&self, p: &Point<S>) -> Result<Self, PolyError> {
        self.checked_add(&VecPoly::constant(p))
    }

    /// The dot product `Σ p_i q_i`, a scalar polynomial.
    pub fn dot(&self, other: &Self) -> Result<Poly<S>, PolyError> {
        self.same_dim(other, Operands::DotProduct)?;
        Ok(self
            .comps
            .iter()
            .zip(&other.comps)
            .fold(Poly::zero(), |acc, (a, b)| acc + a * b))
    }

    /// The cross product of two maps into R^3:
    /// `(p_2 q_3 - p_3 q_2, p_3 q_1 - p_1 q_3, p_1 q_2 - p_2 q_1)`.
    pub fn cross(&self, other: &Self) -> Result<Self, PolyError> {
        match (self.comps.as_slice(), other.comps.as_slice()) {
            ([a0, a1, a2], [b0, b1, b2]) => Ok(VecPoly::new(vec![
                a1 * b2 - a2 * b1,
                a2 * b0 - a0 * b2,
                a0 * b1 - a1 * b0,
            ])),
            _ => Err(PolyError::DimensionMismatch {
                what: Operands::CrossProduct,
                expected: 3,
                found: if self.dim() == 3 {
                    other.dim()
                } else {
                    self.dim()
                },
            }),
        }
    }

    /// The partial derivative, componentwise: `c_u = ∂c/∂u`.
    pub fn partial(&self, var: Var) -> Self {
        self.map(|p| p.partial(var))
    }

    /// The map with `f` applied to every component.
    pub fn map(&self, f: impl FnMut(&Poly<S>) -> Poly<S>) -> Self {
        VecPoly::new(self.comps.iter().map(f).collect())
    }

    /// The point `c(point)`; see [`Poly::eval`].
    pub fn eval(&self, point: &[(Var, S)]) -> Result<Point<S>, PolyError> {
        let coords = self
            .comps
            .iter()
            .map(|p| p.eval(point))
            .collect::<Result<Vec<S>, PolyError>>()?;
        Ok(Point::new(coords))
    }

    /// The map with `var` fixed to `x` (an iso-parametric curve of a surface).
    pub fn substitute_value(&self, var: Var, x: &S) -> Self {
        self.map(|p| p.substitute_value(var, x))
    }

    /// The composition with `var ↦ q`, componentwise; see [`Poly::substitute`].
    pub fn substitute(&self, var: Var, q: &Poly<S>) -> Self {
        self.map(|p| p.substitute(var, q))
    }

    /// The composition with `var ↦ α var + β`; see [`Poly::affine_substitute`].
    pub fn affine_substitute(&self, var: Var, alpha: &S, beta: &S) -> Self {
        self.map(|p| p.affine_substitute(var, alpha, beta))
    }

    /// The reparametrization `var ↦ (var - a)/(b - a)`; see [`Poly::reparametrize_affine`].
    pub fn reparametrize_affine(&self, var: Var, a: &S, b: &S) -> Result<Self, PolyError> {
        let comps = self
            .comps
            .iter()
            .map(|p| p.reparametrize_affine(var, a, b))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(VecPoly::new(comps))
    }

    /// The same map over another number type, exactly; see [`Poly::convert`].
    pub fn convert<T: Scalar>(&self) -> Result<VecPoly<T>, PolyError> {
        let comps = self
            .comps
            .iter()
            .map(Poly::convert)
            .collect::<Result<Vec<_>, _>>()?;
        Ok(VecPoly::new(comps))
    }

    /// The map with every coefficient mapped by `f`.
    pub fn map_coeffs<T: Scalar>(&self, mut f: impl FnMut(&S) -> T) -> VecPoly<T> {
        VecPoly::new(self.comps.iter().map(|p| p.map_coeffs(&mut f)).collect())
    }
}

impl<S: Scalar> Neg for VecPoly<S> {
    type Output = VecPoly<S>;
    fn neg(self) -> VecPoly<S> {
        VecPoly::new(self.comps.into_iter().map(|p| -p).collect())
    }
}

impl<S: Scalar> From<Vec<Poly<S>>> for VecPoly<S> {
    fn from(comps: Vec<Poly<S>>) -> Self {
        VecPoly::new(comps)
    }
}

impl<S: Scalar> fmt::Display for VecPoly<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}

impl<S: Scalar> fmt::Debug for VecPoly<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "VecPoly{}", self.to_text())
    }
}
