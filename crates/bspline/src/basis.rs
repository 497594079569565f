//! The B-spline basis functions N_i^p and their derivatives.

use crate::checked::{at, at_mut};
use crate::knots::scalar_of;
use crate::{BSplineError, KnotVector};
use cagd_scalar::Scalar;

/// `num / den` for a knot difference `den` that is positive by the validity of the knot
/// vector and the span; an error instead of a panic should that ever fail.
pub(crate) fn div_knots<S: Scalar>(num: &S, den: &S, span: usize) -> Result<S, BSplineError> {
    num.checked_div(den)
        .ok_or(BSplineError::InvalidSpan { span })
}

/// The nonzero basis functions of every degree q = 0, ..., p at the span k:
/// `rows[q][j] = N_{k-q+j}^q(t)` for j = 0, ..., q (Piegl and Tiller, A2.2, keeping each row).
///
/// Cox–de Boor recursion (full convention):
/// `N_i^q(t) = (t - u_i)/(u_{i+q} - u_i) N_i^{q-1}(t) + (u_{i+q+1} - t)/(u_{i+q+1} - u_{i+1}) N_{i+1}^{q-1}(t)`.
pub(crate) fn basis_triangle<S: Scalar>(
    knots: &KnotVector<S>,
    span: usize,
    t: &S,
) -> Result<Vec<Vec<S>>, BSplineError> {
    knots.check_span(span)?;
    let u = knots.full();
    let p = knots.degree();
    let mut rows: Vec<Vec<S>> = vec![vec![S::one()]];
    let mut left = vec![S::zero(); p + 1];
    let mut right = vec![S::zero(); p + 1];
    for j in 1..=p {
        // span >= p >= j (checked above), so span + 1 - j does not underflow
        *at_mut(&mut left, j, span)? = t.sub_ref(at(u, span + 1 - j, span)?);
        *at_mut(&mut right, j, span)? = at(u, span + j, span)?.sub_ref(t);
        let prev = rows.last().ok_or(BSplineError::InvalidSpan { span })?;
        let mut row = Vec::with_capacity(j + 1);
        let mut saved = S::zero();
        for (r, n) in prev.iter().enumerate().take(j) {
            let (right_r, left_jr) = (at(&right, r + 1, span)?, at(&left, j - r, span)?);
            let temp = div_knots(n, &right_r.add_ref(left_jr), span)?;
            row.push(saved + right_r.mul_ref(&temp));
            saved = left_jr.mul_ref(&temp);
        }
        row.push(saved);
        rows.push(row);
    }
    Ok(rows)
}

/// The p + 1 basis functions that may be nonzero on the span k (full convention, see
/// [`KnotVector::find_span`]): `N_{k-p}^p(t), ..., N_k^p(t)` (Piegl and Tiller, A2.2). They are
/// non-negative on the span and sum to 1.
///
/// ```
/// use cagd_bspline::{basis_functions, KnotVector};
/// use cagd_scalar::{q, BigRational, Print};
/// let u = KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap();
/// let k = u.find_span(&q!(1/2)).unwrap();
/// let n: Vec<String> = basis_functions(&u, k, &q!(1/2)).unwrap().iter().map(|x| x.to_text()).collect();
/// assert_eq!(n, ["1/4", "5/8", "1/8"]);
/// ```
pub fn basis_functions<S: Scalar>(
    knots: &KnotVector<S>,
    span: usize,
    t: &S,
) -> Result<Vec<S>, BSplineError> {
    let mut rows = basis_triangle(knots, span, t)?;
    Ok(rows.pop().unwrap_or_default())
}

/// The nonzero basis functions at a parameter of the domain: the index of the first one
/// (k - p, also the first control point acting there) and the values
/// `N_{k-p}^p(t), ..., N_k^p(t)`.
pub fn basis_functions_at<S: Scalar>(
    knots: &KnotVector<S>,
    t: &S,
) -> Result<(usize, Vec<S>), BSplineError> {
    let k = knots.find_span(t)?;
    Ok((k - knots.degree(), basis_functions(knots, k, t)?))
}

/// One basis function `N_i^p(t)` at a parameter of the domain (0 outside its support
/// `[u_i, u_{i+p+1})`, full convention). At the right end of the domain the last span is used,
/// so the functions stay a partition of unity there.
///
/// ```
/// use cagd_bspline::{basis_function, KnotVector};
/// use cagd_scalar::q;
/// let u = KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap();
/// assert_eq!(basis_function(&u, 1, &q!(1)).unwrap(), q!(1/2));
/// assert_eq!(basis_function(&u, 3, &q!(1/2)).unwrap(), q!(0));
/// assert_eq!(basis_function(&u, 3, &q!(2)).unwrap(), q!(1));
/// ```
pub fn basis_function<S: Scalar>(
    knots: &KnotVector<S>,
    i: usize,
    t: &S,
) -> Result<S, BSplineError> {
    let (first, values) = basis_functions_at(knots, t)?;
    Ok(i.checked_sub(first)
        .and_then(|j| values.get(j).cloned())
        .unwrap_or_else(S::zero))
}

/// The derivatives of orders 0, ..., `order` of the nonzero basis functions on the span k:
/// `ders[m][j] = (d/dt)^m N_{k-p+j}^p(t)` (Piegl and Tiller, eq. 2.9–2.10). Orders above p are
/// zero.
///
/// `(N_i^p)^(m) = p!/(p-m)! Σ_{j=0}^{m} a_{m,j} N_{i+j}^{p-m}`, with `a_{0,0} = 1`,
/// `a_{m,0} = a_{m-1,0}/(u_{i+p-m+1} - u_i)`,
/// `a_{m,j} = (a_{m-1,j} - a_{m-1,j-1})/(u_{i+p+j-m+1} - u_{i+j})`,
/// `a_{m,m} = -a_{m-1,m-1}/(u_{i+p+1} - u_{i+m})`, a quotient by a zero knot difference being 0.
///
/// ```
/// use cagd_bspline::{basis_derivatives, KnotVector};
/// use cagd_scalar::q;
/// let u = KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap();
/// let k = u.find_span(&q!(1/2)).unwrap();
/// let d = basis_derivatives(&u, k, &q!(1/2), 2).unwrap();
/// assert_eq!(d[1], vec![q!(-1), q!(1/2), q!(1/2)]);
/// assert_eq!(d[2], vec![q!(2), q!(-3), q!(1)]);
/// ```
pub fn basis_derivatives<S: Scalar>(
    knots: &KnotVector<S>,
    span: usize,
    t: &S,
    order: usize,
) -> Result<Vec<Vec<S>>, BSplineError> {
    let rows = basis_triangle(knots, span, t)?;
    let u = knots.full();
    let p = knots.degree();
    let mut ders = vec![vec![S::zero(); p + 1]; order + 1];
    *at_mut(&mut ders, 0, span)? = at(&rows, p, span)?.clone();
    for (j, column) in (0..=p).map(|j| (j, span - p + j)) {
        // column = i, the index of N_i^p.
        let i = column;
        let mut a = vec![S::one()];
        let mut factor = S::one();
        for m in 1..=order.min(p) {
            let mut next = Vec::with_capacity(m + 1);
            for jj in 0..=m {
                let lo = at(u, i + jj, span)?.clone();
                let hi = at(u, i + p + jj + 1 - m, span)?.clone();
                let diff = hi.sub_ref(&lo);
                let num = match (jj.checked_sub(1).and_then(|l| a.get(l)), a.get(jj)) {
                    (Some(prev), Some(cur)) => cur.sub_ref(prev),
                    (Some(prev), None) => -prev.clone(),
                    (None, Some(cur)) => cur.clone(),
                    (None, None) => S::zero(),
                };
                next.push(num.checked_div(&diff).unwrap_or_else(S::zero));
            }
            a = next;
            factor *= scalar_of::<S>(p - m + 1);
            // Σ_j a_{m,j} N_{i+j}^{p-m}(t), reading N from the row of degree p - m.
            let q = p - m;
            let row = at(&rows, q, span)?;
            let mut sum = S::zero();
            for (jj, coef) in a.iter().enumerate() {
                // N_{i+jj}^q sits at position (i + jj) - (span - q) of its row.
                if let Some(pos) = (i + jj + q).checked_sub(span) {
                    if let Some(n) = row.get(pos) {
                        sum += coef.mul_ref(n);
                    }
                }
            }
            *at_mut(&mut ders, m, span).and_then(|d| at_mut(d, j, span))? = sum * &factor;
        }
    }
    Ok(ders)
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, BigRational};

    #[test]
    fn quadratic_basis_on_the_circle_knots() {
        let u: KnotVector<BigRational> = KnotVector::from_notes(
            vec![
                q!(0),
                q!(0),
                q!(1),
                q!(1),
                q!(2),
                q!(2),
                q!(3),
                q!(3),
                q!(4),
                q!(4),
            ],
            2,
        )
        .unwrap();
        // Inside [0, 1] the three functions are the Bernstein polynomials of degree 2.
        let (first, n) = basis_functions_at(&u, &q!(1 / 2)).unwrap();
        assert_eq!(first, 0);
        assert_eq!(n, vec![q!(1 / 4), q!(1 / 2), q!(1 / 4)]);
        // At the double knot 1 only N_2 is nonzero.
        let (first, n) = basis_functions_at(&u, &q!(1)).unwrap();
        assert_eq!(first, 2);
        assert_eq!(n, vec![q!(1), q!(0), q!(0)]);
        assert_eq!(basis_function(&u, 8, &q!(4)).unwrap(), q!(1));
        assert!(basis_functions(&u, 3, &q!(1)).is_err()); // empty span [1, 1]
    }

    #[test]
    fn uniform_cubic_derivatives() {
        // Uniform cubic knots: N at an integer knot is (1/6, 2/3, 1/6, 0), N' = (-1/2, 0, 1/2, 0),
        // N'' = (1, -2, 1, 0), N''' = (-1, 3, -3, 1).
        let u: KnotVector<BigRational> = KnotVector::from_notes(
            (0..9)
                .map(|k| BigRational::from_integer(k.into()))
                .collect(),
            3,
        )
        .unwrap();
        let k = u.find_span(&q!(4)).unwrap();
        assert_eq!(k, 5);
        let d = basis_derivatives(&u, k, &q!(4), 4).unwrap();
        assert_eq!(d[0], vec![q!(1 / 6), q!(2 / 3), q!(1 / 6), q!(0)]);
        assert_eq!(d[1], vec![q!(-1 / 2), q!(0), q!(1 / 2), q!(0)]);
        assert_eq!(d[2], vec![q!(1), q!(-2), q!(1), q!(0)]);
        assert_eq!(d[3], vec![q!(-1), q!(3), q!(-3), q!(1)]);
        assert_eq!(d[4], vec![q!(0); 4]);
    }
}
