//! Circular arcs of exact angles: a sweep angle θ from a start angle α, in N rational quadratic
//! arcs, as a NURBS curve whose numbers stay in Q or one Q(√d).
//!
//! Each arc of angle 2h = θ/N from the angle β is the rational quadratic Bézier arc
//! `(cos β, sin β)`, `(cos(β + h), sin(β + h))/cos h`, `(cos(β + 2h), sin(β + 2h))` with the
//! weights 1, cos h, 1 (the notes' circle of N arcs, chapter 6, with middle weights cos(π/N),
//! is the case α = 0, θ = 360°; Piegl and Tiller, A7.1). Its numbers are exact when the cosines
//! and sines of the angles α + k h, k = 0, ..., 2N, lie in one field: cos and sin of a rational
//! number of degrees are both in a quadratic field exactly for the multiples of 30° (Q(√3))
//! and of 45° (Q(√2)) — cos 36° = (1 + √5)/4 is in Q(√5) but sin 36° is not in any quadratic
//! field — so the angles must all be multiples of 30°, or all multiples of 45°; any other arc
//! is refused with the angle at fault. The arcs must be below 180° (cos h > 0).

use crate::angles::multiple;
use crate::message::curve::Curve as Say;
use crate::ops::out::{at, num};
use crate::spec::Num;
use crate::value::ExactScalar;
use crate::ProblemError;
use cagd_bspline::{KnotVector, NurbsCurve};
use cagd_linalg::Point;
use cagd_scalar::BigRational;

/// cos and sin of k·30° (k mod 12) or k·45° (k mod 8), with the root the field needs.
fn table<S: ExactScalar>(k: i64, step: i64) -> Result<(S, S), Say> {
    let half = |x: S| x / S::from_i64(2);
    let root = |d: u64| S::sqrt_of(d).ok_or(Say::AngleNeedsRoot { root: d });
    let (c, s): (S, S) = match step {
        30 => {
            let r3 = || root(3).map(half);
            match k.rem_euclid(12) {
                0 => (S::one(), S::zero()),
                1 => (r3()?, half(S::one())),
                2 => (half(S::one()), r3()?),
                3 => (S::zero(), S::one()),
                4 => (-half(S::one()), r3()?),
                5 => (-r3()?, half(S::one())),
                6 => (-S::one(), S::zero()),
                7 => (-r3()?, -half(S::one())),
                8 => (-half(S::one()), -r3()?),
                9 => (S::zero(), -S::one()),
                10 => (half(S::one()), -r3()?),
                _ => (r3()?, -half(S::one())),
            }
        }
        _ => {
            let r2 = || root(2).map(half);
            match k.rem_euclid(8) {
                0 => (S::one(), S::zero()),
                1 => (r2()?, r2()?),
                2 => (S::zero(), S::one()),
                3 => (-r2()?, r2()?),
                4 => (-S::one(), S::zero()),
                5 => (-r2()?, -r2()?),
                6 => (S::zero(), -S::one()),
                _ => (r2()?, -r2()?),
            }
        }
    };
    Ok((c, s))
}

/// An angle in degrees as a rational number.
pub(crate) fn degrees<S: ExactScalar>(x: &Num, path: &str) -> Result<BigRational, ProblemError> {
    let v = num::<S>(x, path)?;
    v.as_rational()
        .map(|q| q.into_owned())
        .ok_or_else(|| ProblemError::at(path, Say::AngleNotRational { found: v.to_text() }))
}

/// The arc of `radius` about the origin of the XY plane from `start` through `sweep` degrees,
/// in `arcs` arcs, on `domain` (double knots at the joints), as a NURBS curve in R².
pub(crate) fn arc<S: ExactScalar>(
    radius: &S,
    start: &BigRational,
    sweep: &BigRational,
    arcs: usize,
    domain: (S, S),
    path: &str,
) -> Result<NurbsCurve<S>, ProblemError> {
    let zero = BigRational::from_integer(0.into());
    let full = BigRational::from_integer(360.into());
    if *sweep <= zero || *sweep > full {
        return Err(ProblemError::at(
            path,
            Say::SweepOutOfRange {
                found: sweep.to_string(),
            },
        ));
    }
    let n = i64::try_from(arcs.max(1)).unwrap_or(1);
    let h = sweep / BigRational::from_integer((2 * n).into());
    if h >= BigRational::from_integer(90.into()) {
        return Err(ProblemError::at(
            path,
            Say::ArcTooWide {
                arcs,
                each: (sweep / BigRational::from_integer(n.into())).to_string(),
            },
        ));
    }
    let angles: Vec<BigRational> = (0..=2 * n)
        .map(|k| start + &h * BigRational::from_integer(k.into()))
        .collect();
    let step = if angles.iter().all(|a| multiple(a, 30).is_some()) {
        30
    } else if angles.iter().all(|a| multiple(a, 45).is_some()) {
        45
    } else {
        let bad = angles
            .iter()
            .find(|a| multiple(a, 30).is_none() && multiple(a, 45).is_none())
            .or_else(|| angles.iter().find(|a| multiple(a, 30).is_none()))
            .cloned()
            .unwrap_or_default();
        return Err(ProblemError::at(
            path,
            Say::AngleInNoField {
                angle: bad.to_string(),
            },
        ));
    };
    let (ch, _) =
        table::<S>(multiple(&h, step).unwrap_or(0), step).map_err(|m| ProblemError::at(path, m))?;
    let mut points = Vec::with_capacity(angles.len());
    let mut weights = Vec::with_capacity(angles.len());
    for (k, a) in angles.iter().enumerate() {
        let (c, s) = table::<S>(multiple(a, step).unwrap_or(0), step)
            .map_err(|m| ProblemError::at(path, m))?;
        if k % 2 == 0 {
            points.push(Point::new(vec![radius.clone() * c, radius.clone() * s]));
            weights.push(S::one());
        } else {
            let r = radius.clone() / ch.clone();
            points.push(Point::new(vec![r.clone() * c, r * s]));
            weights.push(ch.clone());
        }
    }
    let (a, b) = domain;
    let len = b.clone() - a.clone();
    let mut breaks = Vec::with_capacity(arcs + 1);
    for j in 0..=n {
        breaks.push(a.clone() + len.clone() * S::from_ratio(j, n));
    }
    // double knots at the joints (the arcs meet with C^0 knots, as in the notes' circle)
    let mut notes = vec![a.clone(), a];
    for x in breaks.iter().skip(1).take(arcs.saturating_sub(1)) {
        notes.push(x.clone());
        notes.push(x.clone());
    }
    notes.push(b.clone());
    notes.push(b);
    let knots = KnotVector::from_notes(notes, 2).map_err(at(path))?;
    NurbsCurve::try_new(knots, points, weights).map_err(at(path))
}
