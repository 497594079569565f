//! The fast exact path of the change from the Bernstein to the monomial basis in two variables:
//! when every coefficient is rational, `A = M_m C M_nᵀ` on integer numerators (one division
//! per coefficient), with the integer matrix
//! `(M_n)_{k,i} = (−1)^(k−i) C(n, k) C(k, i)` of `a_k = C(n, k) Σ_{i ≤ k} (−1)^(k−i) C(k, i) c_i`.

use crate::{Monomial, Poly, Var};
use cagd_linalg::exact::{common_denominator, common_denominator_big, ratio, IntMatrix};
use cagd_scalar::{BigInt, Scalar};
use num_traits::Zero;

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

/// `Σ_i Σ_j c_ij B_i^m(var_u) B_j^n(var_v)` on integers; `None` unless every coefficient is
/// rational. The grid is a non-empty rectangle (checked by the caller).
pub(crate) fn poly_from_bernstein_2d<S: Scalar>(
    grid: &[Vec<S>],
    var_u: Var,
    var_v: Var,
) -> Option<Poly<S>> {
    let rows = grid.len();
    let cols = grid.first().map_or(0, Vec::len);
    let values = grid.iter().flatten();
    let (num, den) = match common_denominator(values.clone()) {
        Some((num, den)) => (IntMatrix::from_i128(rows, cols, num), BigInt::from(den)),
        None => {
            let c = common_denominator_big(values)?;
            (IntMatrix::from_big(rows, cols, c.num), c.den)
        }
    };
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
    use crate::{bernstein, poly_from_bernstein_2d, Poly, Var};
    use cagd_scalar::{BigRational, FieldOps, Quadratic, Scalar};
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
    }
}
