//! Parameters of a fit computed from the data: uniform, chord length and centripetal
//! (Piegl and Tiller, eq. (9.3)-(9.6); Farin §9.1), and the averaged knots of a B-spline
//! interpolant (Piegl and Tiller, eq. (9.8)).
//!
//! Uniform: `t_k = k/n`. Chord length: `t_k = t_{k-1} + |a_k - a_{k-1}| / L`, L the total
//! length. Centripetal: the same with the square roots `|a_k - a_{k-1}|^{1/2}`. The lengths are
//! square roots, so the parameters are exact (and are given) only when the ratios of the
//! lengths are rational: each length is q_k √d with q_k rational and one d for all (for
//! centripetal, each |a_k - a_{k-1}| rational and its square root q_k √d alike); otherwise the
//! parameters are refused ([`ParameterError`]), naming the first segment whose length is of
//! another field. Never a float.

use cagd_linalg::Point;
use cagd_scalar::{BigInt, BigRational, Scalar};
use cagd_words::{said, Lang, Message, Phrase};
use num_traits::{One, ToPrimitive, Zero};

/// How the parameters of a fit are computed from the data.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Parametrization {
    /// `t_k = k/n`.
    Uniform,
    /// Steps proportional to the chord lengths |a_k - a_{k-1}| (exact when their ratios are
    /// rational).
    ChordLength,
    /// Steps proportional to the square roots of the chord lengths.
    Centripetal,
}

/// Why the parameters of data points are not computed exactly.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum ParameterError {
    /// Chord-length or centripetal parameters of data not rational (at data point `point`).
    ChordNeedsRational {
        /// The first data point with a coordinate that is not rational.
        point: usize,
    },
    /// Parameters of fewer than two points.
    TooFewPoints,
    /// Two consecutive data points that coincide.
    PointsCoincide {
        /// The first point.
        first: usize,
        /// The second point.
        second: usize,
    },
    /// A centripetal step that is a fourth root.
    CentripetalFourthRoot {
        /// The later point of the segment.
        to: usize,
        /// The earlier point of the segment.
        from: usize,
        /// The square of the segment's length.
        square: String,
    },
    /// A segment of rational length after a first one in √`first_root`.
    SegmentRational {
        /// The segment's first point.
        from: usize,
        /// The segment's last point.
        to: usize,
        /// The root of the first segment's length.
        first_root: u64,
    },
    /// A segment of length in √`root` after a first one of rational length.
    SegmentAfterRational {
        /// The segment's first point.
        from: usize,
        /// The segment's last point.
        to: usize,
        /// The root of the segment's length.
        root: u64,
    },
    /// A segment of length in √`root` after a first one in another root.
    SegmentOtherRoot {
        /// The segment's first point.
        from: usize,
        /// The segment's last point.
        to: usize,
        /// The root of the segment's length.
        root: u64,
        /// The root of the first segment's length.
        first_root: u64,
    },
}

impl Message for ParameterError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            ParameterError::ChordNeedsRational { .. } => said(
                lang,
                "chord-length and centripetal parameters need rational data (the lengths of other numbers are roots of roots)",
                "los parámetros por longitud de cuerda y centrípetos necesitan datos racionales (las longitudes de otros números son raíces de raíces)",
                [],
            ),
            ParameterError::TooFewPoints => said(
                lang,
                "parameters need at least two points",
                "los parámetros necesitan al menos dos puntos",
                [],
            ),
            ParameterError::PointsCoincide { first, second } => said(
                lang,
                "points ‹› and ‹› coincide: a segment of length 0 gives two equal parameters",
                "los puntos ‹› y ‹› coinciden: un segmento de longitud 0 da dos parámetros iguales",
                [first.into(), second.into()],
            ),
            ParameterError::CentripetalFourthRoot { to, from, square } => said(
                lang,
                "the centripetal step |a_‹› - a_‹›|^(1/2) is the fourth root of ‹›, in no quadratic field: centripetal parameters are exact only when every chord length is rational",
                "el paso centrípeto |a_‹› - a_‹›|^(1/2) es la raíz cuarta de ‹›, que no está en ningún cuerpo cuadrático: los parámetros centrípetos solo son exactos cuando todas las longitudes de cuerda son racionales",
                [to.into(), from.into(), square.into()],
            ),
            ParameterError::SegmentRational {
                from,
                to,
                first_root,
            } => said(
                lang,
                "the length of segment ‹› to ‹› is rational and the first's is in √‹›: their ratio, and so the parameters, are in no quadratic field (the parameters are exact when the lengths are rational multiples of one square root)",
                "la longitud del segmento ‹› a ‹› es racional y la del primero está en √‹›: su cociente, y con él los parámetros, no está en ningún cuerpo cuadrático (los parámetros son exactos cuando las longitudes son múltiplos racionales de una misma raíz cuadrada)",
                [from.into(), to.into(), first_root.into()],
            ),
            ParameterError::SegmentAfterRational { from, to, root } => said(
                lang,
                "the length of segment ‹› to ‹› is in √‹› and the first's is rational: their ratio, and so the parameters, are in no quadratic field (the parameters are exact when the lengths are rational multiples of one square root)",
                "la longitud del segmento ‹› a ‹› está en √‹› y la del primero es racional: su cociente, y con él los parámetros, no está en ningún cuerpo cuadrático (los parámetros son exactos cuando las longitudes son múltiplos racionales de una misma raíz cuadrada)",
                [from.into(), to.into(), root.into()],
            ),
            ParameterError::SegmentOtherRoot {
                from,
                to,
                root,
                first_root,
            } => said(
                lang,
                "the length of segment ‹› to ‹› is in √‹› and the first's is in √‹›: their ratio, and so the parameters, are in no quadratic field (the parameters are exact when the lengths are rational multiples of one square root)",
                "la longitud del segmento ‹› a ‹› está en √‹› y la del primero en √‹›: su cociente, y con él los parámetros, no está en ningún cuerpo cuadrático (los parámetros son exactos cuando las longitudes son múltiplos racionales de una misma raíz cuadrada)",
                [from.into(), to.into(), root.into(), first_root.into()],
            ),
        }
    }
}

cagd_words::display_english!(ParameterError);

/// A positive rational written as q² d with d a square-free integer (found by trial division
/// up to 10⁴; a larger cofactor is kept whole in d, which can only make two equal roots look
/// different: a refusal, never a wrong value): √x = q √d, as (q, d).
fn square_root(x: &BigRational) -> (BigRational, u64) {
    // x = n/m = n m / m², so √x = √(n m)/m
    let nm = x.numer() * x.denom();
    let mut rest = nm.clone();
    let mut q = BigInt::one();
    let mut d = BigInt::one();
    let mut p = BigInt::from(2u32);
    let limit = BigInt::from(10_000u32);
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

/// The data as rationals.
fn rationals<S: Scalar>(points: &[Point<S>]) -> Result<Vec<Vec<BigRational>>, ParameterError> {
    points
        .iter()
        .enumerate()
        .map(|(k, p)| {
            p.coords()
                .iter()
                .map(|x| x.as_rational().map(|q| q.into_owned()))
                .collect::<Option<Vec<_>>>()
                .ok_or(ParameterError::ChordNeedsRational { point: k })
        })
        .collect()
}

/// The parameters t_0 = 0 < ... < t_n = 1 of the data `points` by `how` (see
/// [the module](self)): `t_k = k/n`, or `t_k = t_{k-1} + ℓ_k / Σ ℓ` with the chord lengths
/// `ℓ_k = |a_k - a_{k-1}|` (centripetal: `ℓ_k = |a_k - a_{k-1}|^{1/2}`), Piegl and Tiller
/// eq. (9.3)-(9.6).
///
/// ```
/// use cagd_fit::{parameters, Parametrization};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let a: Vec<Point<BigRational>> = [(0, 0), (3, 4), (3, 5)]
///     .into_iter()
///     .map(|(x, y)| Point::new(vec![BigRational::from_integer(x.into()), BigRational::from_integer(y.into())]))
///     .collect();
/// // chord lengths 5 and 1
/// let t = parameters(Parametrization::ChordLength, &a).unwrap();
/// assert_eq!(t, [q!(0), q!(5/6), q!(1)]);
/// ```
pub fn parameters<S: Scalar>(
    how: Parametrization,
    points: &[Point<S>],
) -> Result<Vec<S>, ParameterError> {
    let n = points.len();
    if n < 2 {
        return Err(ParameterError::TooFewPoints);
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
            return Err(ParameterError::PointsCoincide {
                first: k,
                second: k + 1,
            });
        }
        let (q, d) = square_root(&sq);
        let (q, d) = match how {
            Parametrization::ChordLength => (q, d),
            _ => {
                // |Δ|^{1/2}: |Δ| = q √d must be rational (d = 1), then its root q' √d'
                if d != 1 {
                    return Err(ParameterError::CentripetalFourthRoot {
                        to: k + 1,
                        from: k,
                        square: sq.to_string(),
                    });
                }
                square_root(&q)
            }
        };
        match common {
            None => common = Some(d),
            Some(c) if c == d => {}
            Some(c) => {
                // a rational length is "in √1": said as rational
                let (from, to) = (k, k + 1);
                return Err(match (d, c) {
                    (1, first_root) => ParameterError::SegmentRational {
                        from,
                        to,
                        first_root,
                    },
                    (root, 1) => ParameterError::SegmentAfterRational { from, to, root },
                    (root, first_root) => ParameterError::SegmentOtherRoot {
                        from,
                        to,
                        root,
                        first_root,
                    },
                });
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
/// t_0 < ... < t_n (Piegl and Tiller eq. (9.8)), in the notes' convention: t_0 and t_n p times,
/// and inside `u_{j+p} = (t_j + ... + t_{j+p-1}) / p`, j = 1, ..., n - p.
///
/// ```
/// use cagd_fit::averaged_knots;
/// use cagd_scalar::{q, BigRational};
/// let t: [BigRational; 5] = [q!(0), q!(1/4), q!(1/2), q!(3/4), q!(1)];
/// assert_eq!(averaged_knots(&t, 2), [q!(0), q!(0), q!(3/8), q!(5/8), q!(1), q!(1)]);
/// ```
pub fn averaged_knots<S: Scalar>(params: &[S], p: usize) -> Vec<S> {
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

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, Quadratic};
    use strum::IntoEnumIterator;

    fn points(xy: &[(i64, i64)]) -> Vec<Point<BigRational>> {
        xy.iter()
            .map(|&(x, y)| {
                Point::new(vec![
                    BigRational::from_integer(x.into()),
                    BigRational::from_integer(y.into()),
                ])
            })
            .collect()
    }

    #[test]
    fn uniform_chord_and_centripetal() {
        let a = points(&[(0, 0), (0, 1), (0, 5)]);
        assert_eq!(
            parameters(Parametrization::Uniform, &a).unwrap(),
            [q!(0), q!(1 / 2), q!(1)]
        );
        // lengths 1 and 4
        assert_eq!(
            parameters(Parametrization::ChordLength, &a).unwrap(),
            [q!(0), q!(1 / 5), q!(1)]
        );
        // square roots 1 and 2
        assert_eq!(
            parameters(Parametrization::Centripetal, &a).unwrap(),
            [q!(0), q!(1 / 3), q!(1)]
        );
        // lengths √2 and 2√2: one root, rational ratio
        let b = points(&[(0, 0), (1, 1), (3, 3)]);
        assert_eq!(
            parameters(Parametrization::ChordLength, &b).unwrap(),
            [q!(0), q!(1 / 3), q!(1)]
        );
    }

    #[test]
    fn refusals() {
        let chord = Parametrization::ChordLength;
        assert_eq!(
            parameters(chord, &points(&[(0, 0)])),
            Err(ParameterError::TooFewPoints)
        );
        assert_eq!(
            parameters(chord, &points(&[(0, 0), (1, 1), (1, 1)])),
            Err(ParameterError::PointsCoincide {
                first: 1,
                second: 2
            })
        );
        // √2 then 1
        assert_eq!(
            parameters(chord, &points(&[(0, 0), (1, 1), (2, 1)])),
            Err(ParameterError::SegmentRational {
                from: 1,
                to: 2,
                first_root: 2
            })
        );
        assert_eq!(
            parameters(chord, &points(&[(0, 0), (1, 0), (2, 1)])),
            Err(ParameterError::SegmentAfterRational {
                from: 1,
                to: 2,
                root: 2
            })
        );
        assert_eq!(
            parameters(chord, &points(&[(0, 0), (1, 1), (2, 3)])),
            Err(ParameterError::SegmentOtherRoot {
                from: 1,
                to: 2,
                root: 5,
                first_root: 2
            })
        );
        assert_eq!(
            parameters(Parametrization::Centripetal, &points(&[(0, 0), (1, 1)])),
            Err(ParameterError::CentripetalFourthRoot {
                to: 1,
                from: 0,
                square: "2".into()
            })
        );
        let root: Vec<Point<Quadratic>> = vec![
            Point::new(vec![Quadratic::from_rational(q!(0))]),
            Point::new(vec![Quadratic::sqrt_of(&q!(2)).unwrap()]),
        ];
        assert_eq!(
            parameters(chord, &root),
            Err(ParameterError::ChordNeedsRational { point: 1 })
        );
    }

    #[test]
    fn averaged() {
        // p = 3 through t = 0, 1/6, 1/2, 5/6, 1 (n = 4): one inner knot (1/6 + 1/2 + 5/6)/3 = 1/2
        let t = [q!(0), q!(1 / 6), q!(1 / 2), q!(5 / 6), q!(1)];
        assert_eq!(
            averaged_knots(&t, 3),
            [q!(0), q!(0), q!(0), q!(1 / 2), q!(1), q!(1), q!(1)]
        );
    }

    #[test]
    fn every_variant_in_both_languages() {
        for m in ParameterError::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
