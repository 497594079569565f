//! Mistakes in C^r joins of two patches (chapter 5, §6, eq. (21)-(23)) and of two curves
//! (the curve chapters): the border rows equal (21), the differences across the border
//! divided by the interval lengths equal (22), and for curves of degrees n and m the
//! derivatives n Δb_{n−1} = m Δc_0 at the joint.

use super::{Book, Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{said, Lang, Message, Phrase};

/// A mistake in C^r joins of two patches or two curves.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ContinuityMistake {
    /// The interval lengths Δu_0, Δu_1 of (22) ignored: the differences across the border
    /// compared as they are, Δ^{1,0}c_{m−1,j} = Δ^{1,0}c̃_{0,j}.
    LengthsIgnored,
    /// The interval lengths exchanged: Δ^{1,0}c_{m−1,j} / Δu_1 = Δ^{1,0}c̃_{0,j} / Δu_0.
    LengthsSwapped,
    /// Parallel differences taken for equal ones (the G^1 condition of curves for C^1):
    /// Δ^{1,0}c̃_{0,j} = λ_j Δ^{1,0}c_{m−1,j} with λ_j > 0 read as C^1; for two curves, the
    /// geometric order taken for the parametric one.
    ParallelTakenForC1,
    /// For two Bézier curves of degrees n and m, the degree factors of their derivatives left
    /// out: Δ^k b_{n−k} = Δ^k c_0 compared for n!/(n−k)! Δ^k b_{n−k} = m!/(m−k)! Δ^k c_0.
    DegreeFactorsLeftOut,
}

impl ContinuityMistake {
    /// Every mistake of the family.
    pub const ALL: &'static [ContinuityMistake] = &[
        ContinuityMistake::LengthsIgnored,
        ContinuityMistake::LengthsSwapped,
        ContinuityMistake::ParallelTakenForC1,
        ContinuityMistake::DegreeFactorsLeftOut,
    ];
}

/// (22).
const RIGHT: MistakeFormula = MistakeFormula {
    text: "Δ^{1,0} c_{m-1,j} / Δu_0 = Δ^{1,0} c̃_{0,j} / Δu_1",
    tex: r"\frac{\Delta^{1,0} \mathbf c_{m-1,j}}{\Delta u_0} = \frac{\Delta^{1,0} \tilde{\mathbf c}_{0,j}}{\Delta u_1}",
};

impl Message for ContinuityMistake {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            ContinuityMistake::LengthsIgnored => said(
                lang,
                "ignored the interval lengths Δu_0, Δu_1: compared the differences across the border as they are",
                "ignoró las longitudes de los intervalos Δu_0, Δu_1: comparó las diferencias a través del borde tal cual",
                [],
            ),
            ContinuityMistake::LengthsSwapped => said(
                lang,
                "exchanged the interval lengths: divided the first patch's differences by Δu_1 and the second's by Δu_0",
                "intercambió las longitudes de los intervalos: dividió las diferencias de la primera superficie entre Δu_1 y las de la segunda entre Δu_0",
                [],
            ),
            ContinuityMistake::ParallelTakenForC1 => said(
                lang,
                "took parallel differences across the joint for equal ones: a tangent direction that agrees (G^1) is not C^1",
                "tomó diferencias paralelas a través de la unión por iguales: que coincida la dirección tangente (G^1) no es C^1",
                [],
            ),
            ContinuityMistake::DegreeFactorsLeftOut => said(
                lang,
                "left out the degree factors n!/(n−k)! and m!/(m−k)! of the two curves' derivatives: compared their differences alone",
                "omitió los factores n!/(n−k)! y m!/(m−k)! de las derivadas de las dos curvas: comparó solo sus diferencias",
                [],
            ),
        }
    }
}

impl Catalogued for ContinuityMistake {
    fn id(&self) -> &'static str {
        match self {
            ContinuityMistake::LengthsIgnored => "continuity.lengths_ignored",
            ContinuityMistake::LengthsSwapped => "continuity.lengths_swapped",
            ContinuityMistake::ParallelTakenForC1 => "continuity.parallel_taken_for_c1",
            ContinuityMistake::DegreeFactorsLeftOut => "continuity.degree_factors_left_out",
        }
    }

    fn place(&self) -> NotesPlace {
        match self {
            ContinuityMistake::DegreeFactorsLeftOut => NotesPlace::Curves {
                book: Book::Farin,
                section: "§11.1",
            },
            _ => NotesPlace::Notes {
                chapter: 5,
                section: 6,
                equation: Some("22"),
            },
        }
    }

    fn right(&self) -> MistakeFormula {
        match self {
            ContinuityMistake::DegreeFactorsLeftOut => MistakeFormula {
                text: "n!/(n-k)! Δ^k b_{n-k} = m!/(m-k)! Δ^k c_0",
                tex: r"\frac{n!}{(n-k)!} \Delta^k \mathbf b_{n-k} = \frac{m!}{(m-k)!} \Delta^k \mathbf c_0",
            },
            _ => RIGHT,
        }
    }

    fn used(&self) -> MistakeFormula {
        match self {
            ContinuityMistake::LengthsIgnored => MistakeFormula {
                text: "Δ^{1,0} c_{m-1,j} = Δ^{1,0} c̃_{0,j}",
                tex: r"\Delta^{1,0} \mathbf c_{m-1,j} = \Delta^{1,0} \tilde{\mathbf c}_{0,j}",
            },
            ContinuityMistake::LengthsSwapped => MistakeFormula {
                text: "Δ^{1,0} c_{m-1,j} / Δu_1 = Δ^{1,0} c̃_{0,j} / Δu_0",
                tex: r"\frac{\Delta^{1,0} \mathbf c_{m-1,j}}{\Delta u_1} = \frac{\Delta^{1,0} \tilde{\mathbf c}_{0,j}}{\Delta u_0}",
            },
            ContinuityMistake::ParallelTakenForC1 => MistakeFormula {
                text: "Δ^{1,0} c̃_{0,j} = λ_j Δ^{1,0} c_{m-1,j},  λ_j > 0",
                tex: r"\Delta^{1,0} \tilde{\mathbf c}_{0,j} = \lambda_j \Delta^{1,0} \mathbf c_{m-1,j}, \quad \lambda_j > 0",
            },
            ContinuityMistake::DegreeFactorsLeftOut => MistakeFormula {
                text: "Δ^k b_{n-k} = Δ^k c_0",
                tex: r"\Delta^k \mathbf b_{n-k} = \Delta^k \mathbf c_0",
            },
        }
    }
}
