//! The Python module's own sentences, typed: what `read`, `solve`, `expand`, `examples`,
//! `generate` and figures refuse (the values of a problem given from Python are refused in
//! cagd-problem's words, [`cagd_problem::message::contract::Contract`]). Each is worded in
//! English and in the notes' Spanish beside its definition; the exception shows the English.

use cagd_exercises::ExerciseError;
use cagd_poly::PolyError;
use cagd_problem::message::contract::Contract;
use cagd_render::RenderError;
use cagd_words::{said, Lang, Message, Phrase};

/// A sentence of the Python module.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum PyMessage {
    /// `read` given a list.
    ReadTakesOne,
    /// `solve(problem, max_...=N)` of a problem read under its own limits.
    ReadUnderLimits,
    /// A figure that cannot be drawn (the render's errors are enumerated with cagd-render's).
    #[strum(disabled)]
    CannotDraw(RenderError),
    /// A figure saved under a name of another kind.
    FigureFormat {
        /// The path given.
        path: String,
    },
    /// A file that cannot be written.
    CannotWrite {
        /// The path given.
        path: String,
        /// Why, as the system says.
        why: String,
    },
    /// A fixture built in that is not JSON (a bug of the build).
    FixtureNotJson {
        /// The fixture's path.
        path: String,
        /// What serde_json says, typed.
        why: Box<Contract>,
    },
    /// `examples` given names no example has.
    NoExample {
        /// The names given, joined.
        names: String,
    },
    /// An expression `expand` cannot read.
    Expression(PolyError),
    /// A problem set `generate` cannot draw (enumerated with cagd-exercises' errors).
    #[strum(disabled)]
    Exercises(ExerciseError),
    /// A number of an answer asked as a `Fraction` that is not rational.
    NotRational {
        /// The number, as written.
        text: String,
        /// The d of its √d.
        radicand: u64,
    },
}

impl Message for PyMessage {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            PyMessage::ReadTakesOne => said(
                lang,
                "read takes one problem (a dict), found a list: read each, or use solve_batch",
                "`read` lee un problema (un dict), se encontró una lista: lea cada uno, o use \
                 `solve_batch`",
                [],
            ),
            PyMessage::ReadUnderLimits => said(
                lang,
                "a Problem was read under its limits: give them to read()",
                "un `Problem` se leyó con sus límites: páselos a `read()`",
                [],
            ),
            PyMessage::CannotDraw(e) => said(
                lang,
                "cannot draw it: «»",
                "no se puede dibujar: «»",
                [e.phrase(lang).into()],
            ),
            PyMessage::FigureFormat { path } => said(
                lang,
                "‹›: a figure is saved as .svg or .html",
                "‹›: una figura se guarda como .svg o .html",
                [path.into()],
            ),
            PyMessage::CannotWrite { path, why } => said(
                lang,
                "cannot write ‹›: ‹›",
                "no se puede escribir ‹›: ‹›",
                [path.into(), why.into()],
            ),
            PyMessage::FixtureNotJson { path, why } => said(
                lang,
                "fixture ‹› is not valid JSON: «»",
                "el ejemplo ‹› no es JSON válido: «»",
                [path.into(), why.phrase(lang).into()],
            ),
            PyMessage::NoExample { names } => said(
                lang,
                "no example is called ‹›",
                "ningún ejemplo se llama ‹›",
                [names.into()],
            ),
            PyMessage::Expression(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            PyMessage::Exercises(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            PyMessage::NotRational { text, radicand } => said(
                lang,
                "‹› is not rational (it holds √‹›): use .sympy() for SymPy numbers",
                "‹› no es racional (contiene √‹›): use .sympy() para números de SymPy",
                [text.into(), radicand.into()],
            ),
        }
    }
}

cagd_words::display_english!(PyMessage);

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_variant_in_both_languages() {
        let wrapped = [
            PyMessage::CannotDraw(RenderError::EmptyScene),
            PyMessage::Exercises(ExerciseError::TooMany { count: 1000 }),
        ];
        for m in PyMessage::iter().chain(wrapped) {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
