//! The one error type of cagd-spline-surface, and the two parameter directions.

use cagd_bspline::BSplineError;
use cagd_surface::SurfaceError;
use std::fmt;

/// One of the two parameter directions of a tensor-product surface.
///
/// The mesh `d_{i,j}` has its rows i along u and its columns j along v (notes, eq. (4)): a
/// curve algorithm "in u" runs on every column `d_{0,j}, ..., d_{M,j}` with the knots in u; one
/// "in v" runs on every row `d_{i,0}, ..., d_{i,N}` with the knots in v.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Direction {
    /// The first parameter u: the index i of `d_{i,j}`, down the columns of the mesh.
    U,
    /// The second parameter v: the index j of `d_{i,j}`, along the rows of the mesh.
    V,
}

impl Direction {
    /// The other direction.
    pub fn other(self) -> Self {
        match self {
            Direction::U => Direction::V,
            Direction::V => Direction::U,
        }
    }

    /// `"u"` or `"v"`.
    pub fn name(self) -> &'static str {
        match self {
            Direction::U => "u",
            Direction::V => "v",
        }
    }

    /// What the curves of this direction are, for messages.
    fn curves(self) -> &'static str {
        match self {
            Direction::U => "on the columns of the mesh",
            Direction::V => "on the rows of the mesh",
        }
    }
}

impl fmt::Display for Direction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// What can go wrong with a B-spline or NURBS surface.
///
/// Numbers inside the messages are written exactly (`3/2`, `√2/2`).
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum SplineSurfaceError {
    /// The mesh does not have one row per control point of the knots in u and one column per
    /// control point of the knots in v.
    MeshShape {
        /// The number of rows the knots in u are made for.
        rows_expected: usize,
        /// The number of columns the knots in v are made for.
        cols_expected: usize,
        /// The degree p in u.
        degree_u: usize,
        /// The degree q in v.
        degree_v: usize,
        /// The rows of the mesh given.
        rows: usize,
        /// The columns of the mesh given.
        cols: usize,
    },
    /// An invalid knot vector in one direction (wrong length, decreasing, ...).
    Knots {
        /// The direction of the knot vector.
        direction: Direction,
        /// What is wrong with it.
        source: BSplineError,
    },
    /// A curve algorithm failed on the rows or columns of the mesh (a knot outside the domain,
    /// inserted too many times, a derivative of degree 0, ...).
    Curve {
        /// The direction the algorithm ran in.
        direction: Direction,
        /// What went wrong.
        source: BSplineError,
    },
    /// A parameter outside the domain `[u_{p-1}, u_{p+M-1}] x [v_{q-1}, v_{q+N-1}]`.
    OutsideDomain {
        /// Which parameter.
        direction: Direction,
        /// Its value, as text.
        value: String,
        /// The domain, as text: `[0, 1] x [0, 4]`.
        domain: String,
    },
    /// A weight grid that does not have the mesh's shape.
    WeightShape {
        /// Mesh shape (rows, columns).
        mesh: (usize, usize),
        /// Weight grid shape.
        weights: (usize, usize),
    },
    /// A zero weight `w_{i,j}`.
    ZeroWeight {
        /// Its row i.
        row: usize,
        /// Its column j.
        col: usize,
    },
    /// The denominator of (6) vanishes at (u, v) (possible with negative weights).
    PointAtInfinity {
        /// u, as text.
        u: String,
        /// v, as text.
        v: String,
    },
    /// The surface is not a single Bézier patch in some direction.
    NotBezier {
        /// The direction where it is not.
        direction: Direction,
        /// Why, in words.
        reason: String,
    },
    /// An error of the mesh or of a Bézier patch.
    Surface(SurfaceError),
}

impl fmt::Display for SplineSurfaceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use SplineSurfaceError as E;
        match self {
            E::MeshShape {
                rows_expected,
                cols_expected,
                degree_u,
                degree_v,
                rows,
                cols,
            } => write!(
                f,
                "the knot vectors are made for a mesh of {rows_expected} x {cols_expected} control \
                 points ({rows_expected} rows for the knots in u of degree {degree_u}, \
                 {cols_expected} columns for the knots in v of degree {degree_v}), but the mesh is \
                 {rows} x {cols}"
            ),
            E::Knots { direction, source } => {
                write!(f, "knot vector in {direction}: {source}")
            }
            E::Curve { direction, source } => {
                write!(f, "in {direction} ({}): {source}", direction.curves())
            }
            E::OutsideDomain {
                direction,
                value,
                domain,
            } => write!(
                f,
                "parameter {direction} = {value} is outside the domain {domain}"
            ),
            E::WeightShape { mesh, weights } => write!(
                f,
                "the weights form a {}x{} grid but the mesh is {}x{}",
                weights.0, weights.1, mesh.0, mesh.1
            ),
            E::ZeroWeight { row, col } => {
                write!(f, "weight w_{row},{col} is zero: weights must be nonzero")
            }
            E::PointAtInfinity { u, v } => write!(
                f,
                "the denominator of the rational surface vanishes at (u, v) = ({u}, {v}): the \
                 point is at infinity"
            ),
            E::NotBezier { direction, reason } => {
                write!(f, "not a single Bézier patch in {direction}: {reason}")
            }
            E::Surface(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for SplineSurfaceError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            SplineSurfaceError::Knots { source, .. } | SplineSurfaceError::Curve { source, .. } => {
                Some(source)
            }
            SplineSurfaceError::Surface(e) => Some(e),
            _ => None,
        }
    }
}

impl From<SurfaceError> for SplineSurfaceError {
    fn from(e: SurfaceError) -> Self {
        SplineSurfaceError::Surface(e)
    }
}

impl SplineSurfaceError {
    /// Wraps an error of a curve algorithm run in `direction`.
    pub(crate) fn curve(direction: Direction) -> impl Fn(BSplineError) -> Self {
        move |source| SplineSurfaceError::Curve { direction, source }
    }

    /// Wraps an error of the knot vector of `direction`.
    pub(crate) fn knots(direction: Direction) -> impl Fn(BSplineError) -> Self {
        move |source| SplineSurfaceError::Knots { direction, source }
    }
}
