//! Reading the leaves of a problem: its numbers, points, shapes (curves, surfaces, triangles) and their limits.

use cagd_words::{said, Lang, Message, Phrase};

/// Reading the leaves of a problem: its numbers, points, shapes (curves, surfaces, triangles) and their limits.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum Read {
    /// A placeholder until the sentences of this subject are typed.
    Placeholder,
}

impl Message for Read {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Read::Placeholder => said(lang, "placeholder", "marcador", []),
        }
    }
}
