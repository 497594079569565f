//! The NURBS surface (notes, eq. (6)): a B-spline surface with a weight per control point,
//! handled through its homogeneous form.

use crate::{BSplineSurface, Direction, SplineSurfaceError};
use cagd_bspline::{KnotConvention, KnotVector};
use cagd_linalg::Point;
use cagd_scalar::Scalar;
use cagd_surface::{Grid, Mesh};

/// A NURBS surface (notes, eq. (6)):
///
/// `c(u, v) = Σ_i Σ_j w_{i,j} d_{i,j} N_i^p(u) N_j^q(v) / Σ_i Σ_j w_{i,j} N_i^p(u) N_j^q(v)`.
///
/// The basis no longer factors into functions of u times functions of v, but the numerator
/// and the denominator do: every algorithm runs on the B-spline surface of the homogeneous
/// mesh `(w_{i,j} d_{i,j}, w_{i,j})` (weight last, [`NurbsSurface::homogeneous`]) and projects
/// back. Zero weights are an error; negative weights are allowed (the surface may leave the
/// convex hull of its mesh or go through infinity) and listed by
/// [`NurbsSurface::negative_weights`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NurbsSurface<S> {
    surface: BSplineSurface<S>,
    weights: Grid<S>,
}

impl<S: Scalar> NurbsSurface<S> {
    /// The NURBS surface with these knot vectors, mesh and weights: the mesh as for
    /// [`BSplineSurface::try_new`], the weights of the mesh's shape and nonzero.
    ///
    /// ```
    /// use cagd_spline_surface::NurbsSurface;
    /// use cagd_bspline::KnotVector;
    /// use cagd_surface::{Grid, Mesh};
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational};
    /// let k = KnotVector::clamped(1, &[q!(0), q!(1)]).unwrap();
    /// let mesh: Mesh<BigRational> = Mesh::mesh(vec![vec![Point::from_ints(&[0, 0]); 2]; 2]).unwrap();
    /// let w = Grid::from_rows(vec![vec![q!(1), q!(2)], vec![q!(0), q!(1)]]).unwrap();
    /// assert_eq!(
    ///     NurbsSurface::try_new(k.clone(), k, mesh, w).unwrap_err().to_string(),
    ///     "weight w_1,0 is zero: weights must be nonzero"
    /// );
    /// ```
    pub fn try_new(
        knots_u: KnotVector<S>,
        knots_v: KnotVector<S>,
        mesh: Mesh<S>,
        weights: Grid<S>,
    ) -> Result<Self, SplineSurfaceError> {
        let surface = BSplineSurface::try_new(knots_u, knots_v, mesh)?;
        Self::with_weights(surface, weights)
    }

    /// The NURBS surface of bidegree `(p, q)` with knots `(in u, in v)` in either convention
    /// (see [`BSplineSurface::read`]), mesh and weights; returns the conventions read.
    pub fn read(
        degree: (usize, usize),
        knots: (Vec<S>, Vec<S>),
        mesh: Mesh<S>,
        weights: Grid<S>,
    ) -> Result<(Self, (KnotConvention, KnotConvention)), SplineSurfaceError> {
        let (surface, conventions) = BSplineSurface::read(degree, knots, mesh)?;
        Ok((Self::with_weights(surface, weights)?, conventions))
    }

    /// The B-spline surface `surface` with these weights (of its mesh's shape, nonzero).
    pub fn with_weights(
        surface: BSplineSurface<S>,
        weights: Grid<S>,
    ) -> Result<Self, SplineSurfaceError> {
        let mesh = surface.mesh();
        if (mesh.rows(), mesh.cols()) != (weights.rows(), weights.cols()) {
            return Err(SplineSurfaceError::WeightShape {
                mesh: (mesh.rows(), mesh.cols()),
                weights: (weights.rows(), weights.cols()),
            });
        }
        if let Some(((row, col), _)) = weights.indexed().find(|(_, w)| w.is_zero()) {
            return Err(SplineSurfaceError::ZeroWeight { row, col });
        }
        Ok(NurbsSurface { surface, weights })
    }

    /// The NURBS surface whose homogeneous mesh `(w x, ..., w)` (weight last) is the mesh of
    /// a B-spline surface; a zero last coordinate is an error naming the control point.
    pub fn from_homogeneous(h: BSplineSurface<S>) -> Result<Self, SplineSurfaceError> {
        let (knots_u, knots_v, hmesh) = h.into_parts();
        let mut points = Vec::with_capacity(hmesh.rows());
        let mut weights = Vec::with_capacity(hmesh.rows());
        for (row, hrow) in hmesh.to_rows().into_iter().enumerate() {
            let mut prow = Vec::with_capacity(hrow.len());
            let mut wrow = Vec::with_capacity(hrow.len());
            for (col, x) in hrow.iter().enumerate() {
                let (p, w) = x
                    .from_homogeneous()
                    .ok_or(SplineSurfaceError::ZeroWeight { row, col })?;
                prow.push(p);
                wrow.push(w);
            }
            points.push(prow);
            weights.push(wrow);
        }
        Self::try_new(
            knots_u,
            knots_v,
            Mesh::mesh(points)?,
            Grid::from_rows(weights)?,
        )
    }

    /// The B-spline surface of the homogeneous mesh `(w_{i,j} d_{i,j}, w_{i,j})` in one
    /// dimension more (weight last): the numerator and denominator of (6) at once.
    pub fn homogeneous(&self) -> BSplineSurface<S> {
        let mesh = self.surface.mesh();
        let hmesh = Grid::from_fn(mesh.rows(), mesh.cols(), |i, j| {
            match (mesh.get(i, j), self.weights.get(i, j)) {
                (Some(p), Some(w)) => p.to_homogeneous(w),
                _ => Point::zero(0),
            }
        });
        // Same knots and shape, every point one dimension more: still valid.
        BSplineSurface::from_parts(
            self.surface.knots_u().clone(),
            self.surface.knots_v().clone(),
            hmesh,
        )
    }

    /// The B-spline surface of the (affine) control mesh, without the weights.
    pub fn control_surface(&self) -> &BSplineSurface<S> {
        &self.surface
    }

    /// The bidegree (p, q).
    pub fn bidegree(&self) -> (usize, usize) {
        self.surface.bidegree()
    }

    /// The same surface on the domain [0, 1] x [0, 1] ([`BSplineSurface::normalized`]), the
    /// same mesh and weights.
    pub fn normalized(&self) -> Self {
        NurbsSurface {
            surface: self.surface.normalized(),
            weights: self.weights.clone(),
        }
    }

    /// The knot vector in u.
    pub fn knots_u(&self) -> &KnotVector<S> {
        self.surface.knots_u()
    }

    /// The knot vector in v.
    pub fn knots_v(&self) -> &KnotVector<S> {
        self.surface.knots_v()
    }

    /// The knot vector of a direction.
    pub fn knots(&self, direction: Direction) -> &KnotVector<S> {
        self.surface.knots(direction)
    }

    /// The (affine) control mesh `d_{i,j}`.
    pub fn mesh(&self) -> &Mesh<S> {
        self.surface.mesh()
    }

    /// The weights `w_{i,j}`.
    pub fn weights(&self) -> &Grid<S> {
        &self.weights
    }

    /// The domain, as for [`BSplineSurface::domain`].
    pub fn domain(&self) -> ((S, S), (S, S)) {
        self.surface.domain()
    }

    /// The number of non-empty spans (M, N).
    pub fn spans(&self) -> (usize, usize) {
        self.surface.spans()
    }

    /// The positions (i, j) of the negative weights, row by row (empty when the surface lies
    /// in the convex hull of its mesh).
    pub fn negative_weights(&self) -> Vec<(usize, usize)> {
        self.weights
            .indexed()
            .filter(|(_, w)| **w < S::zero())
            .map(|(ij, _)| ij)
            .collect()
    }

    /// Every weight is positive.
    pub fn has_positive_weights(&self) -> bool {
        self.negative_weights().is_empty()
    }

    /// Runs a B-spline surface algorithm on the homogeneous form and projects back.
    pub(crate) fn through_homogeneous(
        &self,
        f: impl FnOnce(&BSplineSurface<S>) -> Result<BSplineSurface<S>, SplineSurfaceError>,
    ) -> Result<Self, SplineSurfaceError> {
        Self::from_homogeneous(f(&self.homogeneous())?)
    }
}
