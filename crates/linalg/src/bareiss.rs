//! Fraction-free (Bareiss) elimination on integer numerators: the fast exact path used when
//! every entry of a matrix is rational.
//!
//! Each row i is multiplied by a positive rational r_i (the least common multiple of its
//! denominators over the gcd of the scaled numerators), so that A' = diag(r) A has integer
//! entries. Bareiss' step
//!
//! ```text
//! a_ij ← (a_kk a_ij − a_ik a_kj) / a_{k-1,k-1}      (i, j > k)
//! ```
//!
//! divides exactly (every entry is a minor of A'), so the numbers stay integers whose size
//! grows only linearly, and no gcd is ever computed during the elimination. The last pivot is
//! det(P A'). The entries a_ik below the diagonal are kept (not zeroed): they replay the same
//! steps on any right-hand side, so the factorization is computed once and reused.

use crate::exact::{common_denominator, common_denominator_big, IntMatrix};
use crate::{solve::no_pivot, LinalgError};
use cagd_scalar::gcd::gcd;
use cagd_scalar::{BigInt, BigRational, ExactRational, Rat, Scalar};
use num_traits::{One, Zero};

/// The exact rational value of `x`, when `S` is exact and `x` has no root part.
pub(crate) fn as_rational<S: Scalar>(x: &S) -> Option<BigRational> {
    if !S::is_exact() {
        return None;
    }
    x.to_number()?.to_rational()
}

/// A Bareiss factorization of diag(r) P A on integers.
#[derive(Clone, Debug)]
pub(crate) struct IntegerLu {
    /// The eliminated matrix: on and above the diagonal, row k as it was when it became the
    /// pivot row; below the diagonal, the entry a_ik at step k (the multiplier of the replay).
    m: Vec<Vec<BigInt>>,
    /// `scale[i]` is r of the factored row i (already permuted).
    scale: Vec<BigRational>,
    /// Factored row i is row `perm[i]` of the original matrix.
    pub(crate) perm: Vec<usize>,
    /// An odd number of row swaps.
    pub(crate) odd: bool,
}

/// The positive rational r with r·row an integer row whose entries have gcd 1 (r = 1 for a
/// zero row), and that integer row.
fn integer_row(row: &[BigRational]) -> (BigRational, Vec<BigInt>) {
    // lcm(l, q) = l (q / gcd(l, q))
    let lcm = row.iter().fold(BigInt::one(), |acc, q| {
        let g = gcd(&acc, q.denom());
        if g == *q.denom() {
            acc
        } else {
            acc * (q.denom() / g)
        }
    });
    let ints: Vec<BigInt> = row.iter().map(|q| q.numer() * (&lcm / q.denom())).collect();
    let gcd = ints.iter().fold(BigInt::zero(), |acc, a| {
        if acc.is_one() {
            acc
        } else {
            gcd(&acc, a)
        }
    });
    if gcd.is_zero() || gcd.is_one() {
        return (BigRational::from_integer(lcm), ints);
    }
    let ints = ints.into_iter().map(|a| a / &gcd).collect();
    (BigRational::new(lcm, gcd), ints)
}

impl IntegerLu {
    /// Bareiss elimination with the first nonzero pivot of each column; an error naming the
    /// first column without a pivot when the matrix is singular (`rows` is square: the rows of a
    /// [`crate::Matrix`] checked square by the caller).
    pub(crate) fn new(rows: &[Vec<BigRational>]) -> Result<Self, LinalgError> {
        let n = rows.len();
        let (mut scale, mut m): (Vec<_>, Vec<_>) = rows.iter().map(|r| integer_row(r)).unzip();
        let mut perm: Vec<usize> = (0..n).collect();
        let mut odd = false;
        let mut prev = BigInt::one();
        // rows k.. of m, still to eliminate: `rest[0]` is row k
        let mut rest: &mut [Vec<BigInt>] = &mut m;
        for k in 0..n {
            let p = rest
                .iter()
                .position(|row| row.get(k).is_some_and(|a| !a.is_zero()))
                .ok_or_else(|| no_pivot(k))?;
            if p != 0 {
                rest.swap(0, p);
                scale.swap(k, k + p);
                perm.swap(k, k + p);
                odd = !odd;
            }
            let (pivot_row, bottom) = std::mem::take(&mut rest)
                .split_first_mut()
                .ok_or_else(|| no_pivot(k))?;
            // the pivot a_kk and the rest of its row, a_kj for j > k
            let (pivot, pivot_tail) = pivot_row
                .get(k..)
                .and_then(<[BigInt]>::split_first)
                .ok_or_else(|| no_pivot(k))?;
            for row in bottom.iter_mut() {
                cagd_scalar::cancel::checkpoint();
                // a_ik stays in place: the multiplier of the replay
                let Some((factor, tail)) = row.get_mut(k..).and_then(<[BigInt]>::split_first_mut)
                else {
                    continue;
                };
                for (a_ij, a_kj) in tail.iter_mut().zip(pivot_tail) {
                    let value = pivot * &*a_ij - &*factor * a_kj;
                    *a_ij = value / &prev;
                }
            }
            prev = pivot.clone();
            rest = bottom;
        }
        Ok(IntegerLu {
            m,
            scale,
            perm,
            odd,
        })
    }

    /// det A = ± det(P A') / Π r_i: the last Bareiss pivot, unscaled.
    pub(crate) fn determinant(&self) -> BigRational {
        let last = self
            .m
            .last()
            .and_then(|r| r.last())
            .cloned()
            .unwrap_or_else(BigInt::one);
        let r = self.scale.iter().fold(BigRational::one(), |acc, s| acc * s);
        let det = BigRational::from_integer(last) / r;
        if self.odd {
            -det
        } else {
            det
        }
    }

    /// Solves A x = b for a rational right-hand side, on integers: b is scaled as the rows
    /// were and brought to a common denominator D, the Bareiss steps are replayed, and the back
    /// substitution computes the integers y = det(P A') x (Cramer), so x = y / (det · D).
    /// `None` when b has fewer than n entries.
    pub(crate) fn solve_rational(&self, b: &[BigRational]) -> Option<Vec<BigRational>> {
        let n = self.m.len();
        if n == 0 {
            return Some(Vec::new());
        }
        // b_i r_i in machine words while they fit (the data and the scales are short), over
        // their least common denominator D
        let mut scaled: Vec<Rat> = Vec::with_capacity(n);
        for (&p, r) in self.perm.iter().zip(&self.scale) {
            scaled.push(Rat::from_rational(b.get(p)?) * Rat::from_rational(r));
        }
        let (mut c, den): (Vec<BigInt>, BigInt) = match common_denominator(&scaled) {
            Some((num, den)) => (num.into_iter().map(BigInt::from).collect(), den.into()),
            None => {
                let over = common_denominator_big(&scaled)?;
                (over.num, over.den)
            }
        };
        let mut prev = BigInt::one();
        // c_k.., still to eliminate: `rest[0]` is c_k
        let mut rest = c.as_mut_slice();
        for (k, (row_k, below_rows)) in self.rows_and_below().enumerate() {
            let (c_k, below) = std::mem::take(&mut rest).split_first_mut()?;
            let pivot = row_k.get(k)?;
            for (c_i, row_i) in below.iter_mut().zip(below_rows) {
                let value = pivot * &*c_i - row_i.get(k)? * &*c_k;
                *c_i = value / &prev;
            }
            prev = pivot.clone();
            rest = below;
        }
        // prev is now det(P A').
        let det = prev;
        // y_{n-1}, y_{n-2}, ...: back substitution from the last row up
        let mut y_rev: Vec<BigInt> = Vec::with_capacity(n);
        for (i, (row, c_i)) in self.m.iter().zip(&c).enumerate().rev() {
            let (diag, upper) = row.get(i..)?.split_first()?;
            let mut acc = &det * c_i;
            for (a_ij, y_j) in upper.iter().zip(y_rev.iter().rev()) {
                acc -= a_ij * y_j;
            }
            y_rev.push(acc / diag);
        }
        // x_i = y_i / (det · D), reduced by a machine-word gcd or Lehmer's (num-rational's
        // division reduces by Stein's gcd, bit by bit: most of the time of a solve)
        let total = det * den;
        Some(
            y_rev
                .into_iter()
                .rev()
                .map(|yi| crate::exact::ratio(yi, total.clone()))
                .collect(),
        )
    }

    /// Solves A x = b for a right-hand side with irrational entries (a + b√d): the same steps,
    /// replayed in `S`. `None` when b has fewer than n entries.
    pub(crate) fn solve_field<S: Scalar>(&self, b: &[S]) -> Option<Vec<S>> {
        let n = self.m.len();
        let int = |a: &BigInt| S::from_rational(&BigRational::from_integer(a.clone()));
        let mut c: Vec<S> = Vec::with_capacity(n);
        for (&p, r) in self.perm.iter().zip(&self.scale) {
            c.push(b.get(p)?.mul_ref(&S::from_rational(r)));
        }
        let mut prev = S::one();
        let mut rest = c.as_mut_slice();
        for (k, (row_k, below_rows)) in self.rows_and_below().enumerate() {
            let (c_k, below) = std::mem::take(&mut rest).split_first_mut()?;
            let pivot = int(row_k.get(k)?);
            for (c_i, row_i) in below.iter_mut().zip(below_rows) {
                let value = pivot.mul_ref(c_i) - int(row_i.get(k)?) * &*c_k;
                *c_i = value / &prev;
            }
            prev = pivot;
            rest = below;
        }
        // x_{n-1}, x_{n-2}, ...
        let mut x_rev: Vec<S> = Vec::with_capacity(n);
        for (i, (row, c_i)) in self.m.iter().zip(c).enumerate().rev() {
            let (diag, upper) = row.get(i..)?.split_first()?;
            let mut acc = c_i;
            for (a_ij, x_j) in upper.iter().zip(x_rev.iter().rev()) {
                acc -= int(a_ij) * x_j;
            }
            x_rev.push(acc / int(diag));
        }
        x_rev.reverse();
        Some(x_rev)
    }

    /// Each row k of the eliminated matrix with the rows below it.
    fn rows_and_below(&self) -> impl Iterator<Item = (&[BigInt], &[Vec<BigInt>])> {
        let mut rest = self.m.as_slice();
        std::iter::from_fn(move || {
            let (row, below) = rest.split_first()?;
            rest = below;
            Some((row.as_slice(), below))
        })
    }

    /// The largest number of bits of an entry of the eliminated matrix (for tests of growth).
    #[cfg(test)]
    pub(crate) fn max_bits(&self) -> u64 {
        self.m.iter().flatten().map(BigInt::bits).max().unwrap_or(0)
    }
}

/// [`crate::exact::solve_integer`] by Bareiss' fraction-free elimination on the augmented
/// matrix `[A | B]` (every division is exact, every entry a minor of it), then the back
/// substitution of [`IntegerLu`] on integers.
pub(crate) fn solve_bareiss(a: &IntMatrix, b: &IntMatrix) -> Option<(IntMatrix, BigInt)> {
    let n = a.rows();
    assert!(a.cols() == n && b.rows() == n, "solve_integer: shapes");
    let r = b.cols();
    let mut m: Vec<Vec<BigInt>> = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| a.get(i, j))
                .chain((0..r).map(|j| b.get(i, j)))
                .collect()
        })
        .collect();
    let mut prev = BigInt::one();
    // rows k.. of [A | B], still to eliminate: `rest[0]` is row k
    let mut rest: &mut [Vec<BigInt>] = &mut m;
    for k in 0..n {
        let p = rest
            .iter()
            .position(|row| row.get(k).is_some_and(|x| !x.is_zero()))?;
        rest.swap(0, p);
        let (pivot_row, bottom) = std::mem::take(&mut rest).split_first_mut()?;
        let (pivot, pivot_tail) = pivot_row.get(k..)?.split_first()?;
        for row in bottom.iter_mut() {
            let (factor, tail) = row.get_mut(k..)?.split_first_mut()?;
            let factor = std::mem::take(factor);
            for (a_ij, a_kj) in tail.iter_mut().zip(pivot_tail) {
                let mut value = pivot * &*a_ij;
                if !factor.is_zero() && !a_kj.is_zero() {
                    value -= &factor * a_kj;
                }
                *a_ij = if prev.is_one() { value } else { value / &prev };
            }
        }
        prev = pivot.clone();
        rest = bottom;
    }
    let det = prev;
    // the rows y_i of Y (r entries each), from the last row up, all right-hand sides at once:
    // y_i = (det · b_i − Σ_{j>i} a_ij y_j) / a_ii
    let mut y = vec![BigInt::zero(); n * r];
    for (i, row) in m.iter().enumerate().rev() {
        let (diag, upper) = row.get(i..n)?.split_first()?;
        // rows ..=i of Y, and the rows i + 1.. already solved
        let (head, solved) = y.split_at_mut_checked((i + 1) * r)?;
        let y_i = head.get_mut(i * r..)?;
        for (y_ic, b_ic) in y_i.iter_mut().zip(row.get(n..)?) {
            *y_ic = &det * b_ic;
        }
        for (a_ij, y_j) in upper.iter().zip(solved.chunks_exact(r.max(1))) {
            if a_ij.is_zero() {
                continue;
            }
            for (y_ic, y_jc) in y_i.iter_mut().zip(y_j) {
                if !y_jc.is_zero() {
                    *y_ic -= a_ij * y_jc;
                }
            }
        }
        for y_ic in y_i.iter_mut() {
            *y_ic /= diag;
        }
    }
    Some((IntMatrix::from_big(n, r, y), det))
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, FieldOps};

    #[test]
    fn rows_become_primitive_integer_rows() {
        let (r, ints) = integer_row(&[q!(1 / 4), q!(1 / 2), q!(1 / 4)]);
        assert_eq!(r, q!(4));
        assert_eq!(
            ints,
            vec![BigInt::from(1), BigInt::from(2), BigInt::from(1)]
        );
        let (r, ints) = integer_row(&[q!(2 / 3), q!(4 / 9)]);
        assert_eq!(r, q!(9 / 2));
        assert_eq!(ints, vec![BigInt::from(3), BigInt::from(2)]);
        let (r, _) = integer_row(&[q!(0), q!(0)]);
        assert_eq!(r, q!(1));
    }

    #[test]
    fn integer_systems_with_several_right_hand_sides() {
        // [[2, 1], [1, 3]] X = [[1, 0], [2, 5]]: X = [[1, -5], [3, 10]] / 5
        let a = IntMatrix::from_i128(2, 2, vec![2, 1, 1, 3]);
        let b = IntMatrix::from_i128(2, 2, vec![1, 0, 2, 5]);
        let (y, det) = solve_bareiss(&a, &b).unwrap();
        assert_eq!(det, BigInt::from(5));
        assert_eq!(y, IntMatrix::from_i128(2, 2, vec![1, -5, 3, 10]));
        // a zero leading entry needs a row swap; the determinant keeps its sign up to it
        let a = IntMatrix::from_i128(2, 2, vec![0, 1, 1, 0]);
        let (y, det) = solve_bareiss(&a, &IntMatrix::from_i128(2, 1, vec![3, 4])).unwrap();
        assert_eq!(
            (y.get(0, 0) / &det, y.get(1, 0) / &det),
            (BigInt::from(4), BigInt::from(3))
        );
        let singular = IntMatrix::from_i128(2, 2, vec![1, 2, 2, 4]);
        assert!(solve_bareiss(&singular, &IntMatrix::from_i128(2, 1, vec![1, 1])).is_none());
    }

    #[test]
    fn hilbert_determinant_and_growth() {
        // det of the 4×4 Hilbert matrix 1/(i + j + 1) is 1/6048000.
        let h: Vec<Vec<BigRational>> = (0..4)
            .map(|i| {
                (0..4)
                    .map(|j| BigRational::from_ratio(1, i + j + 1))
                    .collect()
            })
            .collect();
        let lu = IntegerLu::new(&h).unwrap();
        assert_eq!(lu.determinant(), q!(1 / 6048000));
        assert!(lu.max_bits() < 40, "Bareiss entries stay small");
        let x = lu.solve_rational(&[q!(1), q!(0), q!(0), q!(0)]).unwrap();
        // First column of the inverse Hilbert matrix: 16, -120, 240, -140.
        assert_eq!(x, vec![q!(16), q!(-120), q!(240), q!(-140)]);
    }
}
