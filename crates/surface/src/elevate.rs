//! Degree elevation (notes, chapter 5, §5, eq. (14)-(15)).

use crate::{BezierSurface, RationalBezierSurface, SurfaceError};
use cagd_bezier::elevate_degree;
use cagd_scalar::Scalar;

impl<S: Scalar> BezierSurface<S> {
    /// The same patch written with bidegree (m + 1, n), eq. (14): curve degree elevation on
    /// each of the n + 1 columns,
    ///
    /// `c_{i,j}^{1,0} = (1 - i/(m+1)) c_{i,j} + i/(m+1) c_{i-1,j}`, `i = 0..m+1`.
    ///
    /// ```
    /// use cagd_surface::BezierSurface;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::BigRational;
    /// let p = |c: &[i64]| Point::from_ints(c);
    /// let s = BezierSurface::<BigRational>::from_rows(vec![
    ///     vec![p(&[0, 0, 0]), p(&[1, 0, 4]), p(&[2, 0, 3])],
    ///     vec![p(&[0, 2, 1]), p(&[1, 2, 5]), p(&[2, 2, 4])],
    ///     vec![p(&[0, 4, 0]), p(&[1, 4, 4]), p(&[2, 4, 3])],
    /// ]).unwrap();
    /// // the notes print c_{1,2}^{1,0} = (0, 4/3, 11/3); the exact value is (2, 4/3, 11/3)
    /// let e = s.elevate_u().unwrap();
    /// assert_eq!(e.mesh().get(1, 2).unwrap().to_text(), "(2, 4/3, 11/3)");
    /// ```
    pub fn elevate_u(&self) -> Result<Self, SurfaceError> {
        self.elevate(1, 0)
    }

    /// The same patch written with bidegree (m, n + 1), eq. (15): curve degree elevation on
    /// each of the m + 1 rows,
    ///
    /// `c_{i,j}^{0,1} = (1 - j/(n+1)) c_{i,j} + j/(n+1) c_{i,j-1}`, `j = 0..n+1`.
    pub fn elevate_v(&self) -> Result<Self, SurfaceError> {
        self.elevate(0, 1)
    }

    /// The same patch written with bidegree (m + r, n + s): r steps of (14) on the columns and
    /// s steps of (15) on the rows (the two passes commute). The domain is kept.
    pub fn elevate(&self, r: usize, s: usize) -> Result<Self, SurfaceError> {
        if let Some(mesh) = crate::fast::elevate(self.mesh(), r, s) {
            // the same mesh, as E_r C E_sᵀ on integer numerators
            return Ok(BezierSurface::from_parts(mesh, self.domain().clone()));
        }
        let columns = self
            .mesh()
            .map_columns(|col| Ok::<_, SurfaceError>(elevate_degree(col, r)?))?;
        let mesh = columns.map_rows(|row| Ok::<_, SurfaceError>(elevate_degree(row, s)?))?;
        Ok(BezierSurface::from_parts(mesh, self.domain().clone()))
    }
}

impl<S: Scalar> RationalBezierSurface<S> {
    /// Bidegree (m + 1, n): (14) on the homogeneous mesh `(w c, w)`, projected.
    pub fn elevate_u(&self) -> Result<Self, SurfaceError> {
        self.elevate(1, 0)
    }

    /// Bidegree (m, n + 1): (15) on the homogeneous mesh, projected.
    pub fn elevate_v(&self) -> Result<Self, SurfaceError> {
        self.elevate(0, 1)
    }

    /// Bidegree (m + r, n + s) on the homogeneous mesh, projected (new weights are the
    /// elevated weights; a new weight can be 0 only when weights of both signs are mixed,
    /// which is an error).
    pub fn elevate(&self, r: usize, s: usize) -> Result<Self, SurfaceError> {
        Self::from_homogeneous_patch(&self.homogeneous_patch().elevate(r, s)?)
    }
}
