//! Mistakes in restriction and subdivision (chapter 5, §4, eq. (13)).

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{Lang, Message, Phrase};

/// A mistake in restriction and subdivision.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SubdivideMistake {}

impl SubdivideMistake {
    /// Every mistake of the family.
    pub const ALL: &'static [SubdivideMistake] = &[];
}

impl Message for SubdivideMistake {
    fn phrase(&self, _lang: Lang) -> Phrase {
        match *self {}
    }
}

impl Catalogued for SubdivideMistake {
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
