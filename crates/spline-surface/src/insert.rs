//! Knot insertion (Boehm's algorithm on every column or every row) and knot refinement.

use crate::{BSplineSurface, Direction, NurbsSurface, SplineSurfaceError};
use cagd_bspline::{insert_knot, refine_knots};
use cagd_scalar::Scalar;

impl<S: Scalar> BSplineSurface<S> {
    /// The same surface with the knot t inserted `times` times in `direction`: Boehm's
    /// algorithm ([`cagd_bspline::insert_knot`]) on every column (in u) or every row (in v).
    /// With k the span of t (`u_k <= t < u_{k+1}`, full convention) each column j gets the new
    /// points
    ///
    /// `d̂_{i,j} = (1 - α_i) d_{i-1,j} + α_i d_{i,j}`, `α_i = (t - u_i)/(u_{i+p} - u_i)`,
    /// i = k-p+1, ..., k
    ///
    /// (notes' convention: `α_i = (t - u_{i-1})/(u_{i+p-1} - u_{i-1})`); the mesh gains one row
    /// (one column in v) per insertion, and the surface does not change.
    ///
    /// Errors: t outside the domain of that direction, or a final multiplicity above the
    /// degree.
    ///
    /// ```
    /// use cagd_spline_surface::{BSplineSurface, Direction};
    /// use cagd_surface::Mesh;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational};
    /// let p = |c: &[i64]| Point::<BigRational>::from_ints(c);
    /// let mesh = Mesh::mesh(vec![
    ///     vec![p(&[0, 0, 0]), p(&[0, 1, 0])],
    ///     vec![p(&[1, 0, 0]), p(&[1, 1, 1])],
    /// ]).unwrap();
    /// let (s, _) = BSplineSurface::read((1, 1), (vec![q!(0), q!(1)], vec![q!(0), q!(1)]), mesh).unwrap();
    /// let t = s.insert_knot(Direction::V, &q!(1/4), 1).unwrap();
    /// assert_eq!(t.knots_v().to_text(), "{0, 1/4, 1}");
    /// assert_eq!(t.mesh().to_text(), "{(0, 0, 0), (0, 1/4, 0), (0, 1, 0); (1, 0, 0), (1, 1/4, 1/4), (1, 1, 1)}");
    /// assert_eq!(
    ///     s.insert_knot(Direction::U, &q!(2), 1).unwrap_err().to_string(),
    ///     "in u (on the columns of the mesh): knot 2 is not inside the domain [0, 1] of the curve"
    /// );
    /// ```
    pub fn insert_knot(
        &self,
        direction: Direction,
        t: &S,
        times: usize,
    ) -> Result<Self, SplineSurfaceError> {
        self.map_curves(direction, |knots, points| {
            insert_knot(knots, points, t, times)
        })
    }

    /// Knot refinement in `direction`: every knot of the list inserted (in any order, repeats
    /// allowed) by [`cagd_bspline::refine_knots`] on every column (in u) or row (in v). The
    /// surface does not change.
    pub fn refine_knots(
        &self,
        direction: Direction,
        new_knots: &[S],
    ) -> Result<Self, SplineSurfaceError> {
        self.map_curves(direction, |knots, points| {
            refine_knots(knots, points, new_knots)
        })
    }
}

impl<S: Scalar> NurbsSurface<S> {
    /// The same surface with the knot t inserted `times` times in `direction`: Boehm's
    /// algorithm on the homogeneous mesh `(w d, w)` (see [`BSplineSurface::insert_knot`]).
    pub fn insert_knot(
        &self,
        direction: Direction,
        t: &S,
        times: usize,
    ) -> Result<Self, SplineSurfaceError> {
        self.through_homogeneous(|h| h.insert_knot(direction, t, times))
    }

    /// Knot refinement in `direction` on the homogeneous mesh.
    pub fn refine_knots(
        &self,
        direction: Direction,
        new_knots: &[S],
    ) -> Result<Self, SplineSurfaceError> {
        self.through_homogeneous(|h| h.refine_knots(direction, new_knots))
    }
}
