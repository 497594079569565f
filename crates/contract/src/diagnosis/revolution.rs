//! Mistakes in surfaces of revolution (chapter 6, §6, eq. (21)).

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{Lang, Message, Phrase};

/// A mistake in surfaces of revolution.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum RevolutionMistake {}

impl RevolutionMistake {
    /// Every mistake of the family.
    pub const ALL: &'static [RevolutionMistake] = &[];
}

impl Message for RevolutionMistake {
    fn phrase(&self, _lang: Lang) -> Phrase {
        match *self {}
    }
}

impl Catalogued for RevolutionMistake {
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
