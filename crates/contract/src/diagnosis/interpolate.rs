//! Mistakes in interpolation: a Bézier curve through data points a_k = c(t_k), the system
//! B C = A with B_{k,i} = B_i^n(t_k) (the curve chapters); a Bézier patch through a grid
//! a_{k,l} = c(u_k, v_l) (chapter 5, §7, eq. (26)), the system B_U C B_Vᵗ = A (eq. (27));
//! the parameters of the data (uniform, by chord length); cubic splines and their end
//! conditions.

use super::{Book, Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{said, Lang, Message, Phrase};

/// A mistake in interpolation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum InterpolateMistake {
    /// The data points written as the control points: c_i = a_i (a Bézier curve or patch).
    DataAsControl,
    /// A curve's system solved with the transposed matrix: Bᵗ C = A.
    TransposedMatrix,
    /// A grid's system written without transposing B_V: B_U C B_V = A.
    UntransposedBv,
    /// Natural end conditions (c'' = 0 at the ends) where Bessel or clamped ends are asked.
    NaturalEnds,
    /// The uniform parameters t_k = k/n where those by chord length are asked.
    UniformForChordLength,
}

impl InterpolateMistake {
    /// Every interpolation mistake.
    pub const ALL: &'static [InterpolateMistake] = &[
        InterpolateMistake::DataAsControl,
        InterpolateMistake::TransposedMatrix,
        InterpolateMistake::UntransposedBv,
        InterpolateMistake::NaturalEnds,
        InterpolateMistake::UniformForChordLength,
    ];
}

impl Message for InterpolateMistake {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            InterpolateMistake::DataAsControl => said(
                lang,
                "took the data points as the control points: the curve or surface they define does not pass through them",
                "tomó los puntos dato como puntos de control: la curva o superficie que definen no pasa por ellos",
                [],
            ),
            InterpolateMistake::TransposedMatrix => said(
                lang,
                "solved the system with the transposed matrix Bᵗ: the values B_i^n(t_k) of each parameter down a column instead of along a row",
                "resolvió el sistema con la matriz traspuesta Bᵗ: los valores B_i^n(t_k) de cada parámetro en una columna en lugar de en una fila",
                [],
            ),
            InterpolateMistake::UntransposedBv => said(
                lang,
                "wrote the system as B_U C B_V = A, without transposing B_V",
                "planteó el sistema B_U C B_V = A, sin trasponer B_V",
                [],
            ),
            InterpolateMistake::NaturalEnds => said(
                lang,
                "used the natural end conditions (second derivative zero at the ends) instead of the end conditions asked",
                "usó las condiciones naturales (derivada segunda nula en los extremos) en lugar de las condiciones en los extremos pedidas",
                [],
            ),
            InterpolateMistake::UniformForChordLength => said(
                lang,
                "used the uniform parameters t_k = k/n instead of the parameters by chord length",
                "usó los parámetros uniformes t_k = k/n en lugar de los parámetros por longitud de cuerda",
                [],
            ),
        }
    }
}

impl Catalogued for InterpolateMistake {
    fn id(&self) -> &'static str {
        match self {
            InterpolateMistake::DataAsControl => "interpolate.data_as_control",
            InterpolateMistake::TransposedMatrix => "interpolate.transposed_matrix",
            InterpolateMistake::UntransposedBv => "interpolate.untransposed_b_v",
            InterpolateMistake::NaturalEnds => "interpolate.natural_ends",
            InterpolateMistake::UniformForChordLength => "interpolate.uniform_for_chord_length",
        }
    }

    fn place(&self) -> NotesPlace {
        match self {
            InterpolateMistake::DataAsControl => NotesPlace::Notes {
                chapter: 5,
                section: 7,
                equation: Some("26"),
            },
            InterpolateMistake::UntransposedBv => NotesPlace::Notes {
                chapter: 5,
                section: 7,
                equation: Some("27"),
            },
            InterpolateMistake::TransposedMatrix | InterpolateMistake::UniformForChordLength => {
                NotesPlace::Curves {
                    book: Book::NurbsBook,
                    section: "§9.2.1",
                }
            }
            InterpolateMistake::NaturalEnds => NotesPlace::Curves {
                book: Book::Farin,
                section: "§9",
            },
        }
    }

    fn right(&self) -> MistakeFormula {
        match self {
            InterpolateMistake::DataAsControl => MistakeFormula {
                text: "c(t_k) = a_k",
                tex: r"\mathbf c(t_k) = \mathbf a_k",
            },
            InterpolateMistake::TransposedMatrix => MistakeFormula {
                text: "B C = A, B_{k,i} = B_i^n(t_k)",
                tex: r"B\,C = A,\quad B_{k,i} = B_i^n(t_k)",
            },
            InterpolateMistake::UntransposedBv => MistakeFormula {
                text: "B_U C B_V^t = A",
                tex: r"B_U\,C\,B_V^t = A",
            },
            InterpolateMistake::NaturalEnds => MistakeFormula {
                text: "c'(t_0) = m_0, c'(t_n) = m_n",
                tex: r"\mathbf c'(t_0) = \mathbf m_0,\quad \mathbf c'(t_n) = \mathbf m_n",
            },
            InterpolateMistake::UniformForChordLength => MistakeFormula {
                text: "t_k - t_(k-1) = |a_k - a_(k-1)| / Σ_l |a_l - a_(l-1)|",
                tex: r"t_k - t_{k-1} = \frac{\lVert \mathbf a_k - \mathbf a_{k-1} \rVert}{\sum_l \lVert \mathbf a_l - \mathbf a_{l-1} \rVert}",
            },
        }
    }

    fn used(&self) -> MistakeFormula {
        match self {
            InterpolateMistake::DataAsControl => MistakeFormula {
                text: "c_k = a_k",
                tex: r"\mathbf c_k = \mathbf a_k",
            },
            InterpolateMistake::TransposedMatrix => MistakeFormula {
                text: "B^t C = A",
                tex: r"B^t\,C = A",
            },
            InterpolateMistake::UntransposedBv => MistakeFormula {
                text: "B_U C B_V = A",
                tex: r"B_U\,C\,B_V = A",
            },
            InterpolateMistake::NaturalEnds => MistakeFormula {
                text: "c''(t_0) = c''(t_n) = 0",
                tex: r"\mathbf c''(t_0) = \mathbf c''(t_n) = \mathbf 0",
            },
            InterpolateMistake::UniformForChordLength => MistakeFormula {
                text: "t_k = k/n",
                tex: r"t_k = k/n",
            },
        }
    }
}
