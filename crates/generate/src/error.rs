//! The one error type of cagd-generate.

use cagd_bezier::BezierError;
use cagd_bspline::BSplineError;
use cagd_linalg::LinalgError;
use cagd_poly::PolyError;
use cagd_scalar::ScalarError;
use cagd_spline_surface::SplineSurfaceError;
use cagd_surface::SurfaceError;
use std::fmt;

/// What can go wrong when generating a surface from curves.
///
/// Points and numbers inside the messages are written exactly (`(1/2, 0, 2)`, `√2/2`).
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum GenerateError {
    /// The two curves of a translational surface do not start at the same point a.
    CurvesDoNotMeet {
        /// The first end, as written: `c1(0)`.
        first: String,
        /// Its point, as text.
        first_point: String,
        /// The second end: `d1(0)`.
        second: String,
        /// Its point, as text.
        second_point: String,
    },
    /// Two boundary curves of a Coons patch do not meet at a corner of the curvilinear
    /// quadrilateral (13).
    CornerMismatch {
        /// The corner: `a`, `b`, `c` or `d`.
        corner: char,
        /// The first curve and where it is evaluated: `c1(1)`.
        first_at: String,
        /// The point, as text.
        first_point: String,
        /// The second curve and where it is evaluated: `d2(0)`.
        second_at: String,
        /// The point, as text.
        second_point: String,
    },
    /// A curve in the wrong parameter, e.g. a `d1` that uses `u` (it must be a curve in v).
    WrongVariable {
        /// The curve's name.
        curve: String,
        /// The variable it must use.
        expected: String,
        /// The variable it uses instead.
        found: String,
    },
    /// Two inputs that must live in the same space have different dimensions.
    DimensionMismatch {
        /// The first input's name.
        first: String,
        /// Its dimension.
        first_dim: usize,
        /// The second input's name.
        second: String,
        /// Its dimension.
        second_dim: usize,
    },
    /// A construction that only makes sense in R^3 (cross products, revolution about Z).
    NotSpatial {
        /// What needs R^3.
        what: String,
        /// The name of the input.
        input: String,
        /// Its dimension.
        dim: usize,
    },
    /// A surface that is not given as a ruled parametrization (linear in v).
    NotRuled {
        /// What is wrong, in words.
        detail: String,
    },
    /// The naive projective Coons construction needs the homogeneous boundary curves to meet:
    /// equal weights at each corner.
    CornerWeights {
        /// The corner.
        corner: char,
        /// The first curve.
        first: String,
        /// Its weight at the corner, as text.
        first_weight: String,
        /// The second curve.
        second: String,
        /// Its weight at the corner, as text.
        second_weight: String,
    },
    /// A control point of the generating curve of a surface of revolution outside the XZ plane.
    NotInXzPlane {
        /// The index of the control point.
        index: usize,
        /// The point, as text.
        point: String,
    },
    /// A generating curve of a surface of revolution (given as a polynomial map) whose second
    /// coordinate is not identically zero.
    CurveNotInXzPlane {
        /// The second coordinate, as text.
        y: String,
    },
    /// A construction needs a number that the scalar type cannot hold exactly (√2/2 asked of
    /// exact rationals).
    NeedsQuadraticField {
        /// What needs it.
        what: String,
        /// The number, as text.
        number: String,
        /// The underlying error.
        source: ScalarError,
    },
    /// A circle for the parallels whose control point is not in the XY plane.
    NotACircleOfXy {
        /// The index of the control point.
        index: usize,
        /// The point, as text.
        point: String,
    },
    /// A cosine and sine that are not those of an angle: cos² v + sin² v ≠ 1.
    NotOnUnitCircle {
        /// cos v, as text.
        cos: String,
        /// sin v, as text.
        sin: String,
    },
    /// A B-spline curve that is not clamped where the construction needs clamped curves.
    NotClamped {
        /// The curve's name.
        curve: String,
        /// Its knots, as text.
        knots: String,
    },
    /// Two B-spline curves on different parameter domains.
    DomainMismatch {
        /// The first curve's name.
        first: String,
        /// Its domain, as text.
        first_domain: String,
        /// The second curve's name.
        second: String,
        /// Its domain, as text.
        second_domain: String,
    },
    /// An error of a polynomial computation.
    Poly(PolyError),
    /// An error of a Bézier curve algorithm.
    Bezier(BezierError),
    /// An error of a B-spline or NURBS curve algorithm.
    BSpline(BSplineError),
    /// An error of a surface (mesh shape, weights).
    Surface(SurfaceError),
    /// An error of a B-spline or NURBS surface.
    SplineSurface(SplineSurfaceError),
    /// An error of linear algebra.
    Linalg(LinalgError),
    /// An error of the number types.
    Scalar(ScalarError),
}

impl fmt::Display for GenerateError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GenerateError::CurvesDoNotMeet {
                first,
                first_point,
                second,
                second_point,
            } => write!(
                f,
                "the curves do not meet: {first} = {first_point} but {second} = {second_point}"
            ),
            GenerateError::CornerMismatch {
                corner,
                first_at,
                first_point,
                second_at,
                second_point,
            } => {
                let name = |at: &str| at.split('(').next().unwrap_or_default().to_string();
                write!(
                    f,
                    "curves {} and {} do not meet at corner {corner}: \
                     {first_at} = {first_point}, {second_at} = {second_point}",
                    name(first_at),
                    name(second_at)
                )
            }
            GenerateError::WrongVariable {
                curve,
                expected,
                found,
            } => write!(
                f,
                "{curve} must be a curve in {expected}, but it uses {found}"
            ),
            GenerateError::DimensionMismatch {
                first,
                first_dim,
                second,
                second_dim,
            } => write!(
                f,
                "{first} has {first_dim} coordinates but {second} has {second_dim}: \
                 they must live in the same space"
            ),
            GenerateError::NotSpatial { what, input, dim } => {
                write!(
                    f,
                    "{what} needs points of R^3, but {input} has {dim} coordinates"
                )
            }
            GenerateError::NotRuled { detail } => write!(f, "not a ruled surface: {detail}"),
            GenerateError::CornerWeights {
                corner,
                first,
                first_weight,
                second,
                second_weight,
            } => write!(
                f,
                "the projective (homogeneous) Coons construction needs equal weights at corner \
                 {corner}: {first} has weight {first_weight} there but {second} has \
                 {second_weight} (scale the weights of one curve)"
            ),
            GenerateError::NotInXzPlane { index, point } => write!(
                f,
                "control point c_{index} = {point} is not in the XZ plane (y ≠ 0): a surface of \
                 revolution about the Z axis rotates a curve of the XZ plane"
            ),
            GenerateError::CurveNotInXzPlane { y } => write!(
                f,
                "the curve is not in the XZ plane: its y coordinate is {y}, not 0 (a surface of \
                 revolution about the Z axis rotates a curve (f(u), 0, g(u)))"
            ),
            GenerateError::NeedsQuadraticField {
                what,
                number,
                source,
            } => write!(
                f,
                "{what} needs {number}, which this number type cannot hold exactly: compute in \
                 the quadratic field a + b√d ({source})"
            ),
            GenerateError::NotACircleOfXy { index, point } => write!(
                f,
                "control point {index} of the circle, {point}, is not a point (x, y) or \
                 (x, y, 0) of the XY plane: the parallels need the unit circle about the origin"
            ),
            GenerateError::NotOnUnitCircle { cos, sin } => write!(
                f,
                "cos v = {cos} and sin v = {sin} are not the cosine and sine of an angle: \
                 cos² v + sin² v ≠ 1"
            ),
            GenerateError::NotClamped { curve, knots } => write!(
                f,
                "{curve} is not clamped (knots {knots}): the construction needs curves that \
                 start and end at their end control points (end knots repeated p times)"
            ),
            GenerateError::DomainMismatch {
                first,
                first_domain,
                second,
                second_domain,
            } => write!(
                f,
                "{first} is defined on {first_domain} but {second} on {second_domain}: \
                 reparametrize them onto the same interval"
            ),
            GenerateError::Poly(e) => write!(f, "{e}"),
            GenerateError::BSpline(e) => write!(f, "{e}"),
            GenerateError::Bezier(e) => write!(f, "{e}"),
            GenerateError::Surface(e) => write!(f, "{e}"),
            GenerateError::SplineSurface(e) => write!(f, "{e}"),
            GenerateError::Linalg(e) => write!(f, "{e}"),
            GenerateError::Scalar(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for GenerateError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            GenerateError::Poly(e) => Some(e),
            GenerateError::Bezier(e) => Some(e),
            GenerateError::BSpline(e) => Some(e),
            GenerateError::Surface(e) => Some(e),
            GenerateError::SplineSurface(e) => Some(e),
            GenerateError::Linalg(e) => Some(e),
            GenerateError::Scalar(e) | GenerateError::NeedsQuadraticField { source: e, .. } => {
                Some(e)
            }
            _ => None,
        }
    }
}

impl From<PolyError> for GenerateError {
    fn from(e: PolyError) -> Self {
        GenerateError::Poly(e)
    }
}

impl From<BezierError> for GenerateError {
    fn from(e: BezierError) -> Self {
        GenerateError::Bezier(e)
    }
}

impl From<BSplineError> for GenerateError {
    fn from(e: BSplineError) -> Self {
        GenerateError::BSpline(e)
    }
}

impl From<SurfaceError> for GenerateError {
    fn from(e: SurfaceError) -> Self {
        GenerateError::Surface(e)
    }
}

impl From<SplineSurfaceError> for GenerateError {
    fn from(e: SplineSurfaceError) -> Self {
        GenerateError::SplineSurface(e)
    }
}

impl From<LinalgError> for GenerateError {
    fn from(e: LinalgError) -> Self {
        GenerateError::Linalg(e)
    }
}

impl From<ScalarError> for GenerateError {
    fn from(e: ScalarError) -> Self {
        GenerateError::Scalar(e)
    }
}
