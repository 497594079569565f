//! Mistakes in knot insertion (Boehm's algorithm; the curve chapters, The NURBS Book §5.2).

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{Lang, Message, Phrase};

/// A mistake in knot insertion.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum InsertKnotMistake {}

impl InsertKnotMistake {
    /// Every mistake of the family.
    pub const ALL: &'static [InsertKnotMistake] = &[];
}

impl Message for InsertKnotMistake {
    fn phrase(&self, _lang: Lang) -> Phrase {
        match *self {}
    }
}

impl Catalogued for InsertKnotMistake {
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
