//! Reading the leaves of a problem: its numbers, points, shapes (curves, surfaces, triangles) and their limits.

use crate::limit::Limit;
use crate::message::found::Found;
use crate::message::inner::Inner;
use cagd_scalar::Exceeded;
use cagd_words::{said, Lang, Message, Phrase};

/// What a reader expected, in words (`expected «», found «»`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, strum::EnumIter)]
pub enum Wanted {
    /// A list.
    #[default]
    List,
    /// A number.
    Number,
    /// A non-negative integer.
    NonNegative,
    /// An integer r or a list [r, s].
    IntegerOrPair,
    /// A point [x, y, z].
    Point,
    /// A string.
    Str,
}

impl Message for Wanted {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Wanted::List => said(lang, "a list", "una lista", []),
            Wanted::Number => said(lang, "a number", "un número", []),
            Wanted::NonNegative => {
                said(lang, "a non-negative integer", "un entero no negativo", [])
            }
            Wanted::IntegerOrPair => said(
                lang,
                "an integer r or a list [r, s]",
                "un entero r o una lista [r, s]",
                [],
            ),
            Wanted::Point => said(lang, "a point [x, y, z]", "un punto [x, y, z]", []),
            Wanted::Str => said(lang, "a string", "una cadena", []),
        }
    }
}

cagd_words::display_english!(Wanted, Read);

/// Reading the leaves of a problem: its numbers, points, shapes (curves, surfaces, triangles) and their limits.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum Read {
    /// The reading stopped at the first number of the root it was asked to locate (the
    /// locating pass of a root conflict; never shown).
    Located,
    /// A value of another kind than the one expected.
    Expected {
        /// What was expected.
        wanted: Wanted,
        /// What was found.
        found: Found,
    },
    /// A pair `[a, b]` of another length.
    TwoNumbers {
        /// The numbers found.
        found: usize,
    },
    /// A pair of integers `[r, s]` of another length.
    TwoIntegers {
        /// The length of the list found.
        found: usize,
    },
    /// The knots of a surface are not two lists.
    TwoKnotVectors {
        /// The length of the list found.
        found: usize,
    },
    /// A text (a number, an expression) that does not read, and why.
    Quoted {
        /// The text, quoted.
        text: String,
        /// Why it does not read.
        error: Inner,
    },
    /// A number written with a decimal comma (`"1,5"`).
    DecimalComma {
        /// The text, quoted.
        text: Box<str>,
        /// Its value, exact (`3/2`).
        exact: Box<str>,
        /// It with a decimal point (`1.5`).
        decimal: Box<str>,
    },
    /// A square root written as a word the grammar does not know (`"raiz2"`).
    RootWord {
        /// The text, quoted.
        text: String,
        /// The text with the root written `sqrt`, quoted.
        fixed: String,
    },
    /// A JSON number with a fraction part.
    FractionPart {
        /// The number, as written.
        number: String,
    },
    /// A JSON integer longer than the digit limit.
    JsonDigits {
        /// The number, as written.
        number: String,
        /// Its digits.
        digits: usize,
        /// The limit.
        max: usize,
    },
    /// A JSON integer of more digits than a machine word counts.
    JsonDigitsMany {
        /// The number, as written.
        number: String,
        /// The limit.
        max: usize,
    },
    /// A number longer than the digit limit, as the grammar counts it (its digits, or, far
    /// past the limit, not counted): cagd-scalar's [`Exceeded`], carried as it is.
    Digits {
        /// The limit exceeded, and by what.
        what: Exceeded,
    },
    /// A decimal that looks like a truncated repeating fraction (a remark).
    Repeating {
        /// The decimal as written.
        text: Box<str>,
        /// Its exact value.
        exact: Box<str>,
        /// The fraction it may stand for.
        meant: Box<str>,
    },
    /// A number needs another square root than the operation.
    RootAgainstOperation {
        /// The radicand this number needs.
        needs: u64,
        /// The radicand of the operation.
        first: u64,
    },
    /// A number needs another square root than an earlier number (not located).
    RootAgainstEarlier {
        /// The radicand this number needs.
        needs: u64,
        /// The radicand of the earlier number.
        first: u64,
    },
    /// A number needs another square root than the number at a path.
    RootAgainstAt {
        /// The radicand this number needs.
        needs: u64,
        /// The path of the first number with a root.
        at: String,
        /// Its radicand.
        first: u64,
    },
    /// A degree past the degree limit.
    DegreeAbove {
        /// The degree.
        degree: u64,
        /// The limit.
        max: usize,
    },
    /// A list past the points limit.
    ListLonger {
        /// Its items.
        items: usize,
        /// The limit.
        max: usize,
    },
    /// An expression of a degree past the limit.
    ExprDegree {
        /// The expression, quoted.
        text: String,
        /// Its degree.
        degree: usize,
        /// The limit.
        max: usize,
    },
    /// A scalar expression where a tuple is expected.
    NotTuple {
        /// The expression, quoted.
        text: String,
        /// The polynomial it reads as.
        poly: String,
    },
    /// A tuple where a scalar expression is expected.
    NotScalar {
        /// The expression, quoted.
        text: String,
    },
    /// A point `[]`.
    PointEmpty,
    /// A point of another dimension than the first of its list.
    PointDim {
        /// Its coordinates.
        found: usize,
        /// The first point's.
        first: usize,
    },
    /// An empty list of points.
    NoPoint,
    /// A row of a mesh of another length than row 0.
    RowLength {
        /// The row.
        row: usize,
        /// Its points.
        found: usize,
        /// Row 0's.
        first: usize,
    },
    /// A row of points of another dimension than row 0.
    RowDim {
        /// Its dimension.
        found: usize,
        /// Row 0's.
        first: usize,
    },
    /// A mesh past the points limit.
    MeshLarger {
        /// Its points.
        points: usize,
        /// The limit.
        max: usize,
    },
    /// An empty mesh.
    MeshEmpty,
    /// Weights not one per control point.
    WeightsCount {
        /// The weights.
        weights: usize,
        /// The control points.
        points: usize,
    },
    /// A Bézier curve past the degree limit.
    CurveDegree {
        /// Its control points.
        points: usize,
        /// Its degree.
        degree: usize,
        /// The limit.
        max: usize,
    },
    /// A Bézier patch past the degree limit in u.
    PatchDegreeU {
        /// Its rows of control points.
        points: usize,
        /// Its degree in u.
        degree: usize,
        /// The limit.
        max: usize,
    },
    /// A Bézier patch past the degree limit in v.
    PatchDegreeV {
        /// Its columns of control points.
        points: usize,
        /// Its degree in v.
        degree: usize,
        /// The limit.
        max: usize,
    },
    /// An object that is no curve.
    NotCurve,
    /// An object that is no surface.
    NotSurface,
    /// Points read from a problem's text that its shape does not use (never shown: the
    /// problem is read again as a value).
    UnusedPoints,
    /// `"homogeneous": true` beside `"weights"`: the weights are the points' last coordinates.
    HomogeneousWithWeights,
    /// `"homogeneous"` on a shape without written control points (`generic`, `expr`).
    HomogeneousWithoutPoints,
    /// A homogeneous point of fewer than two coordinates.
    HomogeneousPoint {
        /// Its coordinates.
        found: usize,
    },
    /// The letter of a generic shape is no letter.
    GenericLetter {
        /// What was written, quoted.
        found: String,
    },
    /// A generic shape past its degree.
    GenericDegree {
        /// The largest degree.
        max: usize,
        /// The degree written.
        found: usize,
    },
    /// A generic shape of a dimension it cannot have.
    GenericDim {
        /// What was written.
        found: String,
    },
    /// A triangular patch past the degree limit.
    TriangleDegree {
        /// Its rows.
        rows: usize,
        /// Its degree.
        degree: usize,
        /// The limit.
        max: usize,
    },
    /// A triangular net past the points limit.
    TriangleLarger {
        /// Its points.
        points: usize,
        /// The limit.
        max: usize,
    },
    /// A row of a triangular net of the wrong length.
    TriangleRow {
        /// The row m.
        row: usize,
        /// The points it holds, m + 1.
        holds: usize,
        /// The points found.
        found: usize,
    },
    /// Rows of weights not as many as the net's.
    TriangleWeightRows {
        /// Rows of weights.
        found: usize,
        /// Rows of the net.
        rows: usize,
    },
    /// A row of weights of the wrong length.
    TriangleWeightRow {
        /// The row m.
        row: usize,
        /// The numbers it holds, m + 1.
        holds: usize,
        /// The numbers found.
        found: usize,
    },
    /// A zero weight of a rational triangular patch.
    TriangleWeightZero {
        /// Index i of w_{i,j,k}.
        i: usize,
        /// Index j.
        j: usize,
        /// Index k.
        k: usize,
    },
    /// An error at a path of a value (an expected value).
    At {
        /// The path.
        at: String,
        /// The error.
        inner: Inner,
    },
}

impl Read {
    /// The limit a refusal is about (`None` for an error of the input itself).
    pub fn limit(&self) -> Option<Limit> {
        match self {
            Read::JsonDigits { .. } | Read::JsonDigitsMany { .. } => Some(Limit::Digits),
            Read::Digits { what } => Limit::of_exceeded(what),
            Read::DegreeAbove { .. }
            | Read::ExprDegree { .. }
            | Read::CurveDegree { .. }
            | Read::PatchDegreeU { .. }
            | Read::PatchDegreeV { .. }
            | Read::TriangleDegree { .. } => Some(Limit::Degree),
            Read::ListLonger { .. } | Read::MeshLarger { .. } | Read::TriangleLarger { .. } => {
                Some(Limit::Points)
            }
            Read::Quoted { error, .. } | Read::At { inner: error, .. } => error.limit(),
            _ => None,
        }
    }
}

impl Message for Read {
    #[allow(clippy::too_many_lines)]
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Read::Located => said(
                lang,
                "the first number of the root looked for",
                "el primer número de la raíz buscada",
                [],
            ),
            Read::Expected { wanted, found } => said(
                lang,
                "expected «», found «»",
                "se esperaba «», se encontró «»",
                [wanted.phrase(lang).into(), found.phrase(lang).into()],
            ),
            Read::TwoNumbers { found } => said(
                lang,
                "expected two numbers [a, b], found ‹›",
                "se esperaban dos números [a, b], se encontró ‹›",
                [found.into()],
            ),
            Read::TwoIntegers { found } => said(
                lang,
                "expected two integers [r, s], found a list of ‹›",
                "se esperaban dos enteros [r, s], se encontró una lista de ‹›",
                [found.into()],
            ),
            Read::TwoKnotVectors { found } => said(
                lang,
                "expected two knot vectors [[u knots], [v knots]], found a list of ‹›",
                "se esperaban dos sucesiones de nudos [[nudos en u], [nudos en v]], se encontró una lista de ‹›",
                [found.into()],
            ),
            Read::Quoted { text, error } => {
                said(lang, "‹›: «»", "‹›: «»", [text.into(), error.phrase(lang).into()])
            }
            Read::DecimalComma {
                text,
                exact,
                decimal,
            } => said(
                lang,
                "‹›: the decimal mark is a point: write ‹› or ‹›",
                "‹›: la marca decimal es el punto: escriba ‹› o ‹›",
                [text.into(), exact.into(), decimal.into()],
            ),
            Read::RootWord { text, fixed } => said(
                lang,
                "‹›: a square root is written √2 or sqrt(2): write ‹›",
                "‹›: una raíz cuadrada se escribe √2 o sqrt(2): escriba ‹›",
                [text.into(), fixed.into()],
            ),
            Read::FractionPart { number } => said(
                lang,
                "the number ‹› has a fraction part; write it as a string (\"‹›\") so it is read exactly",
                "el número ‹› tiene parte decimal; escríbalo como cadena (\"‹›\") para leerlo exactamente",
                [number.into(), number.into()],
            ),
            Read::JsonDigits {
                number,
                digits,
                max,
            } => said(
                lang,
                "the number ‹› has ‹› digits, more than the limit of ‹› digits",
                "el número ‹› tiene ‹› cifras, más que el límite de ‹› cifras",
                [number.into(), digits.into(), max.into()],
            ),
            Read::JsonDigitsMany { number, max } => said(
                lang,
                "the number ‹› has too many digits, more than the limit of ‹› digits",
                "el número ‹› tiene demasiadas cifras, más que el límite de ‹› cifras",
                [number.into(), max.into()],
            ),
            Read::Digits { what } => what.phrase(lang),
            Read::Repeating { text, exact, meant } => said(
                lang,
                "\"‹›\" is read exactly as ‹›; if ‹› is meant, write \"‹›\"",
                "\"‹›\" se lee exactamente como ‹›; si se quiere decir ‹›, escriba \"‹›\"",
                [text.into(), exact.into(), meant.into(), meant.into()],
            ),
            Read::RootAgainstOperation { needs, first } => said(
                lang,
                "this number needs $√‹›$, but the operation needs $√‹›$: a problem runs in one field $a + b√d$",
                "este número necesita $√‹›$, pero la operación necesita $√‹›$: un problema se resuelve en un solo cuerpo $a + b√d$",
                [needs.into(), first.into()],
            ),
            Read::RootAgainstEarlier { needs, first } => said(
                lang,
                "this number needs $√‹›$, but an earlier number needs $√‹›$: a problem runs in one field $a + b√d$",
                "este número necesita $√‹›$, pero un número anterior necesita $√‹›$: un problema se resuelve en un solo cuerpo $a + b√d$",
                [needs.into(), first.into()],
            ),
            Read::RootAgainstAt { needs, at, first } => said(
                lang,
                "this number needs $√‹›$, but ‹› needs $√‹›$: a problem runs in one field $a + b√d$",
                "este número necesita $√‹›$, pero ‹› necesita $√‹›$: un problema se resuelve en un solo cuerpo $a + b√d$",
                [needs.into(), at.into(), first.into()],
            ),
            Read::DegreeAbove { degree, max } => said(
                lang,
                "‹› is above the limit of ‹› for degrees",
                "‹› supera el límite de ‹› para los grados",
                [degree.into(), max.into()],
            ),
            Read::ListLonger { items, max } => said(
                lang,
                "a list of ‹› items is longer than the limit of ‹›",
                "una lista de ‹› elementos supera el límite de ‹›",
                [items.into(), max.into()],
            ),
            Read::ExprDegree { text, degree, max } => said(
                lang,
                "‹›: degree ‹› is above the limit of ‹›",
                "‹›: el grado ‹› supera el límite de ‹›",
                [text.into(), degree.into(), max.into()],
            ),
            Read::NotTuple { text, poly } => said(
                lang,
                "‹›: expected a tuple of polynomials, found the scalar polynomial ‹›",
                "‹›: se esperaba una tupla de polinomios, se encontró el polinomio escalar ‹›",
                [text.into(), poly.into()],
            ),
            Read::NotScalar { text } => said(
                lang,
                "‹›: expected a scalar polynomial, found a tuple",
                "‹›: se esperaba un polinomio escalar, se encontró una tupla",
                [text.into()],
            ),
            Read::PointEmpty => said(
                lang,
                "a point needs at least one coordinate",
                "un punto necesita al menos una coordenada",
                [],
            ),
            Read::PointDim { found, first } => said(
                lang,
                "this point has ‹› coordinates but the first has ‹›",
                "este punto tiene ‹› coordenadas, pero el primero tiene ‹›",
                [found.into(), first.into()],
            ),
            Read::NoPoint => said(
                lang,
                "expected at least one point",
                "se esperaba al menos un punto",
                [],
            ),
            Read::RowLength { row, found, first } => said(
                lang,
                "row ‹› has ‹› points but row 0 has ‹›: a mesh needs rows of equal length",
                "la fila ‹› tiene ‹› puntos, pero la fila 0 tiene ‹›: las filas de una malla de control han de tener la misma longitud",
                [row.into(), found.into(), first.into()],
            ),
            Read::RowDim { found, first } => said(
                lang,
                "points of dimension ‹› here, but row 0 has dimension ‹›",
                "aquí hay puntos de dimensión ‹›, pero la fila 0 tiene dimensión ‹›",
                [found.into(), first.into()],
            ),
            Read::MeshLarger { points, max } => said(
                lang,
                "a mesh of ‹› points is larger than the limit of ‹›",
                "una malla de control de ‹› puntos supera el límite de ‹›",
                [points.into(), max.into()],
            ),
            Read::MeshEmpty => said(
                lang,
                "expected a mesh: a non-empty list of rows of points",
                "se esperaba una malla de control: una lista no vacía de filas de puntos",
                [],
            ),
            Read::WeightsCount { weights, points } => said(
                lang,
                "‹› weights for ‹› control points",
                "‹› pesos para ‹› puntos de control",
                [weights.into(), points.into()],
            ),
            Read::CurveDegree { points, degree, max } => said(
                lang,
                "‹› control points make a Bézier curve of degree ‹›, above the limit of ‹› for degrees",
                "‹› puntos de control dan una curva de Bézier de grado ‹›, por encima del límite de ‹› para los grados",
                [points.into(), degree.into(), max.into()],
            ),
            Read::PatchDegreeU { points, degree, max } => said(
                lang,
                "‹› control points make a Bézier patch (in u) of degree ‹›, above the limit of ‹› for degrees",
                "‹› puntos de control dan una superficie de Bézier (en u) de grado ‹›, por encima del límite de ‹› para los grados",
                [points.into(), degree.into(), max.into()],
            ),
            Read::PatchDegreeV { points, degree, max } => said(
                lang,
                "‹› control points make a Bézier patch (in v) of degree ‹›, above the limit of ‹› for degrees",
                "‹› puntos de control dan una superficie de Bézier (en v) de grado ‹›, por encima del límite de ‹› para los grados",
                [points.into(), degree.into(), max.into()],
            ),
            Read::NotCurve => said(
                lang,
                "expected a curve: {\"bezier\": [...]}, {\"bspline\": [...], \"degree\": p, \"knots\": [...]} or {\"expr\": \"(u, 0, u^2)\"}",
                "se esperaba una curva: {\"bezier\": [...]}, {\"bspline\": [...], \"degree\": p, \"knots\": [...]} o {\"expr\": \"(u, 0, u^2)\"}",
                [],
            ),
            Read::NotSurface => said(
                lang,
                "expected a surface: {\"bezier\": [[...]]}, {\"bspline\": [[...]], \"degree\": [p, q], \"knots\": [[...], [...]]} or {\"expr\": \"(u, v, u v)\"}",
                "se esperaba una superficie: {\"bezier\": [[...]]}, {\"bspline\": [[...]], \"degree\": [p, q], \"knots\": [[...], [...]]} o {\"expr\": \"(u, v, u v)\"}",
                [],
            ),
            Read::UnusedPoints => said(
                lang,
                "points read that the shape does not use",
                "puntos leídos que la forma no usa",
                [],
            ),
            Read::HomogeneousWithWeights => said(
                lang,
                "with ‹› the weights are the last coordinates of the points: give them there or in \"weights\", not both",
                "con ‹› los pesos son las últimas coordenadas de los puntos: dalos allí o en \"weights\", no en los dos sitios",
                ["\"homogeneous\": true".into()],
            ),
            Read::HomogeneousWithoutPoints => said(
                lang,
                "\"homogeneous\" is for control points written in \"bezier\" or \"bspline\"",
                "\"homogeneous\" es para puntos de control escritos en \"bezier\" o \"bspline\"",
                [],
            ),
            Read::HomogeneousPoint { found } => said(
                lang,
                "a homogeneous point (w x, ..., w) needs at least two coordinates, the weight last; found ‹›",
                "un punto homogéneo (w x, ..., w) necesita al menos dos coordenadas, el peso al final; hay ‹›",
                [found.into()],
            ),
            Read::GenericLetter { found } => said(
                lang,
                "expected one letter (such as \"c\"), found ‹›",
                "se esperaba una letra (como \"c\"), se encontró ‹›",
                [found.into()],
            ),
            Read::GenericDegree { max, found } => said(
                lang,
                "a generic polygon or mesh has degree at most ‹›, found ‹›",
                "un polígono o una malla genéricos tienen grado a lo sumo ‹›, se encontró ‹›",
                [max.into(), found.into()],
            ),
            Read::GenericDim { found } => said(
                lang,
                "a generic polygon or mesh has dimension 1, 2, 3 or \"xz\", found ‹›",
                "un polígono o una malla genéricos tienen dimensión 1, 2, 3 o \"xz\", se encontró ‹›",
                [found.into()],
            ),
            Read::TriangleDegree { rows, degree, max } => said(
                lang,
                "‹› rows make a triangular patch of degree ‹›, above the limit of ‹› for degrees",
                "‹› filas dan una superficie triangular de grado ‹›, por encima del límite de ‹› para los grados",
                [rows.into(), degree.into(), max.into()],
            ),
            Read::TriangleLarger { points, max } => said(
                lang,
                "a triangular net of ‹› points is larger than the limit of ‹›",
                "una red triangular de ‹› puntos supera el límite de ‹›",
                [points.into(), max.into()],
            ),
            Read::TriangleRow { row, holds, found } => said(
                lang,
                "row ‹› of a triangular net holds ‹› points (b_{n-‹›,‹›-k,k}, k = 0, ..., ‹›), found ‹›",
                "la fila ‹› de una red triangular tiene ‹› puntos (b_{n-‹›,‹›-k,k}, k = 0, ..., ‹›), hay ‹›",
                [
                    row.into(),
                    holds.into(),
                    row.into(),
                    row.into(),
                    row.into(),
                    found.into(),
                ],
            ),
            Read::TriangleWeightRows { found, rows } => said(
                lang,
                "‹› rows of weights for a net of ‹› rows (one weight per control point, in the same rows)",
                "‹› filas de pesos para una red de ‹› filas (un peso por punto de control, en las mismas filas)",
                [found.into(), rows.into()],
            ),
            Read::TriangleWeightRow { row, holds, found } => said(
                lang,
                "row ‹› of the weights holds ‹› numbers (one per point of row ‹› of the net), found ‹›",
                "la fila ‹› de los pesos tiene ‹› números (uno por punto de la fila ‹› de la red), hay ‹›",
                [row.into(), holds.into(), row.into(), found.into()],
            ),
            Read::TriangleWeightZero { i, j, k } => said(
                lang,
                "the weight w_{‹›,‹›,‹›} is zero: weights must be nonzero",
                "el peso w_{‹›,‹›,‹›} es nulo: los pesos han de ser no nulos",
                [i.into(), j.into(), k.into()],
            ),
            Read::At { at, inner } => said(
                lang,
                "at ‹›: «»",
                "en ‹›: «»",
                [at.into(), inner.phrase(lang).into()],
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    /// A reading error stays small: a problem's error is carried in every `Result` of the
    /// operations.
    #[test]
    fn a_reading_error_is_small() {
        assert!(
            std::mem::size_of::<Read>() <= 56,
            "{}",
            std::mem::size_of::<Read>()
        );
    }

    #[test]
    fn every_variant_in_both_languages() {
        for m in Read::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        for m in Wanted::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
