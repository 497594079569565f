//! Where an example is in the notes, as a reader finds it: "Tema 6, §5 (ec. 19)", "Chapter 6,
//! §5 (eq. 19)", "Transparencias del tema 6, Semiesfera", never the notes' file names.
//!
//! A fixture says where it comes from in `source` (`"000_4f266b7df5f64f70.txt §5"`, several
//! places joined by `;`) and `equation` (`"(19)"`, `"(21)-(23)"`); [`Source::of`] reads them
//! once into a [`Source`], worded per language by [`Source::words`]. The files are those of
//! the notes' README: `002_…` is chapter 5, `000_…` chapter 6, `001_…` the slides of chapter
//! 6, `003_…` and `004_…` excerpts of chapter 6.

use crate::Lang;
use cagd_contract::Meta;

/// A document of the notes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Document {
    /// A chapter of the notes (5, *Superficies*; 6, *Generación de superficies*).
    Chapter(u8),
    /// The slides of a chapter (6).
    Slides(u8),
    /// An excerpt of a chapter (6: revolution; ruled).
    Excerpt(u8),
}

impl Document {
    /// The document of a file of the notes, by the number that starts its name.
    fn of_file(file: &str) -> Option<Document> {
        match file.get(..4)? {
            "002_" => Some(Document::Chapter(5)),
            "000_" => Some(Document::Chapter(6)),
            "001_" => Some(Document::Slides(6)),
            "003_" | "004_" => Some(Document::Excerpt(6)),
            _ => None,
        }
    }

    fn words(self, lang: Lang) -> String {
        match (self, lang) {
            (Document::Chapter(n), Lang::Es) => format!("Tema {n}"),
            (Document::Chapter(n), Lang::En) => format!("Chapter {n}"),
            (Document::Slides(n), Lang::Es) => format!("Transparencias del tema {n}"),
            (Document::Slides(n), Lang::En) => format!("Slides of chapter {n}"),
            (Document::Excerpt(n), Lang::Es) => format!("Extracto del tema {n}"),
            (Document::Excerpt(n), Lang::En) => format!("Excerpt of chapter {n}"),
        }
    }
}

/// One place in the notes: a document, a section, and the notes' words for it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Place {
    /// A place in a document of the notes.
    Notes {
        /// The document.
        document: Document,
        /// Its section (`§5`).
        section: Option<u32>,
        /// The notes' heading or words for the place (`Semiesfera`, `elevación del bigrado`).
        detail: Option<String>,
        /// An equation of the document named in the place (`(18)`).
        equation: Option<String>,
    },
    /// A place outside the notes, as the problem writes it (data, shown as written).
    Other(String),
}

impl Place {
    /// A place as a fixture writes it: `<file>.txt §5 (words)`, `<file>.txt Words`,
    /// `<file>.txt (18)`; anything else is a place outside the notes.
    fn of(written: &str) -> Place {
        let written = written.trim();
        let Some((file, rest)) = written.split_once(".txt") else {
            return Place::Other(written.to_string());
        };
        let Some(document) = Document::of_file(file) else {
            return Place::Other(written.to_string());
        };
        let mut rest = rest.trim();
        let mut section = None;
        if let Some(after) = rest.strip_prefix('§') {
            let digits: String = after.chars().take_while(char::is_ascii_digit).collect();
            section = digits.parse().ok();
            rest = after[digits.len()..].trim();
        }
        let inner = rest
            .strip_prefix('(')
            .and_then(|r| r.strip_suffix(')'))
            .unwrap_or(rest)
            .trim();
        let (detail, equation) = match inner {
            "" => (None, None),
            e if e.chars().all(|c| c.is_ascii_digit()) => (None, Some(e.to_string())),
            d => (Some(d.to_string()), None),
        };
        Place::Notes {
            document,
            section,
            detail,
            equation,
        }
    }

    fn words(&self, lang: Lang) -> String {
        match self {
            Place::Other(s) => s.clone(),
            Place::Notes {
                document,
                section,
                detail,
                equation,
            } => {
                let mut out = document.words(lang);
                if let Some(s) = section {
                    out += &format!(", §{s}");
                }
                if let Some(d) = detail {
                    out += &format!(", {d}");
                }
                if let Some(e) = equation {
                    out += &format!(", {}", equation_words(e, lang));
                }
                out
            }
        }
    }
}

/// Where an example is in the notes: its places and the notes' equations it uses.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Source {
    /// The places, in the order written.
    pub places: Vec<Place>,
    /// The equations (`19`, `21-23`), without their parentheses.
    pub equation: Option<String>,
}

impl Source {
    /// The source of a problem from its fixture's `source` and `equation`.
    pub fn of(meta: &Meta) -> Source {
        let written = meta.source.as_deref().unwrap_or_default();
        let places: Vec<Place> = written
            .split(';')
            .filter(|p| !p.trim().is_empty())
            .map(Place::of)
            .collect();
        // several places of the notes joined by `;`; anything else is shown as written
        let places = match places.iter().all(|p| matches!(p, Place::Notes { .. })) {
            true => places,
            false => vec![Place::Other(written.trim().to_string())],
        };
        let equation = meta
            .equation
            .as_deref()
            .map(|e| e.replace(['(', ')'], "").trim().to_string())
            .filter(|e| !e.is_empty());
        Source { places, equation }
    }

    /// Whether the problem says nothing of where it comes from.
    pub fn is_empty(&self) -> bool {
        self.places.is_empty() && self.equation.is_none()
    }

    /// The document of the notes the source names first (the order of a key of the notes'
    /// examples), if any.
    pub fn document(&self) -> Option<Document> {
        self.places.iter().find_map(|p| match p {
            Place::Notes { document, .. } => Some(*document),
            Place::Other(_) => None,
        })
    }

    /// The source in words: `Tema 6, §5 (ec. 19)`, `Chapter 6, §5 (eq. 19)`; an example beyond
    /// the notes that uses an equation of theirs: `los apuntes, ec. 8`.
    ///
    /// ```
    /// use cagd_contract::Meta;
    /// use cagd_keys::{Lang, Source};
    /// let meta = Meta {
    ///     source: Some("000_4f266b7df5f64f70.txt §5".into()),
    ///     equation: Some("(19)".into()),
    ///     ..Meta::default()
    /// };
    /// assert_eq!(Source::of(&meta).words(Lang::Es), "Tema 6, §5 (ec. 19)");
    /// assert_eq!(Source::of(&meta).words(Lang::En), "Chapter 6, §5 (eq. 19)");
    /// ```
    pub fn words(&self, lang: Lang) -> String {
        let places: Vec<String> = self.places.iter().map(|p| p.words(lang)).collect();
        let places = places.join("; ");
        match (&self.equation, places.is_empty()) {
            (None, _) => places,
            (Some(e), true) => match lang {
                Lang::Es => format!("los apuntes, {}", equation_words(e, lang)),
                Lang::En => format!("the notes, {}", equation_words(e, lang)),
            },
            (Some(e), false) => format!("{places} ({})", equation_words(e, lang)),
        }
    }
}

/// An equation number or range in words: `ec. 19`, `ecs. 21-23`; `eq. 19`, `eqs. 21-23`.
fn equation_words(e: &str, lang: Lang) -> String {
    let many = e.contains(['-', ',']);
    let word = match (lang, many) {
        (Lang::Es, false) => "ec.",
        (Lang::Es, true) => "ecs.",
        (Lang::En, false) => "eq.",
        (Lang::En, true) => "eqs.",
    };
    format!("{word} {e}")
}
