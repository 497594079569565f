//! Mistakes in derivatives and twists (chapter 5, §5, eq. (16)-(20)).

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{Lang, Message, Phrase};

/// A mistake in derivatives and twists.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum DerivativeMistake {}

impl DerivativeMistake {
    /// Every mistake of the family.
    pub const ALL: &'static [DerivativeMistake] = &[];
}

impl Message for DerivativeMistake {
    fn phrase(&self, _lang: Lang) -> Phrase {
        match *self {}
    }
}

impl Catalogued for DerivativeMistake {
    fn id(&self) -> &'static str {
        match *self {}
    }

    fn place(&self) -> NotesPlace {
        match *self {}
    }

    fn right(&self) -> MistakeFormula {
        match *self {}
    }

    fn used(&self) -> MistakeFormula {
        match *self {}
    }
}
