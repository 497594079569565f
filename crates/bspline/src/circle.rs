//! Circles as quadratic NURBS curves: the notes' 9-point circle and the circle of N arcs.

use crate::knots::scalar_of;
use crate::{BSplineError, CircleData, Construction, KnotVector, NurbsCurve};
use cagd_linalg::Point;
use cagd_scalar::Scalar;
use std::cmp::Ordering;

/// The notes' unit circle (chapter 6, "Circunferencia B-spline"): control points
/// `{(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)}`, weights
/// `{1, √2/2, 1, √2/2, 1, √2/2, 1, √2/2, 1}`, knots `{0, 0, 1/4, 1/4, 1/2, 1/2, 3/4, 3/4, 1, 1}`
/// (notes' convention). Needs √2: an error over the rationals.
///
/// ```
/// use cagd_bspline::unit_circle;
/// use cagd_scalar::{parse_number, BigRational, FieldOps, Print, Quadratic};
/// let c = unit_circle::<Quadratic>().unwrap();
/// assert_eq!(c.weights()[1].to_text(), "√2/2");
/// let p = c.eval(&parse_number("1/8").unwrap()).unwrap();
/// assert_eq!(p.dot(&p), Quadratic::from_i64(1));
/// assert_eq!(p.to_text(), "(√2/2, √2/2)");
/// assert_eq!(
///     unit_circle::<BigRational>().unwrap_err().to_string(),
///     "the circle of 4 arcs (cos(π/4) = √2/2, sin(π/4) = √2/2) needs the quadratic field √2: \
///      compute over a + b√2, not over the rationals"
/// );
/// ```
pub fn unit_circle<S: Scalar>() -> Result<NurbsCurve<S>, BSplineError> {
    circle_of_arcs(4, &S::one(), None, (S::zero(), S::one()))
}

/// The slides' circle of radius R (chapter 6, slides, "Circunferencias B-spline"): control
/// points `{(R, 0), (R, R), (0, R), (-R, R), (-R, 0), (-R, -R), (0, -R), (R, -R), (R, 0)}`,
/// weights `{1, 1/√2, 1, ...}` and knots `[0, 0, 1, 1, 2, 2, 3, 3, 4, 4]` on [0, 4].
pub fn circle_slides<S: Scalar>(radius: &S) -> Result<NurbsCurve<S>, BSplineError> {
    circle_of_arcs(4, radius, None, (S::zero(), scalar_of(4)))
}

/// The circle of radius R centred at the origin as a quadratic NURBS curve of N arcs, each
/// of angle 2π/N, on the domain [a, b] with double knots at `a + j (b - a)/N`.
///
/// With `c = cos(π/N)`, `s = sin(π/N)` and `z_j = (cos(jπ/N), sin(jπ/N))` (computed exactly
/// by rotating by (c, s)), the control points are `R z_j` for even j (on the circle, with
/// weight 1) and `(R/c) z_j` for odd j (where the tangents at the neighbouring points meet,
/// with weight c), j = 0, ..., 2N; the last equals the first.
///
/// `half_angle` is `(cos(π/N), sin(π/N))`; `None` uses the built-in values for N = 3
/// `(1/2, √3/2)`, N = 4 `(√2/2, √2/2)` and N = 6 `(√3/2, 1/2)`. A number the scalar type
/// cannot hold gives [`BSplineError::NeedsRoot`]: N = 4 needs √2; N = 3 has the rational
/// middle weights 1/2 but the vertices `(-1/2, ±√3/2)` of an equilateral triangle, which no
/// rational coordinates can give, so it needs √3 too. Over exact types the given pair is
/// checked: `c² + s² = 1`, `c, s > 0` and `(c + i s)^N = -1`.
pub fn circle_of_arcs<S: Scalar>(
    arcs: usize,
    radius: &S,
    half_angle: Option<(S, S)>,
    domain: (S, S),
) -> Result<NurbsCurve<S>, BSplineError> {
    if arcs < 3 {
        return Err(BSplineError::NotACircle {
            reason: CircleData::TooFewArcs { arcs },
        });
    }
    // a radius in letters (`R`) has no sign to decide: the construction holds for R > 0,
    // which the problem layer states; a number must be positive
    if radius
        .compare(&S::zero())
        .is_some_and(|o| o != Ordering::Greater)
    {
        return Err(BSplineError::NotACircle {
            reason: CircleData::Radius {
                radius: radius.to_text(),
            },
        });
    }
    let (a, b) = domain;
    if a.compare(&b) != Some(Ordering::Less) {
        return Err(BSplineError::EmptyDomain {
            start: a.to_text(),
            end: b.to_text(),
        });
    }
    let (c, s) = match half_angle {
        Some(pair) => pair,
        None => known_half_angle(arcs)?,
    };
    check_half_angle(arcs, &c, &s)?;
    let inv_c = S::one().checked_div(&c).ok_or(BSplineError::NotACircle {
        reason: CircleData::CosZero,
    })?;
    let mut points = Vec::with_capacity(2 * arcs + 1);
    let mut weights = Vec::with_capacity(2 * arcs + 1);
    let mut z = (S::one(), S::zero());
    for j in 0..=2 * arcs {
        let p = Point::new(vec![z.0.clone(), z.1.clone()]);
        if j % 2 == 0 {
            points.push(p.scale(radius));
            weights.push(S::one());
        } else {
            points.push(p.scale(&radius.mul_ref(&inv_c)));
            weights.push(c.clone());
        }
        // z ← z · (c + i s)
        z = (
            z.0.mul_ref(&c) - z.1.mul_ref(&s),
            z.0.mul_ref(&s) + z.1.mul_ref(&c),
        );
    }
    // Close the curve exactly (over f64 the rotated point only approximates the first).
    if let (Some(first), Some(last)) = (points.first().cloned(), points.last_mut()) {
        *last = first;
    }
    let n = scalar_of::<S>(arcs);
    let mut notes = vec![a.clone(), a.clone()];
    for j in 1..arcs {
        let x = a.clone() + (b.sub_ref(&a)) * scalar_of::<S>(j) / &n;
        notes.push(x.clone());
        notes.push(x);
    }
    notes.push(b.clone());
    notes.push(b);
    NurbsCurve::try_new(KnotVector::from_notes(notes, 2)?, points, weights)
}

/// `x > 0`, false when the order cannot be decided (a NaN).
fn is_positive<S: Scalar>(x: &S) -> bool {
    x.compare(&S::zero()) == Some(Ordering::Greater)
}

/// cos(π/N) and sin(π/N) for N = 3, 4, 6, in the scalar type if it holds them: each is 1/2 or
/// √d/2, and √d/2 is taken from the field (`S::sqrt_of(d)` divided by `S::from_i64(2)`).
fn known_half_angle<S: Scalar>(arcs: usize) -> Result<(S, S), BSplineError> {
    // (cos, sin) = (1/2, √3/2), (√2/2, √2/2), (√3/2, 1/2): which of them is the root √d/2
    let (cos_is_root, sin_is_root, radicand) = match arcs {
        3 => (false, true, 3),
        4 => (true, true, 2),
        6 => (true, false, 3),
        _ => {
            return Err(BSplineError::NotACircle {
                reason: CircleData::NotBuiltIn { arcs },
            })
        }
    };
    let text = |is_root: bool| {
        if is_root {
            format!("√{radicand}/2")
        } else {
            "1/2".to_string()
        }
    };
    let half_root = S::sqrt_of(radicand)
        .map(|root| root / S::from_i64(2))
        .ok_or_else(|| BSplineError::NeedsRoot {
            what: Construction::Circle {
                arcs,
                cos: text(cos_is_root),
                sin: text(sin_is_root),
            },
            radicand,
        })?;
    let value = |is_root: bool| {
        if is_root {
            half_root.clone()
        } else {
            S::from_ratio(1, 2)
        }
    };
    Ok((value(cos_is_root), value(sin_is_root)))
}

/// The checks of (c, s) = (cos(π/N), sin(π/N)): positive always; exactly on the unit circle
/// and of order 2N over exact types.
fn check_half_angle<S: Scalar>(arcs: usize, c: &S, s: &S) -> Result<(), BSplineError> {
    if !(is_positive(c) && is_positive(s)) {
        return Err(BSplineError::NotACircle {
            reason: CircleData::NotPositive {
                arcs,
                cos: c.to_text(),
                sin: s.to_text(),
            },
        });
    }
    if !S::is_exact() {
        return Ok(());
    }
    let norm = c.mul_ref(c) + s.mul_ref(s);
    if !norm.is_one() {
        return Err(BSplineError::NotACircle {
            reason: CircleData::NotUnit {
                cos: c.to_text(),
                sin: s.to_text(),
                norm: norm.to_text(),
            },
        });
    }
    let mut z = (S::one(), S::zero());
    for _ in 0..arcs {
        z = (
            z.0.mul_ref(c) - z.1.mul_ref(s),
            z.0.mul_ref(s) + z.1.mul_ref(c),
        );
    }
    if !(z.0 == -S::one() && z.1.is_zero()) {
        return Err(BSplineError::NotACircle {
            reason: CircleData::WrongAngle {
                cos: c.to_text(),
                sin: s.to_text(),
                arcs,
            },
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{parse_number, q, BigRational, Print, Quadratic};

    fn num(text: &str) -> Quadratic {
        parse_number(text).unwrap()
    }

    #[test]
    fn the_notes_circle_literally() {
        let c = unit_circle::<Quadratic>().unwrap();
        let pts: Vec<String> = c.points().iter().map(|p| p.to_text()).collect();
        assert_eq!(
            pts,
            [
                "(1, 0)", "(1, 1)", "(0, 1)", "(-1, 1)", "(-1, 0)", "(-1, -1)", "(0, -1)",
                "(1, -1)", "(1, 0)"
            ]
        );
        let w: Vec<String> = c.weights().iter().map(|w| w.to_text()).collect();
        assert_eq!(w, ["1", "√2/2", "1", "√2/2", "1", "√2/2", "1", "√2/2", "1"]);
        assert_eq!(
            c.knots().to_text(),
            "{0, 0, 1/4, 1/4, 1/2, 1/2, 3/4, 3/4, 1, 1}"
        );
        let s = circle_slides(&num("3")).unwrap();
        assert_eq!(s.knots().to_text(), "{0, 0, 1, 1, 2, 2, 3, 3, 4, 4}");
        assert_eq!(s.points()[3].to_text(), "(-3, 3)");
        assert_eq!(s.weights()[3], num("1/sqrt2"));
    }

    #[test]
    fn three_and_six_arcs_need_root_three() {
        let err = circle_of_arcs::<BigRational>(3, &q!(1), None, (q!(0), q!(1))).unwrap_err();
        assert_eq!(
            err.to_string(),
            "the circle of 3 arcs (cos(π/3) = 1/2, sin(π/3) = √3/2) needs the quadratic field \
             √3: compute over a + b√3, not over the rationals"
        );
        let c = circle_of_arcs(3, &num("1"), None, (num("0"), num("3"))).unwrap();
        let w: Vec<String> = c.weights().iter().map(|w| w.to_text()).collect();
        assert_eq!(w, ["1", "1/2", "1", "1/2", "1", "1/2", "1"]);
        assert_eq!(c.points()[1].to_text(), "(1, √3)");
        assert_eq!(c.points()[2].to_text(), "(-1/2, √3/2)");
        assert_eq!(c.knots().to_text(), "{0, 0, 1, 1, 2, 2, 3, 3}");
        let six = circle_of_arcs(6, &num("2"), None, (num("0"), num("1"))).unwrap();
        for t in ["1/7", "1/2", "5/6", "1"] {
            let p = six.eval(&num(t)).unwrap();
            assert_eq!(p.dot(&p), num("4"));
        }
    }

    #[test]
    fn given_half_angles_are_checked() {
        let err = circle_of_arcs(5, &q!(1), None, (q!(0), q!(1))).unwrap_err();
        assert!(err
            .to_string()
            .contains("cos(π/5) and sin(π/5) are not built in"));
        // (3/5, 4/5) is on the unit circle but is not the angle π/4.
        let err =
            circle_of_arcs(4, &q!(1), Some((q!(3 / 5), q!(4 / 5))), (q!(0), q!(1))).unwrap_err();
        assert_eq!(
            err.to_string(),
            "not a circle: (3/5, 4/5) is not (cos(π/4), sin(π/4)): turning 4 times by it does \
             not reach the angle π"
        );
        let err =
            circle_of_arcs(4, &q!(1), Some((q!(1 / 2), q!(1 / 2))), (q!(0), q!(1))).unwrap_err();
        assert!(err.to_string().contains("cos² + sin² = 1/2, not 1"));
        assert!(circle_of_arcs(2, &q!(1), None, (q!(0), q!(1))).is_err());
        assert!(circle_of_arcs(4, &num("0"), None, (num("0"), num("1"))).is_err());
        assert!(circle_of_arcs(4, &num("1"), None, (num("1"), num("1"))).is_err());
        // N = 4 with the pair given explicitly is the built-in circle.
        let h = num("sqrt2/2");
        let given = circle_of_arcs(4, &num("1"), Some((h.clone(), h)), (num("0"), num("1")));
        assert_eq!(given.unwrap(), unit_circle().unwrap());
    }

    #[test]
    fn over_f64() {
        let c = unit_circle::<f64>().unwrap();
        for i in 0..=16 {
            let p = c.eval(&(f64::from(i) / 16.0)).unwrap();
            assert!((p.dot(&p) - 1.0).abs() < 1e-12);
        }
        assert_eq!(c.points()[8], c.points()[0]);
        let hex = circle_of_arcs::<f64>(
            5,
            &2.0,
            Some((
                (std::f64::consts::PI / 5.0).cos(),
                (std::f64::consts::PI / 5.0).sin(),
            )),
            (0.0, 1.0),
        )
        .unwrap();
        let p = hex.eval(&0.37).unwrap();
        assert!((p.dot(&p) - 4.0).abs() < 1e-12);
    }
}
