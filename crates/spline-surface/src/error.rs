//! The one error type of cagd-spline-surface, and the two parameter directions.

use cagd_bspline::BSplineError;
use cagd_surface::SurfaceError;
use cagd_words::{said, Lang, Message, Phrase};
use std::fmt;

/// One of the two parameter directions of a tensor-product surface.
///
/// The mesh `d_{i,j}` has its rows i along u and its columns j along v (notes, eq. (4)): a
/// curve algorithm "in u" runs on every column `d_{0,j}, ..., d_{M,j}` with the knots in u; one
/// "in v" runs on every row `d_{i,0}, ..., d_{i,N}` with the knots in v.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default, strum::EnumIter)]
pub enum Direction {
    /// The first parameter u: the index i of `d_{i,j}`, down the columns of the mesh.
    #[default]
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
}

impl fmt::Display for Direction {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// What can go wrong with a B-spline or NURBS surface.
///
/// Numbers inside the messages are written exactly (`3/2`, `√2/2`).
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
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
        source: Box<BSplineError>,
    },
    /// A curve algorithm failed on the rows or columns of the mesh (a knot outside the domain,
    /// inserted too many times, a derivative of degree 0, ...).
    Curve {
        /// The direction the algorithm ran in.
        direction: Direction,
        /// What went wrong.
        source: Box<BSplineError>,
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
        /// Why.
        reason: NotSingle,
    },
    /// An error of the mesh or of a Bézier patch.
    Surface(SurfaceError),
}

/// Why a B-spline surface is not a single Bézier patch in a direction
/// ([`SplineSurfaceError::NotBezier`]).
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
#[non_exhaustive]
pub enum NotSingle {
    /// Not p + 1 control points for degree p.
    PointCount {
        /// The number of control points in that direction.
        count: usize,
        /// The degree p.
        degree: usize,
    },
    /// Knots not clamped.
    NotClamped {
        /// The knots, as text.
        knots: String,
        /// The degree p.
        degree: usize,
    },
}

impl Default for NotSingle {
    fn default() -> Self {
        NotSingle::PointCount {
            count: 0,
            degree: 0,
        }
    }
}

impl Message for NotSingle {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            NotSingle::PointCount { count, degree } => said(
                lang,
                "‹› control points for degree ‹› (a single Bézier piece has ‹›)",
                "‹› puntos de control para el grado ‹› (un solo trozo de Bézier tiene ‹›)",
                [count.into(), degree.into(), (&(degree + 1)).into()],
            ),
            NotSingle::NotClamped { knots, degree } => said(
                lang,
                "the knots ‹› are not clamped (each end repeated ‹› times)",
                "los nudos ‹› no están sujetos en los extremos (cada extremo repetido ‹› veces)",
                [knots.into(), degree.into()],
            ),
        }
    }
}

impl Message for SplineSurfaceError {
    fn phrase(&self, lang: Lang) -> Phrase {
        use SplineSurfaceError as E;
        match self {
            E::MeshShape {
                rows_expected,
                cols_expected,
                degree_u,
                degree_v,
                rows,
                cols,
            } => said(
                lang,
                "the knot vectors are made for a mesh of ‹› x ‹› control points (‹› rows for the knots in u of degree ‹›, ‹› columns for the knots in v of degree ‹›), but the mesh is ‹› x ‹›",
                "las sucesiones de nudos son para una malla de ‹› x ‹› puntos de control (‹› filas para los nudos en u de grado ‹›, ‹› columnas para los nudos en v de grado ‹›), pero la malla es de ‹› x ‹›",
                [
                    rows_expected.into(),
                    cols_expected.into(),
                    rows_expected.into(),
                    degree_u.into(),
                    cols_expected.into(),
                    degree_v.into(),
                    rows.into(),
                    cols.into(),
                ],
            ),
            E::Knots { direction, source } => said(
                lang,
                "knot vector in ‹›: «»",
                "sucesión de nudos en ‹›: «»",
                [direction.into(), source.phrase(lang).into()],
            ),
            E::Curve { direction, source } => match direction {
                Direction::U => said(
                    lang,
                    "in ‹› (on the columns of the mesh): «»",
                    "en ‹› (en las columnas de la malla): «»",
                    [direction.into(), source.phrase(lang).into()],
                ),
                Direction::V => said(
                    lang,
                    "in ‹› (on the rows of the mesh): «»",
                    "en ‹› (en las filas de la malla): «»",
                    [direction.into(), source.phrase(lang).into()],
                ),
            },
            E::OutsideDomain {
                direction,
                value,
                domain,
            } => said(
                lang,
                "parameter ‹› = ‹› is outside the domain ‹›",
                "el parámetro ‹› = ‹› está fuera del recinto ‹›",
                [direction.into(), value.into(), domain.into()],
            ),
            E::WeightShape { mesh, weights } => said(
                lang,
                "the weights form a ‹›x‹› grid but the mesh is ‹›x‹›",
                "los pesos forman una matriz de ‹›x‹›, pero la malla de control es de ‹›x‹›",
                [
                    (&weights.0).into(),
                    (&weights.1).into(),
                    (&mesh.0).into(),
                    (&mesh.1).into(),
                ],
            ),
            E::ZeroWeight { row, col } => said(
                lang,
                "weight $w_‹›,‹›$ is zero: weights must be nonzero",
                "el peso $w_‹›,‹›$ es cero: los pesos han de ser no nulos",
                [row.into(), col.into()],
            ),
            E::PointAtInfinity { u, v } => said(
                lang,
                "the denominator of the rational surface vanishes at $(u, v) = (‹›, ‹›)$: the point is at infinity",
                "el denominador de la superficie racional se anula en $(u, v) = (‹›, ‹›)$: el punto está en el infinito",
                [u.into(), v.into()],
            ),
            E::NotBezier { direction, reason } => said(
                lang,
                "not a single Bézier patch in ‹›: «»",
                "no es un solo trozo de Bézier en ‹›: «»",
                [direction.into(), reason.phrase(lang).into()],
            ),
            E::Surface(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
        }
    }
}

cagd_words::display_english!(SplineSurfaceError, NotSingle);

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
        move |source| SplineSurfaceError::Curve {
            direction,
            source: Box::new(source),
        }
    }

    /// Wraps an error of the knot vector of `direction`.
    pub(crate) fn knots(direction: Direction) -> impl Fn(BSplineError) -> Self {
        move |source| SplineSurfaceError::Knots {
            direction,
            source: Box::new(source),
        }
    }
}

impl Default for SplineSurfaceError {
    fn default() -> Self {
        SplineSurfaceError::Surface(SurfaceError::default())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_variant_in_both_languages() {
        for m in SplineSurfaceError::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        for reason in NotSingle::iter() {
            for direction in Direction::iter() {
                let m = SplineSurfaceError::NotBezier {
                    direction,
                    reason: reason.clone(),
                };
                assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
            }
        }
        // each direction (the enumeration gives the default one; the inner errors are
        // enumerated with cagd-bspline's)
        for direction in Direction::iter() {
            let source = Box::<BSplineError>::default();
            for m in [
                SplineSurfaceError::Knots {
                    direction,
                    source: source.clone(),
                },
                SplineSurfaceError::Curve { direction, source },
            ] {
                assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
            }
        }
    }
}
