//! The one error type of cagd-fit.

use cagd_bezier::BezierError;
use cagd_bspline::BSplineError;
use cagd_linalg::LinalgError;
use cagd_spline_surface::{Direction, SplineSurfaceError};
use cagd_surface::SurfaceError;
use std::fmt;

/// What one parameter of a direction indexes in a grid of data a_ij = c(u_i, v_j): a row for
/// u, a column for v.
fn line(direction: Direction) -> &'static str {
    match direction {
        Direction::U => "row",
        Direction::V => "column",
    }
}

/// What can go wrong when fitting a curve or a surface to data.
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
    /// More data than an interpolation takes (one point per control point).
    TooManyPoints {
        /// What takes them, in words.
        what: String,
        /// How many it takes.
        expected: usize,
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
    /// A grid of surface data whose shape does not match the parameters: row i of the data is
    /// c(u_i, ·), column j is c(·, v_j).
    GridShape {
        /// Rows of the data grid.
        rows: usize,
        /// Columns of the data grid.
        cols: usize,
        /// The number of parameters u_i.
        u_count: usize,
        /// The number of parameters v_j.
        v_count: usize,
    },
    /// Grid interpolation with two equal parameters in one direction: the collocation matrix
    /// B_U (or B_V) has two equal rows.
    RepeatedGridParameter {
        /// The direction of the parameters.
        direction: Direction,
        /// The first index with that parameter.
        first: usize,
        /// The second index with that parameter.
        second: usize,
        /// The shared parameter, as text.
        value: String,
    },
    /// Spline grid interpolation with parameters that do not increase strictly.
    GridNotIncreasing {
        /// The direction of the parameters.
        direction: Direction,
        /// The index of the parameter that is not greater than the one before it.
        index: usize,
        /// The parameter before, as text.
        before: String,
        /// The parameter at `index`, as text.
        value: String,
    },
    /// A clamped end condition (one given tangent vector) asked of a surface interpolant.
    ClampedSurfaceEnd {
        /// The direction whose end condition is clamped.
        direction: Direction,
        /// Whether it is the end (u_M or v_N) rather than the start.
        at_end: bool,
    },
    /// A fit of bidegree (m, n) with too few distinct parameters in one direction:
    /// the collocation matrix has dependent columns whatever the data.
    TooFewDistinctSurfaceParameters {
        /// The direction of the parameters.
        direction: Direction,
        /// The degree in that direction.
        degree: usize,
        /// The number of distinct parameters found.
        found: usize,
    },
    /// Interpolation with scattered parameters (the notes' eq. (28) with as many points as
    /// control points) whose collocation matrix B is singular.
    SingularScattered {
        /// The bidegree (m, n).
        bidegree: (usize, usize),
        /// What the elimination found, in words.
        detail: String,
    },
    /// Least squares of a surface whose normal matrix BᵗB is singular: the parameters do not
    /// determine every control point.
    UndeterminedMesh {
        /// What was fitted, in words ("a Bézier patch of bidegree (1, 1)").
        what: String,
        /// What the elimination found, in words.
        detail: String,
    },
    /// A parameter of surface data outside the domain of a knot vector.
    SurfaceParameterOutsideDomain {
        /// The direction of the parameter.
        direction: Direction,
        /// The index k of the data point a_k.
        index: usize,
        /// The parameter, as text.
        value: String,
        /// The left end of the domain.
        start: String,
        /// The right end of the domain.
        end: String,
    },
    /// A control point d_ij of a B-spline surface that no parameter reaches: its basis
    /// function N_i(u) N_j(v) vanishes at every parameter (u_k, v_k).
    UndeterminedSurfaceControlPoint {
        /// The row index i.
        row: usize,
        /// The column index j.
        col: usize,
        /// The support of N_i(u) N_j(v), as text: `[0, 1] x [1/2, 2]`.
        support: String,
    },
    /// A degree that does not fit the number of data points.
    DegreeOutOfRange {
        /// What takes the degree, in words.
        what: String,
        /// The degree asked for.
        degree: usize,
        /// The number of data points.
        points: usize,
        /// The least degree that fits.
        low: usize,
        /// The greatest degree that fits.
        high: usize,
    },
    /// An error of the linear algebra (a singular normal matrix, with the column that has no
    /// pivot).
    Linalg(LinalgError),
    /// An error building the Bézier curve.
    Bezier(BezierError),
    /// An error building the knot vector or the B-spline curve, or evaluating its basis.
    BSpline(BSplineError),
    /// An error building a grid, a mesh or a Bézier patch.
    Surface(SurfaceError),
    /// An error building or evaluating a B-spline surface.
    SplineSurface(SplineSurfaceError),
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
            FitError::DegreeOutOfRange {
                what,
                degree,
                points,
                low,
                high,
            } => write!(
                f,
                "{what} through {points} data points has a degree from {low} to {high}, found {degree}"
            ),
            FitError::TooManyPoints {
                what,
                expected,
                found,
            } => write!(
                f,
                "{what} takes exactly {expected} data points (one per control point), found \
                 {found}: approximate them by least squares instead"
            ),
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
            FitError::GridShape {
                rows,
                cols,
                u_count,
                v_count,
            } => write!(
                f,
                "the data grid has {rows} rows and {cols} columns, but {u_count} parameters u_i \
                 and {v_count} parameters v_j were given: row i of the data is c(u_i, v_0), ..., \
                 c(u_i, v_n), so give one u_i per row and one v_j per column"
            ),
            FitError::RepeatedGridParameter {
                direction,
                first,
                second,
                value,
            } => write!(
                f,
                "singular: parameters {direction}_{first} and {direction}_{second} are equal \
                 (both {value}); the matrix B_{} has two equal rows, and a surface cannot \
                 interpolate two {}s of data at one parameter",
                direction.to_string().to_uppercase(),
                line(*direction)
            ),
            FitError::GridNotIncreasing {
                direction,
                index,
                before,
                value,
            } => write!(
                f,
                "the parameters {direction}_{} of a spline interpolant must increase strictly: \
                 {direction}_{index} = {value} is not greater than {direction}_{} = {before}",
                if *direction == Direction::U { 'i' } else { 'j' },
                index.saturating_sub(1)
            ),
            FitError::ClampedSurfaceEnd { direction, at_end } => write!(
                f,
                "a clamped {} condition in {direction} (one given tangent vector) does not apply \
                 to a surface: every {} of data would need its own tangent; use natural or \
                 Bessel ends",
                if *at_end { "end" } else { "start" },
                if *direction == Direction::U { "column" } else { "row" }
            ),
            FitError::TooFewDistinctSurfaceParameters {
                direction,
                degree,
                found,
            } => write!(
                f,
                "a patch of degree {degree} in {direction} needs at least {} distinct values of \
                 {direction} among the parameters (u_k, v_k), found {found}: the columns of the \
                 collocation matrix B are linearly dependent whatever the data",
                degree + 1
            ),
            FitError::SingularScattered { bidegree, detail } => write!(
                f,
                "the interpolation problem with scattered parameters is singular for these \
                 parameters: det B = 0 for the collocation matrix B of eq. (28), bidegree \
                 ({}, {}): {detail}. This is not the data's fault: swapping the \
                 parameters (u_i, v_i) and (u_j, v_j) of two points swaps two rows of B and \
                 changes the sign of det B, so moving the parameters continuously from one order \
                 to the other passes through parameters with det B = 0 (points of the plane, \
                 unlike those of a line, have no order that prevents it). Choose other \
                 parameters, or fit more points by least squares",
                bidegree.0, bidegree.1
            ),
            FitError::UndeterminedMesh { what, detail } => write!(
                f,
                "least squares by {what} is singular for these parameters (u_k, v_k): they do \
                 not determine every control point (as when they all lie on one line of the \
                 domain); {detail}"
            ),
            FitError::SurfaceParameterOutsideDomain {
                direction,
                index,
                value,
                start,
                end,
            } => write!(
                f,
                "parameter {direction}_{index} = {value} (of data point a_{index}) is outside the \
                 domain [{start}, {end}] of the knot vector in {direction}"
            ),
            FitError::UndeterminedSurfaceControlPoint { row, col, support } => write!(
                f,
                "control point d_{row},{col} is not determined: no parameter (u_k, v_k) lies in \
                 the support {support} of its basis function N_{row}(u) N_{col}(v)"
            ),
            FitError::Linalg(e) => write!(f, "{e}"),
            FitError::Bezier(e) => write!(f, "{e}"),
            FitError::BSpline(e) => write!(f, "{e}"),
            FitError::Surface(e) => write!(f, "{e}"),
            FitError::SplineSurface(e) => write!(f, "{e}"),
        }
    }
}

impl std::error::Error for FitError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            FitError::Linalg(e) => Some(e),
            FitError::Bezier(e) => Some(e),
            FitError::BSpline(e) => Some(e),
            FitError::Surface(e) => Some(e),
            FitError::SplineSurface(e) => Some(e),
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

impl From<SurfaceError> for FitError {
    fn from(e: SurfaceError) -> Self {
        FitError::Surface(e)
    }
}

impl From<SplineSurfaceError> for FitError {
    fn from(e: SplineSurfaceError) -> Self {
        FitError::SplineSurface(e)
    }
}
