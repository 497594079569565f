//! A typed message in a key: its [`Phrase`] in the language asked, as text and as LaTeX
//! (fixed words escaped, mathematics through the whitelist typesetter, data escaped).

use crate::{catalogue, tex, Lang, Sentence};
use cagd_problem::Message;
use cagd_words::{MathPart, Phrase, Piece};

/// A message of the engine in `lang`, as text and as LaTeX.
pub fn message(m: &Message, lang: Lang) -> Sentence {
    if let Some(english) = m.untyped() {
        return catalogue::sentence(&english, lang);
    }
    phrase(&cagd_words::Message::phrase(m, lang))
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
    let mut out = String::new();
    for piece in p.pieces() {
        match piece {
            Piece::Words(w) => out += &tex::text(w),
            Piece::Data(d) => out += &tex::words(d),
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
            Piece::Phrase(p) => out += &latex(p),
        }
    }
    out
}
