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
//! is refused with the angle at fault ([`ArcError`]). The arcs must be below 180° (cos h > 0).

use crate::{BSplineError, KnotVector, NurbsCurve};
use cagd_linalg::Point;
use cagd_scalar::{BigRational, Scalar};
use cagd_words::{said, Lang, Message, Phrase};

/// Why an arc of exact angles is not built.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum ArcError {
    /// An angle whose cosine or sine needs √`root`, which the number field has not.
    AngleNeedsRoot {
        /// The root the angle needs.
        root: u64,
    },
    /// A sweep angle outside (0°, 360°].
    SweepOutOfRange {
        /// The sweep angle, in degrees.
        found: String,
    },
    /// Arcs of 180° or more.
    ArcTooWide {
        /// The number of arcs.
        arcs: usize,
        /// The angle of each, in degrees.
        each: String,
    },
    /// An angle whose cosine and sine are in no quadratic field shared with the others.
    AngleInNoField {
        /// The angle, in degrees.
        angle: String,
    },
    /// The knots or the NURBS curve refused (an empty domain).
    BSpline(BSplineError),
}

impl Default for ArcError {
    fn default() -> Self {
        ArcError::AngleNeedsRoot { root: 2 }
    }
}

impl Message for ArcError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            ArcError::AngleNeedsRoot { root } => said(
                lang,
                "this angle needs √‹›, which the problem's number field has not (use one root: multiples of 30° need √3, of 45° √2)",
                "este ángulo necesita √‹›, que el cuerpo de números del problema no tiene (use una sola raíz: los múltiplos de 30° necesitan √3, los de 45° √2)",
                [root.into()],
            ),
            ArcError::SweepOutOfRange { found } => said(
                lang,
                "the sweep angle must be in (0°, 360°], found ‹›°",
                "el ángulo de barrido ha de estar en (0°, 360°], se encontró ‹›°",
                [found.into()],
            ),
            ArcError::ArcTooWide { arcs, each } => said(
                lang,
                "‹› arcs of ‹›° each: an arc must be below 180° (its middle weight cos(θ/2N) is then positive); take more arcs",
                "‹› arcos de ‹›° cada uno: un arco ha de medir menos de 180° (así su peso central cos(θ/2N) es positivo); tome más arcos",
                [arcs.into(), each.into()],
            ),
            ArcError::AngleInNoField { angle } => said(
                lang,
                "the arc needs cos and sin of ‹›°, which are in no quadratic field shared with the other angles α + k θ/(2N): only multiples of 30° (in Q(√3)) or of 45° (in Q(√2)) are exact (cos 36° = (1 + √5)/4, but sin 36° is in no quadratic field)",
                "el arco necesita cos y sen de ‹›°, que no están en ningún cuerpo cuadrático común con los demás ángulos α + k θ/(2N): solo los múltiplos de 30° (en Q(√3)) o de 45° (en Q(√2)) son exactos (cos 36° = (1 + √5)/4, pero sen 36° no está en ningún cuerpo cuadrático)",
                [angle.into()],
            ),
            ArcError::BSpline(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
        }
    }
}

cagd_words::display_english!(ArcError);

impl From<BSplineError> for ArcError {
    fn from(e: BSplineError) -> Self {
        ArcError::BSpline(e)
    }
}

/// cos and sin of k·30° (k mod 12) or k·45° (k mod 8), with the root the field needs.
fn table<S: Scalar>(k: i64, step: i64) -> Result<(S, S), ArcError> {
    let half = |x: S| x / S::from_i64(2);
    let root = |d: u64| S::sqrt_of(d).ok_or(ArcError::AngleNeedsRoot { root: d });
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

/// The whole multiple k of `step` degrees that `deg` is, if it is one.
fn multiple(deg: &BigRational, step: i64) -> Option<i64> {
    let k = deg / BigRational::from_integer(step.into());
    if !k.is_integer() {
        return None;
    }
    i64::try_from(k.to_integer()).ok()
}

/// The root (2 or 3) the angles `start + k sweep/(2 arcs)`, k = 0, ..., 2 arcs, need: `None`
/// when they are all multiples of 90° (rational cosines and sines), 3 when all are multiples
/// of 30°, else 2.
///
/// ```
/// use cagd_bspline::root_of_angles;
/// use cagd_scalar::q;
/// assert_eq!(root_of_angles(&q!(0), &q!(360), 2), None);
/// assert_eq!(root_of_angles(&q!(0), &q!(360), 3), Some(3));
/// assert_eq!(root_of_angles(&q!(0), &q!(90), 1), Some(2));
/// ```
pub fn root_of_angles(start: &BigRational, sweep: &BigRational, arcs: usize) -> Option<u64> {
    let n = i64::try_from(arcs.max(1)).ok()?;
    let h = sweep / BigRational::from_integer((2 * n).into());
    let angles: Vec<BigRational> = (0..=2 * n)
        .map(|k| start + &h * BigRational::from_integer(k.into()))
        .collect();
    if angles.iter().all(|a| multiple(a, 90).is_some()) {
        None
    } else if angles.iter().all(|a| multiple(a, 30).is_some()) {
        Some(3)
    } else {
        Some(2)
    }
}

/// The default number of arcs of a sweep θ: arcs of at most 90°, `N = ⌈θ/90°⌉` (at least 1).
///
/// ```
/// use cagd_bspline::default_arcs;
/// use cagd_scalar::q;
/// assert_eq!(default_arcs(&q!(90)), 1);
/// assert_eq!(default_arcs(&q!(270)), 3);
/// assert_eq!(default_arcs(&q!(300)), 4);
/// ```
pub fn default_arcs(sweep: &BigRational) -> usize {
    let q = sweep / BigRational::from_integer(90.into());
    let n = q.ceil().to_integer();
    usize::try_from(n).unwrap_or(1).max(1)
}

/// The arc of `radius` about the origin of the XY plane from `start` through `sweep` degrees,
/// in `arcs` rational quadratic arcs (see [the module](self)), on `domain` with double knots
/// at the joints, as a NURBS curve in R².
///
/// ```
/// use cagd_bspline::exact_arc;
/// use cagd_scalar::{q, Print, Quadratic};
/// // a half circle in three arcs of 60°: middle weights cos 30° = √3/2
/// let (zero, one) = (Quadratic::from_rational(q!(0)), Quadratic::from_rational(q!(1)));
/// let c = exact_arc(&one, &q!(0), &q!(180), 3, (zero, one.clone())).unwrap();
/// let w: Vec<String> = c.weights().iter().map(|w| w.to_text()).collect();
/// assert_eq!(w, ["1", "√3/2", "1", "√3/2", "1", "√3/2", "1"]);
/// assert_eq!(c.points()[1].to_text(), "(1, √3/3)");
/// ```
pub fn exact_arc<S: Scalar>(
    radius: &S,
    start: &BigRational,
    sweep: &BigRational,
    arcs: usize,
    domain: (S, S),
) -> Result<NurbsCurve<S>, ArcError> {
    let zero = BigRational::from_integer(0.into());
    let full = BigRational::from_integer(360.into());
    if *sweep <= zero || *sweep > full {
        return Err(ArcError::SweepOutOfRange {
            found: sweep.to_string(),
        });
    }
    let n = i64::try_from(arcs.max(1)).unwrap_or(1);
    let h = sweep / BigRational::from_integer((2 * n).into());
    if h >= BigRational::from_integer(90.into()) {
        return Err(ArcError::ArcTooWide {
            arcs,
            each: (sweep / BigRational::from_integer(n.into())).to_string(),
        });
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
        return Err(ArcError::AngleInNoField {
            angle: bad.to_string(),
        });
    };
    let (ch, _) = table::<S>(multiple(&h, step).unwrap_or(0), step)?;
    let mut points = Vec::with_capacity(angles.len());
    let mut weights = Vec::with_capacity(angles.len());
    for (k, a) in angles.iter().enumerate() {
        let (c, s) = table::<S>(multiple(a, step).unwrap_or(0), step)?;
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
    let knots = KnotVector::from_notes(notes, 2)?;
    Ok(NurbsCurve::try_new(knots, points, weights)?)
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, Print, Quadratic};
    use strum::IntoEnumIterator;

    #[test]
    fn a_quarter_circle_in_the_field_of_root_two() {
        // one arc of 90° from 0°: h = 45°, middle point (cos 45°, sin 45°)/cos 45° = (1, 1)
        let c = exact_arc::<Quadratic>(
            &Quadratic::from_rational(q!(2)),
            &q!(0),
            &q!(90),
            1,
            (
                Quadratic::from_rational(q!(0)),
                Quadratic::from_rational(q!(1)),
            ),
        )
        .unwrap();
        let text: Vec<String> = c.points().iter().map(|p| p.to_text()).collect();
        assert_eq!(text, ["(2, 0)", "(2, 2)", "(0, 2)"]);
        let w: Vec<String> = c.weights().iter().map(|w| w.to_text()).collect();
        assert_eq!(w, ["1", "√2/2", "1"]);
    }

    #[test]
    fn refusals() {
        let unit = (q!(0), q!(1));
        let arc = |start, sweep, arcs| {
            exact_arc::<BigRational>(&q!(1), &start, &sweep, arcs, unit.clone())
        };
        assert_eq!(
            arc(q!(0), q!(400), 5),
            Err(ArcError::SweepOutOfRange {
                found: "400".into()
            })
        );
        assert_eq!(
            arc(q!(0), q!(360), 2),
            Err(ArcError::ArcTooWide {
                arcs: 2,
                each: "180".into()
            })
        );
        assert_eq!(
            arc(q!(0), q!(72), 1),
            Err(ArcError::AngleInNoField { angle: "36".into() })
        );
        // 60° arcs need √3, which the rationals have not
        assert_eq!(
            arc(q!(0), q!(120), 1),
            Err(ArcError::AngleNeedsRoot { root: 3 })
        );
    }

    #[test]
    fn roots_and_arcs() {
        assert_eq!(root_of_angles(&q!(30), &q!(90), 1), Some(2));
        assert_eq!(root_of_angles(&q!(0), &q!(180), 1), None);
        assert_eq!(default_arcs(&q!(360)), 4);
    }

    #[test]
    fn every_variant_in_both_languages() {
        for m in ArcError::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
