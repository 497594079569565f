//! Derivatives of a B-spline curve: the derivative curve and the derivatives at a point.

use crate::checked::{at, slice};
use crate::knots::scalar_of;
use crate::{basis_derivatives, check_control_points, BSplineError, KnotVector, NoDerivative};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// The derivative curve c'(t), a B-spline of degree p - 1 (Farin, ch. 8; Piegl and Tiller,
/// eq. 3.4): in the notes' convention its knots are `u_1, ..., u_{n+p-3}` (the first and last
/// knot dropped) and its n - 1 control points are
///
/// `Δd_i = p (d_{i+1} - d_i) / (u_{i+p} - u_i)`, i = 0, ..., n - 2
///
/// (full convention: `p (d_{i+1} - d_i)/(u_{i+p+1} - u_{i+1})`); a zero knot difference
/// belongs to a basis function that vanishes on the domain, and gives the zero vector.
///
/// Errors for degree 1 (the derivative is piecewise constant, not a B-spline of degree ≥ 1)
/// and where a knot would appear p + 1 times in the derivative (the curve jumps there).
///
/// ```
/// use cagd_bspline::{derivative_curve, KnotVector};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let u = KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap();
/// let d: Vec<Point<BigRational>> =
///     [[0, 0], [1, 2], [3, 2], [4, 0]].iter().map(|c| Point::from_ints(c)).collect();
/// let (v, e) = derivative_curve(&u, &d).unwrap();
/// assert_eq!(v.to_text(), "{0, 1, 2}");
/// let text: Vec<String> = e.iter().map(|p| p.to_text()).collect();
/// assert_eq!(text, ["(2, 4)", "(2, 0)", "(2, -4)"]);
/// ```
pub fn derivative_curve<S: Scalar>(
    knots: &KnotVector<S>,
    points: &[Point<S>],
) -> Result<(KnotVector<S>, Vec<Point<S>>), BSplineError> {
    let dim = check_control_points(knots, points)?;
    let p = knots.degree();
    if p < 2 {
        return Err(BSplineError::NoDerivativeCurve {
            reason: NoDerivative::DegreeOne,
        });
    }
    let notes = knots.notes();
    // the notes' vector of a curve of degree p >= 2 has at least two knots
    let inner = notes
        .get(1..notes.len().saturating_sub(1))
        .unwrap_or_default()
        .to_vec();
    let reduced = KnotVector::from_notes(inner, p - 1).map_err(|e| match e {
        BSplineError::Multiplicity { knot, .. } => BSplineError::NoDerivativeCurve {
            reason: NoDerivative::Jump {
                knot,
                times: p + 1,
                degree: p,
            },
        },
        other => other,
    })?;
    let factor = scalar_of::<S>(p);
    let mut out = Vec::with_capacity(points.len().saturating_sub(1));
    for (i, pair) in points.windows(2).enumerate() {
        let [a, b] = pair else { continue };
        let diff = at(notes, i + p, i)?.sub_ref(at(notes, i, i)?);
        let v = match factor.checked_div(&diff) {
            Some(c) => (b - a).scale(&c),
            None => Point::zero(dim),
        };
        out.push(v);
    }
    Ok((reduced, out))
}

/// The derivatives `c(t), c'(t), ..., c^(order)(t)` at a parameter of the domain (Piegl and
/// Tiller, A3.2): `c^(m)(t) = Σ_j (N_{k-p+j}^p)^(m)(t) d_{k-p+j}` with the basis derivatives
/// of [`basis_derivatives`]. Orders above p are the zero vector. At a knot the derivatives
/// are taken from the right (the span starting at t), except at the right end of the domain.
///
/// ```
/// use cagd_bspline::{derivatives, KnotVector};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let u = KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap();
/// let d: Vec<Point<BigRational>> =
///     [[0, 0], [1, 2], [3, 2], [4, 0]].iter().map(|c| Point::from_ints(c)).collect();
/// let ders = derivatives(&u, &d, &q!(1/2), 2).unwrap();
/// let text: Vec<String> = ders.iter().map(|p| p.to_text()).collect();
/// assert_eq!(text, ["(1, 3/2)", "(2, 2)", "(0, -4)"]);
/// ```
pub fn derivatives<S: Scalar>(
    knots: &KnotVector<S>,
    points: &[Point<S>],
    t: &S,
    order: usize,
) -> Result<Vec<Point<S>>, BSplineError> {
    let dim = check_control_points(knots, points)?;
    let k = knots.find_span(t)?;
    let p = knots.degree();
    let ders = basis_derivatives(knots, k, t, order)?;
    let local = slice(points, k - p, k, k)?;
    Ok(ders
        .iter()
        .map(|row| Point::combination(local, row, dim))
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::de_boor;
    use cagd_scalar::{q, BigRational};

    #[test]
    fn derivative_curve_of_a_c0_cubic_and_its_jump() {
        // A C^0 cubic (knot 1 of multiplicity 3): the derivative has degree 2 and a jump at 1.
        let u = KnotVector::from_notes(
            vec![
                q!(0),
                q!(0),
                q!(0),
                q!(1),
                q!(1),
                q!(1),
                q!(2),
                q!(2),
                q!(2),
            ],
            3,
        )
        .unwrap();
        let d: Vec<Point<BigRational>> = [[0, 0], [1, 1], [2, 1], [3, 0], [5, 0], [6, 2], [6, 4]]
            .iter()
            .map(|c| Point::from_ints(c))
            .collect();
        let (v, e) = derivative_curve(&u, &d).unwrap();
        assert_eq!(v.to_text(), "{0, 0, 1, 1, 1, 2, 2}");
        assert_eq!(v.continuity(&q!(1)), -1);
        // Left of 1 the tangent is 3 (d_3 - d_2) = (3, -3); right of it 3 (d_4 - d_3) = (6, 0).
        assert_eq!(e[2].to_text(), "(3, -3)");
        assert_eq!(e[3].to_text(), "(6, 0)");
        assert_eq!(de_boor(&v, &e, &q!(1)).unwrap().to_text(), "(6, 0)");
        for t in [q!(1 / 3), q!(3 / 2), q!(2)] {
            let ders = derivatives(&u, &d, &t, 1).unwrap();
            assert_eq!(ders[1], de_boor(&v, &e, &t).unwrap());
        }
        // The derivative of the jumping derivative is not a B-spline curve.
        let err = derivative_curve(&v, &e).unwrap_err();
        assert_eq!(
            err.to_string(),
            "the derivative is not a B-spline curve: knot 1 appears 3 times, so the curve of \
             degree 2 may jump there"
        );
        let line = KnotVector::clamped(1, &[q!(0), q!(1)]).unwrap();
        assert!(derivative_curve(&line, &d[..2]).is_err());
        // Order 4 of a cubic: zero.
        assert!(derivatives(&u, &d, &q!(1 / 2), 4).unwrap()[4].is_zero());
    }
}
