//! Mistakes in normal vectors (chapter 5, §5, eq. (24)-(25)).

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{Lang, Message, Phrase};

/// A mistake in normal vectors.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum NormalMistake {}

impl NormalMistake {
    /// Every mistake of the family.
    pub const ALL: &'static [NormalMistake] = &[];
}

impl Message for NormalMistake {
    fn phrase(&self, _lang: Lang) -> Phrase {
        match *self {}
    }
}

impl Catalogued for NormalMistake {
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
