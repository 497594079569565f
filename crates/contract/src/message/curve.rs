//! The curve operations' own sentences (errors and remarks), and the sentences they compute
//! as result values (a continuity order "infinite", a conic's kind, an arc length not given,
//! where the Gaussian curvature vanishes).

use cagd_words::{said, Lang, Message, Phrase};

/// The curve operations' own sentences (errors, remarks, sentences as result values).
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum Curve {
    // --- evaluation, elevation, restriction, derivatives, knot insertion, circles ---
    /// A curve's parameter given as a list.
    ParamIsAList,
    /// An order (`by`, `order`) given as a list of `found` entries.
    OrderIsAList {
        /// The entries of the list.
        found: usize,
    },
    /// Degree elevation of a curve given as an expression.
    ElevateExpression,
    /// A point inverted on a curve of another dimension.
    InvertDimension {
        /// The point's dimension.
        point: usize,
        /// The curve's.
        curve: usize,
    },
    /// A remark of a point inversion: the point is not on the curve (no parameter of the
    /// domain gives it).
    NotOnCurve,
    /// Restriction of a curve that is not a Bézier curve.
    RestrictBezierOnly,
    /// Knot insertion in a curve that is not a B-spline curve.
    InsertNeedsBSpline,
    /// A knot inserted past multiplicity p + 1, where the curve is already split in two.
    InsertBeyondSplit {
        /// The knot, as text.
        knot: String,
        /// Its multiplicity before.
        multiplicity: usize,
        /// How many insertions were asked.
        times: usize,
        /// The degree p.
        degree: usize,
    },
    /// A remark: an interior knot inserted up to multiplicity p + 1 splits the curve in two.
    SplitByInsertion {
        /// The knot, as text.
        knot: String,
        /// The degree p.
        degree: usize,
    },
    /// `knot_vector` without a vector to read or build.
    KnotVectorNeeds,
    /// Knots asked of a curve that is not a B-spline or NURBS curve.
    KnotsNeedBSpline,
    /// `convention` given with a curve or surface, whose knots tell theirs by their length.
    ConventionWithCurve,
    /// `normalize` without a curve or knots.
    NormalizeNeeds,
    /// A circle's center of one coordinate.
    CircleCenter,
    /// A start angle without a sweep angle.
    StartWithoutSweep,
    // --- circular arcs of exact angles ---
    /// An angle that is not a rational number of degrees.
    AngleNotRational {
        /// The angle given.
        found: String,
    },
    // --- the continuity of two curves ---
    /// A B-spline curve without a piece.
    NoPiece,
    /// A first derivative vanishing at the joint.
    SingularJoint,
    /// Tangents parallel but opposite at the joint.
    CuspJoint,
    /// The factor α of G¹ in letters.
    AlphaInLetters,
    /// The continuity order of a join where every derivative agrees: two pieces that are one
    /// map, two patches across a border (a result value; the one `infinite` of either).
    Infinite,
    // --- the arc length (result values) ---
    // --- the Gaussian curvature ---
    /// A B-spline or NURBS surface where a patch is expected.
    ExpectedPatch,
    // --- degree reduction ---
    /// Degree reduction of a curve of another kind.
    ReductionKinds,
    /// The remark of an exact reduction.
    ReducedExactly {
        /// The lower degree.
        degree: usize,
        /// The control points.
        points: usize,
    },
    // --- reversal ---
    /// The direction of a reversal missing.
    ReverseDirectionMissing,
    // --- conics and tangent developables ---
    /// A conic arc of other than three points.
    ConicThreePoints {
        /// The points given.
        found: usize,
    },
    /// A conic arc of middle weight zero.
    ConicZeroWeight,
    /// A conic arc's kind: an ellipse (a result value).
    Ellipse,
    /// A conic arc's kind: a parabola.
    Parabola,
    /// A conic arc's kind: a hyperbola.
    Hyperbola,
    /// A conic arc's kind not decided (the shape factor in letters).
    ConicUndecided,
    // --- integrals and areas ---
    /// The integral of a rational curve.
    IntegralRational,
    /// Neither a curve nor knots and a degree given to `integral`.
    IntegralNeedsCurveOrKnots,
    /// The enclosed area of a rational curve, or the area of a rational patch.
    AreaRational,
    /// Neither a curve nor a surface given to `area`.
    AreaNeedsCurveOrSurface,
    /// A closed curve run counter-clockwise (a result value).
    CounterClockwise,
    /// A closed curve run clockwise.
    Clockwise,
    /// A closed curve whose signed area is zero.
    NoOrientation,
    /// A closed curve whose orientation is in letters.
    OrientationUndecided,
    /// A section of a lofted surface given as an expression.
    LoftExpression,
    /// A rational section of a lofted surface.
    LoftRational,
    /// A tangent developable of a curve not polynomial.
    TangentDevelopablePolynomial,
    /// A tangent developable of a curve not in R³.
    TangentDevelopableR3,
    // --- B-spline and NURBS pieces ---
    /// A surface of another kind where a B-spline or NURBS surface is expected.
    ExpectedSplineSurface,
    /// A border in letters.
    BorderInLetters,
    /// A derivative where the weight vanishes.
    DerivativeUndefinedThere,
    /// A border outside the surface's domain.
    BorderOutside,
    /// The remark of a surface's derivative not a B-spline surface.
    SurfaceDerivativeNotSpline {
        /// The order in u.
        r: usize,
        /// The order in v.
        s: usize,
        /// The degree in u.
        p: usize,
        /// The degree in v.
        q: usize,
    },
    /// Continuity across knot lines of a surface without knots.
    KnotLinesNeedSpline,
    /// A curve of another kind where a B-spline or NURBS curve is expected.
    ExpectedSplineCurve,
    /// A curve of another kind where a rational, B-spline or NURBS curve is expected.
    ExpectedRationalOrSplineCurve,
    /// The remark of a curve's derivative not a B-spline curve.
    CurveDerivativeNotSpline {
        /// The order.
        r: usize,
        /// The degree.
        p: usize,
    },
    /// Two surfaces whose borders run over different intervals.
    BordersDiffer {
        /// The direction along the border.
        along: String,
        /// The first's interval, start.
        first_from: String,
        /// The first's interval, end.
        first_to: String,
        /// The second's interval, start.
        second_from: String,
        /// The second's interval, end.
        second_to: String,
    },
    /// No piece of the first surface ending where one of the second begins.
    NoMatchingPieces {
        /// The direction across the border.
        dir: String,
        /// Where the first ends.
        end: String,
        /// Where the second begins.
        start: String,
    },
    /// The remark of a second surface moved to follow the first.
    SecondMoved {
        /// The direction across the border.
        dir: String,
        /// Where the second begins.
        start: String,
        /// Where the first ends.
        end: String,
        /// The shift.
        delta: String,
    },
}

impl Message for Curve {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Curve::ParamIsAList => said(
                lang,
                "expected a number t (a curve takes one parameter), found a list",
                "se esperaba un número t (una curva tiene un parámetro), se encontró una lista",
                [],
            ),
            Curve::OrderIsAList { found } => said(
                lang,
                "expected a non-negative integer, found a list of ‹›",
                "se esperaba un entero no negativo, se encontró una lista de ‹›",
                [found.into()],
            ),
            Curve::ElevateExpression => said(
                lang,
                "a curve given as an expression has no degree to elevate; give its control polygon",
                "una curva dada por una expresión no tiene grado que elevar; dé su polígono de control",
                [],
            ),
            Curve::InvertDimension { point, curve } => said(
                lang,
                "the point has dimension ‹› but the curve's points have dimension ‹›",
                "el punto tiene dimensión ‹› pero los puntos de la curva tienen dimensión ‹›",
                [point.into(), curve.into()],
            ),
            Curve::NotOnCurve => said(
                lang,
                "P is not a point of the curve: no parameter of the domain gives it",
                "P no es un punto de la curva: ningún parámetro del dominio lo da",
                [],
            ),
            Curve::RestrictBezierOnly => said(
                lang,
                "restriction is for Bézier curves; split a B-spline at knots with insert_knot",
                "la restricción es para curvas de Bézier; divida una B-spline por sus nudos con `insert_knot`",
                [],
            ),
            Curve::InsertNeedsBSpline => said(
                lang,
                "knot insertion needs a B-spline curve (`bspline`, `knots`)",
                "el algoritmo de inserción necesita una curva B-spline (`bspline`, `knots`)",
                [],
            ),
            Curve::CircleCenter => said(
                lang,
                "the center of a circle needs at least two coordinates",
                "el centro de una circunferencia necesita al menos dos coordenadas",
                [],
            ),
            Curve::InsertBeyondSplit {
                knot,
                multiplicity,
                times,
                degree,
            } => said(
                lang,
                "knot ‹› cannot be inserted ‹› more time(s): it has multiplicity ‹›, and a curve of degree ‹› splits in two at multiplicity ‹› (p + 1, the same count in both conventions for an interior knot); more would leave a basis function with no support",
                "el nudo ‹› no se puede insertar ‹› vez (veces) más: tiene multiplicidad ‹›, y una curva de grado ‹› se parte en dos con multiplicidad ‹› (p + 1, la misma cuenta en ambos convenios para un nudo interior); más dejaría una función base sin soporte",
                [
                    knot.into(),
                    times.into(),
                    multiplicity.into(),
                    degree.into(),
                    (&(degree + 1)).into(),
                ],
            ),
            Curve::SplitByInsertion { knot, degree } => said(
                lang,
                "at multiplicity ‹› (p + 1) the knot ‹› splits the curve in two: inserted up to multiplicity ‹› (p) the curve passes through a control point there, and the curves on either side of it are the answer, each on its own knots (the knot ‹› repeated p times at its end in the notes' convention, p + 1 times in The NURBS Book's)",
                "con multiplicidad ‹› (p + 1) el nudo ‹› parte la curva en dos: insertado hasta la multiplicidad ‹› (p) la curva pasa allí por un punto de control, y las curvas a cada lado son la respuesta, cada una con sus nudos (el nudo ‹› repetido p veces en su extremo en el convenio de los apuntes, p + 1 veces en el de Piegl y Tiller)",
                [
                    (&(degree + 1)).into(),
                    knot.into(),
                    degree.into(),
                    knot.into(),
                ],
            ),
            Curve::KnotVectorNeeds => said(
                lang,
                "`knot_vector` needs `knots` (with `degree`), a B-spline or NURBS `curve`, or a `spacing` (with `degree` and `control_points`)",
                "`knot_vector` necesita nudos (`knots`, con `degree`), una curva B-spline o NURBS (`curve`) o un espaciado (`spacing`, con `degree` y `control_points`)",
                [],
            ),
            Curve::KnotsNeedBSpline => said(
                lang,
                "a knot vector is that of a B-spline or NURBS curve or surface (`bspline`, `knots`)",
                "una sucesión de nudos es la de una curva o superficie B-spline o NURBS (`bspline`, `knots`)",
                [],
            ),
            Curve::ConventionWithCurve => said(
                lang,
                "the knots of a curve or surface tell their convention by their length (n + p - 1 the notes', n + p + 1 The NURBS Book's): `convention` goes with `knots` or `spacing`",
                "los nudos de una curva o superficie dicen su convenio por su número (n + p - 1 el de los apuntes, n + p + 1 el de Piegl y Tiller): `convention` va con `knots` o con `spacing`",
                [],
            ),
            Curve::NormalizeNeeds => said(
                lang,
                "`normalize` needs a B-spline or NURBS `curve` or `surface`, or `knots` with `degree`",
                "`normalize` necesita una curva B-spline o NURBS (`curve`), una superficie B-spline o NURBS (`surface`) o nudos (`knots`) con `degree`",
                [],
            ),
            Curve::StartWithoutSweep => said(
                lang,
                "a start angle goes with a `sweep` angle",
                "un ángulo inicial va con un ángulo de barrido (`sweep`)",
                [],
            ),
            Curve::AngleNotRational { found } => said(
                lang,
                "an angle is a rational number of degrees (90, 45/2), found ‹›",
                "un ángulo es un número racional de grados sexagesimales (90, 45/2), se encontró ‹›",
                [found.into()],
            ),
            Curve::NoPiece => said(
                lang,
                "the curve has no piece",
                "la curva no tiene ningún trozo",
                [],
            ),
            Curve::SingularJoint => said(
                lang,
                "a first derivative vanishes at the joint: the joint is singular, and G^1 is not decided by the tangents",
                "una primera derivada se anula en la unión: la unión es singular, y las tangentes no deciden G^1",
                [],
            ),
            Curve::CuspJoint => said(
                lang,
                "the tangents are parallel but opposite (α < 0): a cusp, not G^1",
                "las tangentes son paralelas pero de sentidos opuestos (α < 0): un pico, no G^1",
                [],
            ),
            Curve::AlphaInLetters => said(
                lang,
                "α is in letters: its sign, and so G^1, is not decided",
                "α está en letras: su signo, y con él G^1, queda sin decidir",
                [],
            ),
            Curve::Infinite => said(lang, "infinite", "infinito", []),
            Curve::ExpectedPatch => said(lang, "expected a patch", "se esperaba una superficie", []),
            Curve::ReductionKinds => said(
                lang,
                "degree reduction is for Bézier, rational Bézier, B-spline and NURBS curves",
                "la reducción del grado es para curvas de Bézier, de Bézier racionales, B-spline y NURBS",
                [],
            ),
            Curve::ReducedExactly { degree, points } => said(
                lang,
                "exact: the curve is of degree ‹›, the same curve with ‹› control points",
                "exacta: la curva es de grado ‹›, la misma curva con ‹› puntos de control",
                [degree.into(), points.into()],
            ),
            Curve::ReverseDirectionMissing => said(
                lang,
                "missing (give \"u\" to reverse the rows of the mesh, c̃(u, v) = c(a + b - u, v), or \"v\" to reverse each row, c̃(u, v) = c(u, c + d - v))",
                "falta (dé \"u\" para invertir el orden de las filas de la malla, c̃(u, v) = c(a + b - u, v), o \"v\" para invertir cada fila, c̃(u, v) = c(u, c + d - v))",
                [],
            ),
            Curve::ConicThreePoints { found } => said(
                lang,
                "a conic arc takes three points [c_0, c_1, c_2], found ‹›",
                "un arco de cónica lleva tres puntos [c_0, c_1, c_2], se encontraron ‹›",
                [found.into()],
            ),
            Curve::ConicZeroWeight => said(
                lang,
                "a zero weight gives the segment c_0 c_2 traced twice, not a conic arc",
                "un peso nulo da el segmento c_0 c_2 recorrido dos veces, no un arco de cónica",
                [],
            ),
            Curve::Ellipse => said(lang, "ellipse", "elipse", []),
            Curve::Parabola => said(lang, "parabola", "parábola", []),
            Curve::Hyperbola => said(lang, "hyperbola", "hipérbola", []),
            Curve::ConicUndecided => said(
                lang,
                "undecided (the shape factor is in letters)",
                "sin decidir (el factor de forma está en letras)",
                [],
            ),
            Curve::IntegralRational => said(
                lang,
                "the integral of a rational curve is the integral of a quotient of polynomials, in general no number of Q or of one Q(√d) (it has logarithms and arctangents): give a polynomial curve (`bezier` without weights, an expression, a B-spline)",
                "la integral de una curva racional es la integral de un cociente de polinomios, en general no es un número de Q ni de un Q(√d) (tiene logaritmos y arcotangentes): dé una curva polinómica (`bezier` sin pesos, una expresión, una B-spline)",
                [],
            ),
            Curve::IntegralNeedsCurveOrKnots => said(
                lang,
                "`integral` takes a `curve`, or the `knots` and the `degree` of B-spline basis functions",
                "`integral` necesita una curva (`curve`), o los nudos (`knots`) y el grado (`degree`) de unas funciones B-spline",
                [],
            ),
            Curve::AreaRational => said(
                lang,
                "the area of a rational curve or patch is the integral of a quotient of polynomials, in general no number of Q or of one Q(√d): give a polynomial curve or patch",
                "el área de una curva o una superficie racional es la integral de un cociente de polinomios, en general no es un número de Q ni de un Q(√d): dé una curva o una superficie polinómica",
                [],
            ),
            Curve::AreaNeedsCurveOrSurface => said(
                lang,
                "`area` takes a closed planar `curve` or a planar `surface`",
                "`area` necesita una curva cerrada plana (`curve`) o una superficie plana (`surface`)",
                [],
            ),
            Curve::CounterClockwise => said(
                lang,
                "counter-clockwise (the signed area is positive)",
                "en sentido antihorario (el área con signo es positiva)",
                [],
            ),
            Curve::Clockwise => said(
                lang,
                "clockwise (the signed area is negative)",
                "en sentido horario (el área con signo es negativa)",
                [],
            ),
            Curve::NoOrientation => said(
                lang,
                "none: the signed area is zero (the curve runs back over itself, or its loops cancel)",
                "ninguno: el área con signo es nula (la curva vuelve sobre sí misma, o sus lazos se cancelan)",
                [],
            ),
            Curve::OrientationUndecided => said(
                lang,
                "undecided (the signed area is in letters)",
                "sin decidir (el área con signo está en letras)",
                [],
            ),
            Curve::LoftExpression => said(
                lang,
                "a section of a lofted surface is given by its control points (`bezier` or `bspline`), not as an expression",
                "una sección de una superficie por secciones se da por sus puntos de control (`bezier` o `bspline`), no como una expresión",
                [],
            ),
            Curve::LoftRational => said(
                lang,
                "rational sections are not lofted here: interpolating the control points of the sections column by column is right for polynomial sections; with weights the homogeneous points would have to be interpolated, which this construction does not do",
                "aquí no se construyen superficies por secciones racionales: interpolar columna a columna los puntos de control de las secciones es correcto para secciones polinómicas; con pesos habría que interpolar los puntos homogéneos, y esta construcción no lo hace",
                [],
            ),
            Curve::TangentDevelopablePolynomial => said(
                lang,
                "the tangent developable takes a polynomial curve (`bezier` without weights, or an expression)",
                "la superficie tangente desarrollable se construye sobre una curva polinómica (`bezier` sin pesos, o una expresión)",
                [],
            ),
            Curve::TangentDevelopableR3 => said(
                lang,
                "the tangent developable is a surface of R³: the curve needs three coordinates",
                "la superficie tangente desarrollable es una superficie de R³: la curva necesita tres coordenadas",
                [],
            ),
            Curve::ExpectedSplineSurface => said(
                lang,
                "expected a B-spline or NURBS surface",
                "se esperaba una superficie B-spline o NURBS",
                [],
            ),
            Curve::BorderInLetters => said(
                lang,
                "a border in letters cannot be placed among the knots: give it in numbers",
                "un borde en letras no se puede situar entre los nudos: délo en números",
                [],
            ),
            Curve::DerivativeUndefinedThere => said(
                lang,
                "the derivative is not defined there (its weight vanishes)",
                "la derivada no está definida ahí (su peso se anula)",
                [],
            ),
            Curve::BorderOutside => said(
                lang,
                "the border is outside the surface's domain",
                "el borde está fuera del recinto de la superficie",
                [],
            ),
            Curve::SurfaceDerivativeNotSpline { r, s, p, q } => said(
                lang,
                "the derivative of order (‹›, ‹›) is not a B-spline surface of lower degree here (order above the degree (‹›, ‹›), degree 1, or a knot of full multiplicity): only its pieces are given",
                "la derivada de orden (‹›, ‹›) no es aquí una superficie B-spline de grado menor (orden mayor que el grado (‹›, ‹›), grado 1, o un nudo de multiplicidad máxima): solo se dan sus trozos",
                [r.into(), s.into(), p.into(), q.into()],
            ),
            Curve::KnotLinesNeedSpline => said(
                lang,
                "continuity across knot lines needs a B-spline or NURBS surface (`bspline`, `knots`); for two Bézier patches give `first` and `second`",
                "la continuidad a través de las líneas de nudos necesita una superficie B-spline o NURBS (`bspline`, `knots`); para dos superficies de Bézier dé `first` y `second`",
                [],
            ),
            Curve::ExpectedSplineCurve => said(
                lang,
                "expected a B-spline or NURBS curve",
                "se esperaba una curva B-spline o NURBS",
                [],
            ),
            Curve::ExpectedRationalOrSplineCurve => said(
                lang,
                "expected a rational, B-spline or NURBS curve",
                "se esperaba una curva racional, B-spline o NURBS",
                [],
            ),
            Curve::CurveDerivativeNotSpline { r, p } => said(
                lang,
                "the derivative of order ‹› is not a B-spline curve of lower degree here (order above the degree ‹›, degree 1, or a knot of full multiplicity): only its pieces are given",
                "la derivada de orden ‹› no es aquí una curva B-spline de grado menor (orden mayor que el grado ‹›, grado 1, o un nudo de multiplicidad máxima): solo se dan sus trozos",
                [r.into(), p.into()],
            ),
            Curve::BordersDiffer {
                along,
                first_from,
                first_to,
                second_from,
                second_to,
            } => said(
                lang,
                "the borders run over different ‹› intervals: the first's [‹›, ‹›], the second's [‹›, ‹›]; continuity compares them at the same ‹›",
                "los bordes recorren intervalos de ‹› distintos: el de la primera [‹›, ‹›], el de la segunda [‹›, ‹›]; la continuidad los compara en el mismo ‹›",
                [
                    along.into(),
                    first_from.into(),
                    first_to.into(),
                    second_from.into(),
                    second_to.into(),
                    along.into(),
                ],
            ),
            Curve::NoMatchingPieces { dir, end, start } => said(
                lang,
                "no piece of the first surface ends at ‹› = ‹› while one of the second begins at ‹› = ‹›",
                "ningún trozo de la primera superficie acaba en ‹› = ‹› mientras uno de la segunda empieza en ‹› = ‹›",
                [dir.into(), end.into(), dir.into(), start.into()],
            ),
            Curve::SecondMoved {
                dir,
                start,
                end,
                delta,
            } => said(
                lang,
                "the second surface begins at ‹› = ‹› and the first ends at ‹› = ‹›: the second was moved by ‹› along ‹› so that they are consecutive; the derivatives are in the surfaces' own parameters",
                "la segunda superficie empieza en ‹› = ‹› y la primera acaba en ‹› = ‹›: la segunda se ha trasladado ‹› en ‹› para que sean consecutivas; las derivadas son en los parámetros propios de las superficies",
                [
                    dir.into(),
                    start.into(),
                    dir.into(),
                    end.into(),
                    delta.into(),
                    dir.into(),
                ],
            ),
        }
    }
}

cagd_words::display_english!(Curve);

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_variant_in_both_languages() {
        for m in Curve::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
