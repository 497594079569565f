//! The one error type of cagd-render.

use cagd_bezier::BezierError;
use cagd_bspline::BSplineError;
use cagd_contract::ProblemError;
use cagd_poly::PolyError;
use cagd_spline_surface::SplineSurfaceError;
use cagd_surface::SurfaceError;
use cagd_words::{said, Lang, Message, Phrase};

/// What can go wrong while building or drawing a figure.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
#[non_exhaustive]
pub enum RenderError {
    /// A Bézier or rational Bézier patch is invalid.
    Surface(SurfaceError),
    /// A B-spline or NURBS surface is invalid.
    SplineSurface(SplineSurfaceError),
    /// A Bézier curve is invalid.
    Bezier(BezierError),
    /// A B-spline or NURBS curve is invalid.
    BSpline(BSplineError),
    /// A closed form could not be computed or evaluated.
    Poly(PolyError),
    /// A problem or answer could not be read or solved (its messages are enumerated with
    /// cagd-problem's).
    #[strum(disabled)]
    Problem(Box<ProblemError>),
    /// The control points are not in the plane or in space.
    Dimension {
        /// What has the wrong dimension (`surface "c"`, `curve "c1"`).
        what: String,
        /// Its dimension.
        dim: usize,
    },
    /// The SVG of a figure could not be rasterized to PNG.
    Raster(String),
    /// A polynomial map uses variables other than those of a curve (one variable) or of a
    /// surface (u and v).
    Variables {
        /// What the map is (`surface "s"`).
        what: String,
        /// The variables it uses, as written (`u, w`).
        found: String,
    },
    /// The denominator of a rational curve or surface vanishes at a sample point: the point is
    /// at infinity and cannot be drawn.
    PointAtInfinity {
        /// What is being drawn.
        what: String,
        /// The parameters, exactly (`(u, v) = (1/2, 1)`).
        at: String,
    },
    /// A sampling density out of range.
    Density {
        /// Which density (`tessellation density`).
        what: &'static str,
        /// The value asked for.
        value: usize,
        /// The smallest value allowed.
        min: usize,
        /// The largest value allowed.
        max: usize,
    },
    /// A coordinate too large, or a figure too small, to draw in floating point.
    Range {
        /// What is being drawn.
        what: String,
        /// Why, with the size met.
        why: String,
    },
    /// There is nothing to draw.
    EmptyScene,
    /// A quantity to plot is empty or cannot be plotted.
    Plot(String),
}

// TODO: `what`, `why`, `Raster` and `Plot` still hold English words (a figure's subject, the
// reason a quantity cannot be plotted): data holes until they are typed.
impl Message for RenderError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            RenderError::Surface(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            RenderError::SplineSurface(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            RenderError::Bezier(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            RenderError::BSpline(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            RenderError::Poly(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            RenderError::Problem(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            RenderError::Range { what, why } => said(
                lang,
                "‹› cannot be drawn: ‹›; figures are drawn in floating point after exact evaluation (give coordinates between 1e-150 and 1e150)",
                "‹› no se puede dibujar: ‹›; las figuras se dibujan en coma flotante tras la evaluación exacta (dé coordenadas entre 1e-150 y 1e150)",
                [what.into(), why.into()],
            ),
            RenderError::Dimension { what, dim } => said(
                lang,
                "‹› has points of dimension ‹›: only points in the plane (2) or in space (3) can be drawn",
                "‹› tiene puntos de dimensión ‹›: solo se pueden dibujar puntos del plano (2) o del espacio (3)",
                [what.into(), dim.into()],
            ),
            RenderError::Raster(e) => said(
                lang,
                "the figure could not be rasterized: ‹›",
                "no se pudo rasterizar la figura: ‹›",
                [e.into()],
            ),
            RenderError::Variables { what, found } => said(
                lang,
                "‹› is written in the variables ‹›: a curve uses one variable, a surface u and v",
                "‹› está escrita en las variables ‹›: una curva usa una variable; una superficie, u y v",
                [what.into(), found.into()],
            ),
            RenderError::PointAtInfinity { what, at } => said(
                lang,
                "‹› has a zero denominator at ‹›: that point is at infinity and cannot be drawn",
                "‹› tiene denominador nulo en ‹›: ese punto está en el infinito y no se puede dibujar",
                [what.into(), at.into()],
            ),
            RenderError::Density {
                what,
                value,
                min,
                max,
            } => said(
                lang,
                "‹› ‹› is out of range: choose ‹› to ‹›",
                "‹› ‹› está fuera de rango: elija de ‹› a ‹›",
                [what.into(), value.into(), min.into(), max.into()],
            ),
            RenderError::EmptyScene => said(
                lang,
                "there is nothing to draw: the figure has no surface and no curve",
                "no hay nada que dibujar: la figura no tiene ninguna superficie ni ninguna curva",
                [],
            ),
            RenderError::Plot(why) => said(
                lang,
                "cannot plot: ‹›",
                "no se puede representar: ‹›",
                [why.into()],
            ),
        }
    }
}

cagd_words::display_english!(RenderError);

impl std::error::Error for RenderError {}

macro_rules! from_error {
    ($($t:ty => $v:ident),* $(,)?) => {
        $(impl From<$t> for RenderError {
            fn from(e: $t) -> Self {
                RenderError::$v(e)
            }
        })*
    };
}

from_error!(
    SurfaceError => Surface,
    SplineSurfaceError => SplineSurface,
    BezierError => Bezier,
    BSplineError => BSpline,
    PolyError => Poly,
);

impl From<ProblemError> for RenderError {
    fn from(e: ProblemError) -> Self {
        RenderError::Problem(Box::new(e))
    }
}

/// Checks a density against its range.
pub(crate) fn check_density(
    what: &'static str,
    value: usize,
    min: usize,
    max: usize,
) -> Result<usize, RenderError> {
    if (min..=max).contains(&value) {
        Ok(value)
    } else {
        Err(RenderError::Density {
            what,
            value,
            min,
            max,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_variant_in_both_languages() {
        for m in RenderError::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
