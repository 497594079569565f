//! Mistakes in degree elevation of curves and patches (chapter 5, §5, eq. (14)-(15)).

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{Lang, Message, Phrase};

/// A mistake in degree elevation of curves and patches.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ElevateMistake {}

impl ElevateMistake {
    /// Every mistake of the family.
    pub const ALL: &'static [ElevateMistake] = &[];
}

impl Message for ElevateMistake {
    fn phrase(&self, _lang: Lang) -> Phrase {
        match *self {}
    }
}

impl Catalogued for ElevateMistake {
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
