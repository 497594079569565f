//! A typed message in a key: its [`Phrase`] in the language asked, as text, as LaTeX (fixed
//! words escaped, mathematics through the whitelist typesetter, data escaped) and as Markdown.

use crate::{escape_markdown, tex, Lang};
use cagd_contract::Message;
use cagd_words::{MathPart, Phrase, Piece};

/// A sentence rendered: plain text, and LaTeX for text mode (its mathematics in `$...$`).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Sentence {
    /// Plain text.
    pub text: String,
    /// LaTeX, in text mode.
    pub latex: String,
}

impl Sentence {
    /// Text that is data (a value of a problem, never read as words) as a sentence: as it is,
    /// its math-looking words typeset in LaTeX.
    pub fn data(text: &str) -> Sentence {
        Sentence {
            text: text.to_string(),
            latex: tex::words(text),
        }
    }

    /// The sentence for Markdown: its text shown as written ([`escape_markdown`]).
    pub fn markdown(&self) -> String {
        escape_markdown(&self.text)
    }

    /// This sentence, a space, and `other` after it.
    pub fn then(self, other: &Sentence) -> Sentence {
        Sentence {
            text: format!("{} {}", self.text, other.text),
            latex: format!("{} {}", self.latex, other.latex),
        }
    }
}

/// A message of the engine in `lang`, as text and as LaTeX.
pub fn message(m: &Message, lang: Lang) -> Sentence {
    phrase(&cagd_words::Message::phrase(m, lang))
}

/// A message of the engine in `lang` on one line, its line feeds as spaces (an error, one
/// line as the engine's `Display` writes it).
pub fn message_line(m: &Message, lang: Lang) -> Sentence {
    let s = phrase(&cagd_words::Message::phrase(m, lang));
    Sentence {
        text: s.text.replace('\n', " "),
        latex: s.latex.replace('\n', " "),
    }
}

/// A typed sentence of the keys or of a front end in `lang`, as text and as LaTeX.
pub fn said(m: &dyn cagd_words::Message, lang: Lang) -> Sentence {
    phrase(&m.phrase(lang))
}

/// A phrase as text and as LaTeX.
pub fn phrase(p: &Phrase) -> Sentence {
    Sentence {
        text: p.text(),
        latex: latex(p),
    }
}

/// A phrase in LaTeX's text mode: words and data escaped (data that looks like mathematics
/// typeset a word at a time), mathematics in `$...$`.
pub fn latex(p: &Phrase) -> String {
    latex_with(p, &tex::words)
}

/// A phrase in LaTeX's text mode with its data in text written by `data` (an identifier in
/// typewriter: a flag of the command line).
pub fn latex_with(p: &Phrase, data: &dyn Fn(&str) -> String) -> String {
    latex_pieces(p, &tex::text, data)
}

/// A phrase in LaTeX's text mode with its fixed words written by `words` and its data by
/// `data`, its mathematics in `$...$`.
pub fn latex_pieces(
    p: &Phrase,
    words: &dyn Fn(&str) -> String,
    data: &dyn Fn(&str) -> String,
) -> String {
    let mut out = String::new();
    for piece in p.pieces() {
        match piece {
            Piece::Words(w) => out += &words(w),
            Piece::Data(d) => out += &data(d),
            Piece::Math(parts) => {
                let m: String = parts
                    .iter()
                    .map(|p| match p {
                        MathPart::Fixed(f) => *f,
                        MathPart::Data(d) => d.as_str(),
                    })
                    .collect();
                out += &format!("${}$", tex::math(&m));
            }
            Piece::Phrase(p) => out += &latex_pieces(p, words, data),
        }
    }
    out
}
