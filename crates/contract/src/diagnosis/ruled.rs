//! Mistakes in ruled surfaces (chapter 6, §3): the parametrization
//! c(u, v) = (1 − v) c₁(u) + v c₂(u) (eq. (7)) and its Bézier mesh of bidegree (m, 1), whose
//! columns are the polygons of c₁ and c₂, the curve of lower degree raised first.

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{said, Lang, Message, Phrase};

/// A mistake in ruled surfaces.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum RuledMistake {
    /// The two curves exchanged: v c₁(u) + (1 − v) c₂(u), c₂ on the border v = 0.
    CurvesExchanged,
    /// c₂ taken in the opposite direction: c₁(u) joined with c₂(1 − u) (its polygon in
    /// reverse order, c_{i,1} = c_{2,m−i}).
    CurveReversed,
    /// The mesh written with rows and columns swapped: the polygons of c₁ and c₂ as its rows,
    /// of bidegree (1, m).
    MeshTransposed,
    /// The curve of lower degree not raised (chapter 5, §5) but padded with its last control
    /// point repeated until the degrees match.
    LastPointRepeated,
}

impl RuledMistake {
    /// Every ruled-surface mistake.
    pub const ALL: &'static [RuledMistake] = &[
        RuledMistake::CurvesExchanged,
        RuledMistake::CurveReversed,
        RuledMistake::MeshTransposed,
        RuledMistake::LastPointRepeated,
    ];
}

const MESH: MistakeFormula = MistakeFormula {
    text: "c_{i,0} = c_{1i}, c_{i,1} = c_{2i}",
    tex: r"\mathbf c_{i,0} = \mathbf c_{1i},\quad \mathbf c_{i,1} = \mathbf c_{2i}",
};

impl Message for RuledMistake {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            RuledMistake::CurvesExchanged => said(
                lang,
                "exchanged the two curves: put c₂ on the border v = 0 and c₁ on v = 1",
                "intercambió las dos curvas: puso c₂ en el borde v = 0 y c₁ en v = 1",
                [],
            ),
            RuledMistake::CurveReversed => said(
                lang,
                "took c₂ in the opposite direction: joined c₁(u) with c₂(1 − u)",
                "tomó c₂ en sentido contrario: unió c₁(u) con c₂(1 − u)",
                [],
            ),
            RuledMistake::MeshTransposed => said(
                lang,
                "wrote the control mesh with rows and columns swapped: the polygons of c₁ and c₂ as its rows",
                "escribió la malla de control con las filas y las columnas intercambiadas: los polígonos de c₁ y c₂ como filas",
                [],
            ),
            RuledMistake::LastPointRepeated => said(
                lang,
                "did not raise the degree of the curve of lower degree: repeated its last control point instead",
                "no elevó el grado de la curva de menor grado: repitió su último punto de control",
                [],
            ),
        }
    }
}

impl Catalogued for RuledMistake {
    fn id(&self) -> &'static str {
        match self {
            RuledMistake::CurvesExchanged => "ruled.curves_exchanged",
            RuledMistake::CurveReversed => "ruled.curve_reversed",
            RuledMistake::MeshTransposed => "ruled.mesh_transposed",
            RuledMistake::LastPointRepeated => "ruled.last_point_repeated",
        }
    }

    fn place(&self) -> NotesPlace {
        match self {
            RuledMistake::CurvesExchanged | RuledMistake::CurveReversed => NotesPlace::Notes {
                chapter: 6,
                section: 3,
                equation: Some("7"),
            },
            RuledMistake::MeshTransposed => NotesPlace::Notes {
                chapter: 6,
                section: 3,
                equation: None,
            },
            RuledMistake::LastPointRepeated => NotesPlace::Notes {
                chapter: 5,
                section: 5,
                equation: Some("14"),
            },
        }
    }

    fn right(&self) -> MistakeFormula {
        match self {
            RuledMistake::CurvesExchanged | RuledMistake::CurveReversed => MistakeFormula {
                text: "c(u, v) = (1 - v) c_1(u) + v c_2(u)",
                tex: r"\mathbf c(u, v) = (1 - v)\,\mathbf c_1(u) + v\,\mathbf c_2(u)",
            },
            RuledMistake::MeshTransposed => MESH,
            RuledMistake::LastPointRepeated => MistakeFormula {
                text: "c_i^(1) = i/(n+1) c_(i-1) + (1 - i/(n+1)) c_i",
                tex: r"\mathbf c_i^{(1)} = \tfrac{i}{n+1}\,\mathbf c_{i-1} + \Bigl(1 - \tfrac{i}{n+1}\Bigr)\mathbf c_i",
            },
        }
    }

    fn used(&self) -> MistakeFormula {
        match self {
            RuledMistake::CurvesExchanged => MistakeFormula {
                text: "c(u, v) = v c_1(u) + (1 - v) c_2(u)",
                tex: r"\mathbf c(u, v) = v\,\mathbf c_1(u) + (1 - v)\,\mathbf c_2(u)",
            },
            RuledMistake::CurveReversed => MistakeFormula {
                text: "c(u, v) = (1 - v) c_1(u) + v c_2(1 - u)",
                tex: r"\mathbf c(u, v) = (1 - v)\,\mathbf c_1(u) + v\,\mathbf c_2(1 - u)",
            },
            RuledMistake::MeshTransposed => MistakeFormula {
                text: "c_{0,i} = c_{1i}, c_{1,i} = c_{2i}",
                tex: r"\mathbf c_{0,i} = \mathbf c_{1i},\quad \mathbf c_{1,i} = \mathbf c_{2i}",
            },
            RuledMistake::LastPointRepeated => MistakeFormula {
                text: "c_i^(1) = c_i, c_(n+1)^(1) = c_n",
                tex: r"\mathbf c_i^{(1)} = \mathbf c_i,\quad \mathbf c_{n+1}^{(1)} = \mathbf c_n",
            },
        }
    }
}
