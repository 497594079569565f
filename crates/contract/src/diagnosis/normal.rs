//! Mistakes in normal vectors (chapter 5, §6, (25) and the normal n(u, v) = c_u × c_v
//! before it): the closed form of c_u × c_v and its values at the four corners,
//! n(0, 0) = mn Δ^{1,0}c_{0,0} × Δ^{0,1}c_{0,0} and likewise at the others.

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{said, Lang, Message, Phrase};

/// A mistake in normal vectors.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum NormalMistake {
    /// The factors of the cross product exchanged, c_v × c_u for c_u × c_v: the opposite
    /// normal everywhere.
    CrossReversed,
    /// The factors m and n of c_u and c_v (16)-(17) left out: at a corner
    /// Δ^{1,0}c_{0,0} × Δ^{0,1}c_{0,0} for mn Δ^{1,0}c_{0,0} × Δ^{0,1}c_{0,0} (the notes
    /// print (25) so), and c_u × c_v / (mn) for the closed form.
    DegreeFactorsLeftOut,
    /// The control mesh read transposed (its rows for its columns, c_{j,i} for c_{i,j}): the
    /// normal of the patch c(v, u), −n(v, u), so the corners (1, 0) and (0, 1) exchanged and
    /// every normal reversed.
    MeshTransposed,
    /// At every corner both differences taken from the corner outward, as (25) does at
    /// c_{0,0}: at (1, 0) (c_{m−1,0} − c_{m,0}) × (c_{m,1} − c_{m,0}), the opposite normal at
    /// the corners (1, 0) and (0, 1).
    OutwardDifferences,
}

impl NormalMistake {
    /// Every mistake of the family.
    pub const ALL: &'static [NormalMistake] = &[
        NormalMistake::CrossReversed,
        NormalMistake::DegreeFactorsLeftOut,
        NormalMistake::MeshTransposed,
        NormalMistake::OutwardDifferences,
    ];
}

/// n(u, v) = c_u × c_v.
const RIGHT: MistakeFormula = MistakeFormula {
    text: "n(u, v) = c_u(u, v) × c_v(u, v)",
    tex: r"\mathbf n(u, v) = \mathbf c_u(u, v) \times \mathbf c_v(u, v)",
};

/// (25) with its factor mn.
const RIGHT_CORNER: MistakeFormula = MistakeFormula {
    text: "n(0, 0) = m n Δ^{1,0}c_{0,0} × Δ^{0,1}c_{0,0}",
    tex: r"\mathbf n(0, 0) = mn\, \Delta^{1,0}\mathbf c_{0,0} \times \Delta^{0,1}\mathbf c_{0,0}",
};

impl Message for NormalMistake {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            NormalMistake::CrossReversed => said(
                lang,
                "took the cross product in the other order, c_v × c_u instead of c_u × c_v: the opposite normal",
                "tomó el producto vectorial en el otro orden, c_v × c_u en lugar de c_u × c_v: el vector normal opuesto",
                [],
            ),
            NormalMistake::DegreeFactorsLeftOut => said(
                lang,
                "left out the factors m and n of c_u and c_v: the cross product of the differences alone (as (25) is printed in the notes)",
                "omitió los factores m y n de c_u y c_v: tomó solo el producto vectorial de las diferencias (como aparece impresa (25) en los apuntes)",
                [],
            ),
            NormalMistake::MeshTransposed => said(
                lang,
                "read the control mesh transposed, its rows for its columns: the corners (1, 0) and (0, 1) exchanged and the normal reversed",
                "leyó la malla de control traspuesta, las filas por las columnas: las esquinas (1, 0) y (0, 1) intercambiadas y el vector normal invertido",
                [],
            ),
            NormalMistake::OutwardDifferences => said(
                lang,
                "took both differences from the corner outward at every corner, as (25) does at c_{0,0}: the opposite normal at the corners (1, 0) and (0, 1)",
                "tomó en cada esquina las dos diferencias desde la esquina hacia fuera, como (25) en c_{0,0}: el vector normal opuesto en las esquinas (1, 0) y (0, 1)",
                [],
            ),
        }
    }
}

impl Catalogued for NormalMistake {
    fn id(&self) -> &'static str {
        match self {
            NormalMistake::CrossReversed => "normal.cross_reversed",
            NormalMistake::DegreeFactorsLeftOut => "normal.degree_factors_left_out",
            NormalMistake::MeshTransposed => "normal.mesh_transposed",
            NormalMistake::OutwardDifferences => "normal.outward_differences",
        }
    }

    fn place(&self) -> NotesPlace {
        NotesPlace::Notes {
            chapter: 5,
            section: 6,
            equation: match self {
                NormalMistake::CrossReversed | NormalMistake::MeshTransposed => None,
                NormalMistake::DegreeFactorsLeftOut | NormalMistake::OutwardDifferences => {
                    Some("25")
                }
            },
        }
    }

    fn right(&self) -> MistakeFormula {
        match self {
            NormalMistake::CrossReversed => RIGHT,
            NormalMistake::DegreeFactorsLeftOut => RIGHT_CORNER,
            NormalMistake::MeshTransposed => MistakeFormula {
                text: "c(u, v) = Σ_i Σ_j c_{i,j} B_i^m(u) B_j^n(v)",
                tex: r"\mathbf c(u, v) = \sum_{i=0}^{m} \sum_{j=0}^{n} \mathbf c_{i,j} B_i^m(u) B_j^n(v)",
            },
            NormalMistake::OutwardDifferences => MistakeFormula {
                text: "n(1, 0) = m n (c_{m,0} - c_{m-1,0}) × (c_{m,1} - c_{m,0})",
                tex: r"\mathbf n(1, 0) = mn\, (\mathbf c_{m,0} - \mathbf c_{m-1,0}) \times (\mathbf c_{m,1} - \mathbf c_{m,0})",
            },
        }
    }

    fn used(&self) -> MistakeFormula {
        match self {
            NormalMistake::CrossReversed => MistakeFormula {
                text: "n(u, v) = c_v(u, v) × c_u(u, v)",
                tex: r"\mathbf n(u, v) = \mathbf c_v(u, v) \times \mathbf c_u(u, v)",
            },
            NormalMistake::DegreeFactorsLeftOut => MistakeFormula {
                text: "n(0, 0) = Δ^{1,0}c_{0,0} × Δ^{0,1}c_{0,0}",
                tex: r"\mathbf n(0, 0) = \Delta^{1,0}\mathbf c_{0,0} \times \Delta^{0,1}\mathbf c_{0,0}",
            },
            NormalMistake::MeshTransposed => MistakeFormula {
                text: "c(u, v) = Σ_i Σ_j c_{j,i} B_i^n(u) B_j^m(v)",
                tex: r"\mathbf c(u, v) = \sum_{i=0}^{n} \sum_{j=0}^{m} \mathbf c_{j,i} B_i^n(u) B_j^m(v)",
            },
            NormalMistake::OutwardDifferences => MistakeFormula {
                text: "n(1, 0) = m n (c_{m-1,0} - c_{m,0}) × (c_{m,1} - c_{m,0})",
                tex: r"\mathbf n(1, 0) = mn\, (\mathbf c_{m-1,0} - \mathbf c_{m,0}) \times (\mathbf c_{m,1} - \mathbf c_{m,0})",
            },
        }
    }
}
