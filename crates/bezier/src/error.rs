//! The one error type of cagd-bezier.

use cagd_poly::PolyError;
use cagd_scalar::ScalarError;
use cagd_words::{said, Lang, Message, Phrase};

/// What can go wrong with Bézier and rational Bézier curves.
///
/// Numbers inside the messages are written exactly (`3/2`, `√2/2`). Each variant is worded in
/// English and in the notes' Spanish ([`Message`]); `Display` writes the English.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum BezierError {
    /// A control polygon without points: a curve needs at least one control point.
    #[default]
    EmptyPolygon,
    /// Control point `index` has another dimension than control point 0.
    DimensionMismatch {
        /// The index of the offending control point.
        index: usize,
        /// The dimension of control point 0.
        expected: usize,
        /// The dimension of control point `index`.
        found: usize,
    },
    /// The blossom of a degree-n curve takes exactly n arguments.
    BlossomArguments {
        /// The degree n of the curve.
        degree: usize,
        /// How many arguments were given.
        found: usize,
    },
    /// An interval [a, b] with a = b (or a > b where an increasing interval is required).
    DegenerateInterval {
        /// The left end, as text.
        a: String,
        /// The right end, as text.
        b: String,
    },
    /// A sign that a rule needs but that cannot be decided (the values are in letters).
    SignUnknown {
        /// The expression whose sign is needed, as text (`b - a`).
        expression: String,
        /// The rule that needs it.
        rule: Rule,
    },
    /// A parameter outside the domain of a typed curve.
    OutsideDomain {
        /// The parameter, as text.
        t: String,
        /// The left end of the domain.
        a: String,
        /// The right end of the domain.
        b: String,
    },
    /// A subdivision parameter at (or beyond) an end of the domain: one piece would be empty.
    NotInterior {
        /// The parameter, as text.
        t: String,
        /// The left end of the domain.
        a: String,
        /// The right end of the domain.
        b: String,
    },
    /// A rational curve with a different number of weights than control points.
    WeightCount {
        /// Number of control points.
        points: usize,
        /// Number of weights.
        weights: usize,
    },
    /// A zero weight where a control point is needed: the entry is a control vector.
    ZeroWeight {
        /// The index of the zero weight.
        index: usize,
    },
    /// Every weight of a rational curve is zero: no point of it is finite.
    AllWeightsZero,
    /// The denominator w(t) of a rational curve vanishes: c(t) is a point at infinity.
    VanishingDenominator {
        /// The parameter, as text.
        t: String,
    },
    /// The construction needs a number the scalar type cannot hold exactly (√2/2 asked of
    /// exact rationals).
    Number {
        /// What was being built.
        what: NeedsRoot,
        /// The underlying error of the number type.
        source: ScalarError,
    },
    /// Homogeneous control points need at least one coordinate: the weight, last.
    HomogeneousWithoutWeight,
    /// A value that must be positive is not.
    NotPositive {
        /// What the value is.
        what: Quantity,
        /// The value, as text.
        value: String,
    },
    /// An error of the polynomial crate, e.g. a closed form of too high a degree for the
    /// Bernstein basis asked for, or in another variable.
    Poly(PolyError),
    /// The data of a circular arc (or conic) are inconsistent.
    NotACircle {
        /// What is wrong, with the exact values.
        reason: NotAnArc,
    },
}

/// A rule that needs a sign (the `rule` of [`BezierError::SignUnknown`]).
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
#[non_exhaustive]
pub enum Rule {
    /// An interval [a, b] needs a < b.
    IncreasingInterval {
        /// The left end, as text.
        a: String,
        /// The right end, as text.
        b: String,
    },
}

/// A value that must be positive (the `what` of [`BezierError::NotPositive`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Quantity {
    /// The radius of a circle.
    #[default]
    Radius,
    /// The factor ρ of a reweighting.
    ReweightingFactor,
}

/// A construction that needs a square root (the `what` of [`BezierError::Number`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum NeedsRoot {
    /// A quarter circle (weight √2/2).
    #[default]
    QuarterCircle,
    /// The circle as three arcs of 120° (control points with √3).
    ThreeArcs,
}

/// Why the data are not those of a circular arc (the `reason` of [`BezierError::NotACircle`]).
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
#[non_exhaustive]
pub enum NotAnArc {
    /// The end points are at different distances from the tangent point.
    Distances {
        /// |c0 - c1|^2, as text.
        first: String,
        /// |c2 - c1|^2, as text.
        second: String,
    },
    /// The angle at the tangent point does not fit the weight.
    Angle {
        /// The weight cos(θ/2), as text.
        cos_half: String,
        /// The dot product it needs, as text.
        expected: String,
        /// The dot product found, as text.
        found: String,
    },
    /// A weight cos(θ/2) outside (0, 1).
    Weight {
        /// The weight, as text.
        cos_half: String,
    },
    /// A start direction that is not a unit vector.
    StartDirection {
        /// The direction, as text.
        direction: String,
        /// Its squared length, as text.
        length: String,
    },
    /// An end direction that is not a unit vector.
    EndDirection {
        /// The direction, as text.
        direction: String,
        /// Its squared length, as text.
        length: String,
    },
    /// Directions whose angle does not fit the weight.
    Directions {
        /// The weight cos(θ/2), as text.
        cos_half: String,
        /// The cosine it means, as text.
        cos: String,
        /// The dot product of the directions, as text.
        dot: String,
    },
    /// A centre of fewer than two coordinates.
    Centre {
        /// The centre, as text.
        centre: String,
    },
}

impl Default for Rule {
    fn default() -> Self {
        Rule::IncreasingInterval {
            a: String::new(),
            b: String::new(),
        }
    }
}

impl Default for NotAnArc {
    fn default() -> Self {
        NotAnArc::Weight {
            cos_half: String::new(),
        }
    }
}

impl Message for BezierError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            BezierError::EmptyPolygon => said(
                lang,
                "the control polygon is empty: a Bézier curve needs at least one control point",
                "el polígono de control está vacío: una curva de Bézier necesita al menos un punto de control",
                [],
            ),
            BezierError::DimensionMismatch {
                index,
                expected,
                found,
            } => said(
                lang,
                "control point ‹› has dimension ‹› but control point 0 has dimension ‹›",
                "el punto de control ‹› tiene dimensión ‹›, pero el punto de control 0 tiene dimensión ‹›",
                [index.into(), found.into(), expected.into()],
            ),
            BezierError::BlossomArguments { degree, found } => said(
                lang,
                "the blossom of a curve of degree ‹› takes ‹› arguments, but ‹› were given",
                "la forma polar de una curva de grado ‹› toma ‹› argumentos, pero se dieron ‹›",
                [degree.into(), degree.into(), found.into()],
            ),
            BezierError::DegenerateInterval { a, b } => said(
                lang,
                "the interval [‹›, ‹›] is degenerate: its ends must satisfy a < b",
                "el intervalo [‹›, ‹›] es degenerado: sus extremos han de cumplir a < b",
                [a.into(), b.into()],
            ),
            BezierError::SignUnknown { expression, rule } => said(
                lang,
                "«»: the sign of ‹› is not known (it is in letters; give the letters values, or numbers here)",
                "«»: el signo de ‹› no se conoce (está en letras; dé valores a las letras, o ponga aquí números)",
                [rule.phrase(lang).into(), expression.into()],
            ),
            BezierError::OutsideDomain { t, a, b } => said(
                lang,
                "parameter t = ‹› is outside the domain [‹›, ‹›]",
                "el parámetro t = ‹› está fuera del dominio [‹›, ‹›]",
                [t.into(), a.into(), b.into()],
            ),
            BezierError::NotInterior { t, a, b } => said(
                lang,
                "subdivision parameter t = ‹› must lie strictly inside the domain (‹›, ‹›)",
                "el parámetro de subdivisión t = ‹› ha de estar en el interior del dominio (‹›, ‹›)",
                [t.into(), a.into(), b.into()],
            ),
            BezierError::WeightCount { points, weights } => said(
                lang,
                "a rational curve needs one weight per control point: ‹› control points but ‹› weights",
                "una curva racional necesita un peso por punto de control: ‹› puntos de control, pero ‹› pesos",
                [points.into(), weights.into()],
            ),
            BezierError::ZeroWeight { index } => said(
                lang,
                "weight ‹› is zero: that entry is a control vector, not a point, and this needs every control point to be a point",
                "el peso ‹› es cero: esa entrada es un vector de control, no un punto, y aquí todos los puntos de control han de ser puntos",
                [index.into()],
            ),
            BezierError::AllWeightsZero => said(
                lang,
                "every weight is zero: the rational curve has no finite point",
                "todos los pesos son cero: la curva racional no tiene ningún punto finito",
                [],
            ),
            BezierError::VanishingDenominator { t } => said(
                lang,
                "the denominator w(t) of the rational curve vanishes at t = ‹›: c(t) is a point at infinity",
                "el denominador w(t) de la curva racional se anula en t = ‹›: c(t) es un punto del infinito",
                [t.into()],
            ),
            BezierError::HomogeneousWithoutWeight => said(
                lang,
                "homogeneous control points need at least one coordinate: the weight, written last",
                "los puntos de control homogéneos necesitan al menos una coordenada: el peso, escrito el último",
                [],
            ),
            BezierError::NotPositive { what, value } => said(
                lang,
                "«» must be positive, but it is ‹›",
                "«» ha de ser positivo, pero es ‹›",
                [what.phrase(lang).into(), value.into()],
            ),
            BezierError::Number { what, source } => said(
                lang,
                "«»: «»",
                "«»: «»",
                [what.phrase(lang).into(), source.phrase(lang).into()],
            ),
            BezierError::Poly(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            BezierError::NotACircle { reason } => said(
                lang,
                "not a circular arc: «»",
                "no es un arco de circunferencia: «»",
                [reason.phrase(lang).into()],
            ),
        }
    }
}

impl Message for Rule {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Rule::IncreasingInterval { a, b } => said(
                lang,
                "the interval [‹›, ‹›] needs a < b",
                "el intervalo [‹›, ‹›] necesita a < b",
                [a.into(), b.into()],
            ),
        }
    }
}

impl Message for Quantity {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Quantity::Radius => said(lang, "the radius", "el radio", []),
            Quantity::ReweightingFactor => said(
                lang,
                "the reweighting factor ρ",
                "el factor ρ de la reponderación",
                [],
            ),
        }
    }
}

impl Message for NeedsRoot {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            NeedsRoot::QuarterCircle => said(
                lang,
                "a quarter circle has the weight √2/2, which lives in the quadratic field Q(√2), not in the rationals (use that field, or the rational weights {1, 1/2, 1/2} of circle_four_arcs_rational)",
                "un cuarto de circunferencia tiene el peso √2/2, que está en el cuerpo cuadrático Q(√2), no en los racionales (use ese cuerpo, o los pesos racionales {1, 1/2, 1/2} de circle_four_arcs_rational)",
                [],
            ),
            NeedsRoot::ThreeArcs => said(
                lang,
                "the circle as three 120° arcs has control points with √3 (no equilateral triangle has rational vertices), so it needs the quadratic field Q(√3)",
                "la circunferencia en tres arcos de 120° tiene puntos de control con √3 (ningún triángulo equilátero tiene vértices racionales), así que necesita el cuerpo cuadrático Q(√3)",
                [],
            ),
        }
    }
}

impl Message for NotAnArc {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            NotAnArc::Distances { first, second } => said(
                lang,
                "the end points must be at the same positive distance from the tangent point, but |c0 - c1|^2 = ‹› and |c2 - c1|^2 = ‹›",
                "los extremos han de estar a la misma distancia positiva del punto de tangencia, pero |c0 - c1|^2 = ‹› y |c2 - c1|^2 = ‹›",
                [first.into(), second.into()],
            ),
            NotAnArc::Angle {
                cos_half,
                expected,
                found,
            } => said(
                lang,
                "the weight cos(θ/2) = ‹› needs (c0 - c1)·(c2 - c1) = |c0 - c1|^2 (1 - 2 cos^2(θ/2)) = ‹›, but it is ‹›",
                "el peso cos(θ/2) = ‹› necesita (c0 - c1)·(c2 - c1) = |c0 - c1|^2 (1 - 2 cos^2(θ/2)) = ‹›, pero es ‹›",
                [cos_half.into(), expected.into(), found.into()],
            ),
            NotAnArc::Weight { cos_half } => said(
                lang,
                "the weight cos(θ/2) = ‹› must lie strictly between 0 and 1 (0 < θ < π)",
                "el peso cos(θ/2) = ‹› ha de estar estrictamente entre 0 y 1 (0 < θ < π)",
                [cos_half.into()],
            ),
            NotAnArc::StartDirection { direction, length } => said(
                lang,
                "the start direction ‹› must be a unit vector, but its squared length is ‹›",
                "la dirección inicial ‹› ha de ser un vector unitario, pero su longitud al cuadrado es ‹›",
                [direction.into(), length.into()],
            ),
            NotAnArc::EndDirection { direction, length } => said(
                lang,
                "the end direction ‹› must be a unit vector, but its squared length is ‹›",
                "la dirección final ‹› ha de ser un vector unitario, pero su longitud al cuadrado es ‹›",
                [direction.into(), length.into()],
            ),
            NotAnArc::Directions { cos_half, cos, dot } => said(
                lang,
                "cos(θ/2) = ‹› means cos θ = ‹›, but the directions have d0·d1 = ‹›",
                "cos(θ/2) = ‹› significa cos θ = ‹›, pero las direcciones tienen d0·d1 = ‹›",
                [cos_half.into(), cos.into(), dot.into()],
            ),
            NotAnArc::Centre { centre } => said(
                lang,
                "the centre ‹› needs at least two coordinates (the circle lies in the x-y plane)",
                "el centro ‹› necesita al menos dos coordenadas (la circunferencia está en el plano x-y)",
                [centre.into()],
            ),
        }
    }
}

cagd_words::display_english!(BezierError, Rule, Quantity, NeedsRoot, NotAnArc);

impl std::error::Error for BezierError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            BezierError::Number { source, .. } => Some(source),
            BezierError::Poly(e) => Some(e),
            _ => None,
        }
    }
}

impl From<PolyError> for BezierError {
    fn from(e: PolyError) -> Self {
        BezierError::Poly(e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    fn check(m: &BezierError) {
        assert_eq!(cagd_words::check_both(m), Ok(()), "{m:?}");
    }

    #[test]
    fn every_variant_in_both_languages() {
        for m in BezierError::iter() {
            check(&m);
        }
        // the parts, each inside the sentence that carries it
        for rule in Rule::iter() {
            check(&BezierError::SignUnknown {
                expression: "b - a".into(),
                rule,
            });
        }
        for what in Quantity::iter() {
            check(&BezierError::NotPositive {
                what,
                value: "0".into(),
            });
        }
        for what in NeedsRoot::iter() {
            check(&BezierError::Number {
                what,
                source: ScalarError::NotRational {
                    value: "√2/2".into(),
                },
            });
        }
        for reason in NotAnArc::iter() {
            check(&BezierError::NotACircle { reason });
        }
    }
}
