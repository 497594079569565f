//! Bézier and rational Bézier patches: the data and its validation. The algorithms live in
//! their own files (evaluation, blossom and restriction, elevation, derivatives, ...).

use crate::fast::IntegerMesh;
use crate::{Domain, Grid, Mesh, SurfaceError};
use cagd_linalg::Point;
use cagd_scalar::Scalar;
use std::sync::OnceLock;

/// A Bézier patch of bidegree (m, n): c(u, v) = Σ_i Σ_j c_ij B_i^m(u) B_j^n(v), u, v ∈ [0, 1]
/// (notes, chapter 5, eq. (1)), or on another domain [a, b] x [c, d] by the affine
/// reparametrization of §3 (see [`Domain`]; the mesh does not change).
#[derive(Clone)]
pub struct BezierSurface<S> {
    mesh: Mesh<S>,
    domain: Domain<S>,
    /// The mesh as integer matrices over common denominators, one per coordinate, computed on
    /// the first evaluation (`None` inside when a coordinate is not rational): evaluation reads
    /// it instead of converting the mesh at every point. Not part of the value (equality and
    /// `Debug` ignore it).
    integer: OnceLock<Option<IntegerMesh>>,
}

impl<S: Scalar> PartialEq for BezierSurface<S> {
    fn eq(&self, other: &Self) -> bool {
        self.mesh == other.mesh && self.domain == other.domain
    }
}

impl<S: Scalar + Eq> Eq for BezierSurface<S> {}

impl<S: Scalar> std::fmt::Debug for BezierSurface<S> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("BezierSurface")
            .field("mesh", &self.mesh)
            .field("domain", &self.domain)
            .finish()
    }
}

impl<S: Scalar> BezierSurface<S> {
    /// The patch of this control mesh (rows i along u, columns j along v).
    pub fn try_new(mesh: Mesh<S>) -> Result<Self, SurfaceError> {
        // non-empty and of one dimension, checked where the points lie (no copy)
        let mesh = mesh.checked()?;
        Ok(BezierSurface {
            mesh,
            domain: Domain::unit(),
            integer: OnceLock::new(),
        })
    }

    /// The patch of a mesh given as rows of points.
    pub fn from_rows(rows: Vec<Vec<Point<S>>>) -> Result<Self, SurfaceError> {
        Ok(BezierSurface {
            mesh: Mesh::mesh(rows)?,
            domain: Domain::unit(),
            integer: OnceLock::new(),
        })
    }

    /// A patch from a mesh already checked (built by an algorithm of this crate).
    pub(crate) fn from_parts(mesh: Mesh<S>, domain: Domain<S>) -> Self {
        BezierSurface {
            mesh,
            domain,
            integer: OnceLock::new(),
        }
    }

    /// The same mesh on the domain [a, b] x [c, d]: the affine reparametrization
    /// `c̃(ũ, ṽ) = c((ũ - a)/(b - a), (ṽ - c)/(d - c))` of the notes, §3. An error unless
    /// a < b and c < d.
    ///
    /// ```
    /// use cagd_surface::BezierSurface;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational};
    /// let s = BezierSurface::<BigRational>::from_rows(vec![
    ///     vec![Point::from_ints(&[0, 0, 0]), Point::from_ints(&[0, 1, 0])],
    ///     vec![Point::from_ints(&[1, 0, 0]), Point::from_ints(&[1, 1, 1])],
    /// ]).unwrap();
    /// let t = s.clone().with_domain(q!(2), q!(4), q!(0), q!(1)).unwrap();
    /// assert_eq!(t.eval(&q!(3), &q!(1/2)).unwrap(), s.eval(&q!(1/2), &q!(1/2)).unwrap());
    /// assert!(s.with_domain(q!(1), q!(1), q!(0), q!(1)).is_err());
    /// ```
    pub fn with_domain(self, a: S, b: S, c: S, d: S) -> Result<Self, SurfaceError> {
        Ok(BezierSurface {
            domain: Domain::new(a, b, c, d)?,
            ..self
        })
    }

    /// The parameter domain (by default [0, 1] x [0, 1]).
    pub fn domain(&self) -> &Domain<S> {
        &self.domain
    }

    /// The control mesh.
    pub fn mesh(&self) -> &Mesh<S> {
        &self.mesh
    }

    /// The mesh on integers (computed once), when every coordinate is rational.
    pub(crate) fn integer_mesh(&self) -> Option<&IntegerMesh> {
        self.integer
            .get_or_init(|| crate::fast::integer_mesh(&self.mesh))
            .as_ref()
    }

    /// The control mesh, consuming the patch.
    pub fn into_mesh(self) -> Mesh<S> {
        self.mesh
    }

    /// The mesh as text, rows separated by `;` (see [`Mesh::to_text`]).
    pub fn to_text(&self) -> String {
        self.mesh.to_text()
    }

    /// The bidegree (m, n).
    pub fn bidegree(&self) -> (usize, usize) {
        (self.mesh.rows() - 1, self.mesh.cols() - 1)
    }

    /// The dimension of the control points.
    pub fn dim(&self) -> usize {
        self.mesh.dim()
    }
}

/// A rational Bézier patch: c(u, v) = Σ w_ij c_ij B_i^m B_j^n / Σ w_ij B_i^m B_j^n
/// (notes, chapter 5, eq. (5)).
#[derive(Clone, PartialEq, Eq, Debug)]
pub struct RationalBezierSurface<S> {
    mesh: Mesh<S>,
    weights: Grid<S>,
    domain: Domain<S>,
}

impl<S: Scalar> RationalBezierSurface<S> {
    /// The patch of this mesh and weights; the weights must have the mesh's shape and be
    /// nonzero (negative weights are allowed but break the convex-hull property).
    pub fn try_new(mesh: Mesh<S>, weights: Grid<S>) -> Result<Self, SurfaceError> {
        let mesh = mesh.checked()?;
        if (mesh.rows(), mesh.cols()) != (weights.rows(), weights.cols()) {
            return Err(SurfaceError::WeightShape {
                mesh: (mesh.rows(), mesh.cols()),
                weights: (weights.rows(), weights.cols()),
            });
        }
        if let Some(((i, j), _)) = weights.indexed().find(|(_, w)| w.is_zero()) {
            return Err(SurfaceError::ZeroWeight { row: i, col: j });
        }
        Ok(RationalBezierSurface {
            mesh,
            weights,
            domain: Domain::unit(),
        })
    }

    /// The patch of a mesh and weights given as rows.
    pub fn from_rows(rows: Vec<Vec<Point<S>>>, weights: Vec<Vec<S>>) -> Result<Self, SurfaceError> {
        Self::try_new(Mesh::mesh(rows)?, Grid::from_rows(weights)?)
    }

    /// The same mesh and weights on the domain [a, b] x [c, d] (the affine reparametrization
    /// of §3); an error unless a < b and c < d.
    pub fn with_domain(self, a: S, b: S, c: S, d: S) -> Result<Self, SurfaceError> {
        Ok(RationalBezierSurface {
            domain: Domain::new(a, b, c, d)?,
            ..self
        })
    }

    /// The same patch on a domain already checked.
    pub(crate) fn on_domain(self, domain: Domain<S>) -> Self {
        RationalBezierSurface { domain, ..self }
    }

    /// The parameter domain (by default [0, 1] x [0, 1]).
    pub fn domain(&self) -> &Domain<S> {
        &self.domain
    }

    /// The polynomial patch of the homogeneous mesh (weight last), on the same domain.
    pub fn homogeneous_patch(&self) -> BezierSurface<S> {
        BezierSurface::from_parts(self.homogeneous(), self.domain.clone())
    }

    /// The rational patch whose homogeneous form is the polynomial patch `h` (same domain).
    pub fn from_homogeneous_patch(h: &BezierSurface<S>) -> Result<Self, SurfaceError> {
        Ok(Self::from_homogeneous(h.mesh())?.on_domain(h.domain().clone()))
    }

    /// The mesh and weights as text: `{(1, 0, 0), ...} with weights {1, √2/2, ...}`.
    pub fn to_text(&self) -> String {
        format!(
            "{} with weights {}",
            self.mesh.to_text(),
            self.weights.to_text_numbers()
        )
    }

    /// The control mesh.
    pub fn mesh(&self) -> &Mesh<S> {
        &self.mesh
    }

    /// The weights w_ij.
    pub fn weights(&self) -> &Grid<S> {
        &self.weights
    }

    /// The bidegree (m, n).
    pub fn bidegree(&self) -> (usize, usize) {
        (self.mesh.rows() - 1, self.mesh.cols() - 1)
    }

    /// Every weight is positive (then the patch lies in the convex hull of its mesh).
    pub fn has_positive_weights(&self) -> bool {
        self.weights.iter().all(|w| *w > S::zero())
    }

    /// The homogeneous mesh (w_ij c_ij, w_ij) in R^{d+1}, weight last: the polynomial patch
    /// whose projection is this one. Every polynomial algorithm applies to it.
    pub fn homogeneous(&self) -> Mesh<S> {
        Grid::from_fn(self.mesh.rows(), self.mesh.cols(), |i, j| {
            match (self.mesh.get(i, j), self.weights.get(i, j)) {
                (Some(p), Some(w)) => p.to_homogeneous(w),
                _ => Point::zero(0),
            }
        })
    }

    /// The rational patch of a homogeneous mesh (weight last), on [0, 1] x [0, 1]; an error for
    /// a zero weight or points without coordinates.
    pub fn from_homogeneous(h: &Mesh<S>) -> Result<Self, SurfaceError> {
        if h.dim() == 0 {
            return Err(SurfaceError::Dimension {
                what: crate::Computation::HomogeneousMesh,
                expected: 1,
                found: 0,
            });
        }
        let mut points = Vec::with_capacity(h.rows());
        let mut weights = Vec::with_capacity(h.rows());
        for (i, row) in h.to_rows().into_iter().enumerate() {
            let mut prow = Vec::with_capacity(row.len());
            let mut wrow = Vec::with_capacity(row.len());
            for (j, q) in row.iter().enumerate() {
                let (p, w) = q
                    .from_homogeneous()
                    .ok_or(SurfaceError::ZeroWeight { row: i, col: j })?;
                prow.push(p);
                wrow.push(w);
            }
            points.push(prow);
            weights.push(wrow);
        }
        Self::try_new(Mesh::mesh(points)?, Grid::from_rows(weights)?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{parse_number, BigRational, Quadratic};

    #[test]
    fn weights_are_checked() {
        let mesh: Mesh<BigRational> = Mesh::mesh(vec![
            vec![Point::from_ints(&[1, 0, 0]), Point::from_ints(&[1, 1, 0])],
            vec![Point::from_ints(&[0, 0, 1]), Point::from_ints(&[0, 0, 1])],
        ])
        .unwrap();
        let bad = Grid::from_rows(vec![vec![cagd_scalar::q!(1), cagd_scalar::q!(0)]]).unwrap();
        assert_eq!(
            RationalBezierSurface::try_new(mesh.clone(), bad)
                .unwrap_err()
                .to_string(),
            "the weights form a 1x2 grid but the mesh is 2x2"
        );
        let zero = Grid::from_rows(vec![
            vec![cagd_scalar::q!(1), cagd_scalar::q!(1)],
            vec![cagd_scalar::q!(0), cagd_scalar::q!(1)],
        ])
        .unwrap();
        assert_eq!(
            RationalBezierSurface::try_new(mesh, zero)
                .unwrap_err()
                .to_string(),
            "weight w_1,0 is zero: weights must be nonzero"
        );
    }

    #[test]
    fn homogeneous_round_trip_in_the_quadratic_field() {
        let h = parse_number("sqrt2/2").unwrap();
        let one = Quadratic::from_rational(cagd_scalar::q!(1));
        let mesh = Mesh::mesh(vec![vec![
            Point::from_ints(&[1, 0, 0]),
            Point::from_ints(&[1, 1, 0]),
            Point::from_ints(&[0, 1, 0]),
        ]])
        .unwrap();
        let w = Grid::from_rows(vec![vec![one.clone(), h.clone(), one]]).unwrap();
        let s = RationalBezierSurface::try_new(mesh, w).unwrap();
        assert!(s.has_positive_weights());
        let back = RationalBezierSurface::from_homogeneous(&s.homogeneous()).unwrap();
        assert_eq!(back, s);
        assert_eq!(
            s.homogeneous().get(0, 1).unwrap().to_text(),
            "(√2/2, √2/2, 0, √2/2)"
        );
    }
}
