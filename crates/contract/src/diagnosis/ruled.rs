//! Mistakes in ruled surfaces (chapter 6, §3, eq. (7)).

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{Lang, Message, Phrase};

/// A mistake in ruled surfaces.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum RuledMistake {}

impl RuledMistake {
    /// Every mistake of the family.
    pub const ALL: &'static [RuledMistake] = &[];
}

impl Message for RuledMistake {
    fn phrase(&self, _lang: Lang) -> Phrase {
        match *self {}
    }
}

impl Catalogued for RuledMistake {
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
