//! Knot insertion (Boehm's algorithm): one knot, r times, and knot refinement.

use crate::basis::div_knots;
use crate::checked::at;
use crate::{check_control_points, BSplineError, KnotVector};
use cagd_linalg::Point;
use cagd_record::{NoSteps, Record};
use cagd_scalar::Scalar;

/// One step of knot insertion, with its intermediate values.
#[derive(Clone, Debug, PartialEq)]
pub struct Insertion<S: Scalar> {
    /// The knot inserted.
    pub knot: S,
    /// The knot vector after the insertion.
    pub knots: KnotVector<S>,
    /// The control points after the insertion.
    pub points: Vec<Point<S>>,
    /// The index of the first new control point: `k - p + 1`, with k the span of the knot.
    pub first: usize,
    /// The ratios `α_i` of the new points `first, ..., k` (see [`insert_knot_recorded`]).
    pub alphas: Vec<S>,
}

/// Boehm's step without the multiplicity check (used by knot removal to verify itself):
/// inserts t once into a valid knot vector, t in the domain.
pub(crate) fn boehm<S: Scalar>(
    knots: &KnotVector<S>,
    points: &[Point<S>],
    t: &S,
) -> Result<Insertion<S>, BSplineError> {
    let k = knots.find_span(t)?;
    let p = knots.degree();
    let u = knots.full();
    let first = k + 1 - p;
    let mut new_points = Vec::with_capacity(points.len() + 1);
    new_points.extend_from_slice(
        points
            .get(..first)
            .ok_or(BSplineError::InvalidSpan { span: k })?,
    );
    let mut alphas = Vec::with_capacity(p);
    for i in first..=k {
        let ui = at(u, i, k)?;
        let alpha = div_knots(&t.sub_ref(ui), &at(u, i + p, k)?.sub_ref(ui), k)?;
        new_points.push(at(points, i - 1, k)?.lerp(at(points, i, k)?, &alpha));
        alphas.push(alpha);
    }
    new_points.extend_from_slice(
        points
            .get(k..)
            .ok_or(BSplineError::InvalidSpan { span: k })?,
    );
    let mut full = u.to_vec();
    full.insert(k + 1, t.clone());
    Ok(Insertion {
        knot: t.clone(),
        knots: KnotVector::from_full_trusted(full, p),
        points: new_points,
        first,
        alphas,
    })
}

/// The checks of an insertion of t, `times` times: t in the domain, final multiplicity ≤ p.
fn check_insertion<S: Scalar>(
    knots: &KnotVector<S>,
    t: &S,
    times: usize,
) -> Result<(), BSplineError> {
    if !knots.contains(t) {
        return Err(BSplineError::KnotOutsideDomain {
            knot: t.to_text(),
            start: knots.start().to_text(),
            end: knots.end().to_text(),
        });
    }
    let s = knots.multiplicity(t);
    if s.saturating_add(times) > knots.degree() {
        return Err(BSplineError::NotInsertable {
            knot: t.to_text(),
            multiplicity: s,
            times,
            degree: knots.degree(),
        });
    }
    Ok(())
}

/// Inserts the knot t `times` times, one step at a time, recording every step (Boehm's
/// algorithm; Farin, ch. 8; Piegl and Tiller, eq. 5.15). With k the span of t
/// (`u_k <= t < u_{k+1}`, full convention), each step replaces `d_{k-p+1}, ..., d_{k-1}` by
///
/// `d̂_i = (1 - α_i) d_{i-1} + α_i d_i`, `α_i = (t - u_i)/(u_{i+p} - u_i)`, i = k-p+1, ..., k
///
/// (in the notes' convention `α_i = (t - u_{i-1})/(u_{i+p-1} - u_{i-1})`), keeping
/// `d_0, ..., d_{k-p}` and `d_k, ..., d_{n-1}` (renumbered after the new points). The curve
/// does not change. Returns the last knot vector and control points (the curve unchanged when
/// `times = 0`).
///
/// Errors: t outside the domain, or a final multiplicity above p (at multiplicity p the curve
/// passes through a control point; inserting more would add nothing to one curve). An
/// interior knot counts the same in the notes' convention and in The NURBS Book's (they differ
/// only at the ends), and one more copy there, p + 1, gives that point twice: the curve splits
/// in two, which [`BSplineCurve::split_at`](crate::BSplineCurve::split_at) returns (each piece
/// ending with t p times in the notes' convention, p + 1 times in The NURBS Book's).
///
/// ```
/// use cagd_bspline::{insert_knot_recorded, KnotVector};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let u = KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap();
/// let d: Vec<Point<BigRational>> =
///     [[0, 0], [1, 2], [3, 2], [4, 0]].iter().map(|c| Point::from_ints(c)).collect();
/// let mut steps = Vec::new();
/// let (v, _) = insert_knot_recorded(&u, &d, &q!(1/2), 2, &mut steps).unwrap();
/// assert_eq!(v.to_text(), "{0, 0, 1/2, 1/2, 1, 2, 2}");
/// assert_eq!(steps[0].knots.to_text(), "{0, 0, 1/2, 1, 2, 2}");
/// assert_eq!(steps[1].knots, v);
/// ```
pub fn insert_knot_recorded<S: Scalar>(
    knots: &KnotVector<S>,
    points: &[Point<S>],
    t: &S,
    times: usize,
    rec: &mut impl Record<Insertion<S>>,
) -> Result<(KnotVector<S>, Vec<Point<S>>), BSplineError> {
    check_control_points(knots, points)?;
    check_insertion(knots, t, times)?;
    let mut last: Option<Insertion<S>> = None;
    for _ in 0..times {
        let step = match &last {
            Some(prev) => boehm(&prev.knots, &prev.points, t)?,
            None => boehm(knots, points, t)?,
        };
        if let Some(prev) = last.replace(step) {
            rec.record(|| prev);
        }
    }
    Ok(match last {
        Some(step) => {
            rec.record(|| step.clone());
            (step.knots, step.points)
        }
        None => (knots.clone(), points.to_vec()),
    })
}

/// Inserts the knot t `times` times ([`insert_knot_recorded`] without its steps); `times = 0`
/// returns the curve unchanged.
///
/// ```
/// use cagd_bspline::{insert_knot, KnotVector};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let u = KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap();
/// let d: Vec<Point<BigRational>> =
///     [[0, 0], [1, 2], [3, 2], [4, 0]].iter().map(|c| Point::from_ints(c)).collect();
/// let (v, e) = insert_knot(&u, &d, &q!(1/2), 1).unwrap();
/// assert_eq!(v.to_text(), "{0, 0, 1/2, 1, 2, 2}");
/// let text: Vec<String> = e.iter().map(|p| p.to_text()).collect();
/// assert_eq!(text, ["(0, 0)", "(1/2, 1)", "(3/2, 2)", "(3, 2)", "(4, 0)"]);
/// ```
pub fn insert_knot<S: Scalar>(
    knots: &KnotVector<S>,
    points: &[Point<S>],
    t: &S,
    times: usize,
) -> Result<(KnotVector<S>, Vec<Point<S>>), BSplineError> {
    insert_knot_recorded(knots, points, t, times, &mut NoSteps)
}

/// Knot refinement: inserts every knot of the list (in any order, repeats allowed), by
/// repeated Boehm steps. The curve does not change.
///
/// ```
/// use cagd_bspline::{refine_knots, KnotVector};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let u = KnotVector::clamped(1, &[q!(0), q!(1)]).unwrap();
/// let d: Vec<Point<BigRational>> = vec![Point::from_ints(&[0, 0]), Point::from_ints(&[4, 8])];
/// let (v, e) = refine_knots(&u, &d, &[q!(3/4), q!(1/4)]).unwrap();
/// assert_eq!(v.to_text(), "{0, 1/4, 3/4, 1}");
/// assert_eq!(e[1].to_text(), "(1, 2)");
/// assert_eq!(e[2].to_text(), "(3, 6)");
/// ```
pub fn refine_knots<S: Scalar>(
    knots: &KnotVector<S>,
    points: &[Point<S>],
    new_knots: &[S],
) -> Result<(KnotVector<S>, Vec<Point<S>>), BSplineError> {
    check_control_points(knots, points)?;
    let mut current = (knots.clone(), points.to_vec());
    for t in new_knots {
        check_insertion(&current.0, t, 1)?;
        let step = boehm(&current.0, &current.1, t)?;
        current = (step.knots, step.points);
    }
    Ok(current)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::de_boor;
    use cagd_scalar::{q, BigRational};

    fn pts(c: &[[i64; 2]]) -> Vec<Point<BigRational>> {
        c.iter().map(|x| Point::from_ints(x)).collect()
    }

    #[test]
    fn cubic_insertion_by_hand() {
        // Cubic, notes knots {0, 0, 0, 1, 2, 3, 3, 3}, 6 points; insert t = 3/2 (span [1, 2]).
        // Full knots u = {0, 0, 0, 0, 1, 2, 3, 3, 3, 3}, k = 4, new points i = 2, 3, 4:
        // α_2 = (3/2 - 0)/(2 - 0) = 3/4, α_3 = (3/2 - 0)/(3 - 0) = 1/2, α_4 = (3/2 - 1)/(3 - 1) = 1/4.
        let u = KnotVector::clamped(3, &[q!(0), q!(1), q!(2), q!(3)]).unwrap();
        let d = pts(&[[0, 0], [4, 0], [8, 4], [4, 8], [0, 4], [0, 0]]);
        let mut steps = Vec::new();
        insert_knot_recorded(&u, &d, &q!(3 / 2), 1, &mut steps).unwrap();
        let step = &steps[0];
        assert_eq!(step.first, 2);
        assert_eq!(step.alphas, vec![q!(3 / 4), q!(1 / 2), q!(1 / 4)]);
        assert_eq!(step.knots.to_text(), "{0, 0, 0, 1, 3/2, 2, 3, 3, 3}");
        let text: Vec<String> = step.points.iter().map(|p| p.to_text()).collect();
        // (1/4)(4,0) + (3/4)(8,4) = (7, 3); (1/2)(8,4) + (1/2)(4,8) = (6, 6);
        // (3/4)(4,8) + (1/4)(0,4) = (3, 7).
        assert_eq!(
            text,
            ["(0, 0)", "(4, 0)", "(7, 3)", "(6, 6)", "(3, 7)", "(0, 4)", "(0, 0)"]
        );
        // Twice more: multiplicity 3 = p, the curve passes through the middle new point.
        let (v, e) = insert_knot(&u, &d, &q!(3 / 2), 3).unwrap();
        assert_eq!(v.multiplicity(&q!(3 / 2)), 3);
        assert_eq!(e[4], de_boor(&u, &d, &q!(3 / 2)).unwrap());
    }

    #[test]
    fn insertion_errors() {
        let u = KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap();
        let d = pts(&[[0, 0], [1, 2], [3, 2], [4, 0]]);
        assert_eq!(
            insert_knot(&u, &d, &q!(1), 2).unwrap_err().to_string(),
            "knot 1 cannot be inserted 2 more time(s): it already has multiplicity 1, and \
             insertion stops at multiplicity 2 (the degree)"
        );
        assert_eq!(
            insert_knot(&u, &d, &q!(5), 1).unwrap_err().to_string(),
            "knot 5 is not inside the domain [0, 2] of the curve"
        );
        assert!(insert_knot(&u, &d, &q!(0), 1).is_err()); // clamped end: already p
        let (v, e) = insert_knot(&u, &d, &q!(1), 0).unwrap();
        assert_eq!((v, e), (u, d));
    }

    /// A recorder that counts the steps the algorithm hands it and the steps it builds.
    struct Counting {
        on: bool,
        asked: usize,
        built: usize,
    }

    impl<T> Record<T> for Counting {
        fn on(&self) -> bool {
            self.on
        }

        fn record(&mut self, step: impl FnOnce() -> T) {
            self.asked += 1;
            if self.on {
                let _ = step();
                self.built += 1;
            }
        }
    }

    #[test]
    fn without_steps_no_step_is_built() {
        let u = KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap();
        let d = pts(&[[0, 0], [1, 2], [3, 2], [4, 0]]);
        let mut off = Counting {
            on: false,
            asked: 0,
            built: 0,
        };
        let quiet = insert_knot_recorded(&u, &d, &q!(1 / 2), 2, &mut off).unwrap();
        assert_eq!((off.asked, off.built), (2, 0));
        let mut on = Counting {
            on: true,
            asked: 0,
            built: 0,
        };
        let told = insert_knot_recorded(&u, &d, &q!(1 / 2), 2, &mut on).unwrap();
        assert_eq!((on.asked, on.built), (2, 2));
        assert_eq!(quiet, told);
        assert_eq!(insert_knot(&u, &d, &q!(1 / 2), 2).unwrap(), told);
    }
}
