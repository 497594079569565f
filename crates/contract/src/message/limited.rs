//! What a limit of a run refuses to build: the subject of the limit sentences
//! ([`super::fitting::Fitting::TooManyPoints`], [`super::fitting::Fitting::DegreeAbove`]).

use cagd_words::{said, Lang, Message, Phrase};

/// What a limit refuses to build.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum Limited {
    /// A curve's degree elevated.
    ElevatingDegree {
        /// Its degree.
        from: usize,
        /// By how much.
        by: usize,
    },
    /// A patch's bidegree elevated.
    ElevatingBidegree {
        /// Its bidegree.
        m: usize,
        /// Its bidegree in v.
        n: usize,
        /// By how much in u.
        r: usize,
        /// By how much in v.
        s: usize,
    },
    /// The patch elevated.
    ElevatedPatch {
        /// Its bidegree in u.
        m: usize,
        /// Its bidegree in v.
        n: usize,
    },
    /// The first patch of a join, elevated.
    FirstPatchElevated,
    /// The second patch of a join, elevated.
    SecondPatchElevated,
    /// A B-spline surface with a knot inserted.
    SurfaceKnotInserted,
    /// The curve elevated.
    #[default]
    ElevatedCurve,
    /// A B-spline curve with a knot inserted.
    CurveKnotInserted,
    /// A circle.
    Circle,
    /// A circular arc.
    Arc,
    /// The graph of a function.
    Graph {
        /// Its bidegree in u.
        m: usize,
        /// Its bidegree in v.
        n: usize,
    },
    /// A B-spline's Bézier pieces.
    BezierPieces,
    /// A surface of revolution.
    Revolution,
}

impl Message for Limited {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Limited::ElevatingDegree { from, by } => said(
                lang,
                "elevating degree ‹› by ‹›",
                "elevar el grado ‹› en ‹›",
                [from.into(), by.into()],
            ),
            Limited::ElevatingBidegree { m, n, r, s } => said(
                lang,
                "elevating bidegree (‹›, ‹›) by (‹›, ‹›)",
                "elevar el bigrado (‹›, ‹›) en (‹›, ‹›)",
                [m.into(), n.into(), r.into(), s.into()],
            ),
            Limited::ElevatedPatch { m, n } => said(
                lang,
                "the elevated patch of bidegree (‹›, ‹›)",
                "la superficie elevada de bigrado (‹›, ‹›)",
                [m.into(), n.into()],
            ),
            Limited::FirstPatchElevated => said(
                lang,
                "the first patch elevated",
                "la primera superficie elevada",
                [],
            ),
            Limited::SecondPatchElevated => said(
                lang,
                "the second patch elevated",
                "la segunda superficie elevada",
                [],
            ),
            Limited::SurfaceKnotInserted => said(
                lang,
                "the surface with the knot inserted",
                "la superficie con el nudo insertado",
                [],
            ),
            Limited::ElevatedCurve => said(lang, "the elevated curve", "la curva elevada", []),
            Limited::CurveKnotInserted => said(
                lang,
                "the curve with the knot inserted",
                "la curva con el nudo insertado",
                [],
            ),
            Limited::Circle => said(lang, "the circle", "la circunferencia", []),
            Limited::Arc => said(lang, "the arc", "el arco", []),
            Limited::Graph { m, n } => said(
                lang,
                "the graph of bidegree (‹›, ‹›)",
                "la gráfica de bigrado (‹›, ‹›)",
                [m.into(), n.into()],
            ),
            Limited::Revolution => said(
                lang,
                "the surface of revolution",
                "la superficie de revolución",
                [],
            ),
            Limited::BezierPieces => said(lang, "the Bézier pieces", "los trozos de Bézier", []),
        }
    }
}

cagd_words::display_english!(Limited);

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_variant_in_both_languages() {
        for m in Limited::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()));
        }
    }
}
