//! Checking an answer against what the problem expects: mismatches and verdict sentences.

use cagd_words::{said, Lang, Message, Phrase};

/// Checking an answer against what the problem expects: mismatches and verdict sentences.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum Check {
    /// A placeholder until the sentences of this subject are typed.
    Placeholder,
}

impl Message for Check {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Check::Placeholder => said(lang, "placeholder", "marcador", []),
        }
    }
}
