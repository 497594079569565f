//! The integral of a Bézier curve: each Bernstein polynomial of degree n integrates to
//! `1/(n + 1)` over [0, 1] (`∫_0^1 B_i^n(t) dt = 1/(n + 1)`), so
//! `∫_0^1 c(t) dt = (1/(n + 1)) Σ b_i`, the average of the control points; on the curve's
//! interval [a, b], `∫_a^b c(t) dt = (b - a)/(n + 1) Σ b_i`, and its parametric mean
//! `(1/(b - a)) ∫_a^b c dt` is again the average.

use crate::{check_polygon, BezierError};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// The average `(1/(n + 1)) Σ b_i` of the control points: `∫_0^1 c(t) dt`, and the parametric
/// mean of the curve on any interval it is written on.
///
/// ```
/// use cagd_bezier::control_point_average;
/// use cagd_linalg::Point;
/// use cagd_scalar::BigRational;
/// let b: [Point<BigRational>; 3] =
///     [Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2]), Point::from_ints(&[2, 0])];
/// assert_eq!(control_point_average(&b).unwrap().to_text(), "(1, 2/3)");
/// ```
pub fn control_point_average<S: Scalar>(points: &[Point<S>]) -> Result<Point<S>, BezierError> {
    let dim = check_polygon(points)?;
    let count = points.len();
    let mut sum = Point::zero(dim);
    for p in points {
        sum.add_scaled(p, &S::one());
    }
    Ok(sum.scale(&(S::one() / S::from_i64(i64::try_from(count).unwrap_or(i64::MAX)))))
}

/// `∫_a^b c(t) dt = (b - a)/(n + 1) Σ b_i` for the Bézier curve with these control points on
/// its interval [a, b].
///
/// ```
/// use cagd_bezier::polygon_integral;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let b: Vec<Point<BigRational>> = vec![Point::from_ints(&[0]), Point::from_ints(&[3])];
/// assert_eq!(polygon_integral(&b, &q!(0), &q!(2)).unwrap().to_text(), "(3)");
/// ```
pub fn polygon_integral<S: Scalar>(
    points: &[Point<S>],
    a: &S,
    b: &S,
) -> Result<Point<S>, BezierError> {
    Ok(control_point_average(points)?.scale(&(b.clone() - a.clone())))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{elevate_degree, restrict, BezierCurve};
    use cagd_poly::Var;
    use cagd_scalar::{q, BigRational};
    use proptest::prelude::*;

    type Q = BigRational;

    fn polygon(xs: &[(i64, i64)]) -> Vec<Point<Q>> {
        xs.iter().map(|&(x, y)| Point::from_ints(&[x, y])).collect()
    }

    proptest! {
        /// The integral of a degree-elevated curve equals the original's.
        #[test]
        fn elevation_keeps_the_integral(
            xs in proptest::collection::vec((-9i64..9, -9i64..9), 1..6),
            r in 1usize..4,
        ) {
            let b = polygon(&xs);
            let e = elevate_degree(&b, r).unwrap();
            prop_assert_eq!(control_point_average(&b).unwrap(), control_point_average(&e).unwrap());
        }

        /// ∫_0^1 = ∫_0^m + ∫_m^1, the halves by restriction (subdivision), each on its own
        /// interval; and the average is the closed form's integral.
        #[test]
        fn subdivision_splits_the_integral(
            xs in proptest::collection::vec((-9i64..9, -9i64..9), 1..6),
            m in 1i64..9,
        ) {
            let b = polygon(&xs);
            let m = Q::new(m.into(), 9.into());
            let left = restrict(&b, &q!(0), &m).unwrap();
            let right = restrict(&b, &m, &q!(1)).unwrap();
            let whole = polygon_integral(&b, &q!(0), &q!(1)).unwrap();
            let sum = polygon_integral(&left, &q!(0), &m).unwrap()
                + polygon_integral(&right, &m, &q!(1)).unwrap();
            prop_assert_eq!(&whole, &sum);
            let form = BezierCurve::try_new(b).unwrap().closed_form(Var::T);
            prop_assert_eq!(whole, form.definite_integral(Var::T, &q!(0), &q!(1)));
        }
    }
}
