//! Exact rational linear algebra on integer numerators: the fast paths of the algorithm crates.
//!
//! A rational matrix is written as integers over denominators, `R = N / L`, and a product of
//! rational matrices as a product of integer matrices followed by **one** division (and one gcd)
//! per entry of the result, instead of a gcd at every multiply-add as `BigRational` does.
//! Integer matrices use machine integers (`i128`) whenever a bound on the bits of the result
//! shows that nothing can overflow, and big integers otherwise: both are exact, so the result is
//! the same rational either way.
//!
//! The algorithm crates call these kernels only when every number is rational
//! ([`cagd_scalar::ExactRational::as_rational`]); a + b√d and `f64` take the generic path.

use crate::Point;
use cagd_scalar::gcd::{gcd, gcd_lehmer, gcd_u128, gcd_u64};
use cagd_scalar::{BigInt, BigRational, Scalar};
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// The largest number of bits an `i128` kernel may produce (one bit of headroom).
const SMALL_BITS: u64 = 126;

/// The entries of an [`IntMatrix`].
#[derive(Clone, Debug, PartialEq)]
enum Data {
    Small(Vec<i128>),
    Big(Vec<BigInt>),
}

/// A dense integer matrix, row by row: machine integers while every entry fits, big integers
/// otherwise.
#[derive(Clone, Debug, PartialEq)]
pub struct IntMatrix {
    rows: usize,
    cols: usize,
    data: Data,
}

fn bits_i128(x: i128) -> u64 {
    u64::from(128 - x.unsigned_abs().leading_zeros())
}

/// ⌈log2 k⌉ for k ≥ 1 (the bits a sum of k terms adds).
fn log2_ceil(k: usize) -> u64 {
    u64::from(usize::BITS - k.saturating_sub(1).leading_zeros())
}

impl IntMatrix {
    /// The matrix of these machine integers (`data.len() == rows * cols`).
    pub fn from_i128(rows: usize, cols: usize, data: Vec<i128>) -> Self {
        debug_assert_eq!(data.len(), rows * cols);
        IntMatrix {
            rows,
            cols,
            data: Data::Small(data),
        }
    }

    /// The matrix of these big integers, kept as machine integers when they all fit.
    pub fn from_big(rows: usize, cols: usize, data: Vec<BigInt>) -> Self {
        debug_assert_eq!(data.len(), rows * cols);
        let small: Option<Vec<i128>> = data.iter().map(ToPrimitive::to_i128).collect();
        let data = match small {
            Some(s) if s.iter().all(|&x| x != i128::MIN) => Data::Small(s),
            _ => Data::Big(data),
        };
        IntMatrix { rows, cols, data }
    }

    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Number of columns.
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// The position of entry (i, j) in the data, when (i, j) is inside the matrix.
    fn position(&self, i: usize, j: usize) -> Option<usize> {
        (i < self.rows && j < self.cols).then(|| i * self.cols + j)
    }

    /// Entry (i, j) as a big integer, when (i, j) is inside the matrix.
    fn entry(&self, i: usize, j: usize) -> Option<BigInt> {
        let k = self.position(i, j)?;
        match &self.data {
            Data::Small(d) => d.get(k).map(|&x| BigInt::from(x)),
            Data::Big(d) => d.get(k).cloned(),
        }
    }

    /// Entry (i, j) as a big integer.
    ///
    /// # Panics
    /// If (i, j) is outside the matrix.
    pub fn get(&self, i: usize, j: usize) -> BigInt {
        assert!(
            i < self.rows && j < self.cols,
            "IntMatrix index out of range"
        );
        // inside the matrix, so present (the constructors take rows · cols entries)
        let k = i * self.cols + j;
        match &self.data {
            Data::Small(d) => d.get(k).map_or_else(BigInt::zero, |&x| BigInt::from(x)),
            Data::Big(d) => d.get(k).cloned().unwrap_or_default(),
        }
    }

    /// Entry (i, j) as a machine integer, when the matrix holds machine integers (`None` also
    /// when (i, j) is outside the matrix).
    pub fn get_small(&self, i: usize, j: usize) -> Option<i128> {
        let k = self.position(i, j)?;
        match &self.data {
            Data::Small(d) => d.get(k).copied(),
            Data::Big(_) => None,
        }
    }

    /// The largest number of bits of an entry.
    pub fn max_bits(&self) -> u64 {
        match &self.data {
            Data::Small(d) => d.iter().map(|&x| bits_i128(x)).max().unwrap_or(0),
            Data::Big(d) => d.iter().map(BigInt::bits).max().unwrap_or(0),
        }
    }

    fn big(&self) -> Vec<BigInt> {
        match &self.data {
            Data::Small(d) => d.iter().map(|&x| BigInt::from(x)).collect(),
            Data::Big(d) => d.clone(),
        }
    }

    /// The transpose.
    pub fn transpose(&self) -> Self {
        let (r, c) = (self.rows, self.cols);
        // the columns of the r × c data, one after another: the rows of the transpose
        fn columns<T: Clone>(d: &[T], c: usize) -> Vec<T> {
            let mut out = Vec::with_capacity(d.len());
            if c == 0 {
                return out;
            }
            for j in 0..c {
                out.extend(d.chunks_exact(c).filter_map(|row| row.get(j)).cloned());
            }
            out
        }
        let data = match &self.data {
            Data::Small(d) => Data::Small(columns(d, c)),
            Data::Big(d) => Data::Big(columns(d, c)),
        };
        IntMatrix {
            rows: c,
            cols: r,
            data,
        }
    }

    /// The product `self · rhsᵀ` (entry (i, j) is the dot product of row i of `self` with row
    /// j of `rhs`): in machine integers when the bits of the operands bound the result below
    /// 2^126, in big integers otherwise.
    ///
    /// # Panics
    /// If the rows have different lengths (`self.cols() != rhs.cols()`).
    pub fn mul_transpose(&self, rhs: &Self) -> Self {
        assert_eq!(
            self.cols, rhs.cols,
            "mul_transpose: rows of different lengths"
        );
        let (r, c, k) = (self.rows, rhs.rows, self.cols);
        if let (Data::Small(a), Data::Small(b)) = (&self.data, &rhs.data) {
            let (bits_a, bits_b) = (self.max_bits(), rhs.max_bits());
            if bits_a + bits_b + log2_ceil(k.max(1)) <= SMALL_BITS && bits_a < 64 && bits_b < 64 {
                // 64 x 64 → 128-bit products (one widening multiplication each: both
                // factors fit a word, which the casts tell the compiler)
                let mut out = Vec::with_capacity(r * c);
                for row in a.chunks_exact(k.max(1)).take(r) {
                    for other in b.chunks_exact(k.max(1)).take(c) {
                        out.push(
                            row.iter()
                                .zip(other)
                                .map(|(&x, &y)| i128::from(x as i64) * i128::from(y as i64))
                                .sum(),
                        );
                    }
                }
                if k == 0 {
                    out = vec![0; r * c];
                }
                return IntMatrix::from_i128(r, c, out);
            }
            if bits_a + bits_b + log2_ceil(k.max(1)) <= SMALL_BITS {
                let mut out = Vec::with_capacity(r * c);
                for row in rows_of(a, r, k) {
                    for other in rows_of(b, c, k) {
                        out.push(row.iter().zip(other).map(|(x, y)| x * y).sum());
                    }
                }
                return IntMatrix::from_i128(r, c, out);
            }
        }
        let (a, b) = (self.big(), rhs.big());
        let mut out = Vec::with_capacity(r * c);
        for row in rows_of(&a, r, k) {
            for other in rows_of(&b, c, k) {
                cagd_scalar::cancel::checkpoint();
                let mut acc = BigInt::zero();
                for (x, y) in row.iter().zip(other) {
                    if !x.is_zero() && !y.is_zero() {
                        acc += x * y;
                    }
                }
                out.push(acc);
            }
        }
        IntMatrix::from_big(r, c, out)
    }

    /// The product `self · rhs`.
    ///
    /// # Panics
    /// If `self.cols() != rhs.rows()`.
    pub fn mul(&self, rhs: &Self) -> Self {
        self.mul_transpose(&rhs.transpose())
    }
}

/// The `rows` rows of length `len` of row-major data (`rows · len` entries).
fn rows_of<T>(data: &[T], rows: usize, len: usize) -> impl Iterator<Item = &[T]> {
    (0..rows).map(move |i| data.get(i * len..(i + 1) * len).unwrap_or(&[]))
}

/// Above this many bits of Hadamard's bound, [`solve_integer`] works modulo primes.
const MULTIMODULAR_BITS: u64 = 1500;

/// The solution of the integer system A X = B (A square, B with any number of columns) as
/// integers over the determinant: `(Y, d)` with `A Y = d · B`, so `X = Y / d` (d is ± det A);
/// `None` when A is singular.
///
/// Small systems use Bareiss' fraction-free elimination; large ones (Hadamard's bound on the
/// minors above 2^1500) Cramer's rule modulo primes just below 2^62 with the Chinese remainder
/// theorem, whose result is exact because the primes' product exceeds twice that bound.
///
/// ```
/// use cagd_linalg::exact::{solve_integer, IntMatrix};
/// // [[2, 1], [1, 3]] X = [[1], [2]]: X = [[1], [3]] / 5
/// let a = IntMatrix::from_i128(2, 2, vec![2, 1, 1, 3]);
/// let (y, d) = solve_integer(&a, &IntMatrix::from_i128(2, 1, vec![1, 2])).unwrap();
/// assert_eq!((y.get(0, 0) * 5 / &d, y.get(1, 0) * 5 / &d), (1.into(), 3.into()));
/// ```
///
/// # Panics
/// If A is not square or B has another number of rows.
pub fn solve_integer(a: &IntMatrix, b: &IntMatrix) -> Option<(IntMatrix, BigInt)> {
    assert!(
        a.cols() == a.rows() && b.rows() == a.rows(),
        "solve_integer: A must be square and B have as many rows"
    );
    let solution = if crate::modular::hadamard_bits(a, b) > MULTIMODULAR_BITS {
        crate::modular::solve_multimodular(a, b).or_else(|| crate::bareiss::solve_bareiss(a, b))
    } else {
        crate::bareiss::solve_bareiss(a, b)
    }?;
    Some(without_content(solution))
}

/// `(Y / g, d / g)` with g the gcd of d and every entry of Y: the same solution with smaller
/// numbers, so that reducing each entry later costs less. Most entries are multiples of the
/// running gcd, which a division checks without a new gcd.
fn without_content((y, d): (IntMatrix, BigInt)) -> (IntMatrix, BigInt) {
    if d.bits() <= LEHMER_BITS {
        return (y, d);
    }
    let mut g = d.magnitude().clone();
    for i in 0..y.rows() {
        for j in 0..y.cols() {
            if g.is_one() {
                return (y, d);
            }
            let x = y.get(i, j);
            if !(x.magnitude() % &g).is_zero() {
                g = gcd_lehmer(&g, x.magnitude()).magnitude().clone();
            }
        }
    }
    let g = BigInt::from(g);
    let entries = (0..y.rows())
        .flat_map(|i| (0..y.cols()).map(move |j| (i, j)))
        .map(|(i, j)| y.get(i, j) / &g)
        .collect();
    (IntMatrix::from_big(y.rows(), y.cols(), entries), d / g)
}

/// Above this many bits, [`ratio_over_bases`] divides out the common factors base by base, and
/// a common denominator's content is removed.
const LEHMER_BITS: u64 = 100;

/// `p/q` reduced, from integers with `q ≠ 0`: machine-integer gcd when both fit in `i128`,
/// [`cagd_scalar::gcd::gcd`] (one remainder by a short side, Lehmer's for two long ones)
/// otherwise.
pub fn ratio(p: BigInt, q: BigInt) -> BigRational {
    if let (Some(a), Some(b)) = (p.to_i128(), q.to_i128()) {
        if a != i128::MIN && b != i128::MIN && b != 0 {
            return ratio_i128(a, b);
        }
    }
    let g = gcd(&p, &q);
    let (mut p, mut q) = if g.is_one() { (p, q) } else { (p / &g, q / &g) };
    if q.is_negative() {
        p = -p;
        q = -q;
    }
    BigRational::new_raw(p, q)
}

/// `p/q` reduced, from integers with `q ≠ 0` when every prime factor of q divides one of the
/// `bases` (q a product of their powers, as `q_u^m q_v^n L` over the denominators of the
/// parameters and of the data): the common factors are found base by base,
/// `h = gcd(p mod b, b)`, then `gcd(h, q)`, divided out until none is left, so that the only
/// long operation is `p mod b`, linear in the length of p, where a gcd of p and q (Lehmer's, in
/// [`ratio`]) is quadratic. Every common prime divides some base, and none is left once each
/// base has no factor in common with both, so the result is reduced.
///
/// ```
/// use cagd_linalg::exact::{ratio, ratio_over_bases};
/// use cagd_scalar::BigInt;
/// let (p, q) = (BigInt::from(6) * BigInt::from(7).pow(30), BigInt::from(21).pow(20));
/// let bases = [BigInt::from(21)];
/// assert_eq!(ratio_over_bases(p.clone(), q.clone(), &bases), ratio(p, q));
/// ```
pub fn ratio_over_bases(p: BigInt, q: BigInt, bases: &[BigInt]) -> BigRational {
    if p.bits().max(q.bits()) <= LEHMER_BITS || p.is_zero() {
        return ratio(p, q);
    }
    // gcd(x mod y, y) for y > 0
    let gcd_mod = |x: &BigInt, y: &BigInt| gcd(&(x % y), y);
    let (mut p, mut q) = (p, q);
    for b in bases {
        let b = b.abs();
        if b.is_zero() || b.is_one() {
            continue;
        }
        loop {
            let h = gcd_mod(&p, &b);
            let h = if h.is_one() { h } else { gcd_mod(&q, &h) };
            if h.is_one() || h.is_zero() {
                break;
            }
            p /= &h;
            q /= &h;
        }
    }
    if q.is_negative() {
        p = -p;
        q = -q;
    }
    BigRational::new_raw(p, q)
}

/// `a/b` reduced, for machine integers with `b ≠ 0` and neither equal to `i128::MIN`.
pub fn ratio_i128(a: i128, b: i128) -> BigRational {
    if let (Ok(a), Ok(b)) = (i64::try_from(a), i64::try_from(b)) {
        if a != i64::MIN && b != i64::MIN {
            let g = i64::try_from(gcd_u64(a.unsigned_abs(), b.unsigned_abs()).max(1)).unwrap_or(1);
            let (mut a, mut b) = (a / g, b / g);
            if b < 0 {
                a = -a;
                b = -b;
            }
            return BigRational::new_raw(BigInt::from(a), BigInt::from(b));
        }
    }
    let g = gcd_u128(a.unsigned_abs(), b.unsigned_abs()).max(1);
    let g = i128::try_from(g).unwrap_or(1);
    let (mut a, mut b) = (a / g, b / g);
    if b < 0 {
        a = -a;
        b = -b;
    }
    BigRational::new_raw(BigInt::from(a), BigInt::from(b))
}

/// The entry `num / den` of a result, as a scalar.
pub fn to_scalar<S: Scalar>(num: BigInt, den: &BigInt) -> S {
    S::from_rational_owned(ratio(num, den.clone()))
}

/// Rationals over one positive common denominator: `values[k] = num[k] / den`.
#[derive(Clone, Debug, PartialEq)]
pub struct CommonDenominator {
    /// The numerators.
    pub num: Vec<BigInt>,
    /// The least common denominator (positive).
    pub den: BigInt,
}

/// The values over their least common denominator, when every one is an exact rational
/// (`None` for `f64` or a value with a root part, and when the numbers do not fit machine
/// integers: see [`common_denominator_big`]).
pub fn common_denominator<'a, S: Scalar>(
    values: impl IntoIterator<Item = &'a S>,
) -> Option<(Vec<i128>, i128)> {
    let values = values.into_iter();
    let mut small: Vec<(i64, i64)> = Vec::with_capacity(values.size_hint().0);
    let mut den: u64 = 1;
    for x in values {
        let (p, d) = x.as_small_ratio()?;
        let (p, d) = (i64::try_from(p).ok()?, u64::try_from(d).ok()?);
        if den % d != 0 {
            den = den.checked_mul(d / gcd_u64(den, d))?;
            if den > i64::MAX as u64 {
                return None;
            }
        }
        small.push((p, i64::try_from(d).ok()?));
    }
    let den = i64::try_from(den).ok()?;
    let num = small
        .iter()
        .map(|&(p, d)| i128::from(p) * i128::from(den / d))
        .collect();
    Some((num, i128::from(den)))
}

/// The values over their least common denominator in big integers (`None` when a value is not
/// an exact rational).
pub fn common_denominator_big<'a, S: Scalar>(
    values: impl IntoIterator<Item = &'a S> + Clone,
) -> Option<CommonDenominator> {
    let mut den = BigInt::one();
    for x in values.clone() {
        let q = x.as_rational()?;
        if !den.is_multiple_of(q.denom()) {
            den = den.lcm(q.denom());
        }
    }
    let mut num = Vec::new();
    for x in values {
        let q = x.as_rational()?;
        num.push(q.numer() * (&den / q.denom()));
    }
    Some(CommonDenominator { num, den })
}

/// One coordinate of a grid of points (listed row by row) as an integer matrix over a common
/// denominator: `(N, L)` with `coordinate k of point (i, j) = N_ij / L`. `None` when a
/// coordinate is not an exact rational.
pub fn coordinate_matrix<'a, S: Scalar>(
    rows: usize,
    cols: usize,
    points: impl Iterator<Item = &'a Point<S>> + Clone,
    k: usize,
) -> Option<(IntMatrix, BigInt)> {
    let coords = points.map(move |p| &p[k]);
    if let Some((num, den)) = common_denominator(coords.clone()) {
        return Some((IntMatrix::from_i128(rows, cols, num), BigInt::from(den)));
    }
    let CommonDenominator { num, den } = common_denominator_big(coords)?;
    Some((IntMatrix::from_big(rows, cols, num), den))
}

/// The Bernstein values of degree n at the rational t = p/q as integers over `q^n`:
/// `B_i^n(t) = C(n, i) p^i (q - p)^(n - i) / q^n` (one row of `n + 1` numerators, and q^n).
/// `None` when t is not an exact rational.
pub fn bernstein_numerators<S: Scalar>(n: usize, t: &S) -> Option<(IntMatrix, BigInt)> {
    let t = t.as_rational()?;
    if let (Some(p), Some(q)) = (t.numer().to_i128(), t.denom().to_i128()) {
        if let Some(small) = bernstein_numerators_i128(n, p, q) {
            return Some(small);
        }
    }
    let p = t.numer().clone();
    let q = t.denom().clone();
    let r = &q - &p;
    let exp = |k: usize| u32::try_from(k).unwrap_or(u32::MAX);
    // binomials C(n, i), powers p^i and r^(n-i), by recurrence
    let powers = |x: &BigInt| -> Vec<BigInt> {
        let mut v = Vec::with_capacity(n + 1);
        v.push(BigInt::one());
        while v.len() <= n {
            if let Some(next) = v.last().map(|last| last * x) {
                v.push(next);
            }
        }
        v
    };
    let (p_pow, r_pow) = (powers(&p), powers(&r));
    let mut binom = BigInt::one();
    let mut num = Vec::with_capacity(n + 1);
    for (i, (p_i, r_n_i)) in p_pow.iter().zip(r_pow.iter().rev()).enumerate() {
        if i > 0 {
            binom = binom * BigInt::from(n + 1 - i) / BigInt::from(i);
        }
        num.push(&binom * p_i * r_n_i);
    }
    Some((IntMatrix::from_big(1, n + 1, num), q.pow(exp(n))))
}

/// [`bernstein_numerators`] in machine integers; `None` on overflow.
fn bernstein_numerators_i128(n: usize, p: i128, q: i128) -> Option<(IntMatrix, BigInt)> {
    let (num, qn) = bernstein_numerators_small(n, p, q)?;
    Some((IntMatrix::from_i128(1, n + 1, num), BigInt::from(qn)))
}

/// [`bernstein_numerators`] at t = p/q on machine integers: `C(n, i) p^i (q − p)^(n−i)` for
/// i = 0..=n and `q^n`, or `None` when one of them overflows `i128`.
pub fn bernstein_numerators_small(n: usize, p: i128, q: i128) -> Option<(Vec<i128>, i128)> {
    let r = q.checked_sub(p)?;
    // p^0, ..., p^n and r^0, ..., r^n
    let (mut p_pow, mut r_pow) = (Vec::with_capacity(n + 1), Vec::with_capacity(n + 1));
    let (mut p_i, mut r_i) = (1i128, 1i128);
    p_pow.push(p_i);
    r_pow.push(r_i);
    for _ in 0..n {
        p_i = p_i.checked_mul(p)?;
        r_i = r_i.checked_mul(r)?;
        p_pow.push(p_i);
        r_pow.push(r_i);
    }
    let mut binom = 1i128;
    let mut num = Vec::with_capacity(n + 1);
    for (i, (&p_i, &r_n_i)) in p_pow.iter().zip(r_pow.iter().rev()).enumerate() {
        if i > 0 {
            let (a, b) = (i128::try_from(n + 1 - i).ok()?, i128::try_from(i).ok()?);
            binom = binom.checked_mul(a)? / b;
        }
        num.push(binom.checked_mul(p_i)?.checked_mul(r_n_i)?);
    }
    let qn = q.checked_pow(u32::try_from(n).ok()?)?;
    Some((num, qn))
}

/// The Bernstein sum `c(t) = Σ_i B_i^n(t) c_i` of a control polygon on integers, for a
/// rational t = p/q and rational points: with each coordinate k over its common denominator,
/// `c_ik = N_ik / L_k`,
///
/// `c_k(t) = Σ_i C(n, i) p^i (q − p)^(n−i) N_ik / (q^n L_k)`,
///
/// integer binomials and powers ([`bernstein_numerators`]) and one reduction per coordinate at
/// the end, where De Casteljau's n(n+1)/2 rational steps reduce a fraction at every step.
/// `None` when t or a coordinate is not an exact rational (or there is no point).
///
/// ```
/// use cagd_linalg::{exact::bernstein_combination, Point};
/// use cagd_scalar::{q, BigRational};
/// let c: Vec<Point<BigRational>> =
///     vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2]), Point::from_ints(&[3, 3])];
/// assert_eq!(bernstein_combination(&c, &q!(1/3)).unwrap().to_text(), "(7/9, 11/9)");
/// ```
pub fn bernstein_combination<S: Scalar>(points: &[Point<S>], t: &S) -> Option<Point<S>> {
    let n = points.len().checked_sub(1)?;
    let dim = points.first().map(Point::dim)?;
    let (b, qn) = bernstein_numerators(n, t)?;
    let mut nums = Vec::with_capacity(dim);
    let mut dens = Vec::with_capacity(dim);
    for k in 0..dim {
        let (column, den) = coordinate_matrix(points.len(), 1, points.iter(), k)?;
        nums.push(b.mul(&column).get(0, 0));
        dens.push(den);
    }
    let q = t.as_rational()?.denom().clone();
    Some(point_over_bases(nums, &qn, &dens, &[q]))
}

/// The point whose coordinate k is `nums[k] / (den · dens[k])`, each reduced by
/// [`ratio_over_bases`] with the bases `parameter_bases` and `dens[k]`: every prime factor of
/// `den` must divide one of `parameter_bases` (as `q^n` for the parameter p/q).
pub fn point_over_bases<S: Scalar>(
    nums: Vec<BigInt>,
    den: &BigInt,
    dens: &[BigInt],
    parameter_bases: &[BigInt],
) -> Point<S> {
    let coords = nums
        .into_iter()
        .zip(dens)
        .map(|(num, den_k)| {
            let mut bases = parameter_bases.to_vec();
            bases.push(den_k.clone());
            S::from_rational_owned(ratio_over_bases(num, den * den_k, &bases))
        })
        .collect();
    Point::new(coords)
}

/// The points whose coordinate k is `num_k(i, j) / (row_den[i] · col_den[j] · den_k)`: the
/// result of an integer sandwich product brought back to scalars, row by row.
///
/// The matrices `nums` have one shape, `row_den` one entry per row, `col_den` one per column
/// and `dens` one per matrix; a shorter list or a smaller matrix shortens the result.
pub fn points_from_integers<S: Scalar>(
    nums: &[IntMatrix],
    dens: &[BigInt],
    row_den: &[BigInt],
    col_den: &[BigInt],
) -> Vec<Point<S>> {
    let (rows, cols) = nums.first().map_or((0, 0), |m| (m.rows(), m.cols()));
    let small = |v: &[BigInt]| {
        v.iter()
            .map(ToPrimitive::to_i128)
            .collect::<Option<Vec<_>>>()
    };
    // the denominators in machine integers when they all fit
    let small = match (small(row_den), small(col_den), small(dens)) {
        (Some(r), Some(c), Some(d)) => Some((r, c, d)),
        _ => None,
    };
    let mut out = Vec::with_capacity(rows * cols);
    for (i, row_den_i) in row_den.iter().enumerate().take(rows) {
        for (j, col_den_j) in col_den.iter().enumerate().take(cols) {
            let mut coords = Vec::with_capacity(nums.len());
            // row_den[i] · col_den[j], once for the point's coordinates
            let point_den = small
                .as_ref()
                .and_then(|(r, c, _)| r.get(i)?.checked_mul(*c.get(j)?));
            for (k, (m, den_k)) in nums.iter().zip(dens).enumerate() {
                let den = small
                    .as_ref()
                    .and_then(|(_, _, d)| point_den?.checked_mul(*d.get(k)?))
                    .filter(|&x| x != i128::MIN);
                coords.push(match (m.get_small(i, j), den) {
                    (Some(a), Some(b)) => S::from_small_ratio(a, b),
                    _ => match m.entry(i, j) {
                        Some(a) => S::from_rational_owned(ratio(a, row_den_i * col_den_j * den_k)),
                        None => continue,
                    },
                });
            }
            out.push(Point::new(coords));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::q;

    #[test]
    fn products_agree_in_both_representations() {
        let a = IntMatrix::from_i128(2, 3, vec![1, -2, 3, 4, 5, -6]);
        let b = IntMatrix::from_i128(3, 2, vec![7, 8, 9, 10, 11, 12]);
        let p = a.mul(&b);
        assert_eq!(p, IntMatrix::from_i128(2, 2, vec![22, 24, 7, 10]));
        // the same product forced through big integers
        let big = IntMatrix {
            rows: 2,
            cols: 3,
            data: Data::Big(a.big()),
        };
        assert_eq!(big.mul(&b), p);
        // huge entries overflow i128 and switch to big integers exactly
        let h = IntMatrix::from_i128(1, 2, vec![1 << 100, 1 << 100]);
        let s = h.mul_transpose(&h);
        assert_eq!(s.get(0, 0), BigInt::from(1u8) << 201);
        assert_eq!(s.get_small(0, 0), None);
    }

    #[test]
    fn reduced_ratios_and_gcds() {
        assert_eq!(ratio_i128(6, -4), q!(-3 / 2));
        assert_eq!(ratio_i128(0, 7), q!(0));
        assert_eq!(ratio(BigInt::from(10), BigInt::from(4)), q!(5 / 2));
        // a big common factor: the Lehmer path of `ratio`
        let g = BigInt::from(3u8).pow(300) * BigInt::from(7u8).pow(100);
        let a = &g * (BigInt::from(2u8).pow(500) + 1u8);
        let b = &g * (BigInt::from(5u8).pow(200) - 2u8);
        assert_eq!(ratio(a.clone(), -b.clone()), BigRational::new(a, -b));
    }

    #[test]
    fn common_denominators_and_bernstein_numerators() {
        let v = [q!(1 / 2), q!(-5 / 6), q!(2)];
        let (num, den) = common_denominator(v.iter()).unwrap();
        assert_eq!((num, den), (vec![3, -5, 12], 6));
        let big = common_denominator_big(v.iter()).unwrap();
        assert_eq!(big.den, BigInt::from(6));
        // B^3(1/3) = (8, 12, 6, 1) / 27
        let (b, d) = bernstein_numerators(3, &q!(1 / 3)).unwrap();
        assert_eq!(b, IntMatrix::from_i128(1, 4, vec![8, 12, 6, 1]));
        assert_eq!(d, BigInt::from(27));
        assert!(bernstein_numerators(2, &0.5_f64).is_none());
    }
}
