//! The fast exact paths of cagd-poly, taken when every coefficient is rational:
//!
//! - the change from the Bernstein to the monomial basis in two variables,
//!   `A = M_m C M_nᵀ` on integer numerators (one division per coefficient), with the integer
//!   matrix `(M_n)_{k,i} = (−1)^(k−i) C(n, k) C(k, i)` of
//!   `a_k = C(n, k) Σ_{i ≤ k} (−1)^(k−i) C(k, i) c_i`;
//!   done, when every coordinate of a mesh is a rational of machine size, as forward
//!   differences on machine integers (`a_kl = C(m, k) C(n, l) Δ_u^k Δ_v^l c_00` over the
//!   common denominator, checked for overflow, the big-integer matrices as fallback), with the
//!   binomials computed once for all the coordinates and each coefficient built by the scalar
//!   from its numerator and denominator (`from_ratio`: one gcd, no big rational);
//! - the product of two polynomials, `(Σ A_m x^m / α)(Σ B_n x^n / β) = Σ (Σ_{m+n=k} A_m B_n)
//!   x^k / (αβ)`: integer multiply-adds (machine integers when a bound on the bits shows that
//!   nothing overflows) and one reduction per term of the product, instead of a gcd at every
//!   multiply-add as `BigRational` arithmetic does.

use crate::{Monomial, Poly, Var, VecPoly};
use cagd_linalg::exact::{common_denominator_big, ratio, ratio_i128, IntMatrix};
use cagd_linalg::Point;
use cagd_scalar::gcd::gcd_u64;
use cagd_scalar::{BigInt, Scalar};
use num_traits::{ToPrimitive, Zero};
use std::collections::HashMap;
use std::ops::{Mul, Sub};

/// Below this many products of terms, [`product`] leaves the work to the generic path.
const PRODUCT_MIN_TERMS: usize = 16;

/// The coefficients of `p` as integers over their least common denominator; `None` unless
/// every coefficient is rational, and when the common denominator is much longer than the
/// longest denominator (many unrelated denominators: every numerator would grow by it, and the
/// generic path, which reduces term by term, is then the faster one).
fn integer_terms<S: Scalar>(p: &Poly<S>) -> Option<(Vec<(Monomial, BigInt)>, BigInt)> {
    let c = common_denominator_big(p.terms.values())?;
    let longest = p
        .terms
        .values()
        .filter_map(|x| x.as_rational().map(|q| q.denom().bits()))
        .max()
        .unwrap_or(0);
    if c.den.bits() > 2 * longest + 64 {
        return None;
    }
    Some((p.terms.keys().copied().zip(c.num).collect(), c.den))
}

/// The bits of |x|.
fn bits(x: &BigInt) -> u64 {
    x.bits()
}

/// `a b` on integer numerators (see the module documentation): `None` unless every
/// coefficient of both is rational, or when the product is too small to gain from it.
pub(crate) fn product<S: Scalar>(a: &Poly<S>, b: &Poly<S>) -> Option<Poly<S>> {
    if a.terms.len().saturating_mul(b.terms.len()) < PRODUCT_MIN_TERMS {
        return None;
    }
    let (na, da) = integer_terms(a)?;
    let (nb, db) = integer_terms(b)?;
    let den = da * db;
    let max_bits = |v: &[(Monomial, BigInt)]| v.iter().map(|(_, c)| bits(c)).max().unwrap_or(0);
    let shorter = na.len().min(nb.len()) as u64;
    let sum_bits = u64::from(u64::BITS - shorter.leading_zeros());
    let mut sums: Vec<(Monomial, BigInt)> = if max_bits(&na) + max_bits(&nb) + sum_bits <= 126 {
        let small = |v: &[(Monomial, BigInt)]| -> Option<Vec<(Monomial, i128)>> {
            v.iter().map(|(m, c)| Some((*m, c.to_i128()?))).collect()
        };
        let (sa, sb) = (small(&na)?, small(&nb)?);
        let mut acc: HashMap<Monomial, i128> = HashMap::with_capacity(sa.len() + sb.len());
        for (ma, x) in &sa {
            cagd_scalar::cancel::checkpoint();
            for (mb, y) in &sb {
                // |Σ x y| < 2^126 by the bound above
                *acc.entry(ma.mul(mb)).or_insert(0) += x * y;
            }
        }
        acc.into_iter().map(|(m, c)| (m, BigInt::from(c))).collect()
    } else {
        let mut acc: HashMap<Monomial, BigInt> = HashMap::with_capacity(na.len() + nb.len());
        for (ma, x) in &na {
            cagd_scalar::cancel::checkpoint();
            for (mb, y) in &nb {
                *acc.entry(ma.mul(mb)).or_default() += x * y;
            }
        }
        acc.into_iter().collect()
    };
    sums.retain(|(_, c)| !c.is_zero());
    sums.sort_by_key(|t| t.0);
    Some(Poly::from_ordered_terms(
        sums.into_iter()
            .map(|(m, c)| {
                cagd_scalar::cancel::checkpoint();
                (m, S::from_rational_owned(ratio(c, den.clone())))
            })
            .collect(),
    ))
}

/// The integer matrix of the Bernstein-to-monomial change of degree n, in machine integers
/// (`C(n, k) C(k, i) ≤ 2^(n + k)` fits in an i128 up to n = 62), else `None`.
fn power_matrix(n: usize) -> Option<IntMatrix> {
    if n > 62 {
        return None;
    }
    // Pascal's triangle C(k, i), k ≤ n
    let mut pascal: Vec<Vec<i128>> = vec![vec![1]];
    for _ in 1..=n {
        let prev = pascal.last()?;
        // 1, then the sums of neighbours of the previous row, then 1
        let mut row = vec![1];
        row.extend(prev.windows(2).map(|w| w.iter().sum::<i128>()));
        row.push(1);
        pascal.push(row);
    }
    let binomial = |a: usize, b: usize| pascal.get(a).and_then(|r| r.get(b)).copied();
    let mut data = Vec::with_capacity((n + 1) * (n + 1));
    for k in 0..=n {
        for i in 0..=n {
            let x = if i > k {
                0
            } else {
                binomial(n, k)?.checked_mul(binomial(k, i)?)?
            };
            data.push(if (k + i) % 2 == 1 { -x } else { x });
        }
    }
    Some(IntMatrix::from_i128(n + 1, n + 1, data))
}

/// The binomial coefficients `C(n, 0), ..., C(n, n)` in machine integers, by
/// `C(n, k) = C(n, k − 1) (n − k + 1) / k` (an exact division); `None` past `i128`.
fn binomial_row(n: usize) -> Option<Vec<i128>> {
    let mut row = Vec::with_capacity(n + 1);
    let mut c: i128 = 1;
    row.push(c);
    for k in 1..=n {
        let (up, down) = (i128::try_from(n - k + 1).ok()?, i128::try_from(k).ok()?);
        c = c.checked_mul(up)? / down;
        row.push(c);
    }
    Some(row)
}

/// The forward differences of a list in place, scaled by the binomials of its degree:
/// `x_k ← C(n, k) Δ^k x_0` (the monomial coefficients `a_k = C(n, k) Σ_{i ≤ k} (−1)^(k−i)
/// C(k, i) c_i` of `Σ c_i B_i^n`). The caller bounds the result (`|C(n, k) Δ^k x_0| ≤ 4^n
/// max |x_i|`), so nothing overflows.
fn scaled_differences<I: Copy + Sub<Output = I> + Mul<Output = I>>(x: &mut [I], binomials: &[I]) {
    for k in 1..x.len() {
        // Δ^k x_j = Δ^(k−1) x_j − Δ^(k−1) x_(j−1) for j ≥ k, in increasing j, the old value
        // of x_(j−1) carried along
        let Some((&mut first, rest)) = x.get_mut(k - 1..).and_then(|t| t.split_first_mut()) else {
            continue;
        };
        let mut previous = first;
        for xj in rest {
            let old = *xj;
            *xj = old - previous;
            previous = old;
        }
    }
    for (xk, &c) in x.iter_mut().zip(binomials) {
        *xk = *xk * c;
    }
}

/// The monomial coefficients, in place, of the tensor-product Bernstein sum whose integer
/// coefficients `c` are given row by row (`cols` to a row): `a_kl = C(m, k) C(n, l) Δ_u^k
/// Δ_v^l c_00`, along v in each row, then along u (row differences, so each pass runs over
/// whole rows). `|a_kl| ≤ 4^(m + n) max |c_ij|`: the caller chooses `I` by that bound.
fn monomial_numerators<I: Copy + Sub<Output = I> + Mul<Output = I>>(
    c: &mut [I],
    cols: usize,
    binomials_u: &[I],
    binomials_v: &[I],
) {
    for row in c.chunks_exact_mut(cols) {
        scaled_differences(row, binomials_v);
    }
    let rows = c.len() / cols;
    for k in 1..rows {
        for i in (k..rows).rev() {
            // row i ← row i − row (i − 1)
            let (head, tail) = c.split_at_mut(i * cols);
            let previous = head.get((i - 1) * cols..).unwrap_or(&[]);
            for (x, &y) in tail.iter_mut().take(cols).zip(previous) {
                *x = *x - y;
            }
        }
    }
    for (row, &b) in c.chunks_exact_mut(cols).zip(binomials_u) {
        for x in row {
            *x = *x * b;
        }
    }
}

/// Rationals `p/q` (q > 0) over their least common denominator L: the numerators
/// `p · (L/q)` and L, with L in a machine word (`None` when it or a numerator overflows).
fn over_common_denominator(values: &[(i128, i128)]) -> Option<(Vec<i128>, i64)> {
    let mut den: u64 = 1;
    for &(_, q) in values {
        let q = u64::try_from(q).ok().filter(|&q| q > 0)?;
        if den % q != 0 {
            den = den.checked_mul(q / gcd_u64(den, q))?;
        }
    }
    // q divides L, both machine words (checked above): a word division
    let numerators = values
        .iter()
        .map(|&(p, q)| p.checked_mul(i128::from(den / u64::try_from(q).ok()?)))
        .collect::<Option<Vec<_>>>()?;
    Some((numerators, i64::try_from(den).ok()?))
}

/// `a / den` as a scalar (den > 0): built by the scalar from machine words when both fit
/// (`from_ratio` reduces it), through a reduced big rational otherwise; `None` for
/// `i128::MIN`.
fn coefficient<T: Scalar>(a: i128, den: i64) -> Option<T> {
    match i64::try_from(a) {
        Ok(a) => Some(T::from_ratio(a, den)),
        _ if a != i128::MIN => Some(T::from_rational_owned(ratio_i128(a, i128::from(den)))),
        _ => None,
    }
}

/// The polynomial `Σ a_kl var_u^k var_v^l / den` of monomial numerators given row by row,
/// its terms built in the monomials' order (graded: by total degree k + l, then by the power
/// of the variable that comes first), so that the map is filled without a search.
fn poly_of_numerators<T: Scalar, I: Copy + Into<i128>>(
    a: &[I],
    den: i64,
    (rows, cols): (usize, usize),
    var_u: Var,
    var_v: Var,
) -> Option<Poly<T>> {
    let exp = |k: usize| u32::try_from(k).unwrap_or(u32::MAX);
    let u_first = var_u.index() < var_v.index();
    let mut terms = Vec::with_capacity(a.len());
    for d in 0..rows + cols - 1 {
        let (low, high) = (d.saturating_sub(cols - 1), d.min(rows - 1));
        // ascending powers of the first variable within a degree
        let mut push = |k: usize| -> Option<()> {
            let l = d - k;
            let x: i128 = (*a.get(k * cols + l)?).into();
            if x != 0 {
                let m = Monomial::one()
                    .with_exp(var_u, exp(k))
                    .with_exp(var_v, exp(l));
                terms.push((m, coefficient::<T>(x, den)?));
            }
            Some(())
        };
        if u_first {
            (low..=high).try_for_each(&mut push)?;
        } else {
            (low..=high).rev().try_for_each(&mut push)?;
        }
    }
    Some(Poly::from_ordered_terms(terms))
}

/// The binomial rows of degrees m = rows − 1 and n = cols − 1, in 128-bit words and, when
/// they fit, in 64-bit words: computed once for every coordinate of a mesh.
struct Binomials {
    u: Vec<i128>,
    v: Vec<i128>,
    narrow: Option<(Vec<i64>, Vec<i64>)>,
}

impl Binomials {
    fn new(rows: usize, cols: usize) -> Option<Self> {
        let u = binomial_row(rows.checked_sub(1)?)?;
        let v = if cols == rows {
            u.clone()
        } else {
            binomial_row(cols.checked_sub(1)?)?
        };
        let narrow =
            |v: &[i128]| -> Option<Vec<i64>> { v.iter().map(|&x| i64::try_from(x).ok()).collect() };
        let narrow = narrow(&u).zip(narrow(&v));
        Some(Binomials { u, v, narrow })
    }
}

/// `Σ_i Σ_j c_ij B_i^m(var_u) B_j^n(var_v)` of rationals `c_ij = p/q` given row by row, on
/// machine integers ([`monomial_numerators`]): in 64-bit words when the bound
/// `|a_kl| ≤ 4^(m + n) max |N_ij|` on the numerators N over the common denominator fits one,
/// else in 128-bit words when it fits those; `None` beyond (the big-integer path).
fn small_poly<T: Scalar>(
    values: &[(i128, i128)],
    (rows, cols): (usize, usize),
    binomials: &Binomials,
    var_u: Var,
    var_v: Var,
) -> Option<Poly<T>> {
    let (mut a, den) = over_common_denominator(values)?;
    let longest = a
        .iter()
        .map(|x| u64::from(128 - x.unsigned_abs().leading_zeros()))
        .max()
        .unwrap_or(0);
    let bits = longest + 2 * u64::try_from(rows + cols - 2).ok()?;
    if let (true, Some((bu, bv))) = (bits <= 62, &binomials.narrow) {
        // every |a_kl| < 2^62: 64-bit words
        let mut a: Vec<i64> = a.iter().map(|&x| i64::try_from(x).unwrap_or(0)).collect();
        monomial_numerators(&mut a, cols, bu, bv);
        return poly_of_numerators(&a, den, (rows, cols), var_u, var_v);
    }
    if bits <= 126 {
        monomial_numerators(&mut a, cols, &binomials.u, &binomials.v);
        return poly_of_numerators(&a, den, (rows, cols), var_u, var_v);
    }
    None
}

/// The polynomial map `Σ_i Σ_j c_ij B_i^m(var_u) B_j^n(var_v)` of a mesh given row by row
/// (`rows · cols` points of one dimension), with its coefficients built in `T`, when every
/// coordinate is a rational whose numerator and denominator fit machine integers and nothing
/// overflows (`None` otherwise: the caller takes the general path). The binomials are
/// computed once for all the coordinates.
pub(crate) fn map_from_bernstein_2d<'a, S: Scalar + 'a, T: Scalar>(
    points: impl IntoIterator<Item = &'a Point<S>>,
    (rows, cols): (usize, usize),
    var_u: Var,
    var_v: Var,
) -> Option<VecPoly<T>> {
    if rows == 0 || cols == 0 || var_u == var_v {
        return None;
    }
    let binomials = Binomials::new(rows, cols)?;
    // the coordinates, one list per dimension, each row by row
    let mut by_coordinate: Vec<Vec<(i128, i128)>> = Vec::new();
    let mut count = 0;
    for p in points {
        if count == 0 {
            by_coordinate = (0..p.dim())
                .map(|_| Vec::with_capacity(rows * cols))
                .collect();
        } else if p.dim() != by_coordinate.len() {
            return None;
        }
        for (list, x) in by_coordinate.iter_mut().zip(p.coords()) {
            list.push(x.as_small_ratio()?);
        }
        count += 1;
    }
    if count != rows * cols || by_coordinate.is_empty() {
        return None;
    }
    let comps = by_coordinate
        .iter()
        .map(|values| small_poly(values, (rows, cols), &binomials, var_u, var_v))
        .collect::<Option<Vec<_>>>()?;
    Some(VecPoly::new(comps))
}

/// `Σ_i Σ_j c_ij B_i^m(var_u) B_j^n(var_v)` on integers; `None` unless every coefficient is
/// rational. The grid is a non-empty rectangle (checked by the caller). Machine integers when
/// every coefficient and every result fits ([`small_poly`]), else big integer matrices
/// `M_m C M_nᵀ`.
pub(crate) fn poly_from_bernstein_2d<S: Scalar>(
    grid: &[Vec<S>],
    var_u: Var,
    var_v: Var,
) -> Option<Poly<S>> {
    let rows = grid.len();
    let cols = grid.first().map_or(0, Vec::len);
    if rows == 0 || cols == 0 {
        return None;
    }
    let values = grid.iter().flatten();
    let small: Option<Vec<(i128, i128)>> = values.clone().map(|x| x.as_small_ratio()).collect();
    if let Some(small) = small {
        let binomials = Binomials::new(rows, cols);
        if let Some(p) = binomials.and_then(|b| small_poly(&small, (rows, cols), &b, var_u, var_v))
        {
            return Some(p);
        }
    }
    let c = common_denominator_big(values)?;
    let (num, den) = (IntMatrix::from_big(rows, cols, c.num), c.den);
    let mu = power_matrix(rows - 1)?;
    let mv = if cols == rows {
        mu.clone()
    } else {
        power_matrix(cols - 1)?
    };
    let a = mu.mul(&num.mul_transpose(&mv));
    let exp = |k: usize| u32::try_from(k).unwrap_or(u32::MAX);
    let mut terms = Vec::with_capacity(rows * cols);
    for k in 0..rows {
        for l in 0..cols {
            let c = a.get(k, l);
            if !c.is_zero() {
                terms.push((
                    Monomial::from_powers(&[(var_u, exp(k)), (var_v, exp(l))]),
                    S::from_rational_owned(ratio(c, den.clone())),
                ));
            }
        }
    }
    Some(Poly::from_terms(terms))
}

#[cfg(test)]
mod tests {
    use super::map_from_bernstein_2d;
    use crate::{bernstein, poly_from_bernstein_2d, Poly, Var, VecPoly};
    use cagd_linalg::Point;
    use cagd_scalar::{BigRational, ExactRational, FieldOps, Quadratic, Rat, Scalar};
    use proptest::prelude::*;

    type Q = BigRational;

    /// The independent route: Σ c_ij B_i^m(u) B_j^n(v) with polynomial arithmetic.
    fn by_products<S: Scalar>(grid: &[Vec<S>]) -> Poly<S> {
        let (m, n) = (grid.len() - 1, grid[0].len() - 1);
        let mut p = Poly::zero();
        for (i, row) in grid.iter().enumerate() {
            for (j, c) in row.iter().enumerate() {
                let term = bernstein::<S>(i, m, Var::U) * bernstein::<S>(j, n, Var::V);
                p = p + term.scale(c);
            }
        }
        p
    }

    fn grid() -> impl Strategy<Value = Vec<Vec<Q>>> {
        (1usize..=5, 1usize..=5).prop_flat_map(|(r, c)| {
            prop::collection::vec(
                prop::collection::vec(
                    (-9i64..=9, 1i64..=9).prop_map(|(p, q)| Q::from_ratio(p, q)),
                    c,
                ),
                r,
            )
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        #[test]
        fn integer_change_of_basis_equals_the_bernstein_sum(g in grid()) {
            let fast = poly_from_bernstein_2d(&g, Var::U, Var::V).unwrap();
            prop_assert_eq!(&fast, &by_products(&g));
            // a grid with a root part takes the generic path: the same with √2 added to c_00
            let r2 = Quadratic::sqrt_of(&Q::from_i64(2)).unwrap();
            let mut gq: Vec<Vec<Quadratic>> = g
                .iter()
                .map(|row| row.iter().map(|x| Quadratic::from_rational(x.clone())).collect())
                .collect();
            gq[0][0] = gq[0][0].clone() + &r2;
            prop_assert_eq!(poly_from_bernstein_2d(&gq, Var::U, Var::V).unwrap(), by_products(&gq));
        }

        #[test]
        fn integer_product_equals_the_termwise_product(
            a in poly(6, 9),
            b in poly(6, 9),
            big in prop::bool::ANY,
        ) {
            // long coefficients take the big-integer accumulation, short ones the i128 one
            let a = if big { a.scale(&Q::from_ratio(10i64.pow(18) + 7, 3)).pow(2) } else { a };
            let fast = &a * &b;
            prop_assert_eq!(&fast, &termwise(&a, &b));
            // with a root part: the generic path, the same polynomial
            let r2 = Quadratic::sqrt_of(&Q::from_i64(2)).unwrap();
            let aq = a.map_coeffs(|x| Quadratic::from_rational(x.clone()));
            let bq = b.map_coeffs(|x| Quadratic::from_rational(x.clone()) + &r2);
            prop_assert_eq!(&aq * &bq, termwise(&aq, &bq));
        }
    }

    /// A mesh of `rows x cols` points of dimension `dim` whose coordinates are `p/q` scaled
    /// by `10^(18·scale)`: scale 0 takes the 64-bit words, 1 the 128-bit words or the big
    /// integers (by the bound), 2 and 3 numbers past 128 bits (the big-integer path).
    fn mesh() -> impl Strategy<Value = (Vec<Point<Q>>, (usize, usize), u32)> {
        (1usize..=6, 1usize..=6, 1usize..=4, 0u32..=3).prop_flat_map(|(r, c, dim, scale)| {
            let big = Q::from_integer(cagd_scalar::BigInt::from(10u8).pow(18 * scale));
            prop::collection::vec(
                prop::collection::vec((-99i64..=99, 1i64..=60), dim).prop_map(move |xs| {
                    Point::new(
                        xs.into_iter()
                            .map(|(p, q)| Q::from_ratio(p, q) * &big)
                            .collect(),
                    )
                }),
                r * c,
            )
            .prop_map(move |points| (points, (r, c), scale))
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]

        /// The machine-integer closed form of a mesh (and its big-integer fallback) equals the
        /// Bernstein sum coordinate by coordinate, built in the mesh's scalar or in another.
        #[test]
        fn machine_integer_closed_form_equals_the_bernstein_sum((points, (r, c), scale) in mesh()) {
            let rows: Vec<Vec<Point<Q>>> = points.chunks(c).map(<[Point<Q>]>::to_vec).collect();
            let dim = points[0].dim();
            let want: Vec<Poly<Q>> = (0..dim)
                .map(|k| by_products(&rows.iter().map(|row| row.iter().map(|p| p[k].clone()).collect::<Vec<_>>()).collect::<Vec<_>>()))
                .collect();
            let fast: Option<VecPoly<Q>> = map_from_bernstein_2d(&points, (r, c), Var::U, Var::V);
            // small numbers over a common denominator of a machine word never leave the words
            // (36 denominators up to 60 can have an lcm past 2^63: then the fallback answers)
            let word_denominators = (0..dim).all(|k| {
                let lcm = points.iter().fold(cagd_scalar::BigInt::from(1u8), |l, p| {
                    let d = p[k].denom();
                    &l / cagd_scalar::gcd::gcd(&l, d) * d
                });
                lcm.bits() < 63
            });
            if scale == 0 && word_denominators {
                prop_assert!(fast.is_some());
            }
            if let Some(f) = &fast {
                prop_assert_eq!(f.components(), &want[..]);
            }
            // in another scalar: the same coefficients
            let rats: Vec<Point<Rat>> = points
                .iter()
                .map(|p| Point::new(p.coords().iter().map(Rat::from_rational).collect()))
                .collect();
            let other: Option<VecPoly<Quadratic>> =
                map_from_bernstein_2d(&rats, (r, c), Var::U, Var::V);
            prop_assert_eq!(other.is_some(), fast.is_some());
            if let Some(o) = other {
                let want_q: Vec<Poly<Quadratic>> = want
                    .iter()
                    .map(|p| p.map_coeffs(|x| Quadratic::from_rational(x.clone())))
                    .collect();
                prop_assert_eq!(o.components(), &want_q[..]);
            }
            // the public entry (fast path or fallback) and v before u
            let all = crate::from_bernstein_2d(&rows, Var::U, Var::V).unwrap();
            prop_assert_eq!(all.components(), &want[..]);
            let swapped: Option<VecPoly<Q>> = map_from_bernstein_2d(&points, (r, c), Var::V, Var::U);
            if let Some(s) = swapped {
                let back: Vec<Poly<Q>> = s
                    .components()
                    .iter()
                    .map(|p| p.substitute(Var::U, &Poly::var(Var::W)).substitute(Var::V, &Poly::var(Var::U)).substitute(Var::W, &Poly::var(Var::V)))
                    .collect();
                prop_assert_eq!(back, want);
            }
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]

        #[test]
        fn mixed_partial_equals_the_quotient_rule(
            numer in prop::collection::vec(poly(4, 2), 2),
            denom in poly(3, 2),
            r in 0usize..=2,
            s in 0usize..=2,
            u in (-5i64..=5, 1i64..=7),
            v in (-5i64..=5, 1i64..=7),
        ) {
            // w = denom + 50 does not vanish on the small points below
            let denom = denom + Poly::constant(Q::from_i64(50));
            let f = crate::RationalMap::new(crate::VecPoly::new(numer), denom.clone()).unwrap();
            let fast = f.mixed_partial(Var::U, r, Var::V, s);
            let mut slow = f.clone();
            for _ in 0..r {
                slow = slow.partial(Var::U);
            }
            for _ in 0..s {
                slow = slow.partial(Var::V);
            }
            let at = [(Var::U, Q::from_ratio(u.0, u.1)), (Var::V, Q::from_ratio(v.0, v.1))];
            prop_assert_eq!(fast.eval(&at).unwrap(), slow.eval(&at).unwrap());
            // the denominator divides w^(r+s+1)
            let k = u32::try_from(r + s + 1).unwrap();
            prop_assert!(denom.pow(k).divide_exact(fast.denominator()).is_some());
        }
    }

    /// A polynomial in u, v with up to `terms` terms of degree ≤ `degree` in each variable.
    fn poly(terms: usize, degree: u32) -> impl Strategy<Value = Poly<Q>> {
        prop::collection::vec(
            ((0..=degree, 0..=degree), (-99i64..=99, 1i64..=30)),
            1..=terms,
        )
        .prop_map(|ts| {
            Poly::from_terms(ts.into_iter().map(|((i, j), (p, q))| {
                (
                    crate::Monomial::from_powers(&[(Var::U, i), (Var::V, j)]),
                    Q::from_ratio(p, q),
                )
            }))
        })
    }

    /// The integer product (machine words, and big integers) passes a checkpoint for every
    /// term of its first factor and every term of the product: a long product stops at its
    /// deadline (a degree-43 triangle's curvature ran 20 s past it without).
    #[test]
    fn the_integer_product_passes_a_checkpoint_per_term() {
        for digits in [2usize, 60] {
            let c = |k: usize| {
                Q::from_ratio(k as i64 + 1, 7) * Q::from_integer(10.into()).pow(digits as i32)
            };
            let a: Poly<Q> = Poly::from_terms(
                (0..40u32).map(|k| (crate::Monomial::from_powers(&[(Var::U, k)]), c(k as usize))),
            );
            let b: Poly<Q> = Poly::from_terms((0..30u32).map(|k| {
                (
                    crate::Monomial::from_powers(&[(Var::V, k)]),
                    c(k as usize + 3),
                )
            }));
            let before = cagd_scalar::cancel::work();
            let p = super::product(&a, &b).unwrap();
            let passed = cagd_scalar::cancel::work() - before;
            assert_eq!(p, termwise(&a, &b));
            assert!(passed >= (40 + p.num_terms()) as u64, "{digits}: {passed}");
        }
    }

    /// The independent route: every product of two terms, summed by `Poly::from_terms`.
    fn termwise<S: Scalar>(a: &Poly<S>, b: &Poly<S>) -> Poly<S> {
        Poly::from_terms(
            a.terms()
                .flat_map(|(ma, x)| b.terms().map(move |(mb, y)| (ma.mul(mb), x.mul_ref(y)))),
        )
    }
}
