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
    bernstein_numerators, coordinate_matrix, point_over_bases, points_from_integers, IntMatrix,
};
use cagd_linalg::Point;
use cagd_scalar::{BigInt, BigRational, Scalar};
use num_traits::{CheckedAdd, CheckedDiv, CheckedMul, CheckedSub, One, ToPrimitive, Zero};

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
/// parameters are rational. The longer side is contracted first (`C b_vᵀ` first when the mesh
/// has more columns than rows): its Bernstein numerators, the longest numbers, then meet the
/// mesh's small integers, and only the short side's few products are of two long numbers.
pub(crate) fn eval<S: Scalar>(
    mesh: &Mesh<S>,
    coords: &IntegerMesh,
    s: &S,
    t: &S,
) -> Option<Point<S>> {
    let (bu, du) = bernstein_numerators(mesh.rows() - 1, s)?;
    let (bv, dv) = bernstein_numerators(mesh.cols() - 1, t)?;
    let (nums, dens): (Vec<BigInt>, Vec<BigInt>) = coords
        .iter()
        .map(|(n, l)| {
            let product = if mesh.cols() > mesh.rows() {
                bu.mul(&n.mul_transpose(&bv))
            } else {
                bu.mul(n).mul_transpose(&bv)
            };
            (product.get(0, 0), l.clone())
        })
        .unzip();
    // reduced over the parameters' denominators q_u, q_v and the mesh's: linear in the length
    // of the numerators, where a gcd with q_u^m q_v^n L is quadratic
    let bases = [
        s.as_rational()?.denom().clone(),
        t.as_rational()?.denom().clone(),
    ];
    Some(point_over_bases(nums, &(du * dv), &dens, &bases))
}

/// The integers the elevation and restriction matrices are built in: machine integers,
/// checked (`None` on overflow, most degrees a teacher meets fit), or big integers (never
/// `None`).
trait Int: Clone + Zero + One + CheckedAdd + CheckedSub + CheckedMul + CheckedDiv {
    fn from_usize(k: usize) -> Option<Self>;
    fn from_big(n: &BigInt) -> Option<Self>;
    fn to_big(&self) -> BigInt;
    fn matrix(rows: usize, cols: usize, data: Vec<Self>) -> IntMatrix;
}

impl Int for i128 {
    fn from_usize(k: usize) -> Option<Self> {
        i128::try_from(k).ok()
    }
    fn from_big(n: &BigInt) -> Option<Self> {
        n.to_i128()
    }
    fn to_big(&self) -> BigInt {
        BigInt::from(*self)
    }
    fn matrix(rows: usize, cols: usize, data: Vec<Self>) -> IntMatrix {
        IntMatrix::from_i128(rows, cols, data)
    }
}

impl Int for BigInt {
    fn from_usize(k: usize) -> Option<Self> {
        Some(BigInt::from(k))
    }
    fn from_big(n: &BigInt) -> Option<Self> {
        Some(n.clone())
    }
    fn to_big(&self) -> BigInt {
        self.clone()
    }
    fn matrix(rows: usize, cols: usize, data: Vec<Self>) -> IntMatrix {
        IntMatrix::from_big(rows, cols, data)
    }
}

/// `x^e` by repeated products.
fn power<T: Int>(x: &T, e: usize) -> Option<T> {
    (0..e).try_fold(T::one(), |acc, _| acc.checked_mul(x))
}

/// Binomial coefficients C(n, 0..=n).
fn binomials<T: Int>(n: usize) -> Option<Vec<T>> {
    let mut row = Vec::with_capacity(n + 1);
    row.push(T::one());
    for k in 1..=n {
        // C(n, k) = C(n, k − 1) (n + 1 − k) / k
        let previous = row.last()?;
        let next = previous
            .checked_mul(&T::from_usize(n + 1 - k)?)?
            .checked_div(&T::from_usize(k)?)?;
        row.push(next);
    }
    Some(row)
}

/// The elevation matrix from degree n to n + r as numerators `C(n, j) C(r, i − j)` over the
/// row denominators `C(n + r, i)`, in machine integers when they fit.
fn elevation_matrix(n: usize, r: usize) -> Option<(IntMatrix, Vec<BigInt>)> {
    elevation_matrix_in::<i128>(n, r).or_else(|| elevation_matrix_in::<BigInt>(n, r))
}

/// [`elevation_matrix`] in the integers `T`.
fn elevation_matrix_in<T: Int>(n: usize, r: usize) -> Option<(IntMatrix, Vec<BigInt>)> {
    let (bn, br, bnr) = (
        binomials::<T>(n)?,
        binomials::<T>(r)?,
        binomials::<T>(n + r)?,
    );
    let mut data = Vec::with_capacity((n + r + 1) * (n + 1));
    for i in 0..=n + r {
        for (j, bn_j) in bn.iter().enumerate() {
            // C(r, i − j), zero unless 0 <= i − j <= r
            data.push(match i.checked_sub(j).and_then(|d| br.get(d)) {
                Some(br_d) => bn_j.checked_mul(br_d)?,
                None => T::zero(),
            });
        }
    }
    let dens = bnr.iter().map(T::to_big).collect();
    Some((T::matrix(n + r + 1, n + 1, data), dens))
}

/// The mesh elevated by r in u and s in v; `None` unless the mesh is rational.
pub(crate) fn elevate<S: Scalar>(mesh: &Mesh<S>, r: usize, s: usize) -> Option<Mesh<S>> {
    let coords = integer_mesh(mesh)?;
    let (eu, du) = elevation_matrix(mesh.rows() - 1, r)?;
    // a square mesh elevated alike in u and v has one matrix for both
    let v_matrix = if (mesh.cols(), s) == (mesh.rows(), r) {
        None
    } else {
        Some(elevation_matrix(mesh.cols() - 1, s)?)
    };
    let (ev, dv) = v_matrix.as_ref().map_or((&eu, &du), |(m, d)| (m, d));
    let (nums, dens): (Vec<IntMatrix>, Vec<BigInt>) = coords
        .into_iter()
        .map(|(n, l)| (eu.mul(&n.mul_transpose(ev)), l))
        .unzip();
    let points = points_from_integers(&nums, &dens, &du, dv);
    Some(grid(eu.rows(), ev.rows(), points))
}

/// Coefficients of `(c0 + c1 x)^e`.
fn linear_power<T: Int>(c0: &T, c1: &T, e: usize) -> Option<Vec<T>> {
    let mut poly = vec![T::one()];
    for _ in 0..e {
        // next_k = c0 poly_k + c1 poly_{k−1}
        let mut next: Vec<T> = Vec::with_capacity(poly.len() + 1);
        for c in &poly {
            next.push(c.checked_mul(c0)?);
        }
        next.push(T::zero());
        for (x, c) in next.iter_mut().skip(1).zip(&poly) {
            *x = x.checked_add(&c.checked_mul(c1)?)?;
        }
        poly = next;
    }
    Some(poly)
}

/// The restriction matrix of degree n to [a, b] as numerators over the row denominators
/// `q_a^(n−i) q_b^i`: row i holds the coefficients of
/// `((q_a − p_a) + p_a x)^(n−i) ((q_b − p_b) + p_b x)^i`, in machine integers when they fit.
fn restriction_matrix<S: Scalar>(n: usize, a: &S, b: &S) -> Option<(IntMatrix, Vec<BigInt>)> {
    let (a, b) = (a.as_rational()?, b.as_rational()?);
    restriction_matrix_in::<i128>(n, &a, &b).or_else(|| restriction_matrix_in::<BigInt>(n, &a, &b))
}

/// [`restriction_matrix`] in the integers `T`.
fn restriction_matrix_in<T: Int>(
    n: usize,
    a: &BigRational,
    b: &BigRational,
) -> Option<(IntMatrix, Vec<BigInt>)> {
    let (pa, qa) = (T::from_big(a.numer())?, T::from_big(a.denom())?);
    let (pb, qb) = (T::from_big(b.numer())?, T::from_big(b.denom())?);
    let (ra, rb) = (qa.checked_sub(&pa)?, qb.checked_sub(&pb)?);
    let mut data = Vec::with_capacity((n + 1) * (n + 1));
    let mut dens = Vec::with_capacity(n + 1);
    for i in 0..=n {
        let left = linear_power(&ra, &pa, n - i)?;
        let right = linear_power(&rb, &pb, i)?;
        // the product of the two polynomials: row_{k+l} += left_k right_l
        let mut row = vec![T::zero(); n + 1];
        for (k, x) in left.iter().enumerate() {
            for (slot, y) in row.iter_mut().skip(k).zip(&right) {
                *slot = slot.checked_add(&x.checked_mul(y)?)?;
            }
        }
        data.extend(row);
        let den = power(&qa, n - i)?.checked_mul(&power(&qb, i)?)?;
        dens.push(den.to_big());
    }
    Some((T::matrix(n + 1, n + 1, data), dens))
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
        let entries = |m: &IntMatrix| -> Vec<BigInt> {
            (0..m.rows())
                .flat_map(|i| (0..m.cols()).map(move |j| (i, j)))
                .map(|(i, j)| m.get(i, j))
                .collect()
        };
        for (n, r) in [(0, 1), (1, 1), (3, 5), (20, 5), (60, 30)] {
            let small = elevation_matrix_in::<i128>(n, r).unwrap();
            let big = elevation_matrix_in::<BigInt>(n, r).unwrap();
            assert_eq!(small.1, big.1);
            assert_eq!(small.1, binomials::<BigInt>(n + r).unwrap());
            assert_eq!(entries(&small.0), entries(&big.0), "n = {n}, r = {r}");
            // C(n, j) C(r, i − j), e.g. at i = j = n: C(n, n) C(r, 0) = 1
            assert_eq!(small.0.get(n, n), BigInt::one());
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
            let (m, dens) = restriction_matrix_in::<i128>(n, &a, &b).unwrap();
            let (big, big_dens) = restriction_matrix_in::<BigInt>(n, &a, &b).unwrap();
            assert_eq!(entries(&m), entries(&big), "n = {n}");
            for (i, den) in dens.iter().enumerate() {
                assert_eq!(
                    *den,
                    a.denom().pow(u32::try_from(n - i).unwrap())
                        * b.denom().pow(u32::try_from(i).unwrap())
                );
            }
            assert_eq!(dens, big_dens);
        }
        assert!(restriction_matrix_in::<i128>(
            200,
            &BigRational::new(1.into(), 3.into()),
            &BigRational::new(3.into(), 4.into())
        )
        .is_none());
        // past i128, the big integers take over
        assert!(elevation_matrix_in::<i128>(200, 5).is_none());
        assert_eq!(
            elevation_matrix(200, 5).unwrap().1,
            binomials::<BigInt>(205).unwrap()
        );
    }
}
