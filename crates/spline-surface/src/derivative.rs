//! Partial derivatives: the derivative surfaces (B-splines of one degree less in a direction)
//! and the partial derivatives at a point.

use crate::eval::at_infinity;
use crate::{BSplineSurface, Direction, NurbsSurface, SplineSurfaceError};
use cagd_bspline::{derivative_curve, derivatives, KnotVector};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// The derivative of order `order` at t of every curve (knots `knots`).
fn derivative_each<S: Scalar>(
    knots: &KnotVector<S>,
    curves: &[Vec<Point<S>>],
    t: &S,
    order: usize,
    direction: Direction,
) -> Result<Vec<Point<S>>, SplineSurfaceError> {
    curves
        .iter()
        .map(|d| {
            let ders =
                derivatives(knots, d, t, order).map_err(SplineSurfaceError::curve(direction))?;
            Ok(ders.into_iter().last().unwrap_or_else(|| Point::zero(0)))
        })
        .collect()
}

impl<S: Scalar> BSplineSurface<S> {
    /// The partial derivative surface `c_u` (in u) or `c_v` (in v): the derivative curve
    /// ([`cagd_bspline::derivative_curve`]) of every column, resp. row. In u it has bidegree
    /// (p - 1, q), the knots in u without the first and last (notes' convention), and the mesh
    ///
    /// `Δ_u d_{i,j} = p (d_{i+1,j} - d_{i,j}) / (u_{i+p} - u_i)`, i = 0, ..., M + p - 2
    ///
    /// (notes' indices); in v likewise with q and the knots in v.
    ///
    /// Errors for degree 1 in that direction (the derivative is piecewise constant) and where
    /// a knot of multiplicity p + 1 would make the derivative jump.
    ///
    /// ```
    /// use cagd_spline_surface::{BSplineSurface, Direction};
    /// use cagd_surface::Mesh;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational, FieldOps, Print};
    /// // The plane (u, v, u + v) as a biquadratic: c_u = (1, 0, 1) everywhere.
    /// let h = |k: i64| BigRational::from_ratio(k, 2);
    /// let m: Vec<Vec<Point<BigRational>>> = (0..3)
    ///     .map(|i| (0..3).map(|j| Point::new(vec![h(i), h(j), h(i + j)])).collect())
    ///     .collect();
    /// let (s, _) = BSplineSurface::read(
    ///     (2, 2),
    ///     (vec![q!(0), q!(0), q!(1), q!(1)], vec![q!(0), q!(0), q!(1), q!(1)]),
    ///     Mesh::mesh(m).unwrap(),
    /// ).unwrap();
    /// let du = s.derivative(Direction::U).unwrap();
    /// assert_eq!(du.bidegree(), (1, 2));
    /// assert_eq!(du.knots_u().to_text(), "{0, 1}");
    /// assert_eq!(du.mesh().get(1, 2).unwrap().to_text(), "(1, 0, 1)");
    /// ```
    pub fn derivative(&self, direction: Direction) -> Result<Self, SplineSurfaceError> {
        self.map_curves(direction, derivative_curve)
    }

    /// The partial derivative `∂^{k+l} c / ∂u^k ∂v^l` at (u, v): the l-th derivative in v of
    /// every row ([`cagd_bspline::derivatives`]), giving the control polygon in u of
    /// `∂^l c/∂v^l (·, v)`, then its k-th derivative in u. At a knot the derivatives are taken
    /// from the right (except at the right end of the domain); orders above the degree give
    /// the zero vector. `(0, 0)` is the point.
    pub fn partial(
        &self,
        u: &S,
        v: &S,
        k: usize,
        l: usize,
    ) -> Result<Point<S>, SplineSurfaceError> {
        self.check_parameters(u, v)?;
        let polygon = derivative_each(
            self.knots_v(),
            &self.curves(Direction::V),
            v,
            l,
            Direction::V,
        )?;
        let ders = derivatives(self.knots_u(), &polygon, u, k)
            .map_err(SplineSurfaceError::curve(Direction::U))?;
        Ok(ders
            .into_iter()
            .last()
            .unwrap_or_else(|| Point::zero(self.dim())))
    }
}

impl<S: Scalar> NurbsSurface<S> {
    /// The point and first partial derivatives `[c, c_u, c_v]` at (u, v), by the quotient rule
    /// on the homogeneous surface `(A, W)` (numerator and denominator of (6)):
    ///
    /// `c = A / W`, `c_u = (A_u - W_u c) / W`, `c_v = (A_v - W_v c) / W`.
    ///
    /// An error outside the domain or where W vanishes.
    pub fn first_partials(&self, u: &S, v: &S) -> Result<[Point<S>; 3], SplineSurfaceError> {
        let h = self.homogeneous();
        let split = |p: Point<S>| -> (Point<S>, S) {
            let mut coords = p.into_coords();
            let w = coords.pop().unwrap_or_else(S::zero);
            (Point::new(coords), w)
        };
        let (a, w) = split(h.partial(u, v, 0, 0)?);
        let (au, wu) = split(h.partial(u, v, 1, 0)?);
        let (av, wv) = split(h.partial(u, v, 0, 1)?);
        let inv = S::one().checked_div(&w).ok_or_else(|| at_infinity(u, v))?;
        let c = a.scale(&inv);
        let mut cu = au;
        cu.add_scaled(&c, &(-wu));
        let mut cv = av;
        cv.add_scaled(&c, &(-wv));
        let (cu, cv) = (cu.scale(&inv), cv.scale(&inv));
        Ok([c, cu, cv])
    }
}
