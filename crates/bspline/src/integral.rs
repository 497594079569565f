//! Integrals of B-splines over the domain: each basis function's, and a curve's as the
//! combination of its control points with them.
//!
//! The basis function `N_{i,p}` on the full knot vector `t_0, ..., t_{n+p}` (The NURBS Book's
//! indexing, i = 0, ..., n - 1 for n control points) has `∫ N_{i,p} = (t_{i+p+1} - t_i)/(p + 1)`
//! over its support `[t_i, t_{i+p+1}]` (de Boor, A Practical Guide to Splines; it follows from
//! the derivative formula of The NURBS Book, §2.3). In the notes' indexing, without end knots (`u_{k} = t_{k+1}`), the same function is
//! `N_i^p` with support `[u_{i-1}, u_{i+p}]` and integral `(u_{i+p} - u_{i-1})/(p + 1)`. When a
//! support reaches outside the domain (an unclamped end), its part inside the domain is what
//! is computed here, exactly, piece by piece (the Bézier pieces of the basis functions: each
//! piece's integral is its interval's length times the average of its Bézier points).

use crate::{bezier_pieces, BSplineError, KnotVector};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// `∫_{domain} N_{i,p}(t) dt` for i = 0, ..., n - 1 (as many as the knot vector's control
/// points): the Bézier extraction of the basis itself (control points the unit vectors of
/// R^n), each piece `(b - a)/(p + 1) Σ b_j`.
///
/// ```
/// use cagd_bspline::{basis_integrals, KnotVector};
/// use cagd_scalar::{q, BigRational};
/// let u: KnotVector<BigRational> = KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap();
/// // clamped: (t_{i+3} - t_i)/3 with t = 0, 0, 0, 1, 2, 2, 2
/// assert_eq!(basis_integrals(&u).unwrap(), [q!(1/3), q!(2/3), q!(2/3), q!(1/3)]);
/// ```
pub fn basis_integrals<S: Scalar>(knots: &KnotVector<S>) -> Result<Vec<S>, BSplineError> {
    let n = knots.control_point_count();
    let unit: Vec<Point<S>> = (0..n)
        .map(|i| {
            Point::new(
                (0..n)
                    .map(|j| if i == j { S::one() } else { S::zero() })
                    .collect(),
            )
        })
        .collect();
    let p1 = S::from_i64(i64::try_from(knots.degree() + 1).unwrap_or(i64::MAX));
    let mut total = Point::zero(n);
    for piece in bezier_pieces(knots, &unit)? {
        let (a, b) = &piece.interval;
        let length = (b.clone() - a.clone()) / p1.clone();
        for q in &piece.points {
            total.add_scaled(q, &length);
        }
    }
    Ok(total.coords().to_vec())
}

/// `(t_{i+p+1} - t_i)/(p + 1)` on the full knot vector (The NURBS Book's indexing) for each
/// i = 0, ..., n - 1: the integral of `N_{i,p}` over its whole support. Equal to
/// [`basis_integrals`] for every function whose support lies in the domain (all of them when
/// the ends are clamped).
pub fn support_integrals<S: Scalar>(knots: &KnotVector<S>) -> Vec<S> {
    let p = knots.degree();
    let t = knots.full();
    let p1 = S::from_i64(i64::try_from(p + 1).unwrap_or(i64::MAX));
    (0..knots.control_point_count())
        .filter_map(|i| Some((t.get(i + p + 1)?.clone() - t.get(i)?.clone()) / p1.clone()))
        .collect()
}

/// `∫_{domain} c(t) dt = Σ d_i ∫ N_{i,p}` for the B-spline curve with these control points.
pub fn curve_integral<S: Scalar>(
    knots: &KnotVector<S>,
    points: &[Point<S>],
) -> Result<Point<S>, BSplineError> {
    crate::check_control_points(knots, points)?;
    let weights = basis_integrals(knots)?;
    let dim = points.first().map_or(0, Point::dim);
    let mut total = Point::zero(dim);
    for (d, w) in points.iter().zip(&weights) {
        total.add_scaled(d, w);
    }
    Ok(total)
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, BigRational};
    use proptest::prelude::*;

    type Q = BigRational;

    #[test]
    fn unclamped_uniform_cubic_inner_function() {
        // notes' knots 0..7, cubic: 6 functions, domain [2, 5]
        let u: KnotVector<Q> =
            KnotVector::from_notes((0..8).map(|k| Q::from_integer(k.into())).collect(), 3).unwrap();
        let inside = basis_integrals(&u).unwrap();
        // partition of unity: the integrals sum to the domain's length
        assert_eq!(inside.iter().fold(q!(0), |a, x| a + x.clone()), q!(3));
        // N_2's support [u_1, u_5] = [1, 5] is not inside [2, 5]; N_3's, [2, 6], neither;
        // a uniform cubic's pieces integrate to 1/24, 11/24, 11/24, 1/24: N_2 on [2, 5] misses 1/24
        assert_eq!(inside[2], q!(23 / 24));
    }

    proptest! {
        /// Clamped knots: every support lies in the domain, and ∫ N_i = (t_{i+p+1} - t_i)/(p + 1).
        #[test]
        fn clamped_formula(
            p in 1usize..4,
            gaps in proptest::collection::vec(1i64..5, 1..5),
        ) {
            let mut x = 0i64;
            let mut breaks = vec![q!(0)];
            for g in gaps {
                x += g;
                breaks.push(Q::from_integer(x.into()));
            }
            let u = KnotVector::clamped(p, &breaks).unwrap();
            prop_assert_eq!(basis_integrals(&u).unwrap(), support_integrals(&u));
        }
    }
}
