//! Triangles' and fitting's own sentences (errors and remarks), and those of the dispatch
//! (a required argument, the limits of a result).

use super::inner::Inner;
use cagd_words::{said, Lang, Message, Phrase};

/// A parametrization of data points, in words.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, strum::EnumIter)]
pub enum How {
    /// Uniform.
    #[default]
    Uniform,
    /// By chord length.
    ChordLength,
    /// Centripetal.
    Centripetal,
}

impl Message for How {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            How::Uniform => said(lang, "uniform", "uniformes", []),
            How::ChordLength => said(lang, "by chord length", "por longitud de cuerda", []),
            How::Centripetal => said(lang, "centripetal", "centrípetos", []),
        }
    }
}

/// Triangles' and fitting's own sentences (errors and remarks).
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum Fitting {
    /// A rational triangular patch has no net of this operation.
    RationalHasNo {
        /// The operation refused (a key).
        what: String,
    },
    /// A homogeneous point without coordinates.
    HomogeneousWithoutCoordinates,
    /// The weight of a rational triangular patch vanishes at the point.
    WeightZeroHere,
    /// A point of the domain triangle of the wrong length.
    DomainPointList {
        /// How many numbers.
        len: usize,
    },
    /// A number where a point of the domain triangle is expected.
    DomainPointNumber,
    /// Two degrees to elevate a triangular patch by.
    OneDegreeBy,
    /// What a points limit refuses: the elevated triangular patch.
    ElevatedPatch,
    /// `at` given for a triangular patch.
    AtTensor,
    /// Two orders of derivation for a triangular patch.
    OneDirection,
    /// `t` given to split a triangular patch.
    SplitAtPoint,
    /// The normal of a triangular patch not in space.
    NormalDimension {
        /// The dimension found.
        dim: usize,
    },
    /// Intervals given to restrict a triangular patch.
    RestrictVertices,
    /// Not three vertices of a sub-triangle.
    SubTriangle {
        /// How many points.
        found: usize,
    },
    /// `w` without a triangular patch.
    WNeedsTriangle,
    /// No iso-line of a triangular patch.
    IsoMissing,
    /// Two iso-lines of a triangular patch.
    IsoTwo,
    /// Not a permutation of the vertices.
    Permutation {
        /// The list found.
        found: String,
    },
    /// Not three vertices of a triangle of the plane.
    TriangleDomain {
        /// How many points.
        found: usize,
        /// Their dimensions.
        dims: String,
    },
    /// Collinear vertices.
    Collinear,
    /// Two degrees of a graph over a triangle.
    OneDegreeN,
    /// A function of a degree above the one asked.
    GraphDegree {
        /// The total degree of f.
        found: usize,
        /// The degree asked.
        n: usize,
    },
    /// What a points limit refuses: the graph over a triangle.
    GraphOfDegree {
        /// The degree.
        n: usize,
    },
    /// A reduction past degree 0.
    PatchCannotReduce {
        /// The degree.
        n: usize,
        /// By how much.
        r: usize,
    },
    /// No exact reduction of a triangular patch.
    NoExactReduction {
        /// The total degree of the closed form.
        found: usize,
        /// The degree asked.
        to: usize,
    },
    /// No exact reduction of a rational triangular patch.
    NoExactReductionRational {
        /// The total degree of the homogeneous closed form.
        found: usize,
        /// The degree asked.
        to: usize,
    },
    /// The remark of the Gaussian curvature's numerator.
    SignOfK,
    /// A result past the points limit.
    TooManyPoints {
        /// What would be built.
        what: Inner,
        /// Its control points.
        points: usize,
        /// The limit.
        max: usize,
    },
    /// A computed degree past the degree limit.
    DegreeAbove {
        /// What gives the degree.
        what: Inner,
        /// The degree.
        degree: usize,
        /// The limit.
        max: usize,
    },
    /// A count given past the points limit.
    CountLimit {
        /// The count given.
        n: u64,
        /// The limit.
        max: usize,
    },
    /// A fitted curve on another domain than [0, 1].
    OutsideCurve {
        /// The start of the domain.
        a: String,
        /// Its end.
        b: String,
    },
    /// A triangular patch evaluated at a point outside its domain triangle (a remark: the value
    /// is the patch's polynomial extended beyond the triangle).
    OutsideTriangle {
        /// The path of the point (`params[1]`).
        path: String,
        /// The point (r, s, t), as text.
        point: String,
        /// The negative coordinate and its value in u, v: `r = 1 - u - v`.
        coordinate: String,
        /// Its value.
        value: String,
    },
    /// A fitted patch on another domain than the unit square.
    OutsidePatch {
        /// U from.
        a: String,
        /// U to.
        b: String,
        /// V from.
        c: String,
        /// V to.
        d: String,
    },
    /// The parameters of a column of a grid cannot be computed.
    ColumnParameters {
        /// The column.
        line: usize,
        /// Why.
        inner: Inner,
    },
    /// The parameters of a row of a grid cannot be computed.
    RowParameters {
        /// The row.
        line: usize,
        /// Why.
        inner: Inner,
    },
    /// Interpolation parameters repeated.
    RepeatsEntry {
        /// The parameter.
        value: String,
        /// The entry it repeats.
        entry: usize,
    },
    /// A list of points with parameters u and v.
    GridForUV,
    /// The parameters computed of a grid.
    GridParameters {
        /// The parametrization.
        how: How,
        /// The parameters u.
        u: String,
        /// The parameters v.
        v: String,
    },
    /// Both parameters and a parametrization of a grid.
    UVOrParametrization,
    /// No parameters and no parametrization.
    MissingOrParametrization,
    /// Clamped ends of a grid.
    GridEnds,
    /// A B-spline basis for a grid.
    GridBasis,
    /// A grid without u and v.
    GridNeedsUV,
    /// The parameters computed of a list of points.
    CurveParameters {
        /// The parametrization.
        how: How,
        /// The parameters.
        list: String,
    },
    /// Both parameters and a parametrization.
    ParamsOrParametrization,
    /// Not two end derivatives.
    EndDerivatives {
        /// How many.
        found: usize,
    },
    /// Tangents without clamped ends.
    TangentsNeedClamped,
    /// Natural or Bessel ends of a B-spline interpolant.
    BSplineEnd,
    /// The degree of a B-spline interpolant out of range.
    BSplineDegreeRange {
        /// The data points.
        points: usize,
        /// The highest degree.
        max: usize,
    },
    /// Parameters not increasing.
    Increasing,
    /// No parameters and no parametrization to approximate.
    MissingOrParametrizationShort,
    /// A number among pairs of parameters.
    UVNotNumber,
    /// One degree for a patch.
    PatchDegreeNumber {
        /// The number.
        n: u64,
    },
    /// What a points limit refuses: a patch.
    PatchOfBidegree {
        /// Degree in u.
        m: usize,
        /// Degree in v.
        n: usize,
    },
    /// What a points limit refuses: a B-spline surface.
    BSplineSurface,
    /// A list among numbers t.
    FirstIsNumber,
    /// Two degrees for a curve.
    DegreeNotList,
    /// What a points limit refuses: a B-spline curve.
    BSpline,
    /// B-spline least squares whose knots (read in the notes' convention, without end knots)
    /// make more control points than there are data points.
    KnotsForTooFewPoints {
        /// How many knots were given.
        knots: usize,
        /// The degree p.
        degree: usize,
        /// The control points they make in the notes' convention: knots - p + 1.
        unknowns: usize,
        /// How many data points were given.
        found: usize,
    },
    /// As [`Fitting::KnotsForTooFewPoints`], for a vector whose ends are repeated p + 1 times:
    /// it looks like The NURBS Book's, with one more knot at each end.
    KnotsLookFull {
        /// How many knots were given.
        knots: usize,
        /// The degree p.
        degree: usize,
        /// The control points they make in the notes' convention: knots - p + 1.
        unknowns: usize,
        /// How many data points were given.
        found: usize,
    },
    /// A list where a number is expected.
    NumberNotList,
    /// The blossom of a curve that is not Bézier.
    BlossomCurve,
    /// The blossom of a surface that is not Bézier.
    BlossomSurface,
    /// A blossom of nothing.
    BlossomNeeds,
    /// Where to split a B-spline surface.
    SplitSurfaceWhere,
    /// What a points limit refuses: a subdivision.
    SurfacesOfSubdivision,
    /// Where to split a Bézier patch.
    SplitPatchWhere,
    /// A split outside the patch.
    NotInsideUnit {
        /// The parameter.
        x: String,
    },
    /// Subdivision of a surface that is not Bézier.
    SubdivisionPatches,
    /// A subdivision of nothing.
    SubdivideNeeds,
    /// Subdivision of an expression.
    SubdivisionMap,
    /// Both u and v for an iso-curve.
    IsoBoth,
    /// Neither u nor v for an iso-curve.
    IsoNeither,
    /// What a points limit refuses: the Bézier pieces of a curve.
    BezierPieces,
    /// What a points limit refuses: the Bézier patches of a surface.
    BezierPatches,
    /// Extraction of a Bézier curve.
    ExtractCurve,
    /// Extraction of a Bézier patch.
    ExtractSurface,
    /// An extraction of nothing.
    ExtractNeeds,
    /// Knot removal of a curve without knots.
    RemoveKnotCurve,
    /// A least-squares degree reduction.
    ReducedLeastSquares {
        /// The degree.
        m: usize,
    },
}

impl Message for Fitting {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Fitting::RationalHasNo { what } => said(
                lang,
                "a rational triangular patch has no `‹›` here: its derivatives are quotients (the quotient rule mixes the weights in), not a net of this form; take its `closed_form`, a quotient",
                "una superficie triangular racional no tiene aquí `‹›`: sus derivadas son cocientes (la regla del cociente mezcla los pesos), no una red de esta forma; pida su `closed_form`, un cociente",
                [what.into()],
            ),
            Fitting::HomogeneousWithoutCoordinates => said(
                lang,
                "a homogeneous point without coordinates",
                "un punto homogéneo sin coordenadas",
                [],
            ),
            Fitting::WeightZeroHere => said(
                lang,
                "the weight (the denominator Σ w_{ijk} B_{ijk}) is zero here: the rational patch has no point there",
                "el peso (el denominador Σ w_{ijk} B_{ijk}) es nulo aquí: la superficie racional no tiene punto ahí",
                [],
            ),
            Fitting::DomainPointList { len } => said(
                lang,
                "expected [u, v] or barycentric [r, s, t], found a list of ‹›",
                "se esperaba [u, v] o unas coordenadas baricéntricas [r, s, t], se encontró una lista de ‹›",
                [len.into()],
            ),
            Fitting::DomainPointNumber => said(
                lang,
                "expected a point [u, v] of the domain triangle (or barycentric [r, s, t]), found a number",
                "se esperaba un punto [u, v] del triángulo del dominio (o unas coordenadas baricéntricas [r, s, t]), se encontró un número",
                [],
            ),
            Fitting::OneDegreeBy => said(
                lang,
                "expected a non-negative integer (a triangular patch has one degree), found a list of 2",
                "se esperaba un entero no negativo (una superficie triangular tiene un solo grado), se encontró una lista de 2",
                [],
            ),
            Fitting::ElevatedPatch => said(
                lang,
                "the elevated patch",
                "la superficie elevada",
                [],
            ),
            Fitting::AtTensor => said(
                lang,
                "`at` restricts a tensor-product patch to a border; for a triangular patch, `evaluate` the derivative's closed form or `boundary` its net",
                "`at` restringe una superficie producto tensorial a un borde; en una superficie triangular, evalúe (`evaluate`) la parametrización de la derivada o tome el borde (`boundary`) de su red",
                [],
            ),
            Fitting::OneDirection => said(
                lang,
                "expected a non-negative integer (derivatives along one direction), found a list of 2",
                "se esperaba un entero no negativo (derivadas en una sola dirección), se encontró una lista de 2",
                [],
            ),
            Fitting::SplitAtPoint => said(
                lang,
                "a triangular patch is split at a point (u, v) of its domain: give `u` and `v`",
                "una superficie triangular se divide en un punto (u, v) de su dominio: dé `u` y `v`",
                [],
            ),
            Fitting::NormalDimension { dim } => said(
                lang,
                "the normal b_u × b_v needs points in R³, found dimension ‹›",
                "el vector normal b_u × b_v necesita puntos de R³, se encontró dimensión ‹›",
                [dim.into()],
            ),
            Fitting::RestrictVertices => said(
                lang,
                "a triangular patch is restricted to a sub-triangle: give `vertices`, three points [u, v] (or [r, s, t]) of its domain, not intervals",
                "una superficie triangular se restringe a un subtriángulo: dé `vertices`, tres puntos [u, v] (o [r, s, t]) de su dominio, no intervalos",
                [],
            ),
            Fitting::SubTriangle { found } => said(
                lang,
                "expected the three vertices a, b, c of the sub-triangle, found ‹› points",
                "se esperaban los tres vértices a, b, c del subtriángulo, hay ‹› puntos",
                [found.into()],
            ),
            Fitting::WNeedsTriangle => said(
                lang,
                "`w` = 1 - u - v fixes an iso-line of a triangular patch: give `triangle` (a tensor-product `surface` takes `u` or `v`)",
                "`w` = 1 - u - v fija una isolínea de una superficie triangular: dé `triangle` (una superficie producto tensorial `surface` admite `u` o `v`)",
                [],
            ),
            Fitting::IsoMissing => said(
                lang,
                "missing (give `u`, `v` or `w` = 1 - u - v: the iso-line where it is constant)",
                "falta (dé `u`, `v` o `w` = 1 - u - v: la isolínea en la que es constante)",
                [],
            ),
            Fitting::IsoTwo => said(
                lang,
                "give one of `u`, `v`, `w` (an iso-line), not two: two fix a point (`evaluate`)",
                "dé uno de `u`, `v`, `w` (una isolínea), no dos: dos fijan un punto (`evaluate`)",
                [],
            ),
            Fitting::Permutation { found } => said(
                lang,
                "expected a permutation of [1, 2, 3] (the old vertices in their new order), found ‹›",
                "se esperaba una permutación de [1, 2, 3] (los vértices antiguos en su nuevo orden), hay ‹›",
                [found.into()],
            ),
            Fitting::TriangleDomain { found, dims } => said(
                lang,
                "expected the three vertices [x, y] of a triangle, found ‹› points of dimensions ‹›",
                "se esperaban los tres vértices [x, y] de un triángulo, hay ‹› puntos de dimensiones ‹›",
                [found.into(), dims.into()],
            ),
            Fitting::Collinear => said(
                lang,
                "the three vertices are collinear: they bound no triangle",
                "los tres vértices están alineados: no limitan ningún triángulo",
                [],
            ),
            Fitting::OneDegreeN => said(
                lang,
                "expected one integer n (a triangular patch has one degree), found a list of 2",
                "se esperaba un entero n (una superficie triangular tiene un solo grado), hay una lista de 2",
                [],
            ),
            Fitting::GraphDegree { found, n } => said(
                lang,
                "f has total degree ‹›, more than the degree ‹› asked for: its graph is a triangular patch of degree ‹› or more",
                "f tiene grado total ‹›, mayor que el grado ‹› pedido: su gráfica es una superficie triangular de grado ‹› o mayor",
                [found.into(), n.into(), found.into()],
            ),
            Fitting::GraphOfDegree { n } => said(
                lang,
                "the graph of degree ‹›",
                "la gráfica de grado ‹›",
                [n.into()],
            ),
            Fitting::PatchCannotReduce { n, r } => said(
                lang,
                "a patch of degree ‹› cannot be reduced by ‹›",
                "una superficie de grado ‹› no puede reducirse en ‹›",
                [n.into(), r.into()],
            ),
            Fitting::NoExactReduction { found, to } => said(
                lang,
                "the closed form has total degree ‹›, more than ‹›: no patch of degree ‹› is the same surface, so there is no exact reduction (a least-squares reduction of triangular nets is not available)",
                "la parametrización tiene grado total ‹›, mayor que ‹›: ninguna superficie de grado ‹› es la misma, así que no hay reducción exacta (la reducción por mínimos cuadrados de redes triangulares no está disponible)",
                [found.into(), to.into(), to.into()],
            ),
            Fitting::NoExactReductionRational { found, to } => said(
                lang,
                "the closed form (homogeneous: of (w b, w)) has total degree ‹›, more than ‹›: no patch of degree ‹› is the same surface, so there is no exact reduction (a least-squares reduction of triangular nets is not available)",
                "la parametrización (homogénea: de (w b, w)) tiene grado total ‹›, mayor que ‹›: ninguna superficie de grado ‹› es la misma, así que no hay reducción exacta (la reducción por mínimos cuadrados de redes triangulares no está disponible)",
                [found.into(), to.into(), to.into()],
            ),
            Fitting::SignOfK => said(
                lang,
                "K has the sign of the numerator G: positive where the surface is elliptic, negative where it is hyperbolic, zero where it is parabolic or flat",
                "K tiene el signo del numerador G: positivo donde la superficie es elíptica, negativo donde es hiperbólica, nulo donde es parabólica o plana",
                [],
            ),
            Fitting::TooManyPoints { what, points, max } => said(
                lang,
                "«» would have ‹› control points, more than the limit of ‹›",
                "«»: ‹› puntos de control, más que el límite de ‹›",
                [what.phrase(lang).into(), points.into(), max.into()],
            ),
            Fitting::DegreeAbove { what, degree, max } => said(
                lang,
                "«» gives degree ‹›, above the limit of ‹›",
                "«» da grado ‹›, por encima del límite de ‹›",
                [what.phrase(lang).into(), degree.into(), max.into()],
            ),
            Fitting::CountLimit { n, max } => said(
                lang,
                "‹› is above the limit of ‹›",
                "‹› supera el límite de ‹›",
                [n.into(), max.into()],
            ),
            Fitting::OutsideCurve { a, b } => said(
                lang,
                "the parameters lie outside [0, 1]: the curve is on [‹›, ‹›], written as a B-spline of one piece (knots ‹› and ‹›, each n times) so that it is evaluated at the given parameters",
                "los parámetros quedan fuera de [0, 1]: la curva está en [‹›, ‹›], escrita como una B-spline de un solo trozo (nudos ‹› y ‹›, cada uno n veces) para que se evalúe en los parámetros dados",
                [a.into(), b.into(), a.into(), b.into()],
            ),
            Fitting::OutsideTriangle {
                path,
                point,
                coordinate,
                value,
            } => said(
                lang,
                "the point ‹› = ‹› (r, s, t) is outside the domain triangle: $‹›$ = ‹› is negative; its value is the patch's polynomial extended beyond the triangle, not a point of the patch",
                "el punto ‹› = ‹› (r, s, t) está fuera del triángulo del dominio: $‹›$ = ‹› es negativo; su valor es el del polinomio de la superficie prolongado fuera del triángulo, no un punto de la superficie",
                [path.into(), point.into(), coordinate.into(), value.into()],
            ),
            Fitting::OutsidePatch { a, b, c, d } => said(
                lang,
                "the parameters lie outside [0, 1]: the patch is on [‹›, ‹›] x [‹›, ‹›], written as a B-spline surface of one piece (knots at the ends, each m and n times) so that its mesh and its closed form agree",
                "los parámetros quedan fuera de [0, 1]: la superficie está en [‹›, ‹›] x [‹›, ‹›], escrita como una superficie B-spline de un solo trozo (nudos en los extremos, m y n veces) para que su malla y su parametrización coincidan",
                [a.into(), b.into(), c.into(), d.into()],
            ),
            Fitting::ColumnParameters { line, inner } => said(
                lang,
                "the parameters of column ‹›: «»",
                "los parámetros de la columna ‹›: «»",
                [line.into(), inner.phrase(lang).into()],
            ),
            Fitting::RowParameters { line, inner } => said(
                lang,
                "the parameters of row ‹›: «»",
                "los parámetros de la fila ‹›: «»",
                [line.into(), inner.phrase(lang).into()],
            ),
            Fitting::RepeatsEntry { value, entry } => said(
                lang,
                "the parameter ‹› repeats entry ‹›: the interpolation system is singular (the parameters must be distinct)",
                "el parámetro ‹› repite el valor ‹›: el sistema de interpolación es singular (los parámetros han de ser distintos)",
                [value.into(), entry.into()],
            ),
            Fitting::GridForUV => said(
                lang,
                "expected a grid of points (rows of points) for the parameters u and v",
                "se esperaba una malla de puntos (filas de puntos) para los parámetros u y v",
                [],
            ),
            Fitting::GridParameters { how, u, v } => said(
                lang,
                "the parameters, «» and averaged over the columns (u) and the rows (v): u = ‹›; v = ‹›",
                "los parámetros, «» y promediados sobre las columnas (u) y las filas (v): u = ‹›; v = ‹›",
                [how.phrase(lang).into(), u.into(), v.into()],
            ),
            Fitting::UVOrParametrization => said(
                lang,
                "either `u` and `v` or a `parametrization`, not both",
                "o bien `u` y `v` o bien una `parametrization`, no ambas",
                [],
            ),
            Fitting::MissingOrParametrization => said(
                lang,
                "missing (this operation needs it, or a `parametrization`: uniform, chord_length, centripetal)",
                "falta (esta operación lo necesita, o una `parametrization`: uniform, chord_length, centripetal)",
                [],
            ),
            Fitting::GridEnds => said(
                lang,
                "given end derivatives are for curves: a grid takes `natural` or `bessel`",
                "las derivadas dadas en los extremos son para curvas: una malla de datos admite `natural` o `bessel`",
                [],
            ),
            Fitting::GridBasis => said(
                lang,
                "a grid is interpolated by a Bézier patch or a bicubic spline (`bezier`, `bicubic`); `bspline` of a degree p is for curves",
                "una malla de datos se interpola con una superficie de Bézier o un spline bicúbico (`bezier`, `bicubic`); `bspline` de grado p es para curvas",
                [],
            ),
            Fitting::GridNeedsUV => said(
                lang,
                "a grid of points needs the parameters `u` and `v` (a list of points takes `params`)",
                "una malla de datos necesita los parámetros `u` y `v` (una lista de puntos lleva `params`)",
                [],
            ),
            Fitting::CurveParameters { how, list } => said(
                lang,
                "the parameters, «»: ‹›",
                "los parámetros, «»: ‹›",
                [how.phrase(lang).into(), list.into()],
            ),
            Fitting::ParamsOrParametrization => said(
                lang,
                "either `params` or a `parametrization`, not both",
                "o bien `params` o bien una `parametrization`, no ambas",
                [],
            ),
            Fitting::EndDerivatives { found } => said(
                lang,
                "expected two end derivatives [$c'(t_0), c'(t_n)$], found ‹›",
                "se esperaban dos derivadas en los extremos [$c'(t_0), c'(t_n)$], se encontraron ‹›",
                [found.into()],
            ),
            Fitting::TangentsNeedClamped => said(
                lang,
                "end derivatives go with `end`: `clamped` (a cubic spline, or a B-spline of `degree` p)",
                "las derivadas en los extremos van con `end`: `clamped` (un spline cúbico, o una B-spline de grado p, `degree`)",
                [],
            ),
            Fitting::BSplineEnd => said(
                lang,
                "a B-spline of `degree` p takes `end`: `clamped` with `tangents` (natural and Bessel ends are for the cubic spline, `bicubic`)",
                "una B-spline de grado p (`degree`) lleva `end`: `clamped` con `tangents` (los extremos natural y de Bessel son del spline cúbico, `bicubic`)",
                [],
            ),
            Fitting::BSplineDegreeRange { points, max } => said(
                lang,
                "a B-spline interpolant of ‹› points has a degree from 1 to ‹›",
                "un interpolante B-spline de ‹› puntos tiene un grado de 1 a ‹›",
                [points.into(), max.into()],
            ),
            Fitting::Increasing => said(
                lang,
                "a B-spline interpolant takes increasing parameters",
                "un interpolante B-spline lleva parámetros crecientes",
                [],
            ),
            Fitting::MissingOrParametrizationShort => said(
                lang,
                "missing (this operation needs it, or a `parametrization`)",
                "falta (esta operación lo necesita, o una `parametrization`)",
                [],
            ),
            Fitting::UVNotNumber => said(
                lang,
                "expected two numbers [u, v], found a number",
                "se esperaban dos números [u, v], se encontró un número",
                [],
            ),
            Fitting::PatchDegreeNumber { n } => said(
                lang,
                "expected two integers [m, n] for a patch, found the number ‹›",
                "se esperaban dos enteros [m, n] para una superficie, se encontró el número ‹›",
                [n.into()],
            ),
            Fitting::PatchOfBidegree { m, n } => said(
                lang,
                "a patch of bidegree (‹›, ‹›)",
                "una superficie de bigrado (‹›, ‹›)",
                [m.into(), n.into()],
            ),
            Fitting::BSplineSurface => said(
                lang,
                "the B-spline surface",
                "la superficie B-spline",
                [],
            ),
            Fitting::FirstIsNumber => said(
                lang,
                "expected a number t (the first parameter is a number), found a list",
                "se esperaba un número t (el primer parámetro es un número), se encontró una lista",
                [],
            ),
            Fitting::DegreeNotList => said(
                lang,
                "expected a non-negative integer, found a list of 2",
                "se esperaba un entero no negativo, se encontró una lista de 2",
                [],
            ),
            Fitting::BSpline => said(
                lang,
                "the B-spline",
                "la B-spline",
                [],
            ),
            Fitting::KnotsForTooFewPoints {
                knots,
                degree,
                unknowns,
                found,
            } => said(
                lang,
                "the ‹› knots of degree ‹› are read in the notes' convention (without end knots, n + p - 1 knots for n control points): they make ‹› control points, which need at least ‹› data points, found ‹›",
                "los ‹› nudos de grado ‹› se leen en el convenio de los apuntes (sin nudos extremos, n + p - 1 nudos para n puntos de control): dan ‹› puntos de control, que necesitan al menos ‹› puntos dato; se dieron ‹›",
                [
                    knots.into(),
                    degree.into(),
                    unknowns.into(),
                    unknowns.into(),
                    found.into(),
                ],
            ),
            Fitting::KnotsLookFull {
                knots,
                degree,
                unknowns,
                found,
            } => said(
                lang,
                "the ‹› knots of degree ‹› are read in the notes' convention (without end knots, n + p - 1 knots for n control points): they make ‹› control points, which need at least ‹› data points, found ‹›; the vector repeats each end knot ‹› times, as The NURBS Book does (n + p + 1 knots, one more at each end): without its first and last knot it is the notes' vector of ‹› knots, for ‹› control points",
                "los ‹› nudos de grado ‹› se leen en el convenio de los apuntes (sin nudos extremos, n + p - 1 nudos para n puntos de control): dan ‹› puntos de control, que necesitan al menos ‹› puntos dato; se dieron ‹›; la sucesión repite cada nudo extremo ‹› veces, como el libro de Piegl y Tiller (n + p + 1 nudos, uno más en cada extremo): sin su primer y su último nudo es la sucesión de los apuntes de ‹› nudos, para ‹› puntos de control",
                [
                    knots.into(),
                    degree.into(),
                    unknowns.into(),
                    unknowns.into(),
                    found.into(),
                    (&(degree + 1)).into(),
                    (&knots.saturating_sub(2)).into(),
                    (&unknowns.saturating_sub(2)).into(),
                ],
            ),
            Fitting::NumberNotList => said(
                lang,
                "expected a number, found a list",
                "se esperaba un número, se encontró una lista",
                [],
            ),
            Fitting::BlossomCurve => said(
                lang,
                "the blossom is taken of a Bézier curve (`bezier`); of a B-spline, `extract` its Bézier pieces first (each piece's blossom is the B-spline's on that span)",
                "la forma polar es de una curva de Bézier (`bezier`); de una B-spline, extraiga (`extract`) antes sus tramos de Bézier (la forma polar de cada tramo es la de la B-spline en ese intervalo)",
                [],
            ),
            Fitting::BlossomSurface => said(
                lang,
                "the blossom is taken of a Bézier patch (`bezier`); of a B-spline surface, `extract` its Bézier patches first",
                "la forma polar es de una superficie de Bézier (`bezier`); de una superficie B-spline, extraiga (`extract`) antes sus trozos de Bézier",
                [],
            ),
            Fitting::BlossomNeeds => said(
                lang,
                "blossom needs a `curve`, a `surface` or a `triangle`",
                "la forma polar (`blossom`) necesita una curva (`curve`), una superficie (`surface`) o una superficie triangular (`triangle`)",
                [],
            ),
            Fitting::SplitSurfaceWhere => said(
                lang,
                "missing (give `u`, `v` or both: where the surface is split)",
                "falta (dé `u`, `v` o ambos: dónde se divide la superficie)",
                [],
            ),
            Fitting::SurfacesOfSubdivision => said(
                lang,
                "the surfaces of the subdivision",
                "las superficies de la subdivisión",
                [],
            ),
            Fitting::SplitPatchWhere => said(
                lang,
                "missing (give `u`, `v` or both: where the patch is split)",
                "falta (dé `u`, `v` o ambos: dónde se divide la superficie)",
                [],
            ),
            Fitting::NotInsideUnit { x } => said(
                lang,
                "‹› is not strictly inside (0, 1): the patch is split inside its domain",
                "‹› no está estrictamente dentro de (0, 1): la superficie se divide dentro de su recinto",
                [x.into()],
            ),
            Fitting::SubdivisionPatches => said(
                lang,
                "subdivision is for Bézier patches; a B-spline surface is split into its Bézier patches by `extract`",
                "la subdivisión es para superficies de Bézier; una superficie B-spline se divide en sus trozos de Bézier con `extract`",
                [],
            ),
            Fitting::SubdivideNeeds => said(
                lang,
                "subdivide needs a `curve`, a `surface` or a `triangle`",
                "la subdivisión (`subdivide`) necesita una curva (`curve`), una superficie (`surface`) o una superficie triangular (`triangle`)",
                [],
            ),
            Fitting::SubdivisionMap => said(
                lang,
                "subdivision is for curves given by control points; a polynomial map is split by `restrict`-ing its Bézier form",
                "la subdivisión es para curvas dadas por puntos de control; una aplicación polinómica se divide restringiendo (`restrict`) su forma de Bézier",
                [],
            ),
            Fitting::IsoBoth => said(
                lang,
                "give `u` (the curve u = u0) or `v` (the curve v = v0), not both: both make a point (`evaluate`)",
                "dé `u` (la curva u = u0) o `v` (la curva v = v0), no ambos: los dos dan un punto (`evaluate`)",
                [],
            ),
            Fitting::IsoNeither => said(
                lang,
                "missing (give `u` for the curve u = u0, or `v` for v = v0)",
                "falta (dé `u` para la curva u = u0, o `v` para v = v0)",
                [],
            ),
            Fitting::BezierPieces => said(
                lang,
                "the Bézier pieces",
                "los tramos de Bézier",
                [],
            ),
            Fitting::BezierPatches => said(
                lang,
                "the Bézier patches",
                "los trozos de Bézier",
                [],
            ),
            Fitting::ExtractCurve => said(
                lang,
                "Bézier extraction is for B-spline and NURBS curves (`bspline`); a Bézier curve is its own one piece",
                "la extracción de Bézier es para curvas B-spline y NURBS (`bspline`); una curva de Bézier es su propio y único tramo",
                [],
            ),
            Fitting::ExtractSurface => said(
                lang,
                "Bézier extraction is for B-spline and NURBS surfaces (`bspline`); a Bézier patch is its own one piece",
                "la extracción de Bézier es para superficies B-spline y NURBS (`bspline`); una superficie de Bézier es su propio y único trozo",
                [],
            ),
            Fitting::ExtractNeeds => said(
                lang,
                "extract needs a `curve` or a `surface`",
                "la extracción (`extract`) necesita una curva (`curve`) o una superficie (`surface`)",
                [],
            ),
            Fitting::RemoveKnotCurve => said(
                lang,
                "knot removal needs a B-spline or NURBS curve (`bspline`, `knots`)",
                "quitar un nudo requiere una curva B-spline o NURBS (`bspline`, `knots`)",
                [],
            ),
            Fitting::ReducedLeastSquares { m } => said(
                lang,
                "not exact: the curve is not of degree ‹›; this is the least-squares reduction of the control polygon (E^t E c̃ = E^t c), a different curve",
                "no exacta: la curva no es de grado ‹›; esta es la reducción por mínimos cuadrados del polígono de control (E^t E c̃ = E^t c), una curva distinta",
                [m.into()],
            ),
        }
    }
}

cagd_words::display_english!(Fitting, How);

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_variant_in_both_languages() {
        for m in Fitting::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()));
        }
        for m in How::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()));
        }
    }
}
