//! Mistakes in translational surfaces (chapter 6, §2, eq. (1)-(4)).

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{Lang, Message, Phrase};

/// A mistake in translational surfaces.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TranslationalMistake {}

impl TranslationalMistake {
    /// Every mistake of the family.
    pub const ALL: &'static [TranslationalMistake] = &[];
}

impl Message for TranslationalMistake {
    fn phrase(&self, _lang: Lang) -> Phrase {
        match *self {}
    }
}

impl Catalogued for TranslationalMistake {
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
