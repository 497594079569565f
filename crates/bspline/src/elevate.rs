//! Degree elevation of a B-spline curve.

use crate::{bezier_pieces, check_control_points, remove_knot, BSplineError, KnotVector};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// The same curve written with degree p + r (Piegl and Tiller §5.5, by the route of their
/// A5.9 spelled out): every interior knot's multiplicity grows by r, the ends are clamped
/// with multiplicity p + r (notes' convention).
///
/// 1. Bézier extraction ([`crate::bezier_pieces`]): one Bézier polygon per span.
/// 2. Each piece is elevated by r ([`cagd_bezier::elevate_degree`]:
///    `c_i^(1) = (i/(m+1)) c_{i-1} + (1 - i/(m+1)) c_i`).
/// 3. The pieces are joined into a C^0 B-spline of degree p + r (each breakpoint with
///    multiplicity p + r; p + r + 1 where the curve jumps).
/// 4. Each interior breakpoint of original multiplicity s ≤ p is removed p - s times
///    ([`crate::remove_knot`], exact), back to multiplicity s + r, i.e. continuity C^{p-s}.
///
/// An unclamped curve comes back clamped (the knots outside the domain do not belong to the
/// curve). `r = 0` returns the curve unchanged.
///
/// ```
/// use cagd_bspline::{elevate_degree, KnotVector};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let u = KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap();
/// let d: Vec<Point<BigRational>> =
///     [[0, 0], [1, 2], [3, 2], [4, 0]].iter().map(|c| Point::from_ints(c)).collect();
/// let (v, e) = elevate_degree(&u, &d, 1).unwrap();
/// assert_eq!(v.to_text(), "{0, 0, 0, 1, 1, 2, 2, 2}");
/// let text: Vec<String> = e.iter().map(|p| p.to_text()).collect();
/// assert_eq!(text, ["(0, 0)", "(2/3, 4/3)", "(4/3, 2)", "(8/3, 2)", "(10/3, 4/3)", "(4, 0)"]);
/// ```
pub fn elevate_degree<S: Scalar>(
    knots: &KnotVector<S>,
    points: &[Point<S>],
    r: usize,
) -> Result<(KnotVector<S>, Vec<Point<S>>), BSplineError> {
    check_control_points(knots, points)?;
    if r == 0 {
        return Ok((knots.clone(), points.to_vec()));
    }
    let p = knots.degree();
    let q = p
        .checked_add(r)
        .ok_or(BSplineError::InvalidDegree { degree: usize::MAX })?;
    let pieces = bezier_pieces(knots, points)?;
    let mut notes: Vec<S> = Vec::new();
    let mut joined: Vec<Point<S>> = Vec::new();
    for (j, piece) in pieces.iter().enumerate() {
        let elevated = cagd_bezier::elevate_degree(&piece.points, r)?;
        let (a, _) = &piece.interval;
        if j == 0 {
            notes.extend(std::iter::repeat_n(a.clone(), q));
            joined.extend(elevated);
        } else if knots.multiplicity(a) <= p {
            // The pieces meet at a: one shared point, multiplicity q.
            notes.extend(std::iter::repeat_n(a.clone(), q));
            joined.extend(elevated.into_iter().skip(1));
        } else {
            // The curve jumps at a: both end points, multiplicity q + 1.
            notes.extend(std::iter::repeat_n(a.clone(), q + 1));
            joined.extend(elevated);
        }
    }
    notes.extend(std::iter::repeat_n(knots.end().clone(), q));
    let mut current = (KnotVector::from_notes(notes, q)?, joined);
    for (x, s) in knots.breakpoints() {
        let interior = knots.start() < &x && &x < knots.end();
        if interior && s < p {
            current = remove_knot(&current.0, &current.1, &x, p - s)?;
        }
    }
    Ok(current)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::de_boor;
    use cagd_scalar::{q, BigRational};

    #[test]
    fn elevating_a_cubic_with_a_double_knot() {
        let u = KnotVector::from_notes(
            vec![
                q!(0),
                q!(0),
                q!(0),
                q!(1),
                q!(1),
                q!(2),
                q!(3),
                q!(3),
                q!(3),
            ],
            3,
        )
        .unwrap();
        let d: Vec<Point<BigRational>> = [[0, 0], [0, 3], [3, 6], [6, 6], [9, 3], [9, 0], [12, 1]]
            .iter()
            .map(|c| Point::from_ints(c))
            .collect();
        let (v, e) = elevate_degree(&u, &d, 2).unwrap();
        assert_eq!(v.degree(), 5);
        assert_eq!(
            v.to_text(),
            "{0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 3, 3, 3, 3, 3}"
        );
        assert_eq!(e.len(), v.control_point_count());
        for t in [q!(0), q!(1 / 3), q!(1), q!(3 / 2), q!(2), q!(5 / 2), q!(3)] {
            assert_eq!(de_boor(&v, &e, &t).unwrap(), de_boor(&u, &d, &t).unwrap());
        }
    }
}
