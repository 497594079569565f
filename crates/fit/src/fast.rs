//! The fast exact paths of surface fitting, used when no intermediate step is asked for and
//! every number is rational; they give the same meshes as the step-by-step functions.
//!
//! **Grid interpolation** (eqs. (26)-(27)), `C = B_U⁻¹ A B_V⁻ᵀ`, with the inverse of the
//! Bernstein collocation matrix written down from its structure (a Bernstein–Vandermonde
//! matrix): column i of `B⁻¹` holds the Bernstein coefficients of the Lagrange polynomial
//! `ℓ_i(u) = Π_{k≠i} (u − u_k)/(u_i − u_k)`. With u_k = p_k/q_k,
//!
//! `u − u_k = ((q_k − p_k) u − p_k (1 − u)) / q_k`,
//!
//! so with `e_ij` the coefficient of `x^j` in `Π_{k≠i} (−p_k + (q_k − p_k) x)` and
//! `W_i = Π_{k≠i} (p_i q_k − p_k q_i)`,
//!
//! `(B⁻¹)_{ji} = q_i^n e_ij / (C(n, j) W_i)`.
//!
//! Both passes are then integer matrix products with one division per control point.
//!
//! **Least squares** (eq. (29)), `BᵗB C = BᵗA`: the rows of B are integers over
//! `D_k = q_k^m s_k^n` (the Bernstein numerators of u_k = p_k/q_k and v_k = r_k/s_k), so with
//! `L = lcm D_k` and the integer rows `β_k = (L/D_k) D_k B_k`, `BᵗB = βᵗβ / L²` and the system is
//! the integer one `(βᵗβ) C = L βᵗ A`, solved by fraction-free elimination
//! ([`cagd_linalg::exact::solve_integer`]).

use cagd_linalg::exact::{
    bernstein_numerators, bernstein_numerators_small, coordinate_matrix, points_from_integers,
    solve_integer, to_scalar, IntMatrix,
};
use cagd_linalg::Point;
use cagd_scalar::gcd::gcd_u128;
use cagd_scalar::{BigInt, Scalar};
use num_traits::{One, Signed, Zero};
use std::collections::BTreeMap;

/// gcd(a, b) ≥ 0 by Lehmer's algorithm (`cagd_scalar::gcd::gcd_lehmer`): the numbers here
/// have thousands of digits, where num-integer's binary gcd is quadratic in bits.
fn gcd(a: &BigInt, b: &BigInt) -> BigInt {
    cagd_scalar::cancel::checkpoint();
    cagd_scalar::gcd::gcd_lehmer(a.magnitude(), b.magnitude())
}

/// lcm(a, b) ≥ 0 (0 when either is 0).
fn lcm(a: &BigInt, b: &BigInt) -> BigInt {
    if a.is_zero() || b.is_zero() {
        return BigInt::zero();
    }
    (a.magnitude() / gcd(a, b).magnitude() * b.magnitude()).into()
}

/// `B⁻¹ = diag(1 / row_den) F` at distinct rational nodes: `F_{ji} = e_ij α_i` on integers,
/// `row_den_j = C(n, j) Λ` (see the module documentation; `q_i^n / W_i = α_i / Λ`).
fn bernstein_inverse<S: Scalar>(nodes: &[S]) -> Option<(IntMatrix, Vec<BigInt>)> {
    let n = nodes.len().checked_sub(1)?;
    let pq: Vec<(BigInt, BigInt)> = nodes
        .iter()
        .map(|u| {
            u.as_rational()
                .map(|q| (q.numer().clone(), q.denom().clone()))
        })
        .collect::<Option<_>>()?;
    let exp = u32::try_from(n).ok()?;
    // e_ij and the factor q_i^n / W_i, reduced with a positive denominator
    let mut e: Vec<Vec<BigInt>> = Vec::with_capacity(n + 1);
    let mut rho: Vec<(BigInt, BigInt)> = Vec::with_capacity(n + 1);
    for (i, (pi, qi)) in pq.iter().enumerate() {
        cagd_scalar::cancel::checkpoint();
        let mut poly = vec![BigInt::one()];
        let mut w = BigInt::one();
        for (k, (pk, qk)) in pq.iter().enumerate() {
            if k == i {
                continue;
            }
            let (c0, c1) = (-pk, qk - pk);
            // poly · (c0 + c1 x): the coefficients times c0, plus those times c1 one place up
            let mut next: Vec<BigInt> = poly.iter().map(|c| c * &c0).collect();
            next.push(BigInt::zero());
            for (slot, c) in next.iter_mut().skip(1).zip(&poly) {
                if !c.is_zero() {
                    *slot += c * &c1;
                }
            }
            poly = next;
            w *= pi * qk - pk * qi;
        }
        if w.is_zero() {
            return None; // two equal nodes: the caller reports it
        }
        let num = qi.pow(exp);
        let g = gcd(&num, &w);
        let (mut a, mut b) = (num / &g, w / &g);
        if b.is_negative() {
            a = -a;
            b = -b;
        }
        e.push(poly);
        rho.push((a, b));
    }
    let lambda = rho.iter().fold(BigInt::one(), |acc, (_, d)| lcm(&acc, d));
    let alpha: Vec<BigInt> = rho.iter().map(|(a, d)| a * (&lambda / d)).collect();
    let mut data = Vec::with_capacity((n + 1) * (n + 1));
    for j in 0..=n {
        // e_i has n + 1 coefficients (a product of n linear factors)
        for (e_i, alpha_i) in e.iter().zip(&alpha) {
            data.push(e_i.get(j).map_or_else(BigInt::zero, |x| x * alpha_i));
        }
    }
    let mut binom = BigInt::one();
    let mut row_den = Vec::with_capacity(n + 1);
    for j in 0..=n {
        if j > 0 {
            binom = binom * BigInt::from(n + 1 - j) / BigInt::from(j);
        }
        row_den.push(&binom * &lambda);
    }
    Some((IntMatrix::from_big(n + 1, n + 1, data), row_den))
}

/// The control points (row by row) of the patch through the grid `data` (rows along u) at
/// distinct local parameters: `C = B_U⁻¹ A B_V⁻ᵀ` on integers. `None` unless everything is
/// rational.
pub(crate) fn interpolate_grid<S: Scalar>(
    u: &[S],
    v: &[S],
    rows: usize,
    cols: usize,
    data: &[&Point<S>],
) -> Option<Vec<Point<S>>> {
    let (fu, du) = bernstein_inverse(u)?;
    // the same nodes in both directions (a square grid at i/n): one inverse
    let (fv, dv) = if u == v {
        (fu.clone(), du.clone())
    } else {
        bernstein_inverse(v)?
    };
    let dim = data.first().map_or(0, |p| p.dim());
    let mut nums = Vec::with_capacity(dim);
    let mut dens = Vec::with_capacity(dim);
    for k in 0..dim {
        let (n, l) = coordinate_matrix(rows, cols, data.iter().copied(), k)?;
        nums.push(fu.mul(&n.mul_transpose(&fv)));
        dens.push(l);
    }
    Some(points_from_integers(&nums, &dens, &du, &dv))
}

/// The least-squares control points c_00, c_01, ..., c_mn (row by row) of eq. (29) on
/// integers; `None` unless everything is rational and BᵗB is nonsingular (the caller then
/// takes the step-by-step path, which names what is wrong).
///
/// The normal equations are one machine-integer product when β is small ([`small_beta`],
/// [`normal_equations_of`]), else summed over the groups of equal D_k
/// ([`grouped_normal_equations`]).
pub(crate) fn least_squares<S: Scalar>(
    m: usize,
    n: usize,
    params: &[(S, S)],
    points: &[Point<S>],
) -> Option<Vec<Point<S>>> {
    let unknowns = (m + 1) * (n + 1);
    let dim = points.first().map_or(0, Point::dim);
    let (data, data_dens) = data_columns(points)?;
    // β straight from machine-integer parameters when it fits, else from the big rows
    let small = small_beta(m, n, params)
        .and_then(|(beta, l)| Some((normal_equations_of(&beta, &data)?, BigInt::from(l))));
    let ((normal, rhs), l) = match small {
        Some(small) => small,
        None => {
            // β past i128 (β_max ≥ L / unknowns, so a β that [`normal_equations_of`] could sum
            // in machine integers has L and every product within i128: [`small_beta`] took it)
            let (rows, dks, l) = integer_rows(m, n, params)?;
            (
                grouped_normal_equations(&rows, &dks, &l, &data, unknowns),
                l,
            )
        }
    };
    // (βᵗβ) Y = βᵗ N with β = diag(L/D_k) D_k B: C = L Y / (Λ det)
    let (y, det) = solve_integer(&normal, &rhs)?;
    let nums: Vec<IntMatrix> = (0..dim)
        .map(|k| {
            IntMatrix::from_big(
                unknowns,
                1,
                (0..unknowns).map(|i| y.get(i, k) * &l).collect(),
            )
        })
        .collect();
    let den: Vec<BigInt> = data_dens.iter().map(|lambda| lambda * &det).collect();
    Some(points_from_integers(
        &nums,
        &den,
        &vec![BigInt::one(); unknowns],
        &[BigInt::one()],
    ))
}

/// The data, one integer column per coordinate over its common denominator Λ.
fn data_columns<S: Scalar>(points: &[Point<S>]) -> Option<(Vec<IntMatrix>, Vec<BigInt>)> {
    let dim = points.first().map_or(0, Point::dim);
    let mut data = Vec::with_capacity(dim);
    let mut data_dens = Vec::with_capacity(dim);
    for k in 0..dim {
        let (a, lambda) = coordinate_matrix(points.len(), 1, points.iter(), k)?;
        data.push(a);
        data_dens.push(lambda);
    }
    Some((data, data_dens))
}

/// The rows of B of eq. (28) on integers: `D_k B_k` (the Bernstein numerators), `D_k` and
/// `L = lcm D_k`.
fn integer_rows<S: Scalar>(
    m: usize,
    n: usize,
    params: &[(S, S)],
) -> Option<(Vec<Vec<BigInt>>, Vec<BigInt>, BigInt)> {
    let unknowns = (m + 1) * (n + 1);
    let mut dks: Vec<BigInt> = Vec::with_capacity(params.len());
    let mut rows: Vec<Vec<BigInt>> = Vec::with_capacity(params.len());
    for (u, v) in params {
        let (bu, du) = bernstein_numerators(m, u)?;
        let (bv, dv) = bernstein_numerators(n, v)?;
        let mut row = Vec::with_capacity(unknowns);
        for i in 0..=m {
            let x = bu.get(0, i);
            for j in 0..=n {
                row.push(&x * bv.get(0, j));
            }
        }
        rows.push(row);
        dks.push(du * dv);
    }
    let l = dks.iter().fold(BigInt::one(), |acc, d| lcm(&acc, d));
    Some((rows, dks, l))
}

/// Rows of a matrix.
pub(crate) type Rows<S> = Vec<Vec<S>>;

/// The first `count` rows of BᵗB and BᵗA of eq. (29) at local parameters, from the integer
/// rows of [`least_squares`]: with `β_k = (L/D_k) D_k B_k = L B_k` and the data `N/Λ`,
///
/// `(BᵗB)_{a,b} = Σ_k β_{k,a} β_{k,b} / L²`,  `(BᵗA)_{a,c} = Σ_k β_{k,a} N_{k,c} / (L Λ_c)`,
///
/// every sum on integers and reduced once. `None` unless everything is rational.
pub(crate) fn normal_equations_rows<S: Scalar>(
    m: usize,
    n: usize,
    params: &[(S, S)],
    points: &[Point<S>],
    count: usize,
) -> Option<[Rows<S>; 2]> {
    let unknowns = (m + 1) * (n + 1);
    let (data, data_dens) = data_columns(points)?;
    let (rows, dks, l) = integer_rows(m, n, params)?;
    let beta: Vec<Vec<BigInt>> = rows
        .iter()
        .zip(&dks)
        .map(|(row, d)| {
            let f = &l / d;
            row.iter().map(|x| x * &f).collect()
        })
        .collect();
    let entry = |a: usize, b: usize| -> BigInt {
        beta.iter()
            .filter_map(|row| Some(row.get(a)? * row.get(b)?))
            .fold(BigInt::zero(), |acc, x| acc + x)
    };
    let l2 = &l * &l;
    let shown = count.min(unknowns);
    let normal = (0..shown)
        .map(|a| {
            cagd_scalar::cancel::checkpoint();
            (0..unknowns).map(|b| to_scalar(entry(a, b), &l2)).collect()
        })
        .collect();
    let rhs = (0..shown)
        .map(|a| {
            data.iter()
                .zip(&data_dens)
                .map(|(column, lambda)| {
                    let sum = beta
                        .iter()
                        .enumerate()
                        .filter_map(|(k, row)| Some(row.get(a)? * column.get(k, 0)))
                        .fold(BigInt::zero(), |acc, x| acc + x);
                    to_scalar(sum, &(&l * lambda))
                })
                .collect()
        })
        .collect();
    Some([normal, rhs])
}

/// β of eq. (29) on machine integers, straight from the parameters: the unknowns × M matrix
/// of `β_k = (L/D_k) D_k B_k`, with `D_k B_k = C(m, i) C(n, j) p^i (q − p)^(m−i) …` the
/// Bernstein numerators at `(u_k, v_k)` and `L = lcm D_k`, and L. `None` when a parameter is
/// not a ratio of machine integers or a product overflows `i128` (then [`integer_rows`]).
fn small_beta<S: Scalar>(m: usize, n: usize, params: &[(S, S)]) -> Option<(IntMatrix, i128)> {
    let unknowns = (m + 1) * (n + 1);
    // D_k B_k, row k at k · unknowns
    let mut rows: Vec<i128> = Vec::with_capacity(unknowns * params.len());
    let mut dks: Vec<i128> = Vec::with_capacity(params.len());
    for (u, v) in params {
        let (pu, qu) = u.as_small_ratio()?;
        let (pv, qv) = v.as_small_ratio()?;
        let (bu, du) = bernstein_numerators_small(m, pu, qu)?;
        let (bv, dv) = bernstein_numerators_small(n, pv, qv)?;
        for x in &bu {
            for y in &bv {
                rows.push(x.checked_mul(*y)?);
            }
        }
        dks.push(du.checked_mul(dv)?);
    }
    let l = dks.iter().try_fold(1i128, |acc, &d| {
        let g = i128::try_from(gcd_u128(acc.unsigned_abs(), d.unsigned_abs())).ok()?;
        (acc / g).checked_mul(d)
    })?;
    let mut beta = Vec::with_capacity(rows.len());
    for i in 0..unknowns {
        for (k, d) in dks.iter().enumerate() {
            let b = *rows.get(k * unknowns + i)?;
            beta.push(b.checked_mul(l.checked_div(*d)?)?);
        }
    }
    Some((IntMatrix::from_i128(unknowns, params.len(), beta), l))
}

/// `(βᵗβ, βᵗN)` in one product each when β (unknowns × M) is small enough for βᵗβ to be summed
/// in machine integers, else `None`.
fn normal_equations_of(beta: &IntMatrix, data: &[IntMatrix]) -> Option<(IntMatrix, IntMatrix)> {
    let sum_bits = u64::BITS - beta.cols().leading_zeros();
    if 2 * beta.max_bits() + u64::from(sum_bits) > 126 {
        return None;
    }
    let values: Vec<BigInt> = data
        .iter()
        .flat_map(|column| (0..column.rows()).map(move |k| column.get(k, 0)))
        .collect();
    let values = IntMatrix::from_big(data.len(), beta.cols(), values);
    Some((beta.mul_transpose(beta), beta.mul_transpose(&values)))
}

/// The bytes of a big integer of `bits` bits: its 32 bytes and its 64-bit words.
fn big_bytes(bits: u64) -> u64 {
    32 + 8 * bits.div_ceil(64)
}

/// States the memory the normal equations `βᵗβ` will hold before they are summed
/// ([`cagd_scalar::cancel::claim`], refused past the problem's memory budget), from a lower
/// bound: every term `(L/D_k)² (D_k B_{k,a}) (D_k B_{k,b})` of an entry is a nonnegative
/// integer (parameters in [0, 1]), and at a point k inside the domain every Bernstein numerator
/// is at least 1, so every entry is at least `(L/D_k)²` for the inner point of least D_k, and
/// the matrix holds unknowns² integers of at least that many bits. Without an inner point,
/// nothing is claimed.
fn claim_normal_equations(rows: &[Vec<BigInt>], dks: &[BigInt], l: &BigInt, unknowns: usize) {
    let inner = rows
        .iter()
        .zip(dks)
        .filter(|(row, d)| d.is_positive() && row.iter().all(Signed::is_positive))
        .map(|(_, d)| d)
        .min();
    let Some(least) = inner.map(|d| l / d) else {
        return;
    };
    let bits = 2 * least.bits().saturating_sub(1) + 1;
    let entries = (unknowns as u64).saturating_mul(unknowns as u64);
    cagd_scalar::cancel::claim(entries.saturating_mul(big_bytes(bits)), || {
        cagd_scalar::cancel::Claimed::NormalEquations {
            unknowns,
            digits: digits(bits),
        }
    });
}

/// The decimal digits a number of `bits` bits has at least (those of 2^(bits − 1)).
fn digits(bits: u64) -> u64 {
    // 0.301029 < log10 2: rounded down, never more digits than 2^(bits - 1) has
    bits.saturating_sub(1).saturating_mul(301_029) / 1_000_000 + 1
}

/// `(βᵗβ, βᵗN)` summed group by group of equal D_k: within a group the rows are small and
/// `Σ β_k β_kᵀ` is summed in machine integers, then scaled by `(L/D)²` once.
fn grouped_normal_equations(
    rows: &[Vec<BigInt>],
    dks: &[BigInt],
    l: &BigInt,
    data: &[IntMatrix],
    unknowns: usize,
) -> (IntMatrix, IntMatrix) {
    let mut groups: BTreeMap<&BigInt, Vec<usize>> = BTreeMap::new();
    for (k, d) in dks.iter().enumerate() {
        groups.entry(d).or_default().push(k);
    }
    let dim = data.len();
    claim_normal_equations(rows, dks, l, unknowns);
    let mut normal = vec![BigInt::zero(); unknowns * unknowns];
    let mut rhs = vec![BigInt::zero(); unknowns * dim];
    for (d, members) in &groups {
        let f = l / *d;
        // the group's rows as columns: unknowns × |group|
        let cols = IntMatrix::from_big(
            unknowns,
            members.len(),
            (0..unknowns)
                .flat_map(|i| {
                    members.iter().map(move |&k| {
                        rows.get(k)
                            .and_then(|r| r.get(i))
                            .cloned()
                            .unwrap_or_else(BigInt::zero)
                    })
                })
                .collect(),
        );
        let gram = cols.mul_transpose(&cols);
        let f2 = &f * &f;
        for i in 0..unknowns {
            cagd_scalar::cancel::checkpoint();
            for j in 0..unknowns {
                let x = gram.get(i, j);
                if let (false, Some(slot)) = (x.is_zero(), normal.get_mut(i * unknowns + j)) {
                    *slot += x * &f2;
                }
            }
        }
        for (c, column) in data.iter().enumerate() {
            let values = IntMatrix::from_big(
                1,
                members.len(),
                members.iter().map(|&k| column.get(k, 0)).collect(),
            );
            let part = cols.mul_transpose(&values);
            for i in 0..unknowns {
                let x = part.get(i, 0);
                if let (false, Some(slot)) = (x.is_zero(), rhs.get_mut(i * dim + c)) {
                    *slot += x * &f;
                }
            }
        }
    }
    (
        IntMatrix::from_big(unknowns, unknowns, normal),
        IntMatrix::from_big(unknowns, dim, rhs),
    )
}
