//! The one error type of cagd-render.

use cagd_bezier::BezierError;
use cagd_bspline::BSplineError;
use cagd_poly::PolyError;
use cagd_problem::ProblemError;
use cagd_spline_surface::SplineSurfaceError;
use cagd_surface::SurfaceError;
use std::fmt;

/// What can go wrong while building or drawing a figure.
#[derive(Debug, Clone, PartialEq, Eq)]
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
    /// A problem or answer could not be read or solved.
    Problem(ProblemError),
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

impl fmt::Display for RenderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RenderError::Surface(e) => write!(f, "{e}"),
            RenderError::SplineSurface(e) => write!(f, "{e}"),
            RenderError::Bezier(e) => write!(f, "{e}"),
            RenderError::BSpline(e) => write!(f, "{e}"),
            RenderError::Poly(e) => write!(f, "{e}"),
            RenderError::Problem(e) => write!(f, "{e}"),
            RenderError::Range { what, why } => write!(
                f,
                "{what} cannot be drawn: {why}; figures are drawn in floating point after \
                 exact evaluation (give coordinates between 1e-150 and 1e150)"
            ),
            RenderError::Dimension { what, dim } => write!(
                f,
                "{what} has points of dimension {dim}: only points in the plane (2) or in space \
                 (3) can be drawn"
            ),
            RenderError::Raster(e) => write!(f, "the figure could not be rasterized: {e}"),
            RenderError::Variables { what, found } => write!(
                f,
                "{what} is written in the variables {found}: a curve uses one variable, a \
                 surface u and v"
            ),
            RenderError::PointAtInfinity { what, at } => write!(
                f,
                "{what} has a zero denominator at {at}: that point is at infinity and cannot be \
                 drawn"
            ),
            RenderError::Density {
                what,
                value,
                min,
                max,
            } => write!(f, "{what} {value} is out of range: choose {min} to {max}"),
            RenderError::EmptyScene => {
                write!(
                    f,
                    "there is nothing to draw: the figure has no surface and no curve"
                )
            }
            RenderError::Plot(why) => write!(f, "cannot plot: {why}"),
        }
    }
}

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
    ProblemError => Problem,
);

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
