//! Mistakes in knot insertion (Boehm's algorithm; the curve chapters, The NURBS Book §5.2):
//! with k the span of t, the points d_{k-p+1}, ..., d_k replaced by
//! d̂_i = (1 − α_i) d_{i−1} + α_i d_i, α_i = (t − u_{i−1})/(u_{i+p−1} − u_{i−1}) (the notes'
//! convention of knots), in homogeneous coordinates for a rational curve or surface, along the
//! asked direction for a surface.

use super::{Book, Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{said, Lang, Message, Phrase};

/// A mistake in knot insertion.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum InsertKnotMistake {
    /// α_i and 1 − α_i exchanged: d̂_i = α_i d_{i−1} + (1 − α_i) d_i.
    AlphaSwapped,
    /// The order p + 1 taken for the degree p in α_i's denominator (the span of the knot
    /// one knot too long): α_i = (t − u_{i−1})/(u_{i+p} − u_{i−1}).
    OrderForDegree,
    /// A rational curve's (surface's) points and weights combined apart, the points as they
    /// are: d̂_i = (1 − α_i) d_{i−1} + α_i d_i, ŵ_i = (1 − α_i) w_{i−1} + α_i w_i, instead
    /// of combining w d and w (the homogeneous form) and dividing.
    NotHomogeneous,
    /// A surface's knot inserted in v where u is asked: into each row instead of each
    /// column.
    VForU,
    /// A surface's knot inserted in u where v is asked: into each column instead of each
    /// row.
    UForV,
}

impl InsertKnotMistake {
    /// Every mistake of the family.
    pub const ALL: &'static [InsertKnotMistake] = &[
        InsertKnotMistake::AlphaSwapped,
        InsertKnotMistake::OrderForDegree,
        InsertKnotMistake::NotHomogeneous,
        InsertKnotMistake::VForU,
        InsertKnotMistake::UForV,
    ];
}

/// Boehm's step, the notes' convention of knots (as the keys write it).
const BOEHM: MistakeFormula = MistakeFormula {
    text: "d̂_i = (1 - α_i) d_{i-1} + α_i d_i,  α_i = (t - u_{i-1})/(u_{i+p-1} - u_{i-1})",
    tex: r"\hat{d}_i = (1 - \alpha_i)\, d_{i-1} + \alpha_i\, d_i, \quad \alpha_i = \frac{t - u_{i-1}}{u_{i+p-1} - u_{i-1}}",
};

/// Boehm's step on a surface in u: each column j of the mesh.
const IN_U: MistakeFormula = MistakeFormula {
    text: "d̂_{i,j} = (1 - α_i) d_{i-1,j} + α_i d_{i,j}",
    tex: r"\hat{d}_{i,j} = (1 - \alpha_i)\, d_{i-1,j} + \alpha_i\, d_{i,j}",
};

/// Boehm's step on a surface in v: each row i of the mesh.
const IN_V: MistakeFormula = MistakeFormula {
    text: "d̂_{i,j} = (1 - α_j) d_{i,j-1} + α_j d_{i,j}",
    tex: r"\hat{d}_{i,j} = (1 - \alpha_j)\, d_{i,j-1} + \alpha_j\, d_{i,j}",
};

impl Message for InsertKnotMistake {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            InsertKnotMistake::AlphaSwapped => said(
                lang,
                "exchanged α_i and 1 − α_i: gave α_i to d_{i−1} and 1 − α_i to d_i",
                "intercambió α_i y 1 − α_i: dio α_i a d_{i−1} y 1 − α_i a d_i",
                [],
            ),
            InsertKnotMistake::OrderForDegree => said(
                lang,
                "took the order p + 1 for the degree p in the denominator of α_i: u_{i+p} − u_{i−1} instead of u_{i+p−1} − u_{i−1}",
                "tomó el orden p + 1 por el grado p en el denominador de α_i: u_{i+p} − u_{i−1} en lugar de u_{i+p−1} − u_{i−1}",
                [],
            ),
            InsertKnotMistake::NotHomogeneous => said(
                lang,
                "combined the points and the weights apart, not in homogeneous coordinates (w d, w)",
                "combinó los puntos y los pesos por separado, no en coordenadas homogéneas (w d, w)",
                [],
            ),
            InsertKnotMistake::VForU => said(
                lang,
                "inserted the knot in v, into each row, where u is asked (into each column)",
                "insertó el nudo en v, en cada fila, donde se pide en u (en cada columna)",
                [],
            ),
            InsertKnotMistake::UForV => said(
                lang,
                "inserted the knot in u, into each column, where v is asked (into each row)",
                "insertó el nudo en u, en cada columna, donde se pide en v (en cada fila)",
                [],
            ),
        }
    }
}

impl Catalogued for InsertKnotMistake {
    fn id(&self) -> &'static str {
        match self {
            InsertKnotMistake::AlphaSwapped => "insert_knot.alpha_swapped",
            InsertKnotMistake::OrderForDegree => "insert_knot.order_for_degree",
            InsertKnotMistake::NotHomogeneous => "insert_knot.not_homogeneous",
            InsertKnotMistake::VForU => "insert_knot.v_for_u",
            InsertKnotMistake::UForV => "insert_knot.u_for_v",
        }
    }

    fn place(&self) -> NotesPlace {
        NotesPlace::Curves {
            book: Book::NurbsBook,
            section: "§5.2",
        }
    }

    fn right(&self) -> MistakeFormula {
        match self {
            InsertKnotMistake::NotHomogeneous => MistakeFormula {
                text: "(ŵ_i d̂_i, ŵ_i) = (1 - α_i) (w_{i-1} d_{i-1}, w_{i-1}) + α_i (w_i d_i, w_i)",
                tex: r"(\hat w_i \hat{d}_i, \hat w_i) = (1 - \alpha_i)\, (w_{i-1} d_{i-1}, w_{i-1}) + \alpha_i\, (w_i d_i, w_i)",
            },
            InsertKnotMistake::VForU => IN_U,
            InsertKnotMistake::UForV => IN_V,
            _ => BOEHM,
        }
    }

    fn used(&self) -> MistakeFormula {
        match self {
            InsertKnotMistake::AlphaSwapped => MistakeFormula {
                text: "d̂_i = α_i d_{i-1} + (1 - α_i) d_i",
                tex: r"\hat{d}_i = \alpha_i\, d_{i-1} + (1 - \alpha_i)\, d_i",
            },
            InsertKnotMistake::OrderForDegree => MistakeFormula {
                text: "α_i = (t - u_{i-1})/(u_{i+p} - u_{i-1})",
                tex: r"\alpha_i = \frac{t - u_{i-1}}{u_{i+p} - u_{i-1}}",
            },
            InsertKnotMistake::NotHomogeneous => MistakeFormula {
                text: "d̂_i = (1 - α_i) d_{i-1} + α_i d_i,  ŵ_i = (1 - α_i) w_{i-1} + α_i w_i",
                tex: r"\hat{d}_i = (1 - \alpha_i)\, d_{i-1} + \alpha_i\, d_i, \quad \hat w_i = (1 - \alpha_i)\, w_{i-1} + \alpha_i\, w_i",
            },
            InsertKnotMistake::VForU => IN_V,
            InsertKnotMistake::UForV => IN_U,
        }
    }
}
