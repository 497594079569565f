//! The one error type of cagd-fit.

use cagd_bezier::BezierError;
use cagd_bspline::BSplineError;
use cagd_linalg::LinalgError;
use cagd_spline_surface::{Direction, SplineSurfaceError};
use cagd_surface::SurfaceError;
use cagd_words::{said, Lang, Message, Phrase};

/// What can go wrong when fitting a curve or a surface to data.
///
/// Numbers inside the messages are written exactly (`1/2`, `√2/2`); indices are those of the
/// data as given (a_0, a_1, ... and u_0, u_1, ...).
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
#[non_exhaustive]
pub enum FitError {
    /// No data points at all.
    NoData,
    /// A different number of parameters than data points.
    CountMismatch {
        /// The number of data points.
        points: usize,
        /// The number of parameters.
        parameters: usize,
    },
    /// Data point `index` has another dimension than data point 0 (or than the end tangents).
    DimensionMismatch {
        /// What has the wrong dimension.
        what: Datum,
        /// The dimension of data point 0.
        expected: usize,
        /// The dimension found.
        found: usize,
    },
    /// Two data points share one parameter: the interpolation system is singular.
    RepeatedParameter {
        /// The first index with that parameter.
        first: usize,
        /// The second index with that parameter.
        second: usize,
        /// The shared parameter, as text.
        value: String,
    },
    /// The knots of a spline interpolant do not increase strictly.
    NotIncreasing {
        /// The index of the knot that is not greater than the one before it.
        index: usize,
        /// The knot before, as text.
        before: String,
        /// The knot at `index`, as text.
        value: String,
    },
    /// Fewer data than the method needs.
    TooFewPoints {
        /// What is fitted.
        what: Fitted,
        /// How many are needed.
        needed: usize,
        /// How many were given.
        found: usize,
    },
    /// More data than an interpolation takes (one point per control point).
    TooManyPoints {
        /// What is fitted.
        what: Fitted,
        /// How many it takes.
        expected: usize,
        /// How many were given.
        found: usize,
    },
    /// Least squares of degree n with fewer than n + 1 distinct parameters: the Bernstein
    /// collocation matrix has dependent columns whatever the data.
    TooFewDistinctParameters {
        /// The degree n.
        degree: usize,
        /// The number of distinct parameters.
        found: usize,
    },
    /// A B-spline control point that no parameter reaches: its basis function vanishes at every
    /// parameter, so nothing determines it.
    UndeterminedControlPoint {
        /// The index j of the control point d_j.
        index: usize,
        /// The support of N_j.
        support: Support,
    },
    /// A parameter outside the domain of the knot vector.
    ParameterOutsideDomain {
        /// The index i of the parameter u_i.
        index: usize,
        /// The parameter, as text.
        value: String,
        /// The left end of the domain.
        start: String,
        /// The right end of the domain.
        end: String,
    },
    /// A grid of surface data whose shape does not match the parameters: row i of the data is
    /// c(u_i, ·), column j is c(·, v_j).
    GridShape {
        /// Rows of the data grid.
        rows: usize,
        /// Columns of the data grid.
        cols: usize,
        /// The number of parameters u_i.
        u_count: usize,
        /// The number of parameters v_j.
        v_count: usize,
    },
    /// Grid interpolation with two equal parameters in one direction: the collocation matrix
    /// B_U (or B_V) has two equal rows.
    RepeatedGridParameter {
        /// The direction of the parameters.
        direction: Direction,
        /// The first index with that parameter.
        first: usize,
        /// The second index with that parameter.
        second: usize,
        /// The shared parameter, as text.
        value: String,
    },
    /// Spline grid interpolation with parameters that do not increase strictly.
    GridNotIncreasing {
        /// The direction of the parameters.
        direction: Direction,
        /// The index of the parameter that is not greater than the one before it.
        index: usize,
        /// The parameter before, as text.
        before: String,
        /// The parameter at `index`, as text.
        value: String,
    },
    /// A clamped end condition (one given tangent vector) asked of a surface interpolant.
    ClampedSurfaceEnd {
        /// The direction whose end condition is clamped.
        direction: Direction,
        /// Whether it is the end (u_M or v_N) rather than the start.
        at_end: bool,
    },
    /// A fit of bidegree (m, n) with too few distinct parameters in one direction:
    /// the collocation matrix has dependent columns whatever the data.
    TooFewDistinctSurfaceParameters {
        /// The direction of the parameters.
        direction: Direction,
        /// The degree in that direction.
        degree: usize,
        /// The number of distinct parameters found.
        found: usize,
    },
    /// Interpolation with scattered parameters (the notes' eq. (28) with as many points as
    /// control points) whose collocation matrix B is singular.
    SingularScattered {
        /// The bidegree (m, n).
        bidegree: (usize, usize),
        /// Why.
        detail: Singularity,
    },
    /// Least squares of a surface whose normal matrix BᵗB is singular: the parameters do not
    /// determine every control point.
    UndeterminedMesh {
        /// What is fitted.
        what: Fitted,
        /// What the elimination found.
        detail: cagd_linalg::Singularity,
    },
    /// A parameter of surface data outside the domain of a knot vector.
    SurfaceParameterOutsideDomain {
        /// The direction of the parameter.
        direction: Direction,
        /// The index k of the data point a_k.
        index: usize,
        /// The parameter, as text.
        value: String,
        /// The left end of the domain.
        start: String,
        /// The right end of the domain.
        end: String,
    },
    /// A control point d_ij of a B-spline surface that no parameter reaches: its basis
    /// function N_i(u) N_j(v) vanishes at every parameter (u_k, v_k).
    UndeterminedSurfaceControlPoint {
        /// The row index i.
        row: usize,
        /// The column index j.
        col: usize,
        /// The support of N_i(u) N_j(v): the supports of N_i and N_j.
        support: (Support, Support),
    },
    /// A degree that does not fit the number of data points.
    DegreeOutOfRange {
        /// What is fitted.
        what: Fitted,
        /// The degree asked for.
        degree: usize,
        /// The number of data points.
        points: usize,
        /// The least degree that fits.
        low: usize,
        /// The greatest degree that fits.
        high: usize,
    },
    /// An error of the linear algebra (a singular normal matrix, with the column that has no
    /// pivot).
    Linalg(LinalgError),
    /// An error building the Bézier curve.
    Bezier(BezierError),
    /// An error building the knot vector or the B-spline curve, or evaluating its basis.
    BSpline(BSplineError),
    /// An error building a grid, a mesh or a Bézier patch.
    Surface(SurfaceError),
    /// An error building or evaluating a B-spline surface.
    SplineSurface(SplineSurfaceError),
}

/// What a fit needs points for, or what it fits ([`FitError::TooFewPoints`],
/// [`FitError::TooManyPoints`], [`FitError::DegreeOutOfRange`], [`FitError::UndeterminedMesh`]).
#[derive(Debug, Clone, PartialEq, Eq, Hash, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Fitted {
    /// Least squares by a Bézier curve of degree n.
    LeastSquaresDegree {
        /// The degree n.
        degree: usize,
        /// n + 1.
        unknowns: usize,
    },
    /// Least squares by a B-spline curve.
    LeastSquaresUnknowns {
        /// The number of control points.
        unknowns: usize,
        /// The degree.
        degree: usize,
    },
    /// A B-spline interpolant with end derivatives.
    EndDerivatives,
    /// Interpolation with scattered parameters.
    ScatteredInterpolation {
        /// The degree in u.
        m: usize,
        /// The degree in v.
        n: usize,
        /// (m + 1)(n + 1).
        unknowns: usize,
    },
    /// Least squares by a Bézier patch.
    LeastSquaresPatch {
        /// The degree in u.
        m: usize,
        /// The degree in v.
        n: usize,
        /// (m + 1)(n + 1).
        unknowns: usize,
    },
    /// A Bézier patch.
    BezierPatch {
        /// The degree in u.
        m: usize,
        /// The degree in v.
        n: usize,
    },
    /// A B-spline surface.
    SplineSurface {
        /// The degree in u.
        p: usize,
        /// The degree in v.
        q: usize,
        /// Its control points in u.
        rows: usize,
        /// Its control points in v.
        cols: usize,
    },
    /// Least squares by a B-spline surface.
    LeastSquaresSplineSurface {
        /// The degree in u.
        p: usize,
        /// The degree in v.
        q: usize,
        /// Its control points in u.
        rows: usize,
        /// Its control points in v.
        cols: usize,
    },
    /// A Bessel end tangent of a cubic spline.
    BesselEndTangent,
    /// A cubic spline interpolant.
    #[default]
    CubicSpline,
    /// A Bessel end of a surface interpolant, in one direction.
    BesselEndIn {
        /// The direction.
        direction: Direction,
    },
    /// A cubic spline of a surface interpolant, in one direction.
    CubicSplineIn {
        /// The direction.
        direction: Direction,
    },
}

impl Message for Fitted {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Fitted::LeastSquaresDegree { degree, unknowns } => said(
                lang,
                "least squares of degree ‹› (‹› unknown control points)",
                "el ajuste por mínimos cuadrados de grado ‹› (‹› puntos de control incógnita)",
                [degree.into(), unknowns.into()],
            ),
            Fitted::LeastSquaresUnknowns { unknowns, degree } => said(
                lang,
                "least squares with ‹› unknown control points (degree ‹›)",
                "el ajuste por mínimos cuadrados con ‹› puntos de control incógnita (grado ‹›)",
                [unknowns.into(), degree.into()],
            ),
            Fitted::EndDerivatives => said(
                lang,
                "a B-spline interpolant with end derivatives",
                "un interpolante B-spline con derivadas en los extremos",
                [],
            ),
            Fitted::ScatteredInterpolation { m, n, unknowns } => said(
                lang,
                "interpolation by a patch of bidegree (‹›, ‹›) with scattered parameters (‹› control points)",
                "la interpolación por una superficie de bigrado (‹›, ‹›) con parámetros dispersos (‹› puntos de control)",
                [m.into(), n.into(), unknowns.into()],
            ),
            Fitted::LeastSquaresPatch { m, n, unknowns } => said(
                lang,
                "least squares by a patch of bidegree (‹›, ‹›) (‹› unknown control points)",
                "el ajuste por mínimos cuadrados con una superficie de bigrado (‹›, ‹›) (‹› puntos de control incógnita)",
                [m.into(), n.into(), unknowns.into()],
            ),
            Fitted::BezierPatch { m, n } => said(
                lang,
                "a Bézier patch of bidegree (‹›, ‹›)",
                "una superficie de Bézier de bigrado (‹›, ‹›)",
                [m.into(), n.into()],
            ),
            Fitted::SplineSurface { p, q, rows, cols } => said(
                lang,
                "a B-spline surface of bidegree (‹›, ‹›) with ‹› x ‹› control points",
                "una superficie B-spline de bigrado (‹›, ‹›) con ‹› x ‹› puntos de control",
                [p.into(), q.into(), rows.into(), cols.into()],
            ),
            Fitted::LeastSquaresSplineSurface { p, q, rows, cols } => said(
                lang,
                "least squares by a B-spline surface of bidegree (‹›, ‹›) with ‹› x ‹› control points",
                "el ajuste por mínimos cuadrados con una superficie B-spline de bigrado (‹›, ‹›) con ‹› x ‹› puntos de control",
                [p.into(), q.into(), rows.into(), cols.into()],
            ),
            Fitted::BesselEndTangent => said(
                lang,
                "a Bessel end tangent (the parabola through three points)",
                "una tangente extrema de Bessel (la parábola por tres puntos)",
                [],
            ),
            Fitted::CubicSpline => said(
                lang,
                "a cubic spline interpolant",
                "un spline cúbico interpolante",
                [],
            ),
            Fitted::BesselEndIn { direction } => said(
                lang,
                "a Bessel end in ‹› (the parabola through three parameters ‹›)",
                "un extremo de Bessel en ‹› (la parábola por tres parámetros ‹›)",
                [direction.into(), direction.into()],
            ),
            Fitted::CubicSplineIn { direction } => said(
                lang,
                "a cubic spline in ‹›",
                "un spline cúbico en ‹›",
                [direction.into()],
            ),
        }
    }
}

/// The datum of another dimension than data point 0 ([`FitError::DimensionMismatch`]).
#[derive(Debug, Clone, PartialEq, Eq, Hash, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Datum {
    /// Data point i of a curve fit.
    DataPoint {
        /// i.
        index: usize,
    },
    /// Data point a_ij of a grid.
    GridPoint {
        /// i.
        row: usize,
        /// j.
        col: usize,
    },
    /// Entry (i, j) of a grid of data.
    GridEntry {
        /// i.
        row: usize,
        /// j.
        col: usize,
    },
    /// The start derivative D_0.
    StartDerivative,
    /// The end derivative D_n.
    EndDerivative,
    /// The start tangent of a cubic spline.
    #[default]
    StartTangent,
    /// The end tangent of a cubic spline.
    EndTangent,
}

impl Message for Datum {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Datum::DataPoint { index } => {
                said(lang, "data point ‹›", "el punto dato ‹›", [index.into()])
            }
            Datum::GridPoint { row, col } => said(
                lang,
                "data point $a_‹›,‹›$ (point 0 is $a_0,0$)",
                "el punto dato $a_‹›,‹›$ (el punto 0 es $a_0,0$)",
                [row.into(), col.into()],
            ),
            Datum::GridEntry { row, col } => said(
                lang,
                "point ‹›,‹› of the grid (point 0 is the entry 0,0)",
                "el punto ‹›,‹› de la malla de datos (el punto 0 es la entrada 0,0)",
                [row.into(), col.into()],
            ),
            Datum::StartDerivative => said(
                lang,
                "the start derivative $D_0$",
                "la derivada inicial $D_0$",
                [],
            ),
            Datum::EndDerivative => said(
                lang,
                "the end derivative $D_n$",
                "la derivada final $D_n$",
                [],
            ),
            Datum::StartTangent => said(lang, "the start tangent", "la tangente inicial", []),
            Datum::EndTangent => said(lang, "the end tangent", "la tangente final", []),
        }
    }
}

/// The support [t_i, t_{i+p+1}] of a B-spline basis function N_i (full convention)
/// ([`FitError::UndeterminedControlPoint`], [`FitError::UndeterminedSurfaceControlPoint`]).
#[derive(Debug, Clone, PartialEq, Eq, Hash, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Support {
    /// [start, end], the knots as text.
    Interval {
        /// t_i.
        start: String,
        /// t_{i+p+1}.
        end: String,
    },
    /// An index past the knot vector (no such basis function).
    #[default]
    Outside,
}

impl Message for Support {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Support::Interval { start, end } => {
                said(lang, "[‹›, ‹›]", "[‹›, ‹›]", [start.into(), end.into()])
            }
            Support::Outside => said(
                lang,
                "(outside the knot vector)",
                "(fuera de la sucesión de nudos)",
                [],
            ),
        }
    }
}

/// Why interpolation with scattered parameters is singular
/// ([`FitError::SingularScattered`]).
#[derive(Debug, Clone, PartialEq, Eq, Hash, strum::EnumIter)]
#[non_exhaustive]
pub enum Singularity {
    /// Two points with the same parameters.
    SameParameters {
        /// The first point's index l.
        first: usize,
        /// The second point's index k.
        second: usize,
        /// The shared u, as text.
        u: String,
        /// The shared v, as text.
        v: String,
    },
    /// What the elimination found.
    Elimination(cagd_linalg::Singularity),
}

impl Default for Singularity {
    fn default() -> Self {
        Singularity::Elimination(cagd_linalg::Singularity::default())
    }
}

impl Message for Singularity {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Singularity::SameParameters {
                first,
                second,
                u,
                v,
            } => said(
                lang,
                "points $a_‹›$ and $a_‹›$ have the same parameters (‹›, ‹›), so B has two equal rows",
                "los puntos $a_‹›$ y $a_‹›$ tienen los mismos parámetros (‹›, ‹›), así que B tiene dos filas iguales",
                [first.into(), second.into(), u.into(), v.into()],
            ),
            Singularity::Elimination(detail) => said(lang, "«»", "«»", [detail.phrase(lang).into()]),
        }
    }
}

impl Message for FitError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            FitError::NoData => said(
                lang,
                "no data points: a fit needs at least one point",
                "no hay datos: un ajuste necesita al menos un punto",
                [],
            ),
            FitError::CountMismatch { points, parameters } => said(
                lang,
                "‹› data points but ‹› parameters: give one parameter per point",
                "‹› puntos dato, pero ‹› parámetros: dé un parámetro por punto",
                [points.into(), parameters.into()],
            ),
            FitError::DimensionMismatch {
                what,
                expected,
                found,
            } => said(
                lang,
                "«» has dimension ‹›, but data point 0 has dimension ‹›",
                "«» tiene dimensión ‹›, pero el punto dato 0 tiene dimensión ‹›",
                [what.phrase(lang).into(), found.into(), expected.into()],
            ),
            FitError::RepeatedParameter {
                first,
                second,
                value,
            } => said(
                lang,
                "singular: parameters $u_‹›$ and $u_‹›$ are equal (both ‹›); a curve cannot pass through two points at one parameter",
                "singular: los parámetros $u_‹›$ y $u_‹›$ son iguales (ambos ‹›); una curva no puede pasar por dos puntos con un mismo parámetro",
                [first.into(), second.into(), value.into()],
            ),
            FitError::NotIncreasing {
                index,
                before,
                value,
            } => said(
                lang,
                "the knots must increase strictly: $u_‹›$ = ‹› is not greater than $u_‹›$ = ‹›",
                "los nudos han de ser estrictamente crecientes: $u_‹›$ = ‹› no es mayor que $u_‹›$ = ‹›",
                [
                    index.into(),
                    value.into(),
                    (&index.saturating_sub(1)).into(),
                    before.into(),
                ],
            ),
            FitError::TooFewPoints {
                what,
                needed,
                found,
            } => said(
                lang,
                "«» needs at least ‹› data points, found ‹›",
                "«» necesita al menos ‹› puntos dato, se encontraron ‹›",
                [what.phrase(lang).into(), needed.into(), found.into()],
            ),
            FitError::DegreeOutOfRange {
                what,
                degree,
                points,
                low,
                high,
            } => said(
                lang,
                "«» through ‹› data points has a degree from ‹› to ‹›, found ‹›",
                "«» por ‹› puntos dato tiene un grado de ‹› a ‹›, se encontró ‹›",
                [
                    what.phrase(lang).into(),
                    points.into(),
                    low.into(),
                    high.into(),
                    degree.into(),
                ],
            ),
            FitError::TooManyPoints {
                what,
                expected,
                found,
            } => said(
                lang,
                "«» takes exactly ‹› data points (one per control point), found ‹›: approximate them by least squares instead",
                "«» toma exactamente ‹› puntos dato (uno por punto de control), se encontraron ‹›: aproxímelos por mínimos cuadrados",
                [what.phrase(lang).into(), expected.into(), found.into()],
            ),
            FitError::TooFewDistinctParameters { degree, found } => said(
                lang,
                "least squares of degree ‹› needs at least ‹› distinct parameters, found ‹›: the normal matrix would be singular",
                "el ajuste por mínimos cuadrados de grado ‹› necesita al menos ‹› parámetros distintos, se encontraron ‹›: la matriz normal sería singular",
                [degree.into(), (&(degree + 1)).into(), found.into()],
            ),
            FitError::UndeterminedControlPoint { index, support } => said(
                lang,
                "control point $d_‹›$ is not determined: no parameter lies in the support «» of its basis function $N_‹›$",
                "el punto de control $d_‹›$ no queda determinado: ningún parámetro está en el soporte «» de su función base $N_‹›$",
                [index.into(), support.phrase(lang).into(), index.into()],
            ),
            FitError::ParameterOutsideDomain {
                index,
                value,
                start,
                end,
            } => said(
                lang,
                "parameter $u_‹›$ = ‹› is outside the domain [‹›, ‹›] of the knot vector",
                "el parámetro $u_‹›$ = ‹› está fuera del dominio [‹›, ‹›] de la sucesión de nudos",
                [index.into(), value.into(), start.into(), end.into()],
            ),
            FitError::GridShape {
                rows,
                cols,
                u_count,
                v_count,
            } => said(
                lang,
                "the data grid has ‹› rows and ‹› columns, but ‹› parameters $u_i$ and ‹› parameters $v_j$ were given: row i of the data is $c(u_i, v_0)$, ..., $c(u_i, v_n)$, so give one $u_i$ per row and one $v_j$ per column",
                "la malla de datos tiene ‹› filas y ‹› columnas, pero se dieron ‹› parámetros $u_i$ y ‹› parámetros $v_j$: la fila i de los datos es $c(u_i, v_0)$, ..., $c(u_i, v_n)$, así que dé un $u_i$ por fila y un $v_j$ por columna",
                [rows.into(), cols.into(), u_count.into(), v_count.into()],
            ),
            FitError::RepeatedGridParameter {
                direction,
                first,
                second,
                value,
            } => {
                let upper = direction.to_string().to_uppercase();
                let holes = [
                    direction.into(),
                    first.into(),
                    direction.into(),
                    second.into(),
                    value.into(),
                    (&upper).into(),
                ];
                match direction {
                    Direction::U => said(
                        lang,
                        "singular: parameters $‹›_‹›$ and $‹›_‹›$ are equal (both ‹›); the matrix $B_‹›$ has two equal rows, and a surface cannot interpolate two rows of data at one parameter",
                        "singular: los parámetros $‹›_‹›$ y $‹›_‹›$ son iguales (ambos ‹›); la matriz $B_‹›$ tiene dos filas iguales, y una superficie no puede interpolar dos filas de datos con un mismo parámetro",
                        holes,
                    ),
                    Direction::V => said(
                        lang,
                        "singular: parameters $‹›_‹›$ and $‹›_‹›$ are equal (both ‹›); the matrix $B_‹›$ has two equal rows, and a surface cannot interpolate two columns of data at one parameter",
                        "singular: los parámetros $‹›_‹›$ y $‹›_‹›$ son iguales (ambos ‹›); la matriz $B_‹›$ tiene dos filas iguales, y una superficie no puede interpolar dos columnas de datos con un mismo parámetro",
                        holes,
                    ),
                }
            }
            FitError::GridNotIncreasing {
                direction,
                index,
                before,
                value,
            } => {
                let letter = if *direction == Direction::U { 'i' } else { 'j' };
                said(
                    lang,
                    "the parameters $‹›_‹›$ of a spline interpolant must increase strictly: $‹›_‹›$ = ‹› is not greater than $‹›_‹›$ = ‹›",
                    "los parámetros $‹›_‹›$ de un interpolante spline han de ser estrictamente crecientes: $‹›_‹›$ = ‹› no es mayor que $‹›_‹›$ = ‹›",
                    [
                        direction.into(),
                        (&letter).into(),
                        direction.into(),
                        index.into(),
                        value.into(),
                        direction.into(),
                        (&index.saturating_sub(1)).into(),
                        before.into(),
                    ],
                )
            }
            FitError::ClampedSurfaceEnd { direction, at_end } => {
                let holes = [direction.into()];
                match (at_end, direction) {
                    (false, Direction::U) => said(
                        lang,
                        "a clamped start condition in ‹› (one given tangent vector) does not apply to a surface: every column of data would need its own tangent; use natural or Bessel ends",
                        "una condición inicial de tangente dada en ‹› (un solo vector tangente) no sirve para una superficie: cada columna de datos necesitaría su propia tangente; use extremos naturales o de Bessel",
                        holes,
                    ),
                    (false, Direction::V) => said(
                        lang,
                        "a clamped start condition in ‹› (one given tangent vector) does not apply to a surface: every row of data would need its own tangent; use natural or Bessel ends",
                        "una condición inicial de tangente dada en ‹› (un solo vector tangente) no sirve para una superficie: cada fila de datos necesitaría su propia tangente; use extremos naturales o de Bessel",
                        holes,
                    ),
                    (true, Direction::U) => said(
                        lang,
                        "a clamped end condition in ‹› (one given tangent vector) does not apply to a surface: every column of data would need its own tangent; use natural or Bessel ends",
                        "una condición final de tangente dada en ‹› (un solo vector tangente) no sirve para una superficie: cada columna de datos necesitaría su propia tangente; use extremos naturales o de Bessel",
                        holes,
                    ),
                    (true, Direction::V) => said(
                        lang,
                        "a clamped end condition in ‹› (one given tangent vector) does not apply to a surface: every row of data would need its own tangent; use natural or Bessel ends",
                        "una condición final de tangente dada en ‹› (un solo vector tangente) no sirve para una superficie: cada fila de datos necesitaría su propia tangente; use extremos naturales o de Bessel",
                        holes,
                    ),
                }
            }
            FitError::TooFewDistinctSurfaceParameters {
                direction,
                degree,
                found,
            } => said(
                lang,
                "a patch of degree ‹› in ‹› needs at least ‹› distinct values of ‹› among the parameters $(u_k, v_k)$, found ‹›: the columns of the collocation matrix B are linearly dependent whatever the data",
                "una superficie de grado ‹› en ‹› necesita al menos ‹› valores distintos de ‹› entre los parámetros $(u_k, v_k)$, se encontraron ‹›: las columnas de la matriz de colocación B son linealmente dependientes sean cuales sean los datos",
                [
                    degree.into(),
                    direction.into(),
                    (&(degree + 1)).into(),
                    direction.into(),
                    found.into(),
                ],
            ),
            FitError::SingularScattered { bidegree, detail } => said(
                lang,
                "the interpolation problem with scattered parameters is singular for these parameters: $det B = 0$ for the collocation matrix B of eq. (28), bidegree (‹›, ‹›): «». This is not the data's fault: swapping the parameters $(u_i, v_i)$ and $(u_j, v_j)$ of two points swaps two rows of B and changes the sign of $det B$, so moving the parameters continuously from one order to the other passes through parameters with $det B = 0$ (points of the plane, unlike those of a line, have no order that prevents it). Choose other parameters, or fit more points by least squares",
                "el problema de interpolación con parámetros dispersos es singular para estos parámetros: $det B = 0$ para la matriz de colocación B de la ec. (28), bigrado (‹›, ‹›): «». No es culpa de los datos: intercambiar los parámetros $(u_i, v_i)$ y $(u_j, v_j)$ de dos puntos intercambia dos filas de B y cambia el signo de $det B$, así que al mover los parámetros de forma continua de un orden al otro se pasa por parámetros con $det B = 0$ (los puntos del plano, a diferencia de los de una recta, no tienen un orden que lo impida). Elija otros parámetros, o ajuste más puntos por mínimos cuadrados",
                [
                    (&bidegree.0).into(),
                    (&bidegree.1).into(),
                    detail.phrase(lang).into(),
                ],
            ),
            FitError::UndeterminedMesh { what, detail } => said(
                lang,
                "least squares by «» is singular for these parameters $(u_k, v_k)$: they do not determine every control point (as when they all lie on one line of the domain); «»",
                "el ajuste por mínimos cuadrados con «» es singular para estos parámetros $(u_k, v_k)$: no determinan todos los puntos de control (como cuando están todos en una misma recta del recinto); «»",
                [what.phrase(lang).into(), detail.phrase(lang).into()],
            ),
            FitError::SurfaceParameterOutsideDomain {
                direction,
                index,
                value,
                start,
                end,
            } => said(
                lang,
                "parameter $‹›_‹›$ = ‹› (of data point $a_‹›$) is outside the domain [‹›, ‹›] of the knot vector in ‹›",
                "el parámetro $‹›_‹›$ = ‹› (del punto dato $a_‹›$) está fuera del dominio [‹›, ‹›] de la sucesión de nudos en ‹›",
                [
                    direction.into(),
                    index.into(),
                    value.into(),
                    index.into(),
                    start.into(),
                    end.into(),
                    direction.into(),
                ],
            ),
            FitError::UndeterminedSurfaceControlPoint {
                row,
                col,
                support: (su, sv),
            } => said(
                lang,
                "control point $d_‹›,‹›$ is not determined: no parameter $(u_k, v_k)$ lies in the support «» x «» of its basis function $N_‹›(u) N_‹›(v)$",
                "el punto de control $d_‹›,‹›$ no queda determinado: ningún parámetro $(u_k, v_k)$ está en el soporte «» x «» de su función base $N_‹›(u) N_‹›(v)$",
                [
                    row.into(),
                    col.into(),
                    su.phrase(lang).into(),
                    sv.phrase(lang).into(),
                    row.into(),
                    col.into(),
                ],
            ),
            FitError::Linalg(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            FitError::Bezier(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            FitError::BSpline(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            FitError::Surface(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            FitError::SplineSurface(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
        }
    }
}

cagd_words::display_english!(FitError, Fitted, Datum, Singularity);

impl std::error::Error for FitError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            FitError::Linalg(e) => Some(e),
            FitError::Bezier(e) => Some(e),
            FitError::BSpline(e) => Some(e),
            FitError::Surface(e) => Some(e),
            FitError::SplineSurface(e) => Some(e),
            _ => None,
        }
    }
}

impl From<LinalgError> for FitError {
    fn from(e: LinalgError) -> Self {
        FitError::Linalg(e)
    }
}

impl From<BezierError> for FitError {
    fn from(e: BezierError) -> Self {
        FitError::Bezier(e)
    }
}

impl From<BSplineError> for FitError {
    fn from(e: BSplineError) -> Self {
        FitError::BSpline(e)
    }
}

impl From<SurfaceError> for FitError {
    fn from(e: SurfaceError) -> Self {
        FitError::Surface(e)
    }
}

impl From<SplineSurfaceError> for FitError {
    fn from(e: SplineSurfaceError) -> Self {
        FitError::SplineSurface(e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    fn check(m: &FitError) {
        assert_eq!(cagd_words::check_both(m), Ok(()), "{m:?}");
    }

    #[test]
    fn every_variant_in_both_languages() {
        for m in FitError::iter() {
            check(&m);
            for direction in Direction::iter() {
                for at_end in [false, true] {
                    if let FitError::ClampedSurfaceEnd { .. } = m {
                        check(&FitError::ClampedSurfaceEnd { direction, at_end });
                    }
                }
            }
        }
        for what in Fitted::iter() {
            check(&FitError::TooFewPoints {
                what,
                needed: 3,
                found: 2,
            });
        }
        for what in Datum::iter() {
            check(&FitError::DimensionMismatch {
                what,
                expected: 3,
                found: 2,
            });
        }
        for detail in Singularity::iter() {
            check(&FitError::SingularScattered {
                bidegree: (1, 1),
                detail,
            });
        }
        for support in Support::iter() {
            check(&FitError::UndeterminedControlPoint {
                index: 1,
                support: support.clone(),
            });
            check(&FitError::UndeterminedSurfaceControlPoint {
                row: 1,
                col: 2,
                support: (support.clone(), support),
            });
        }
        for direction in Direction::iter() {
            check(&FitError::RepeatedGridParameter {
                direction,
                first: 0,
                second: 1,
                value: "0".into(),
            });
        }
    }
}
