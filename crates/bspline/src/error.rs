//! The one error type of cagd-bspline.

use cagd_bezier::BezierError;
use cagd_scalar::ScalarError;
use cagd_words::{said, Lang, Message, Phrase};

/// What can go wrong with knot vectors, B-spline and NURBS curves.
///
/// Numbers inside the messages are written exactly (`3/2`, `√2/2`). Knot indices are those of
/// the vector as it was given (in the convention it was read in); control-point indices are the
/// same in both conventions. Each variant is worded in English and in the notes' Spanish
/// ([`Message`]); `Display` writes the English.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
#[non_exhaustive]
pub enum BSplineError {
    /// A degree below 1.
    InvalidDegree {
        /// The degree given.
        degree: usize,
    },
    /// Fewer than `degree + 1` control points.
    TooFewPoints {
        /// The degree of the curve.
        degree: usize,
        /// How many control points were given.
        found: usize,
    },
    /// A knot vector of neither accepted length.
    KnotCount {
        /// The degree of the curve.
        degree: usize,
        /// The number of control points.
        points: usize,
        /// How many knots were given.
        found: usize,
    },
    /// `knots[index - 1] > knots[index]`.
    DecreasingKnots {
        /// The index of the knot that is smaller than the one before it.
        index: usize,
        /// The knot before, as text.
        before: String,
        /// The knot at `index`, as text.
        after: String,
    },
    /// Two knots whose order cannot be decided (they are in letters).
    KnotOrderUnknown {
        /// The index of the second knot.
        index: usize,
        /// The difference whose sign is needed, as text.
        difference: String,
    },
    /// A knot repeated more than `degree + 1` times (in the notes' convention).
    Multiplicity {
        /// The knot, as text.
        knot: String,
        /// How many times it appears.
        multiplicity: usize,
        /// The degree of the curve.
        degree: usize,
    },
    /// The domain `[u_{p-1}, u_{n-1}]` has no length.
    EmptyDomain {
        /// Its left end, as text.
        start: String,
        /// Its right end, as text.
        end: String,
    },
    /// A parameter outside the domain.
    OutsideDomain {
        /// The parameter, as text.
        t: String,
        /// The left end of the domain.
        start: String,
        /// The right end of the domain.
        end: String,
    },
    /// A knot to insert or remove that lies outside the domain (or, for removal, on its ends).
    KnotOutsideDomain {
        /// The knot, as text.
        knot: String,
        /// The left end of the domain.
        start: String,
        /// The right end of the domain.
        end: String,
    },
    /// The number of control points does not fit the knot vector.
    PointCount {
        /// The number the knot vector is made for.
        expected: usize,
        /// The number given.
        found: usize,
    },
    /// Control point `index` has another dimension than control point 0.
    DimensionMismatch {
        /// The index of the offending control point.
        index: usize,
        /// The dimension of control point 0.
        expected: usize,
        /// The dimension of control point `index`.
        found: usize,
    },
    /// A NURBS curve with a different number of weights than control points.
    WeightCount {
        /// Number of control points.
        points: usize,
        /// Number of weights.
        weights: usize,
    },
    /// A zero weight: a control vector, which a NURBS curve does not take.
    ZeroWeight {
        /// The index of the zero weight.
        index: usize,
    },
    /// The denominator of a rational curve vanishes: the point is at infinity.
    PointAtInfinity {
        /// The parameter, as text.
        t: String,
    },
    /// An index that is not a non-empty span of the domain.
    InvalidSpan {
        /// The index given (full convention, Piegl and Tiller's `k` with `u_k <= t < u_{k+1}`).
        span: usize,
    },
    /// Inserting a knot that many times would exceed the multiplicity `degree`.
    NotInsertable {
        /// The knot, as text.
        knot: String,
        /// Its multiplicity before insertion.
        multiplicity: usize,
        /// How many insertions were asked for.
        times: usize,
        /// The degree of the curve.
        degree: usize,
    },
    /// The value to remove is not a knot of the curve (or not that many times).
    NotAKnot {
        /// The value, as text.
        knot: String,
        /// Its multiplicity.
        multiplicity: usize,
        /// How many removals were asked for.
        times: usize,
    },
    /// Removing the knot would change the curve.
    NotRemovable {
        /// The knot, as text.
        knot: String,
        /// How many copies were removed before the one that fails.
        removed: usize,
    },
    /// The derivative of the curve is not a B-spline curve of this crate.
    NoDerivativeCurve {
        /// Why.
        reason: NoDerivative,
    },
    /// A construction needs a square root the scalar type does not hold exactly.
    NeedsRoot {
        /// What was being built.
        what: Construction,
        /// The radicand d of the quadratic field Q(√d) needed.
        radicand: u64,
    },
    /// The data of a circle are inconsistent (number of arcs, cosine and sine).
    NotACircle {
        /// What is wrong, with the exact values.
        reason: CircleData,
    },
    /// An error of a Bézier piece.
    Bezier(BezierError),
    /// An error of the number type.
    Number {
        /// What was being done.
        what: Construction,
        /// The underlying error.
        source: ScalarError,
    },
}

impl Default for BSplineError {
    fn default() -> Self {
        BSplineError::InvalidDegree { degree: 0 }
    }
}

/// Why the derivative of a curve is not a B-spline curve of this crate (the `reason` of
/// [`BSplineError::NoDerivativeCurve`]).
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum NoDerivative {
    /// The curve has degree 1.
    #[default]
    DegreeOne,
    /// A knot of full multiplicity: the curve may jump there.
    Jump {
        /// The knot, as text.
        knot: String,
        /// How many times it appears.
        times: usize,
        /// The degree of the curve.
        degree: usize,
    },
}

/// A construction that needs a number the scalar type may not hold (the `what` of
/// [`BSplineError::NeedsRoot`] and [`BSplineError::Number`]).
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
#[non_exhaustive]
pub enum Construction {
    /// The circle of N arcs, with its cos(π/N) and sin(π/N).
    Circle {
        /// The number of arcs N.
        arcs: usize,
        /// cos(π/N), as text.
        cos: String,
        /// sin(π/N), as text.
        sin: String,
    },
}

/// Why the data of a circle are inconsistent (the `reason` of [`BSplineError::NotACircle`]).
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum CircleData {
    /// Fewer than 3 arcs.
    TooFewArcs {
        /// The number of arcs asked for.
        arcs: usize,
    },
    /// A radius that is not positive.
    Radius {
        /// The radius, as text.
        radius: String,
    },
    /// cos(π/N) = 0.
    #[default]
    CosZero,
    /// cos(π/N) and sin(π/N) for an N without built-in values.
    NotBuiltIn {
        /// N.
        arcs: usize,
    },
    /// cos(π/N) and sin(π/N) not both positive.
    NotPositive {
        /// N.
        arcs: usize,
        /// The cosine, as text.
        cos: String,
        /// The sine, as text.
        sin: String,
    },
    /// A (cos, sin) pair off the unit circle.
    NotUnit {
        /// The cosine, as text.
        cos: String,
        /// The sine, as text.
        sin: String,
        /// cos² + sin², as text.
        norm: String,
    },
    /// A (cos, sin) pair of another angle than π/N.
    WrongAngle {
        /// The cosine, as text.
        cos: String,
        /// The sine, as text.
        sin: String,
        /// N.
        arcs: usize,
    },
}

impl Default for Construction {
    fn default() -> Self {
        Construction::Circle {
            arcs: 0,
            cos: String::new(),
            sin: String::new(),
        }
    }
}

impl Message for BSplineError {
    fn phrase(&self, lang: Lang) -> Phrase {
        use BSplineError as E;
        match self {
            E::InvalidDegree { degree } => said(
                lang,
                "degree ‹› is not allowed: a B-spline curve needs degree at least 1",
                "el grado ‹› no es válido: una curva B-spline necesita grado al menos 1",
                [degree.into()],
            ),
            E::TooFewPoints { degree, found } => said(
                lang,
                "a B-spline curve of degree ‹› needs at least ‹› control points, found ‹›",
                "una curva B-spline de grado ‹› necesita al menos ‹› puntos de control, se encontraron ‹›",
                [degree.into(), (&(degree + 1)).into(), found.into()],
            ),
            E::KnotCount {
                degree,
                points,
                found,
            } => said(
                lang,
                "a curve of degree ‹› with ‹› control points needs ‹› knots (the notes' convention, without end knots) or ‹› (with one more knot at each end, as in The NURBS Book); found ‹›",
                "una curva de grado ‹› con ‹› puntos de control necesita ‹› nudos (el convenio de los apuntes, sin nudos extremos) o ‹› (con un nudo más en cada extremo, como en el libro de Piegl y Tiller); se dieron ‹›",
                [
                    degree.into(),
                    points.into(),
                    (&(points + degree).saturating_sub(1)).into(),
                    (&(points + degree + 1)).into(),
                    found.into(),
                ],
            ),
            E::DecreasingKnots {
                index,
                before,
                after,
            } => said(
                lang,
                "knot vector decreases at index ‹›: ‹› > ‹›",
                "la sucesión de nudos decrece en la posición ‹›: ‹› > ‹›",
                [index.into(), before.into(), after.into()],
            ),
            E::KnotOrderUnknown { index, difference } => said(
                lang,
                "the knots must not decrease: the sign of ‹› (knots ‹› and ‹›) is not known (it is in letters; give the letters values, or numbers here)",
                "los nudos no pueden decrecer: el signo de ‹› (nudos ‹› y ‹›) no se conoce (está en letras; dé valores a las letras, o ponga aquí números)",
                [
                    difference.into(),
                    (&index.saturating_sub(1)).into(),
                    index.into(),
                ],
            ),
            E::Multiplicity {
                knot,
                multiplicity,
                degree,
            } => said(
                lang,
                "knot ‹› appears ‹› times, but a curve of degree ‹› allows at most ‹› (the notes' convention, without end knots)",
                "el nudo ‹› aparece ‹› veces, pero una curva de grado ‹› admite como mucho ‹› (el convenio de los apuntes, sin nudos extremos)",
                [
                    knot.into(),
                    multiplicity.into(),
                    degree.into(),
                    (&(degree + 1)).into(),
                ],
            ),
            E::EmptyDomain { start, end } => said(
                lang,
                "the domain [‹›, ‹›] of the knot vector is empty: its ends must differ",
                "el dominio [‹›, ‹›] de la sucesión de nudos es vacío: sus extremos han de ser distintos",
                [start.into(), end.into()],
            ),
            E::OutsideDomain { t, start, end } => said(
                lang,
                "parameter t = ‹› is outside the domain [‹›, ‹›]",
                "el parámetro t = ‹› está fuera del dominio [‹›, ‹›]",
                [t.into(), start.into(), end.into()],
            ),
            E::KnotOutsideDomain { knot, start, end } => said(
                lang,
                "knot ‹› is not inside the domain [‹›, ‹›] of the curve",
                "el nudo ‹› no está en el interior del dominio [‹›, ‹›] de la curva",
                [knot.into(), start.into(), end.into()],
            ),
            E::PointCount { expected, found } => said(
                lang,
                "the knot vector is made for ‹› control points, but ‹› were given",
                "la sucesión de nudos es para ‹› puntos de control, pero se dieron ‹›",
                [expected.into(), found.into()],
            ),
            E::DimensionMismatch {
                index,
                expected,
                found,
            } => said(
                lang,
                "control point ‹› has dimension ‹› but control point 0 has dimension ‹›",
                "el punto de control ‹› tiene dimensión ‹›, pero el punto de control 0 tiene dimensión ‹›",
                [index.into(), found.into(), expected.into()],
            ),
            E::WeightCount { points, weights } => said(
                lang,
                "a NURBS curve needs one weight per control point: ‹› control points but ‹› weights",
                "una curva NURBS necesita un peso por punto de control: ‹› puntos de control, pero ‹› pesos",
                [points.into(), weights.into()],
            ),
            E::ZeroWeight { index } => said(
                lang,
                "weight ‹› is zero: a control vector (weight zero) is taken in a rational Bézier curve, not in a NURBS curve",
                "el peso ‹› es cero: un vector de control (peso cero) se admite en una curva de Bézier racional, no en una curva NURBS",
                [index.into()],
            ),
            E::PointAtInfinity { t } => said(
                lang,
                "the denominator of the rational curve vanishes at t = ‹›: the point is at infinity",
                "el denominador de la curva racional se anula en t = ‹›: el punto está en el infinito",
                [t.into()],
            ),
            E::InvalidSpan { span } => said(
                lang,
                "‹› is not the index of a non-empty span [u_k, u_(k+1)] of the domain",
                "‹› no es el índice de un intervalo no vacío [u_k, u_(k+1)] del dominio",
                [span.into()],
            ),
            E::NotInsertable {
                knot,
                multiplicity,
                times,
                degree,
            } => said(
                lang,
                "knot ‹› cannot be inserted ‹› more time(s): it already has multiplicity ‹›, and insertion stops at multiplicity ‹› (the degree)",
                "el nudo ‹› no se puede insertar ‹› vez (veces) más: ya tiene multiplicidad ‹›, y la inserción se detiene en la multiplicidad ‹› (el grado)",
                [knot.into(), times.into(), multiplicity.into(), degree.into()],
            ),
            E::NotAKnot {
                knot,
                multiplicity,
                times,
            } => said(
                lang,
                "knot ‹› cannot be removed ‹› time(s): it has multiplicity ‹›",
                "el nudo ‹› no se puede eliminar ‹› vez (veces): tiene multiplicidad ‹›",
                [knot.into(), times.into(), multiplicity.into()],
            ),
            E::NotRemovable { knot, removed } => said(
                lang,
                "knot ‹› cannot be removed (after ‹› removal(s)) without changing the curve",
                "el nudo ‹› no se puede eliminar (tras ‹› eliminación(es)) sin cambiar la curva",
                [knot.into(), removed.into()],
            ),
            E::NoDerivativeCurve { reason } => said(
                lang,
                "the derivative is not a B-spline curve: «»",
                "la derivada no es una curva B-spline: «»",
                [reason.phrase(lang).into()],
            ),
            E::NeedsRoot { what, radicand } => said(
                lang,
                "«» needs the quadratic field √‹›: compute over a + b√‹›, not over the rationals",
                "«» necesita el cuerpo cuadrático √‹›: calcule en a + b√‹›, no en los racionales",
                [what.phrase(lang).into(), radicand.into(), radicand.into()],
            ),
            E::NotACircle { reason } => said(
                lang,
                "not a circle: «»",
                "no es una circunferencia: «»",
                [reason.phrase(lang).into()],
            ),
            E::Bezier(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            E::Number { what, source } => said(
                lang,
                "«»: «»",
                "«»: «»",
                [what.phrase(lang).into(), source.phrase(lang).into()],
            ),
        }
    }
}

impl Message for NoDerivative {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            NoDerivative::DegreeOne => said(
                lang,
                "the derivative of a curve of degree 1 is piecewise constant",
                "la derivada de una curva de grado 1 es constante a trozos",
                [],
            ),
            NoDerivative::Jump {
                knot,
                times,
                degree,
            } => said(
                lang,
                "knot ‹› appears ‹› times, so the curve of degree ‹› may jump there",
                "el nudo ‹› aparece ‹› veces, así que la curva de grado ‹› puede saltar ahí",
                [knot.into(), times.into(), degree.into()],
            ),
        }
    }
}

impl Message for Construction {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Construction::Circle { arcs, cos, sin } => said(
                lang,
                "the circle of ‹› arcs (cos(π/‹›) = ‹›, sin(π/‹›) = ‹›)",
                "la circunferencia de ‹› arcos (cos(π/‹›) = ‹›, sin(π/‹›) = ‹›)",
                [
                    arcs.into(),
                    arcs.into(),
                    cos.into(),
                    arcs.into(),
                    sin.into(),
                ],
            ),
        }
    }
}

impl Message for CircleData {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            CircleData::TooFewArcs { arcs } => said(
                lang,
                "a closed circle of quadratic arcs needs at least 3 arcs, got ‹› (an arc of angle π or more has a middle weight cos(π/N) ≤ 0)",
                "una circunferencia cerrada de arcos cuadráticos necesita al menos 3 arcos, se pidieron ‹› (un arco de ángulo π o mayor tiene peso central cos(π/N) ≤ 0)",
                [arcs.into()],
            ),
            CircleData::Radius { radius } => said(
                lang,
                "the radius ‹› is not positive",
                "el radio ‹› no es positivo",
                [radius.into()],
            ),
            CircleData::CosZero => said(lang, "cos(π/N) is zero", "cos(π/N) es cero", []),
            CircleData::NotBuiltIn { arcs } => said(
                lang,
                "cos(π/‹›) and sin(π/‹›) are not built in (only N = 3, 4, 6): pass them exactly",
                "cos(π/‹›) y sin(π/‹›) no vienen incorporados (solo N = 3, 4, 6): páselos exactamente",
                [arcs.into(), arcs.into()],
            ),
            CircleData::NotPositive { arcs, cos, sin } => said(
                lang,
                "cos(π/‹›) = ‹› and sin(π/‹›) = ‹› must both be positive",
                "cos(π/‹›) = ‹› y sin(π/‹›) = ‹› han de ser ambos positivos",
                [arcs.into(), cos.into(), arcs.into(), sin.into()],
            ),
            CircleData::NotUnit { cos, sin, norm } => said(
                lang,
                "(cos, sin) = (‹›, ‹›) has cos² + sin² = ‹›, not 1",
                "(cos, sin) = (‹›, ‹›) tiene cos² + sin² = ‹›, no 1",
                [cos.into(), sin.into(), norm.into()],
            ),
            CircleData::WrongAngle { cos, sin, arcs } => said(
                lang,
                "(‹›, ‹›) is not (cos(π/‹›), sin(π/‹›)): turning ‹› times by it does not reach the angle π",
                "(‹›, ‹›) no es (cos(π/‹›), sin(π/‹›)): girar ‹› veces con él no llega al ángulo π",
                [cos.into(), sin.into(), arcs.into(), arcs.into(), arcs.into()],
            ),
        }
    }
}

cagd_words::display_english!(BSplineError, NoDerivative, Construction, CircleData);

impl std::error::Error for BSplineError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            BSplineError::Bezier(e) => Some(e),
            BSplineError::Number { source, .. } => Some(source),
            _ => None,
        }
    }
}

impl From<BezierError> for BSplineError {
    fn from(e: BezierError) -> Self {
        BSplineError::Bezier(e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    fn check(m: &BSplineError) {
        assert_eq!(cagd_words::check_both(m), Ok(()), "{m:?}");
    }

    #[test]
    fn every_variant_in_both_languages() {
        for m in BSplineError::iter() {
            check(&m);
        }
        // the parts, each inside the sentence that carries it
        for reason in NoDerivative::iter() {
            check(&BSplineError::NoDerivativeCurve { reason });
        }
        for what in Construction::iter() {
            check(&BSplineError::NeedsRoot { what, radicand: 3 });
        }
        for reason in CircleData::iter() {
            check(&BSplineError::NotACircle { reason });
        }
    }
}
