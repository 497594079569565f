//! The engine's sentences as values.
//!
//! Every error, remark, mismatch and verdict sentence of cagd-exact is a value of a typed enum
//! (its fields: the role of the input, the numbers, the limit) that implements [`Message`]:
//! an exhaustive match beside the enum's definition gives each variant its words in English
//! and in the notes' Spanish, side by side ([`said`]), so a new variant without its Spanish
//! does not compile. The words come from a fixed template; what the input or the computation
//! supplies (a number, a name, a point, an inner message) fills its holes and is never read
//! back for meaning.
//!
//! A template's notation (the same as the worked steps'):
//! - `‹›` a hole for data: a number, a point, a key, as text;
//! - `«»` a hole for an inner sentence ([`Phrase`]), rendered in the same language;
//! - `$...$` mathematics: dropped marks in text, typeset by a key writer in LaTeX (a data hole
//!   inside it is typeset as mathematics too).
//!
//! ```
//! use cagd_words::{said, Lang, Message, Phrase};
//! enum E { Degree { found: usize } }
//! impl Message for E {
//!     fn phrase(&self, lang: Lang) -> Phrase {
//!         match self {
//!             E::Degree { found } => said(
//!                 lang,
//!                 "the degree $n$ is ‹›",
//!                 "el grado $n$ es ‹›",
//!                 [found.into()],
//!             ),
//!         }
//!     }
//! }
//! assert_eq!(E::Degree { found: 3 }.phrase(Lang::Es).text(), "el grado n es 3");
//! assert_eq!(E::Degree { found: 3 }.english(), "the degree n is 3");
//! ```

use std::fmt;

/// The language of a key or a message.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum Lang {
    /// English.
    #[default]
    En,
    /// Spanish, with the notes' vocabulary (malla de control, pesos, bigrado, nudos).
    Es,
}

impl Lang {
    /// Reads `en` or `es`.
    pub fn parse(s: &str) -> Option<Lang> {
        match s {
            "en" => Some(Lang::En),
            "es" => Some(Lang::Es),
            _ => None,
        }
    }

    /// Both languages, in order.
    pub const ALL: [Lang; 2] = [Lang::En, Lang::Es];
}

/// A sentence with a meaning of its own: an error, a remark, a mismatch, a verdict.
pub trait Message {
    /// Its words in `lang`.
    fn phrase(&self, lang: Lang) -> Phrase;

    /// Its English text (what `Display` writes, and the JSON).
    fn english(&self) -> String {
        self.phrase(Lang::En).text()
    }
}

impl<M: Message + ?Sized> Message for Box<M> {
    fn phrase(&self, lang: Lang) -> Phrase {
        (**self).phrase(lang)
    }
}

/// What fills a hole of a template.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Hole {
    /// Data, as text: a number, a point, a key (`‹›`).
    Data(String),
    /// An inner sentence (`«»`).
    Phrase(Phrase),
}

impl<T: fmt::Display + ?Sized> From<&T> for Hole {
    fn from(x: &T) -> Hole {
        Hole::Data(x.to_string())
    }
}

impl From<Phrase> for Hole {
    fn from(p: Phrase) -> Hole {
        Hole::Phrase(p)
    }
}

/// A piece of a phrase.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Piece {
    /// Fixed words of a template (never data).
    Words(&'static str),
    /// Fixed mathematics of a template, between its `$` marks, with the data holes inside it
    /// in order: `Math(["c_{1,", "}"], ["2"])` is `$c_{1,‹›}$` with 2 in the hole.
    Math(Vec<MathPart>),
    /// Data in text: a number, a point, a key.
    Data(String),
    /// An inner sentence.
    Phrase(Phrase),
}

/// A part of a mathematical span.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum MathPart {
    /// Fixed mathematics of a template.
    Fixed(&'static str),
    /// Data inside the mathematics (a number, a point).
    Data(String),
}

/// A sentence rendered in one language: fixed words, mathematics and data, in order. Its
/// [`Phrase::text`] is the plain text; a key writer renders [`Phrase::pieces`] in LaTeX or
/// Markdown, escaping the data.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Phrase {
    pieces: Vec<Piece>,
}

impl Phrase {
    /// The pieces, in order.
    pub fn pieces(&self) -> &[Piece] {
        &self.pieces
    }

    /// A phrase of data only (a sentence the engine does not word: serde's own).
    pub fn data(s: impl Into<String>) -> Phrase {
        Phrase {
            pieces: vec![Piece::Data(s.into())],
        }
    }

    /// Fills `template` (see the crate's notation) with `holes`, in order. A hole without a
    /// value is left empty, a value without a hole is dropped (the test of every message
    /// catches both: [`holes_agree`]).
    pub fn fill(template: &'static str, holes: impl IntoIterator<Item = Hole>) -> Phrase {
        let mut holes = holes.into_iter();
        let mut pieces = Vec::new();
        let mut math: Option<Vec<MathPart>> = None;
        for part in parts(template) {
            match part {
                Part::Lit(l) => {
                    for (i, piece) in l.split('$').enumerate() {
                        if i > 0 {
                            math = match math.take() {
                                Some(m) => {
                                    pieces.push(Piece::Math(m));
                                    None
                                }
                                None => Some(Vec::new()),
                            };
                        }
                        if piece.is_empty() {
                            continue;
                        }
                        match &mut math {
                            Some(m) => m.push(MathPart::Fixed(piece)),
                            None => pieces.push(Piece::Words(piece)),
                        }
                    }
                }
                Part::Hole | Part::Sentence => {
                    let h = holes.next();
                    match (h, &mut math) {
                        (Some(Hole::Data(d)), Some(m)) => m.push(MathPart::Data(d)),
                        (Some(Hole::Phrase(p)), Some(m)) => m.push(MathPart::Data(p.text())),
                        (Some(Hole::Data(d)), None) => pieces.push(Piece::Data(d)),
                        (Some(Hole::Phrase(p)), None) => pieces.push(Piece::Phrase(p)),
                        (None, _) => {}
                    }
                }
            }
        }
        if let Some(m) = math {
            pieces.push(Piece::Math(m));
        }
        Phrase { pieces }
    }

    /// Plain text: the `$` marks dropped, data as it is.
    pub fn text(&self) -> String {
        let mut s = String::new();
        self.write_text(&mut s);
        s
    }

    fn write_text(&self, s: &mut String) {
        for p in &self.pieces {
            match p {
                Piece::Words(w) => s.push_str(w),
                Piece::Data(d) => s.push_str(d),
                Piece::Math(m) => {
                    for part in m {
                        match part {
                            MathPart::Fixed(f) => s.push_str(f),
                            MathPart::Data(d) => s.push_str(d),
                        }
                    }
                }
                Piece::Phrase(p) => p.write_text(s),
            }
        }
    }

    /// Appends another phrase.
    pub fn then(mut self, other: Phrase) -> Phrase {
        self.pieces.extend(other.pieces);
        self
    }

    /// The fixed words of the phrase and of its inner phrases (mathematics and data left
    /// out): what a test reads for English left in Spanish.
    pub fn words(&self) -> Vec<&'static str> {
        let mut out = Vec::new();
        for p in &self.pieces {
            match p {
                Piece::Words(w) => out.push(*w),
                Piece::Phrase(p) => out.extend(p.words()),
                Piece::Math(_) | Piece::Data(_) => {}
            }
        }
        out
    }
}

/// A message's words: `en` or `es` by `lang`, filled with `holes` ([`Phrase::fill`]). The two
/// templates sit side by side in the message's match, one arm per variant.
pub fn said<const N: usize>(
    lang: Lang,
    en: &'static str,
    es: &'static str,
    holes: [Hole; N],
) -> Phrase {
    // the test of every message (built in debug) stops on templates that disagree
    debug_assert!(holes_agree(en, es), "holes differ: {en} / {es}");
    debug_assert_eq!(holes_of(en).len(), N, "{en}");
    let template = match lang {
        Lang::En => en,
        Lang::Es => es,
    };
    Phrase::fill(template, holes)
}

/// `Display` for a typed message: its English text.
///
/// ```
/// # use cagd_words::{said, Lang, Message, Phrase};
/// struct Empty;
/// impl Message for Empty {
///     fn phrase(&self, lang: Lang) -> Phrase { said(lang, "empty", "vacío", []) }
/// }
/// cagd_words::display_english!(Empty);
/// assert_eq!(Empty.to_string(), "empty");
/// ```
#[macro_export]
macro_rules! display_english {
    ($($t:ty),+ $(,)?) => {$(
        impl ::std::fmt::Display for $t {
            fn fmt(&self, f: &mut ::std::fmt::Formatter<'_>) -> ::std::fmt::Result {
                f.write_str(&$crate::Message::english(self))
            }
        }
    )+};
}

/// The holes of a template, in order: `true` for an inner sentence (`«»`).
pub fn holes_of(template: &str) -> Vec<bool> {
    parts(template)
        .into_iter()
        .filter_map(|p| match p {
            Part::Lit(_) => None,
            Part::Hole => Some(false),
            Part::Sentence => Some(true),
        })
        .collect()
}

/// Whether two templates (a message's English and Spanish) have the same holes in the same
/// order, and each closes every `$` it opens.
pub fn holes_agree(en: &str, es: &str) -> bool {
    holes_of(en) == holes_of(es)
        && en.matches('$').count() % 2 == 0
        && es.matches('$').count() % 2 == 0
}

/// Common English words that have no place in a Spanish sentence (none of them is a Spanish
/// word): what [`english_in`] looks for.
pub const ENGLISH: &[&str] = &[
    "the",
    "and",
    "of",
    "is",
    "not",
    "with",
    "for",
    "to",
    "but",
    "has",
    "have",
    "are",
    "was",
    "be",
    "in",
    "at",
    "on",
    "or",
    "an",
    "it",
    "its",
    "than",
    "from",
    "by",
    "this",
    "that",
    "which",
    "only",
    "one",
    "two",
    "each",
    "every",
    "give",
    "given",
    "where",
    "when",
    "there",
    "here",
    "above",
    "below",
    "between",
    "into",
    "as",
    "after",
    "before",
    "should",
    "cannot",
    "can",
    "does",
    "do",
    "more",
    "less",
    "same",
    "other",
    "first",
    "last",
    "found",
    "expected",
    "needs",
    "need",
    "must",
    "point",
    "points",
    "curve",
    "curves",
    "surface",
    "surfaces",
    "degree",
    "weight",
    "weights",
    "knot",
    "knots",
    "value",
    "values",
    "number",
    "numbers",
    "row",
    "rows",
    "column",
    "columns",
    "mesh",
    "parameter",
    "parameters",
    "input",
    "field",
    "list",
    "empty",
    "zero",
    "vanishes",
    "letters",
    "intervals",
    "geometric",
    "kind",
    "shape",
    "normals",
    "ellipse",
    "parabola",
    "hyperbola",
    "pieces",
    "vertices",
    "domain",
    "sign",
    "zeros",
    "end",
    "raise",
    "limit",
    "operation",
    "expression",
    "write",
    "written",
    "read",
    "would",
    "could",
    "were",
    "been",
    "about",
    "gives",
    "got",
    "then",
    "too",
    "many",
    "least",
    "most",
    "exactly",
    "because",
    "so",
    "keys",
    "key",
    "unknown",
    "missing",
    "invalid",
    "type",
    "string",
    "object",
    "array",
    "null",
    "true",
    "false",
    "line",
];

/// More English words that have no place in a Spanish answer key, which a key's text is
/// scanned for besides [`ENGLISH`] (the keys' test of Spanish keys). Not in [`ENGLISH`]:
/// a message's template may name an identifier made of them (`closed_form`, `cagd-exact`,
/// `circle_four_arcs_rational`), which [`english_in`] would read as words.
pub const ENGLISH_IN_KEYS: &[&str] = &[
    "records",
    "named",
    "computed",
    "bidegree",
    "second",
    "fails",
    "failed",
    "problem",
    "problems",
    "yes",
    "matches",
    "match",
    "notes",
    "print",
    "exact",
    "result",
    "steps",
    "verdict",
    "source",
    "note",
    "polygon",
    "patch",
    "patches",
    "closed",
    "form",
    "derivative",
    "circle",
    "radius",
    "sweep",
    "start",
    "arcs",
    "interval",
    "direction",
    "border",
    "corners",
    "order",
    "continuity",
    "smoothness",
    "developable",
    "planar",
    "cell",
    "infinite",
    "data",
    "basis",
    "elevated",
    "inserted",
    "elevation",
    "digits",
    "did",
    "you",
    "mean",
    "takes",
    "integer",
    "coordinates",
    "length",
    "equal",
    "three",
    "four",
    "five",
    "answer",
    "answers",
    "correct",
    "wrong",
    "checked",
    "example",
    "examples",
    "erratum",
    "kept",
    "operations",
    "name",
    "ruled",
    "graph",
    "function",
    "restriction",
    "evaluation",
    "approximation",
    "interpolation",
    "squares",
    "translational",
    "revolution",
    "insertion",
    "since",
    "while",
    "if",
    "also",
    "triangles",
];

/// The English words left in the fixed words of `p` (a Spanish phrase), outside `` `keys` ``
/// and quotes: empty when the phrase is Spanish throughout.
pub fn english_in(p: &Phrase) -> Vec<String> {
    let mut found = Vec::new();
    for w in p.words() {
        let mut plain = String::new();
        let mut quote: Option<char> = None;
        for c in w.chars() {
            match (quote, c) {
                (Some(q), c) if c == q => quote = None,
                (Some(_), _) => {}
                (None, '`' | '"') => quote = Some(c),
                (None, c) => plain.push(c),
            }
        }
        for word in plain
            .split(|c: char| !c.is_alphabetic())
            .filter(|w| !w.is_empty())
        {
            let word = word.to_lowercase();
            if ENGLISH.contains(&word.as_str()) && !found.contains(&word) {
                found.push(word);
            }
        }
    }
    found
}

/// The check of one message in both languages, for the test that enumerates every variant of
/// a message enum: its two templates agree on their holes (the phrase is built), neither is
/// empty or has a control character but the line feed in its fixed words, and its Spanish
/// has no English word.
/// `Err` says what is wrong, naming the variant by its English.
pub fn check_both(m: &dyn Message) -> Result<(), String> {
    let en = m.phrase(Lang::En);
    let es = m.phrase(Lang::Es);
    if en.text().trim().is_empty() || es.text().trim().is_empty() {
        return Err(format!(
            "an empty sentence: {:?} / {:?}",
            en.text(),
            es.text()
        ));
    }
    for p in [&en, &es] {
        // a line feed may end a line of a message of several lines (a list of topics)
        if p.words()
            .iter()
            .any(|w| w.chars().any(|c| c.is_control() && c != '\n'))
        {
            return Err(format!("a control character in {:?}", p.text()));
        }
    }
    let left = english_in(&es);
    if !left.is_empty() {
        return Err(format!(
            "English in Spanish ({}): {:?} (English: {:?})",
            left.join(", "),
            es.text(),
            en.text()
        ));
    }
    Ok(())
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Part<'a> {
    Lit(&'a str),
    Hole,
    Sentence,
}

fn parts(format: &str) -> Vec<Part<'_>> {
    let mut out = Vec::new();
    let mut rest = format;
    while let Some(i) = rest.find(['‹', '«']) {
        let (lit, tail) = rest.split_at(i);
        if !lit.is_empty() {
            out.push(Part::Lit(lit));
        }
        if let Some(t) = tail.strip_prefix("‹›") {
            out.push(Part::Hole);
            rest = t;
        } else if let Some(t) = tail.strip_prefix("«»") {
            out.push(Part::Sentence);
            rest = t;
        } else {
            // a lone mark is literal
            let n = tail.chars().next().map_or(1, char::len_utf8);
            let (mark, t) = tail.split_at(n);
            out.push(Part::Lit(mark));
            rest = t;
        }
    }
    if !rest.is_empty() {
        out.push(Part::Lit(rest));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn math_holds_its_data() {
        let p = Phrase::fill(
            "the point $c_{‹›}$ is ‹›",
            [(&2).into(), (&"(1, 2)").into()],
        );
        assert_eq!(p.text(), "the point c_{2} is (1, 2)");
        assert_eq!(
            p.pieces(),
            &[
                Piece::Words("the point "),
                Piece::Math(vec![
                    MathPart::Fixed("c_{"),
                    MathPart::Data("2".into()),
                    MathPart::Fixed("}")
                ]),
                Piece::Words(" is "),
                Piece::Data("(1, 2)".into()),
            ]
        );
    }

    #[test]
    fn an_inner_sentence() {
        let inner = Phrase::fill("división por cero", []);
        let p = said(
            Lang::Es,
            "at column ‹›: «»",
            "en la columna ‹›: «»",
            [(&3).into(), inner.into()],
        );
        assert_eq!(p.text(), "en la columna 3: división por cero");
        assert_eq!(p.words(), vec!["en la columna ", ": ", "división por cero"]);
    }

    #[test]
    fn holes_are_compared() {
        assert!(holes_agree("a ‹› b «»", "x ‹› y «»"));
        assert!(!holes_agree("a ‹› b «»", "x «» y ‹›"));
        assert!(!holes_agree("$a", "$a$"));
    }
}

#[cfg(test)]
mod every_variant {
    use super::*;
    use strum::IntoEnumIterator;

    /// The shape of every crate's test: each variant, reached by enumeration, in both
    /// languages.
    #[derive(strum::EnumIter)]
    enum Sample {
        Empty,
        Degree { found: usize, name: String },
    }

    impl Message for Sample {
        fn phrase(&self, lang: Lang) -> Phrase {
            match self {
                Sample::Empty => said(lang, "the polygon is empty", "el polígono está vacío", []),
                Sample::Degree { found, name } => said(
                    lang,
                    "`‹›` has degree ‹›",
                    "`‹›` tiene grado ‹›",
                    [name.into(), found.into()],
                ),
            }
        }
    }

    #[test]
    fn every_sample_in_both_languages() {
        for m in Sample::iter() {
            assert_eq!(check_both(&m), Ok(()));
        }
        struct Bad;
        impl Message for Bad {
            fn phrase(&self, lang: Lang) -> Phrase {
                said(lang, "the point", "the punto", [])
            }
        }
        assert!(check_both(&Bad).is_err());
    }
}
