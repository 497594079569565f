//! What a problem gave where something else was expected: the JSON kind of a value, in
//! words, and a string of the input quoted as a message echoes it.

use cagd_words::{said, Lang, Message, Phrase};

/// A string quoted for an error message, cut to its first 40 characters so that the
/// message stays one short line whatever the input holds.
pub fn quoted(s: &str) -> String {
    const SHOWN: usize = 40;
    let mut chars = s.chars();
    let head: String = chars.by_ref().take(SHOWN).collect();
    if chars.next().is_some() {
        format!("{:?}", head + "...")
    } else {
        format!("{s:?}")
    }
}

/// What a problem gave where something else was expected: the JSON kind of a value, in words
/// (the one such type, for reading a problem, its leaves and checking an answer).
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum Found {
    /// `null`.
    #[default]
    Null,
    /// `true` or `false`.
    Bool(bool),
    /// A number, as written.
    Number(String),
    /// A string, quoted as an error echoes it.
    Str(String),
    /// A list.
    List,
    /// A list of so many items.
    ListOf(usize),
    /// An object.
    Object,
    /// Something else, in serde's words.
    Other(String),
}

impl Found {
    /// The kind of a JSON value, as an error names it .
    pub fn of(v: &serde_json::Value) -> Found {
        use serde_json::Value;
        match v {
            Value::Null => Found::Null,
            Value::Bool(b) => Found::Bool(*b),
            Value::Number(n) => Found::Number(n.to_string()),
            Value::String(s) => Found::Str(quoted(s)),
            Value::Array(a) => Found::ListOf(a.len()),
            Value::Object(_) => Found::Object,
        }
    }
}

impl Message for Found {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Found::Null => said(lang, "‹›", "‹›", [(&"null").into()]),
            Found::Bool(b) => said(lang, "‹›", "‹›", [b.into()]),
            Found::Number(n) => said(lang, "the number ‹›", "el número ‹›", [n.into()]),
            Found::Str(s) => said(lang, "the string ‹›", "la cadena ‹›", [s.into()]),
            Found::List => said(lang, "a list", "una lista", []),
            Found::ListOf(n) => said(lang, "a list of ‹›", "una lista de ‹›", [n.into()]),
            Found::Object => said(lang, "an object", "un objeto", []),
            Found::Other(s) => said(lang, "‹›", "‹›", [s.into()]),
        }
    }
}

cagd_words::display_english!(Found);

#[cfg(test)]
mod tests {
    use super::*;

    /// The kinds of JSON values, in words; a long string cut at forty characters.
    #[test]
    fn found_is_the_kind_in_words() {
        for (v, words) in [
            (serde_json::json!(null), "null"),
            (serde_json::json!(true), "true"),
            (serde_json::json!(2.5), "the number 2.5"),
            (
                serde_json::json!("a string longer than forty characters, cut at forty"),
                "the string \"a string longer than forty characters, c...\"",
            ),
            (serde_json::json!([1, 2]), "a list of 2"),
            (serde_json::json!({"a": 1}), "an object"),
        ] {
            assert_eq!(Found::of(&v).english(), words);
        }
    }
}
