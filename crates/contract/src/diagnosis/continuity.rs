//! Mistakes in c^r joins of two patches or two curves (chapter 5, §6, eq. (21)-(22)).

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{Lang, Message, Phrase};

/// A mistake in c^r joins of two patches or two curves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ContinuityMistake {}

impl ContinuityMistake {
    /// Every mistake of the family.
    pub const ALL: &'static [ContinuityMistake] = &[];
}

impl Message for ContinuityMistake {
    fn phrase(&self, _lang: Lang) -> Phrase {
        match *self {}
    }
}

impl Catalogued for ContinuityMistake {
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
