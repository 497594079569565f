//! Mistakes in surfaces of revolution (chapter 6, §6, eq. (21)): the mesh of the profile
//! {c_0, ..., c_n} with weights {w_0, ..., w_n} rotated about the Z axis has as row i the
//! polygon of the circle C_i described by c_i (c_{i,j} = (C_i)_j, its middle vertices at
//! r_i/cos(θ/2)) and as weights w_{i,j} = w_i ω_j, ω_j the circle's normalized weights
//! {1, cos(θ/2), 1, ...}.

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{said, Lang, Message, Phrase};

/// A mistake in surfaces of revolution.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum RevolutionMistake {
    /// The weights of row i the circle's ω_j alone, not multiplied by the profile's weight
    /// w_i: w_{i,j} = ω_j.
    ProfileWeightLeftOut,
    /// The circle's middle weights 1: w_{i,j} = w_i (row i of weights constant).
    MiddleWeightOne,
    /// The middle vertices of each row on the parallel, at distance r_i from the axis,
    /// instead of r_i/cos(θ/2).
    MiddleVertexOnParallel,
    /// Rows and columns exchanged: row i the profile rotated (a meridian) instead of the
    /// circle C_i described by c_i (the mesh and weights transposed).
    Transposed,
    /// The weights left out: the mesh written as a polynomial surface's (the classic "forgot
    /// the weights").
    WeightsLeftOut,
}

impl RevolutionMistake {
    /// Every mistake of the family.
    pub const ALL: &'static [RevolutionMistake] = &[
        RevolutionMistake::ProfileWeightLeftOut,
        RevolutionMistake::MiddleWeightOne,
        RevolutionMistake::MiddleVertexOnParallel,
        RevolutionMistake::Transposed,
        RevolutionMistake::WeightsLeftOut,
    ];
}

const PLACE: NotesPlace = NotesPlace::Notes {
    chapter: 6,
    section: 6,
    equation: Some("21"),
};

const WEIGHTS: MistakeFormula = MistakeFormula {
    text: "w_{i,j} = w_i ω_j,  ω_j = 1, cos(θ/2), 1, ...",
    tex: r"w_{i,j} = w_i\, \omega_j, \quad \omega_j = 1, \cos\frac{\theta}{2}, 1, \dots",
};

impl Message for RevolutionMistake {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            RevolutionMistake::ProfileWeightLeftOut => said(
                lang,
                "did not multiply the weights of row i by the weight w_i of the profile's vertex",
                "no multiplicó los pesos de la fila i por el peso w_i del vértice del perfil",
                [],
            ),
            RevolutionMistake::MiddleWeightOne => said(
                lang,
                "gave the circles' middle vertices weight 1 (times w_i), not the cosine of half the angle",
                "dio a los vértices intermedios de las circunferencias peso 1 (por w_i), no el coseno de la mitad del ángulo",
                [],
            ),
            RevolutionMistake::MiddleVertexOnParallel => said(
                lang,
                "put the middle vertices of each row on the parallel, at distance r_i from the axis, not at r_i/cos(θ/2)",
                "situó los vértices intermedios de cada fila sobre el paralelo, a distancia r_i del eje, no a r_i/cos(θ/2)",
                [],
            ),
            RevolutionMistake::WeightsLeftOut => said(
                lang,
                "left the weights out: wrote the control mesh alone, as if the surface were polynomial (its circles are only rational)",
                "omitió los pesos: escribió solo la malla de control, como si la superficie fuera polinómica (sus circunferencias solo son racionales)",
                [],
            ),
            RevolutionMistake::Transposed => said(
                lang,
                "exchanged rows and columns: made row i a rotated copy of the profile instead of the polygon of the circle C_i described by c_i",
                "intercambió filas y columnas: hizo de la fila i una copia girada del perfil en lugar del polígono de la circunferencia C_i que describe c_i",
                [],
            ),
        }
    }
}

impl Catalogued for RevolutionMistake {
    fn id(&self) -> &'static str {
        match self {
            RevolutionMistake::ProfileWeightLeftOut => "revolution.profile_weight_left_out",
            RevolutionMistake::MiddleWeightOne => "revolution.middle_weight_one",
            RevolutionMistake::MiddleVertexOnParallel => "revolution.middle_vertex_on_parallel",
            RevolutionMistake::Transposed => "revolution.transposed",
            RevolutionMistake::WeightsLeftOut => "revolution.weights_left_out",
        }
    }

    fn place(&self) -> NotesPlace {
        PLACE
    }

    fn right(&self) -> MistakeFormula {
        match self {
            RevolutionMistake::ProfileWeightLeftOut
            | RevolutionMistake::MiddleWeightOne
            | RevolutionMistake::WeightsLeftOut => WEIGHTS,
            RevolutionMistake::MiddleVertexOnParallel => MistakeFormula {
                text: "|(C_i)_{2j+1} - (0, 0, z_i)| = r_i/cos(θ/2)",
                tex: r"\lvert (C_i)_{2j+1} - (0, 0, z_i) \rvert = \frac{r_i}{\cos(\theta/2)}",
            },
            RevolutionMistake::Transposed => MistakeFormula {
                text: "c_{i,j} = (C_i)_j",
                tex: r"c_{i,j} = (C_i)_j",
            },
        }
    }

    fn used(&self) -> MistakeFormula {
        match self {
            RevolutionMistake::ProfileWeightLeftOut => MistakeFormula {
                text: "w_{i,j} = ω_j",
                tex: r"w_{i,j} = \omega_j",
            },
            RevolutionMistake::MiddleWeightOne => MistakeFormula {
                text: "w_{i,j} = w_i",
                tex: r"w_{i,j} = w_i",
            },
            RevolutionMistake::WeightsLeftOut => MistakeFormula {
                text: "w_{i,j} = 1",
                tex: r"w_{i,j} = 1",
            },
            RevolutionMistake::MiddleVertexOnParallel => MistakeFormula {
                text: "|(C_i)_{2j+1} - (0, 0, z_i)| = r_i",
                tex: r"\lvert (C_i)_{2j+1} - (0, 0, z_i) \rvert = r_i",
            },
            RevolutionMistake::Transposed => MistakeFormula {
                text: "c_{i,j} = (C_j)_i",
                tex: r"c_{i,j} = (C_j)_i",
            },
        }
    }
}
