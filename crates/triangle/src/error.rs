//! The one error type of the crate.

use cagd_words::{said, Lang, Message, Phrase};

/// What can go wrong with a triangular Bézier patch.
///
/// Every message names the offending value so that a student can find it in the input.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
#[non_exhaustive]
pub enum TriangleError {
    /// The control net does not have (n + 1)(n + 2)/2 points.
    WrongPointCount {
        /// The degree n asked for.
        degree: usize,
        /// (n + 1)(n + 2)/2.
        needed: usize,
        /// How many points were given.
        found: usize,
    },
    /// The degree is so large that (n + 1)(n + 2)/2 does not fit in memory addresses.
    DegreeTooLarge {
        /// The degree asked for (as text, since it may be the sum of two degrees).
        degree: String,
    },
    /// Two control points have different dimensions.
    MixedDimensions {
        /// The multi-index (i, j, k) of the first point whose dimension differs.
        index: (usize, usize, usize),
        /// Its dimension.
        found: usize,
        /// The dimension of b_{n,0,0}, the first point.
        expected: usize,
    },
    /// Barycentric coordinates (r, s, t) must satisfy r + s + t = 1.
    BarycentricSum {
        /// The coordinates, as text.
        coords: String,
        /// Their sum, as text.
        sum: String,
    },
    /// A direction (a barycentric vector) must have components summing to 0.
    DirectionSum {
        /// The components, as text.
        components: String,
        /// Their sum, as text.
        sum: String,
    },
    /// (i, j, k) is not a multi-index of the degree: i + j + k ≠ n.
    NotAnIndex {
        /// The multi-index asked for.
        index: (usize, usize, usize),
        /// The degree n of the patch.
        degree: usize,
    },
    /// The blossom of a degree-n patch takes exactly n arguments.
    BlossomArity {
        /// The degree n of the patch.
        degree: usize,
        /// How many arguments were given.
        found: usize,
    },
    /// A computation that needs points of R^3 (the normal vector, a cross product) was asked
    /// of a patch in another dimension.
    DimensionNotThree {
        /// What was being computed.
        what: Spatial,
        /// The dimension of the control points.
        found: usize,
    },
    /// A closed form given to build a patch uses variables other than u and v.
    NotInUV {
        /// The other variables, comma-separated.
        vars: String,
    },
    /// A closed form has a total degree higher than the degree asked for.
    DegreeTooHigh {
        /// The total degree of the polynomial map.
        found: usize,
        /// The degree n of the patch asked for.
        degree: usize,
    },
}

/// What needs control points in R^3 ([`TriangleError::DimensionNotThree`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Spatial {
    /// The normal vector, a cross product of two directional derivatives.
    #[default]
    NormalVector,
}

impl Message for Spatial {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Spatial::NormalVector => said(lang, "the normal vector", "el vector normal", []),
        }
    }
}

impl Message for TriangleError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            TriangleError::WrongPointCount {
                degree,
                needed,
                found,
            } => said(
                lang,
                "a triangular patch of degree ‹› needs $(‹› + 1)(‹› + 2)/2$ = ‹› control points, found ‹›",
                "una superficie triangular de grado ‹› necesita $(‹› + 1)(‹› + 2)/2$ = ‹› puntos de control, se encontraron ‹›",
                [
                    degree.into(),
                    degree.into(),
                    degree.into(),
                    needed.into(),
                    found.into(),
                ],
            ),
            TriangleError::DegreeTooLarge { degree } => said(
                lang,
                "degree ‹› is too large: its $(n + 1)(n + 2)/2$ control points cannot be stored",
                "el grado ‹› es demasiado grande: sus $(n + 1)(n + 2)/2$ puntos de control no caben en memoria",
                [degree.into()],
            ),
            TriangleError::MixedDimensions {
                index: (i, j, k),
                found,
                expected,
            } => said(
                lang,
                "control point $b_{‹›,‹›,‹›}$ has dimension ‹›, but the first control point has dimension ‹›: all control points need the same dimension",
                "el punto de control $b_{‹›,‹›,‹›}$ tiene dimensión ‹›, pero el primer punto de control tiene dimensión ‹›: todos los puntos de control han de tener la misma dimensión",
                [i.into(), j.into(), k.into(), found.into(), expected.into()],
            ),
            TriangleError::BarycentricSum { coords, sum } => said(
                lang,
                "barycentric coordinates ‹› sum to ‹›, not 1 ($r + s + t = 1$ is needed)",
                "las coordenadas baricéntricas ‹› suman ‹›, no 1 (se necesita $r + s + t = 1$)",
                [coords.into(), sum.into()],
            ),
            TriangleError::DirectionSum { components, sum } => said(
                lang,
                "direction ‹› has components summing to ‹›, not 0 (a direction is a difference of two barycentric points)",
                "la dirección ‹› tiene componentes que suman ‹›, no 0 (una dirección es la diferencia de dos puntos baricéntricos)",
                [components.into(), sum.into()],
            ),
            TriangleError::NotAnIndex {
                index: (i, j, k),
                degree,
            } => said(
                lang,
                "$b_{‹›,‹›,‹›}$ is not a control point of a patch of degree ‹›: $‹› + ‹› + ‹› = ‹›$, not ‹›",
                "$b_{‹›,‹›,‹›}$ no es un punto de control de una superficie de grado ‹›: $‹› + ‹› + ‹› = ‹›$, no ‹›",
                [
                    i.into(),
                    j.into(),
                    k.into(),
                    degree.into(),
                    i.into(),
                    j.into(),
                    k.into(),
                    (&(i + j + k)).into(),
                    degree.into(),
                ],
            ),
            TriangleError::BlossomArity { degree, found } => {
                if *degree == 1 {
                    said(
                        lang,
                        "the blossom of a patch of degree ‹› takes ‹› argument, found ‹›",
                        "la forma polar de una superficie de grado ‹› toma ‹› argumento, se encontraron ‹›",
                        [degree.into(), degree.into(), found.into()],
                    )
                } else {
                    said(
                        lang,
                        "the blossom of a patch of degree ‹› takes ‹› arguments, found ‹›",
                        "la forma polar de una superficie de grado ‹› toma ‹› argumentos, se encontraron ‹›",
                        [degree.into(), degree.into(), found.into()],
                    )
                }
            }
            TriangleError::DimensionNotThree { what, found } => said(
                lang,
                "«» needs control points in $R^3$, but they have dimension ‹›",
                "«» necesita puntos de control en $R^3$, pero tienen dimensión ‹›",
                [what.phrase(lang).into(), found.into()],
            ),
            TriangleError::NotInUV { vars } => said(
                lang,
                "a triangular patch is a polynomial map in u and v only, but the map also uses ‹›",
                "una superficie triangular es una aplicación polinómica solo en u y v, pero la aplicación usa también ‹›",
                [vars.into()],
            ),
            TriangleError::DegreeTooHigh { found, degree } => said(
                lang,
                "the polynomial map has total degree ‹›, more than the degree ‹› of the patch asked for (ask for degree ‹› or more)",
                "la aplicación polinómica tiene grado total ‹›, mayor que el grado ‹› de la superficie pedida (pida grado ‹› o mayor)",
                [found.into(), degree.into(), found.into()],
            ),
        }
    }
}

cagd_words::display_english!(TriangleError, Spatial);

impl std::error::Error for TriangleError {}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_variant_in_both_languages() {
        for m in TriangleError::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        for what in Spatial::iter() {
            let m = TriangleError::DimensionNotThree { what, found: 2 };
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        let one = TriangleError::BlossomArity {
            degree: 1,
            found: 2,
        };
        assert_eq!(
            one.to_string(),
            "the blossom of a patch of degree 1 takes 1 argument, found 2"
        );
        assert_eq!(cagd_words::check_both(&one), Ok(()));
    }
}
