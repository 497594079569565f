//! Exact knot removal: the inverse of knot insertion, when the curve allows it.

use crate::basis::div_knots;
use crate::checked::{at, slice};
use crate::insert::boehm;
use crate::{check_control_points, BSplineError, KnotVector};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// A knot vector with its control points.
type Spline<S> = (KnotVector<S>, Vec<Point<S>>);

/// Removes one copy of the knot u (strictly inside the domain) if the curve does not change.
///
/// With V the knot vector without that copy, k the span of u in V and s' the multiplicity of
/// u in V, Boehm's insertion of u into (V, e) gives back (U, d) exactly when
/// `e_i = d_i` (i ≤ k - p), `e_i = d_{i+1}` (i ≥ k - s'), and for i = k-p+1, ..., k-s'-1
///
/// `e_i = (d_i - (1 - α_i) e_{i-1}) / α_i`, `α_i = (u - v_i)/(v_{i+p} - v_i)`.
///
/// The candidate e is then checked by inserting u again: exactly for exact scalars, up to a
/// relative 1e-9 for `f64`.
fn remove_once<S: Scalar>(
    knots: &KnotVector<S>,
    points: &[Point<S>],
    u: &S,
) -> Result<Option<Spline<S>>, BSplineError> {
    let p = knots.degree();
    let full = knots.full();
    let Some(last) = full.iter().rposition(|x| x == u) else {
        return Ok(None);
    };
    let mut reduced = full.to_vec();
    reduced.remove(last);
    let v = KnotVector::from_full_trusted(reduced, p);
    let k = v.find_span(u)?;
    let s = v.multiplicity(u);
    let vf = v.full();
    // e_i = d_i for i ≤ k - p.
    let mut e: Vec<Point<S>> = Vec::with_capacity(points.len().saturating_sub(1));
    e.extend_from_slice(slice(points, 0, k - p, k)?);
    let right_start = (k - s).max(k - p + 1);
    for i in k - p + 1..right_start {
        let vi = at(vf, i, k)?;
        let alpha = div_knots(&u.sub_ref(vi), &at(vf, i + p, k)?.sub_ref(vi), k)?;
        let inv = div_knots(&S::one(), &alpha, k)?;
        // d_i = (1 - α) e_{i-1} + α e_i  ⇒  e_i = (d_i - (1 - α) e_{i-1}) / α.
        let mut ei = at(points, i, k)?.clone();
        if let Some(prev) = e.last() {
            ei.add_scaled(prev, &(alpha - S::one()));
        }
        e.push(ei.scale(&inv));
    }
    // e_i = d_{i+1} for i ≥ k - s'.
    e.extend_from_slice(
        points
            .get(right_start + 1..)
            .ok_or(BSplineError::InvalidSpan { span: k })?,
    );
    let back = boehm(&v, &e, u)?;
    let same = back
        .points
        .iter()
        .zip(points)
        .all(|(a, b)| same_point(a, b));
    Ok(same.then_some((v, e)))
}

/// Exact equality for exact scalars; a relative tolerance of 1e-9 for `f64`.
fn same_point<S: Scalar>(a: &Point<S>, b: &Point<S>) -> bool {
    if S::is_exact() {
        return a == b;
    }
    a.coords().iter().zip(b.coords()).all(|(x, y)| {
        let (x, y) = (x.to_f64(), y.to_f64());
        (x - y).abs() <= 1e-9 * (1.0 + x.abs().max(y.abs()))
    })
}

/// Removes the knot u `times` times (Tiller's knot removal, Piegl and Tiller §5.4, in the
/// form "solve the insertion equations, then check by inserting back"). Each removal must
/// leave the curve unchanged, else [`BSplineError::NotRemovable`] says after how many
/// removals it failed. The knot must lie strictly inside the domain.
///
/// ```
/// use cagd_bspline::{insert_knot, remove_knot, KnotVector};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let u = KnotVector::clamped(2, &[q!(0), q!(2)]).unwrap();
/// let d: Vec<Point<BigRational>> =
///     [[0, 0], [1, 2], [2, 0]].iter().map(|c| Point::from_ints(c)).collect();
/// let (v, e) = insert_knot(&u, &d, &q!(1/2), 2).unwrap();
/// assert_eq!(remove_knot(&v, &e, &q!(1/2), 2).unwrap(), (u, d));
/// // Moving a control point of the refined curve makes the knot essential.
/// let mut bent = e.clone();
/// bent[2] = Point::from_ints(&[1, 1]);
/// assert_eq!(
///     remove_knot(&v, &bent, &q!(1/2), 1).unwrap_err().to_string(),
///     "knot 1/2 cannot be removed (after 0 removal(s)) without changing the curve"
/// );
/// ```
pub fn remove_knot<S: Scalar>(
    knots: &KnotVector<S>,
    points: &[Point<S>],
    u: &S,
    times: usize,
) -> Result<(KnotVector<S>, Vec<Point<S>>), BSplineError> {
    check_control_points(knots, points)?;
    if !(knots.start() < u && u < knots.end()) {
        return Err(BSplineError::KnotOutsideDomain {
            knot: u.to_text(),
            start: knots.start().to_text(),
            end: knots.end().to_text(),
        });
    }
    let multiplicity = knots.multiplicity(u);
    if multiplicity < times {
        return Err(BSplineError::NotAKnot {
            knot: u.to_text(),
            multiplicity,
            times,
        });
    }
    let mut current = (knots.clone(), points.to_vec());
    for removed in 0..times {
        current =
            remove_once(&current.0, &current.1, u)?.ok_or_else(|| BSplineError::NotRemovable {
                knot: u.to_text(),
                removed,
            })?;
    }
    Ok(current)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::insert_knot;
    use cagd_scalar::{q, BigRational};

    #[test]
    fn removal_undoes_insertion_and_refuses_otherwise() {
        let u = KnotVector::clamped(3, &[q!(0), q!(1), q!(3)]).unwrap();
        let d: Vec<Point<BigRational>> = [[0, 0], [1, 3], [4, 4], [6, 1], [7, -2]]
            .iter()
            .map(|c| Point::from_ints(c))
            .collect();
        let (v, e) = insert_knot(&u, &d, &q!(1), 2).unwrap();
        assert_eq!(v.multiplicity(&q!(1)), 3);
        assert_eq!(
            remove_knot(&v, &e, &q!(1), 2).unwrap(),
            (u.clone(), d.clone())
        );
        // The original knot 1 itself is essential: the curve is only C^2 there.
        let err = remove_knot(&v, &e, &q!(1), 3).unwrap_err();
        assert_eq!(
            err.to_string(),
            "knot 1 cannot be removed (after 2 removal(s)) without changing the curve"
        );
        assert_eq!(
            remove_knot(&u, &d, &q!(2), 1).unwrap_err().to_string(),
            "knot 2 cannot be removed 1 time(s): it has multiplicity 0"
        );
        assert!(remove_knot(&u, &d, &q!(0), 1).is_err());
        // Over f64 the check is up to rounding.
        let uf = KnotVector::clamped(2, &[0.0, 1.0]).unwrap();
        let df = vec![
            Point::new(vec![0.0, 0.0]),
            Point::new(vec![1.0, 2.0]),
            Point::new(vec![2.0, 0.0]),
        ];
        let (vf, ef) = insert_knot(&uf, &df, &0.3, 2).unwrap();
        let (wf, back) = remove_knot(&vf, &ef, &0.3, 2).unwrap();
        assert_eq!(wf, uf);
        assert!(back.iter().zip(&df).all(|(a, b)| same_point(a, b)));
    }
}
