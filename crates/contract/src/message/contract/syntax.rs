//! What is wrong with a text that is not JSON (serde_json's syntax errors), in words.

use cagd_words::{said, Lang, Message, Phrase};

/// What is wrong with a text that is not JSON (serde_json's syntax errors).
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum Syntax {
    /// The text ends inside a list.
    EofInList,
    /// The text ends inside an object.
    EofInObject,
    /// The text ends inside a string.
    EofInString,
    /// The text ends before a value.
    #[default]
    EofInValue,
    /// A `:` expected.
    ExpectedColon,
    /// A `,` or `]` expected.
    ExpectedListCommaOrEnd,
    /// A `,` or `}` expected.
    ExpectedObjectCommaOrEnd,
    /// An identifier expected.
    ExpectedIdent,
    /// A value expected.
    ExpectedValue,
    /// A `"` expected.
    ExpectedDoubleQuote,
    /// An invalid escape.
    InvalidEscape,
    /// An invalid number.
    InvalidNumber,
    /// A number out of range.
    NumberOutOfRange,
    /// An invalid unicode code point.
    InvalidUnicodeCodePoint,
    /// A control character in a string.
    ControlCharacter,
    /// A key that is no string.
    KeyMustBeAString,
    /// A lone leading surrogate.
    LoneLeadingSurrogate,
    /// A trailing comma.
    TrailingComma,
    /// Characters after the value.
    TrailingCharacters,
    /// A hex escape cut short.
    UnexpectedEndOfHexEscape,
    /// Nested too deep.
    RecursionLimitExceeded,
    /// Something else, in serde's words.
    Other(String),
}

impl Syntax {
    /// serde_json's words for each (its `ErrorCode`'s Display), for the one reader of them.
    pub(crate) const WORDS: [(&'static str, Syntax); 21] = [
        ("EOF while parsing a list", Syntax::EofInList),
        ("EOF while parsing an object", Syntax::EofInObject),
        ("EOF while parsing a string", Syntax::EofInString),
        ("EOF while parsing a value", Syntax::EofInValue),
        ("expected `:`", Syntax::ExpectedColon),
        ("expected `,` or `]`", Syntax::ExpectedListCommaOrEnd),
        ("expected `,` or `}`", Syntax::ExpectedObjectCommaOrEnd),
        ("expected ident", Syntax::ExpectedIdent),
        ("expected value", Syntax::ExpectedValue),
        ("expected `\"`", Syntax::ExpectedDoubleQuote),
        ("invalid escape", Syntax::InvalidEscape),
        ("invalid number", Syntax::InvalidNumber),
        ("number out of range", Syntax::NumberOutOfRange),
        (
            "invalid unicode code point",
            Syntax::InvalidUnicodeCodePoint,
        ),
        (
            "control character (\\u0000-\\u001F) found while parsing a string",
            Syntax::ControlCharacter,
        ),
        ("key must be a string", Syntax::KeyMustBeAString),
        (
            "lone leading surrogate in hex escape",
            Syntax::LoneLeadingSurrogate,
        ),
        ("trailing comma", Syntax::TrailingComma),
        ("trailing characters", Syntax::TrailingCharacters),
        (
            "unexpected end of hex escape",
            Syntax::UnexpectedEndOfHexEscape,
        ),
        ("recursion limit exceeded", Syntax::RecursionLimitExceeded),
    ];
}

impl Message for Syntax {
    fn phrase(&self, lang: Lang) -> Phrase {
        let (en, es): (&'static str, &'static str) = match self {
            Syntax::EofInList => (
                "EOF while parsing a list",
                "el texto acaba dentro de una lista",
            ),
            Syntax::EofInObject => (
                "EOF while parsing an object",
                "el texto acaba dentro de un objeto",
            ),
            Syntax::EofInString => (
                "EOF while parsing a string",
                "el texto acaba dentro de una cadena",
            ),
            Syntax::EofInValue => (
                "EOF while parsing a value",
                "el texto acaba donde se esperaba un valor",
            ),
            // the marks in backticks are data, as a key writer sets them (in typewriter)
            Syntax::ExpectedColon => {
                return said(lang, "expected ‹›", "se esperaba ‹›", [(&"`:`").into()])
            }
            Syntax::ExpectedListCommaOrEnd => {
                return said(
                    lang,
                    "expected ‹› or ‹›",
                    "se esperaba ‹› o ‹›",
                    [(&"`,`").into(), (&"`]`").into()],
                )
            }
            Syntax::ExpectedObjectCommaOrEnd => {
                return said(
                    lang,
                    "expected ‹› or ‹›",
                    "se esperaba ‹› o ‹›",
                    [(&"`,`").into(), (&"`}`").into()],
                )
            }
            Syntax::ExpectedIdent => ("expected ident", "se esperaba un identificador"),
            Syntax::ExpectedValue => ("expected value", "se esperaba un valor"),
            Syntax::ExpectedDoubleQuote => {
                return said(lang, "expected ‹›", "se esperaba ‹›", [(&"`\"`").into()])
            }
            Syntax::InvalidEscape => ("invalid escape", "secuencia de escape no válida"),
            Syntax::InvalidNumber => ("invalid number", "número no válido"),
            Syntax::NumberOutOfRange => ("number out of range", "número fuera de rango"),
            Syntax::InvalidUnicodeCodePoint => (
                "invalid unicode code point",
                "punto de código Unicode no válido",
            ),
            Syntax::ControlCharacter => (
                "control character (\\u0000-\\u001F) found while parsing a string",
                "carácter de control (\\u0000-\\u001F) dentro de una cadena",
            ),
            Syntax::KeyMustBeAString => ("key must be a string", "la clave ha de ser una cadena"),
            Syntax::LoneLeadingSurrogate => (
                "lone leading surrogate in hex escape",
                "sustituto inicial sin pareja en un escape hexadecimal",
            ),
            Syntax::TrailingComma => ("trailing comma", "coma sobrante al final"),
            Syntax::TrailingCharacters => {
                ("trailing characters", "caracteres sobrantes tras el valor")
            }
            Syntax::UnexpectedEndOfHexEscape => (
                "unexpected end of hex escape",
                "escape hexadecimal incompleto",
            ),
            Syntax::RecursionLimitExceeded => {
                ("recursion limit exceeded", "límite de anidamiento superado")
            }
            Syntax::Other(s) => return said(lang, "‹›", "‹›", [s.into()]),
        };
        said(lang, en, es, [])
    }
}
