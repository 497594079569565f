//! The curve operations' own sentences (errors and remarks).

use cagd_words::{said, Lang, Message, Phrase};

/// The curve operations' own sentences (errors and remarks).
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum Curve {
    /// A placeholder until the sentences of this subject are typed.
    Placeholder,
}

impl Message for Curve {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Curve::Placeholder => said(lang, "placeholder", "marcador", []),
        }
    }
}
