//! Conic arcs and exact circles as quadratic rational Bézier curves.
//!
//! A quadratic rational Bézier curve with weights `(1, w, 1)` is a conic arc: an ellipse for
//! w < 1, a parabola for w = 1, a hyperbola for w > 1. It is an arc of a circle of angle θ
//! exactly when its control polygon is isosceles, `|c_0 - c_1| = |c_2 - c_1|` (c_1 the
//! intersection of the end tangents), and `w = cos(θ/2)`.
//!
//! The weights `cos(θ/2)` are often roots (√2/2 for a quarter circle): over exact rationals
//! those constructions return an error that names the field they need, and they run over
//! [`Quadratic`](cagd_scalar::Quadratic). Two constructions need no root in the weights:
//! the 120° arcs (weight 1/2) and the quarter circles reweighted to `{1, 1/2, 1/2}`
//! ([`circle_four_arcs_rational`]), the only one whose control points are rational too.

use crate::polygon::check_polygon;
use crate::{BezierError, NeedsRoot, NotAnArc, Quantity, RationalBezierCurve};
use cagd_linalg::Point;
use cagd_scalar::{Scalar, ScalarError};
use std::cmp::Ordering;

/// √n / den, taken from the field (`S::sqrt_of(n)` divided by `S::from_i64(den)`), or an error
/// explaining `what` needs it when the field has no √n: over the exact rationals
/// [`ScalarError::NotRational`] naming the number (`√2/2`), as converting it would say.
fn root_over<S: Scalar>(n: u64, den: i64, what: NeedsRoot) -> Result<S, BezierError> {
    S::sqrt_of(n)
        .map(|root| root / S::from_i64(den))
        .ok_or_else(|| BezierError::Number {
            what,
            source: ScalarError::NotRational {
                value: if den == 1 {
                    format!("√{n}")
                } else {
                    format!("√{n}/{den}")
                },
            },
        })
}

/// An error unless `value > 0` is decided (an order that cannot be decided is an error too).
fn positive<S: Scalar>(value: &S, what: Quantity) -> Result<(), BezierError> {
    if value.compare(&S::zero()) == Some(Ordering::Greater) {
        Ok(())
    } else {
        Err(BezierError::NotPositive {
            what,
            value: value.to_text(),
        })
    }
}

/// The conic arc from `start` to `end` whose end tangents meet at `tangent_point`, with
/// weights `(1, weight, 1)`: an ellipse (weight < 1), parabola (= 1) or hyperbola (> 1). An
/// error for weight 0: the tangent point is a point, and weight 0 would read it as a control
/// vector.
pub fn conic_arc<S: Scalar>(
    start: Point<S>,
    tangent_point: Point<S>,
    end: Point<S>,
    weight: S,
) -> Result<RationalBezierCurve<S>, BezierError> {
    if weight.is_zero() {
        return Err(BezierError::ZeroWeight { index: 1 });
    }
    RationalBezierCurve::try_new(
        vec![start, tangent_point, end],
        vec![S::one(), weight, S::one()],
    )
}

/// The arc of circle of angle θ (0 < θ < π) from `start` to `end`, whose end tangents meet at
/// `tangent_point`, with weights `(1, cos(θ/2), 1)`; the caller gives `cos_half = cos(θ/2)`
/// exactly (e.g. `√2/2` for 90°, `1/2` for 120°).
///
/// Checked exactly: `0 < cos_half < 1`, the polygon is isosceles `|c_0 - c_1| = |c_2 - c_1|`,
/// and its angle at `c_1` is π - θ, i.e.
/// `(c_0 - c_1)·(c_2 - c_1) = |c_0 - c_1|^2 (1 - 2 cos^2(θ/2))`. Any dimension.
///
/// ```
/// use cagd_bezier::circle_arc_from_tangents;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// // legs of length 25 at the angle with cosine 7/25: cos(θ/2) = 3/5, all rational
/// let arc = circle_arc_from_tangents::<BigRational>(
///     Point::from_ints(&[25, 0]), Point::from_ints(&[0, 0]), Point::from_ints(&[7, 24]), q!(3/5),
/// ).unwrap();
/// // on the circle of centre (25, 75/4) and radius 75/4
/// assert_eq!(arc.eval(&q!(1/2)).unwrap().to_text(), "(10, 15/2)");
/// let bad = circle_arc_from_tangents::<BigRational>(
///     Point::from_ints(&[25, 0]), Point::from_ints(&[0, 0]), Point::from_ints(&[7, 24]), q!(1/2),
/// );
/// assert!(bad.unwrap_err().to_string().starts_with("not a circular arc: the weight cos(θ/2) = 1/2"));
/// ```
pub fn circle_arc_from_tangents<S: Scalar>(
    start: Point<S>,
    tangent_point: Point<S>,
    end: Point<S>,
    cos_half: S,
) -> Result<RationalBezierCurve<S>, BezierError> {
    let polygon = [start, tangent_point, end];
    check_polygon(&polygon)?;
    check_cos_half(&cos_half)?;
    let [start, tangent_point, end] = polygon;
    let u = &start - &tangent_point;
    let v = &end - &tangent_point;
    let (uu, vv) = (u.dot(&u), v.dot(&v));
    if uu.is_zero() || uu != vv {
        return Err(BezierError::NotACircle {
            reason: NotAnArc::Distances {
                first: uu.to_text(),
                second: vv.to_text(),
            },
        });
    }
    let expected = uu.clone() * (S::one() - S::from_i64(2) * cos_half.mul_ref(&cos_half));
    let uv = u.dot(&v);
    if uv != expected {
        return Err(BezierError::NotACircle {
            reason: NotAnArc::Angle {
                cos_half: cos_half.to_text(),
                expected: expected.to_text(),
                found: uv.to_text(),
            },
        });
    }
    conic_arc(start, tangent_point, end, cos_half)
}

fn check_cos_half<S: Scalar>(cos_half: &S) -> Result<(), BezierError> {
    if *cos_half <= S::zero() || *cos_half >= S::one() {
        return Err(BezierError::NotACircle {
            reason: NotAnArc::Weight {
                cos_half: cos_half.to_text(),
            },
        });
    }
    Ok(())
}

/// The arc of angle θ (0 < θ < π) of the circle with this `center` and `radius`, from
/// `center + radius · start_dir` to `center + radius · end_dir`, given `cos_half = cos(θ/2)`:
///
/// `c_0 = m + r d_0`, `c_1 = m + r (d_0 + d_1) / (2 cos^2(θ/2))`, `c_2 = m + r d_1`,
/// weights `(1, cos(θ/2), 1)`.
///
/// The directions must be unit vectors with `d_0 · d_1 = cos θ = 2 cos^2(θ/2) - 1`, checked
/// exactly. Any dimension (an arc in a plane of R^3 too).
///
/// ```
/// use cagd_bezier::circle_arc;
/// use cagd_linalg::Point;
/// use cagd_scalar::{parse_number, Quadratic};
/// let n = |s: &str| parse_number(s).unwrap();
/// let arc = circle_arc::<Quadratic>(
///     &Point::from_ints(&[0, 0]), &n("2"),
///     &Point::from_ints(&[1, 0]), &Point::from_ints(&[0, 1]), &n("sqrt2/2"),
/// ).unwrap();
/// assert_eq!(arc.to_text(), "(2, 0) w = 1; (2, 2) w = √2/2; (0, 2) w = 1");
/// ```
pub fn circle_arc<S: Scalar>(
    center: &Point<S>,
    radius: &S,
    start_dir: &Point<S>,
    end_dir: &Point<S>,
    cos_half: &S,
) -> Result<RationalBezierCurve<S>, BezierError> {
    check_polygon(&[center.clone(), start_dir.clone(), end_dir.clone()])?;
    positive(radius, Quantity::Radius)?;
    check_cos_half(cos_half)?;
    for (start, d) in [(true, start_dir), (false, end_dir)] {
        let len2 = d.dot(d);
        if !len2.is_one() {
            let (direction, length) = (d.to_text(), len2.to_text());
            return Err(BezierError::NotACircle {
                reason: if start {
                    NotAnArc::StartDirection { direction, length }
                } else {
                    NotAnArc::EndDirection { direction, length }
                },
            });
        }
    }
    let c2 = cos_half.mul_ref(cos_half);
    let cos = c2.clone() * S::from_i64(2) - S::one();
    let dot = start_dir.dot(end_dir);
    if dot != cos {
        return Err(BezierError::NotACircle {
            reason: NotAnArc::Directions {
                cos_half: cos_half.to_text(),
                cos: cos.to_text(),
                dot: dot.to_text(),
            },
        });
    }
    let mut start = center.clone();
    start.add_scaled(start_dir, radius);
    let mut end = center.clone();
    end.add_scaled(end_dir, radius);
    let mut middle = center.clone();
    let k = radius.clone() / (c2 * S::from_i64(2));
    middle.add_scaled(&(start_dir + end_dir), &k);
    conic_arc(start, middle, end, cos_half.clone())
}

/// The quarter of the circle of radius r centred at the origin, from (r, 0) to (0, r):
/// control points `(r, 0), (r, r), (0, r)`, weights `{1, √2/2, 1}`.
///
/// √2/2 is not rational: over exact rationals this is an error telling the user to use the
/// quadratic field Q(√2) (or the rational weights of [`circle_four_arcs_rational`]).
///
/// ```
/// use cagd_bezier::quarter_circle;
/// use cagd_scalar::{parse_number, q, BigRational, Quadratic};
/// let c = quarter_circle::<Quadratic>(&parse_number("1").unwrap()).unwrap();
/// assert_eq!(c.to_text(), "(1, 0) w = 1; (1, 1) w = √2/2; (0, 1) w = 1");
/// let err = quarter_circle::<BigRational>(&q!(1)).unwrap_err().to_string();
/// assert!(err.contains("quadratic field Q(√2)"), "{err}");
/// ```
pub fn quarter_circle<S: Scalar>(radius: &S) -> Result<RationalBezierCurve<S>, BezierError> {
    positive(radius, Quantity::Radius)?;
    let w = root_over::<S>(2, 2, NeedsRoot::QuarterCircle)?;
    let (z, r) = (S::zero(), radius.clone());
    conic_arc(
        Point::new(vec![r.clone(), z.clone()]),
        Point::new(vec![r.clone(), r.clone()]),
        Point::new(vec![z, r]),
        w,
    )
}

/// The circle of radius r around `center`, in the plane of its first two coordinates (the
/// others are copied, so a circle at height z works in R^3), as arcs from the given corner
/// offsets `(x, y)` (in units of r) and weights.
fn circle_arcs<S: Scalar>(
    center: &Point<S>,
    radius: &S,
    offsets: &[(S, S)],
    weights: &[[S; 3]],
) -> Result<Vec<RationalBezierCurve<S>>, BezierError> {
    positive(radius, Quantity::Radius)?;
    if center.dim() < 2 {
        return Err(BezierError::NotACircle {
            reason: NotAnArc::Centre {
                centre: center.to_text(),
            },
        });
    }
    let point = |(x, y): &(S, S)| {
        let mut p = center.clone();
        p[0] += x.mul_ref(radius);
        p[1] += y.mul_ref(radius);
        p
    };
    let pts: Vec<Point<S>> = offsets.iter().map(point).collect();
    weights
        .iter()
        .enumerate()
        .map(|(k, w)| {
            // the points 2k, 2k + 1, 2k + 2 of the square, cyclically
            let polygon: Vec<Point<S>> = pts.iter().cycle().skip(2 * k).take(3).cloned().collect();
            RationalBezierCurve::try_new(polygon, w.to_vec())
        })
        .collect()
}

/// The 8 offsets (units of r) of the square around the circle: (1, 0), (1, 1), (0, 1), ...
fn square_offsets<S: Scalar>() -> Vec<(S, S)> {
    [
        (1, 0),
        (1, 1),
        (0, 1),
        (-1, 1),
        (-1, 0),
        (-1, -1),
        (0, -1),
        (1, -1),
    ]
    .iter()
    .map(|&(x, y)| (S::from_i64(x), S::from_i64(y)))
    .collect()
}

/// The whole circle as four quarter arcs, counterclockwise from (m_x + r, m_y): control
/// points on the square around it, `(r, 0), (r, r), (0, r), (-r, r), ...` (plus the centre),
/// each arc with weights `{1, √2/2, 1}`. Needs the quadratic field Q(√2).
pub fn circle_four_arcs<S: Scalar>(
    center: &Point<S>,
    radius: &S,
) -> Result<Vec<RationalBezierCurve<S>>, BezierError> {
    let w = root_over::<S>(2, 2, NeedsRoot::QuarterCircle)?;
    let one = S::one();
    let arc = [one.clone(), w, one];
    circle_arcs(center, radius, &square_offsets(), &vec![arc; 4])
}

/// The whole circle as four quarter arcs with RATIONAL weights: the control points of
/// [`circle_four_arcs`] and the weights `{1, 1/2, 1/2}`, `{1/2, 1/2, 1}`, `{1, 1/2, 1/2}`,
/// `{1/2, 1/2, 1}` (equal weights where consecutive arcs meet).
///
/// They are the weights `{1, √2/2, 1}` reweighted by ρ = √2/2 (`w_i ρ^i`, see
/// [`RationalBezierCurve::reweight`]) and then, for every other arc, the arc reversed: the
/// same point sets in another parametrization, and every point at a rational parameter is a
/// rational point of the circle. Works over exact rationals.
///
/// ```
/// use cagd_bezier::circle_four_arcs_rational;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let arcs = circle_four_arcs_rational::<BigRational>(&Point::from_ints(&[0, 0]), &q!(5)).unwrap();
/// assert_eq!(arcs[0].eval(&q!(1/2)).unwrap().to_text(), "(4, 3)");
/// ```
pub fn circle_four_arcs_rational<S: Scalar>(
    center: &Point<S>,
    radius: &S,
) -> Result<Vec<RationalBezierCurve<S>>, BezierError> {
    let (one, half) = (S::one(), S::from_ratio(1, 2));
    let a = [one.clone(), half.clone(), half.clone()];
    let b = [half.clone(), half, one];
    circle_arcs(
        center,
        radius,
        &square_offsets(),
        &[a.clone(), b.clone(), a, b],
    )
}

/// The whole circle as three arcs of 120°, counterclockwise from (m_x + r, m_y): the middle
/// control points are the vertices of the equilateral triangle around the circle, at distance
/// 2r from the centre, and every arc has weights `{1, 1/2, 1}` (cos 60° = 1/2: no root in the
/// weights). The control points are `(r, 0), (r, √3 r), (-r/2, √3 r/2), (-2r, 0),
/// (-r/2, -√3 r/2), (r, -√3 r)`: no equilateral triangle has rational vertices, so this needs
/// the quadratic field Q(√3).
pub fn circle_three_arcs<S: Scalar>(
    center: &Point<S>,
    radius: &S,
) -> Result<Vec<RationalBezierCurve<S>>, BezierError> {
    let r3 = root_over::<S>(3, 1, NeedsRoot::ThreeArcs)?;
    let (one, half) = (S::one(), S::from_ratio(1, 2));
    let offsets = vec![
        (one.clone(), S::zero()),
        (one.clone(), r3.clone()),
        (-half.clone(), r3.mul_ref(&half)),
        (S::from_i64(-2), S::zero()),
        (-half.clone(), -(r3.mul_ref(&half))),
        (one.clone(), -r3),
    ];
    let arc = [one.clone(), half, one];
    circle_arcs(center, radius, &offsets, &vec![arc; 3])
}
