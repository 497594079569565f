//! Bézier extraction: the Bézier control polygon of every polynomial piece.

use crate::checked::{at, slice};
use crate::{check_control_points, insert_knot, BSplineError, KnotVector};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// One polynomial piece of a B-spline curve as a Bézier curve on its parameter interval.
#[derive(Clone, Debug, PartialEq)]
pub struct BezierPiece<S: Scalar> {
    /// The interval `[u_k, u_{k+1}]` of the piece.
    pub interval: (S, S),
    /// Its Bézier control points `b_0, ..., b_p` (for the parameter running over `interval`).
    pub points: Vec<Point<S>>,
}

/// The B-spline curve with every breakpoint of its domain (ends included) inserted up to
/// multiplicity p, so that each non-empty span k carries the Bézier points
/// `d_{k-p}, ..., d_k` (full convention) of its piece.
///
/// Returns the refined knot vector and control points.
pub fn insert_breakpoints<S: Scalar>(
    knots: &KnotVector<S>,
    points: &[Point<S>],
) -> Result<(KnotVector<S>, Vec<Point<S>>), BSplineError> {
    check_control_points(knots, points)?;
    let p = knots.degree();
    let mut current = (knots.clone(), points.to_vec());
    for (x, s) in knots.breakpoints() {
        if s < p {
            current = insert_knot(&current.0, &current.1, &x, p - s)?;
        }
    }
    Ok(current)
}

/// The Bézier pieces of the curve, one per non-empty span of the domain, left to right
/// (Farin, ch. 8, "B-spline to Bézier"; Piegl and Tiller, A5.6): every breakpoint is inserted
/// until it has multiplicity p, and then the p + 1 control points `d_{k-p}, ..., d_k` of
/// each span k are the Bézier points of the piece. Consecutive pieces share an end point
/// (unless the curve jumps at a knot of multiplicity p + 1). An unclamped end is clamped on
/// the way, so the points outside the domain do not appear.
///
/// ```
/// use cagd_bspline::{bezier_pieces, KnotVector};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let u = KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap();
/// let d: Vec<Point<BigRational>> =
///     [[0, 0], [1, 2], [3, 2], [4, 0]].iter().map(|c| Point::from_ints(c)).collect();
/// let pieces = bezier_pieces(&u, &d).unwrap();
/// assert_eq!(pieces[0].interval, (q!(0), q!(1)));
/// let first: Vec<String> = pieces[0].points.iter().map(|p| p.to_text()).collect();
/// assert_eq!(first, ["(0, 0)", "(1, 2)", "(2, 2)"]);
/// let second: Vec<String> = pieces[1].points.iter().map(|p| p.to_text()).collect();
/// assert_eq!(second, ["(2, 2)", "(3, 2)", "(4, 0)"]);
/// ```
pub fn bezier_pieces<S: Scalar>(
    knots: &KnotVector<S>,
    points: &[Point<S>],
) -> Result<Vec<BezierPiece<S>>, BSplineError> {
    let (v, d) = insert_breakpoints(knots, points)?;
    let p = v.degree();
    let u = v.full();
    v.spans()
        .into_iter()
        .map(|k| {
            Ok(BezierPiece {
                interval: (at(u, k, k)?.clone(), at(u, k + 1, k)?.clone()),
                points: slice(&d, k.saturating_sub(p), k, k)?.to_vec(),
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, BigRational};

    #[test]
    fn unclamped_uniform_cubic() {
        // The uniform cubic B-spline segment: knots 0..7 (notes), 6 points, domain [2, 5].
        // The Bézier points of a uniform cubic piece with points a, b, c, d are
        // (a + 4b + c)/6, (2b + c)/3, (b + 2c)/3, (b + 4c + d)/6.
        let u: KnotVector<BigRational> = KnotVector::from_notes(
            (0..8)
                .map(|k| BigRational::from_integer(k.into()))
                .collect(),
            3,
        )
        .unwrap();
        assert_eq!(u.domain(), (q!(2), q!(5)));
        let d: Vec<Point<BigRational>> = [0, 6, 12, 6, 0, 6]
            .iter()
            .map(|&y| Point::from_ints(&[y]))
            .collect();
        let pieces = bezier_pieces(&u, &d).unwrap();
        assert_eq!(pieces.len(), 3);
        assert_eq!(pieces[1].interval, (q!(3), q!(4)));
        let text: Vec<String> = pieces[0].points.iter().map(|p| p.to_text()).collect();
        // a, b, c, d = 0, 6, 12, 6: (0 + 24 + 12)/6 = 6, 8, 10, (6 + 48 + 6)/6 = 10.
        assert_eq!(text, ["(6)", "(8)", "(10)", "(10)"]);
        assert_eq!(pieces[0].points[3], pieces[1].points[0]);
        let last: Vec<String> = pieces[2].points.iter().map(|p| p.to_text()).collect();
        // 12, 6, 0, 6: (12 + 24 + 0)/6 = 6, 4, 2, (6 + 0 + 6)/6 = 2.
        assert_eq!(last, ["(6)", "(4)", "(2)", "(2)"]);
    }

    #[test]
    fn a_jump_gives_separate_pieces() {
        // Linear with a knot of multiplicity 2 = p + 1 at 1: two separate segments.
        let u = KnotVector::from_notes(vec![q!(0), q!(1), q!(1), q!(2)], 1).unwrap();
        let d: Vec<Point<BigRational>> = [[0], [1], [5], [6]]
            .iter()
            .map(|c| Point::from_ints(c))
            .collect();
        let pieces = bezier_pieces(&u, &d).unwrap();
        assert_eq!(pieces.len(), 2);
        assert_eq!(pieces[0].points, d[..2].to_vec());
        assert_eq!(pieces[1].points, d[2..].to_vec());
    }
}
