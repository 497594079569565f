//! Reading a problem as a whole: its JSON (serde's own messages, read in one place), its keys, its operation, its number field, its values, a batch.

use cagd_words::{said, Lang, Message, Phrase};

/// Reading a problem as a whole: its JSON (serde's own messages, read in one place), its keys, its operation, its number field, its values, a batch.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum Contract {
    /// A placeholder until the sentences of this subject are typed.
    Placeholder,
}

impl Message for Contract {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Contract::Placeholder => said(lang, "placeholder", "marcador", []),
        }
    }
}
