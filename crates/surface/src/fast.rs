//! The fast exact paths of evaluation, degree elevation and restriction: when every
//! coordinate and parameter is rational, the patch operations are integer matrix products
//! (`cagd_linalg::exact`) with one division per result, the same values as the step-by-step
//! algorithms (which stay as they are for the answers that show their steps, and run for
//! a + b√d and `f64`).
//!
//! - Evaluation, the matrix form (1): `c(u, v) = b_u C b_vᵀ` with the Bernstein numerators
//!   `C(m, i) p^i (q − p)^(m−i)` of u = p/q over `q^m`, and the mesh over the common
//!   denominator of each coordinate.
//! - Elevation (14)-(15) by r and s: `E_r C E_sᵀ` with `(E_r)_{ij} = C(m, j) C(r, i − j) / C(m + r, i)`.
//! - Restriction (13): `R_u C R_vᵀ`, row i of `R` the blossoms `c[a^<m−i>, b^<i>]` of the
//!   Bernstein polynomials, that is the coefficients of x^j in
//!   `((1 − a) + a x)^(m−i) ((1 − b) + b x)^i`.

use crate::{Grid, Mesh};
use cagd_linalg::exact::{
    bernstein_numerators, coordinate_matrix, points_from_integers, IntMatrix,
};
use cagd_linalg::Point;
use cagd_scalar::{BigInt, BigRational, Scalar};
use num_traits::{One, ToPrimitive};

/// The coordinates of a mesh as integer matrices over their common denominators.
pub(crate) type IntegerMesh = Vec<(IntMatrix, BigInt)>;

/// Each coordinate of the mesh as an integer matrix over its common denominator.
pub(crate) fn integer_mesh<S: Scalar>(mesh: &Mesh<S>) -> Option<IntegerMesh> {
    let dim = mesh.get(0, 0).map_or(0, Point::dim);
    let points: Vec<&Point<S>> = mesh.iter().collect();
    (0..dim)
        .map(|k| coordinate_matrix(mesh.rows(), mesh.cols(), points.iter().copied(), k))
        .collect()
}

/// A grid from its points listed row by row.
fn grid<S: Scalar>(rows: usize, cols: usize, points: Vec<Point<S>>) -> Mesh<S> {
    let mut it = points.into_iter();
    Grid::from_fn(rows, cols, |_, _| {
        it.next().unwrap_or_else(|| Point::zero(0))
    })
}

/// c(s, t) at local parameters by the matrix form on integers; `None` unless the mesh and the
/// parameters are rational.
pub(crate) fn eval<S: Scalar>(
    mesh: &Mesh<S>,
    coords: &IntegerMesh,
    s: &S,
    t: &S,
) -> Option<Point<S>> {
    let (bu, du) = bernstein_numerators(mesh.rows() - 1, s)?;
    let (bv, dv) = bernstein_numerators(mesh.cols() - 1, t)?;
    let (nums, dens): (Vec<IntMatrix>, Vec<BigInt>) = coords
        .iter()
        .map(|(n, l)| (bu.mul(n).mul_transpose(&bv), l.clone()))
        .unzip();
    points_from_integers(&nums, &dens, &[du], &[dv]).pop()
}

/// Binomial coefficients C(n, 0..=n).
fn binomials(n: usize) -> Vec<BigInt> {
    let mut row = Vec::with_capacity(n + 1);
    row.push(BigInt::one());
    for k in 1..=n {
        // C(n, k) = C(n, k − 1) (n + 1 − k) / k
        if let Some(previous) = row.last() {
            let next = previous * BigInt::from(n + 1 - k) / BigInt::from(k);
            row.push(next);
        }
    }
    row
}

/// The elevation matrix from degree n to n + r as numerators `C(n, j) C(r, i − j)` over the
/// row denominators `C(n + r, i)`.
fn elevation_matrix(n: usize, r: usize) -> (IntMatrix, Vec<BigInt>) {
    if let Some(small) = small_elevation_matrix(n, r) {
        return small;
    }
    let (bn, br, bnr) = (binomials(n), binomials(r), binomials(n + r));
    let mut data = Vec::with_capacity((n + r + 1) * (n + 1));
    for i in 0..=n + r {
        for (j, bn_j) in bn.iter().enumerate() {
            // C(r, i − j), zero unless 0 <= i − j <= r
            data.push(match i.checked_sub(j).and_then(|d| br.get(d)) {
                Some(br_d) => bn_j * br_d,
                None => BigInt::default(),
            });
        }
    }
    (IntMatrix::from_big(n + r + 1, n + 1, data), bnr)
}

/// C(n, 0), ..., C(n, n) in machine integers, when they fit.
fn small_binomials(n: usize) -> Option<Vec<i128>> {
    let mut row: Vec<i128> = Vec::with_capacity(n + 1);
    row.push(1);
    for k in 1..=n {
        let previous = *row.last()?;
        let (up, down) = (i128::try_from(n + 1 - k).ok()?, i128::try_from(k).ok()?);
        row.push(previous.checked_mul(up)? / down);
    }
    Some(row)
}

/// [`elevation_matrix`] in machine integers (most degrees a teacher meets), else `None`.
fn small_elevation_matrix(n: usize, r: usize) -> Option<(IntMatrix, Vec<BigInt>)> {
    let (bn, br, bnr) = (
        small_binomials(n)?,
        small_binomials(r)?,
        small_binomials(n + r)?,
    );
    let mut data = Vec::with_capacity((n + r + 1) * (n + 1));
    for i in 0..=n + r {
        for (j, &bn_j) in bn.iter().enumerate() {
            data.push(match i.checked_sub(j).and_then(|d| br.get(d)) {
                Some(&br_d) => bn_j.checked_mul(br_d)?,
                None => 0,
            });
        }
    }
    let dens = bnr.into_iter().map(BigInt::from).collect();
    Some((IntMatrix::from_i128(n + r + 1, n + 1, data), dens))
}

/// The mesh elevated by r in u and s in v; `None` unless the mesh is rational.
pub(crate) fn elevate<S: Scalar>(mesh: &Mesh<S>, r: usize, s: usize) -> Option<Mesh<S>> {
    let coords = integer_mesh(mesh)?;
    let (eu, du) = elevation_matrix(mesh.rows() - 1, r);
    let (ev, dv) = elevation_matrix(mesh.cols() - 1, s);
    let (nums, dens): (Vec<IntMatrix>, Vec<BigInt>) = coords
        .into_iter()
        .map(|(n, l)| (eu.mul(&n.mul_transpose(&ev)), l))
        .unzip();
    let points = points_from_integers(&nums, &dens, &du, &dv);
    Some(grid(eu.rows(), ev.rows(), points))
}

/// Coefficients of `(c0 + c1 x)^e`.
fn linear_power(c0: &BigInt, c1: &BigInt, e: usize) -> Vec<BigInt> {
    let mut poly = vec![BigInt::one()];
    for _ in 0..e {
        // next_k = c0 poly_k + c1 poly_{k−1}
        let mut next: Vec<BigInt> = Vec::with_capacity(poly.len() + 1);
        next.extend(poly.iter().map(|c| c * c0));
        next.push(BigInt::default());
        for (x, c) in next.iter_mut().skip(1).zip(&poly) {
            *x += c * c1;
        }
        poly = next;
    }
    poly
}

/// Coefficients of `(c0 + c1 x)^e` in machine integers, when they fit.
fn small_linear_power(c0: i128, c1: i128, e: usize) -> Option<Vec<i128>> {
    let mut poly = vec![1i128];
    for _ in 0..e {
        let mut next: Vec<i128> = Vec::with_capacity(poly.len() + 1);
        for c in &poly {
            next.push(c.checked_mul(c0)?);
        }
        next.push(0);
        for (x, c) in next.iter_mut().skip(1).zip(&poly) {
            *x = x.checked_add(c.checked_mul(c1)?)?;
        }
        poly = next;
    }
    Some(poly)
}

/// [`restriction_matrix`] in machine integers (small parameters and degrees), else `None`.
fn small_restriction_matrix(
    n: usize,
    a: &BigRational,
    b: &BigRational,
) -> Option<(IntMatrix, Vec<BigInt>)> {
    let (pa, qa) = (a.numer().to_i128()?, a.denom().to_i128()?);
    let (pb, qb) = (b.numer().to_i128()?, b.denom().to_i128()?);
    let (ra, rb) = (qa.checked_sub(pa)?, qb.checked_sub(pb)?);
    let mut data = Vec::with_capacity((n + 1) * (n + 1));
    let mut dens = Vec::with_capacity(n + 1);
    for i in 0..=n {
        let left = small_linear_power(ra, pa, n - i)?;
        let right = small_linear_power(rb, pb, i)?;
        let mut row = vec![0i128; n + 1];
        for (k, x) in left.iter().enumerate() {
            for (slot, y) in row.iter_mut().skip(k).zip(&right) {
                *slot = slot.checked_add(x.checked_mul(*y)?)?;
            }
        }
        data.extend(row);
        let e = |k: usize| u32::try_from(k).ok();
        let den = qa
            .checked_pow(e(n - i)?)?
            .checked_mul(qb.checked_pow(e(i)?)?)?;
        dens.push(BigInt::from(den));
    }
    Some((IntMatrix::from_i128(n + 1, n + 1, data), dens))
}

/// The restriction matrix of degree n to [a, b] as numerators over the row denominators
/// `q_a^(n−i) q_b^i`: row i holds the coefficients of
/// `((q_a − p_a) + p_a x)^(n−i) ((q_b − p_b) + p_b x)^i`.
fn restriction_matrix<S: Scalar>(n: usize, a: &S, b: &S) -> Option<(IntMatrix, Vec<BigInt>)> {
    let (a, b) = (a.as_rational()?, b.as_rational()?);
    if let Some(small) = small_restriction_matrix(n, &a, &b) {
        return Some(small);
    }
    let (pa, qa) = (a.numer(), a.denom());
    let (pb, qb) = (b.numer(), b.denom());
    let (ra, rb) = (qa - pa, qb - pb);
    let mut data = Vec::with_capacity((n + 1) * (n + 1));
    let mut dens = Vec::with_capacity(n + 1);
    for i in 0..=n {
        let left = linear_power(&ra, pa, n - i);
        let right = linear_power(&rb, pb, i);
        // the product of the two polynomials: row_{k+l} += left_k right_l
        let mut row = vec![BigInt::default(); n + 1];
        for (k, x) in left.iter().enumerate() {
            for (slot, y) in row.iter_mut().skip(k).zip(&right) {
                *slot += x * y;
            }
        }
        data.extend(row);
        let e = |k: usize| u32::try_from(k).unwrap_or(u32::MAX);
        dens.push(qa.pow(e(n - i)) * qb.pow(e(i)));
    }
    Some((IntMatrix::from_big(n + 1, n + 1, data), dens))
}

/// Both steps of the restriction (13) at local intervals: the rows restricted in v to [c, d]
/// (ĉ), then the columns of ĉ in u to [a, b]; `None` unless mesh and interval ends are
/// rational.
pub(crate) fn restrict<S: Scalar>(
    mesh: &Mesh<S>,
    (a, b): (&S, &S),
    (c, d): (&S, &S),
) -> Option<(Mesh<S>, Mesh<S>)> {
    let (ru, du) = restriction_matrix(mesh.rows() - 1, a, b)?;
    let (rv, dv) = restriction_matrix(mesh.cols() - 1, c, d)?;
    let coords = integer_mesh(mesh)?;
    let ones = vec![BigInt::one(); mesh.rows()];
    let mut rows_nums = Vec::with_capacity(coords.len());
    let mut result_nums = Vec::with_capacity(coords.len());
    let mut dens = Vec::with_capacity(coords.len());
    for (n, l) in coords {
        let hat = n.mul_transpose(&rv);
        result_nums.push(ru.mul(&hat));
        rows_nums.push(hat);
        dens.push(l);
    }
    let rows_step = points_from_integers(&rows_nums, &dens, &ones, &dv);
    let result = points_from_integers(&result_nums, &dens, &du, &dv);
    Some((
        grid(mesh.rows(), mesh.cols(), rows_step),
        grid(mesh.rows(), mesh.cols(), result),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_elevation_matrix_in_machine_integers_is_the_big_one() {
        for (n, r) in [(0, 1), (1, 1), (3, 5), (20, 5), (60, 30)] {
            let small = small_elevation_matrix(n, r).unwrap();
            let (bn, br, bnr) = (binomials(n), binomials(r), binomials(n + r));
            assert_eq!(small.1, bnr);
            for i in 0..=n + r {
                for (j, bn_j) in bn.iter().enumerate() {
                    let big = i
                        .checked_sub(j)
                        .and_then(|d| br.get(d))
                        .map_or_else(BigInt::default, |br_d| bn_j * br_d);
                    assert_eq!(small.0.get(i, j), big, "n = {n}, r = {r}, ({i}, {j})");
                }
            }
        }
        // the restriction matrix likewise, against the big-integer rows
        for (n, a, b) in [
            (3, (1, 3), (3, 4)),
            (10, (1, 5), (1, 2)),
            (40, (2, 9), (7, 8)),
        ] {
            let (a, b) = (
                BigRational::new(a.0.into(), a.1.into()),
                BigRational::new(b.0.into(), b.1.into()),
            );
            let (m, dens) = small_restriction_matrix(n, &a, &b).unwrap();
            for i in 0..=n {
                let left = linear_power(&(a.denom() - a.numer()), a.numer(), n - i);
                let right = linear_power(&(b.denom() - b.numer()), b.numer(), i);
                for j in 0..=n {
                    let big: BigInt = (0..=j)
                        .filter_map(|k| Some(left.get(k)? * right.get(j - k)?))
                        .sum();
                    assert_eq!(m.get(i, j), big, "n = {n}, ({i}, {j})");
                }
                assert_eq!(
                    dens[i],
                    a.denom().pow(u32::try_from(n - i).unwrap())
                        * b.denom().pow(u32::try_from(i).unwrap())
                );
            }
        }
        assert!(small_restriction_matrix(
            200,
            &BigRational::new(1.into(), 3.into()),
            &BigRational::new(3.into(), 4.into())
        )
        .is_none());
        // past i128, the big integers take over
        assert!(small_elevation_matrix(200, 5).is_none());
        assert_eq!(elevation_matrix(200, 5).1, binomials(205));
    }
}
