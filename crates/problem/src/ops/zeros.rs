//! Where a polynomial g(u, v) vanishes on a rectangle `[a, b] × [c, d]`, decided exactly.
//!
//! Written in the Bernstein basis of the rectangle, `g = Σ b_ij B_i^m(s) B_j^n(t)` with
//! `u = a + (b - a) s`, `v = c + (d - c) t`, s, t ∈ [0, 1]. Since the B_i^m B_j^n are
//! non-negative and sum to 1, g lies between the least and the greatest b_ij (the convex hull
//! property): when every b_ij is positive, g > 0 on the whole rectangle, and when every one is
//! negative, g < 0. The corner coefficients are the values of g at the corners
//! (`b_00 = g(a, c)`, ...), so they are exact values at exact points: a zero there is a zero of
//! g, and a positive value at one point and a negative one at another prove a zero on the
//! segment between them (the rectangle is convex and g continuous). When neither happens, the
//! rectangle is cut into four at its midpoint (De Casteljau at 1/2 in s and in t, exactly) and
//! each quarter tried again, at most [`LEVELS`] times; past that the answer is "not decided",
//! never a guess.

use crate::message::surface::Surface;
use crate::value::ExactScalar;
use cagd_poly::{to_bernstein_2d, Poly, Var};
use std::cmp::Ordering;

/// How many times a rectangle is cut into four before the answer is "not decided": at most
/// 4⁴ = 256 rectangles at the last level.
pub(crate) const LEVELS: usize = 4;

/// The zero set of g on a rectangle, as far as it was decided.
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum ZeroSet<S> {
    /// g ≡ 0.
    Everywhere,
    /// g has no zero on the rectangle and this strict sign: the Bernstein coefficients of g on
    /// each of `rectangles` sub-rectangles (after `levels` cuts) are all of this sign.
    Sign {
        sign: Ordering,
        rectangles: usize,
        levels: usize,
    },
    /// g(u, v) = 0 at this exact point.
    Zero(S, S),
    /// g > 0 at the first point and g < 0 at the second: a zero lies on the segment between.
    SignChange((S, S), (S, S)),
    /// (Of pieces.) Each piece keeps one strict sign, but not the same on every piece: g jumps
    /// across a line where the pieces meet.
    Mixed,
    /// Not decided within [`LEVELS`] cuts (or a sign needed the sign of an expression in
    /// letters, `letters`).
    Undecided { letters: bool },
}

impl<S: ExactScalar> ZeroSet<S> {
    /// The verdict in words, G being the numerator of the Gaussian curvature (K has its sign).
    pub(crate) fn verdict(&self) -> Surface {
        let point = |(u, v): (&S, &S)| format!("({}, {})", u.to_text(), v.to_text());
        match self {
            ZeroSet::Everywhere => Surface::GEverywhere,
            ZeroSet::Sign {
                sign,
                rectangles,
                levels,
            } => match (*sign == Ordering::Less, *levels == 0) {
                (true, true) => Surface::GNegative,
                (false, true) => Surface::GPositive,
                (true, false) => Surface::GNegativeCut {
                    rectangles: *rectangles,
                },
                (false, false) => Surface::GPositiveCut {
                    rectangles: *rectangles,
                },
            },
            ZeroSet::Mixed => Surface::GMixed,
            ZeroSet::Zero(u, v) => Surface::GZeroAt { at: point((u, v)) },
            ZeroSet::SignChange((a, b), (c, d)) => Surface::GSignChange {
                positive: point((a, b)),
                negative: point((c, d)),
            },
            ZeroSet::Undecided { letters: true } => Surface::GUndecidedLetters,
            ZeroSet::Undecided { letters: false } => Surface::GUndecided { halvings: LEVELS },
        }
    }
}

/// A rectangle of [0, 1]² (lower corner `s`, `t`, side `h`) and the Bernstein coefficients of
/// g on it.
struct Cell<S> {
    s: S,
    t: S,
    h: S,
    b: Vec<Vec<S>>,
}

/// De Casteljau at 1/2: the coefficients of the halves [0, 1/2] and [1/2, 1] of a row.
pub(crate) fn halves<S: ExactScalar>(row: &[S]) -> (Vec<S>, Vec<S>) {
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

/// The rows (along s) halved: the coefficients on s ∈ [0, 1/2] and on s ∈ [1/2, 1].
fn halves_in_s<S: ExactScalar>(b: &[Vec<S>]) -> (Vec<Vec<S>>, Vec<Vec<S>>) {
    let n = b.first().map_or(0, Vec::len);
    let (mut lo, mut hi) = (vec![Vec::new(); b.len()], vec![Vec::new(); b.len()]);
    for j in 0..n {
        let column: Vec<S> = b.iter().filter_map(|r| r.get(j).cloned()).collect();
        let (l, h) = halves(&column);
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
fn halves_in_t<S: ExactScalar>(b: &[Vec<S>]) -> (Vec<Vec<S>>, Vec<Vec<S>>) {
    b.iter().map(|r| halves(r)).unzip()
}

/// The zero set of `g` on `[a, b] × [c, d]` (a < b, c < d), as [the module](self) decides it.
pub(crate) fn zero_set<S: ExactScalar>(
    g: &Poly<S>,
    (a, b): &(S, S),
    (c, d): &(S, S),
) -> Result<ZeroSet<S>, cagd_poly::PolyError> {
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
    for depth in 0..=LEVELS {
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
            } else if depth < LEVELS {
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
pub(crate) type PieceZeros<S> = ((S, S), (S, S), ZeroSet<S>);

/// The zero set of a piecewise g from its pieces' (each piece's rectangle and zero set): a
/// piece where g ≡ 0 gives the zero at its lower corner, a zero or a change of sign of any
/// piece is one of the whole, and one strict sign on every piece is the sign of the whole.
pub(crate) fn combine<S: ExactScalar>(pieces: &[PieceZeros<S>]) -> ZeroSet<S> {
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
