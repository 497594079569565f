//! Mistakes in restriction and subdivision of Bézier curves and patches, rational ones too
//! (chapter 5, §4: the restriction to [a, b] × [c, d] by the polar form, eq. (13); a
//! subdivision is the restriction to the two (or four) pieces).

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{said, Lang, Message, Phrase};

/// A mistake in restriction or subdivision.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum SubdivideMistake {
    /// Subdivided at 1 − t (at 1 − u, 1 − v on a patch) instead of t.
    AtOneMinusT,
    /// The polygon of the piece over [t, 1] written in reverse order (the side of the De
    /// Casteljau triangle read from the other end); on a patch, the pieces over [u, 1] (over
    /// [v, 1]) with their mesh reversed in u (in v).
    RightPieceReversed,
    /// The restriction's control points taken as points of the curve (patch) at equally
    /// spaced parameters, `c(a + i(b − a)/n)`, instead of values of the polar form.
    PointsOnCurve,
    /// The intervals (the split values) of u and v exchanged.
    UvSwapped,
}

impl SubdivideMistake {
    /// Every mistake of restriction and subdivision.
    pub const ALL: &'static [SubdivideMistake] = &[
        SubdivideMistake::AtOneMinusT,
        SubdivideMistake::RightPieceReversed,
        SubdivideMistake::PointsOnCurve,
        SubdivideMistake::UvSwapped,
    ];
}

/// The restriction to [a, b] × [c, d] (eq. (13)).
const RIGHT: MistakeFormula = MistakeFormula {
    text: "c̃_{i,j} = c[a^⟨m-i⟩, b^⟨i⟩; c^⟨n-j⟩, d^⟨j⟩]",
    tex: r"\tilde{\mathbf c}_{i,j} = \mathbf c[a^{\langle m-i \rangle}, b^{\langle i \rangle}; c^{\langle n-j \rangle}, d^{\langle j \rangle}]",
};

const PLACE: NotesPlace = NotesPlace::Notes {
    chapter: 5,
    section: 4,
    equation: Some("13"),
};

impl Message for SubdivideMistake {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            SubdivideMistake::AtOneMinusT => said(
                lang,
                "subdivided at 1 − t instead of t",
                "subdividió en 1 − t en lugar de en t",
                [],
            ),
            SubdivideMistake::RightPieceReversed => said(
                lang,
                "wrote the control points of the piece over [t, 1] in reverse order: read the side of the De Casteljau triangle from the other end",
                "escribió en orden inverso los puntos de control del trozo sobre [t, 1]: leyó el lado del triángulo de De Casteljau desde el otro extremo",
                [],
            ),
            SubdivideMistake::PointsOnCurve => said(
                lang,
                "took points of the curve or surface at equally spaced parameters as the control points, instead of values of the polar form",
                "tomó como puntos de control puntos de la curva o superficie en parámetros equiespaciados, en lugar de valores de la forma polar",
                [],
            ),
            SubdivideMistake::UvSwapped => said(
                lang,
                "exchanged u and v: took in u the values given for v, and in v those given for u",
                "intercambió u y v: tomó en u los valores dados para v, y en v los dados para u",
                [],
            ),
        }
    }
}

impl Catalogued for SubdivideMistake {
    fn id(&self) -> &'static str {
        match self {
            SubdivideMistake::AtOneMinusT => "subdivide.at_one_minus_t",
            SubdivideMistake::RightPieceReversed => "subdivide.right_piece_reversed",
            SubdivideMistake::PointsOnCurve => "subdivide.points_on_curve",
            SubdivideMistake::UvSwapped => "subdivide.u_v_swapped",
        }
    }

    fn place(&self) -> NotesPlace {
        PLACE
    }

    fn right(&self) -> MistakeFormula {
        match self {
            SubdivideMistake::AtOneMinusT => MistakeFormula {
                text: "[0, t], [t, 1]",
                tex: r"[0, t],\ [t, 1]",
            },
            SubdivideMistake::RightPieceReversed => MistakeFormula {
                text: "c̃_i = c[t^⟨n-i⟩, 1^⟨i⟩]",
                tex: r"\tilde{\mathbf c}_i = \mathbf c[t^{\langle n-i \rangle}, 1^{\langle i \rangle}]",
            },
            SubdivideMistake::PointsOnCurve | SubdivideMistake::UvSwapped => RIGHT,
        }
    }

    fn used(&self) -> MistakeFormula {
        match self {
            SubdivideMistake::AtOneMinusT => MistakeFormula {
                text: "[0, 1 - t], [1 - t, 1]",
                tex: r"[0, 1 - t],\ [1 - t, 1]",
            },
            SubdivideMistake::RightPieceReversed => MistakeFormula {
                text: "c̃_i = c[t^⟨i⟩, 1^⟨n-i⟩]",
                tex: r"\tilde{\mathbf c}_i = \mathbf c[t^{\langle i \rangle}, 1^{\langle n-i \rangle}]",
            },
            SubdivideMistake::PointsOnCurve => MistakeFormula {
                text: "c̃_{i,j} = c(a + i(b-a)/m, c + j(d-c)/n)",
                tex: r"\tilde{\mathbf c}_{i,j} = \mathbf c\Bigl(a + \frac{i(b-a)}{m},\ c + \frac{j(d-c)}{n}\Bigr)",
            },
            SubdivideMistake::UvSwapped => MistakeFormula {
                text: "c̃_{i,j} = c[c^⟨m-i⟩, d^⟨i⟩; a^⟨n-j⟩, b^⟨j⟩]",
                tex: r"\tilde{\mathbf c}_{i,j} = \mathbf c[c^{\langle m-i \rangle}, d^{\langle i \rangle}; a^{\langle n-j \rangle}, b^{\langle j \rangle}]",
            },
        }
    }
}
