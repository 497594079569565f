//! The one error type of cagd-generate.

use cagd_bezier::BezierError;
use cagd_bspline::BSplineError;
use cagd_linalg::LinalgError;
use cagd_poly::PolyError;
use cagd_scalar::ScalarError;
use cagd_spline_surface::SplineSurfaceError;
use cagd_surface::SurfaceError;
use cagd_words::{said, Lang, Message, Phrase};

/// What can go wrong when generating a surface from curves.
///
/// Points and numbers inside the messages are written exactly (`(1/2, 0, 2)`, `√2/2`).
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
#[non_exhaustive]
pub enum GenerateError {
    /// The two curves of a translational surface do not start at the same point a.
    CurvesDoNotMeet {
        /// The first end, as written: `c1(0)`.
        first: String,
        /// Its point, as text.
        first_point: String,
        /// The second end: `d1(0)`.
        second: String,
        /// Its point, as text.
        second_point: String,
    },
    /// Two boundary curves of a Coons patch do not meet at a corner of the curvilinear
    /// quadrilateral (13).
    CornerMismatch {
        /// The corner: `a`, `b`, `c` or `d`.
        corner: char,
        /// The first curve and where it is evaluated: `c1(1)`.
        first_at: String,
        /// The point, as text.
        first_point: String,
        /// The second curve and where it is evaluated: `d2(0)`.
        second_at: String,
        /// The point, as text.
        second_point: String,
    },
    /// A curve in the wrong parameter, e.g. a `d1` that uses `u` (it must be a curve in v).
    WrongVariable {
        /// The curve's name.
        curve: String,
        /// The variable it must use.
        expected: String,
        /// The variable it uses instead.
        found: String,
    },
    /// Two inputs that must live in the same space have different dimensions.
    DimensionMismatch {
        /// The first input's name.
        first: String,
        /// Its dimension.
        first_dim: usize,
        /// The second input's name.
        second: String,
        /// Its dimension.
        second_dim: usize,
    },
    /// A construction that only makes sense in R^3 (cross products, revolution about Z).
    NotSpatial {
        /// What needs R^3.
        what: Spatial,
        /// The input.
        input: Input,
        /// Its dimension.
        dim: usize,
    },
    /// A surface that is not given as a ruled parametrization (linear in v).
    NotRuled {
        /// What is wrong.
        detail: NotRuled,
    },
    /// The naive projective Coons construction needs the homogeneous boundary curves to meet:
    /// equal weights at each corner.
    CornerWeights {
        /// The corner.
        corner: char,
        /// The first curve.
        first: String,
        /// Its weight at the corner, as text.
        first_weight: String,
        /// The second curve.
        second: String,
        /// Its weight at the corner, as text.
        second_weight: String,
    },
    /// A control point of the generating curve of a surface of revolution outside the XZ plane.
    NotInXzPlane {
        /// The index of the control point.
        index: usize,
        /// The point, as text.
        point: String,
    },
    /// A generating curve of a surface of revolution (given as a polynomial map) whose second
    /// coordinate is not identically zero.
    CurveNotInXzPlane {
        /// The second coordinate, as text.
        y: String,
    },
    /// A construction needs a number that the scalar type cannot hold exactly (√2/2 asked of
    /// exact rationals).
    NeedsQuadraticField {
        /// What needs it.
        what: Needs,
        /// The number, as text.
        number: String,
        /// The underlying error.
        source: ScalarError,
    },
    /// A circle for the parallels whose control point is not in the XY plane.
    NotACircleOfXy {
        /// The index of the control point.
        index: usize,
        /// The point, as text.
        point: String,
    },
    /// A cosine and sine that are not those of an angle: cos² v + sin² v ≠ 1.
    NotOnUnitCircle {
        /// cos v, as text.
        cos: String,
        /// sin v, as text.
        sin: String,
    },
    /// A B-spline curve that is not clamped where the construction needs clamped curves.
    NotClamped {
        /// The curve's name.
        curve: String,
        /// Its knots, as text.
        knots: String,
    },
    /// Two B-spline curves on different parameter domains.
    DomainMismatch {
        /// The first curve's name.
        first: String,
        /// Its domain, as text.
        first_domain: String,
        /// The second curve's name.
        second: String,
        /// Its domain, as text.
        second_domain: String,
    },
    /// Lofting through fewer than two sections.
    LoftSections {
        /// The sections given.
        found: usize,
    },
    /// Lofting with as many parameters as not sections.
    LoftParameters {
        /// The parameters given.
        found: usize,
        /// The sections.
        sections: usize,
    },
    /// Lofting parameters that do not increase.
    LoftNotIncreasing,
    /// A lofting degree in v outside 1..=K - 1.
    LoftDegree {
        /// The degree given.
        degree: usize,
        /// K - 1.
        max: usize,
    },
    /// An error of a polynomial computation.
    Poly(PolyError),
    /// An error of a Bézier curve algorithm.
    Bezier(BezierError),
    /// An error of a B-spline or NURBS curve algorithm.
    BSpline(BSplineError),
    /// An error of a surface (mesh shape, weights).
    Surface(SurfaceError),
    /// An error of a B-spline or NURBS surface.
    SplineSurface(SplineSurfaceError),
    /// An error of linear algebra.
    Linalg(LinalgError),
    /// An error of the number types.
    Scalar(ScalarError),
}

/// What needs points of R^3 ([`GenerateError::NotSpatial`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Spatial {
    /// The developability test (9).
    #[default]
    Developability,
    /// The planarity of a cell of a ruled Bézier patch.
    CellPlanarity,
    /// A surface of revolution about the Z axis.
    Revolution,
    /// A circle about the Z axis.
    CircleAboutZ,
}

impl Message for Spatial {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Spatial::Developability => said(
                lang,
                "the developability test",
                "el criterio de desarrollabilidad",
                [],
            ),
            Spatial::CellPlanarity => said(
                lang,
                "the planarity of a cell",
                "la planaridad de una celda",
                [],
            ),
            Spatial::Revolution => said(
                lang,
                "a surface of revolution about Z",
                "una superficie de revolución alrededor de Z",
                [],
            ),
            Spatial::CircleAboutZ => said(
                lang,
                "a circle about the Z axis",
                "una circunferencia alrededor del eje Z",
                [],
            ),
        }
    }
}

/// The input that is not in R^3 ([`GenerateError::NotSpatial`]).
#[derive(Debug, Clone, PartialEq, Eq, Hash, strum::EnumIter)]
#[non_exhaustive]
pub enum Input {
    /// An input by its name: `c`, `c1`.
    Named(String),
    /// A cell of the mesh.
    Cell,
    /// A point.
    Point,
    /// The curve.
    Curve,
    /// The surface.
    Surface,
}

impl Default for Input {
    fn default() -> Self {
        Input::Named("c".into())
    }
}

impl Message for Input {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Input::Named(name) => said(lang, "‹›", "‹›", [name.into()]),
            Input::Cell => said(lang, "the cell", "la celda", []),
            Input::Point => said(lang, "the point", "el punto", []),
            Input::Curve => said(lang, "the curve", "la curva", []),
            Input::Surface => said(lang, "the surface", "la superficie", []),
        }
    }
}

/// Why a surface is not a ruled parametrization ([`GenerateError::NotRuled`]).
#[derive(Debug, Clone, PartialEq, Eq, Hash, strum::EnumIter)]
#[non_exhaustive]
pub enum NotRuled {
    /// A polynomial parametrization of degree > 1 in v (the test (9)).
    DegreeInV {
        /// Its degree in v.
        degree: u32,
    },
    /// A Bézier patch of bidegree (m, n) with n ≠ 1.
    Bidegree {
        /// m.
        m: usize,
        /// n.
        n: usize,
    },
    /// A rational parametrization of degree > 1 in v: its lines v ↦ c(u, v) are not lines.
    Lines {
        /// Its degree in v.
        degree: u32,
    },
}

impl Default for NotRuled {
    fn default() -> Self {
        NotRuled::DegreeInV { degree: 2 }
    }
}

impl Message for NotRuled {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            NotRuled::DegreeInV { degree } => said(
                lang,
                "c has degree ‹› in v; the test (9) is for ruled parametrizations (1 - v) c1(u) + v c2(u), of degree 1 in v",
                "c tiene grado ‹› en v; el criterio (9) es para parametrizaciones regladas (1 - v) c1(u) + v c2(u), de grado 1 en v",
                [degree.into()],
            ),
            NotRuled::Bidegree { m, n } => said(
                lang,
                "a ruled Bézier patch has bidegree (m, 1), this one has (‹›, ‹›)",
                "una superficie de Bézier reglada tiene bigrado (m, 1), esta tiene (‹›, ‹›)",
                [m.into(), n.into()],
            ),
            NotRuled::Lines { degree } => said(
                lang,
                "c has degree ‹› in v; the lines v ↦ c(u, v) of a ruled parametrization need degree 1",
                "c tiene grado ‹› en v; las rectas v ↦ c(u, v) de una parametrización reglada necesitan grado 1",
                [degree.into()],
            ),
        }
    }
}

/// What needs a number of a quadratic field ([`GenerateError::NeedsQuadraticField`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Needs {
    /// The weight √2/2 of a quarter circle.
    #[default]
    QuarterCircleWeight,
}

impl Message for Needs {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Needs::QuarterCircleWeight => said(
                lang,
                "the weight of a quarter circle",
                "el peso de un cuarto de circunferencia",
                [],
            ),
        }
    }
}

impl Message for GenerateError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            GenerateError::CurvesDoNotMeet {
                first,
                first_point,
                second,
                second_point,
            } => said(
                lang,
                "the curves do not meet: $‹›$ = $‹›$ but $‹›$ = $‹›$",
                "las curvas no se cortan: $‹›$ = $‹›$, pero $‹›$ = $‹›$",
                [
                    first.into(),
                    first_point.into(),
                    second.into(),
                    second_point.into(),
                ],
            ),
            GenerateError::CornerMismatch {
                corner,
                first_at,
                first_point,
                second_at,
                second_point,
            } => {
                let name = |at: &str| at.split('(').next().unwrap_or_default().to_string();
                said(
                    lang,
                    "curves ‹› and ‹› do not meet at corner ‹›: $‹› = ‹›$, $‹› = ‹›$",
                    "las curvas ‹› y ‹› no se cortan en la esquina ‹›: $‹› = ‹›$, $‹› = ‹›$",
                    [
                        (&name(first_at)).into(),
                        (&name(second_at)).into(),
                        corner.into(),
                        first_at.into(),
                        first_point.into(),
                        second_at.into(),
                        second_point.into(),
                    ],
                )
            }
            GenerateError::WrongVariable {
                curve,
                expected,
                found,
            } => said(
                lang,
                "‹› must be a curve in ‹›, but it uses ‹›",
                "‹› ha de ser una curva en ‹›, pero usa ‹›",
                [curve.into(), expected.into(), found.into()],
            ),
            GenerateError::DimensionMismatch {
                first,
                first_dim,
                second,
                second_dim,
            } => said(
                lang,
                "‹› has ‹› coordinates but ‹› has ‹›: they must live in the same space",
                "‹› tiene ‹› coordenadas, pero ‹› tiene ‹›: han de estar en el mismo espacio",
                [first.into(), first_dim.into(), second.into(), second_dim.into()],
            ),
            GenerateError::NotSpatial { what, input, dim } => said(
                lang,
                "«» needs points of $R^3$, but «» has ‹› coordinates",
                "«» necesita puntos de $R^3$, pero «» tiene ‹› coordenadas",
                [what.phrase(lang).into(), input.phrase(lang).into(), dim.into()],
            ),
            GenerateError::NotRuled { detail } => said(
                lang,
                "not a ruled surface: «»",
                "no es una superficie reglada: «»",
                [detail.phrase(lang).into()],
            ),
            GenerateError::CornerWeights {
                corner,
                first,
                first_weight,
                second,
                second_weight,
            } => said(
                lang,
                "the projective (homogeneous) Coons construction needs equal weights at corner ‹›: ‹› has weight ‹› there but ‹› has ‹› (scale the weights of one curve)",
                "la construcción de Coons proyectiva (homogénea) necesita pesos iguales en la esquina ‹›: ‹› tiene peso ‹› ahí, pero ‹› tiene ‹› (escale los pesos de una de las curvas)",
                [
                    corner.into(),
                    first.into(),
                    first_weight.into(),
                    second.into(),
                    second_weight.into(),
                ],
            ),
            GenerateError::NotInXzPlane { index, point } => said(
                lang,
                "control point $c_‹›$ = ‹› is not in the XZ plane ($y ≠ 0$): a surface of revolution about the Z axis rotates a curve of the XZ plane",
                "el punto de control $c_‹›$ = ‹› no está en el plano XZ ($y ≠ 0$): una superficie de revolución alrededor del eje Z gira una curva del plano XZ",
                [index.into(), point.into()],
            ),
            GenerateError::CurveNotInXzPlane { y } => said(
                lang,
                "the curve is not in the XZ plane: its y coordinate is ‹›, not 0 (a surface of revolution about the Z axis rotates a curve $(f(u), 0, g(u))$)",
                "la curva no está en el plano XZ: su coordenada y es ‹›, no 0 (una superficie de revolución alrededor del eje Z gira una curva $(f(u), 0, g(u))$)",
                [y.into()],
            ),
            GenerateError::NeedsQuadraticField {
                what,
                number,
                source,
            } => said(
                lang,
                "«» needs ‹›, which this number type cannot hold exactly: compute in the quadratic field $a + b√d$ («»)",
                "«» necesita ‹›, que este tipo de números no puede representar exactamente: calcule en el cuerpo cuadrático $a + b√d$ («»)",
                [what.phrase(lang).into(), number.into(), source.phrase(lang).into()],
            ),
            GenerateError::NotACircleOfXy { index, point } => said(
                lang,
                "control point ‹› of the circle, ‹›, is not a point $(x, y)$ or $(x, y, 0)$ of the XY plane: the parallels need the unit circle about the origin",
                "el punto de control ‹› de la circunferencia, ‹›, no es un punto $(x, y)$ o $(x, y, 0)$ del plano XY: los paralelos necesitan la circunferencia unidad centrada en el origen",
                [index.into(), point.into()],
            ),
            GenerateError::NotOnUnitCircle { cos, sin } => said(
                lang,
                "$cos v$ = ‹› and $sin v$ = ‹› are not the cosine and sine of an angle: $cos² v + sin² v ≠ 1$",
                "$cos v$ = ‹› y $sin v$ = ‹› no son el coseno y el seno de un ángulo: $cos² v + sin² v ≠ 1$",
                [cos.into(), sin.into()],
            ),
            GenerateError::NotClamped { curve, knots } => said(
                lang,
                "‹› is not clamped (knots ‹›): the construction needs curves that start and end at their end control points (end knots repeated p times)",
                "‹› no tiene los extremos sujetos (nudos ‹›): la construcción necesita curvas que empiecen y acaben en sus puntos de control extremos (nudos de los extremos repetidos p veces)",
                [curve.into(), knots.into()],
            ),
            GenerateError::DomainMismatch {
                first,
                first_domain,
                second,
                second_domain,
            } => said(
                lang,
                "‹› is defined on ‹› but ‹› on ‹›: reparametrize them onto the same interval",
                "‹› está definida en ‹›, pero ‹› en ‹›: reparametrícelas sobre el mismo intervalo",
                [
                    first.into(),
                    first_domain.into(),
                    second.into(),
                    second_domain.into(),
                ],
            ),
            GenerateError::Poly(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            GenerateError::BSpline(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            GenerateError::Bezier(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            GenerateError::LoftSections { found } => said(
                lang,
                "a lofted surface goes through at least two section curves; ‹› given",
                "una superficie por secciones pasa por al menos dos curvas sección; se han dado ‹›",
                [found.into()],
            ),
            GenerateError::LoftParameters { found, sections } => said(
                lang,
                "‹› parameters v_k for ‹› sections: one parameter per section",
                "‹› parámetros v_k para ‹› secciones: un parámetro por sección",
                [found.into(), sections.into()],
            ),
            GenerateError::LoftNotIncreasing => said(
                lang,
                "the parameters v_k of the sections must increase",
                "los parámetros v_k de las secciones deben ser crecientes",
                [],
            ),
            GenerateError::LoftDegree { degree, max } => said(
                lang,
                "the degree q across the sections is between 1 and K - 1 = ‹›; ‹› given",
                "el grado q entre las secciones está entre 1 y K - 1 = ‹›; se ha dado ‹›",
                [max.into(), degree.into()],
            ),
            GenerateError::Surface(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            GenerateError::SplineSurface(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            GenerateError::Linalg(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            GenerateError::Scalar(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
        }
    }
}

cagd_words::display_english!(GenerateError, Spatial, Input, NotRuled, Needs);

impl std::error::Error for GenerateError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            GenerateError::Poly(e) => Some(e),
            GenerateError::Bezier(e) => Some(e),
            GenerateError::BSpline(e) => Some(e),
            GenerateError::Surface(e) => Some(e),
            GenerateError::SplineSurface(e) => Some(e),
            GenerateError::Linalg(e) => Some(e),
            GenerateError::Scalar(e) | GenerateError::NeedsQuadraticField { source: e, .. } => {
                Some(e)
            }
            _ => None,
        }
    }
}

impl From<PolyError> for GenerateError {
    fn from(e: PolyError) -> Self {
        GenerateError::Poly(e)
    }
}

impl From<BezierError> for GenerateError {
    fn from(e: BezierError) -> Self {
        GenerateError::Bezier(e)
    }
}

impl From<BSplineError> for GenerateError {
    fn from(e: BSplineError) -> Self {
        GenerateError::BSpline(e)
    }
}

impl From<SurfaceError> for GenerateError {
    fn from(e: SurfaceError) -> Self {
        GenerateError::Surface(e)
    }
}

impl From<SplineSurfaceError> for GenerateError {
    fn from(e: SplineSurfaceError) -> Self {
        GenerateError::SplineSurface(e)
    }
}

impl From<LinalgError> for GenerateError {
    fn from(e: LinalgError) -> Self {
        GenerateError::Linalg(e)
    }
}

impl From<ScalarError> for GenerateError {
    fn from(e: ScalarError) -> Self {
        GenerateError::Scalar(e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_variant_in_both_languages() {
        for m in GenerateError::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        for what in Spatial::iter() {
            for input in Input::iter() {
                let m = GenerateError::NotSpatial {
                    what,
                    input,
                    dim: 2,
                };
                assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
            }
        }
        for detail in NotRuled::iter() {
            let m = GenerateError::NotRuled { detail };
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        // each of what needs a square root (the enumeration gives the default one; the inner
        // errors are enumerated with their own crates')
        for what in Needs::iter() {
            let m = GenerateError::NeedsQuadraticField {
                what,
                number: "√2/2".into(),
                source: ScalarError::DivisionByZero { column: None },
            };
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
