//! C² cubic spline interpolation in B-spline form (Farin, *Curves and Surfaces for CAGD*,
//! chapter 9), with natural, clamped and Bessel end conditions.

use crate::data::{check_data, check_increasing, check_vector};
use crate::FitError;
use cagd_bspline::{basis_derivatives, BSplineCurve, KnotVector};
use cagd_linalg::{Factorization, Matrix, Point};
use cagd_scalar::Scalar;

/// The condition that fixes one end of a C² cubic spline interpolant (two are needed: the
/// N + 1 interpolation conditions leave N + 3 control points two degrees of freedom).
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum EndCondition<S: Scalar> {
    /// Natural: the second derivative vanishes at the end, `c''(u_0) = 0` (or `c''(u_N) = 0`).
    Natural,
    /// Clamped: the first derivative at the end is this vector, `c'(u_0) = m_0` (a derivative
    /// with respect to the parameter u, not a unit tangent).
    Tangent(Point<S>),
    /// Bessel: the first derivative at the end is that of the parabola through the first (or
    /// last) three data points, see [`bessel_tangents`].
    Bessel,
}

/// The end conditions at u_0 and at u_N.
#[derive(Clone, Debug, PartialEq)]
pub struct EndConditions<S: Scalar> {
    /// The condition at u_0.
    pub start: EndCondition<S>,
    /// The condition at u_N.
    pub end: EndCondition<S>,
}

impl<S: Scalar> EndConditions<S> {
    /// Natural conditions at both ends: `c''(u_0) = c''(u_N) = 0`.
    pub fn natural() -> Self {
        EndConditions {
            start: EndCondition::Natural,
            end: EndCondition::Natural,
        }
    }

    /// Bessel tangents at both ends.
    pub fn bessel() -> Self {
        EndConditions {
            start: EndCondition::Bessel,
            end: EndCondition::Bessel,
        }
    }

    /// Given end derivatives: `c'(u_0) = m_0`, `c'(u_N) = m_N`.
    pub fn clamped(m0: Point<S>, mn: Point<S>) -> Self {
        EndConditions {
            start: EndCondition::Tangent(m0),
            end: EndCondition::Tangent(mn),
        }
    }
}

/// The Bessel end derivatives: those of the parabolas through the first three and the last
/// three data points, at u_0 and u_N.
///
/// With Δ_0 = u_1 − u_0, Δ_1 = u_2 − u_1 and the slopes s_0 = (a_1 − a_0)/Δ_0,
/// s_1 = (a_2 − a_1)/Δ_1 (Newton's form of the parabola),
///
/// `m_0 = s_0 + Δ_0 (s_0 − s_1) / (Δ_0 + Δ_1)`,
///
/// and symmetrically, with the last three points, `m_N = s_1 + Δ_1 (s_1 − s_0) / (Δ_0 + Δ_1)`.
///
/// ```
/// use cagd_fit::bessel_tangents;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// // Points of the parabola (u, u²) at u = 0, 1, 3: its derivative (1, 2u) is (1, 0) at 0, (1, 6) at 3.
/// let a: Vec<Point<BigRational>> =
///     vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 1]), Point::from_ints(&[3, 9])];
/// let (m0, mn) = bessel_tangents(&[q!(0), q!(1), q!(3)], &a).unwrap();
/// assert_eq!((m0.to_text(), mn.to_text()), ("(1, 0)".to_string(), "(1, 6)".to_string()));
/// ```
pub fn bessel_tangents<S: Scalar>(
    knots: &[S],
    points: &[Point<S>],
) -> Result<(Point<S>, Point<S>), FitError> {
    check_data(knots, points)?;
    check_increasing(knots)?;
    let n = points.len();
    if n < 3 {
        return Err(FitError::TooFewPoints {
            what: crate::Fitted::BesselEndTangent,
            needed: 3,
            found: n,
        });
    }
    if knots.len() != n {
        return Err(FitError::CountMismatch {
            points: n,
            parameters: knots.len(),
        });
    }
    let (first, last) = (knots.len() - 3, n - 3);
    let start = match (knots, points) {
        ([u0, u1, u2, ..], [a0, a1, a2, ..]) => {
            parabola_end_derivative([u0, u1, u2], [a0, a1, a2], false)
        }
        _ => {
            return Err(FitError::CountMismatch {
                points: n,
                parameters: knots.len(),
            })
        }
    };
    let end = match (knots.get(first..), points.get(last..)) {
        (Some([u0, u1, u2]), Some([a0, a1, a2])) => {
            parabola_end_derivative([u0, u1, u2], [a0, a1, a2], true)
        }
        _ => {
            return Err(FitError::CountMismatch {
                points: n,
                parameters: knots.len(),
            })
        }
    };
    Ok((start, end))
}

/// The derivative of the parabola through three points at the first (or last) parameter.
fn parabola_end_derivative<S: Scalar>(
    [u0, u1, u2]: [&S; 3],
    [a0, a1, a2]: [&Point<S>; 3],
    at_end: bool,
) -> Point<S> {
    let d0 = u1.sub_ref(u0);
    let d1 = u2.sub_ref(u1);
    let s0 = (a1 - a0).scale(&(S::one() / &d0));
    let s1 = (a2 - a1).scale(&(S::one() / &d1));
    let total = d0.add_ref(&d1);
    if at_end {
        let mut m = s1.clone();
        m.add_scaled(&(&s1 - &s0), &(d1 / &total));
        m
    } else {
        let mut m = s0.clone();
        m.add_scaled(&(&s0 - &s1), &(d0 / &total));
        m
    }
}

/// The linear system of a C² cubic spline interpolant, for step-by-step answers
/// ([`cubic_spline_system`]).
#[derive(Clone, Debug, PartialEq)]
pub struct CubicSplineSystem<S: Scalar> {
    /// The knot vector `{u_0, u_0, u_0, u_1, ..., u_{N−1}, u_N, u_N, u_N}`.
    pub knots: KnotVector<S>,
    /// The (N + 3) × (N + 3) matrix: start condition, N + 1 interpolation rows, end condition.
    pub matrix: Matrix<S>,
    /// The right-hand side: the start value, a_0, ..., a_N, the end value.
    pub rhs: Vec<Point<S>>,
}

/// The knot vector of the C² cubic spline interpolant of the knots u_0 < ... < u_N:
/// `{u_0, u_0, u_0, u_1, ..., u_{N−1}, u_N, u_N, u_N}` in the notes' convention ("con los
/// nudos inicial y final repetidos tres veces"), for N + 3 control points.
pub fn cubic_spline_knots<S: Scalar>(knots: &[S]) -> Result<KnotVector<S>, FitError> {
    check_increasing(knots)?;
    if knots.len() < 2 {
        return Err(FitError::TooFewPoints {
            what: crate::Fitted::CubicSpline,
            needed: 2,
            found: knots.len(),
        });
    }
    Ok(KnotVector::clamped(3, knots)?)
}

/// The linear system of the C² cubic spline interpolant, rows in order: the start condition,
/// the N + 1 interpolation conditions `Σ_j N_j(u_i) d_j = a_i`, the end condition. The
/// unknowns are the control points d_0, ..., d_{N+2}; a natural end is
/// `Σ_j N_j''(u_0) d_j = 0`, a clamped or Bessel end `Σ_j N_j'(u_0) d_j = m_0`.
///
/// Returns the knot vector, the (N + 3) × (N + 3) matrix and the right-hand side, as a
/// [`CubicSplineSystem`].
pub fn cubic_spline_system<S: Scalar>(
    knots: &[S],
    points: &[Point<S>],
    ends: &EndConditions<S>,
) -> Result<CubicSplineSystem<S>, FitError> {
    check_data(knots, points)?;
    let vector = cubic_spline_knots(knots)?;
    let rhs = cubic_spline_rhs(knots, points, ends)?;
    let matrix = cubic_spline_matrix(knots, &vector, ends)?;
    Ok(CubicSplineSystem {
        knots: vector,
        matrix,
        rhs,
    })
}

/// The matrix of [`cubic_spline_system`]: it depends on the knots and on the kind of each end
/// condition (second derivative for a natural end, first derivative otherwise), never on the
/// data, so one factorization serves every row of a grid of data.
pub(crate) fn cubic_spline_matrix<S: Scalar>(
    knots: &[S],
    vector: &KnotVector<S>,
    ends: &EndConditions<S>,
) -> Result<Matrix<S>, FitError> {
    let n = knots.len() + 2;
    let mut matrix = Matrix::zeros(n, n);
    let (first, last) = match (knots.first(), knots.last()) {
        (Some(first), Some(last)) => (first, last),
        _ => return Err(FitError::NoData),
    };
    for (row, u, condition) in [(0, first, &ends.start), (n - 1, last, &ends.end)] {
        let order = match condition {
            EndCondition::Natural => 2,
            EndCondition::Tangent(_) | EndCondition::Bessel => 1,
        };
        set_row(&mut matrix, row, vector, u, order)?;
    }
    for (i, u) in knots.iter().enumerate() {
        set_row(&mut matrix, i + 1, vector, u, 0)?;
    }
    Ok(matrix)
}

/// The right-hand side of [`cubic_spline_system`]: the start value, a_0, ..., a_N, the end
/// value (0 for a natural end, the tangent for a clamped or Bessel end).
pub(crate) fn cubic_spline_rhs<S: Scalar>(
    knots: &[S],
    points: &[Point<S>],
    ends: &EndConditions<S>,
) -> Result<Vec<Point<S>>, FitError> {
    let dim = check_data(knots, points)?;
    let bessel = if ends.start == EndCondition::Bessel || ends.end == EndCondition::Bessel {
        Some(bessel_tangents(knots, points)?)
    } else {
        None
    };
    let mut rhs = Vec::with_capacity(points.len() + 2);
    for (condition, at_end) in [(&ends.start, false), (&ends.end, true)] {
        let value = match (condition, &bessel) {
            (EndCondition::Tangent(m), _) => {
                let what = if at_end {
                    crate::Datum::EndTangent
                } else {
                    crate::Datum::StartTangent
                };
                check_vector(m, dim, what)?;
                m.clone()
            }
            (EndCondition::Bessel, Some((m0, mn))) => {
                if at_end {
                    mn.clone()
                } else {
                    m0.clone()
                }
            }
            _ => Point::zero(dim),
        };
        if at_end {
            rhs.extend(points.iter().cloned());
        }
        rhs.push(value);
    }
    Ok(rhs)
}

/// Writes the derivatives of the given order of the basis functions at u into a row.
fn set_row<S: Scalar>(
    matrix: &mut Matrix<S>,
    row: usize,
    vector: &KnotVector<S>,
    u: &S,
    order: usize,
) -> Result<(), FitError> {
    let span = vector.find_span(u)?;
    let ders = basis_derivatives(vector, span, u, order)?;
    let first = span - vector.degree();
    if let Some(values) = ders.get(order) {
        for (k, v) in values.iter().enumerate() {
            matrix.set(row, first + k, v.clone());
        }
    }
    Ok(())
}

/// The C² cubic spline through a_0, ..., a_N at the knots u_0 < ... < u_N (Farin, chapter 9),
/// in B-spline form: control points d_0, ..., d_{N+2} on the knot vector
/// `{u_0, u_0, u_0, u_1, ..., u_{N−1}, u_N, u_N, u_N}` (notes' convention, see
/// [`cubic_spline_knots`]), with the given end conditions. The system
/// ([`cubic_spline_system`]) is solved exactly, all coordinates with one factorization.
///
/// At a clamped end d_0 = a_0 and d_1 = a_0 + (Δ_0/3) m_0, as every end condition gives.
///
/// ```
/// use cagd_fit::{interpolate_cubic_spline, EndConditions};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let a: Vec<Point<BigRational>> =
///     vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 1]), Point::from_ints(&[2, 0])];
/// let c = interpolate_cubic_spline(&[q!(0), q!(1), q!(2)], &a, &EndConditions::natural()).unwrap();
/// assert_eq!(c.knots().to_text(), "{0, 0, 0, 1, 2, 2, 2}");
/// let d: Vec<String> = c.points().iter().map(|p| p.to_text()).collect();
/// assert_eq!(d, ["(0, 0)", "(1/3, 1/2)", "(1, 3/2)", "(5/3, 1/2)", "(2, 0)"]);
/// ```
pub fn interpolate_cubic_spline<S: Scalar>(
    knots: &[S],
    points: &[Point<S>],
    ends: &EndConditions<S>,
) -> Result<BSplineCurve<S>, FitError> {
    let system = cubic_spline_system(knots, points, ends)?;
    let control = Factorization::new(&system.matrix)?.solve_points(&system.rhs)?;
    Ok(BSplineCurve::try_new(system.knots, control)?)
}
