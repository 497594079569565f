//! Bicubic B-spline interpolation of a grid of data (the notes' chapter 5, §7): a C² cubic
//! spline through each row of data, then through each column of the control points found.

use crate::data::{check_grid, check_increasing_in};
use crate::spline::{cubic_spline_knots, cubic_spline_matrix, cubic_spline_rhs};
use crate::surface::two_passes;
use crate::{Direction, EndCondition, EndConditions, FitError, GridStep, PassOrder};
use cagd_linalg::{Factorization, Point};
use cagd_record::{NoSteps, Record};
use cagd_scalar::Scalar;
use cagd_spline_surface::BSplineSurface;
use cagd_surface::Mesh;

/// The end conditions of a bicubic spline interpolant, one pair per direction: natural or
/// Bessel (a clamped end, one given tangent vector, has no meaning for a whole row of data).
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceEndConditions<S: Scalar> {
    /// The conditions at u_0 and u_M, closing each cubic spline in u (down a column).
    pub u: EndConditions<S>,
    /// The conditions at v_0 and v_N, closing each cubic spline in v (along a row).
    pub v: EndConditions<S>,
}

impl<S: Scalar> SurfaceEndConditions<S> {
    /// Natural conditions at every end (vanishing second derivative across the border).
    pub fn natural() -> Self {
        SurfaceEndConditions {
            u: EndConditions::natural(),
            v: EndConditions::natural(),
        }
    }

    /// Bessel tangents at every end.
    pub fn bessel() -> Self {
        SurfaceEndConditions {
            u: EndConditions::bessel(),
            v: EndConditions::bessel(),
        }
    }

    /// The conditions `u` in the direction u and `v` in the direction v.
    pub fn new(u: EndConditions<S>, v: EndConditions<S>) -> Self {
        SurfaceEndConditions { u, v }
    }
}

/// The bicubic B-spline surface through a grid of data, `c(u_i, v_j) = a_ij`, rows first. See
/// [`interpolate_bicubic_spline_in_passes`].
///
/// ```
/// use cagd_fit::{interpolate_bicubic_spline, SurfaceEndConditions};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// use cagd_surface::Mesh;
/// // z = u² + v sampled on {0, 1, 2} x {0, 1, 3}: Bessel ends reproduce every quadratic.
/// let (u, v) = ([q!(0), q!(1), q!(2)], [q!(0), q!(1), q!(3)]);
/// let data: Mesh<BigRational> = Mesh::from_fn(3, 3, |i, j| {
///     Point::new(vec![u[i].clone(), v[j].clone(), u[i].clone() * &u[i] + &v[j]])
/// });
/// let s = interpolate_bicubic_spline(&u, &v, &data, &SurfaceEndConditions::bessel()).unwrap();
/// assert_eq!(s.knots_u().to_text(), "{0, 0, 0, 1, 2, 2, 2}");
/// assert_eq!((s.mesh().rows(), s.mesh().cols()), (5, 5));
/// assert_eq!(s.eval(&q!(3/2), &q!(2)).unwrap().to_text(), "(3/2, 2, 17/4)");
/// ```
pub fn interpolate_bicubic_spline<S: Scalar>(
    u: &[S],
    v: &[S],
    data: &Mesh<S>,
    ends: &SurfaceEndConditions<S>,
) -> Result<BSplineSurface<S>, FitError> {
    interpolate_bicubic_spline_in_passes(u, v, data, ends, PassOrder::RowsFirst, &mut NoSteps)
}

/// Bicubic B-spline interpolation of an (M + 1) × (N + 1) grid a_ij = c(u_i, v_j),
/// u_0 < ... < u_M, v_0 < ... < v_N, in two passes, recording the matrix of the splines in u,
/// the one in v and the control points after the first pass ([`GridStep`]; the notes, §7).
///
/// Rows first: each row {a_i0, ..., a_iN} is interpolated by a C² cubic spline in v
/// ([`crate::interpolate_cubic_spline`]), whose N + 3 control points form row i of
/// `{d̃_00, ..., d̃_{M,N+2}}`; then each column {d̃_0j, ..., d̃_Mj} by a cubic spline in u, whose
/// M + 3 control points form column j of the B-spline mesh `{d_00, ..., d_{M+2,N+2}}`. The
/// knots are the parameters "con los nudos inicial y final repetidos tres veces":
/// `{u_0, u_0, u_0, u_1, ..., u_M, u_M, u_M}` and likewise in v. Columns first gives the same
/// mesh. Every spline in one direction has the same matrix, factored once for all rows (or
/// columns) and coordinates.
///
/// The end conditions may differ per direction ([`SurfaceEndConditions`]): natural
/// (`∂²c/∂v² = 0` along the borders v = v_0, v = v_N, and likewise in u) or Bessel. In the
/// second pass they act on the control points of the first, exactly as the notes describe; as
/// both conditions are linear in the data, the two orders agree.
///
/// ```
/// use cagd_fit::{interpolate_bicubic_spline_in_passes, GridStep, PassOrder, SurfaceEndConditions};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// use cagd_surface::Mesh;
/// let t = [q!(0), q!(1), q!(2)];
/// let data: Mesh<BigRational> =
///     Mesh::from_fn(3, 3, |i, j| Point::from_ints(&[i as i64, j as i64, ((i + j) % 2) as i64]));
/// let ends = SurfaceEndConditions::natural();
/// let mut steps = Vec::new();
/// let rows =
///     interpolate_bicubic_spline_in_passes(&t, &t, &data, &ends, PassOrder::RowsFirst, &mut steps)
///         .unwrap();
/// let columns = cagd_fit::interpolate_bicubic_spline(&t, &t, &data, &ends).unwrap();
/// assert_eq!(rows, columns);
/// let Some(GridStep::FirstPass { mesh, .. }) = steps.last() else { panic!() };
/// assert_eq!((mesh.rows(), mesh.cols()), (3, 5));
/// assert_eq!(rows.eval(&q!(1), &q!(2)).unwrap().to_text(), "(1, 2, 1)");
/// ```
pub fn interpolate_bicubic_spline_in_passes<S: Scalar>(
    u: &[S],
    v: &[S],
    data: &Mesh<S>,
    ends: &SurfaceEndConditions<S>,
    order: PassOrder,
    rec: &mut impl Record<GridStep<S>>,
) -> Result<BSplineSurface<S>, FitError> {
    check_grid(u, v, data)?;
    for (direction, params, conditions) in [(Direction::U, u, &ends.u), (Direction::V, v, &ends.v)]
    {
        check_direction(direction, params, conditions)?;
    }
    let (knots_u, knots_v) = (cubic_spline_knots(u)?, cubic_spline_knots(v)?);
    let matrix_u = cubic_spline_matrix(u, &knots_u, &ends.u)?;
    let matrix_v = cubic_spline_matrix(v, &knots_v, &ends.v)?;
    let in_u = Factorization::new(&matrix_u)?;
    let in_v = Factorization::new(&matrix_v)?;
    rec.record(|| GridStep::MatrixU(matrix_u));
    rec.record(|| GridStep::MatrixV(matrix_v));
    let rows = |row: &[Point<S>]| {
        Ok::<_, FitError>(in_v.solve_points(&cubic_spline_rhs(v, row, &ends.v)?)?)
    };
    let columns = |column: &[Point<S>]| {
        Ok::<_, FitError>(in_u.solve_points(&cubic_spline_rhs(u, column, &ends.u)?)?)
    };
    let mesh = two_passes(data, order, rows, columns, rec)?;
    Ok(BSplineSurface::try_new(knots_u, knots_v, mesh)?)
}

/// The parameters of one direction increase strictly and are enough for its end conditions,
/// which must be natural or Bessel.
fn check_direction<S: Scalar>(
    direction: Direction,
    params: &[S],
    conditions: &EndConditions<S>,
) -> Result<(), FitError> {
    let mut needed = 2;
    for (condition, at_end) in [(&conditions.start, false), (&conditions.end, true)] {
        match condition {
            EndCondition::Tangent(_) => {
                return Err(FitError::ClampedSurfaceEnd { direction, at_end });
            }
            EndCondition::Bessel => needed = 3,
            EndCondition::Natural => {}
        }
    }
    check_increasing_in(direction, params)?;
    if params.len() < needed {
        let what = if needed == 3 {
            crate::Fitted::BesselEndIn { direction }
        } else {
            crate::Fitted::CubicSplineIn { direction }
        };
        return Err(FitError::TooFewPoints {
            what,
            needed,
            found: params.len(),
        });
    }
    Ok(())
}
