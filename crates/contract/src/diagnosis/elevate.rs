//! Mistakes in degree elevation of Bézier curves and patches, rational ones too (chapter 5,
//! §5, eq. (14)-(15); a rational one elevated in homogeneous coordinates).

use super::{Book, Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{said, Lang, Message, Phrase};

/// A mistake in degree elevation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ElevateMistake {
    /// The coefficients divided by m instead of m + 1:
    /// `c_{i,j}^{1,0} = (1 − i/m) c_{i,j} + (i/m) c_{i−1,j}` (the end points kept).
    DividedByM,
    /// The two coefficients swapped:
    /// `c_{i,j}^{1,0} = (i/(m + 1)) c_{i,j} + (1 − i/(m + 1)) c_{i−1,j}` (the end points kept).
    CoefficientsSwapped,
    /// A rational curve or patch elevated on its control points and its weights apart, not
    /// on the homogeneous points (w c, w).
    WeightsApart,
    /// A patch elevated in the other direction: by (s, r) where (r, s) is asked.
    OtherDirection,
}

impl ElevateMistake {
    /// Every mistake of degree elevation.
    pub const ALL: &'static [ElevateMistake] = &[
        ElevateMistake::DividedByM,
        ElevateMistake::CoefficientsSwapped,
        ElevateMistake::WeightsApart,
        ElevateMistake::OtherDirection,
    ];
}

/// The elevation of bidegree (m, n) to (m + 1, n) (eq. (14)).
const RIGHT: MistakeFormula = MistakeFormula {
    text: "c_{i,j}^{1,0} = (1 - i/(m+1)) c_{i,j} + i/(m+1) c_{i-1,j}",
    tex: r"\mathbf c_{i,j}^{1,0} = \Bigl(1 - \frac{i}{m+1}\Bigr)\mathbf c_{i,j} + \frac{i}{m+1}\,\mathbf c_{i-1,j}",
};

const PLACE: NotesPlace = NotesPlace::Notes {
    chapter: 5,
    section: 5,
    equation: Some("14"),
};

impl Message for ElevateMistake {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            ElevateMistake::DividedByM => said(
                lang,
                "divided by the degree m instead of m + 1 in the coefficients of degree elevation",
                "dividió entre el grado m en lugar de entre m + 1 en los coeficientes de la elevación del grado",
                [],
            ),
            ElevateMistake::CoefficientsSwapped => said(
                lang,
                "swapped the two coefficients of degree elevation: i/(m + 1) on c_i,j and 1 − i/(m + 1) on c_i−1,j",
                "intercambió los dos coeficientes de la elevación del grado: i/(m + 1) para c_i,j y 1 − i/(m + 1) para c_i−1,j",
                [],
            ),
            ElevateMistake::WeightsApart => said(
                lang,
                "elevated the control points and the weights separately, not the homogeneous points (w c, w)",
                "elevó por separado los puntos de control y los pesos, no los puntos en coordenadas homogéneas (w c, w)",
                [],
            ),
            ElevateMistake::OtherDirection => said(
                lang,
                "elevated the degree in the other direction: u and v exchanged",
                "elevó el grado en la otra dirección: intercambió u y v",
                [],
            ),
        }
    }
}

impl Catalogued for ElevateMistake {
    fn id(&self) -> &'static str {
        match self {
            ElevateMistake::DividedByM => "elevate.divided_by_m",
            ElevateMistake::CoefficientsSwapped => "elevate.coefficients_swapped",
            ElevateMistake::WeightsApart => "elevate.weights_apart",
            ElevateMistake::OtherDirection => "elevate.other_direction",
        }
    }

    fn place(&self) -> NotesPlace {
        match self {
            ElevateMistake::WeightsApart => NotesPlace::Curves {
                book: Book::NurbsBook,
                section: "§5.5",
            },
            ElevateMistake::OtherDirection => NotesPlace::Notes {
                chapter: 5,
                section: 5,
                equation: None,
            },
            _ => PLACE,
        }
    }

    fn right(&self) -> MistakeFormula {
        match self {
            ElevateMistake::WeightsApart => MistakeFormula {
                text: "(w c)_i^1 = (1 - i/(n+1)) w_i c_i + i/(n+1) w_{i-1} c_{i-1}, w_i^1 = (1 - i/(n+1)) w_i + i/(n+1) w_{i-1}",
                tex: r"(w\mathbf c)_i^{1} = \Bigl(1 - \frac{i}{n+1}\Bigr) w_i\mathbf c_i + \frac{i}{n+1}\, w_{i-1}\mathbf c_{i-1},\quad w_i^{1} = \Bigl(1 - \frac{i}{n+1}\Bigr) w_i + \frac{i}{n+1}\, w_{i-1}",
            },
            ElevateMistake::OtherDirection => MistakeFormula {
                text: "(m, n) -> (m + r, n + s)",
                tex: r"(m, n) \to (m + r, n + s)",
            },
            _ => RIGHT,
        }
    }

    fn used(&self) -> MistakeFormula {
        match self {
            ElevateMistake::DividedByM => MistakeFormula {
                text: "c_{i,j}^{1,0} = (1 - i/m) c_{i,j} + i/m c_{i-1,j}",
                tex: r"\mathbf c_{i,j}^{1,0} = \Bigl(1 - \frac{i}{m}\Bigr)\mathbf c_{i,j} + \frac{i}{m}\,\mathbf c_{i-1,j}",
            },
            ElevateMistake::CoefficientsSwapped => MistakeFormula {
                text: "c_{i,j}^{1,0} = i/(m+1) c_{i,j} + (1 - i/(m+1)) c_{i-1,j}",
                tex: r"\mathbf c_{i,j}^{1,0} = \frac{i}{m+1}\,\mathbf c_{i,j} + \Bigl(1 - \frac{i}{m+1}\Bigr)\mathbf c_{i-1,j}",
            },
            ElevateMistake::WeightsApart => MistakeFormula {
                text: "c_i^1 = (1 - i/(n+1)) c_i + i/(n+1) c_{i-1}, w_i^1 = (1 - i/(n+1)) w_i + i/(n+1) w_{i-1}",
                tex: r"\mathbf c_i^{1} = \Bigl(1 - \frac{i}{n+1}\Bigr)\mathbf c_i + \frac{i}{n+1}\,\mathbf c_{i-1},\quad w_i^{1} = \Bigl(1 - \frac{i}{n+1}\Bigr) w_i + \frac{i}{n+1}\, w_{i-1}",
            },
            ElevateMistake::OtherDirection => MistakeFormula {
                text: "(m, n) -> (m + s, n + r)",
                tex: r"(m, n) \to (m + s, n + r)",
            },
        }
    }
}
