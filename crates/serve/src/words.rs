//! The words of the pages (buttons, headings, messages of the page itself), English and
//! Spanish by one exhaustive match; `/api/set` sends them all to the page as `words`.

use cagd_words::{said, Lang, Message, Phrase};
use serde_json::{Map, Value};
use strum::IntoEnumIterator;

/// A word of the pages, by the id the page's script knows it by (`PageWord::Check` is
/// `"check"`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, strum::EnumIter, strum::IntoStaticStr)]
#[strum(serialize_all = "snake_case")]
pub enum PageWord {
    /// The button that checks an answer.
    Check,
}

impl Message for PageWord {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            PageWord::Check => said(lang, "Check", "Comprobar", []),
        }
    }
}

/// Every word of the pages in `lang`, by id.
pub fn all(lang: Lang) -> Value {
    let mut out = Map::new();
    for w in PageWord::iter() {
        let id: &'static str = w.into();
        out.insert(id.to_string(), Value::String(w.phrase(lang).text()));
    }
    Value::Object(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_page_word_in_both_languages() {
        for w in PageWord::iter() {
            assert_eq!(cagd_words::check_both(&w), Ok(()), "{w:?}");
        }
    }
}
