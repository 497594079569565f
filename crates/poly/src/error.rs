//! The one error type of cagd-poly.

use cagd_scalar::{Exceeded, ScalarError};
use cagd_words::{said, Lang, Message, Phrase};

/// What can go wrong with polynomials: reading an expression, evaluating, changing basis.
///
/// Each variant is worded in English and in the notes' Spanish ([`Message`]); `Display` writes
/// the English.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
#[non_exhaustive]
pub enum PolyError {
    /// An error of the number grammar (with its column), a division by zero, a negative square
    /// root, two different roots... as reported by `cagd-scalar`.
    Scalar(ScalarError),
    /// A name that is not a variable (nor a product of one-letter variables such as `uv`).
    UnknownVariable {
        /// The name as written.
        name: String,
        /// 1-based column, when it comes from parsing.
        column: Option<usize>,
    },
    /// An operation of the expression language that is not defined on these operands, such as
    /// a tuple times a tuple or a scalar plus a tuple.
    Operation {
        /// 1-based column of the operator.
        column: usize,
        /// What is wrong.
        message: Misuse,
    },
    /// A division by a non-constant polynomial (only constants can divide a polynomial).
    DivisionByPolynomial {
        /// 1-based column of the `/`.
        column: usize,
        /// The divisor, as text.
        divisor: String,
    },
    /// A square root that is not a square root of a non-negative rational constant.
    Sqrt {
        /// 1-based column of `sqrt`.
        column: usize,
        /// What is wrong.
        message: BadRoot,
    },
    /// Numbers with two different square roots in one expression, e.g. `sqrt2 + sqrt3`.
    MixedRoots {
        /// 1-based column of the second root.
        column: usize,
        /// The first radicand met.
        first: u64,
        /// The radicand that differs.
        second: u64,
    },
    /// An expression too large to expand (degree or number of terms).
    TooLarge {
        /// 1-based column of the operation.
        column: usize,
        /// What limit.
        what: TooLarge,
    },
    /// Evaluation without a value for a variable the polynomial uses.
    MissingVariable {
        /// The variable.
        var: String,
    },
    /// Two operands of different dimensions (tuples of 2 and 3 polynomials...).
    DimensionMismatch {
        /// What was being done.
        what: Operands,
        /// The dimension expected.
        expected: usize,
        /// The dimension found.
        found: usize,
    },
    /// A polynomial whose degree exceeds the degree of the Bernstein basis asked for.
    DegreeTooHigh {
        /// The variable.
        var: String,
        /// The degree of the polynomial in it.
        degree: u32,
        /// The degree of the basis.
        max: u32,
    },
    /// A polynomial that uses a variable outside the Bernstein basis asked for.
    ExtraVariable {
        /// The variable.
        var: String,
        /// The variables of the basis.
        basis: String,
    },
    /// A tensor-product basis asked for in one variable twice.
    SameVariable {
        /// The variable.
        var: String,
    },
    /// An empty control polygon or mesh.
    Empty {
        /// What is empty.
        what: Control,
    },
    /// A control mesh whose rows have different lengths.
    Ragged {
        /// The row that differs.
        row: usize,
        /// Its length.
        len: usize,
        /// The length of row 0.
        expected: usize,
    },
    /// The denominator of a rational map vanishes where it is evaluated, or is the zero
    /// polynomial.
    ZeroDenominator {
        /// Where.
        at: Vanishes,
    },
    /// An affine reparametrization onto an interval of length zero.
    DegenerateInterval {
        /// The end point `a = b`, as text.
        at: String,
    },
    /// A coefficient that the target number type cannot hold exactly.
    Conversion {
        /// The coefficient, as text.
        value: String,
        /// Why not.
        reason: Unconvertible,
    },
    /// A scalar polynomial where a tuple was expected, or the other way round.
    Shape {
        /// What was expected.
        expected: Form,
        /// What was found.
        found: Form,
    },
}

/// An operation of the expression language on operands it is not defined on (the `message`
/// of [`PolyError::Operation`]).
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Misuse {
    /// `a / (b, c)`.
    #[default]
    DivideByTuple,
    /// A sum of tuples of different lengths.
    AddTuples {
        /// The components of the first.
        first: usize,
        /// The components of the second.
        second: usize,
    },
    /// A scalar plus a tuple.
    AddScalarAndTuple,
    /// A difference of tuples of different lengths.
    SubtractTuples {
        /// The components of the first.
        first: usize,
        /// The components of the second.
        second: usize,
    },
    /// A scalar minus a tuple, or the other way round.
    SubtractScalarAndTuple,
    /// A tuple times a tuple.
    MultiplyTuples,
    /// A tuple to a power.
    PowerOfTuple,
    /// A negative power of a non-constant polynomial.
    NegativePower {
        /// The polynomial, as text.
        poly: String,
    },
    /// A tuple as a component of a tuple.
    TupleInTuple,
}

/// A square root the expression language cannot take (the `message` of [`PolyError::Sqrt`]).
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum BadRoot {
    /// The root of a tuple.
    #[default]
    OfTuple,
    /// The root of a non-constant polynomial.
    OfPolynomial {
        /// The polynomial, as text.
        poly: String,
    },
    /// The root of a number that has a root itself.
    OfRoot {
        /// The number, as text.
        value: String,
    },
    /// The root of a negative number.
    Negative {
        /// The number, as text.
        value: String,
    },
}

/// The size limit an expression exceeded (the `what` of [`PolyError::TooLarge`]).
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
#[non_exhaustive]
pub enum TooLarge {
    /// A degree above the limit.
    Degree {
        /// The degree.
        degree: u64,
        /// The limit.
        max: u32,
    },
    /// More work than the budget.
    Products {
        /// The budget.
        max: usize,
        /// The terms of the first factor.
        first: usize,
        /// The terms of the second factor.
        second: usize,
    },
    /// A power of a term whose coefficient would be too long.
    Coefficient {
        /// Its size, in 64-bit words.
        size: usize,
        /// The limit.
        max: usize,
    },
    /// A power of a variable above the exponent limit.
    Power {
        /// The variable.
        var: String,
        /// Its exponent.
        exponent: u32,
        /// The limit.
        max: u32,
    },
    /// A coefficient of too many digits.
    CoefficientDigits(Exceeded),
}

impl Default for PolyError {
    fn default() -> Self {
        PolyError::Scalar(ScalarError::default())
    }
}

impl Default for TooLarge {
    fn default() -> Self {
        TooLarge::Degree { degree: 0, max: 0 }
    }
}

/// The operands of an operation whose dimensions differ (the `what` of
/// [`PolyError::DimensionMismatch`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Operands {
    /// A sum of polynomial maps.
    #[default]
    Adding,
    /// A difference of polynomial maps.
    Subtracting,
    /// A dot product.
    DotProduct,
    /// A cross product (of 3-vectors).
    CrossProduct,
    /// The points of a control polygon or mesh.
    PointsOf(Control),
}

/// A control structure (the `what` of [`PolyError::Empty`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Control {
    /// A control polygon.
    #[default]
    Polygon,
    /// A control mesh.
    Mesh,
    /// A homogeneous map (weight last).
    HomogeneousMap,
}

/// Where a denominator vanishes (the `at` of [`PolyError::ZeroDenominator`]).
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Vanishes {
    /// It is the zero polynomial.
    #[default]
    Everywhere,
    /// At a point.
    At {
        /// The point, as `u = 1, v = 2`.
        point: String,
    },
}

/// Why a coefficient cannot be converted (the `reason` of [`PolyError::Conversion`]).
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Unconvertible {
    /// A coefficient in letters, or otherwise not an exact number.
    #[default]
    NotExact,
    /// The target number type refuses it.
    Scalar(ScalarError),
}

/// A scalar polynomial or a tuple (the `expected` and `found` of [`PolyError::Shape`]).
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Form {
    /// A scalar polynomial.
    #[default]
    ScalarPolynomial,
    /// A tuple of polynomials.
    TupleOfPolynomials,
    /// A tuple of so many polynomials.
    Tuple {
        /// Its components.
        dim: usize,
    },
    /// This scalar polynomial.
    Scalar {
        /// The polynomial, as text.
        poly: String,
    },
}

impl Message for PolyError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            PolyError::Scalar(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            PolyError::UnknownVariable {
                name,
                column: Some(c),
            } => said(
                lang,
                "at column ‹›: unknown variable '‹›' (the variables are u, v, w, t, s, x, y, z; 'uv' means u v)",
                "en la columna ‹›: variable desconocida '‹›' (las variables son u, v, w, t, s, x, y, z; 'uv' es u v)",
                [c.into(), name.into()],
            ),
            PolyError::UnknownVariable { name, column: None } => said(
                lang,
                "unknown variable '‹›' (the variables are u, v, w, t, s, x, y, z; 'uv' means u v)",
                "variable desconocida '‹›' (las variables son u, v, w, t, s, x, y, z; 'uv' es u v)",
                [name.into()],
            ),
            PolyError::Operation { column, message } => said(
                lang,
                "at column ‹›: «»",
                "en la columna ‹›: «»",
                [column.into(), message.phrase(lang).into()],
            ),
            PolyError::DivisionByPolynomial { column, divisor } => said(
                lang,
                "at column ‹›: division by a polynomial is not a polynomial (divisor ‹›; only nonzero constants can divide)",
                "en la columna ‹›: dividir por un polinomio no da un polinomio (divisor ‹›; solo se puede dividir por constantes no nulas)",
                [column.into(), divisor.into()],
            ),
            PolyError::Sqrt { column, message } => said(
                lang,
                "at column ‹›: «»",
                "en la columna ‹›: «»",
                [column.into(), message.phrase(lang).into()],
            ),
            PolyError::MixedRoots {
                column,
                first,
                second,
            } => said(
                lang,
                "at column ‹›: numbers with $√‹›$ and $√‹›$ cannot be mixed: an expression runs in one field $a + b√d$",
                "en la columna ‹›: no se pueden mezclar números con $√‹›$ y con $√‹›$: una expresión se calcula en un solo cuerpo $a + b√d$",
                [column.into(), first.into(), second.into()],
            ),
            PolyError::TooLarge { column, what } => said(
                lang,
                "at column ‹›: expression too large to expand: «»",
                "en la columna ‹›: expresión demasiado grande para desarrollarla: «»",
                [column.into(), what.phrase(lang).into()],
            ),
            PolyError::MissingVariable { var } => said(
                lang,
                "no value given for the variable ‹›",
                "no se ha dado valor a la variable ‹›",
                [var.into()],
            ),
            PolyError::DimensionMismatch {
                what,
                expected,
                found,
            } => said(
                lang,
                "«»: expected dimension ‹›, found ‹›",
                "«»: se esperaba dimensión ‹›, se encontró ‹›",
                [what.phrase(lang).into(), expected.into(), found.into()],
            ),
            PolyError::DegreeTooHigh { var, degree, max } => said(
                lang,
                "the polynomial has degree ‹› in ‹›, more than the degree ‹› of the Bernstein basis",
                "el polinomio tiene grado ‹› en ‹›, más que el grado ‹› de la base de Bernstein",
                [degree.into(), var.into(), max.into()],
            ),
            PolyError::ExtraVariable { var, basis } => said(
                lang,
                "the polynomial depends on ‹›, but the Bernstein basis is in ‹› only",
                "el polinomio depende de ‹›, pero la base de Bernstein solo es en ‹›",
                [var.into(), basis.into()],
            ),
            PolyError::SameVariable { var } => said(
                lang,
                "the two variables of a tensor-product Bernstein basis must differ, both are ‹›",
                "las dos variables de una base de Bernstein de producto tensorial han de ser distintas; ambas son ‹›",
                [var.into()],
            ),
            PolyError::Empty { what } => match what {
                Control::Polygon => said(
                    lang,
                    "the control polygon is empty",
                    "el polígono de control está vacío",
                    [],
                ),
                Control::Mesh => said(
                    lang,
                    "the control mesh is empty",
                    "la malla de control está vacía",
                    [],
                ),
                Control::HomogeneousMap => said(
                    lang,
                    "the homogeneous map is empty",
                    "la aplicación homogénea está vacía",
                    [],
                ),
            },
            PolyError::Ragged { row, len, expected } => said(
                lang,
                "row ‹› of the control mesh has ‹› points but row 0 has ‹›",
                "la fila ‹› de la malla de control tiene ‹› puntos, pero la fila 0 tiene ‹›",
                [row.into(), len.into(), expected.into()],
            ),
            PolyError::ZeroDenominator { at } => said(
                lang,
                "the denominator vanishes «»",
                "el denominador se anula «»",
                [at.phrase(lang).into()],
            ),
            PolyError::DegenerateInterval { at } => said(
                lang,
                "the interval [‹›, ‹›] has length zero: cannot reparametrize onto it",
                "el intervalo [‹›, ‹›] tiene longitud cero: no se puede reparametrizar sobre él",
                [at.into(), at.into()],
            ),
            PolyError::Conversion { value, reason } => said(
                lang,
                "coefficient ‹› cannot be converted: «»",
                "el coeficiente ‹› no se puede convertir: «»",
                [value.into(), reason.phrase(lang).into()],
            ),
            PolyError::Shape { expected, found } => said(
                lang,
                "expected «», found «»",
                "se esperaba «», se encontró «»",
                [expected.phrase(lang).into(), found.phrase(lang).into()],
            ),
        }
    }
}

impl Message for Misuse {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Misuse::DivideByTuple => said(
                lang,
                "cannot divide by a tuple",
                "no se puede dividir por una tupla",
                [],
            ),
            Misuse::AddTuples { first, second } => said(
                lang,
                "cannot add tuples of ‹› and ‹› components",
                "no se pueden sumar tuplas de ‹› y ‹› componentes",
                [first.into(), second.into()],
            ),
            Misuse::AddScalarAndTuple => said(
                lang,
                "cannot add a scalar and a tuple",
                "no se pueden sumar un escalar y una tupla",
                [],
            ),
            Misuse::SubtractTuples { first, second } => said(
                lang,
                "cannot subtract tuples of ‹› and ‹› components",
                "no se pueden restar tuplas de ‹› y ‹› componentes",
                [first.into(), second.into()],
            ),
            Misuse::SubtractScalarAndTuple => said(
                lang,
                "cannot subtract a scalar and a tuple",
                "no se pueden restar un escalar y una tupla",
                [],
            ),
            Misuse::MultiplyTuples => said(
                lang,
                "cannot multiply a tuple by a tuple (multiply a tuple by a scalar polynomial)",
                "no se puede multiplicar una tupla por una tupla (multiplique la tupla por un polinomio escalar)",
                [],
            ),
            Misuse::PowerOfTuple => said(
                lang,
                "cannot raise a tuple to a power",
                "no se puede elevar una tupla a una potencia",
                [],
            ),
            Misuse::NegativePower { poly } => said(
                lang,
                "a negative power of the polynomial ‹› is not a polynomial",
                "una potencia negativa del polinomio ‹› no es un polinomio",
                [poly.into()],
            ),
            Misuse::TupleInTuple => said(
                lang,
                "a tuple inside a tuple",
                "una tupla dentro de una tupla",
                [],
            ),
        }
    }
}

impl Message for BadRoot {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            BadRoot::OfTuple => said(lang, "sqrt of a tuple", "sqrt de una tupla", []),
            BadRoot::OfPolynomial { poly } => said(
                lang,
                "sqrt of the polynomial ‹› is not a polynomial (only square roots of constants, such as sqrt2 or sqrt(3/4))",
                "sqrt del polinomio ‹› no es un polinomio (solo raíces cuadradas de constantes, como sqrt2 o sqrt(3/4))",
                [poly.into()],
            ),
            BadRoot::OfRoot { value } => said(
                lang,
                "sqrt of ‹› (a number with a root) is not in a quadratic field $a + b√d$",
                "sqrt de ‹› (un número con raíz) no está en un cuerpo cuadrático $a + b√d$",
                [value.into()],
            ),
            BadRoot::Negative { value } => said(
                lang,
                "square root of a negative number (‹›) is not real",
                "la raíz cuadrada de un número negativo (‹›) no es real",
                [value.into()],
            ),
        }
    }
}

impl Message for TooLarge {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            TooLarge::Degree { degree, max } => said(
                lang,
                "degree ‹› is more than ‹›",
                "el grado ‹› supera ‹›",
                [degree.into(), max.into()],
            ),
            TooLarge::Products { max, first, second } => said(
                lang,
                "more than ‹› products of 64-bit words (at a product of ‹› by ‹› terms)",
                "más de ‹› productos de palabras de 64 bits (en un producto de ‹› por ‹› términos)",
                [max.into(), first.into(), second.into()],
            ),
            TooLarge::Coefficient { size, max } => said(
                lang,
                "a coefficient of about ‹› 64-bit words, more than ‹›",
                "un coeficiente de unas ‹› palabras de 64 bits, más de ‹›",
                [size.into(), max.into()],
            ),
            TooLarge::Power { var, exponent, max } => said(
                lang,
                "the power $‹›^‹›$, above the exponent limit of ‹›",
                "la potencia $‹›^‹›$, por encima del límite de exponentes de ‹›",
                [var.into(), exponent.into(), max.into()],
            ),
            TooLarge::CoefficientDigits(what) => said(
                lang,
                "a coefficient: «»",
                "un coeficiente: «»",
                [what.phrase(lang).into()],
            ),
        }
    }
}

impl Message for Operands {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Operands::Adding => said(
                lang,
                "adding polynomial maps",
                "al sumar aplicaciones polinómicas",
                [],
            ),
            Operands::Subtracting => said(
                lang,
                "subtracting polynomial maps",
                "al restar aplicaciones polinómicas",
                [],
            ),
            Operands::DotProduct => said(lang, "dot product", "producto escalar", []),
            Operands::CrossProduct => said(lang, "cross product", "producto vectorial", []),
            Operands::PointsOf(c) => said(
                lang,
                "points of «»",
                "puntos de «»",
                [c.phrase(lang).into()],
            ),
        }
    }
}

impl Message for Control {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Control::Polygon => said(lang, "the control polygon", "el polígono de control", []),
            Control::Mesh => said(lang, "the control mesh", "la malla de control", []),
            Control::HomogeneousMap => {
                said(lang, "the homogeneous map", "la aplicación homogénea", [])
            }
        }
    }
}

impl Message for Vanishes {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Vanishes::Everywhere => said(
                lang,
                "everywhere: it is the zero polynomial",
                "en todas partes: es el polinomio cero",
                [],
            ),
            Vanishes::At { point } => said(lang, "at (‹›)", "en (‹›)", [point.into()]),
        }
    }
}

impl Message for Unconvertible {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Unconvertible::NotExact => said(
                lang,
                "it is not an exact number",
                "no es un número exacto",
                [],
            ),
            Unconvertible::Scalar(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
        }
    }
}

impl Message for Form {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Form::ScalarPolynomial => said(lang, "a scalar polynomial", "un polinomio escalar", []),
            Form::TupleOfPolynomials => said(
                lang,
                "a tuple of polynomials",
                "una tupla de polinomios",
                [],
            ),
            Form::Tuple { dim } => said(
                lang,
                "a tuple of ‹› polynomials",
                "una tupla de ‹› polinomios",
                [dim.into()],
            ),
            Form::Scalar { poly } => said(
                lang,
                "the scalar polynomial ‹›",
                "el polinomio escalar ‹›",
                [poly.into()],
            ),
        }
    }
}

cagd_words::display_english!(
    PolyError,
    Misuse,
    BadRoot,
    TooLarge,
    Operands,
    Control,
    Vanishes,
    Unconvertible,
    Form
);

impl std::error::Error for PolyError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            PolyError::Scalar(e) => Some(e),
            _ => None,
        }
    }
}

impl From<ScalarError> for PolyError {
    fn from(e: ScalarError) -> Self {
        PolyError::Scalar(e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{Expected, Found};
    use strum::IntoEnumIterator;

    fn check(m: &PolyError) {
        assert_eq!(cagd_words::check_both(m), Ok(()), "{m:?}");
    }

    #[test]
    fn every_variant_in_both_languages() {
        for m in PolyError::iter().chain([PolyError::UnknownVariable {
            name: "q".into(),
            column: Some(2),
        }]) {
            check(&m);
        }
        // the parts, each inside the sentence that carries it
        for message in Misuse::iter() {
            check(&PolyError::Operation { column: 1, message });
        }
        for message in BadRoot::iter() {
            check(&PolyError::Sqrt { column: 1, message });
        }
        for what in TooLarge::iter() {
            check(&PolyError::TooLarge { column: 1, what });
        }
        for what in Operands::iter().chain(Control::iter().map(Operands::PointsOf)) {
            check(&PolyError::DimensionMismatch {
                what,
                expected: 2,
                found: 3,
            });
        }
        for what in Control::iter() {
            check(&PolyError::Empty { what });
        }
        for at in Vanishes::iter() {
            check(&PolyError::ZeroDenominator { at });
        }
        for reason in Unconvertible::iter() {
            check(&PolyError::Conversion {
                value: "√2".into(),
                reason,
            });
        }
        for (expected, found) in Form::iter().zip(Form::iter().rev()) {
            check(&PolyError::Shape { expected, found });
        }
        check(&PolyError::Scalar(ScalarError::Parse {
            column: 3,
            expected: Expected::OperatorOrEnd,
            found: Found::End,
        }));
    }
}
