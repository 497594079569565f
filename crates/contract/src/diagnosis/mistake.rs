//! A mistake of the catalogue ([`Mistake`]): its family and which one.

use super::catalogue::{Catalogued, Family, MistakeFormula, NotesPlace};
use super::{
    CircleMistake, ContinuityMistake, CoonsMistake, DerivativeMistake, ElevateMistake,
    EvaluateMistake, InsertKnotMistake, InterpolateMistake, NormalMistake, RevolutionMistake,
    RuledMistake, SubdivideMistake, TranslationalMistake,
};
use cagd_words::{Lang, Message, Phrase};

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
