//! A curve as written (`bezier`, `bspline`, `expr`), checked.

use super::context::Typed;
use super::number::{Degree, Num};
use super::points::{List, Points};
use super::shape::{
    bezier_degree, generic_degree, generic_dim, generic_letter, generic_number, generic_point,
    generic_weights, member, missing, weights_count, Deferred, RawShape,
};
use crate::input::CurveIn;
use crate::message::read::Read;
use crate::value::exact::Number;
use cagd_linalg::Point;
use serde::de::Deserializer;
use serde::Deserialize;

impl<'de> Deserialize<'de> for CurveIn<Number> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let raw = RawShape::deserialize(d)?;
        curve(raw).map_err(Typed::serde)
    }
}

pub(super) fn numbers(key: &str, v: &Deferred) -> Result<Vec<Number>, Typed> {
    let List(xs) = member::<List<Num>>(key, v)?;
    Ok(xs.into_iter().map(|Num(x)| x).collect())
}

/// The points and weights of homogeneous points `(w x, ..., w)` written at `key`: `x` and `w`,
/// or for w = 0 the control vector of the first coordinates and the weight 0.
pub(super) fn split_homogeneous(
    key: &str,
    homogeneous: Vec<Point<Number>>,
) -> Result<(Vec<Point<Number>>, Vec<Number>), Typed> {
    let mut points = Vec::with_capacity(homogeneous.len());
    let mut weights = Vec::with_capacity(homogeneous.len());
    for (i, h) in homogeneous.iter().enumerate() {
        let Some((w, rest)) = h.coords().split_last().filter(|(_, r)| !r.is_empty()) else {
            return Err(Typed::from(Read::HomogeneousPoint { found: h.dim() })
                .below(&format!("{key}[{i}]")));
        };
        let p = if num_traits::Zero::is_zero(w) {
            Point::new(rest.to_vec())
        } else {
            Point::new(rest.iter().map(|x| x.clone() / w.clone()).collect())
        };
        points.push(p);
        weights.push(w.clone());
    }
    Ok((points, weights))
}

/// The weights of a shape: from `"weights"`, or with `"homogeneous": true` from the points'
/// last coordinates (then the points are replaced by their affine parts or vectors).
fn read_weights(
    raw: &RawShape<Points>,
    key: &str,
    points: &mut Vec<Point<Number>>,
) -> Result<Option<Vec<Number>>, Typed> {
    if raw.homogeneous == Some(true) {
        if raw.weights.is_some() {
            return Err(Typed::from(Read::HomogeneousWithWeights).below("weights"));
        }
        super::context::note_homogeneous();
        let (p, w) = split_homogeneous(key, std::mem::take(points))?;
        *points = p;
        return Ok(Some(w));
    }
    let weights = raw
        .weights
        .as_ref()
        .map(|w| numbers("weights", w))
        .transpose()?;
    if let Some(w) = &weights {
        weights_count(points.len(), w)?;
    }
    Ok(weights)
}

pub(super) fn curve(mut raw: RawShape<Points>) -> Result<CurveIn<Number>, Typed> {
    raw.unused_points_read()?;
    if raw.homogeneous.is_some() && raw.bezier.is_none() && raw.bspline.is_none() {
        return Err(Typed::from(Read::HomogeneousWithoutPoints).below("homogeneous"));
    }
    if let Some(letter) = &raw.generic {
        let letter = generic_letter("generic", letter)?;
        let Degree(n) = member(
            "degree",
            raw.degree.as_ref().ok_or_else(|| missing("degree"))?,
        )?;
        let n = generic_degree(n, "degree")?;
        let dim = generic_dim(&raw)?;
        let points = (0..=n).map(|i| generic_point(&letter, dim, &[i])).collect();
        let weights = match (generic_weights(&raw)?, &raw.weights) {
            (Some(w), _) => Some((0..=n).map(|i| generic_number(&w, &[i])).collect()),
            (None, Some(w)) => Some(numbers("weights", w)?),
            (None, None) => None,
        };
        if let Some(w) = &weights {
            weights_count(n + 1, w)?;
        }
        return Ok(CurveIn::Bezier { points, weights });
    }
    if let Some(pts) = raw.bezier.take() {
        let Points(mut points) = pts.points("bezier")?;
        bezier_degree(points.len(), |points, degree, max| Read::CurveDegree {
            points,
            degree,
            max,
        })?;
        let weights = read_weights(&raw, "bezier", &mut points)?;
        return Ok(CurveIn::Bezier { points, weights });
    }
    if let Some(pts) = raw.bspline.take() {
        let Points(mut points) = pts.points("bspline")?;
        let Degree(degree) = member(
            "degree",
            raw.degree.as_ref().ok_or_else(|| missing("degree"))?,
        )?;
        let knots = numbers("knots", raw.knots.as_ref().ok_or_else(|| missing("knots"))?)?;
        let weights = read_weights(&raw, "bspline", &mut points)?;
        return Ok(CurveIn::BSpline {
            points,
            degree,
            knots,
            weights,
        });
    }
    if let Some(e) = raw.expr {
        return e.vector::<Number>().map(CurveIn::Expr).map_err(Typed::from);
    }
    Err(Read::NotCurve.into())
}
