//! Mistakes in de Casteljau evaluation of curves and patches, rational ones too (chapter 5, §4).

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{Lang, Message, Phrase};

/// A mistake in de casteljau evaluation of curves and patches, rational ones too.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum EvaluateMistake {}

impl EvaluateMistake {
    /// Every mistake of the family.
    pub const ALL: &'static [EvaluateMistake] = &[];
}

impl Message for EvaluateMistake {
    fn phrase(&self, _lang: Lang) -> Phrase {
        match *self {}
    }
}

impl Catalogued for EvaluateMistake {
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
