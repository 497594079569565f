//! Parameters of a fit computed from the data: uniform, chord length and centripetal
//! (Piegl and Tiller, eq. (9.3)-(9.6); Farin §9.1), and the averaged knots of a B-spline
//! interpolant (Piegl and Tiller, eq. (9.8)).
//!
//! Uniform: `t_k = k/n`. Chord length: `t_k = t_{k-1} + |a_k - a_{k-1}| / L`, L the total
//! length. Centripetal: the same with the square roots `|a_k - a_{k-1}|^{1/2}`. The lengths are
//! square roots, so the parameters are exact (and are given) only when the ratios of the
//! lengths are rational: each length is q_k √d with q_k rational and one d for all (for
//! centripetal, each |a_k - a_{k-1}| rational and its square root q_k √d alike); otherwise the
//! problem is refused, naming the first segment whose length is of another field. Never a
//! float.

use crate::message::curve::Curve as Say;
use crate::problem::Parametrization;
use crate::value::ExactScalar;
use crate::ProblemError;
use cagd_linalg::Point;
use cagd_scalar::BigRational;
use num_traits::{One, ToPrimitive, Zero};

/// A positive rational written as q² d with d a square-free integer (found by trial division
/// up to 10⁴; a larger cofactor is kept whole in d, which can only make two equal roots look
/// different: a refusal, never a wrong value).
fn square_free(x: &BigRational) -> (BigRational, u64) {
    // x = n/m = n m / m², so √x = √(n m)/m
    let nm = x.numer() * x.denom();
    let mut rest = nm.clone();
    let mut q = num_bigint::BigInt::one();
    let mut d = num_bigint::BigInt::one();
    let mut p = num_bigint::BigInt::from(2u32);
    let limit = num_bigint::BigInt::from(10_000u32);
    while p <= limit && &p * &p <= rest {
        let mut e = 0u32;
        while (&rest % &p).is_zero() {
            rest /= &p;
            e += 1;
        }
        for _ in 0..e / 2 {
            q *= &p;
        }
        if e % 2 == 1 {
            d *= &p;
        }
        p += 1;
    }
    // the cofactor: a square, or kept in d
    let r = rest.sqrt();
    if &r * &r == rest {
        q *= r;
    } else {
        d *= rest;
    }
    let q = BigRational::new(q, x.denom().clone());
    (q, d.to_u64().unwrap_or(u64::MAX))
}

/// The square root of a positive rational as q √d.
fn root(x: &BigRational) -> (BigRational, u64) {
    square_free(x)
}

/// The data as rationals.
fn rationals<S: ExactScalar>(points: &[Point<S>]) -> Result<Vec<Vec<BigRational>>, ProblemError> {
    points
        .iter()
        .enumerate()
        .map(|(k, p)| {
            p.coords()
                .iter()
                .map(|x| x.as_rational().map(|q| q.into_owned()))
                .collect::<Option<Vec<_>>>()
                .ok_or_else(|| ProblemError::at(format!("points[{k}]"), Say::ChordNeedsRational))
        })
        .collect()
}

/// The parameters of `points` by `how`, on [0, 1].
pub(crate) fn parameters<S: ExactScalar>(
    how: Parametrization,
    points: &[Point<S>],
) -> Result<Vec<S>, ProblemError> {
    let n = points.len();
    if n < 2 {
        return Err(ProblemError::at("points", Say::ParametersNeedTwoPoints));
    }
    let last = i64::try_from(n - 1).unwrap_or(i64::MAX);
    if how == Parametrization::Uniform {
        return Ok((0..=last).map(|k| S::from_ratio(k, last)).collect());
    }
    let data = rationals(points)?;
    // the step of each segment as q_k (times one common √d)
    let mut steps: Vec<BigRational> = Vec::with_capacity(n - 1);
    let mut common: Option<u64> = None;
    for (k, pair) in data.windows(2).enumerate() {
        let (a, b) = match pair {
            [a, b] => (a, b),
            _ => continue,
        };
        let sq = a
            .iter()
            .zip(b)
            .fold(BigRational::zero(), |acc, (x, y)| acc + (y - x) * (y - x));
        if sq.is_zero() {
            return Err(ProblemError::at(
                format!("points[{}]", k + 1),
                Say::PointsCoincide {
                    first: k,
                    second: k + 1,
                },
            ));
        }
        let (q, d) = root(&sq);
        let (q, d) = match how {
            Parametrization::ChordLength => (q, d),
            _ => {
                // |Δ|^{1/2}: |Δ| = q √d must be rational (d = 1), then its root q' √d'
                if d != 1 {
                    return Err(ProblemError::at(
                        format!("points[{}]", k + 1),
                        Say::CentripetalFourthRoot {
                            to: k + 1,
                            from: k,
                            square: sq.to_string(),
                        },
                    ));
                }
                root(&q)
            }
        };
        match common {
            None => common = Some(d),
            Some(c) if c == d => {}
            Some(c) => {
                // a rational length is "in √1": said as rational
                let (from, to) = (k, k + 1);
                let said = match (d, c) {
                    (1, first_root) => Say::SegmentRational {
                        from,
                        to,
                        first_root,
                    },
                    (root, 1) => Say::SegmentAfterRational { from, to, root },
                    (root, first_root) => Say::SegmentOtherRoot {
                        from,
                        to,
                        root,
                        first_root,
                    },
                };
                return Err(ProblemError::at(format!("points[{}]", k + 1), said));
            }
        }
        steps.push(q);
    }
    let total: BigRational = steps.iter().fold(BigRational::zero(), |a, s| a + s);
    let mut out = Vec::with_capacity(n);
    let mut acc = BigRational::zero();
    out.push(S::zero());
    for (k, s) in steps.iter().enumerate() {
        acc += s;
        out.push(if k + 2 == n {
            S::one()
        } else {
            S::from_rational(&(&acc / &total))
        });
    }
    Ok(out)
}

/// The averaged knots of a B-spline interpolant of degree p through the parameters
/// t_0 < ... < t_n (Piegl and Tiller eq. (9.8)): t_0 and t_n p + 1 times (full convention),
/// and inside `u_{j+p} = (t_j + ... + t_{j+p-1}) / p`, j = 1, ..., n - p.
pub(crate) fn averaged_knots<S: ExactScalar>(params: &[S], p: usize) -> Vec<S> {
    let n = params.len().saturating_sub(1);
    let (first, last) = (
        params.first().cloned().unwrap_or_else(S::zero),
        params.last().cloned().unwrap_or_else(S::one),
    );
    let mut notes = vec![first; p];
    let pp = S::from_i64(i64::try_from(p.max(1)).unwrap_or(1));
    for j in 1..=n.saturating_sub(p) {
        let sum = params
            .iter()
            .skip(j)
            .take(p)
            .fold(S::zero(), |a, t| a + t.clone());
        notes.push(sum / pp.clone());
    }
    notes.extend(std::iter::repeat_n(last, p));
    notes
}
