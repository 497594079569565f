use cagd_words::{said, Lang, Message, Phrase};

/// What can go wrong with numbers: reading them, or asking a number type for a value it cannot
/// hold exactly.
///
/// Each variant is worded in English and in the notes' Spanish ([`Message`]); `Display` writes
/// the English.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
#[non_exhaustive]
pub enum ScalarError {
    /// The text is not a number (or expression) of the grammar.
    Parse {
        /// 1-based column (in characters) where the problem was found.
        column: usize,
        /// What the parser expected there.
        expected: Expected,
        /// What it found instead.
        found: Found,
    },
    /// A division by zero, e.g. `1/0`.
    DivisionByZero {
        /// 1-based column of the division, when known from parsing.
        column: Option<usize>,
    },
    /// `sqrt` of a negative number.
    NegativeSqrt {
        /// The argument of the square root.
        value: String,
    },
    /// Two different square roots in one computation, e.g. `sqrt2 + sqrt3`: a + b√d holds one d.
    MixedRoots {
        /// The first root's radicand.
        first: u64,
        /// The second root's radicand.
        second: u64,
    },
    /// A number with a square root where only rationals are allowed.
    NotRational {
        /// The number, as text.
        value: String,
    },
    /// A resource limit of the parser (exponent, digits, depth).
    Limit {
        /// Which limit, and its value.
        what: Exceeded,
    },
}

/// What the grammar expected where it found something else (the `expected` of
/// [`ScalarError::Parse`]).
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Expected {
    /// A digit after a lone `.`.
    Digit,
    /// Any token of the grammar.
    Token,
    /// An expression (the text is empty).
    #[default]
    Expression,
    /// An operator or the end, after a complete expression.
    OperatorOrEnd,
    /// A number where variables are not allowed.
    NumberWithoutVariables,
    /// A rational number under a square root.
    RationalUnderRoot,
    /// One number, not a tuple.
    SingleNumber,
    /// `)` closing a parenthesized exponent.
    CloseExponent,
    /// An integer exponent.
    IntegerExponent,
    /// `)` closing a square root.
    CloseRoot,
    /// The radicand after `sqrt`.
    RootArgument,
    /// `)` closing a parenthesis.
    CloseParenthesis,
    /// `,` or `)` in a tuple.
    CommaOrClose,
    /// The start of an operand.
    Operand,
    /// A radicand d of a quadratic field.
    SquareFreeRadicand,
    /// A scalar inside an expression, where a tuple is not allowed.
    ScalarNotTuple,
    /// A variable or a declared parameter.
    VariableOrParameter,
    /// A divisor that is a constant (in letters).
    ConstantDivisor,
    /// A small power of a polynomial.
    SmallPower,
    /// A number, in a problem that declares no parameters.
    NumberNoParameters,
    /// A number or one of the declared parameters.
    NumberOrParameter {
        /// The declared parameters, as a list (`R, a`).
        declared: String,
    },
    /// A number.
    Number,
}

/// What the grammar found where it expected something else (the `found` of
/// [`ScalarError::Parse`]).
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Found {
    /// A numeric literal.
    Number(String),
    /// A character, a name or an operator, quoted (`'x'`, `'+'`, `'sqrt'`).
    Quoted(String),
    /// The end of the text.
    #[default]
    End,
    /// A tuple.
    Tuple,
    /// A value, as text (a number with a root, a non-integer exponent).
    Value(String),
    /// A letter that is not a declared parameter.
    Undeclared(String),
}

/// A resource limit of the grammar and what exceeded it (the `what` of
/// [`ScalarError::Limit`]).
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
#[non_exhaustive]
pub enum Exceeded {
    /// A value of more digits than the limit (by its bit length).
    Digits {
        /// The limit, in digits.
        max: usize,
    },
    /// A value whose digits were counted.
    DigitsCounted {
        /// Its digits.
        digits: usize,
        /// The limit, in digits.
        max: usize,
    },
    /// An input longer than the limit.
    Length {
        /// Its length, in characters.
        length: usize,
        /// The limit.
        max: usize,
    },
    /// A numeric literal of too many digits.
    Literal {
        /// Its column.
        column: usize,
        /// The limit, in digits.
        max: usize,
    },
    /// A power whose value would be too long.
    Power {
        /// The column of its `^`.
        column: usize,
        /// The limit, in digits.
        max: usize,
    },
    /// Parentheses and signs nested too deep.
    Depth {
        /// The limit.
        max: usize,
        /// The column where it was reached.
        column: usize,
    },
    /// An exponent above the limit.
    Exponent {
        /// The exponent's absolute value, as text.
        exponent: String,
        /// The column of its `^`.
        column: usize,
        /// The limit.
        max: u32,
    },
    /// A square root of too large a number.
    Radicand {
        /// The argument, as text.
        value: String,
        /// The limit.
        max: u64,
    },
    /// A power of a value in letters above 64.
    PowerAbove64 {
        /// The column of its `^`.
        column: usize,
    },
    /// A power whose exponent is not a machine word.
    PowerAt {
        /// The column of its `^`.
        column: usize,
    },
    /// A power of a value in letters above 64 (the parameter field's reader).
    LetterPower {
        /// The column of its `^`.
        column: usize,
    },
}

impl Default for Exceeded {
    fn default() -> Self {
        Exceeded::Digits { max: 0 }
    }
}

impl Default for ScalarError {
    fn default() -> Self {
        ScalarError::DivisionByZero { column: None }
    }
}

impl Message for ScalarError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            ScalarError::Parse {
                column,
                expected,
                found,
            } => said(
                lang,
                "at column ‹›: expected «», found «»",
                "en la columna ‹›: se esperaba «», se encontró «»",
                [
                    column.into(),
                    expected.phrase(lang).into(),
                    found.phrase(lang).into(),
                ],
            ),
            ScalarError::DivisionByZero { column: Some(c) } => said(
                lang,
                "at column ‹›: division by zero",
                "en la columna ‹›: división por cero",
                [c.into()],
            ),
            ScalarError::DivisionByZero { column: None } => {
                said(lang, "division by zero", "división por cero", [])
            }
            ScalarError::NegativeSqrt { value } => said(
                lang,
                "square root of a negative number (‹›) is not real",
                "la raíz cuadrada de un número negativo (‹›) no es real",
                [value.into()],
            ),
            ScalarError::MixedRoots { first, second } => said(
                lang,
                "numbers with $√‹›$ and $√‹›$ cannot be mixed: a problem runs in one field $a + b√d$",
                "no se pueden mezclar números con $√‹›$ y con $√‹›$: un problema se resuelve en un solo cuerpo $a + b√d$",
                [first.into(), second.into()],
            ),
            ScalarError::NotRational { value } => said(
                lang,
                "‹› is not a rational number (it has a square root) where a rational is required",
                "‹› no es un número racional (tiene una raíz cuadrada) donde se necesita un racional",
                [value.into()],
            ),
            ScalarError::Limit { what } => said(
                lang,
                "limit exceeded: «»",
                "límite superado: «»",
                [what.phrase(lang).into()],
            ),
        }
    }
}

impl Message for Expected {
    fn phrase(&self, lang: Lang) -> Phrase {
        let fixed = |en, es| said(lang, en, es, []);
        match self {
            Expected::Digit => fixed("a digit", "una cifra"),
            Expected::Token => fixed(
                "a number, a name, an operator or a parenthesis",
                "un número, un nombre, un operador o un paréntesis",
            ),
            Expected::Expression => fixed("an expression", "una expresión"),
            Expected::OperatorOrEnd => fixed(
                "an operator or the end of the input (is a parenthesis unbalanced?)",
                "un operador o el final de la expresión (¿falta cerrar un paréntesis?)",
            ),
            Expected::NumberWithoutVariables => fixed(
                "a number (variables are not allowed here)",
                "un número (aquí no se admiten variables)",
            ),
            Expected::RationalUnderRoot => fixed(
                "a rational number under the square root",
                "un número racional dentro de la raíz cuadrada",
            ),
            Expected::SingleNumber => fixed("a single number", "un solo número"),
            Expected::CloseExponent => {
                fixed("')' closing the exponent", "')' que cierre el exponente")
            }
            Expected::IntegerExponent => fixed("an integer exponent", "un exponente entero"),
            Expected::CloseRoot => fixed(
                "')' closing the square root",
                "')' que cierre la raíz cuadrada",
            ),
            Expected::RootArgument => {
                fixed("an integer or '(' after sqrt", "un entero o '(' tras sqrt")
            }
            Expected::CloseParenthesis => fixed(
                "')' (unbalanced parenthesis)",
                "')' (un paréntesis sin cerrar)",
            ),
            Expected::CommaOrClose => fixed("',' or ')'", "',' o ')'"),
            Expected::Operand => fixed(
                "a number, a variable, 'sqrt' or '('",
                "un número, una variable, 'sqrt' o '('",
            ),
            Expected::SquareFreeRadicand => fixed(
                "a square-free radicand d ≥ 2",
                "un radicando d ≥ 2 libre de cuadrados",
            ),
            Expected::ScalarNotTuple => fixed(
                "a scalar (a tuple is allowed only as the whole expression)",
                "un escalar (una tupla solo se admite como expresión completa)",
            ),
            Expected::VariableOrParameter => fixed(
                "a variable (u, v, w, t, s, x, y, z) or a declared parameter",
                "una variable (u, v, w, t, s, x, y, z) o un parámetro declarado",
            ),
            Expected::ConstantDivisor => fixed(
                "a divisor without u, v, ... (a polynomial is expanded, not a quotient)",
                "un divisor sin u, v, ... (un polinomio se desarrolla, no es un cociente)",
            ),
            Expected::SmallPower => fixed(
                "a power from 0 to 64 of a polynomial",
                "una potencia de 0 a 64 de un polinomio",
            ),
            Expected::NumberNoParameters => fixed(
                "a number (declare letters in \"parameters\" to use them)",
                "un número (declare las letras en \"parameters\" para usarlas)",
            ),
            Expected::NumberOrParameter { declared } => said(
                lang,
                "a number or a declared parameter (‹›)",
                "un número o un parámetro declarado (‹›)",
                [declared.into()],
            ),
            Expected::Number => fixed("a number", "un número"),
        }
    }
}

impl Message for Found {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Found::Number(q) => said(lang, "the number ‹›", "el número ‹›", [q.into()]),
            Found::Quoted(s) => said(lang, "'‹›'", "'‹›'", [s.into()]),
            Found::End => said(lang, "the end of the input", "el final de la expresión", []),
            Found::Tuple => said(lang, "a tuple", "una tupla", []),
            Found::Value(v) => said(lang, "‹›", "‹›", [v.into()]),
            Found::Undeclared(name) => said(
                lang,
                "'‹›', which is not a declared parameter",
                "'‹›', que no es un parámetro declarado",
                [name.into()],
            ),
        }
    }
}

impl Message for Exceeded {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Exceeded::Digits { max } => said(
                lang,
                "a number of more than ‹› digits",
                "un número de más de ‹› cifras",
                [max.into()],
            ),
            Exceeded::DigitsCounted { digits, max } => said(
                lang,
                "a number of ‹› digits is longer than the limit of ‹› digits",
                "un número de ‹› cifras supera el límite de ‹› cifras",
                [digits.into(), max.into()],
            ),
            Exceeded::Length { length, max } => said(
                lang,
                "input of ‹› characters is longer than ‹›",
                "un texto de ‹› caracteres supera el máximo de ‹›",
                [length.into(), max.into()],
            ),
            Exceeded::Literal { column, max } => said(
                lang,
                "number at column ‹› has more than ‹› digits",
                "el número de la columna ‹› tiene más de ‹› cifras",
                [column.into(), max.into()],
            ),
            Exceeded::Power { column, max } => said(
                lang,
                "the power at column ‹› would have more than ‹› digits",
                "la potencia de la columna ‹› tendría más de ‹› cifras",
                [column.into(), max.into()],
            ),
            Exceeded::Depth { max, column } => said(
                lang,
                "expression nested deeper than ‹› at column ‹›",
                "expresión anidada a más de ‹› niveles en la columna ‹›",
                [max.into(), column.into()],
            ),
            Exceeded::Exponent {
                exponent,
                column,
                max,
            } => said(
                lang,
                "exponent ‹› at column ‹› is larger than ‹›",
                "el exponente ‹› de la columna ‹› es mayor que ‹›",
                [exponent.into(), column.into(), max.into()],
            ),
            Exceeded::Radicand { value, max } => said(
                lang,
                "square root argument ‹› is larger than ‹›",
                "el argumento ‹› de la raíz cuadrada es mayor que ‹›",
                [value.into(), max.into()],
            ),
            Exceeded::PowerAbove64 { column } => said(
                lang,
                "the power at column ‹› is above 64",
                "la potencia de la columna ‹› supera 64",
                [column.into()],
            ),
            Exceeded::PowerAt { column } => said(
                lang,
                "the power at column ‹›",
                "la potencia de la columna ‹›",
                [column.into()],
            ),
            Exceeded::LetterPower { column } => said(
                lang,
                "the power at column ‹› of a value in letters is above 64",
                "la potencia de la columna ‹› de un valor en letras supera 64",
                [column.into()],
            ),
        }
    }
}

cagd_words::display_english!(ScalarError, Expected, Found, Exceeded);

impl std::error::Error for ScalarError {}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_variant_in_both_languages() {
        for m in ScalarError::iter().chain([ScalarError::DivisionByZero { column: Some(3) }]) {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        // the parts, each inside the sentence that carries it
        for expected in Expected::iter() {
            let m = ScalarError::Parse {
                column: 1,
                expected,
                found: Found::End,
            };
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        for found in Found::iter() {
            let m = ScalarError::Parse {
                column: 1,
                expected: Expected::Number,
                found,
            };
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        for what in Exceeded::iter() {
            let m = ScalarError::Limit { what };
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }

    /// The grammar's two sentences that the catalogue left half in English: a sum without its
    /// second term, and a parenthesis never closed.
    #[test]
    fn the_grammar_s_errors_are_spanish_throughout() {
        for (text, spanish) in [
            (
                "1 +",
                "en la columna 4: se esperaba un número, una variable, 'sqrt' o '(', se encontró el final de la expresión",
            ),
            (
                "(2",
                "en la columna 3: se esperaba ')' (un paréntesis sin cerrar), se encontró el final de la expresión",
            ),
            (
                "2)",
                "en la columna 2: se esperaba un operador o el final de la expresión (¿falta cerrar un paréntesis?), se encontró ')'",
            ),
        ] {
            let e = match crate::parse_number(text) {
                Err(e) => e,
                Ok(x) => panic!("{text} read as {x}"),
            };
            let es = e.phrase(Lang::Es);
            assert_eq!(es.text(), spanish, "{text}");
            assert_eq!(cagd_words::english_in(&es), Vec::<String>::new(), "{text}");
        }
        assert_eq!(
            crate::parse_number("1 +").map_err(|e| e.to_string()),
            Err("at column 4: expected a number, a variable, 'sqrt' or '(', found the end of the input".to_string())
        );
    }
}
