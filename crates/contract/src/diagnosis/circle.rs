//! Mistakes in circles and arcs (chapter 6, §6: the 9-point circle; rational quadratic arcs).

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{Lang, Message, Phrase};

/// A mistake in circles and arcs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CircleMistake {}

impl CircleMistake {
    /// Every mistake of the family.
    pub const ALL: &'static [CircleMistake] = &[];
}

impl Message for CircleMistake {
    fn phrase(&self, _lang: Lang) -> Phrase {
        match *self {}
    }
}

impl Catalogued for CircleMistake {
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
