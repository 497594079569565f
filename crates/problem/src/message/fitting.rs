//! Triangles' and fitting's own sentences (errors and remarks).

use cagd_words::{said, Lang, Message, Phrase};

/// Triangles' and fitting's own sentences (errors and remarks).
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum Fitting {
    /// A placeholder until the sentences of this subject are typed.
    Placeholder,
}

impl Message for Fitting {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Fitting::Placeholder => said(lang, "placeholder", "marcador", []),
        }
    }
}
