use crate::Corner;
use cagd_bezier::BezierError;
use cagd_linalg::LinalgError;
use cagd_poly::PolyError;
use cagd_words::{said, Lang, Message, Phrase};

/// What can go wrong with a surface.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
#[non_exhaustive]
pub enum SurfaceError {
    /// A mesh with no rows or no columns.
    EmptyMesh,
    /// A mesh whose rows differ in length.
    RaggedMesh {
        /// The row that differs.
        row: usize,
        /// Its length.
        len: usize,
        /// The length of row 0.
        expected: usize,
    },
    /// Control points of different dimensions.
    MixedDimensions {
        /// Where the odd point is, `c_ij`.
        row: usize,
        /// Its column.
        col: usize,
        /// Its dimension.
        found: usize,
        /// The dimension of c_00.
        expected: usize,
    },
    /// A weight grid that does not have the mesh's shape.
    WeightShape {
        /// Mesh shape (rows, columns).
        mesh: (usize, usize),
        /// Weight grid shape.
        weights: (usize, usize),
    },
    /// A zero weight.
    ZeroWeight {
        /// Row of the weight.
        row: usize,
        /// Column of the weight.
        col: usize,
    },
    /// A parameter outside the patch's domain.
    OutOfDomain {
        /// Which parameter ("u" or "v").
        param: &'static str,
        /// Its value, as text.
        value: String,
        /// The domain, as text.
        domain: String,
    },
    /// The denominator of a rational patch vanishes at a parameter.
    ZeroDenominator {
        /// The parameter, as text.
        at: String,
    },
    /// A domain [a, b] x [c, d] with a >= b or c >= d.
    DegenerateDomain {
        /// Which parameter ("u" or "v").
        param: &'static str,
        /// The left end, as text.
        a: String,
        /// The right end, as text.
        b: String,
    },
    /// A subdivision parameter at (or beyond) an end of the domain: a piece would be empty.
    NotInterior {
        /// Which parameter ("u" or "v").
        param: &'static str,
        /// Its value, as text.
        value: String,
        /// The interval of that parameter, as text.
        interval: String,
    },
    /// The polar form of a patch of bidegree (m, n) takes m values of u and n values of v.
    BlossomArguments {
        /// Which group ("u" or "v").
        param: &'static str,
        /// The degree in that parameter.
        degree: usize,
        /// How many values were given.
        found: usize,
    },
    /// Forward differences Δ^{r,s} c_ij need r <= m and s <= n.
    DifferenceOrder {
        /// The order in u.
        r: usize,
        /// The order in v.
        s: usize,
        /// The bidegree (m, n).
        bidegree: (usize, usize),
    },
    /// The graph of f(x, y) as a patch of bidegree (m, n) needs f of degree <= m in x and
    /// <= n in y, and m, n >= 1.
    GraphDegree {
        /// The variable of f.
        var: String,
        /// The degree of f in it.
        degree: u32,
        /// The degree of the patch in the matching parameter.
        max: usize,
    },
    /// Something that needs points of a given dimension (the normal c_u x c_v needs R^3).
    Dimension {
        /// What was being computed.
        what: Computation,
        /// The dimension it needs.
        expected: usize,
        /// The dimension found.
        found: usize,
    },
    /// A value that must be positive is not (a parameter length Δu, a weight for the
    /// convex-hull property).
    NotPositive {
        /// What the value is.
        what: Positive,
        /// The value, as text.
        value: String,
    },
    /// Two patches that cannot be compared along a border: their borders have different
    /// degrees.
    BorderDegree {
        /// The parameter along the border ("u" or "v").
        param: &'static str,
        /// The degree of the first patch along it.
        first: usize,
        /// The degree of the second patch along it.
        second: usize,
    },
    /// A C^r neighbour asked of a patch with fewer than r + 1 rows across the border.
    Order {
        /// The order r of continuity asked for.
        r: usize,
        /// The degree m of the patch across the border.
        degree: usize,
        /// The parameter across the border ("u" or "v").
        param: String,
    },
    /// The weight of a rational patch vanishes at a corner, where its normal is asked.
    WeightAtCorner {
        /// The corner.
        corner: Corner,
    },
    /// An error from a curve algorithm applied to a row or column.
    Curve(BezierError),
    /// An error from a polynomial (closed form) computation.
    Poly(PolyError),
    /// An error from linear algebra (a cross product of points not in R^3...).
    Linalg(LinalgError),
}

/// What needs points of a given dimension ([`SurfaceError::Dimension`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Computation {
    /// Joining two patches along a border.
    #[default]
    Join,
    /// A homogeneous mesh, its weight last.
    HomogeneousMesh,
    /// The convex-hull test.
    ConvexHull,
    /// The normal `c_u x c_v`.
    Normal,
}

impl Message for Computation {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Computation::Join => said(lang, "joining two patches", "unir dos superficies", []),
            Computation::HomogeneousMesh => said(
                lang,
                "a homogeneous mesh (weight last)",
                "una malla homogénea (con el peso al final)",
                [],
            ),
            Computation::ConvexHull => said(
                lang,
                "the convex-hull test",
                "la prueba de la envoltura convexa",
                [],
            ),
            Computation::Normal => said(
                lang,
                "the normal $c_u x c_v$",
                "el vector normal $c_u x c_v$",
                [],
            ),
        }
    }
}

/// A value that must be positive ([`SurfaceError::NotPositive`]).
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
#[non_exhaustive]
pub enum Positive {
    /// A parameter length of a join, `Δu_0`.
    ParameterLength {
        /// Its name, `Δu_0`.
        name: String,
    },
    /// A weight `w_ij` of a rational patch, for the convex-hull property.
    Weight {
        /// Its row i.
        row: usize,
        /// Its column j.
        col: usize,
    },
}

impl Default for Positive {
    fn default() -> Self {
        Positive::Weight { row: 0, col: 0 }
    }
}

impl Message for Positive {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Positive::ParameterLength { name } => said(
                lang,
                "the parameter length ‹›",
                "la longitud de parámetro ‹›",
                [name.into()],
            ),
            Positive::Weight { row, col } => said(
                lang,
                "weight $w_‹›,‹›$ (the convex-hull property needs positive weights)",
                "el peso $w_‹›,‹›$ (la propiedad de la envoltura convexa necesita pesos positivos)",
                [row.into(), col.into()],
            ),
        }
    }
}

impl Message for SurfaceError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            SurfaceError::EmptyMesh => {
                said(lang, "the control mesh is empty", "la malla de control está vacía", [])
            }
            SurfaceError::RaggedMesh { row, len, expected } => said(
                lang,
                "row ‹› of the control mesh has ‹› points but row 0 has ‹›: a mesh needs rows of equal length",
                "la fila ‹› de la malla de control tiene ‹› puntos, pero la fila 0 tiene ‹›: las filas de una malla de control han de tener la misma longitud",
                [row.into(), len.into(), expected.into()],
            ),
            SurfaceError::MixedDimensions {
                row,
                col,
                found,
                expected,
            } => said(
                lang,
                "control point $c_‹›,‹›$ has ‹› coordinates but $c_0,0$ has ‹›",
                "el punto de control $c_‹›,‹›$ tiene ‹› coordenadas, pero $c_0,0$ tiene ‹›",
                [row.into(), col.into(), found.into(), expected.into()],
            ),
            SurfaceError::WeightShape { mesh, weights } => said(
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
            SurfaceError::ZeroWeight { row, col } => said(
                lang,
                "weight $w_‹›,‹›$ is zero: weights must be nonzero",
                "el peso $w_‹›,‹›$ es cero: los pesos han de ser no nulos",
                [row.into(), col.into()],
            ),
            SurfaceError::OutOfDomain {
                param,
                value,
                domain,
            } => said(
                lang,
                "parameter ‹› = ‹› is outside the domain ‹›",
                "el parámetro ‹› = ‹› está fuera del recinto ‹›",
                [param.into(), value.into(), domain.into()],
            ),
            SurfaceError::ZeroDenominator { at } => said(
                lang,
                "the denominator of the rational patch vanishes at ‹›: the point is at infinity",
                "el denominador de la superficie racional se anula en ‹›: el punto está en el infinito",
                [at.into()],
            ),
            SurfaceError::DegenerateDomain { param, a, b } => said(
                lang,
                "the interval [‹›, ‹›] of ‹› is degenerate: its ends must satisfy ‹› < ‹›",
                "el intervalo [‹›, ‹›] de ‹› es degenerado: sus extremos han de cumplir ‹› < ‹›",
                [a.into(), b.into(), param.into(), a.into(), b.into()],
            ),
            SurfaceError::NotInterior {
                param,
                value,
                interval,
            } => said(
                lang,
                "subdivision parameter ‹› = ‹› must lie strictly inside ‹›",
                "el parámetro de subdivisión ‹› = ‹› ha de estar en el interior de ‹›",
                [param.into(), value.into(), interval.into()],
            ),
            SurfaceError::BlossomArguments {
                param,
                degree,
                found,
            } => said(
                lang,
                "the polar form takes ‹› values of ‹› (the degree in ‹›), but ‹› were given",
                "la forma polar toma ‹› valores de ‹› (el grado en ‹›), pero se dieron ‹›",
                [degree.into(), param.into(), param.into(), found.into()],
            ),
            SurfaceError::DifferenceOrder { r, s, bidegree } => said(
                lang,
                "the differences $Δ^{‹›,‹›}$ need bidegree at least (‹›, ‹›), but the patch has bidegree (‹›, ‹›)",
                "las diferencias $Δ^{‹›,‹›}$ necesitan bigrado al menos (‹›, ‹›), pero la superficie tiene bigrado (‹›, ‹›)",
                [
                    r.into(),
                    s.into(),
                    r.into(),
                    s.into(),
                    (&bidegree.0).into(),
                    (&bidegree.1).into(),
                ],
            ),
            SurfaceError::GraphDegree { var, degree, max } => {
                let param = if var == "x" || var == "u" { "u" } else { "v" };
                let needed = (*degree).max(1);
                said(
                    lang,
                    "f has degree ‹› in ‹›: its graph needs degree at least ‹› in ‹›, but the patch has degree ‹›",
                    "f tiene grado ‹› en ‹›: su gráfica necesita grado al menos ‹› en ‹›, pero la superficie tiene grado ‹›",
                    [
                        degree.into(),
                        var.into(),
                        (&needed).into(),
                        param.into(),
                        max.into(),
                    ],
                )
            }
            SurfaceError::Dimension {
                what,
                expected,
                found,
            } => said(
                lang,
                "«» needs points with ‹› coordinates, but they have ‹›",
                "«» necesita puntos con ‹› coordenadas, pero tienen ‹›",
                [what.phrase(lang).into(), expected.into(), found.into()],
            ),
            SurfaceError::NotPositive { what, value } => said(
                lang,
                "«» must be positive, but it is ‹›",
                "«» ha de ser mayor que cero, pero es ‹›",
                [what.phrase(lang).into(), value.into()],
            ),
            SurfaceError::BorderDegree {
                param,
                first,
                second,
            } => said(
                lang,
                "the patches do not share a border: along ‹› the first has degree ‹› and the second degree ‹›",
                "las superficies no comparten borde: en ‹› la primera tiene grado ‹› y la segunda grado ‹›",
                [param.into(), first.into(), second.into()],
            ),
            SurfaceError::Order { r, degree, param } => said(
                lang,
                "a $C^‹›$ neighbour is fixed by ‹› rows, but the patch has only ‹› (degree ‹› in ‹›)",
                "una superficie vecina $C^‹›$ queda fijada por ‹› filas, pero esta solo tiene ‹› (grado ‹› en ‹›)",
                [
                    r.into(),
                    (&(r + 1)).into(),
                    (&(degree + 1)).into(),
                    degree.into(),
                    param.into(),
                ],
            ),
            SurfaceError::WeightAtCorner { corner } => said(
                lang,
                "the weight vanishes at corner ‹›",
                "el peso se anula en la esquina ‹›",
                [corner.into()],
            ),
            SurfaceError::Curve(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            SurfaceError::Poly(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            SurfaceError::Linalg(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
        }
    }
}

cagd_words::display_english!(SurfaceError, Computation, Positive);

impl std::error::Error for SurfaceError {}

/// The default is [`SurfaceError::EmptyMesh`] (for the enumeration of the messages that
/// carry one).
impl Default for SurfaceError {
    fn default() -> Self {
        SurfaceError::EmptyMesh
    }
}

impl From<BezierError> for SurfaceError {
    fn from(e: BezierError) -> Self {
        SurfaceError::Curve(e)
    }
}

impl From<PolyError> for SurfaceError {
    fn from(e: PolyError) -> Self {
        SurfaceError::Poly(e)
    }
}

impl From<LinalgError> for SurfaceError {
    fn from(e: LinalgError) -> Self {
        SurfaceError::Linalg(e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_variant_in_both_languages() {
        for m in SurfaceError::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        for m in Computation::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        for m in crate::Smoothness::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        for m in crate::Degeneracy::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
            for limit in [
                None,
                Some(crate::LimitDirection {
                    along: "v = 0".into(),
                    direction: "(0, 0, 1)".into(),
                }),
            ] {
                let m = crate::DegenerateCorner {
                    corner: crate::Corner::U1V0,
                    reason: m,
                    limit,
                };
                assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
            }
        }
        let m = crate::ConditionFails::default();
        assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        for what in Positive::iter() {
            let m = SurfaceError::NotPositive {
                what,
                value: "0".into(),
            };
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
