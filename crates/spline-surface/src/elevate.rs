//! Degree elevation in u, in v, or both.

use crate::{BSplineSurface, Direction, NurbsSurface, SplineSurfaceError};
use cagd_bspline::elevate_degree;
use cagd_scalar::Scalar;

impl<S: Scalar> BSplineSurface<S> {
    /// The same surface written with bidegree (p + r, q + s): [`cagd_bspline::elevate_degree`]
    /// (Bézier extraction, `c_i^(1) = (i/(m+1)) c_{i-1} + (1 - i/(m+1)) c_i` on each piece,
    /// exact knot removal) on every column r times, then on every row s times. Every interior
    /// knot's multiplicity grows by r in u and by s in v, so the continuity C^{p-k} across a
    /// knot of multiplicity k is kept; unclamped ends come back clamped. `(0, 0)` returns the
    /// surface unchanged.
    ///
    /// ```
    /// use cagd_spline_surface::BSplineSurface;
    /// use cagd_surface::Mesh;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational};
    /// // z = u v as a bilinear patch: elevated to (2, 1), the middle row is the average.
    /// let p = |c: &[i64]| Point::<BigRational>::from_ints(c);
    /// let mesh = Mesh::mesh(vec![
    ///     vec![p(&[0, 0, 0]), p(&[0, 1, 0])],
    ///     vec![p(&[1, 0, 0]), p(&[1, 1, 1])],
    /// ]).unwrap();
    /// let (s, _) = BSplineSurface::read((1, 1), (vec![q!(0), q!(1)], vec![q!(0), q!(1)]), mesh).unwrap();
    /// let e = s.elevate_degree(1, 0).unwrap();
    /// assert_eq!(e.bidegree(), (2, 1));
    /// assert_eq!(e.knots_u().to_text(), "{0, 0, 1, 1}");
    /// assert_eq!(e.mesh().to_text(), "{(0, 0, 0), (0, 1, 0); (1/2, 0, 0), (1/2, 1, 1/2); (1, 0, 0), (1, 1, 1)}");
    /// ```
    pub fn elevate_degree(&self, r: usize, s: usize) -> Result<Self, SplineSurfaceError> {
        self.map_curves(Direction::U, |knots, points| {
            elevate_degree(knots, points, r)
        })?
        .map_curves(Direction::V, |knots, points| {
            elevate_degree(knots, points, s)
        })
    }

    /// The same surface with the degree in `direction` raised by r (the other kept).
    pub fn elevate_degree_in(
        &self,
        direction: Direction,
        r: usize,
    ) -> Result<Self, SplineSurfaceError> {
        match direction {
            Direction::U => self.elevate_degree(r, 0),
            Direction::V => self.elevate_degree(0, r),
        }
    }
}

impl<S: Scalar> NurbsSurface<S> {
    /// The same surface with bidegree (p + r, q + s): degree elevation of the homogeneous
    /// mesh (see [`BSplineSurface::elevate_degree`]), projected back.
    pub fn elevate_degree(&self, r: usize, s: usize) -> Result<Self, SplineSurfaceError> {
        self.through_homogeneous(|h| h.elevate_degree(r, s))
    }

    /// The same surface with the degree in `direction` raised by r.
    pub fn elevate_degree_in(
        &self,
        direction: Direction,
        r: usize,
    ) -> Result<Self, SplineSurfaceError> {
        self.through_homogeneous(|h| h.elevate_degree_in(direction, r))
    }
}
