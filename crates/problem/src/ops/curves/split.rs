//! A B-spline curve split at a parameter (`subdivide` of a curve, and of a spline surface
//! column by column).

use crate::message::fitting::Fitting;
use crate::ops::out::at;
use crate::value::ExactScalar;
use crate::ProblemError;
use cagd_bspline::{BSplineCurve, KnotVector};
use cagd_linalg::Point;

/// A B-spline curve split at t strictly inside its domain [a, b]: t inserted (Boehm) until its
/// multiplicity is p, so that the point d_{s-1} before the first copy U_s = t is c(t); then
/// the curve on [a, t] has the points d_0, ..., d_{s-1} and the knots U_0, ..., U_{s+p-1}, t,
/// and the curve on [t, b] the points d_{s-1}, ..., d_{N-1} and the knots t, U_s, ..., U_{N+p}
/// (The NURBS Book's convention, N points).
pub(crate) fn split_bspline<S: ExactScalar>(
    c: &BSplineCurve<S>,
    t: &S,
    key: &str,
) -> Result<(BSplineCurve<S>, BSplineCurve<S>), ProblemError> {
    let (a, b) = c.domain();
    let inside = matches!(t.compare(&a), Some(std::cmp::Ordering::Greater))
        && matches!(t.compare(&b), Some(std::cmp::Ordering::Less));
    if !inside {
        return Err(ProblemError::at(
            key,
            Fitting::NotInsideCurve {
                t: t.to_text(),
                a: a.to_text(),
                b: b.to_text(),
            },
        ));
    }
    let p = c.degree();
    let times = p.saturating_sub(c.knots().multiplicity(t));
    let c = if times > 0 {
        c.insert_knot(t, times).map_err(at(key))?
    } else {
        c.clone()
    };
    let full = c.knots().full();
    let s = full
        .iter()
        .position(|u| u == t)
        .ok_or_else(|| ProblemError::at(key, Fitting::KnotNotFound))?;
    let (Some(left_knots), Some(right_knots)) = (full.get(..s + p), full.get(s..)) else {
        return Err(ProblemError::at(key, Fitting::KnotVectorShort));
    };
    let (Some(left_points), Some(right_points)) = (
        c.points().get(..s),
        s.checked_sub(1).and_then(|k| c.points().get(k..)),
    ) else {
        return Err(ProblemError::at(key, Fitting::PolygonShort));
    };
    let mut lk = left_knots.to_vec();
    lk.push(t.clone());
    let mut rk = vec![t.clone()];
    rk.extend(right_knots.iter().cloned());
    let make = |k: Vec<S>, pts: &[Point<S>]| {
        KnotVector::from_full(k, p)
            .and_then(|k| BSplineCurve::try_new(k, pts.to_vec()))
            .map_err(at(key))
    };
    Ok((make(lk, left_points)?, make(rk, right_points)?))
}
