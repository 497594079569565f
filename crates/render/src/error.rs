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
        what: Drawn,
        /// Its dimension.
        dim: usize,
    },
    /// The SVG of a figure could not be rasterized to PNG.
    Raster(Raster),
    /// A polynomial map uses variables other than those of a curve (one variable) or of a
    /// surface (u and v).
    Variables {
        /// What the map is (`surface "s"`).
        what: Drawn,
        /// The variables it uses, as written (`u, w`).
        found: String,
    },
    /// The denominator of a rational curve or surface vanishes at a sample point: the point is
    /// at infinity and cannot be drawn.
    PointAtInfinity {
        /// What is being drawn.
        what: Drawn,
        /// The parameters, exactly (`(u, v) = (1/2, 1)`).
        at: String,
    },
    /// A sampling density out of range.
    Density {
        /// Which density (`tessellation density`).
        what: Sampling,
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
        what: Drawn,
        /// Why, with the size met.
        why: Magnitude,
    },
    /// The problem is written in letters (a sphere of radius R) and gives no `values`: a
    /// figure needs numbers.
    Letters {
        /// The letters, as written (`R`; `a, b, c, d`).
        letters: String,
        /// How to give them values, as the problem would write it (`"values": {"R": 1}`).
        values: String,
    },
    /// There is nothing to draw.
    EmptyScene,
    /// A quantity to plot is empty or cannot be plotted.
    Plot(Unplotted),
}

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
                "«» cannot be drawn: «»; figures are drawn in floating point after exact evaluation (give coordinates between 1e-150 and 1e150)",
                "«» no se puede dibujar: «»; las figuras se dibujan en coma flotante tras la evaluación exacta (dé coordenadas entre 1e-150 y 1e150)",
                [what.phrase(lang).into(), why.phrase(lang).into()],
            ),
            RenderError::Dimension { what, dim } => said(
                lang,
                "«» has points of dimension ‹›: only points in the plane (2) or in space (3) can be drawn",
                "«» tiene puntos de dimensión ‹›: solo se pueden dibujar puntos del plano (2) o del espacio (3)",
                [what.phrase(lang).into(), dim.into()],
            ),
            RenderError::Raster(e) => said(
                lang,
                "the figure could not be rasterized: «»",
                "no se pudo rasterizar la figura: «»",
                [e.phrase(lang).into()],
            ),
            RenderError::Variables { what, found } => said(
                lang,
                "«» is written in the variables ‹›: a curve uses one variable, a surface u and v",
                "«» usa las variables ‹›: una curva usa una variable; una superficie, u y v",
                [what.phrase(lang).into(), found.into()],
            ),
            RenderError::PointAtInfinity { what, at } => said(
                lang,
                "«» has a zero denominator at ‹›: that point is at infinity and cannot be drawn",
                "«» tiene denominador nulo en ‹›: ese punto está en el infinito y no se puede dibujar",
                [what.phrase(lang).into(), at.into()],
            ),
            RenderError::Density {
                what,
                value,
                min,
                max,
            } => said(
                lang,
                "«» ‹› is out of range: choose ‹› to ‹›",
                "«» ‹› está fuera de rango: elija de ‹› a ‹›",
                [what.phrase(lang).into(), value.into(), min.into(), max.into()],
            ),
            RenderError::Letters { letters, values } => said(
                lang,
                "the problem is written in letters (‹›) and a figure needs numbers: give the values to draw it at in the problem, as ‹›",
                "el problema está escrito con letras (‹›) y una figura necesita números: dé en el problema los valores en que dibujarla, así: ‹›",
                [letters.into(), values.into()],
            ),
            RenderError::EmptyScene => said(
                lang,
                "there is nothing to draw: the figure has no surface and no curve",
                "no hay nada que dibujar: la figura no tiene ninguna superficie ni ninguna curva",
                [],
            ),
            RenderError::Plot(why) => said(
                lang,
                "cannot plot: «»",
                "no se puede representar: «»",
                [why.phrase(lang).into()],
            ),
        }
    }
}

cagd_words::display_english!(RenderError);

/// What a figure's error speaks of: a surface or curve of the scene by its name, the surface
/// of a curvature plot, a polynomial plotted, the figure as a whole.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum Drawn {
    /// A surface of the scene: `surface "c"` (its name quoted).
    Surface {
        /// Its name in the scene.
        name: String,
    },
    /// A curve of the scene: `curve "c1"`.
    Curve {
        /// Its name in the scene.
        name: String,
    },
    /// A polynomial curve whose control polygon is drawn.
    PolynomialCurve,
    /// The surface whose Gaussian curvature is plotted.
    CurvatureSurface,
    /// A polynomial plotted.
    Polynomial {
        /// The polynomial, as text.
        text: String,
    },
    /// The figure as a whole.
    #[default]
    Figure,
    /// A surface or curve at a parameter outside its domain.
    OutsideDomain(Box<Drawn>),
}

impl Message for Drawn {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Drawn::Surface { name } => said(
                lang,
                "surface ‹›",
                "la superficie ‹›",
                [(&format!("{name:?}")).into()],
            ),
            Drawn::Curve { name } => said(
                lang,
                "curve ‹›",
                "la curva ‹›",
                [(&format!("{name:?}")).into()],
            ),
            Drawn::PolynomialCurve => said(lang, "a polynomial curve", "una curva polinómica", []),
            Drawn::CurvatureSurface => said(
                lang,
                "the surface of the Gaussian curvature",
                "la superficie de la curvatura de Gauss",
                [],
            ),
            Drawn::Polynomial { text } => {
                said(lang, "the polynomial ‹›", "el polinomio ‹›", [text.into()])
            }
            Drawn::Figure => said(lang, "the figure", "la figura", []),
            Drawn::OutsideDomain(what) => said(
                lang,
                "«» (outside its domain)",
                "«» (fuera de su dominio)",
                [what.phrase(lang).into()],
            ),
        }
    }
}

/// Which sampling density is out of range.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, strum::EnumIter)]
pub enum Sampling {
    /// The cells of a tessellation per direction (OBJ, STL).
    #[default]
    Tessellation,
    /// The samples of a plotted polynomial.
    Samples,
    /// The isoparametric lines per direction of a figure.
    Isolines,
    /// The samples per cell edge of a figure.
    SamplesPerCell,
    /// The cells per direction of a curvature grid.
    CurvatureGrid,
}

impl Message for Sampling {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Sampling::Tessellation => {
                said(lang, "tessellation density", "la densidad del teselado", [])
            }
            Sampling::Samples => said(lang, "number of samples", "el número de muestras", []),
            Sampling::Isolines => said(
                lang,
                "number of isolines",
                "el número de líneas isoparamétricas",
                [],
            ),
            Sampling::SamplesPerCell => said(
                lang,
                "samples per cell",
                "el número de muestras por celda",
                [],
            ),
            Sampling::CurvatureGrid => said(
                lang,
                "curvature grid size",
                "el tamaño de la rejilla de curvatura",
                [],
            ),
        }
    }
}

/// Why a figure is beyond floating point.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum Magnitude {
    /// A coordinate of this size (beyond 1e150).
    Coordinate {
        /// The size, as `1.5e200`.
        size: String,
    },
    /// A coordinate beyond f64 altogether.
    CoordinateBeyondF64,
    /// Every point of the figure within this extent of one point.
    Extent {
        /// The extent, as `1e-200`.
        size: String,
    },
    /// A tessellation whose points are all equal in floating point.
    #[default]
    PointsEqual,
}

impl Message for Magnitude {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Magnitude::Coordinate { size } => said(
                lang,
                "a coordinate is ‹›",
                "una coordenada vale ‹›",
                [size.into()],
            ),
            Magnitude::CoordinateBeyondF64 => said(
                lang,
                "a coordinate is beyond 1e308",
                "una coordenada pasa de 1e308",
                [],
            ),
            Magnitude::Extent { size } => said(
                lang,
                "its extent is ‹› in floating point",
                "su extensión es ‹› en coma flotante",
                [size.into()],
            ),
            Magnitude::PointsEqual => said(
                lang,
                "its points are equal in floating point (an extent below 1e-150)",
                "sus puntos son iguales en coma flotante (una extensión menor que 1e-150)",
                [],
            ),
        }
    }
}

/// Why the SVG of a figure is not rasterized.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum Raster {
    /// The rasterizer's own words (resvg's, in English: data).
    Library(String),
    /// A scale that leaves no pixel.
    Scale {
        /// The scale asked.
        scale: String,
    },
    /// A figure of no area.
    #[default]
    NoArea,
}

impl Message for Raster {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Raster::Library(words) => said(lang, "‹›", "‹›", [words.into()]),
            Raster::Scale { scale } => said(
                lang,
                "cannot scale the figure by ‹›",
                "no se puede escalar la figura por ‹›",
                [scale.into()],
            ),
            Raster::NoArea => said(
                lang,
                "the figure has no area",
                "la figura no tiene área",
                [],
            ),
        }
    }
}

/// Why a quantity is not plotted.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum Unplotted {
    /// An empty interval.
    EmptyInterval {
        /// Its start.
        from: String,
        /// Its end.
        to: String,
    },
    /// No weights to plot.
    #[default]
    NoWeights,
    /// A sample point that no piece of the surface holds.
    NoPiece {
        /// The point, `(u, v) = (1/2, 1)`.
        at: String,
    },
    /// A normal of a surface not in space.
    NormalNeedsSpace,
}

impl Message for Unplotted {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Unplotted::EmptyInterval { from, to } => said(
                lang,
                "the interval [‹›, ‹›] is empty",
                "el intervalo [‹›, ‹›] es vacío",
                [from.into(), to.into()],
            ),
            Unplotted::NoWeights => said(lang, "there are no weights", "no hay pesos", []),
            Unplotted::NoPiece { at } => said(
                lang,
                "no piece of the surface holds ‹›",
                "ningún trozo de la superficie contiene ‹›",
                [at.into()],
            ),
            Unplotted::NormalNeedsSpace => said(
                lang,
                "the normal needs points in space",
                "la normal necesita puntos del espacio",
                [],
            ),
        }
    }
}

cagd_words::display_english!(Drawn, Sampling, Magnitude, Raster, Unplotted);

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
    what: Sampling,
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
        for m in Drawn::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        for m in Sampling::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        for m in Magnitude::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        for m in Raster::iter() {
            let m = match m {
                // the rasterizer's words are data, in English
                Raster::Library(_) => Raster::Library("svg".into()),
                other => other,
            };
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
        for m in Unplotted::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
