//! The surface operations' own sentences, chapters 5 and 6: their errors, their remarks and
//! the sentences they compute as results (where the numerator of the Gaussian curvature
//! vanishes). The order and the failing condition of a continuity and the degenerate normals
//! at the corners are cagd-surface's own ([`cagd_surface::Smoothness`],
//! [`cagd_surface::ConditionFails`], [`cagd_surface::DegenerateCorner`]), carried as they are.

use super::inner::Inner;
use cagd_words::{said, Lang, Message, Phrase};

/// The surface operations' own sentences, chapters 5 and 6 (errors, remarks, and sentences
/// computed as results).
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum Surface {
    // --- evaluation, restriction, elevation, derivatives (chapter 5) ---
    /// A restriction asked of a surface that is not a Bézier patch.
    RestrictionNeedsBezier,
    /// A parameter of `evaluate` given as one number.
    TwoParametersFoundNumber,
    /// A weight of a restricted rational patch is zero: the weight function vanishes at a
    /// corner of [u0, u1] × [v0, v1].
    RestrictedZeroWeight {
        row: usize,
        col: usize,
        u0: String,
        u1: String,
        v0: String,
        v1: String,
    },
    /// `by` or `order` given as one number.
    ListRsFoundNumber { found: String },
    /// `degree` of a graph given as one number.
    TwoIntegersFoundNumber { found: String },
    /// Degree elevation of an expression.
    ElevationNeedsMesh,
    /// The derivative of a rational patch where its weight vanishes.
    DerivativeUndefined { because: Inner },
    /// `closed_form` without a `surface` or a `curve`.
    ClosedFormNeeds,
    /// Knot insertion into a surface that is not a B-spline or NURBS surface.
    KnotInsertionNeedsBSpline,

    // --- the continuity of two patches ---
    /// `continuity` of one surface given with another key of two.
    OneSurfaceKnotLines,
    /// `lengths` given for B-spline or NURBS surfaces.
    SplineLengths,
    /// `continuity` of patches that are not polynomial Bézier patches.
    ContinuityTakes,
    /// (Remark.) The first patch elevated along the border to the second's degree.
    FirstElevated {
        first: usize,
        second: usize,
        along: String,
        across: String,
    },
    /// (Remark.) The second patch elevated along the border to the first's degree.
    SecondElevated {
        first: usize,
        second: usize,
        along: String,
        across: String,
    },

    // --- subdivision and knot removal of B-spline and NURBS surfaces ---
    /// Knot removal from a surface that is not a B-spline or NURBS surface.
    KnotRemovalNeedsSpline,

    // --- the constructions (chapter 6) ---
    /// An expression among curves not all expressions or Bézier curves.
    CurvesAsExpressions,
    /// Bézier and B-spline curves together.
    MixingBezierBSpline,
    /// A B-spline curve was expected.
    ExpectedBSplineCurve,
    /// A Bézier curve was expected.
    ExpectedBezierCurve,
    /// Two curves were expected.
    ExpectedTwoCurves,
    /// Four curves were expected.
    ExpectedFourCurves,
    /// The developability test of curves that are not polynomial.
    DevelopableCurves,
    /// The developability test of a surface that is neither a ruled patch nor an expression.
    DevelopableSurface,
    /// `quadrant` and `sweep` together.
    QuadrantOrSweep,
    /// `start` without `sweep`.
    StartWithSweep,
    /// A quadrant above 3.
    NotAQuadrant { quadrant: u64 },
    /// A quadrant with more than one arc.
    QuadrantArcs { arcs: usize },
    /// The Coons patch of rational curves.
    CoonsRational,
    /// A sweep angle for a profile given as an expression.
    ProfileSweep,

    // --- where the numerator G of the Gaussian curvature vanishes ---
    /// (Result.) G ≡ 0.
    GEverywhere,
    /// (Result.) G > 0, its Bernstein coefficients on the domain all positive.
    GPositive,
    /// (Result.) G < 0, its Bernstein coefficients on the domain all negative.
    GNegative,
    /// (Result.) G > 0, on each of `rectangles` rectangles.
    GPositiveCut { rectangles: usize },
    /// (Result.) G < 0, on each of `rectangles` rectangles.
    GNegativeCut { rectangles: usize },
    /// (Result.) G = 0 at the point `at`.
    GZeroAt { at: String },
    /// (Result.) G > 0 at `positive` and G < 0 at `negative`.
    GSignChange { positive: String, negative: String },
    /// (Result.) The signs depend on the letters.
    GUndecidedLetters,
    /// (Result.) Not decided within `halvings` halvings.
    GUndecided { halvings: usize },
    /// (Result.) One strict sign on each piece, not the same on all.
    GMixed,
}

impl Message for Surface {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Surface::RestrictionNeedsBezier => said(
                lang,
                "restriction needs a Bézier patch (`bezier`); for a B-spline surface, split it into Bézier patches first",
                "la restricción necesita una superficie de Bézier (`bezier`); una superficie B-spline se divide antes en trozos de Bézier",
                [],
            ),
            Surface::TwoParametersFoundNumber => said(
                lang,
                "expected two numbers [u, v] (a surface takes two parameters), found a number",
                "se esperaban dos números [u, v] (una superficie tiene dos parámetros), se encontró un número",
                [],
            ),
            Surface::RestrictedZeroWeight {
                row,
                col,
                u0,
                u1,
                v0,
                v1,
            } => said(
                lang,
                "the restricted patch's weight $w_‹›,‹›$ is zero: the weight function of the patch vanishes at that corner of [‹›, ‹›] x [‹›, ‹›], so the restriction has a point at infinity there",
                "el peso $w_‹›,‹›$ de la superficie restringida es nulo: la función peso de la superficie se anula en esa esquina de [‹›, ‹›] x [‹›, ‹›], así que la restricción tiene ahí un punto del infinito",
                [
                    row.into(),
                    col.into(),
                    u0.into(),
                    u1.into(),
                    v0.into(),
                    v1.into(),
                ],
            ),
            Surface::ListRsFoundNumber { found } => said(
                lang,
                "expected a list [r, s], found the number ‹›",
                "se esperaba una lista [r, s], se encontró el número ‹›",
                [found.into()],
            ),
            Surface::TwoIntegersFoundNumber { found } => said(
                lang,
                "expected two integers [m, n], found the number ‹›",
                "se esperaban dos enteros [m, n], se encontró el número ‹›",
                [found.into()],
            ),
            Surface::ElevationNeedsMesh => said(
                lang,
                "degree elevation needs a control mesh (`bezier` or `bspline`)",
                "la elevación del grado necesita una malla de control (`bezier` o `bspline`)",
                [],
            ),
            Surface::DerivativeUndefined { because } => said(
                lang,
                "the derivative is not defined there: «»",
                "la derivada no está definida ahí: «»",
                [because.phrase(lang).into()],
            ),
            Surface::ClosedFormNeeds => said(
                lang,
                "closed_form needs a `surface` or a `curve`",
                "`closed_form` necesita una superficie (`surface`) o una curva (`curve`)",
                [],
            ),
            Surface::KnotInsertionNeedsBSpline => said(
                lang,
                "knot insertion needs a B-spline surface (`bspline`, `knots`)",
                "el algoritmo de inserción necesita una superficie B-spline (`bspline`, `knots`)",
                [],
            ),
            Surface::OneSurfaceKnotLines => said(
                lang,
                "continuity of one `surface` is across its own knot lines: give either `surface` or `first` and `second`",
                "la continuidad de una sola superficie (`surface`) se estudia a través de sus propias líneas de nudos: dé o bien `surface` o bien `first` y `second`",
                [],
            ),
            Surface::SplineLengths => said(
                lang,
                "a B-spline or NURBS surface is joined in its own parameters (its spans give the lengths): leave out `lengths`",
                "una superficie B-spline o NURBS se une en sus propios parámetros (sus intervalos dan las longitudes): quite `lengths`",
                [],
            ),
            Surface::ContinuityTakes => said(
                lang,
                "continuity takes two polynomial Bézier patches (`bezier`, no weights), or B-spline or NURBS surfaces",
                "la continuidad se estudia entre dos superficies de Bézier polinómicas (`bezier`, sin pesos), o entre superficies B-spline o NURBS",
                [],
            ),
            Surface::FirstElevated {
                first,
                second,
                along,
                across,
            } => said(
                lang,
                "the first patch has degree ‹› along the border ($‹›$) and the second ‹›: the first was elevated to degree ‹› in $‹›$ before comparing (the border $‹› = 1$ is the same curve)",
                "la primera superficie tiene grado ‹› a lo largo del borde ($‹›$) y la segunda ‹›: se ha elevado la primera a grado ‹› en $‹›$ antes de comparar (el borde $‹› = 1$ es la misma curva)",
                [
                    first.into(),
                    along.into(),
                    second.into(),
                    second.into(),
                    along.into(),
                    across.into(),
                ],
            ),
            Surface::SecondElevated {
                first,
                second,
                along,
                across,
            } => said(
                lang,
                "the second patch has degree ‹› along the border ($‹›$) and the first ‹›: the second was elevated to degree ‹› in $‹›$ before comparing (the border $‹› = 0$ is the same curve)",
                "la segunda superficie tiene grado ‹› a lo largo del borde ($‹›$) y la primera ‹›: se ha elevado la segunda a grado ‹› en $‹›$ antes de comparar (el borde $‹› = 0$ es la misma curva)",
                [
                    second.into(),
                    along.into(),
                    first.into(),
                    first.into(),
                    along.into(),
                    across.into(),
                ],
            ),
            Surface::KnotRemovalNeedsSpline => said(
                lang,
                "knot removal needs a B-spline or NURBS surface (`bspline`, `knots`)",
                "quitar un nudo requiere una superficie B-spline o NURBS (`bspline`, `knots`)",
                [],
            ),
            Surface::CurvesAsExpressions => said(
                lang,
                "give all the curves as expressions or polynomial Bézier curves when one is an expression",
                "cuando una curva es una expresión, dé todas como expresiones o como curvas de Bézier polinómicas",
                [],
            ),
            Surface::MixingBezierBSpline => said(
                lang,
                "mixing Bézier and B-spline curves: write the Bézier ones as B-splines (knots [0, ..., 0, 1, ..., 1])",
                "se mezclan curvas de Bézier y B-spline: escriba las de Bézier como B-splines (nudos [0, ..., 0, 1, ..., 1])",
                [],
            ),
            Surface::ExpectedBSplineCurve => said(
                lang,
                "expected a B-spline curve",
                "se esperaba una curva B-spline",
                [],
            ),
            Surface::ExpectedBezierCurve => said(
                lang,
                "expected a Bézier curve",
                "se esperaba una curva de Bézier",
                [],
            ),
            Surface::ExpectedTwoCurves => {
                said(lang, "expected two curves", "se esperaban dos curvas", [])
            }
            Surface::ExpectedFourCurves => {
                said(lang, "expected four curves", "se esperaban cuatro curvas", [])
            }
            Surface::DevelopableCurves => said(
                lang,
                "the developability test takes polynomial curves (expressions or Bézier curves)",
                "el criterio de desarrollabilidad necesita curvas polinómicas (expresiones o curvas de Bézier)",
                [],
            ),
            Surface::DevelopableSurface => said(
                lang,
                "the developability test takes a ruled Bézier patch of bidegree $(m, 1)$ or a parametric surface",
                "el criterio de desarrollabilidad necesita una superficie de Bézier reglada de bigrado $(m, 1)$ o una superficie paramétrica",
                [],
            ),
            Surface::QuadrantOrSweep => said(
                lang,
                "a quadrant or a `sweep` angle, not both (a quadrant q is `start` 90 q, `sweep` 90)",
                "un cuadrante o un ángulo `sweep`, pero no ambos (el cuadrante q es `start` 90 q, `sweep` 90)",
                [],
            ),
            Surface::StartWithSweep => said(
                lang,
                "a start angle goes with a `sweep` angle",
                "un ángulo inicial (`start`) va con un ángulo `sweep`",
                [],
            ),
            Surface::NotAQuadrant { quadrant } => said(
                lang,
                "‹› is not a quadrant: 0 to 3, counterclockwise from the x axis",
                "‹› no es un cuadrante: de 0 a 3, en sentido antihorario desde el eje x",
                [quadrant.into()],
            ),
            Surface::QuadrantArcs { arcs } => said(
                lang,
                "a quadrant is for `arcs` = 1; ‹› arcs make the full turn",
                "un cuadrante es para `arcs` = 1; ‹› arcos dan la vuelta completa",
                [arcs.into()],
            ),
            Surface::CoonsRational => said(
                lang,
                "the Coons patch of rational curves has no mesh and weights of its own (notes §5: the projective construction can give zero or negative weights); give polynomial curves",
                "la superficie de Coons de curvas racionales no tiene malla de control ni pesos propios (apuntes §5: la construcción proyectiva puede dar pesos nulos o negativos); dé curvas polinómicas",
                [],
            ),
            Surface::ProfileSweep => said(
                lang,
                "a profile given as an expression turns by the parametrization $(f(u) cos v, f(u) sin v, g(u))$ of any angle v: a sweep angle is for profiles given by control points",
                "un perfil dado por una expresión gira según la parametrización $(f(u) cos v, f(u) sin v, g(u))$ con cualquier ángulo v: un ángulo de barrido (`sweep`) es para perfiles dados por puntos de control",
                [],
            ),
            Surface::GEverywhere => said(
                lang,
                "$G ≡ 0$ on the domain: $K = 0$, the surface is developable (8)",
                "$G ≡ 0$ en el recinto: $K = 0$, la superficie es desarrollable (8)",
                [],
            ),
            Surface::GPositive => said(
                lang,
                "$G > 0$ on the whole domain (its Bernstein coefficients on the domain are all positive): $K > 0$, the surface is elliptic there",
                "$G > 0$ en todo el recinto (sus coeficientes de Bernstein en el recinto son todos positivos): $K > 0$, la superficie es elíptica ahí",
                [],
            ),
            Surface::GNegative => said(
                lang,
                "$G < 0$ on the whole domain (its Bernstein coefficients on the domain are all negative): $K < 0$, the surface is hyperbolic there",
                "$G < 0$ en todo el recinto (sus coeficientes de Bernstein en el recinto son todos negativos): $K < 0$, la superficie es hiperbólica ahí",
                [],
            ),
            Surface::GPositiveCut { rectangles } => said(
                lang,
                "$G > 0$ on the whole domain (its Bernstein coefficients are all positive on each of the ‹› rectangles the domain was cut into): $K > 0$, the surface is elliptic there",
                "$G > 0$ en todo el recinto (sus coeficientes de Bernstein son todos positivos en cada uno de los ‹› rectángulos en que se dividió el recinto): $K > 0$, la superficie es elíptica ahí",
                [rectangles.into()],
            ),
            Surface::GNegativeCut { rectangles } => said(
                lang,
                "$G < 0$ on the whole domain (its Bernstein coefficients are all negative on each of the ‹› rectangles the domain was cut into): $K < 0$, the surface is hyperbolic there",
                "$G < 0$ en todo el recinto (sus coeficientes de Bernstein son todos negativos en cada uno de los ‹› rectángulos en que se dividió el recinto): $K < 0$, la superficie es hiperbólica ahí",
                [rectangles.into()],
            ),
            Surface::GZeroAt { at } => said(
                lang,
                "$G$ vanishes on the domain: $G = 0$ at $(u, v) = ‹›$",
                "$G$ se anula en el recinto: $G = 0$ en $(u, v) = ‹›$",
                [at.into()],
            ),
            Surface::GSignChange { positive, negative } => said(
                lang,
                "$G$ vanishes on the domain: $G > 0$ at $(u, v) = ‹›$ and $G < 0$ at $(u, v) = ‹›$, so $G = 0$ somewhere on the segment between them",
                "$G$ se anula en el recinto: $G > 0$ en $(u, v) = ‹›$ y $G < 0$ en $(u, v) = ‹›$, así que $G = 0$ en algún punto del segmento que los une",
                [positive.into(), negative.into()],
            ),
            Surface::GUndecidedLetters => said(
                lang,
                "where $G$ vanishes is not decided: the signs of its Bernstein coefficients depend on the letters",
                "no se decide dónde se anula $G$: los signos de sus coeficientes de Bernstein dependen de las letras",
                [],
            ),
            Surface::GUndecided { halvings } => said(
                lang,
                "where $G$ vanishes is not decided within ‹› halvings of the domain: on some rectangle the Bernstein coefficients of $G$ have both signs, and no corner gave a zero or a change of sign",
                "no se decide dónde se anula $G$ en ‹› divisiones por la mitad del recinto: en algún rectángulo los coeficientes de Bernstein de $G$ tienen ambos signos, y ninguna esquina dio un cero ni un cambio de signo",
                [halvings.into()],
            ),
            Surface::GMixed => said(
                lang,
                "$G$ has no zero inside any piece, but it is positive on some pieces and negative on others: it jumps across a knot line, where the second derivatives of the surface jump",
                "$G$ no tiene ceros dentro de ningún trozo, pero es positivo en unos trozos y negativo en otros: salta a través de una línea de nudos, donde saltan las segundas derivadas de la superficie",
                [],
            ),
        }
    }
}

cagd_words::display_english!(Surface);

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_variant_in_both_languages() {
        for m in Surface::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
