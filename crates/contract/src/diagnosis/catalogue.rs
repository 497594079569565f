//! What every mistake of the catalogue says about itself ([`Catalogued`]), where in the notes
//! it is taught ([`NotesPlace`]), its formulas ([`MistakeFormula`]) and the operation
//! families ([`Family`]).

use cagd_words::{said, Lang, Message, Phrase};

/// Where the formula a mistake violates is taught: a chapter (Tema), section and equation
/// of the notes, worded "Tema 6, §5 (ec. 19)" / "Chapter 6, §5 (eq. 19)"; or, for the curve
/// chapters the notes lean on but do not include (chapters 1-4), the standard reference.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NotesPlace {
    /// A chapter of the notes.
    Notes {
        /// The chapter (tema) of the notes.
        chapter: u8,
        /// The section, `§n`.
        section: u8,
        /// The equation number, when the formula has one.
        equation: Option<&'static str>,
    },
    /// The curve chapters (1-4), not in the notes: the standard reference, a book and its
    /// section (`§5.1`).
    Curves {
        /// The book.
        book: Book,
        /// The section, `§5.2`.
        section: &'static str,
    },
}

impl Message for NotesPlace {
    fn phrase(&self, lang: Lang) -> Phrase {
        match *self {
            NotesPlace::Notes {
                chapter,
                section,
                equation: Some(e),
            } => said(
                lang,
                "Chapter ‹›, §‹› (eq. ‹›)",
                "Tema ‹›, §‹› (ec. ‹›)",
                [(&chapter).into(), (&section).into(), e.into()],
            ),
            NotesPlace::Notes {
                chapter,
                section,
                equation: None,
            } => said(
                lang,
                "Chapter ‹›, §‹›",
                "Tema ‹›, §‹›",
                [(&chapter).into(), (&section).into()],
            ),
            NotesPlace::Curves { book, section } => said(
                lang,
                "the curve chapters (‹›, ‹›)",
                "los temas de curvas (‹›, ‹›)",
                [book.phrase(lang).into(), section.into()],
            ),
        }
    }
}

/// A book the notes lean on for the curve chapters.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Book {
    /// Farin, *Curves and Surfaces for CAGD*.
    Farin,
    /// Piegl and Tiller, *The NURBS Book*.
    NurbsBook,
}

impl Message for Book {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Book::Farin => said(lang, "Farin", "Farin", []),
            Book::NurbsBook => said(lang, "The NURBS Book", "Piegl y Tiller", []),
        }
    }
}

/// A formula in plain text (text and Markdown keys) and in LaTeX (math mode, without
/// dollars): the engine's own constants, never a problem's text.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct MistakeFormula {
    /// Plain text: `c = c_c + c_d - c_cd`.
    pub text: &'static str,
    /// LaTeX (math mode): `\mathbf c = \mathbf c_c + \mathbf c_d - \mathbf c_{cd}`.
    pub tex: &'static str,
}

/// What every mistake of the catalogue says about itself: its identifier, the notes' place
/// it violates, the notes' formula and the one the student used instead. What the student
/// did is its [`Message`] (one sentence, English and Spanish).
pub trait Catalogued: Message {
    /// The identifier, `family.what` (`coons.cd_added`), stable: the JSON and the docs use it.
    fn id(&self) -> &'static str;
    /// The notes' section (and equation) the mistake violates.
    fn place(&self) -> NotesPlace;
    /// The notes' formula.
    fn right(&self) -> MistakeFormula;
    /// The formula the student used instead.
    fn used(&self) -> MistakeFormula;
}

/// The operation families of the catalogue: those whose answers students compute by hand.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, strum::EnumIter)]
pub enum Family {
    /// De Casteljau evaluation of curves and patches (rational ones too): `evaluate`.
    Evaluate,
    /// Degree elevation: `elevate`.
    Elevate,
    /// Restriction and subdivision: `restrict`, `subdivide`.
    Subdivide,
    /// Knot insertion: `insert_knot`.
    InsertKnot,
    /// Derivatives and twists: `derivative`.
    Derivative,
    /// Normals: `normal`.
    Normal,
    /// C^r joins: `continuity`, `curve_continuity`.
    Continuity,
    /// Ruled surfaces: `ruled`.
    Ruled,
    /// Translational surfaces: `translational`.
    Translational,
    /// Coons surfaces, every blending: `coons`.
    Coons,
    /// Surfaces of revolution: `revolution`.
    Revolution,
    /// Circles and arcs: `circle`.
    Circle,
    /// Interpolation: `interpolate`.
    Interpolate,
}

impl Message for Family {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Family::Evaluate => said(
                lang,
                "De Casteljau evaluation",
                "evaluación por el algoritmo de De Casteljau",
                [],
            ),
            Family::Elevate => said(lang, "degree elevation", "elevación de grado", []),
            Family::Subdivide => said(
                lang,
                "restriction and subdivision",
                "restricción y subdivisión",
                [],
            ),
            Family::InsertKnot => said(lang, "knot insertion", "inserción de nudos", []),
            Family::Derivative => said(
                lang,
                "derivatives and twists",
                "derivadas parciales y derivadas segundas cruzadas",
                [],
            ),
            Family::Normal => said(lang, "normal vectors", "vectores normales", []),
            Family::Continuity => said(lang, "C^r joins", "uniones C^r", []),
            Family::Ruled => said(lang, "ruled surfaces", "superficies regladas", []),
            Family::Translational => said(
                lang,
                "translational surfaces",
                "superficies de traslación",
                [],
            ),
            Family::Coons => said(lang, "Coons surfaces", "superficies de Coons", []),
            Family::Revolution => said(
                lang,
                "surfaces of revolution",
                "superficies de revolución",
                [],
            ),
            Family::Circle => said(lang, "circles and arcs", "circunferencias y arcos", []),
            Family::Interpolate => said(lang, "interpolation", "interpolación", []),
        }
    }
}
