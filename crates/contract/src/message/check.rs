//! Checking an answer against what the problem expects: mismatches and verdict sentences.

use super::inner::Inner;
use crate::message::found::Found;
use cagd_words::{said, Lang, Message, Phrase};

/// The kind of a surface of an answer.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, strum::EnumIter)]
pub enum SurfaceKind {
    /// A Bézier surface.
    #[default]
    Bezier,
    /// A rational Bézier surface.
    RationalBezier,
    /// A B-spline surface.
    BSpline,
    /// A NURBS surface.
    Nurbs,
    /// A parametric surface (an expression).
    Parametric,
}

impl Message for SurfaceKind {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            SurfaceKind::Bezier => said(lang, "a Bézier surface", "una superficie de Bézier", []),
            SurfaceKind::RationalBezier => said(
                lang,
                "a rational Bézier surface",
                "una superficie de Bézier racional",
                [],
            ),
            SurfaceKind::BSpline => said(lang, "a B-spline surface", "una superficie B-spline", []),
            SurfaceKind::Nurbs => said(lang, "a NURBS surface", "una superficie NURBS", []),
            SurfaceKind::Parametric => said(
                lang,
                "a parametric surface",
                "una superficie paramétrica",
                [],
            ),
        }
    }
}

/// Where an erratum found by computing is: an equation of the notes (or, when the problem
/// names none, the formula) at an entry of the result, or of a result as a whole.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum ErratumPlace {
    /// The equation at the entry (i) or (i, j).
    At {
        /// The equation, as the problem names it: `(14)`.
        equation: String,
        /// The entry's indices, `1, 0`.
        at: String,
    },
    /// The equation of a result that is one point.
    Of {
        /// The equation.
        equation: String,
        /// The result.
        result: String,
    },
    /// The formula, the problem naming no equation, at the entry (i) or (i, j).
    FormulaAt {
        /// The entry's indices.
        at: String,
    },
    /// The formula, the problem naming no equation, of a result that is one point.
    FormulaOf {
        /// The result.
        result: String,
    },
}

impl Default for ErratumPlace {
    fn default() -> Self {
        ErratumPlace::FormulaAt { at: "0".into() }
    }
}

impl Message for ErratumPlace {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            ErratumPlace::At { equation, at } => said(
                lang,
                "‹› at (‹›)",
                "‹› en (‹›)",
                [equation.into(), at.into()],
            ),
            ErratumPlace::Of { equation, result } => {
                said(lang, "‹› (‹›)", "‹› (‹›)", [equation.into(), result.into()])
            }
            ErratumPlace::FormulaAt { at } => said(
                lang,
                "the formula at (‹›)",
                "la fórmula en (‹›)",
                [at.into()],
            ),
            ErratumPlace::FormulaOf { result } => {
                said(lang, "the formula (‹›)", "la fórmula (‹›)", [result.into()])
            }
        }
    }
}

/// Checking an answer against what the problem expects: mismatches and verdict sentences.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum Check {
    // --- a value against the expected one ---
    /// Two values differ.
    Differ {
        /// The expected value, as text.
        expected: String,
        /// The computed value, as text.
        computed: String,
    },
    /// A list was computed where something else was expected.
    ComputedList {
        /// The expected value (JSON).
        expected: String,
    },
    /// An object was computed where something else was expected.
    ComputedObject {
        /// The expected value (JSON).
        expected: String,
    },
    /// Lists of different lengths.
    Items {
        /// Items expected.
        expected: usize,
        /// Items computed.
        computed: usize,
    },
    /// An item of a list differs.
    Item {
        /// Its index.
        index: usize,
        /// How.
        inner: Box<Check>,
    },
    /// A named value expected and not computed.
    NoValue {
        /// Its name.
        key: String,
    },
    /// A named value of an object differs.
    Entry {
        /// Its name.
        key: String,
        /// How.
        inner: Box<Check>,
    },
    /// An expected expression that is not a string.
    ExpressionString {
        /// What was found (JSON).
        found: String,
    },
    /// An expected expression that does not parse.
    DoesNotParse {
        /// The expression, quoted.
        text: String,
        /// Why.
        inner: Inner,
    },
    /// An expected value that cannot be read, or an error of the engine reading it.
    Unread {
        /// Why.
        inner: Inner,
    },
    /// Lists of points of different lengths.
    Points {
        /// Points expected.
        expected: usize,
        /// Points computed.
        computed: usize,
    },
    /// A point differs.
    Point {
        /// Its index.
        index: usize,
        /// Expected.
        expected: String,
        /// Computed.
        computed: String,
    },
    /// Meshes of different sizes.
    MeshSize {
        /// Rows expected.
        rows: usize,
        /// Columns expected.
        cols: usize,
        /// Rows computed.
        found_rows: usize,
        /// Columns computed.
        found_cols: usize,
    },
    /// Grids of weights of different sizes.
    WeightsSize {
        /// Rows expected.
        rows: usize,
        /// Columns expected.
        cols: usize,
        /// Rows computed.
        found_rows: usize,
        /// Columns computed.
        found_cols: usize,
    },
    /// An entry of a mesh or of a grid of weights differs.
    GridEntry {
        /// The letter (`c`, `w`).
        name: String,
        /// Row.
        i: usize,
        /// Column.
        j: usize,
        /// Expected.
        expected: String,
        /// Computed.
        computed: String,
    },
    /// Weights expected of a polynomial surface.
    WeightsOfPolynomialSurface,
    /// Weights expected of a polynomial curve.
    WeightsOfPolynomialCurve,
    /// A rational answer (a curve or a surface whose weights are not all equal) expected
    /// without its weights: the polynomial curve or surface with the same control points is
    /// another one.
    WeightsMissing {
        /// The computed weights, as text.
        computed: String,
    },
    /// Bidegrees differ.
    Bidegree {
        /// Expected.
        expected: (usize, usize),
        /// Computed.
        computed: (usize, usize),
    },
    /// Knots in u and v differ.
    KnotsUV {
        /// Expected in u.
        expected_u: String,
        /// Expected in v.
        expected_v: String,
        /// Computed in u.
        computed_u: String,
        /// Computed in v.
        computed_v: String,
    },
    /// Weights differ.
    Weights {
        /// Expected.
        expected: String,
        /// Computed.
        computed: String,
    },
    /// Degrees differ.
    Degree {
        /// Expected.
        expected: usize,
        /// Computed.
        computed: usize,
    },
    /// Knots differ.
    Knots {
        /// Expected.
        expected: String,
        /// Computed.
        computed: String,
    },
    /// Curves of different kinds.
    AnotherCurve,
    /// Surfaces of different kinds.
    SurfaceKinds {
        /// Expected.
        expected: SurfaceKind,
        /// Computed.
        computed: SurfaceKind,
    },

    // --- `expected` as a whole ---
    /// `expected` is not an object.
    NotAnObject {
        /// The operation.
        op: String,
        /// The results it gives, in backticks.
        names: String,
        /// What was found.
        found: Found,
    },
    /// `expected` is empty.
    EmptyExpected {
        /// The operation.
        op: String,
        /// The results it gives, in backticks.
        names: String,
    },
    /// `expected` holds only words, which are not compared.
    OnlyWords {
        /// The operation.
        op: String,
        /// The results it gives, in backticks.
        names: String,
    },
    /// `remarks` not a list of strings.
    RemarksShape {
        /// What was found.
        found: Found,
    },
    /// `derivation` not a list of objects.
    DerivationShape {
        /// What was found.
        found: Found,
    },
    /// A key that names no result.
    NotAResult {
        /// The key.
        key: String,
        /// The operation.
        op: String,
        /// The results it gives, in backticks.
        names: String,
    },
    /// A result differs.
    Result {
        /// Its name.
        key: String,
        /// How.
        inner: Box<Check>,
    },

    // --- steps ---
    /// `steps` is an empty object.
    EmptySteps,
    /// A step differs.
    Step {
        /// Its name.
        name: String,
        /// How.
        inner: Box<Check>,
    },
    /// An item of a list of steps that is not a step.
    StepItem {
        /// Its index.
        index: usize,
        /// What was found.
        found: Found,
    },
    /// Lists of steps of different lengths.
    StepCount {
        /// Steps expected.
        expected: usize,
        /// Steps computed.
        computed: usize,
    },
    /// A step of a list under another name.
    StepName {
        /// Its index.
        index: usize,
        /// The name expected.
        expected: String,
        /// The name computed.
        computed: String,
    },
    /// `steps` neither an object nor a list.
    StepsShape {
        /// What was found.
        found: Found,
    },
    /// A step named when the operation records none.
    NoNamedSteps {
        /// The step.
        name: String,
        /// The operation.
        op: String,
    },
    /// A step the operation does not record.
    NoSuchStep {
        /// The step.
        name: String,
        /// The operation.
        op: String,
        /// The steps it records, in backticks.
        listed: String,
    },
    /// A step the operation does not record, of many.
    NoSuchStepOfMany {
        /// The step.
        name: String,
        /// The operation.
        op: String,
        /// The first steps it records, in backticks.
        listed: String,
        /// How many more.
        more: usize,
    },

    // --- errata and formulas ---
    /// An erratum found by computing that the fixture does not record.
    Unrecorded {
        /// Where.
        place: ErratumPlace,
        /// What the printed formula gives.
        printed: String,
        /// What the engine derives.
        exact: String,
    },
    /// An erratum recorded that the formula does not give.
    NotAnErratum {
        /// Where.
        place: String,
    },
    /// `cagd check` of a problem that expects nothing.
    #[default]
    NothingToCheck,
    /// A formula of a result that is not there.
    FormulaNotAResult {
        /// The result named.
        result: String,
    },
    /// A formula of a result that is not generic points.
    FormulaNotGeneric {
        /// The result named.
        result: String,
    },
    /// Formulas and coordinates that do not agree in number.
    FormulaCount {
        /// Formulas.
        formulas: usize,
        /// Coordinates.
        coordinates: usize,
    },
    /// A formula with a subscript not closed.
    UnclosedSubscript {
        /// The formula, quoted.
        printed: String,
    },
    /// A subscript that is not an integer.
    IndexNotInteger {
        /// The index, quoted.
        index: String,
        /// The formula, quoted.
        printed: String,
    },
    /// A formula that does not read.
    FormulaUnread {
        /// The formula at the entry, quoted.
        text: String,
        /// Why.
        inner: Inner,
    },
}

impl Message for Check {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Check::Differ { expected, computed } => said(
                lang,
                "expected ‹›, computed ‹›",
                "se esperaba ‹›, se obtiene ‹›",
                [expected.into(), computed.into()],
            ),
            Check::ComputedList { expected } => said(
                lang,
                "expected ‹›, computed a list",
                "se esperaba ‹›, se obtiene una lista",
                [expected.into()],
            ),
            Check::ComputedObject { expected } => said(
                lang,
                "expected ‹›, computed an object",
                "se esperaba ‹›, se obtiene un objeto",
                [expected.into()],
            ),
            Check::Items { expected, computed } => said(
                lang,
                "expected ‹› items, computed ‹›",
                "se esperaban ‹› elementos, se obtienen ‹›",
                [expected.into(), computed.into()],
            ),
            Check::Item { index, inner } => said(
                lang,
                "item ‹›: «»",
                "elemento ‹›: «»",
                [index.into(), inner.phrase(lang).into()],
            ),
            Check::NoValue { key } => said(
                lang,
                "‹›: expected a value, none computed",
                "‹›: se esperaba un valor, no se obtiene ninguno",
                [key.into()],
            ),
            Check::Entry { key, inner } => said(
                lang,
                "‹›: «»",
                "‹›: «»",
                [key.into(), inner.phrase(lang).into()],
            ),
            Check::ExpressionString { found } => said(
                lang,
                "expected an expression string, found ‹›",
                "se esperaba una expresión (una cadena), se encontró ‹›",
                [found.into()],
            ),
            Check::DoesNotParse { text, inner } => said(
                lang,
                "the expected expression ‹› does not parse: «»",
                "la expresión esperada ‹› no se puede leer: «»",
                [text.into(), inner.phrase(lang).into()],
            ),
            Check::Unread { inner } => said(lang, "«»", "«»", [inner.phrase(lang).into()]),
            Check::Points { expected, computed } => said(
                lang,
                "expected ‹› points, computed ‹›",
                "se esperaban ‹› puntos, se obtienen ‹›",
                [expected.into(), computed.into()],
            ),
            Check::Point {
                index,
                expected,
                computed,
            } => said(
                lang,
                "point ‹›: expected ‹›, computed ‹›",
                "punto ‹›: se esperaba ‹›, se obtiene ‹›",
                [index.into(), expected.into(), computed.into()],
            ),
            Check::MeshSize {
                rows,
                cols,
                found_rows,
                found_cols,
            } => said(
                lang,
                "expected a ‹›x‹› mesh, computed ‹›x‹›",
                "se esperaba una malla de control de ‹›x‹›, se obtiene una de ‹›x‹›",
                [rows.into(), cols.into(), found_rows.into(), found_cols.into()],
            ),
            Check::WeightsSize {
                rows,
                cols,
                found_rows,
                found_cols,
            } => said(
                lang,
                "expected a ‹›x‹› grid of weights, computed ‹›x‹›",
                "se esperaba una matriz de pesos de ‹›x‹›, se obtiene una de ‹›x‹›",
                [rows.into(), cols.into(), found_rows.into(), found_cols.into()],
            ),
            Check::GridEntry {
                name,
                i,
                j,
                expected,
                computed,
            } => said(
                lang,
                "‹›_‹›,‹›: expected ‹›, computed ‹›",
                "‹›_‹›,‹›: se esperaba ‹›, se obtiene ‹›",
                [
                    name.into(),
                    i.into(),
                    j.into(),
                    expected.into(),
                    computed.into(),
                ],
            ),
            Check::WeightsOfPolynomialSurface => said(
                lang,
                "expected weights, computed a polynomial surface",
                "se esperaban pesos, se obtiene una superficie polinómica",
                [],
            ),
            Check::WeightsOfPolynomialCurve => said(
                lang,
                "expected weights, computed a polynomial curve",
                "se esperaban pesos, se obtiene una curva polinómica",
                [],
            ),
            Check::WeightsMissing { computed } => said(
                lang,
                "the answer is rational: its weights ‹› are missing",
                "la respuesta es racional: faltan sus pesos ‹›",
                [computed.into()],
            ),
            Check::Bidegree { expected, computed } => said(
                lang,
                "expected bidegree ‹›, computed ‹›",
                "se esperaba bigrado ‹›, se obtiene ‹›",
                [
                    (&format!("{expected:?}")).into(),
                    (&format!("{computed:?}")).into(),
                ],
            ),
            Check::KnotsUV {
                expected_u,
                expected_v,
                computed_u,
                computed_v,
            } => said(
                lang,
                "expected knots ‹› and ‹›, computed ‹› and ‹›",
                "se esperaban los nudos ‹› y ‹›, se obtienen ‹› y ‹›",
                [
                    expected_u.into(),
                    expected_v.into(),
                    computed_u.into(),
                    computed_v.into(),
                ],
            ),
            Check::Weights { expected, computed } => said(
                lang,
                "expected weights ‹›, computed ‹›",
                "se esperaban los pesos ‹›, se obtienen ‹›",
                [expected.into(), computed.into()],
            ),
            Check::Degree { expected, computed } => said(
                lang,
                "expected degree ‹›, computed ‹›",
                "se esperaba grado ‹›, se obtiene ‹›",
                [expected.into(), computed.into()],
            ),
            Check::Knots { expected, computed } => said(
                lang,
                "expected knots ‹›, computed ‹›",
                "se esperaban los nudos ‹›, se obtienen ‹›",
                [expected.into(), computed.into()],
            ),
            Check::AnotherCurve => said(
                lang,
                "expected another kind of curve",
                "se esperaba otra clase de curva",
                [],
            ),
            Check::SurfaceKinds { expected, computed } => said(
                lang,
                "expected «», computed «»",
                "se esperaba «», se obtiene «»",
                [expected.phrase(lang).into(), computed.phrase(lang).into()],
            ),
            Check::NotAnObject { op, names, found } => said(
                lang,
                "expected: an object of results by name (`‹›` gives ‹›), found «»",
                "`expected`: un objeto de resultados por nombre (`‹›` da ‹›), se encontró «»",
                [op.into(), names.into(), found.phrase(lang).into()],
            ),
            Check::EmptyExpected { op, names } => said(
                lang,
                "expected: an empty object checks nothing; name the results to check (`‹›` gives ‹›)",
                "`expected`: un objeto vacío no comprueba nada; nombre los resultados que comprobar (`‹›` da ‹›)",
                [op.into(), names.into()],
            ),
            Check::OnlyWords { op, names } => said(
                lang,
                "`expected`: `remarks` and `derivation` are not compared, so this checks nothing; name the results to check (`‹›` gives ‹›)",
                "`expected`: `remarks` y `derivation` no se comparan, así que no comprueba nada; nombre los resultados que comprobar (`‹›` da ‹›)",
                [op.into(), names.into()],
            ),
            Check::RemarksShape { found } => said(
                lang,
                "`remarks`: a list of strings (the answer's remarks, not compared), found «»",
                "`remarks`: una lista de cadenas (las observaciones de la respuesta, que no se comparan), se encontró «»",
                [found.phrase(lang).into()],
            ),
            Check::DerivationShape { found } => said(
                lang,
                "`derivation`: a list of objects (the answer's worked solution, not compared), found «»",
                "`derivation`: una lista de objetos (la resolución de la respuesta, que no se compara), se encontró «»",
                [found.phrase(lang).into()],
            ),
            Check::NotAResult { key, op, names } => said(
                lang,
                "`‹›`: not a result of this problem (`‹›` gives ‹›)",
                "`‹›`: no es un resultado de este problema (`‹›` da ‹›)",
                [key.into(), op.into(), names.into()],
            ),
            Check::Result { key, inner } => said(
                lang,
                "`‹›`: «»",
                "`‹›`: «»",
                [key.into(), inner.phrase(lang).into()],
            ),
            Check::EmptySteps => said(
                lang,
                "`steps`: an empty object checks no step; name the steps to check",
                "`steps`: un objeto vacío no comprueba ningún paso; nombre los pasos que comprobar",
                [],
            ),
            Check::Step { name, inner } => said(
                lang,
                "step `‹›`: «»",
                "paso `‹›`: «»",
                [name.into(), inner.phrase(lang).into()],
            ),
            Check::StepItem { index, found } => said(
                lang,
                "`steps[‹›]`: a step {\"name\": ..., \"value\": ...}, found «»",
                "`steps[‹›]`: un paso {\"name\": ..., \"value\": ...}, se encontró «»",
                [index.into(), found.phrase(lang).into()],
            ),
            Check::StepCount { expected, computed } => said(
                lang,
                "`steps`: ‹› steps expected, ‹› computed (a list of steps is compared whole; an object of steps by name checks some)",
                "`steps`: se esperan ‹› pasos, se obtienen ‹› (una lista de pasos se compara entera; un objeto de pasos por nombre comprueba algunos)",
                [expected.into(), computed.into()],
            ),
            Check::StepName {
                index,
                expected,
                computed,
            } => said(
                lang,
                "`steps[‹›]`: expected the step `‹›`, computed `‹›`",
                "`steps[‹›]`: se esperaba el paso `‹›`, se obtiene `‹›`",
                [index.into(), expected.into(), computed.into()],
            ),
            Check::StepsShape { found } => said(
                lang,
                "`steps`: the steps by name (an object) or the list an answer writes, found «»",
                "`steps`: los pasos por nombre (un objeto) o la lista que escribe una respuesta, se encontró «»",
                [found.phrase(lang).into()],
            ),
            Check::NoNamedSteps { name, op } => said(
                lang,
                "step `‹›`: `‹›` records no named steps to check",
                "paso `‹›`: `‹›` no registra pasos con nombre que comprobar",
                [name.into(), op.into()],
            ),
            Check::NoSuchStep { name, op, listed } => said(
                lang,
                "step `‹›`: `‹›` records no step named `‹›` (its steps: ‹›)",
                "paso `‹›`: `‹›` no registra ningún paso llamado `‹›` (sus pasos: ‹›)",
                [name.into(), op.into(), name.into(), listed.into()],
            ),
            Check::NoSuchStepOfMany {
                name,
                op,
                listed,
                more,
            } => said(
                lang,
                "step `‹›`: `‹›` records no step named `‹›` (its steps: ‹› and ‹› more)",
                "paso `‹›`: `‹›` no registra ningún paso llamado `‹›` (sus pasos: ‹› y ‹› más)",
                [name.into(), op.into(), name.into(), listed.into(), more.into()],
            ),
            Check::Unrecorded {
                place,
                printed,
                exact,
            } => said(
                lang,
                "«»: the notes' formula gives ‹›, the engine derives ‹› (an erratum found by computing that the fixture does not record)",
                "«»: la fórmula de los apuntes da ‹›, y el cálculo da ‹› (una errata hallada al calcular que el ejemplo no registra)",
                [place.phrase(lang).into(), printed.into(), exact.into()],
            ),
            Check::NotAnErratum { place } => said(
                lang,
                "‹›: recorded as an erratum, but the formula as printed gives the derived value",
                "‹›: registrada como errata, pero la fórmula tal como se imprime da el valor calculado",
                [place.into()],
            ),
            Check::NothingToCheck => said(
                lang,
                "nothing to check: the problem has no \"expected\" answer (and no \"formula\")",
                "nada que comprobar: el problema no tiene respuesta esperada (\"expected\") ni fórmula (\"formula\")",
                [],
            ),
            Check::FormulaNotAResult { result } => said(
                lang,
                "formula: `‹›` is not a result or a step of this problem",
                "fórmula: `‹›` no es un resultado ni un paso de este problema",
                [result.into()],
            ),
            Check::FormulaNotGeneric { result } => said(
                lang,
                "formula: `‹›` is not a polygon or mesh of generic points",
                "fórmula: `‹›` no es un polígono ni una malla de puntos genéricos",
                [result.into()],
            ),
            Check::FormulaCount {
                formulas,
                coordinates,
            } => said(
                lang,
                "formula: ‹› formulas for points of ‹› coordinates",
                "fórmula: ‹› fórmulas para puntos de ‹› coordenadas",
                [formulas.into(), coordinates.into()],
            ),
            Check::UnclosedSubscript { printed } => said(
                lang,
                "an unclosed subscript in ‹›",
                "un subíndice sin cerrar en ‹›",
                [printed.into()],
            ),
            Check::IndexNotInteger { index, printed } => said(
                lang,
                "the index ‹› of ‹› is not an integer",
                "el índice ‹› de ‹› no es un entero",
                [index.into(), printed.into()],
            ),
            Check::FormulaUnread { text, inner } => said(
                lang,
                "formula: ‹›: «»",
                "fórmula: ‹›: «»",
                [text.into(), inner.phrase(lang).into()],
            ),
        }
    }
}

cagd_words::display_english!(Check, SurfaceKind, ErratumPlace);

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_variant_in_both_languages() {
        for m in Check::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()));
        }
        for m in SurfaceKind::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()));
        }
        for m in ErratumPlace::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
