//! A student's answer diagnosed: the catalogue of common mistakes ([`Mistake`], one enum per
//! operation family, each worded in English and Spanish beside its definition, with the
//! formula used instead of the notes' one and the section it violates), and the report on an
//! answer ([`Assessment`]: every entry right or wrong, a score, and the mistakes whose exact
//! answer matches the student's). The computations of the catalogue are cagd-diagnose's; this
//! module holds the inert types every output (keys, JSON, Python) reads.

mod assessment;
mod circle;
mod continuity;
mod coons;
mod derivative;
mod elevate;
mod entry;
mod evaluate;
mod insert_knot;
mod interpolate;
mod normal;
mod revolution;
mod ruled;
mod subdivide;
mod translational;

pub use assessment::{Assessed, Assessment, Diagnosis, Mark};
pub use circle::CircleMistake;
pub use continuity::ContinuityMistake;
pub use coons::CoonsMistake;
pub use derivative::DerivativeMistake;
pub use elevate::ElevateMistake;
pub use entry::{marks, same_knots, Entry};
pub use evaluate::EvaluateMistake;
pub use insert_knot::InsertKnotMistake;
pub use interpolate::InterpolateMistake;
pub use normal::NormalMistake;
pub use revolution::RevolutionMistake;
pub use ruled::RuledMistake;
pub use subdivide::SubdivideMistake;
pub use translational::TranslationalMistake;

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
    /// The curve chapters (1-4), not in the notes: the standard reference (`Farin, §5.1`,
    /// `The NURBS Book, §5.2`).
    Curves {
        /// The book and section.
        reference: &'static str,
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
            NotesPlace::Curves { reference } => said(
                lang,
                "the curve chapters (‹›)",
                "los temas de curvas (‹›)",
                [reference.into()],
            ),
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
            Family::InsertKnot => said(lang, "knot insertion", "inserción de nodos", []),
            Family::Derivative => said(
                lang,
                "derivatives and twists",
                "derivadas y vectores de torsión",
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

/// A mistake of the catalogue: its family and which one.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Mistake {
    /// De Casteljau evaluation.
    Evaluate(EvaluateMistake),
    /// Degree elevation.
    Elevate(ElevateMistake),
    /// Restriction and subdivision.
    Subdivide(SubdivideMistake),
    /// Knot insertion.
    InsertKnot(InsertKnotMistake),
    /// Derivatives and twists.
    Derivative(DerivativeMistake),
    /// Normals.
    Normal(NormalMistake),
    /// C^r joins.
    Continuity(ContinuityMistake),
    /// Ruled surfaces.
    Ruled(RuledMistake),
    /// Translational surfaces.
    Translational(TranslationalMistake),
    /// Coons surfaces.
    Coons(CoonsMistake),
    /// Surfaces of revolution.
    Revolution(RevolutionMistake),
    /// Circles and arcs.
    Circle(CircleMistake),
    /// Interpolation.
    Interpolate(InterpolateMistake),
}

/// Calls `$m` with the family's mistake (every arm of [`Mistake`], one expression).
macro_rules! each_family {
    ($self:expr, $m:ident => $e:expr) => {
        match $self {
            Mistake::Evaluate($m) => $e,
            Mistake::Elevate($m) => $e,
            Mistake::Subdivide($m) => $e,
            Mistake::InsertKnot($m) => $e,
            Mistake::Derivative($m) => $e,
            Mistake::Normal($m) => $e,
            Mistake::Continuity($m) => $e,
            Mistake::Ruled($m) => $e,
            Mistake::Translational($m) => $e,
            Mistake::Coons($m) => $e,
            Mistake::Revolution($m) => $e,
            Mistake::Circle($m) => $e,
            Mistake::Interpolate($m) => $e,
        }
    };
}

impl Mistake {
    /// Every mistake of the catalogue, family by family in the order of [`Family`].
    pub fn all() -> Vec<Mistake> {
        let mut out = Vec::new();
        out.extend(EvaluateMistake::ALL.iter().copied().map(Mistake::Evaluate));
        out.extend(ElevateMistake::ALL.iter().copied().map(Mistake::Elevate));
        out.extend(
            SubdivideMistake::ALL
                .iter()
                .copied()
                .map(Mistake::Subdivide),
        );
        out.extend(
            InsertKnotMistake::ALL
                .iter()
                .copied()
                .map(Mistake::InsertKnot),
        );
        out.extend(
            DerivativeMistake::ALL
                .iter()
                .copied()
                .map(Mistake::Derivative),
        );
        out.extend(NormalMistake::ALL.iter().copied().map(Mistake::Normal));
        out.extend(
            ContinuityMistake::ALL
                .iter()
                .copied()
                .map(Mistake::Continuity),
        );
        out.extend(RuledMistake::ALL.iter().copied().map(Mistake::Ruled));
        out.extend(
            TranslationalMistake::ALL
                .iter()
                .copied()
                .map(Mistake::Translational),
        );
        out.extend(CoonsMistake::ALL.iter().copied().map(Mistake::Coons));
        out.extend(
            RevolutionMistake::ALL
                .iter()
                .copied()
                .map(Mistake::Revolution),
        );
        out.extend(CircleMistake::ALL.iter().copied().map(Mistake::Circle));
        out.extend(
            InterpolateMistake::ALL
                .iter()
                .copied()
                .map(Mistake::Interpolate),
        );
        out
    }

    /// The mistake of identifier `id` (`coons.cd_added`).
    pub fn from_id(id: &str) -> Option<Mistake> {
        Mistake::all().into_iter().find(|m| m.id() == id)
    }

    /// Its family.
    pub fn family(self) -> Family {
        match self {
            Mistake::Evaluate(_) => Family::Evaluate,
            Mistake::Elevate(_) => Family::Elevate,
            Mistake::Subdivide(_) => Family::Subdivide,
            Mistake::InsertKnot(_) => Family::InsertKnot,
            Mistake::Derivative(_) => Family::Derivative,
            Mistake::Normal(_) => Family::Normal,
            Mistake::Continuity(_) => Family::Continuity,
            Mistake::Ruled(_) => Family::Ruled,
            Mistake::Translational(_) => Family::Translational,
            Mistake::Coons(_) => Family::Coons,
            Mistake::Revolution(_) => Family::Revolution,
            Mistake::Circle(_) => Family::Circle,
            Mistake::Interpolate(_) => Family::Interpolate,
        }
    }
}

impl Message for Mistake {
    fn phrase(&self, lang: Lang) -> Phrase {
        each_family!(self, m => m.phrase(lang))
    }
}

impl Catalogued for Mistake {
    fn id(&self) -> &'static str {
        each_family!(self, m => m.id())
    }
    fn place(&self) -> NotesPlace {
        each_family!(self, m => m.place())
    }
    fn right(&self) -> MistakeFormula {
        each_family!(self, m => m.right())
    }
    fn used(&self) -> MistakeFormula {
        each_family!(self, m => m.used())
    }
}

impl serde::Serialize for Mistake {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.id())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashSet;

    #[test]
    fn ids_are_unique_and_name_their_family() {
        let mut seen = HashSet::new();
        for m in Mistake::all() {
            assert!(seen.insert(m.id()), "{} twice", m.id());
            assert_eq!(Mistake::from_id(m.id()), Some(m));
            assert!(m.id().contains('.'), "{}", m.id());
        }
    }

    #[test]
    fn every_mistake_in_both_languages() {
        for m in Mistake::all() {
            cagd_words::check_both(&m).unwrap();
            cagd_words::check_both(&m.place()).unwrap();
            assert_ne!(m.right(), m.used(), "{}", m.id());
        }
        for f in <Family as strum::IntoEnumIterator>::iter() {
            cagd_words::check_both(&f).unwrap();
        }
    }
}
