//! A student's answer diagnosed: the catalogue of common mistakes ([`Mistake`], one enum per
//! operation family, each worded in English and Spanish beside its definition, with the
//! formula used instead of the notes' one and the section it violates), and the report on an
//! answer ([`Assessment`]: every entry right or wrong, a score, and the mistakes whose exact
//! answer matches the student's). The computations of the catalogue are cagd-diagnose's; this
//! module holds the inert types every output (keys, JSON, Python) reads.

mod assessment;
mod catalogue;
mod circle;
mod continuity;
mod coons;
mod derivative;
mod elevate;
mod entry;
mod evaluate;
mod insert_knot;
mod interpolate;
mod mistake;
mod normal;
mod revolution;
mod ruled;
mod subdivide;
mod translational;

pub use crate::value::expected::same_knots;
pub use assessment::{score, Assessed, Assessment, Diagnosis};
pub use catalogue::{Book, Catalogued, Family, MistakeFormula, NotesPlace};
pub use circle::CircleMistake;
pub use continuity::ContinuityMistake;
pub use coons::CoonsMistake;
pub use derivative::DerivativeMistake;
pub use elevate::ElevateMistake;
pub use entry::{marks, Entry, Mark};
pub use evaluate::EvaluateMistake;
pub use insert_knot::InsertKnotMistake;
pub use interpolate::InterpolateMistake;
pub use mistake::Mistake;
pub use normal::NormalMistake;
pub use revolution::RevolutionMistake;
pub use ruled::RuledMistake;
pub use subdivide::SubdivideMistake;
pub use translational::TranslationalMistake;
