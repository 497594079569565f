//! The one error type of cagd-fit.

use cagd_bezier::BezierError;
use cagd_bspline::BSplineError;
use cagd_linalg::LinalgError;
use std::fmt;

/// What can go wrong when fitting a curve to data.
///
/// Numbers inside the messages are written exactly (`1/2`, `√2/2`); indices are those of the
/// data as given (a_0, a_1, ... and u_0, u_1, ...).
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum FitError {
    /// No data points at all.
    NoData,
    /// A different number of parameters than data points.
    CountMismatch {
        /// The number of data points.
        points: usize,
        /// The number of parameters.
        parameters: usize,
    },
    /// Data point `index` has another dimension than data point 0 (or than the end tangents).
    DimensionMismatch {
        /// What has the wrong dimension, in words ("data point 2", "the start tangent").
        what: String,
        /// The dimension of data point 0.
        expected: usize,
        /// The dimension found.
        found: usize,
    },
    /// Two data points share one parameter: the interpolation system is singular.
    RepeatedParameter {
        /// The first index with that parameter.
        first: usize,
        /// The second index with that parameter.
        second: usize,
        /// The shared parameter, as text.
        value: String,
    },
    /// The knots of a spline interpolant do not increase strictly.
    NotIncreasing {
        /// The index of the knot that is not greater than the one before it.
        index: usize,
        /// The knot before, as text.
        before: String,
        /// The knot at `index`, as text.
        value: String,
    },
    /// Fewer data than the method needs.
    TooFewPoints {
        /// What needs them, in words.
        what: String,
        /// How many are needed.
        needed: usize,
        /// How many were given.
        found: usize,
    },
    /// Least squares of degree n with fewer than n + 1 distinct parameters: the Bernstein
    /// collocation matrix has dependent columns whatever the data.
    TooFewDistinctParameters {
        /// The degree n.
        degree: usize,
        /// The number of distinct parameters.
        found: usize,
    },
    /// A B-spline control point that no parameter reaches: its basis function vanishes at every
    /// parameter, so nothing determines it.
    UndeterminedControlPoint {
        /// The index j of the control point d_j.
        index: usize,
        /// The support of N_j, as text: `[1/2, 2)`.
        support: String,
    },
    /// A parameter outside the domain of the knot vector.
    ParameterOutsideDomain {
        /// The index i of the parameter u_i.
        index: usize,
        /// The parameter, as text.
        value: String,
        /// The left end of the domain.
        start: String,
        /// The right end of the domain.
        end: String,
    },
    /// An error of the linear algebra (a singular normal matrix, with the column that has no
    /// pivot).
    Linalg(LinalgError),
    /// An error building the Bézier curve.
    Bezier(BezierError),
    /// An error building the knot vector or the B-spline curve, or evaluating its basis.
    BSpline(BSplineError),
}

impl fmt::Display for FitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FitError::NoData => write!(f, "no data points: a fit needs at least one point"),
            FitError::CountMismatch { points, parameters } => write!(
                f,
                "{points} data points but {parameters} parameters: give one parameter per point"
            ),
            FitError::DimensionMismatch {
                what,
                expected,
                found,
            } => write!(
                f,
                "{what} has dimension {found}, but data point 0 has dimension {expected}"
            ),
            FitError::RepeatedParameter {
                first,
                second,
                value,
            } => write!(
                f,
                "singular: parameters u_{first} and u_{second} are equal (both {value}); \
                 a curve cannot pass through two points at one parameter"
            ),
            FitError::NotIncreasing {
                index,
                before,
                value,
            } => write!(
                f,
                "the knots must increase strictly: u_{index} = {value} is not greater than \
                 u_{} = {before}",
                index.saturating_sub(1)
            ),
            FitError::TooFewPoints {
                what,
                needed,
                found,
            } => write!(f, "{what} needs at least {needed} data points, found {found}"),
            FitError::TooFewDistinctParameters { degree, found } => write!(
                f,
                "least squares of degree {degree} needs at least {} distinct parameters, \
                 found {found}: the normal matrix would be singular",
                degree + 1
            ),
            FitError::UndeterminedControlPoint { index, support } => write!(
                f,
                "control point d_{index} is not determined: no parameter lies in the support \
                 {support} of its basis function N_{index}"
            ),
            FitError::ParameterOutsideDomain {
                index,
                value,
                start,
                end,
            } => write!(
                f,
                "parameter u_{index} = {value} is outside the domain [{start}, {end}] of the knot vector"
            ),
            FitError::Linalg(e) => write!(f, "{e}"),
            FitError::Bezier(e) => write!(f, "{e}"),
            FitError::BSpline(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for FitError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            FitError::Linalg(e) => Some(e),
            FitError::Bezier(e) => Some(e),
            FitError::BSpline(e) => Some(e),
            _ => None,
        }
    }
}

impl From<LinalgError> for FitError {
    fn from(e: LinalgError) -> Self {
        FitError::Linalg(e)
    }
}

impl From<BezierError> for FitError {
    fn from(e: BezierError) -> Self {
        FitError::Bezier(e)
    }
}

impl From<BSplineError> for FitError {
    fn from(e: BSplineError) -> Self {
        FitError::BSpline(e)
    }
}
