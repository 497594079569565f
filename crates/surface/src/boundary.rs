//! The border of a patch: its four boundary curves and four corners (notes, chapter 5, §3).

use crate::{BezierSurface, Border, Corner, Domain, Grid, RationalBezierSurface, SurfaceError};
use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// The row or column of a grid that lies on a border.
pub(crate) fn border_line<T: Clone>(grid: &Grid<T>, border: Border) -> Vec<T> {
    let (rows, cols) = (grid.rows(), grid.cols());
    match border {
        Border::U0 => grid.row(0).map(<[T]>::to_vec),
        Border::U1 => grid.row(rows.saturating_sub(1)).map(<[T]>::to_vec),
        Border::V0 => grid.column(0),
        Border::V1 => grid.column(cols.saturating_sub(1)),
    }
    .unwrap_or_default()
}

/// The interval of the parameter that runs along a border: [c, d] for u = const, [a, b]
/// for v = const.
pub(crate) fn border_interval<S: Scalar>(domain: &Domain<S>, border: Border) -> (S, S) {
    let (lo, hi) = if border.is_u() {
        domain.v_interval()
    } else {
        domain.u_interval()
    };
    (lo.clone(), hi.clone())
}

/// The entry of a grid at a corner.
pub(crate) fn corner_entry<T: Clone>(grid: &Grid<T>, corner: Corner) -> Option<T> {
    let (i, j) = corner.index(grid.rows() - 1, grid.cols() - 1);
    grid.get(i, j).cloned()
}

impl<S: Scalar> BezierSurface<S> {
    /// The boundary curve on a border, a Bézier curve whose control polygon is the first or last
    /// row or column of the mesh (§3): `c(0, v) = Σ_j c_{0,j} B_j^n(v)`, `c(1, v)` from the last
    /// row, `c(u, 0) = Σ_i c_{i,0} B_i^m(u)`, `c(u, 1)` from the last column. The curve's domain
    /// is the patch's interval of the running parameter.
    ///
    /// ```
    /// use cagd_surface::{Border, BezierSurface};
    /// use cagd_linalg::Point;
    /// use cagd_scalar::BigRational;
    /// let s = BezierSurface::<BigRational>::from_rows(vec![
    ///     vec![Point::from_ints(&[0, 0, 0]), Point::from_ints(&[0, 1, 0])],
    ///     vec![Point::from_ints(&[1, 0, 0]), Point::from_ints(&[1, 1, 1])],
    /// ]).unwrap();
    /// assert_eq!(s.boundary(Border::U1).unwrap().to_text(), "(1, 0, 0), (1, 1, 1)");
    /// assert_eq!(s.boundary(Border::V0).unwrap().to_text(), "(0, 0, 0), (1, 0, 0)");
    /// ```
    pub fn boundary(&self, border: Border) -> Result<BezierCurve<S>, SurfaceError> {
        let (lo, hi) = border_interval(self.domain(), border);
        Ok(BezierCurve::try_new(border_line(self.mesh(), border))?.with_domain(lo, hi)?)
    }

    /// The four boundary curves, in the order u = 0, u = 1, v = 0, v = 1.
    pub fn boundaries(&self) -> Result<[BezierCurve<S>; 4], SurfaceError> {
        Ok([
            self.boundary(Border::U0)?,
            self.boundary(Border::U1)?,
            self.boundary(Border::V0)?,
            self.boundary(Border::V1)?,
        ])
    }

    /// The vertex of the mesh at a corner, where the patch passes (§3):
    /// `c(0, 0) = c_{0,0}`, `c(1, 0) = c_{m,0}`, `c(0, 1) = c_{0,n}`, `c(1, 1) = c_{m,n}`.
    pub fn corner(&self, corner: Corner) -> Point<S> {
        corner_entry(self.mesh(), corner).unwrap_or_else(|| Point::zero(self.dim()))
    }

    /// The four corners in the notes' order `c_{0,0}, c_{m,0}, c_{0,n}, c_{m,n}`.
    pub fn corners(&self) -> [Point<S>; 4] {
        Corner::ALL.map(|c| self.corner(c))
    }
}

impl<S: Scalar> RationalBezierSurface<S> {
    /// The boundary curve on a border: the rational Bézier curve of the first or last row or
    /// column of the mesh and of the weights (§3: the property holds for rational patches).
    pub fn boundary(&self, border: Border) -> Result<RationalBezierCurve<S>, SurfaceError> {
        let (lo, hi) = border_interval(self.domain(), border);
        let curve = RationalBezierCurve::try_new(
            border_line(self.mesh(), border),
            border_line(self.weights(), border),
        )?;
        Ok(curve.with_domain(lo, hi)?)
    }

    /// The four boundary curves, in the order u = 0, u = 1, v = 0, v = 1.
    pub fn boundaries(&self) -> Result<[RationalBezierCurve<S>; 4], SurfaceError> {
        Ok([
            self.boundary(Border::U0)?,
            self.boundary(Border::U1)?,
            self.boundary(Border::V0)?,
            self.boundary(Border::V1)?,
        ])
    }

    /// The vertex of the mesh at a corner, where the patch passes.
    pub fn corner(&self, corner: Corner) -> Point<S> {
        corner_entry(self.mesh(), corner).unwrap_or_else(|| Point::zero(self.mesh().dim()))
    }

    /// The four corners in the notes' order `c_{0,0}, c_{m,0}, c_{0,n}, c_{m,n}`.
    pub fn corners(&self) -> [Point<S>; 4] {
        Corner::ALL.map(|c| self.corner(c))
    }
}
