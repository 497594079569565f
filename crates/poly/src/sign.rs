//! The sign of a polynomial on an interval or a rectangle, and where it vanishes, decided
//! exactly from its Bernstein coefficients.
//!
//! Written in the Bernstein basis of the rectangle `[a, b] × [c, d]`,
//! `g = Σ b_ij B_i^m(s) B_j^n(t)` with `u = a + (b - a) s`, `v = c + (d - c) t`, s, t ∈ [0, 1].
//! Since the B_i^m B_j^n are non-negative and sum to 1, g lies between the least and the
//! greatest b_ij (the convex hull property): when every b_ij is positive, g > 0 on the whole
//! rectangle, and when every one is negative, g < 0. The corner coefficients are the values of
//! g at the corners (`b_00 = g(a, c)`, ...), so they are exact values at exact points: a zero
//! there is a zero of g, and a positive value at one point and a negative one at another prove
//! a zero on the segment between them (the rectangle is convex and g continuous). When neither
//! happens, the rectangle is cut into four at its midpoint (De Casteljau at 1/2 in s and in t,
//! exactly) and each quarter tried again, at most [`ZERO_SET_LEVELS`] times; past that the
//! answer is "not decided", never a guess. [`sign_on`] does the same in one variable on an
//! interval.

use crate::{to_bernstein_1d, to_bernstein_2d, Poly, PolyError, Var};
use cagd_scalar::Scalar;
use std::cmp::Ordering;

/// How many times [`zero_set`] cuts a rectangle into four before the answer is "not decided":
/// at most 4⁴ = 256 rectangles at the last level.
pub const ZERO_SET_LEVELS: usize = 4;

/// How many times [`sign_on`] halves an interval where the Bernstein coefficients of σ have
/// both signs: at depth k the pieces are 2^-k of [a, b] long. A sign still undecided there
/// (σ with a root in [a, b], or one so close that the pieces cannot separate it) is `None`.
pub const SIGN_HALVINGS: u32 = 8;

/// The zero set of g on a rectangle, as far as [`zero_set`] decided it.
#[derive(Debug, Clone, PartialEq)]
pub enum ZeroSet<S> {
    /// g ≡ 0.
    Everywhere,
    /// g has no zero on the rectangle and this strict sign: the Bernstein coefficients of g on
    /// each of `rectangles` sub-rectangles (after `levels` cuts) are all of this sign.
    Sign {
        /// The strict sign of g (`Greater`: g > 0).
        sign: Ordering,
        /// How many sub-rectangles were decided.
        rectangles: usize,
        /// How many cuts the deepest of them took.
        levels: usize,
    },
    /// g(u, v) = 0 at this exact point.
    Zero(S, S),
    /// g > 0 at the first point and g < 0 at the second: a zero lies on the segment between.
    SignChange((S, S), (S, S)),
    /// (Of pieces.) Each piece keeps one strict sign, but not the same on every piece: g jumps
    /// across a line where the pieces meet.
    Mixed,
    /// Not decided within [`ZERO_SET_LEVELS`] cuts (or a sign needed the sign of an
    /// expression in letters, `letters`).
    Undecided {
        /// Whether a sign could not be decided because it is in letters.
        letters: bool,
    },
}

/// De Casteljau at 1/2 on Bernstein coefficients: the coefficients of the halves [0, 1/2] and
/// [1/2, 1] of a polynomial whose coefficients on [0, 1] are `row`,
/// `b_i^{k} = (b_i^{k-1} + b_{i+1}^{k-1}) / 2`, the left half the first of each level, the
/// right half the last (notes, chapter 2, the subdivision of De Casteljau's algorithm).
///
/// ```
/// use cagd_poly::bernstein_halves;
/// use cagd_scalar::q;
/// let (left, right) = bernstein_halves(&[q!(0), q!(0), q!(1)]);
/// assert_eq!(left, [q!(0), q!(0), q!(1/4)]);
/// assert_eq!(right, [q!(1/4), q!(1/2), q!(1)]);
/// ```
pub fn bernstein_halves<S: Scalar>(row: &[S]) -> (Vec<S>, Vec<S>) {
    let half = S::from_ratio(1, 2);
    let mut level = row.to_vec();
    let mut left = Vec::with_capacity(row.len());
    let mut right = Vec::with_capacity(row.len());
    while let Some(first) = level.first() {
        cagd_scalar::cancel::checkpoint();
        left.push(first.clone());
        if let Some(last) = level.last() {
            right.push(last.clone());
        }
        level = level
            .windows(2)
            .filter_map(|w| match w {
                [x, y] => Some((x.clone() + y.clone()) * half.clone()),
                _ => None,
            })
            .collect();
    }
    right.reverse();
    (left, right)
}

/// A rectangle of [0, 1]² (lower corner `s`, `t`, side `h`) and the Bernstein coefficients of
/// g on it.
struct Cell<S> {
    s: S,
    t: S,
    h: S,
    b: Vec<Vec<S>>,
}

/// The rows (along s) halved: the coefficients on s ∈ [0, 1/2] and on s ∈ [1/2, 1].
fn halves_in_s<S: Scalar>(b: &[Vec<S>]) -> (Vec<Vec<S>>, Vec<Vec<S>>) {
    let n = b.first().map_or(0, Vec::len);
    let (mut lo, mut hi) = (vec![Vec::new(); b.len()], vec![Vec::new(); b.len()]);
    for j in 0..n {
        let column: Vec<S> = b.iter().filter_map(|r| r.get(j).cloned()).collect();
        let (l, h) = bernstein_halves(&column);
        for (row, x) in lo.iter_mut().zip(l) {
            row.push(x);
        }
        for (row, x) in hi.iter_mut().zip(h) {
            row.push(x);
        }
    }
    (lo, hi)
}

/// The columns (along t) halved.
fn halves_in_t<S: Scalar>(b: &[Vec<S>]) -> (Vec<Vec<S>>, Vec<Vec<S>>) {
    b.iter().map(|r| bernstein_halves(r)).unzip()
}

/// The zero set of `g(u, v)` on `[a, b] × [c, d]` (a < b, c < d), as [the module](self)
/// decides it: the corners of each rectangle first (an exact zero, or a change of sign between
/// two exact points), then one strict sign of all its Bernstein coefficients, else the
/// rectangle cut into four, at most [`ZERO_SET_LEVELS`] times.
///
/// Fails only as the change to the Bernstein basis does (g in another variable than u and v).
///
/// ```
/// use cagd_poly::{parse_poly, zero_set, ZeroSet};
/// use cagd_scalar::{q, BigRational};
/// use std::cmp::Ordering;
/// let unit = (q!(0), q!(1));
/// let g = parse_poly::<BigRational>("u + v + 1").unwrap();
/// let z = zero_set(&g, &unit, &unit).unwrap();
/// assert_eq!(z, ZeroSet::Sign { sign: Ordering::Greater, rectangles: 1, levels: 0 });
/// ```
pub fn zero_set<S: Scalar>(
    g: &Poly<S>,
    (a, b): &(S, S),
    (c, d): &(S, S),
) -> Result<ZeroSet<S>, PolyError> {
    if g.is_zero() {
        return Ok(ZeroSet::Everywhere);
    }
    let (du, dv) = (b.clone() - a.clone(), d.clone() - c.clone());
    let on_unit = g
        .affine_substitute(Var::U, &du, a)
        .affine_substitute(Var::V, &dv, c);
    let m = usize::try_from(on_unit.degree_in(Var::U)).unwrap_or(usize::MAX);
    let n = usize::try_from(on_unit.degree_in(Var::V)).unwrap_or(usize::MAX);
    let root = to_bernstein_2d(&on_unit, Var::U, Var::V, m, n)?;
    let point = |s: &S, t: &S| {
        (
            a.clone() + du.clone() * s.clone(),
            c.clone() + dv.clone() * t.clone(),
        )
    };
    let mut level = vec![Cell {
        s: S::zero(),
        t: S::zero(),
        h: S::one(),
        b: root,
    }];
    let mut positive: Option<(S, S)> = None;
    let mut negative: Option<(S, S)> = None;
    let mut letters = false;
    let mut sign = None;
    let mut decided = 0;
    for depth in 0..=ZERO_SET_LEVELS {
        let mut next = Vec::new();
        for cell in level {
            // the corners: exact values of g at exact points
            let last_i = cell.b.len().saturating_sub(1);
            let last_j = cell.b.first().map_or(0, |r| r.len().saturating_sub(1));
            for (i, j) in [(0, 0), (last_i, 0), (0, last_j), (last_i, last_j)] {
                let Some(x) = cell.b.get(i).and_then(|r| r.get(j)) else {
                    continue;
                };
                let s = if i == 0 {
                    cell.s.clone()
                } else {
                    cell.s.clone() + cell.h.clone()
                };
                let t = if j == 0 {
                    cell.t.clone()
                } else {
                    cell.t.clone() + cell.h.clone()
                };
                match x.compare(&S::zero()) {
                    Some(Ordering::Equal) => {
                        let (u, v) = point(&s, &t);
                        return Ok(ZeroSet::Zero(u, v));
                    }
                    Some(Ordering::Greater) => {
                        positive.get_or_insert_with(|| point(&s, &t));
                    }
                    Some(Ordering::Less) => {
                        negative.get_or_insert_with(|| point(&s, &t));
                    }
                    None => letters = true,
                }
                if let (Some(p), Some(q)) = (&positive, &negative) {
                    return Ok(ZeroSet::SignChange(p.clone(), q.clone()));
                }
            }
            let signs: Option<Vec<Ordering>> = cell
                .b
                .iter()
                .flatten()
                .map(|x| x.compare(&S::zero()))
                .collect();
            let Some(signs) = signs else {
                letters = true;
                continue;
            };
            let one = |o: Ordering| signs.iter().all(|x| *x == o);
            if one(Ordering::Greater) || one(Ordering::Less) {
                sign = signs.first().copied();
                decided += 1;
            } else if depth < ZERO_SET_LEVELS {
                let h = cell.h.clone() * S::from_ratio(1, 2);
                let (lo, hi) = halves_in_s(&cell.b);
                for (ds, half) in [(S::zero(), lo), (h.clone(), hi)] {
                    let (bottom, top) = halves_in_t(&half);
                    for (dt, b) in [(S::zero(), bottom), (h.clone(), top)] {
                        next.push(Cell {
                            s: cell.s.clone() + ds.clone(),
                            t: cell.t.clone() + dt,
                            h: h.clone(),
                            b,
                        });
                    }
                }
            } else {
                return Ok(ZeroSet::Undecided { letters });
            }
        }
        if letters {
            return Ok(ZeroSet::Undecided { letters });
        }
        if next.is_empty() {
            // every rectangle of this level (and the ones decided before) has one strict sign,
            // the same everywhere since no corner of any disagreed
            return Ok(match sign {
                Some(sign) => ZeroSet::Sign {
                    sign,
                    rectangles: decided,
                    levels: depth,
                },
                None => ZeroSet::Undecided { letters },
            });
        }
        level = next;
    }
    Ok(ZeroSet::Undecided { letters })
}

/// A piece's rectangle [a, b] × [c, d] and the zero set of g on it.
pub type PieceZeros<S> = ((S, S), (S, S), ZeroSet<S>);

/// The zero set of a piecewise g from its pieces' (each piece's rectangle and zero set): a
/// piece where g ≡ 0 gives the zero at its lower corner, a zero or a change of sign of any
/// piece is one of the whole, and one strict sign on every piece is the sign of the whole.
pub fn combine_zero_sets<S: Scalar>(pieces: &[PieceZeros<S>]) -> ZeroSet<S> {
    if pieces.iter().all(|(_, _, z)| *z == ZeroSet::Everywhere) {
        return ZeroSet::Everywhere;
    }
    let mut signs = Vec::new();
    let (mut rectangles, mut levels) = (0, 0);
    let mut undecided = None;
    for ((a, _), (c, _), z) in pieces {
        match z {
            ZeroSet::Everywhere => return ZeroSet::Zero(a.clone(), c.clone()),
            ZeroSet::Zero(..) | ZeroSet::SignChange(..) => return z.clone(),
            ZeroSet::Sign {
                sign,
                rectangles: r,
                levels: l,
            } => {
                signs.push(*sign);
                rectangles += r;
                levels = levels.max(*l);
            }
            ZeroSet::Mixed => signs.extend([Ordering::Less, Ordering::Greater]),
            ZeroSet::Undecided { letters } => {
                undecided = Some(*letters || undecided.unwrap_or(false));
            }
        }
    }
    if let Some(letters) = undecided {
        return ZeroSet::Undecided { letters };
    }
    match signs.first() {
        Some(sign) if signs.iter().all(|s| s == sign) => ZeroSet::Sign {
            sign: *sign,
            rectangles,
            levels,
        },
        Some(_) => ZeroSet::Mixed,
        None => ZeroSet::Undecided { letters: false },
    }
}

/// The sign σ(var) keeps on [a, b]: `Greater` when σ ≥ 0 there, `Less` when σ ≤ 0, decided by
/// the Bernstein coefficients of σ on [a, b] (the convex hull property), halving the pieces
/// whose coefficients have both signs by De Casteljau at 1/2 ([`bernstein_halves`]), at most
/// [`SIGN_HALVINGS`] deep. `None` when σ changes sign (a piece ≥ 0 beside a piece ≤ 0), a
/// piece is still undecided, or a sign is in letters.
///
/// ```
/// use cagd_poly::{parse_poly, sign_on, Var};
/// use cagd_scalar::{q, BigRational};
/// use std::cmp::Ordering;
/// let sigma = parse_poly::<BigRational>("1 - t").unwrap();
/// assert_eq!(sign_on(&sigma, Var::T, &q!(0), &q!(1)), Some(Ordering::Greater));
/// assert_eq!(sign_on(&sigma, Var::T, &q!(0), &q!(2)), None);
/// ```
pub fn sign_on<S: Scalar>(sigma: &Poly<S>, var: Var, a: &S, b: &S) -> Option<Ordering> {
    let on_unit = sigma.affine_substitute(var, &(b.clone() - a.clone()), a);
    let n = usize::try_from(on_unit.degree_in(var)).ok()?;
    let mut pieces = vec![(to_bernstein_1d(&on_unit, var, n).ok()?, 0)];
    let (mut positive, mut negative) = (false, false);
    while let Some((coefs, depth)) = pieces.pop() {
        let signs: Vec<Ordering> = coefs
            .iter()
            .map(|x| x.compare(&S::zero()))
            .collect::<Option<_>>()?;
        let up = signs.contains(&Ordering::Greater);
        let down = signs.contains(&Ordering::Less);
        if up && down {
            if depth == SIGN_HALVINGS {
                return None;
            }
            let (left, right) = bernstein_halves(&coefs);
            pieces.push((right, depth + 1));
            pieces.push((left, depth + 1));
            continue;
        }
        positive |= up;
        negative |= down;
        if positive && negative {
            return None;
        }
    }
    Some(if negative {
        Ordering::Less
    } else {
        Ordering::Greater
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::parse_poly;
    use cagd_scalar::{q, BigRational};

    fn poly(s: &str) -> Poly<BigRational> {
        parse_poly(s).unwrap()
    }

    fn unit() -> (BigRational, BigRational) {
        (q!(0), q!(1))
    }

    #[test]
    fn halves_of_a_square() {
        // t² on [0, 1]: coefficients 0, 0, 1; on [0, 1/2] it is (s/2)², on [1/2, 1] ((1+s)/2)²
        let (left, right) = bernstein_halves(&[q!(0), q!(0), q!(1)]);
        assert_eq!(left, [q!(0), q!(0), q!(1 / 4)]);
        assert_eq!(right, [q!(1 / 4), q!(1 / 2), q!(1)]);
    }

    #[test]
    fn zero_set_of_each_kind() {
        let z = |g: &str| zero_set(&poly(g), &unit(), &unit()).unwrap();
        assert_eq!(z("0"), ZeroSet::Everywhere);
        // u v vanishes at the corner (0, 0)
        assert_eq!(z("u v"), ZeroSet::Zero(q!(0), q!(0)));
        // u - 1/2: g(0, 0) = -1/2, g(1, 0) = 1/2
        assert_eq!(
            z("u - 1/2"),
            ZeroSet::SignChange((q!(1), q!(0)), (q!(0), q!(0)))
        );
        assert_eq!(
            z("-u - v - 1"),
            ZeroSet::Sign {
                sign: Ordering::Less,
                rectangles: 1,
                levels: 0
            }
        );
        // (u - 1/2)² + 1/100: Bernstein 26/100, -24/100, 26/100; one cut makes all positive
        assert_eq!(
            z("u^2 - u + 26/100"),
            ZeroSet::Sign {
                sign: Ordering::Greater,
                rectangles: 4,
                levels: 1
            }
        );
        // (u - 1/3)² + 1/10^6: on the cell [5/16, 6/16] of the fourth cut the middle
        // coefficient is (5/16 - 1/3)(6/16 - 1/3) + 1/10^6 = -1/1152 + 1/10^6 < 0: not decided
        assert_eq!(
            z("u^2 - 2/3 u + 1/9 + 1/1000000"),
            ZeroSet::Undecided { letters: false }
        );
    }

    #[test]
    fn zero_set_on_a_rectangle() {
        // u - 3 on [2, 4] x [0, 1]: g(2, 0) = -1, g(4, 0) = 1
        let z = zero_set(&poly("u - 3"), &(q!(2), q!(4)), &unit()).unwrap();
        assert_eq!(z, ZeroSet::SignChange((q!(4), q!(0)), (q!(2), q!(0))));
    }

    #[test]
    fn pieces_combined() {
        let positive = ZeroSet::Sign {
            sign: Ordering::Greater,
            rectangles: 1,
            levels: 0,
        };
        let negative = ZeroSet::Sign {
            sign: Ordering::Less,
            rectangles: 4,
            levels: 1,
        };
        let piece = |a: i64, z: ZeroSet<BigRational>| {
            ((BigRational::from_integer(a.into()), q!(1)), unit(), z)
        };
        assert_eq!(
            combine_zero_sets(&[piece(0, positive.clone()), piece(1, positive.clone())]),
            ZeroSet::Sign {
                sign: Ordering::Greater,
                rectangles: 2,
                levels: 0
            }
        );
        assert_eq!(
            combine_zero_sets(&[piece(0, positive.clone()), piece(1, negative)]),
            ZeroSet::Mixed
        );
        assert_eq!(
            combine_zero_sets(&[piece(0, positive), piece(1, ZeroSet::Everywhere)]),
            ZeroSet::Zero(q!(1), q!(0))
        );
        assert_eq!(
            combine_zero_sets(&[piece(0, ZeroSet::Everywhere)]),
            ZeroSet::Everywhere
        );
    }

    #[test]
    fn sign_of_a_speed() {
        let t = |s: &str| poly(s);
        assert_eq!(
            sign_on(&t("t"), Var::T, &q!(0), &q!(1)),
            Some(Ordering::Greater)
        );
        assert_eq!(
            sign_on(&t("-t - 1"), Var::T, &q!(0), &q!(1)),
            Some(Ordering::Less)
        );
        assert_eq!(sign_on(&t("t - 1/2"), Var::T, &q!(0), &q!(1)), None);
        // (t - 1/2)² ≥ 0 everywhere, its coefficients 1/4, -1/4, 1/4 halved once: ≥ 0
        assert_eq!(
            sign_on(&t("t^2 - t + 1/4"), Var::T, &q!(0), &q!(1)),
            Some(Ordering::Greater)
        );
    }
}
