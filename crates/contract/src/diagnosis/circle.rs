//! Mistakes in circles and arcs (chapter 6, §6: the circle of N arcs, the 9-point circle;
//! rational quadratic arcs): each arc of angle θ is a rational quadratic with weights
//! {1, w, 1}, w = cos(θ/2), its middle vertex at distance r/cos(θ/2) from the center (where
//! the tangents at the ends meet), the knots double at the joins of the arcs.

use super::{Catalogued, MistakeFormula, NotesPlace};
use cagd_words::{said, Lang, Message, Phrase};

/// A mistake in circles and arcs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CircleMistake {
    /// The middle weight of every arc 1: weights {1, 1, 1} (a parabola's arcs, not the
    /// circle's).
    MiddleWeightOne,
    /// The middle vertex of every arc on the circle, at distance r from the center, instead
    /// of r/cos(θ/2) (where the tangents at the ends of the arc meet).
    MiddleVertexOnCircle,
    /// The knots equally spaced, each interior one single, instead of double at the joins
    /// of the arcs: {a, a, a + h, a + 2h, ..., b, b}, h = (b − a)/(2N − 1).
    SingleKnots,
    /// The middle weight the cosine of the whole angle of the arc, cos θ, instead of the
    /// cosine of half of it.
    WeightWholeAngle,
    /// The weights left out: the control polygon and knots written as a polynomial B-spline
    /// curve's (the classic "forgot the weights"; without them it is no circle).
    WeightsLeftOut,
}

impl CircleMistake {
    /// Every mistake of the family.
    pub const ALL: &'static [CircleMistake] = &[
        CircleMistake::MiddleWeightOne,
        CircleMistake::MiddleVertexOnCircle,
        CircleMistake::SingleKnots,
        CircleMistake::WeightWholeAngle,
        CircleMistake::WeightsLeftOut,
    ];
}

const PLACE: NotesPlace = NotesPlace::Notes {
    chapter: 6,
    section: 6,
    equation: None,
};

const WEIGHTS: MistakeFormula = MistakeFormula {
    text: "w_j = 1, w, 1, w, ..., 1,  w = cos(θ/2)",
    tex: r"w_j = 1, w, 1, w, \dots, 1, \quad w = \cos\frac{\theta}{2}",
};

impl Message for CircleMistake {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            CircleMistake::MiddleWeightOne => said(
                lang,
                "gave weight 1 to the middle vertex of every arc, not the cosine of half its angle",
                "dio peso 1 al vértice intermedio de cada arco, no el coseno de la mitad de su ángulo",
                [],
            ),
            CircleMistake::MiddleVertexOnCircle => said(
                lang,
                "put the middle vertex of every arc on the circle, at distance r from the center, not at r/cos(θ/2) where the tangents at its ends meet",
                "situó el vértice intermedio de cada arco sobre la circunferencia, a distancia r del centro, no a r/cos(θ/2), donde se cortan las tangentes en sus extremos",
                [],
            ),
            CircleMistake::SingleKnots => said(
                lang,
                "took equally spaced single knots instead of a double knot at each join of two arcs",
                "tomó nudos simples equiespaciados en lugar de un nudo doble en cada unión de dos arcos",
                [],
            ),
            CircleMistake::WeightsLeftOut => said(
                lang,
                "left the weights out: wrote the control polygon and the knots alone, as if the curve were polynomial (no polynomial curve is a circle)",
                "omitió los pesos: escribió solo el polígono de control y los nudos, como si la curva fuera polinómica (ninguna curva polinómica es una circunferencia)",
                [],
            ),
            CircleMistake::WeightWholeAngle => said(
                lang,
                "took the cosine of the whole angle θ of the arc as the middle weight, not the cosine of θ/2",
                "tomó como peso intermedio el coseno del ángulo θ del arco completo, no el coseno de θ/2",
                [],
            ),
        }
    }
}

impl Catalogued for CircleMistake {
    fn id(&self) -> &'static str {
        match self {
            CircleMistake::MiddleWeightOne => "circle.middle_weight_one",
            CircleMistake::MiddleVertexOnCircle => "circle.middle_vertex_on_circle",
            CircleMistake::SingleKnots => "circle.single_knots",
            CircleMistake::WeightWholeAngle => "circle.weight_whole_angle",
            CircleMistake::WeightsLeftOut => "circle.weights_left_out",
        }
    }

    fn place(&self) -> NotesPlace {
        PLACE
    }

    fn right(&self) -> MistakeFormula {
        match self {
            CircleMistake::MiddleWeightOne
            | CircleMistake::WeightWholeAngle
            | CircleMistake::WeightsLeftOut => WEIGHTS,
            CircleMistake::MiddleVertexOnCircle => MistakeFormula {
                text: "|b_{2j+1} - c| = r/cos(θ/2)",
                tex: r"\lvert b_{2j+1} - c \rvert = \frac{r}{\cos(\theta/2)}",
            },
            CircleMistake::SingleKnots => MistakeFormula {
                text: "u = {a, a, a + h, a + h, a + 2h, a + 2h, ..., b, b},  h = (b - a)/N",
                tex: r"u = \{a, a, a + h, a + h, a + 2h, a + 2h, \dots, b, b\}, \quad h = \frac{b - a}{N}",
            },
        }
    }

    fn used(&self) -> MistakeFormula {
        match self {
            CircleMistake::MiddleWeightOne => MistakeFormula {
                text: "w_j = 1, 1, 1, ..., 1",
                tex: r"w_j = 1, 1, 1, \dots, 1",
            },
            CircleMistake::MiddleVertexOnCircle => MistakeFormula {
                text: "|b_{2j+1} - c| = r",
                tex: r"\lvert b_{2j+1} - c \rvert = r",
            },
            CircleMistake::SingleKnots => MistakeFormula {
                text: "u = {a, a, a + h, a + 2h, ..., b, b},  h = (b - a)/(2N - 1)",
                tex: r"u = \{a, a, a + h, a + 2h, \dots, b, b\}, \quad h = \frac{b - a}{2N - 1}",
            },
            CircleMistake::WeightWholeAngle => MistakeFormula {
                text: "w_j = 1, w, 1, w, ..., 1,  w = cos θ",
                tex: r"w_j = 1, w, 1, w, \dots, 1, \quad w = \cos\theta",
            },
            CircleMistake::WeightsLeftOut => MistakeFormula {
                text: "c(u) = Σ b_j N_j^2(u)",
                tex: r"c(u) = \sum_j b_j N_j^2(u)",
            },
        }
    }
}
