//! Mistakes in translational surfaces (chapter 6, §2): c(u, v) = c₁(u) + d₁(v) − a
//! (eq. (1)), with a = c₁(0) = d₁(0) the common point; the Bézier (and B-spline) mesh
//! c_{i,j} = c_{1i} + d_{1j} − a (eq. (4)) and, for rational curves, the weights
//! w_{i,j} = w_{1i} ω_{1j} (eq. (5)).

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{said, Lang, Message, Phrase};

/// A mistake in translational surfaces.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TranslationalMistake {
    /// The common point a not subtracted: c_{i,j} = c_{1i} + d_{1j} (c₁(u) + d₁(v)).
    CommonPointKept,
    /// The other end of c₁ subtracted instead of the common point: c_{1i} + d_{1j} − c_{1m}
    /// (c₁(u) + d₁(v) − c₁(1)).
    OtherEndSubtracted,
    /// The mesh written with rows and columns swapped: c_{j,i} = c_{1i} + d_{1j} − a.
    MeshTransposed,
    /// The rule of the points applied to the weights: w_{i,j} = w_{1i} + ω_{1j} − w_{10},
    /// instead of their products (eq. (5)).
    WeightsAdded,
}

impl TranslationalMistake {
    /// Every translational-surface mistake.
    pub const ALL: &'static [TranslationalMistake] = &[
        TranslationalMistake::CommonPointKept,
        TranslationalMistake::OtherEndSubtracted,
        TranslationalMistake::MeshTransposed,
        TranslationalMistake::WeightsAdded,
    ];
}

const MESH: MistakeFormula = MistakeFormula {
    text: "c_{i,j} = c_{1i} + d_{1j} - a",
    tex: r"\mathbf c_{i,j} = \mathbf c_{1i} + \mathbf d_{1j} - \mathbf a",
};

impl Message for TranslationalMistake {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            TranslationalMistake::CommonPointKept => said(
                lang,
                "did not subtract the common point a = c₁(0) = d₁(0): added the two curves only",
                "no restó el punto común a = c₁(0) = d₁(0): solo sumó las dos curvas",
                [],
            ),
            TranslationalMistake::OtherEndSubtracted => said(
                lang,
                "subtracted the other end c₁(1) of the first curve instead of the common point a = c₁(0)",
                "restó el otro extremo c₁(1) de la primera curva en lugar del punto común a = c₁(0)",
                [],
            ),
            TranslationalMistake::MeshTransposed => said(
                lang,
                "wrote the control mesh with rows and columns swapped: the polygon of c₁ along the rows",
                "escribió la malla de control con las filas y las columnas intercambiadas: el polígono de c₁ a lo largo de las filas",
                [],
            ),
            TranslationalMistake::WeightsAdded => said(
                lang,
                "applied the rule of the control points to the weights: added them and subtracted the weight at a, instead of multiplying them",
                "aplicó a los pesos la regla de los puntos de control: los sumó y restó el peso de a, en lugar de multiplicarlos",
                [],
            ),
        }
    }
}

impl Catalogued for TranslationalMistake {
    fn id(&self) -> &'static str {
        match self {
            TranslationalMistake::CommonPointKept => "translational.common_point_kept",
            TranslationalMistake::OtherEndSubtracted => "translational.other_end_subtracted",
            TranslationalMistake::MeshTransposed => "translational.mesh_transposed",
            TranslationalMistake::WeightsAdded => "translational.weights_added",
        }
    }

    fn place(&self) -> NotesPlace {
        let equation = match self {
            TranslationalMistake::CommonPointKept | TranslationalMistake::OtherEndSubtracted => "1",
            TranslationalMistake::MeshTransposed => "4",
            TranslationalMistake::WeightsAdded => "5",
        };
        NotesPlace::Notes {
            chapter: 6,
            section: 2,
            equation: Some(equation),
        }
    }

    fn right(&self) -> MistakeFormula {
        match self {
            TranslationalMistake::CommonPointKept | TranslationalMistake::OtherEndSubtracted => {
                MistakeFormula {
                    text: "c(u, v) = c_1(u) + d_1(v) - a, a = c_1(0) = d_1(0)",
                    tex: r"\mathbf c(u, v) = \mathbf c_1(u) + \mathbf d_1(v) - \mathbf a,\quad \mathbf a = \mathbf c_1(0) = \mathbf d_1(0)",
                }
            }
            TranslationalMistake::MeshTransposed => MESH,
            TranslationalMistake::WeightsAdded => MistakeFormula {
                text: "w_{i,j} = w_{1i} ω_{1j}",
                tex: r"w_{i,j} = w_{1i}\,\omega_{1j}",
            },
        }
    }

    fn used(&self) -> MistakeFormula {
        match self {
            TranslationalMistake::CommonPointKept => MistakeFormula {
                text: "c(u, v) = c_1(u) + d_1(v)",
                tex: r"\mathbf c(u, v) = \mathbf c_1(u) + \mathbf d_1(v)",
            },
            TranslationalMistake::OtherEndSubtracted => MistakeFormula {
                text: "c(u, v) = c_1(u) + d_1(v) - c_1(1)",
                tex: r"\mathbf c(u, v) = \mathbf c_1(u) + \mathbf d_1(v) - \mathbf c_1(1)",
            },
            TranslationalMistake::MeshTransposed => MistakeFormula {
                text: "c_{j,i} = c_{1i} + d_{1j} - a",
                tex: r"\mathbf c_{j,i} = \mathbf c_{1i} + \mathbf d_{1j} - \mathbf a",
            },
            TranslationalMistake::WeightsAdded => MistakeFormula {
                text: "w_{i,j} = w_{1i} + ω_{1j} - w_{10}",
                tex: r"w_{i,j} = w_{1i} + \omega_{1j} - w_{10}",
            },
        }
    }
}
