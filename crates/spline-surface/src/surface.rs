//! The B-spline surface (notes, eq. (4)): two knot vectors and a control mesh, validated once.

use crate::{Direction, SplineSurfaceError};
use cagd_bspline::{BSplineError, KnotConvention, KnotVector};
use cagd_linalg::Point;
use cagd_scalar::Scalar;
use cagd_surface::Mesh;

/// A knot vector with a control polygon: what every curve algorithm of `cagd-bspline` takes
/// and returns.
pub(crate) type Spline<S> = (KnotVector<S>, Vec<Point<S>>);

/// A B-spline surface of bidegree (p, q) (the notes' (m, n)) with M x N spans (notes, eq. (4)):
///
/// `c(u, v) = Σ_{i=0}^{p+M-1} Σ_{j=0}^{q+N-1} d_{i,j} N_i^p(u) N_j^q(v)`,
///
/// on the domain `[u_{p-1}, u_{p+M-1}] x [v_{q-1}, v_{q+N-1}]` (notes' convention: knots
/// `u_0, ..., u_{2p+M-2}` and `v_0, ..., v_{2q+N-2}`, see [`KnotVector`]). Row i of the mesh
/// goes with `N_i^p(u)`, column j with `N_j^q(v)`: the mesh has one row per control point of
/// the knots in u and one column per control point of the knots in v.
///
/// Every algorithm is a curve algorithm of `cagd-bspline` applied "en dos pasadas" (notes, §2):
/// in u to every column of the mesh, in v to every row.
///
/// ```
/// use cagd_spline_surface::BSplineSurface;
/// use cagd_surface::Mesh;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// // Bilinear in u on [0, 2] with a knot at 1 (3 rows), linear in v (2 columns): z = u v.
/// let p = |c: &[i64]| Point::<BigRational>::from_ints(c);
/// let mesh = Mesh::mesh(vec![
///     vec![p(&[0, 0, 0]), p(&[0, 1, 0])],
///     vec![p(&[1, 0, 0]), p(&[1, 1, 1])],
///     vec![p(&[2, 0, 0]), p(&[2, 1, 2])],
/// ]).unwrap();
/// let (s, _) = BSplineSurface::read((1, 1), (vec![q!(0), q!(1), q!(2)], vec![q!(0), q!(1)]), mesh).unwrap();
/// assert_eq!(s.eval(&q!(3/2), &q!(1/3)).unwrap().to_text(), "(3/2, 1/3, 1/2)");
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BSplineSurface<S> {
    knots_u: KnotVector<S>,
    knots_v: KnotVector<S>,
    mesh: Mesh<S>,
}

impl<S: Scalar> BSplineSurface<S> {
    /// The surface with these knot vectors (degree p in u, q in v) and control mesh: an error
    /// unless the mesh has as many rows as `knots_u` has control points and as many columns as
    /// `knots_v` has, all points of one dimension.
    ///
    /// ```
    /// use cagd_spline_surface::BSplineSurface;
    /// use cagd_bspline::KnotVector;
    /// use cagd_surface::Mesh;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational};
    /// let u = KnotVector::clamped(2, &[q!(0), q!(1)]).unwrap(); // 3 control points
    /// let v = KnotVector::clamped(1, &[q!(0), q!(1)]).unwrap(); // 2 control points
    /// let mesh: Mesh<BigRational> = Mesh::mesh(vec![vec![Point::from_ints(&[0, 0]); 2]; 2]).unwrap();
    /// assert_eq!(
    ///     BSplineSurface::try_new(u, v, mesh).unwrap_err().to_string(),
    ///     "the knot vectors are made for a mesh of 3 x 2 control points (3 rows for the knots \
    ///      in u of degree 2, 2 columns for the knots in v of degree 1), but the mesh is 2 x 2"
    /// );
    /// ```
    pub fn try_new(
        knots_u: KnotVector<S>,
        knots_v: KnotVector<S>,
        mesh: Mesh<S>,
    ) -> Result<Self, SplineSurfaceError> {
        let (rows_expected, cols_expected) =
            (knots_u.control_point_count(), knots_v.control_point_count());
        if (mesh.rows(), mesh.cols()) != (rows_expected, cols_expected) {
            return Err(SplineSurfaceError::MeshShape {
                rows_expected,
                cols_expected,
                degree_u: knots_u.degree(),
                degree_v: knots_v.degree(),
                rows: mesh.rows(),
                cols: mesh.cols(),
            });
        }
        // The shape is right; re-check the dimensions of a mesh built by hand.
        let mesh = Mesh::mesh(mesh.to_rows())?;
        Ok(BSplineSurface {
            knots_u,
            knots_v,
            mesh,
        })
    }

    /// The surface of bidegree `(p, q)` with knots `(in u, in v)`, each in either convention
    /// (told apart by length, see [`KnotVector::read`]): for a mesh of R rows and C columns,
    /// R + p - 1 knots in u in the notes' convention or R + p + 1 in the full one, and likewise
    /// in v. Returns the conventions read `(in u, in v)`.
    ///
    /// ```
    /// use cagd_spline_surface::BSplineSurface;
    /// use cagd_bspline::KnotConvention;
    /// use cagd_surface::Mesh;
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational};
    /// let mesh: Mesh<BigRational> = Mesh::mesh(vec![vec![Point::from_ints(&[0, 0]); 3]; 2]).unwrap();
    /// let (s, conv) = BSplineSurface::read(
    ///     (1, 2),
    ///     (vec![q!(0), q!(1)], vec![q!(0), q!(0), q!(0), q!(1), q!(1), q!(1)]),
    ///     mesh.clone(),
    /// ).unwrap();
    /// assert_eq!(conv, (KnotConvention::Notes, KnotConvention::Full));
    /// assert_eq!(s.knots_v().to_text(), "{0, 0, 1, 1}");
    /// let err = BSplineSurface::read((1, 2), (vec![q!(1), q!(0)], vec![q!(0), q!(0), q!(1), q!(1)]), mesh)
    ///     .unwrap_err();
    /// assert_eq!(err.to_string(), "knot vector in u: knot vector decreases at index 1: 1 > 0");
    /// ```
    pub fn read(
        degree: (usize, usize),
        knots: (Vec<S>, Vec<S>),
        mesh: Mesh<S>,
    ) -> Result<(Self, (KnotConvention, KnotConvention)), SplineSurfaceError> {
        let (knots_u, conv_u) = KnotVector::read(knots.0, degree.0, mesh.rows())
            .map_err(SplineSurfaceError::knots(Direction::U))?;
        let (knots_v, conv_v) = KnotVector::read(knots.1, degree.1, mesh.cols())
            .map_err(SplineSurfaceError::knots(Direction::V))?;
        Ok((Self::try_new(knots_u, knots_v, mesh)?, (conv_u, conv_v)))
    }

    /// A surface from parts known to fit (the output of an algorithm of this crate).
    pub(crate) fn from_parts(
        knots_u: KnotVector<S>,
        knots_v: KnotVector<S>,
        mesh: Mesh<S>,
    ) -> Self {
        BSplineSurface {
            knots_u,
            knots_v,
            mesh,
        }
    }

    /// The bidegree (p, q).
    pub fn bidegree(&self) -> (usize, usize) {
        (self.knots_u.degree(), self.knots_v.degree())
    }

    /// The same surface on the domain [0, 1] x [0, 1]: each knot vector reparametrized
    /// affinely onto [0, 1] ([`KnotVector::normalized`]), the same mesh; its point at (s, r) is
    /// this surface's at (a + s (b - a), c + r (d - c)) on [a, b] x [c, d].
    pub fn normalized(&self) -> Self {
        BSplineSurface {
            knots_u: self.knots_u.normalized(),
            knots_v: self.knots_v.normalized(),
            mesh: self.mesh.clone(),
        }
    }

    /// The knot vector in u (degree p).
    pub fn knots_u(&self) -> &KnotVector<S> {
        &self.knots_u
    }

    /// The knot vector in v (degree q).
    pub fn knots_v(&self) -> &KnotVector<S> {
        &self.knots_v
    }

    /// The knot vector of a direction.
    pub fn knots(&self, direction: Direction) -> &KnotVector<S> {
        match direction {
            Direction::U => &self.knots_u,
            Direction::V => &self.knots_v,
        }
    }

    /// The control mesh `d_{i,j}` (rows i along u, columns j along v).
    pub fn mesh(&self) -> &Mesh<S> {
        &self.mesh
    }

    /// The knot vectors and the mesh, consuming the surface.
    pub fn into_parts(self) -> (KnotVector<S>, KnotVector<S>, Mesh<S>) {
        (self.knots_u, self.knots_v, self.mesh)
    }

    /// The dimension of the control points.
    pub fn dim(&self) -> usize {
        self.mesh.dim()
    }

    /// The number of non-empty spans (M, N) in u and in v.
    pub fn spans(&self) -> (usize, usize) {
        (self.knots_u.spans().len(), self.knots_v.spans().len())
    }

    /// The domain `([u_{p-1}, u_{p+M-1}], [v_{q-1}, v_{q+N-1}])` (notes' indices; see
    /// [`KnotVector::domain`]).
    pub fn domain(&self) -> ((S, S), (S, S)) {
        (self.knots_u.domain(), self.knots_v.domain())
    }

    /// The domain as text, `[0, 1] x [0, 4]`.
    pub fn domain_text(&self) -> String {
        domain_text(&self.knots_u, &self.knots_v)
    }

    /// An error naming the parameter and the domain unless (u, v) lies in the domain (borders
    /// included).
    pub fn check_parameters(&self, u: &S, v: &S) -> Result<(), SplineSurfaceError> {
        check_parameters(&self.knots_u, &self.knots_v, u, v)
    }

    /// Applies a curve algorithm to every curve of the mesh in `direction` ("en dos pasadas",
    /// notes §2): in u to every column `d_{0,j}, ..., d_{M,j}` with the knots in u, in v to
    /// every row `d_{i,0}, ..., d_{i,N}` with the knots in v. The algorithm's knot vector (the
    /// same for every curve, as it depends on the knots alone) replaces that direction's.
    pub(crate) fn map_curves(
        &self,
        direction: Direction,
        f: impl Fn(&KnotVector<S>, &[Point<S>]) -> Result<Spline<S>, BSplineError>,
    ) -> Result<Self, SplineSurfaceError> {
        let knots = self.knots(direction);
        let mut new_knots: Option<KnotVector<S>> = None;
        let mut pass = |points: &[Point<S>]| -> Result<Vec<Point<S>>, SplineSurfaceError> {
            let (k, d) = f(knots, points).map_err(SplineSurfaceError::curve(direction))?;
            new_knots.get_or_insert(k);
            Ok(d)
        };
        let mesh = match direction {
            Direction::U => self.mesh.map_columns(&mut pass)?,
            Direction::V => self.mesh.map_rows(&mut pass)?,
        };
        let new_knots = new_knots.unwrap_or_else(|| knots.clone());
        Ok(match direction {
            Direction::U => Self::from_parts(new_knots, self.knots_v.clone(), mesh),
            Direction::V => Self::from_parts(self.knots_u.clone(), new_knots, mesh),
        })
    }

    /// The rows (or columns) of the mesh: the control polygons of the curves in `direction`.
    pub(crate) fn curves(&self, direction: Direction) -> Vec<Vec<Point<S>>> {
        match direction {
            Direction::U => self.mesh.to_columns(),
            Direction::V => self.mesh.to_rows(),
        }
    }
}

/// `[a, b] x [c, d]` of two knot vectors.
pub(crate) fn domain_text<S: Scalar>(u: &KnotVector<S>, v: &KnotVector<S>) -> String {
    format!(
        "[{}, {}] x [{}, {}]",
        u.start().to_text(),
        u.end().to_text(),
        v.start().to_text(),
        v.end().to_text()
    )
}

/// The error naming the first parameter outside its knot vector's domain.
pub(crate) fn check_parameters<S: Scalar>(
    knots_u: &KnotVector<S>,
    knots_v: &KnotVector<S>,
    u: &S,
    v: &S,
) -> Result<(), SplineSurfaceError> {
    for (direction, knots, t) in [(Direction::U, knots_u, u), (Direction::V, knots_v, v)] {
        if !knots.contains(t) {
            return Err(SplineSurfaceError::OutsideDomain {
                direction,
                value: t.to_text(),
                domain: domain_text(knots_u, knots_v),
            });
        }
    }
    Ok(())
}
