//! A B-spline curve split at a parameter strictly inside its domain: t inserted until its
//! multiplicity is p (Boehm's insertion, The NURBS Book A5.1), then the knots and the control
//! points cut where t is (The NURBS Book A5.6 applied to a curve): the curve on [a, t] and the
//! curve on [t, b], each on its own knots, which keep the parameter.

use crate::{BSplineCurve, BSplineError, KnotVector};
use cagd_linalg::Point;
use cagd_scalar::Scalar;
use cagd_words::{said, Lang, Message, Phrase};
use std::cmp::Ordering;

/// Why a B-spline curve is not split.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum SplitError {
    /// A parameter not strictly inside the domain of the curve.
    NotInsideCurve {
        /// The parameter.
        t: String,
        /// The domain's start.
        a: String,
        /// The domain's end.
        b: String,
    },
    /// The knot inserted not found among the knots.
    #[default]
    KnotNotFound,
    /// A knot vector too short to cut.
    KnotVectorShort,
    /// A control polygon too short to cut.
    PolygonShort,
    /// The insertion or the halves refused.
    BSpline(BSplineError),
}

impl Message for SplitError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            SplitError::NotInsideCurve { t, a, b } => said(
                lang,
                "‹› is not strictly inside the domain [‹›, ‹›] of the curve",
                "‹› no está estrictamente dentro del dominio [‹›, ‹›] de la curva",
                [t.into(), a.into(), b.into()],
            ),
            SplitError::KnotNotFound => said(
                lang,
                "the knot inserted was not found",
                "no se encontró el nudo insertado",
                [],
            ),
            SplitError::KnotVectorShort => said(
                lang,
                "the knot vector is too short",
                "la sucesión de nudos es demasiado corta",
                [],
            ),
            SplitError::PolygonShort => said(
                lang,
                "the control polygon is too short",
                "el polígono de control es demasiado corto",
                [],
            ),
            SplitError::BSpline(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
        }
    }
}

cagd_words::display_english!(SplitError);

impl From<BSplineError> for SplitError {
    fn from(e: BSplineError) -> Self {
        SplitError::BSpline(e)
    }
}

impl<S: Scalar> BSplineCurve<S> {
    /// The curve split at t strictly inside its domain [a, b]: t inserted (Boehm) until its
    /// multiplicity is p, so that the point d_{s-1} before the first copy U_s = t is c(t); then
    /// the curve on [a, t] has the points d_0, ..., d_{s-1} and the knots U_0, ..., U_{s+p-1},
    /// t, and the curve on [t, b] the points d_{s-1}, ..., d_{N-1} and the knots t, U_s, ...,
    /// U_{N+p} (The NURBS Book's convention, N points).
    ///
    /// ```
    /// use cagd_bspline::{BSplineCurve, KnotVector};
    /// use cagd_linalg::Point;
    /// use cagd_scalar::{q, BigRational};
    /// let knots = KnotVector::from_notes(vec![q!(0), q!(0), q!(1), q!(1)], 2).unwrap();
    /// let p = |x: BigRational| Point::new(vec![x]);
    /// let c = BSplineCurve::try_new(knots, vec![p(q!(0)), p(q!(1)), p(q!(2))]).unwrap();
    /// let (left, right) = c.split_at(&q!(1/2)).unwrap();
    /// assert_eq!(left.points(), [p(q!(0)), p(q!(1/2)), p(q!(1))]);
    /// assert_eq!(right.points(), [p(q!(1)), p(q!(3/2)), p(q!(2))]);
    /// ```
    pub fn split_at(&self, t: &S) -> Result<(Self, Self), SplitError> {
        let (a, b) = self.domain();
        let inside = matches!(t.compare(&a), Some(Ordering::Greater))
            && matches!(t.compare(&b), Some(Ordering::Less));
        if !inside {
            return Err(SplitError::NotInsideCurve {
                t: t.to_text(),
                a: a.to_text(),
                b: b.to_text(),
            });
        }
        let p = self.degree();
        let times = p.saturating_sub(self.knots().multiplicity(t));
        let c = if times > 0 {
            self.insert_knot(t, times)?
        } else {
            self.clone()
        };
        let full = c.knots().full();
        let s = full
            .iter()
            .position(|u| u == t)
            .ok_or(SplitError::KnotNotFound)?;
        let (Some(left_knots), Some(right_knots)) = (full.get(..s + p), full.get(s..)) else {
            return Err(SplitError::KnotVectorShort);
        };
        let (Some(left_points), Some(right_points)) = (
            c.points().get(..s),
            s.checked_sub(1).and_then(|k| c.points().get(k..)),
        ) else {
            return Err(SplitError::PolygonShort);
        };
        let mut lk = left_knots.to_vec();
        lk.push(t.clone());
        let mut rk = vec![t.clone()];
        rk.extend(right_knots.iter().cloned());
        let make = |k: Vec<S>, pts: &[Point<S>]| {
            KnotVector::from_full(k, p).and_then(|k| BSplineCurve::try_new(k, pts.to_vec()))
        };
        Ok((make(lk, left_points)?, make(rk, right_points)?))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, BigRational};
    use strum::IntoEnumIterator;

    fn p(x: BigRational) -> Point<BigRational> {
        Point::new(vec![x])
    }

    #[test]
    fn split_of_a_cubic_on_two_spans() {
        // degree 2 on the notes' knots 0, 0, 1, 2, 2 split at the knot 1 (multiplicity 1 → 2)
        let knots = KnotVector::from_notes(vec![q!(0), q!(0), q!(1), q!(2), q!(2)], 2).unwrap();
        let c = BSplineCurve::try_new(knots, vec![p(q!(0)), p(q!(2)), p(q!(4)), p(q!(0))]).unwrap();
        let (left, right) = c.split_at(&q!(1)).unwrap();
        // the inserted point (d_1 + d_2)/2 = 3 is the joint
        assert_eq!(left.points(), [p(q!(0)), p(q!(2)), p(q!(3))]);
        assert_eq!(right.points(), [p(q!(3)), p(q!(4)), p(q!(0))]);
        assert_eq!(left.domain(), (q!(0), q!(1)));
        assert_eq!(right.domain(), (q!(1), q!(2)));
        assert_eq!(
            c.split_at(&q!(2)),
            Err(SplitError::NotInsideCurve {
                t: "2".into(),
                a: "0".into(),
                b: "2".into()
            })
        );
    }

    #[test]
    fn every_variant_in_both_languages() {
        for m in SplitError::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
