//! Forward differences, partial derivatives, cross-boundary derivatives and twists (notes,
//! chapter 5, §6, eq. (16)-(20) and (24)).

use crate::{BezierSurface, Border, Corner, Mesh, RationalBezierSurface, SurfaceError};
use cagd_bezier::{derivative_points, forward_differences, BezierCurve};
use cagd_linalg::Point;
use cagd_poly::{RationalMap, Var};
use cagd_scalar::Scalar;

fn exponent(k: usize) -> u32 {
    u32::try_from(k).unwrap_or(u32::MAX)
}

/// The forward differences `Δ^{r,s} c_{i,j}` of a mesh (r in u along the columns, then s in v
/// along the rows); an error unless r <= m and s <= n.
pub(crate) fn mesh_differences<S: Scalar>(
    mesh: &Mesh<S>,
    r: usize,
    s: usize,
) -> Result<Mesh<S>, SurfaceError> {
    let (m, n) = (mesh.rows() - 1, mesh.cols() - 1);
    if r > m || s > n {
        return Err(SurfaceError::DifferenceOrder {
            r,
            s,
            bidegree: (m, n),
        });
    }
    let in_u = mesh.map_columns(|col| Ok::<_, SurfaceError>(forward_differences(col, r)?))?;
    in_u.map_rows(|row| Ok::<_, SurfaceError>(forward_differences(row, s)?))
}

impl<S: Scalar> BezierSurface<S> {
    /// The forward differences `Δ^{r,s} c_{i,j}`, `i = 0..m-r`, `j = 0..n-s` (§6):
    ///
    /// `Δ^{r,s} c_{i,j} = Δ^{r-1,s} c_{i+1,j} - Δ^{r-1,s} c_{i,j}
    ///                  = Δ^{r,s-1} c_{i,j+1} - Δ^{r,s-1} c_{i,j}`,
    ///
    /// with `Δ^{1,0} c_{i,j} = c_{i+1,j} - c_{i,j}` and `Δ^{0,1} c_{i,j} = c_{i,j+1} - c_{i,j}`:
    /// the curve differences on every column (r times), then on every row (s times). An
    /// error unless r <= m and s <= n.
    pub fn forward_differences(&self, r: usize, s: usize) -> Result<Mesh<S>, SurfaceError> {
        mesh_differences(self.mesh(), r, s)
    }

    /// The partial derivative `∂^{r+s} c / ∂u^r ∂v^s` as a (vector-valued) Bézier patch of
    /// bidegree (m - r, n - s), eq. (18):
    ///
    /// `∂^{r+s} c(u, v)/∂u^r ∂v^s = m! n! / ((m-r)! (n-s)!) Σ_i Σ_j Δ^{r,s} c_{i,j}
    ///  B_i^{m-r}(u) B_j^{n-s}(v)`,
    ///
    /// by the curve hodograph on every column, then on every row. On a domain
    /// [a, b] x [c, d] the chain rule divides by `(b - a)^r (d - c)^s`. When r > m or s > n the
    /// derivative is zero: the patch with the single zero vector.
    ///
    /// ```
    /// use cagd_surface::BezierSurface;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::BigRational;
    /// let p = |c: &[i64]| Point::from_ints(c);
    /// let s = BezierSurface::<BigRational>::from_rows(vec![
    ///     vec![p(&[0, 0, 0]), p(&[0, 1, 0])],
    ///     vec![p(&[1, 0, 0]), p(&[1, 1, 1])],
    /// ]).unwrap();
    /// // c(u, v) = (u, v, uv): c_u = (1, 0, v), a patch of bidegree (0, 1)
    /// assert_eq!(s.partial_derivative(1, 0).unwrap().to_text(), "{(1, 0, 0), (1, 0, 1)}");
    /// assert_eq!(s.twist().unwrap().to_text(), "{(0, 0, 1)}");
    /// ```
    pub fn partial_derivative(&self, r: usize, s: usize) -> Result<Self, SurfaceError> {
        let (m, n) = self.bidegree();
        let in_u = self
            .mesh()
            .map_columns(|col| Ok::<_, SurfaceError>(derivative_points(col, r)?))?;
        let mut mesh = in_u.map_rows(|row| Ok::<_, SurfaceError>(derivative_points(row, s)?))?;
        let dom = self.domain();
        if !dom.is_unit() && r <= m && s <= n {
            let scale = dom.u_length().powi(exponent(r)) * dom.v_length().powi(exponent(s));
            let inverse = S::one().checked_div(&scale).unwrap_or_else(S::zero);
            mesh = mesh.map(|p| p.scale(&inverse));
        }
        Ok(BezierSurface::from_parts(mesh, dom.clone()))
    }

    /// The first partial derivative in u, eq. (16):
    /// `∂c/∂u = m Σ_j Σ_{i=0}^{m-1} Δ^{1,0} c_{i,j} B_i^{m-1}(u) B_j^n(v)`.
    pub fn derivative_u(&self) -> Result<Self, SurfaceError> {
        self.partial_derivative(1, 0)
    }

    /// The first partial derivative in v, eq. (17):
    /// `∂c/∂v = n Σ_i Σ_{j=0}^{n-1} Δ^{0,1} c_{i,j} B_i^m(u) B_j^{n-1}(v)`.
    pub fn derivative_v(&self) -> Result<Self, SurfaceError> {
        self.partial_derivative(0, 1)
    }

    /// The twist, the mixed derivative (24):
    /// `∂^2 c/∂u ∂v = m n Σ_{i=0}^{m-1} Σ_{j=0}^{n-1} Δ^{1,1} c_{i,j} B_i^{m-1}(u) B_j^{n-1}(v)`,
    /// with `Δ^{1,1} c_{i,j} = c_{i+1,j+1} - c_{i+1,j} - c_{i,j+1} + c_{i,j}`.
    pub fn twist(&self) -> Result<Self, SurfaceError> {
        self.partial_derivative(1, 1)
    }

    /// The twist vectors `∂^2 c/∂u ∂v` at the corners: `m n Δ^{1,1} c_{0,0}` at (0, 0),
    /// `m n Δ^{1,1} c_{m-1,0}` at (1, 0), `m n Δ^{1,1} c_{0,n-1}` at (0, 1),
    /// `m n Δ^{1,1} c_{m-1,n-1}` at (1, 1) (the corners of the twist patch (24)), in the order
    /// of [`Corner::ALL`]. Zero vectors when m = 0 or n = 0.
    pub fn twist_vectors(&self) -> Result<[Point<S>; 4], SurfaceError> {
        Ok(self.twist()?.corners())
    }

    /// The cross-boundary derivative of order r along a border, a vector-valued Bézier curve
    /// in the running parameter, eq. (19)-(20):
    ///
    /// `∂^r c/∂u^r (0, v) = m!/(m-r)! Σ_j Δ^{r,0} c_{0,j} B_j^n(v)`,
    /// `∂^r c/∂u^r (1, v) = m!/(m-r)! Σ_j Δ^{r,0} c_{m-r,j} B_j^n(v)`,
    ///
    /// and in the same way `∂^r c/∂v^r` at v = 0 (`Δ^{0,r} c_{i,0}`) and v = 1
    /// (`Δ^{0,r} c_{i,n-r}`). Its control vectors are the differences of the first (last) r + 1
    /// rows (columns): "the first row gives the border, the second the tangent...".
    pub fn cross_boundary_derivative(
        &self,
        border: Border,
        r: usize,
    ) -> Result<BezierCurve<S>, SurfaceError> {
        let d = if border.is_u() {
            self.partial_derivative(r, 0)?
        } else {
            self.partial_derivative(0, r)?
        };
        d.boundary(border)
    }
}

/// The map with `var` fixed to `x`; an error when the denominator vanishes identically there.
pub(crate) fn substitute_rational<S: Scalar>(
    f: &RationalMap<S>,
    var: Var,
    x: &S,
) -> Result<RationalMap<S>, SurfaceError> {
    Ok(RationalMap::new(
        f.numerator().substitute_value(var, x),
        f.denominator().substitute_value(var, x),
    )?)
}

/// The parameter values of the domain at a corner.
pub(crate) fn corner_parameters<S: Scalar>(domain: &crate::Domain<S>, corner: Corner) -> (S, S) {
    let (iu, iv) = corner.is_end();
    let (a, b) = domain.u_interval();
    let (c, d) = domain.v_interval();
    (
        if iu { b.clone() } else { a.clone() },
        if iv { d.clone() } else { c.clone() },
    )
}

impl<S: Scalar> RationalBezierSurface<S> {
    /// The partial derivative `∂^{r+s} c/∂u^r ∂v^s` of the rational patch (5) in closed form,
    /// through the homogeneous form: with `c = N/w` (numerator and weight of the closed form),
    /// Leibniz's rule on `N = w c` gives `c^{(r,s)} = P_{r,s} / w^{r+s+1}`,
    ///
    /// `P_{a,b} = w^{a+b} N^{(a,b)} − Σ_{(i,j) ≠ (0,0)} C(a, i) C(b, j) w^{(i,j)} w^{i+j-1}
    /// P_{a-i,b-j}`, `P_{0,0} = N`,
    ///
    /// reduced by the factors of w that divide the numerator ([`RationalMap::mixed_partial`]): the
    /// denominator grows by one power of w per derivative (the quotient rule applied r + s
    /// times would give `w^{2^{r+s}}`). A rational patch's derivatives are not Bézier patches
    /// of lower degree, so the closed form is the exact answer.
    pub fn partial_derivative(&self, r: usize, s: usize) -> Result<RationalMap<S>, SurfaceError> {
        Ok(self.closed_form()?.mixed_partial(Var::U, r, Var::V, s))
    }

    /// The cross-boundary derivative of order r along a border, in closed form: a rational
    /// map in the running parameter (v for u = const, u for v = const).
    pub fn cross_boundary_derivative(
        &self,
        border: Border,
        r: usize,
    ) -> Result<RationalMap<S>, SurfaceError> {
        let dom = self.domain();
        let (var, x) = match border {
            Border::U0 => (Var::U, dom.u_interval().0),
            Border::U1 => (Var::U, dom.u_interval().1),
            Border::V0 => (Var::V, dom.v_interval().0),
            Border::V1 => (Var::V, dom.v_interval().1),
        };
        let d = if border.is_u() {
            self.partial_derivative(r, 0)?
        } else {
            self.partial_derivative(0, r)?
        };
        substitute_rational(&d, var, x)
    }

    /// The twist vectors `∂^2 c/∂u ∂v` at the corners, in the order of [`Corner::ALL`],
    /// evaluated exactly from the closed form.
    pub fn twist_vectors(&self) -> Result<[Point<S>; 4], SurfaceError> {
        let t = self.partial_derivative(1, 1)?;
        let at = |corner: Corner| -> Result<Point<S>, SurfaceError> {
            let (u, v) = corner_parameters(self.domain(), corner);
            Ok(t.eval(&[(Var::U, u), (Var::V, v)])?)
        };
        Ok([
            at(Corner::U0V0)?,
            at(Corner::U1V0)?,
            at(Corner::U0V1)?,
            at(Corner::U1V1)?,
        ])
    }
}
