//! The remarks of a construction: what was done to its curves before the surface was built.

use cagd_words::{said, Lang, Message, Phrase};
use std::fmt;

/// A remark of a construction in words, kept with or without its steps: a curve raised to the
/// degree of the others, knots inserted to make two B-spline curves compatible, the knots of a
/// NURBS surface. What the computation supplies (a curve's name, a knot vector as text) fills
/// the holes of its sentence.
#[derive(Debug, Clone, PartialEq, Eq, Hash, strum::EnumIter)]
#[non_exhaustive]
pub enum Note {
    /// A curve elevated to the degree of the others: `c2 elevated from degree 2 to 3`.
    CurveElevated {
        /// The curve's name, as the notes write it (`c1`, `d2`).
        name: String,
        /// Its degree.
        from: usize,
        /// The common degree.
        to: usize,
    },
    /// Knots inserted into a curve to give it the knots of the other one:
    /// `c1: knots 1/2, 3/4 inserted`.
    KnotsInserted {
        /// The curve's name.
        name: String,
        /// The knots inserted, as text, separated by commas.
        knots: String,
    },
    /// The knots in u of the surface built: `knots in u: {0, 0, 1, 1}`.
    KnotsInU {
        /// The knot vector, as text.
        knots: String,
    },
    /// The knots in v of the surface built.
    KnotsInV {
        /// The knot vector, as text.
        knots: String,
    },
}

impl Message for Note {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Note::CurveElevated { name, from, to } => said(
                lang,
                "$‹›$ elevated from degree ‹› to ‹›",
                "$‹›$ elevada de grado ‹› a grado ‹›",
                [name.into(), from.into(), to.into()],
            ),
            Note::KnotsInserted { name, knots } => said(
                lang,
                "$‹›$: knots ‹› inserted",
                "$‹›$: se insertan los nudos ‹›",
                [name.into(), knots.into()],
            ),
            Note::KnotsInU { knots } => {
                said(lang, "knots in u: ‹›", "nudos en u: ‹›", [knots.into()])
            }
            Note::KnotsInV { knots } => {
                said(lang, "knots in v: ‹›", "nudos en v: ‹›", [knots.into()])
            }
        }
    }
}

/// The English text.
///
/// ```
/// use cagd_generate::Note;
/// let note = Note::CurveElevated { name: "c2".into(), from: 2, to: 3 };
/// assert_eq!(note.to_string(), "c2 elevated from degree 2 to 3");
/// ```
impl fmt::Display for Note {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.english())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_variant_in_both_languages() {
        for m in Note::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        let m = Note::KnotsInserted {
            name: "d1".into(),
            knots: "1/3, 2/3".into(),
        };
        assert_eq!(
            m.phrase(Lang::Es).text(),
            "d1: se insertan los nudos 1/3, 2/3"
        );
        assert_eq!(m.to_string(), "d1: knots 1/3, 2/3 inserted");
    }
}
