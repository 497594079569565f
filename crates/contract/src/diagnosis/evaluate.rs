//! Mistakes in De Casteljau evaluation of Bézier curves and patches, rational ones too
//! (chapter 5, §4, eq. (9)-(11); the rational surface of §2, eq. (5); the Bernstein
//! polynomials of eq. (1)).

use super::{Book, Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{said, Lang, Message, Phrase};

/// A mistake in De Casteljau evaluation of a Bézier curve or patch (rational ones too).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum EvaluateMistake {
    /// 1 − t and t swapped in the De Casteljau step, `t c_i + (1 − t) c_{i+1}`: the curve
    /// evaluated at 1 − t (a patch at (1 − u, 1 − v)).
    OneMinusT,
    /// u applied to the rows of the mesh and v to the columns (the mesh read transposed): the
    /// patch evaluated at (v, u).
    UvSwapped,
    /// A rational curve or patch evaluated without its weights: `Σ c_i B_i`.
    WeightsIgnored,
    /// The homogeneous De Casteljau point not divided by its weight: the numerator
    /// `Σ w_i c_i B_i` taken as the point.
    NotDivided,
    /// The binomial coefficients of the Bernstein polynomials left out:
    /// `Σ t^i (1 − t)^{n−i} c_i` (in the weights too, for a rational curve).
    BinomialsForgotten,
}

impl EvaluateMistake {
    /// Every mistake of De Casteljau evaluation.
    pub const ALL: &'static [EvaluateMistake] = &[
        EvaluateMistake::OneMinusT,
        EvaluateMistake::UvSwapped,
        EvaluateMistake::WeightsIgnored,
        EvaluateMistake::NotDivided,
        EvaluateMistake::BinomialsForgotten,
    ];
}

/// The De Casteljau step along u (eq. (9)).
const STEP: MistakeFormula = MistakeFormula {
    text: "c_{i,j}^{r,0} = (1 - u) c_{i,j}^{r-1,0} + u c_{i+1,j}^{r-1,0}",
    tex: r"\mathbf c_{i,j}^{r,0} = (1 - u)\,\mathbf c_{i,j}^{r-1,0} + u\,\mathbf c_{i+1,j}^{r-1,0}",
};

/// The rational patch (eq. (5)).
const RATIONAL: MistakeFormula = MistakeFormula {
    text: "c(u, v) = Σ w_{i,j} c_{i,j} B_i^m(u) B_j^n(v) / Σ w_{i,j} B_i^m(u) B_j^n(v)",
    tex: r"\mathbf c(u, v) = \frac{\sum w_{i,j}\,\mathbf c_{i,j} B_i^m(u) B_j^n(v)}{\sum w_{i,j} B_i^m(u) B_j^n(v)}",
};

impl Message for EvaluateMistake {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            EvaluateMistake::OneMinusT => said(
                lang,
                "swapped 1 − t and t in the De Casteljau step: evaluated at 1 − t (at (1 − u, 1 − v) on a surface)",
                "intercambió 1 − t y t en el paso del algoritmo de De Casteljau: evaluó en 1 − t (en (1 − u, 1 − v) en una superficie)",
                [],
            ),
            EvaluateMistake::UvSwapped => said(
                lang,
                "ran the De Casteljau algorithm with u along the rows of the control mesh and with v along the columns: evaluated at (v, u)",
                "aplicó el algoritmo de De Casteljau con u a las filas de la malla de control y con v a las columnas: evaluó en (v, u)",
                [],
            ),
            EvaluateMistake::WeightsIgnored => said(
                lang,
                "ignored the weights: evaluated the polynomial curve or surface of the same control points",
                "ignoró los pesos: evaluó la curva o superficie polinómica de los mismos puntos de control",
                [],
            ),
            EvaluateMistake::NotDivided => said(
                lang,
                "did not divide by the weight: took the numerator Σ w_i c_i B_i of the homogeneous point as the point",
                "no dividió entre el peso: tomó como punto el numerador Σ w_i c_i B_i del punto en coordenadas homogéneas",
                [],
            ),
            EvaluateMistake::BinomialsForgotten => said(
                lang,
                "left out the binomial coefficients of the Bernstein polynomials",
                "omitió los coeficientes binomiales de los polinomios de Bernstein",
                [],
            ),
        }
    }
}

impl Catalogued for EvaluateMistake {
    fn id(&self) -> &'static str {
        match self {
            EvaluateMistake::OneMinusT => "evaluate.one_minus_t",
            EvaluateMistake::UvSwapped => "evaluate.u_v_swapped",
            EvaluateMistake::WeightsIgnored => "evaluate.weights_ignored",
            EvaluateMistake::NotDivided => "evaluate.not_divided",
            EvaluateMistake::BinomialsForgotten => "evaluate.binomials_forgotten",
        }
    }

    fn place(&self) -> NotesPlace {
        match self {
            EvaluateMistake::OneMinusT | EvaluateMistake::UvSwapped => NotesPlace::Notes {
                chapter: 5,
                section: 4,
                equation: Some("9"),
            },
            EvaluateMistake::WeightsIgnored | EvaluateMistake::NotDivided => NotesPlace::Notes {
                chapter: 5,
                section: 2,
                equation: Some("5"),
            },
            EvaluateMistake::BinomialsForgotten => NotesPlace::Curves {
                book: Book::Farin,
                section: "§5.1",
            },
        }
    }

    fn right(&self) -> MistakeFormula {
        match self {
            EvaluateMistake::OneMinusT | EvaluateMistake::UvSwapped => STEP,
            EvaluateMistake::WeightsIgnored | EvaluateMistake::NotDivided => RATIONAL,
            EvaluateMistake::BinomialsForgotten => MistakeFormula {
                text: "B_i^n(t) = C(n, i) t^i (1 - t)^(n-i)",
                tex: r"B_i^n(t) = \binom{n}{i} t^i (1 - t)^{n-i}",
            },
        }
    }

    fn used(&self) -> MistakeFormula {
        match self {
            EvaluateMistake::OneMinusT => MistakeFormula {
                text: "c_{i,j}^{r,0} = u c_{i,j}^{r-1,0} + (1 - u) c_{i+1,j}^{r-1,0}",
                tex: r"\mathbf c_{i,j}^{r,0} = u\,\mathbf c_{i,j}^{r-1,0} + (1 - u)\,\mathbf c_{i+1,j}^{r-1,0}",
            },
            EvaluateMistake::UvSwapped => MistakeFormula {
                text: "c_{i,j}^{0,s} = (1 - u) c_{i,j}^{0,s-1} + u c_{i,j+1}^{0,s-1}",
                tex: r"\mathbf c_{i,j}^{0,s} = (1 - u)\,\mathbf c_{i,j}^{0,s-1} + u\,\mathbf c_{i,j+1}^{0,s-1}",
            },
            EvaluateMistake::WeightsIgnored => MistakeFormula {
                text: "c(u, v) = Σ c_{i,j} B_i^m(u) B_j^n(v)",
                tex: r"\mathbf c(u, v) = \sum \mathbf c_{i,j} B_i^m(u) B_j^n(v)",
            },
            EvaluateMistake::NotDivided => MistakeFormula {
                text: "c(u, v) = Σ w_{i,j} c_{i,j} B_i^m(u) B_j^n(v)",
                tex: r"\mathbf c(u, v) = \sum w_{i,j}\,\mathbf c_{i,j} B_i^m(u) B_j^n(v)",
            },
            EvaluateMistake::BinomialsForgotten => MistakeFormula {
                text: "B_i^n(t) = t^i (1 - t)^(n-i)",
                tex: r"B_i^n(t) = t^i (1 - t)^{n-i}",
            },
        }
    }
}
