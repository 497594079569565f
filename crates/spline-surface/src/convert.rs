//! Conversions between a single Bézier patch and the B-spline form.

use crate::{BSplineSurface, Direction, NotSingle, NurbsSurface, SplineSurfaceError};
use cagd_bspline::KnotVector;
use cagd_scalar::Scalar;
use cagd_surface::{BezierSurface, RationalBezierSurface};

/// The knot vector of one Bézier piece of degree m on [a, b]: a and b each m times (notes'
/// convention).
fn single_span<S: Scalar>(
    direction: Direction,
    degree: usize,
    (a, b): (&S, &S),
) -> Result<KnotVector<S>, SplineSurfaceError> {
    KnotVector::bezier(degree, a.clone(), b.clone()).map_err(SplineSurfaceError::knots(direction))
}

/// Why the knots of a direction are not those of a single Bézier piece, if they are not.
fn not_single_span<S: Scalar>(knots: &KnotVector<S>) -> Option<NotSingle> {
    let p = knots.degree();
    let n = knots.control_point_count();
    if n != p + 1 {
        Some(NotSingle::PointCount {
            count: n,
            degree: p,
        })
    } else if !knots.is_clamped() {
        Some(NotSingle::NotClamped {
            knots: knots.to_text(),
            degree: p,
        })
    } else {
        None
    }
}

impl<S: Scalar> BSplineSurface<S> {
    /// The Bézier patch of bidegree (m, n) on its domain [a, b] x [c, d] as a B-spline
    /// surface with a single span each way: knots `{a, ..., a, b, ..., b}` (each m times, notes'
    /// convention) in u and likewise in v, and the same mesh, since the B-spline basis of
    /// these knots is the Bernstein basis on [a, b]. An error for degree 0 in a direction.
    ///
    /// ```
    /// use cagd_spline_surface::BSplineSurface;
    /// use cagd_surface::BezierSurface;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational};
    /// let p = |c: &[i64]| Point::<BigRational>::from_ints(c);
    /// let patch = BezierSurface::from_rows(vec![
    ///     vec![p(&[0, 0, 0]), p(&[0, 1, 0]), p(&[0, 2, 1])],
    ///     vec![p(&[1, 0, 0]), p(&[1, 1, 1]), p(&[1, 2, 0])],
    /// ]).unwrap();
    /// let s = BSplineSurface::from_bezier(&patch).unwrap();
    /// assert_eq!(s.knots_u().to_text(), "{0, 1}");
    /// assert_eq!(s.knots_v().to_text(), "{0, 0, 1, 1}");
    /// assert!(s.is_bezier());
    /// assert_eq!(s.eval(&q!(1/3), &q!(1/2)).unwrap(), patch.eval(&q!(1/3), &q!(1/2)).unwrap());
    /// assert_eq!(s.to_bezier().unwrap(), patch);
    /// ```
    pub fn from_bezier(patch: &BezierSurface<S>) -> Result<Self, SplineSurfaceError> {
        let (m, n) = patch.bidegree();
        let domain = patch.domain();
        let knots_u = single_span(Direction::U, m, domain.u_interval())?;
        let knots_v = single_span(Direction::V, n, domain.v_interval())?;
        Self::try_new(knots_u, knots_v, patch.mesh().clone())
    }

    /// Whether the surface is a single Bézier patch as it stands: p + 1 rows and q + 1
    /// columns, with clamped knots `{a, ..., a, b, ..., b}` each way. Then the B-spline mesh is
    /// the Bézier mesh (see [`BSplineSurface::to_bezier`]); otherwise
    /// [`BSplineSurface::bezier_patches`] computes the Bézier meshes.
    pub fn is_bezier(&self) -> bool {
        self.why_not_bezier().is_none()
    }

    fn why_not_bezier(&self) -> Option<(Direction, NotSingle)> {
        [Direction::U, Direction::V]
            .into_iter()
            .find_map(|d| not_single_span(self.knots(d)).map(|why| (d, why)))
    }

    /// The Bézier patch, on the domain of the surface, when [`BSplineSurface::is_bezier`];
    /// otherwise an error saying why not.
    pub fn to_bezier(&self) -> Result<BezierSurface<S>, SplineSurfaceError> {
        if let Some((direction, reason)) = self.why_not_bezier() {
            return Err(SplineSurfaceError::NotBezier { direction, reason });
        }
        let ((a, b), (c, d)) = self.domain();
        Ok(BezierSurface::try_new(self.mesh().clone())?.with_domain(a, b, c, d)?)
    }
}

impl<S: Scalar> NurbsSurface<S> {
    /// The rational Bézier patch (5) as a NURBS surface with a single span each way (see
    /// [`BSplineSurface::from_bezier`]), same mesh and weights.
    pub fn from_rational_bezier(
        patch: &RationalBezierSurface<S>,
    ) -> Result<Self, SplineSurfaceError> {
        let (m, n) = patch.bidegree();
        let domain = patch.domain();
        let knots_u = single_span(Direction::U, m, domain.u_interval())?;
        let knots_v = single_span(Direction::V, n, domain.v_interval())?;
        Self::try_new(
            knots_u,
            knots_v,
            patch.mesh().clone(),
            patch.weights().clone(),
        )
    }

    /// Whether the surface is a single rational Bézier patch as it stands (see
    /// [`BSplineSurface::is_bezier`]).
    pub fn is_bezier(&self) -> bool {
        self.control_surface().is_bezier()
    }

    /// The rational Bézier patch, on the domain of the surface, when
    /// [`NurbsSurface::is_bezier`]; otherwise an error saying why not.
    pub fn to_rational_bezier(&self) -> Result<RationalBezierSurface<S>, SplineSurfaceError> {
        let patch = self.control_surface().to_bezier()?;
        let ((a, b), (c, d)) = self.domain();
        Ok(
            RationalBezierSurface::try_new(patch.into_mesh(), self.weights().clone())?
                .with_domain(a, b, c, d)?,
        )
    }
}
