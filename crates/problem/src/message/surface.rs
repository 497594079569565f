//! The surface operations' own sentences, chapters 5 and 6 (errors and remarks).

use cagd_words::{said, Lang, Message, Phrase};

/// The surface operations' own sentences, chapters 5 and 6 (errors and remarks).
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum Surface {
    /// A placeholder until the sentences of this subject are typed.
    Placeholder,
}

impl Message for Surface {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Surface::Placeholder => said(lang, "placeholder", "marcador", []),
        }
    }
}
