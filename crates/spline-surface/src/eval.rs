//! Evaluation: De Boor in two passes (both orders), the basis sum (4), and the rational
//! quotient (6).

use crate::{BSplineSurface, Direction, NurbsSurface, SplineSurfaceError};
use cagd_bspline::{basis_functions_at, de_boor, KnotVector};
use cagd_linalg::Point;
use cagd_record::{NoSteps, Record};
use cagd_scalar::Scalar;

/// The step between the two passes of De Boor's algorithm at (u, v), rows first.
#[derive(Clone, Debug, PartialEq)]
pub struct DeBoorStep<S: Scalar> {
    /// The parameters (u, v).
    pub at: (S, S),
    /// First pass: De Boor in v on every row i, giving `d_i(v) = Σ_j d_{i,j} N_j^q(v)`, the
    /// control polygon (with the knots in u) of the curve `u ↦ c(u, v)`; the second pass,
    /// De Boor in u on it, gives the point c(u, v).
    pub polygon: Vec<Point<S>>,
}

/// De Boor on every curve of `curves` (knots `knots`) at t.
fn de_boor_each<S: Scalar>(
    knots: &KnotVector<S>,
    curves: &[Vec<Point<S>>],
    t: &S,
    direction: Direction,
) -> Result<Vec<Point<S>>, SplineSurfaceError> {
    curves
        .iter()
        .map(|d| de_boor(knots, d, t).map_err(SplineSurfaceError::curve(direction)))
        .collect()
}

impl<S: Scalar> BSplineSurface<S> {
    /// The point c(u, v) of (4), by De Boor in two passes, rows first
    /// ([`BSplineSurface::de_boor_rows_first`]). An error outside the domain.
    pub fn eval(&self, u: &S, v: &S) -> Result<Point<S>, SplineSurfaceError> {
        self.de_boor_rows_first(u, v)
    }

    /// De Boor's algorithm on every row i in v (knots in v), giving the polygon
    /// `d_i(v) = Σ_j d_{i,j} N_j^q(v)`, then on that polygon in u (knots in u):
    ///
    /// `c(u, v) = Σ_i (Σ_j d_{i,j} N_j^q(v)) N_i^p(u)`.
    ///
    /// ```
    /// use cagd_spline_surface::BSplineSurface;
    /// use cagd_surface::Mesh;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational, FieldOps, Print};
    /// // Biquadratic with one span each way: the mesh (i/2, j/2, (i + j)/2) of eq. (3) is the
    /// // plane x = u, y = v, z = u + v.
    /// let h = |k: i64| BigRational::from_ratio(k, 2);
    /// let m: Vec<Vec<Point<BigRational>>> = (0..3)
    ///     .map(|i| (0..3).map(|j| Point::new(vec![h(i), h(j), h(i + j)])).collect())
    ///     .collect();
    /// let (s, _) = BSplineSurface::read(
    ///     (2, 2),
    ///     (vec![q!(0), q!(0), q!(1), q!(1)], vec![q!(0), q!(0), q!(1), q!(1)]),
    ///     Mesh::mesh(m).unwrap(),
    /// ).unwrap();
    /// let p = s.de_boor_rows_first(&q!(1/3), &q!(3/4)).unwrap();
    /// assert_eq!(p.to_text(), "(1/3, 3/4, 13/12)");
    /// assert_eq!(p, s.de_boor_columns_first(&q!(1/3), &q!(3/4)).unwrap());
    /// ```
    pub fn de_boor_rows_first(&self, u: &S, v: &S) -> Result<Point<S>, SplineSurfaceError> {
        self.de_boor_rows_first_recorded(u, v, &mut NoSteps)
    }

    /// [`BSplineSurface::de_boor_rows_first`], recording the polygon of the first pass,
    /// `d_i(v) = Σ_j d_{i,j} N_j^q(v)`, for a step-by-step answer.
    pub fn de_boor_rows_first_recorded(
        &self,
        u: &S,
        v: &S,
        rec: &mut impl Record<DeBoorStep<S>>,
    ) -> Result<Point<S>, SplineSurfaceError> {
        self.check_parameters(u, v)?;
        let polygon = de_boor_each(self.knots_v(), &self.curves(Direction::V), v, Direction::V)?;
        let point = de_boor(self.knots_u(), &polygon, u)
            .map_err(SplineSurfaceError::curve(Direction::U))?;
        rec.record(|| DeBoorStep {
            at: (u.clone(), v.clone()),
            polygon,
        });
        Ok(point)
    }

    /// De Boor's algorithm on every column j in u (knots in u), giving the polygon
    /// `d_j(u) = Σ_i d_{i,j} N_i^p(u)`, then on that polygon in v:
    ///
    /// `c(u, v) = Σ_j (Σ_i d_{i,j} N_i^p(u)) N_j^q(v)`,
    ///
    /// the same point as [`BSplineSurface::de_boor_rows_first`].
    pub fn de_boor_columns_first(&self, u: &S, v: &S) -> Result<Point<S>, SplineSurfaceError> {
        self.check_parameters(u, v)?;
        let polygon = de_boor_each(self.knots_u(), &self.curves(Direction::U), u, Direction::U)?;
        de_boor(self.knots_v(), &polygon, v).map_err(SplineSurfaceError::curve(Direction::V))
    }

    /// The sum (4) itself, `c(u, v) = Σ_i Σ_j d_{i,j} N_i^p(u) N_j^q(v)`, over the (p + 1)(q + 1)
    /// basis functions that may be nonzero at (u, v) (Cox–de Boor recursion): an independent
    /// route to the point of De Boor's algorithm.
    pub fn eval_basis(&self, u: &S, v: &S) -> Result<Point<S>, SplineSurfaceError> {
        self.check_parameters(u, v)?;
        let (i0, nu) = basis_functions_at(self.knots_u(), u)
            .map_err(SplineSurfaceError::curve(Direction::U))?;
        let (j0, nv) = basis_functions_at(self.knots_v(), v)
            .map_err(SplineSurfaceError::curve(Direction::V))?;
        let mut acc = Point::zero(self.dim());
        for (a, ni) in nu.iter().enumerate() {
            for (b, nj) in nv.iter().enumerate() {
                if let Some(d) = self.mesh().get(i0 + a, j0 + b) {
                    acc.add_scaled(d, &ni.mul_ref(nj));
                }
            }
        }
        Ok(acc)
    }
}

impl<S: Scalar> NurbsSurface<S> {
    /// The point c(u, v) of (6): De Boor in two passes (rows first) on the homogeneous mesh
    /// `(w_{i,j} d_{i,j}, w_{i,j})`, then the projection `(X, Y, Z, W) ↦ (X/W, Y/W, Z/W)`. An
    /// error outside the domain or where the denominator vanishes.
    pub fn eval(&self, u: &S, v: &S) -> Result<Point<S>, SplineSurfaceError> {
        self.de_boor_rows_first(u, v)
    }

    /// The homogeneous point `(Σ w d N N, Σ w N N)` (weight last) by De Boor, rows first.
    pub fn eval_homogeneous(&self, u: &S, v: &S) -> Result<Point<S>, SplineSurfaceError> {
        self.homogeneous().de_boor_rows_first(u, v)
    }

    /// De Boor on the homogeneous rows in v, then in u, projected.
    pub fn de_boor_rows_first(&self, u: &S, v: &S) -> Result<Point<S>, SplineSurfaceError> {
        project(&self.homogeneous().de_boor_rows_first(u, v)?, u, v)
    }

    /// De Boor on the homogeneous columns in u, then in v, projected: the same point as
    /// [`NurbsSurface::de_boor_rows_first`].
    pub fn de_boor_columns_first(&self, u: &S, v: &S) -> Result<Point<S>, SplineSurfaceError> {
        project(&self.homogeneous().de_boor_columns_first(u, v)?, u, v)
    }

    /// The quotient (6) itself,
    ///
    /// `Σ_i Σ_j w_{i,j} d_{i,j} N_i^p(u) N_j^q(v) / Σ_i Σ_j w_{i,j} N_i^p(u) N_j^q(v)`,
    ///
    /// numerator and denominator summed over the basis functions (an independent route).
    pub fn eval_quotient(&self, u: &S, v: &S) -> Result<Point<S>, SplineSurfaceError> {
        self.surface_check(u, v)?;
        let (i0, nu) = basis_functions_at(self.knots_u(), u)
            .map_err(SplineSurfaceError::curve(Direction::U))?;
        let (j0, nv) = basis_functions_at(self.knots_v(), v)
            .map_err(SplineSurfaceError::curve(Direction::V))?;
        let mut num = Point::zero(self.mesh().dim());
        let mut den = S::zero();
        for (a, ni) in nu.iter().enumerate() {
            for (b, nj) in nv.iter().enumerate() {
                let (i, j) = (i0 + a, j0 + b);
                if let (Some(d), Some(w)) = (self.mesh().get(i, j), self.weights().get(i, j)) {
                    let c = w.mul_ref(ni).mul_ref(nj);
                    num.add_scaled(d, &c);
                    den += c;
                }
            }
        }
        let inv = S::one()
            .checked_div(&den)
            .ok_or_else(|| at_infinity(u, v))?;
        Ok(num.scale(&inv))
    }

    fn surface_check(&self, u: &S, v: &S) -> Result<(), SplineSurfaceError> {
        self.control_surface().check_parameters(u, v)
    }
}

/// The error of a vanishing denominator at (u, v).
pub(crate) fn at_infinity<S: Scalar>(u: &S, v: &S) -> SplineSurfaceError {
    SplineSurfaceError::PointAtInfinity {
        u: u.to_text(),
        v: v.to_text(),
    }
}

/// The affine point of a homogeneous point of the surface at (u, v).
pub(crate) fn project<S: Scalar>(
    h: &Point<S>,
    u: &S,
    v: &S,
) -> Result<Point<S>, SplineSurfaceError> {
    h.from_homogeneous()
        .map(|(p, _)| p)
        .ok_or_else(|| at_infinity(u, v))
}
