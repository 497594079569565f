//! Exact solution of square linear systems: a factorization computed once and reused for many
//! right-hand sides (scalars, points, matrices).

use crate::bareiss::{as_rational, IntegerLu};
use crate::{LinalgError, Matrix, Operands, Point, Singularity};
use cagd_scalar::Scalar;

/// How a [`Factorization`] eliminates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Elimination {
    /// Fraction-free when every entry is rational and the scalar is exact, Gauss otherwise.
    Auto,
    /// Gaussian elimination in the scalar type: the first nonzero pivot of each column for the
    /// exact types, the largest one (partial pivoting) for `f64`.
    Gauss,
    /// Bareiss' fraction-free elimination on the integer numerators of the rows (rational
    /// matrices only; any other matrix falls back to [`Elimination::Gauss`]).
    FractionFree,
}

/// A factorization P A = L U of a square matrix, for solving A x = b with many right-hand sides.
///
/// For a rational matrix it is Bareiss' fraction-free form of the same elimination on the
/// integer rows of diag(r) A ([`Elimination::FractionFree`]); otherwise Gaussian elimination
/// in the scalar type ([`Elimination::Gauss`]). Both give the same exact answers.
///
/// Row operations are done once, in [`Factorization::new`]; each solve is then a forward and a
/// back substitution, O(n²). This is how the interpolation problems of the notes (chapter 5,
/// eq. (27), "tres sistemas lineales, uno por cada coordenada") solve the x, y and z systems at
/// once: [`Factorization::solve_points`].
///
/// ```
/// use cagd_linalg::{Factorization, Matrix, Point};
/// use cagd_scalar::{q, BigRational};
/// // B_U of the notes' bidegree (2, 3) example: B_j^2(u_i) at u = 0, 1/2, 1.
/// let b: Matrix<BigRational> = Matrix::from_rows(vec![
///     vec![q!(1), q!(0), q!(0)],
///     vec![q!(1/4), q!(1/2), q!(1/4)],
///     vec![q!(0), q!(0), q!(1)],
/// ]).unwrap();
/// let lu = Factorization::new(&b).unwrap();
/// let data = [Point::from_ints(&[0, 0, 0]), Point::from_ints(&[0, 1, 1]), Point::from_ints(&[0, 2, 0])];
/// let c = lu.solve_points(&data).unwrap();
/// let text: Vec<String> = c.iter().map(|p| p.to_text()).collect();
/// assert_eq!(text, ["(0, 0, 0)", "(0, 1, 2)", "(0, 2, 0)"]);
/// assert_eq!(lu.determinant().to_string(), "1/2");
/// ```
#[derive(Clone, Debug)]
pub struct Factorization<S> {
    n: usize,
    kind: Kind<S>,
}

#[derive(Clone, Debug)]
enum Kind<S> {
    /// Doolittle form in one array: the multipliers l_ik below the diagonal, U on and above.
    Gauss {
        lu: Vec<Vec<S>>,
        perm: Vec<usize>,
        odd: bool,
    },
    FractionFree(IntegerLu),
}

/// The error of a column without a pivot.
pub(crate) fn no_pivot(k: usize) -> LinalgError {
    LinalgError::Singular {
        detail: Singularity::NoPivot { column: k },
    }
}

fn abs<S: Scalar>(x: &S) -> S {
    if *x < S::zero() {
        -x.clone()
    } else {
        x.clone()
    }
}

fn check_square<S: Scalar>(a: &Matrix<S>) -> Result<(), LinalgError> {
    if a.rows() == a.cols() {
        Ok(())
    } else {
        Err(LinalgError::DimensionMismatch {
            what: Operands::Square {
                rows: a.rows(),
                cols: a.cols(),
            },
            expected: a.rows(),
            found: a.cols(),
        })
    }
}

impl<S: Scalar> Factorization<S> {
    /// Factors a square matrix with [`Elimination::Auto`]; an error when it is not square or is
    /// singular (naming the first column without a pivot).
    pub fn new(a: &Matrix<S>) -> Result<Self, LinalgError> {
        Self::with_method(a, Elimination::Auto)
    }

    /// Factors a square matrix with the given elimination.
    pub fn with_method(a: &Matrix<S>, method: Elimination) -> Result<Self, LinalgError> {
        check_square(a)?;
        let n = a.rows();
        if method != Elimination::Gauss {
            let rational: Option<Vec<Vec<_>>> = (0..n)
                .map(|i| a.row(i).iter().map(as_rational).collect())
                .collect();
            if let Some(rows) = rational {
                return Ok(Factorization {
                    n,
                    kind: Kind::FractionFree(IntegerLu::new(&rows)?),
                });
            }
        }
        Ok(Factorization { n, kind: gauss(a)? })
    }

    /// The order n of the matrix.
    pub fn order(&self) -> usize {
        self.n
    }

    /// The elimination that was used: [`Elimination::Gauss`] or [`Elimination::FractionFree`].
    pub fn method(&self) -> Elimination {
        match self.kind {
            Kind::Gauss { .. } => Elimination::Gauss,
            Kind::FractionFree(_) => Elimination::FractionFree,
        }
    }

    /// det A = (−1)^s u_00 u_11 ⋯ u_{n−1,n−1}, s the number of row swaps.
    pub fn determinant(&self) -> S {
        match &self.kind {
            Kind::Gauss { lu, odd, .. } => {
                let d = lu
                    .iter()
                    .enumerate()
                    .filter_map(|(k, row)| row.get(k))
                    .fold(S::one(), |acc, u_kk| acc * u_kk);
                if *odd {
                    -d
                } else {
                    d
                }
            }
            Kind::FractionFree(f) => S::from_rational(&f.determinant()),
        }
    }

    /// The solution x of A x = b.
    pub fn solve(&self, b: &[S]) -> Result<Vec<S>, LinalgError> {
        if b.len() != self.n {
            return Err(self.rhs_mismatch(b.len()));
        }
        self.solve_column(b)
            .ok_or_else(|| self.rhs_mismatch(b.len()))
    }

    /// The error of a right-hand side without one entry per row.
    fn rhs_mismatch(&self, found: usize) -> LinalgError {
        LinalgError::DimensionMismatch {
            what: Operands::RightHandSide,
            expected: self.n,
            found,
        }
    }

    /// The points x_0, ..., x_{n−1} with Σ_j a_ij x_j = b_i: one system per coordinate, all
    /// solved with this one factorization.
    pub fn solve_points(&self, b: &[Point<S>]) -> Result<Vec<Point<S>>, LinalgError> {
        if b.len() != self.n {
            return Err(LinalgError::DimensionMismatch {
                what: Operands::RightHandPoints,
                expected: self.n,
                found: b.len(),
            });
        }
        let dim = b.first().map_or(0, Point::dim);
        for (i, p) in b.iter().enumerate() {
            if p.dim() != dim {
                return Err(LinalgError::DimensionMismatch {
                    what: Operands::RightHandPoint { index: i },
                    expected: dim,
                    found: p.dim(),
                });
            }
        }
        let columns: Vec<Vec<S>> = (0..dim)
            .map(|c| {
                let column: Vec<S> = b
                    .iter()
                    .filter_map(|p| p.coords().get(c))
                    .cloned()
                    .collect();
                self.solve_column(&column)
                    .ok_or_else(|| self.rhs_mismatch(column.len()))
            })
            .collect::<Result<_, _>>()?;
        Ok((0..self.n)
            .map(|i| {
                Point::new(
                    columns
                        .iter()
                        .filter_map(|col| col.get(i))
                        .cloned()
                        .collect(),
                )
            })
            .collect())
    }

    /// The matrix X with A X = B, column by column.
    pub fn solve_matrix(&self, b: &Matrix<S>) -> Result<Matrix<S>, LinalgError> {
        if b.rows() != self.n {
            return Err(LinalgError::DimensionMismatch {
                what: Operands::RightHandRows,
                expected: self.n,
                found: b.rows(),
            });
        }
        let columns: Vec<Vec<S>> = (0..b.cols())
            .map(|j| {
                let column: Vec<S> = (0..b.rows()).map(|i| b.get(i, j).clone()).collect();
                self.solve_column(&column)
                    .ok_or_else(|| self.rhs_mismatch(column.len()))
            })
            .collect::<Result<_, _>>()?;
        Ok(Matrix::from_fn(self.n, b.cols(), |i, j| {
            entry_of_columns(&columns, i, j)
        }))
    }

    /// A⁻¹, solving A X = I.
    pub fn inverse(&self) -> Matrix<S> {
        let columns: Vec<Vec<S>> = (0..self.n)
            .map(|j| {
                let e: Vec<S> = (0..self.n)
                    .map(|i| if i == j { S::one() } else { S::zero() })
                    .collect();
                // e_j has n entries, so this solve cannot fail
                self.solve_column(&e).unwrap_or_default()
            })
            .collect();
        Matrix::from_fn(self.n, self.n, |i, j| entry_of_columns(&columns, i, j))
    }

    /// Solves one column; `None` when it has fewer than n entries.
    fn solve_column(&self, b: &[S]) -> Option<Vec<S>> {
        match &self.kind {
            Kind::Gauss { lu, perm, .. } => substitute(lu, perm, b),
            Kind::FractionFree(f) => {
                let rational: Option<Vec<_>> = b.iter().map(as_rational).collect();
                match rational {
                    Some(q) => Some(
                        f.solve_rational(&q)?
                            .into_iter()
                            .map(S::from_rational_owned)
                            .collect(),
                    ),
                    None => f.solve_field(b),
                }
            }
        }
    }
}

/// Entry (i, j) of the matrix with these columns (each solved column has n entries).
fn entry_of_columns<S: Scalar>(columns: &[Vec<S>], i: usize, j: usize) -> S {
    columns
        .get(j)
        .and_then(|column| column.get(i))
        .cloned()
        .unwrap_or_else(S::zero)
}

/// Gaussian elimination P A = L U in `S`.
///
/// Exact types take the first nonzero pivot of the column; `f64` takes the largest in absolute
/// value and treats a pivot below n · 2⁻⁴⁰ · max |a_ij| as zero.
fn gauss<S: Scalar>(a: &Matrix<S>) -> Result<Kind<S>, LinalgError> {
    let n = a.rows();
    let mut lu = a.to_rows();
    let mut perm: Vec<usize> = (0..n).collect();
    let mut odd = false;
    let exact = S::is_exact();
    let tolerance = if exact {
        S::zero()
    } else {
        let largest = lu
            .iter()
            .flatten()
            .map(abs)
            .fold(S::zero(), |m, x| if x > m { x } else { m });
        largest * S::from_i64(n as i64) * S::from_ratio(1, 1 << 40)
    };
    // rows k.. of lu, still to eliminate: `rest[0]` is row k
    let mut rest: &mut [Vec<S>] = &mut lu;
    for k in 0..n {
        // the candidates a_ik, i >= k, with i counted from k
        let column = rest
            .iter()
            .enumerate()
            .filter_map(|(i, row)| Some((i, row.get(k)?)));
        let p = if exact {
            column.filter(|(_, a)| !a.is_zero()).map(|(i, _)| i).next()
        } else {
            column
                .map(|(i, a)| (i, abs(a)))
                .filter(|(_, a)| *a > tolerance)
                .fold(None, |best: Option<(usize, S)>, (i, a)| match best {
                    Some((b, largest)) if largest >= a => Some((b, largest)),
                    _ => Some((i, a)),
                })
                .map(|(i, _)| i)
        };
        let p = p.ok_or_else(|| no_pivot(k))?;
        if p != 0 {
            rest.swap(0, p);
            perm.swap(k, k + p);
            odd = !odd;
        }
        let (pivot_row, bottom) = std::mem::take(&mut rest)
            .split_first_mut()
            .ok_or_else(|| no_pivot(k))?;
        // the pivot u_kk and the rest of its row, u_kj for j > k
        let (pivot, pivot_tail) = pivot_row
            .get(k..)
            .and_then(<[S]>::split_first)
            .ok_or_else(|| no_pivot(k))?;
        for row in bottom.iter_mut() {
            let Some((a_ik, tail)) = row.get_mut(k..).and_then(<[S]>::split_first_mut) else {
                continue;
            };
            if a_ik.is_zero() {
                continue;
            }
            let l = a_ik.clone() / pivot;
            for (a_ij, u_kj) in tail.iter_mut().zip(pivot_tail) {
                let t = l.mul_ref(u_kj);
                *a_ij -= t;
            }
            *a_ik = l;
        }
        rest = bottom;
    }
    Ok(Kind::Gauss { lu, perm, odd })
}

/// Forward substitution L y = P b, then back substitution U x = y; `None` when b has fewer than
/// n entries.
fn substitute<S: Scalar>(lu: &[Vec<S>], perm: &[usize], b: &[S]) -> Option<Vec<S>> {
    // y_i = (P b)_i − Σ_{j<i} l_ij y_j
    let mut y: Vec<S> = Vec::with_capacity(lu.len());
    for (row, &p) in lu.iter().zip(perm) {
        let mut y_i = b.get(p)?.clone();
        // y holds y_0..y_{i-1}: the zip stops at j = i
        for (l_ij, y_j) in row.iter().zip(&y) {
            let t = l_ij.mul_ref(y_j);
            y_i -= t;
        }
        y.push(y_i);
    }
    // x_i = (y_i − Σ_{j>i} u_ij x_j) / u_ii, from the last row up: x_{n-1}, x_{n-2}, ...
    let mut x_rev: Vec<S> = Vec::with_capacity(y.len());
    for (i, (row, y_i)) in lu.iter().zip(y).enumerate().rev() {
        let (u_ii, upper) = row.get(i..)?.split_first()?;
        let mut x_i = y_i;
        for (u_ij, x_j) in upper.iter().zip(x_rev.iter().rev()) {
            let t = u_ij.mul_ref(x_j);
            x_i -= t;
        }
        x_rev.push(x_i / u_ii);
    }
    x_rev.reverse();
    Some(x_rev)
}

/// The solution x of A x = b (factors A, then substitutes).
///
/// ```
/// use cagd_linalg::{solve, Matrix};
/// use cagd_scalar::{q, BigRational};
/// let a: Matrix<BigRational> = Matrix::from_rows(vec![vec![q!(2), q!(1)], vec![q!(1), q!(3)]]).unwrap();
/// assert_eq!(solve(&a, &[q!(1), q!(2)]).unwrap(), vec![q!(1/5), q!(3/5)]);
/// ```
pub fn solve<S: Scalar>(a: &Matrix<S>, b: &[S]) -> Result<Vec<S>, LinalgError> {
    Factorization::new(a)?.solve(b)
}

/// The points x with A x = b, one system per coordinate ([`Factorization::solve_points`]).
pub fn solve_points<S: Scalar>(
    a: &Matrix<S>,
    b: &[Point<S>],
) -> Result<Vec<Point<S>>, LinalgError> {
    Factorization::new(a)?.solve_points(b)
}

/// The matrix X with A X = B.
pub fn solve_matrix<S: Scalar>(a: &Matrix<S>, b: &Matrix<S>) -> Result<Matrix<S>, LinalgError> {
    Factorization::new(a)?.solve_matrix(b)
}

/// The inverse A⁻¹; an error when A is singular.
///
/// ```
/// use cagd_linalg::{inverse, Matrix};
/// use cagd_scalar::{q, BigRational};
/// let a: Matrix<BigRational> = Matrix::from_rows(vec![vec![q!(1), q!(0)], vec![q!(1/2), q!(1/2)]]).unwrap();
/// assert_eq!(inverse(&a).unwrap().to_text(), "1  0\n-1  2");
/// ```
pub fn inverse<S: Scalar>(a: &Matrix<S>) -> Result<Matrix<S>, LinalgError> {
    Ok(Factorization::new(a)?.inverse())
}

/// The determinant of a square matrix: 0 when it is singular, an error only when it is not
/// square.
///
/// ```
/// use cagd_linalg::{determinant, Matrix};
/// use cagd_scalar::{q, BigRational};
/// let a: Matrix<BigRational> = Matrix::from_rows(vec![vec![q!(1/2), q!(1)], vec![q!(1/3), q!(1)]]).unwrap();
/// assert_eq!(determinant(&a).unwrap(), q!(1/6));
/// ```
pub fn determinant<S: Scalar>(a: &Matrix<S>) -> Result<S, LinalgError> {
    check_square(a)?;
    match Factorization::new(a) {
        Ok(f) => Ok(f.determinant()),
        Err(LinalgError::Singular { .. }) => Ok(S::zero()),
        Err(e) => Err(e),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, BigRational, Quadratic};

    fn m(rows: Vec<Vec<BigRational>>) -> Matrix<BigRational> {
        Matrix::from_rows(rows).unwrap()
    }

    #[test]
    fn hand_checked_three_by_three() {
        // 2x + y - z = 8, -3x - y + 2z = -11, -2x + y + 2z = -3: x = 2, y = 3, z = -1.
        let a = m(vec![
            vec![q!(2), q!(1), q!(-1)],
            vec![q!(-3), q!(-1), q!(2)],
            vec![q!(-2), q!(1), q!(2)],
        ]);
        let b = [q!(8), q!(-11), q!(-3)];
        for method in [Elimination::Gauss, Elimination::FractionFree] {
            let f = Factorization::with_method(&a, method).unwrap();
            assert_eq!(f.method(), method);
            assert_eq!(f.solve(&b).unwrap(), vec![q!(2), q!(3), q!(-1)]);
            assert_eq!(f.determinant(), q!(-1));
        }
    }

    #[test]
    fn zero_leading_entry_needs_a_swap() {
        let a = m(vec![vec![q!(0), q!(1)], vec![q!(1), q!(0)]]);
        for method in [Elimination::Gauss, Elimination::FractionFree] {
            let f = Factorization::with_method(&a, method).unwrap();
            assert_eq!(f.determinant(), q!(-1));
            assert_eq!(
                f.solve(&[q!(3), q!(1 / 2)]).unwrap(),
                vec![q!(1 / 2), q!(3)]
            );
        }
    }

    #[test]
    fn singular_names_the_column() {
        // Row 2 = row 0 + row 1; columns 0 and 1 get pivots, column 2 does not.
        let a = m(vec![
            vec![q!(1), q!(2), q!(3)],
            vec![q!(0), q!(1), q!(1)],
            vec![q!(1), q!(3), q!(4)],
        ]);
        for method in [Elimination::Gauss, Elimination::FractionFree] {
            let err = Factorization::with_method(&a, method).unwrap_err();
            assert!(
                err.to_string().contains("column 2 has no pivot"),
                "{method:?}: {err}"
            );
            assert!(err.to_string().contains("linearly dependent"));
        }
        assert_eq!(determinant(&a).unwrap(), q!(0));
    }

    #[test]
    fn sizes_are_checked() {
        let a = m(vec![vec![q!(1), q!(2)], vec![q!(3), q!(4)]]);
        let e = solve(&a, &[q!(1)]).unwrap_err();
        assert!(matches!(
            e,
            LinalgError::DimensionMismatch {
                expected: 2,
                found: 1,
                ..
            }
        ));
        let rect = m(vec![vec![q!(1), q!(2), q!(3)], vec![q!(3), q!(4), q!(5)]]);
        assert!(determinant(&rect)
            .unwrap_err()
            .to_string()
            .contains("this one is 2×3"));
        let pts = [Point::from_ints(&[1, 2]), Point::from_ints(&[1, 2, 3])];
        let e = solve_points(&a, &pts).unwrap_err();
        assert!(e.to_string().contains("right-hand side point 1"), "{e}");
        assert!(solve_matrix(&a, &Matrix::zeros(3, 1)).is_err());
        // The empty system has the empty solution and determinant 1.
        let empty = Matrix::<BigRational>::zeros(0, 0);
        assert_eq!(solve(&empty, &[]).unwrap(), Vec::<BigRational>::new());
        assert_eq!(determinant(&empty).unwrap(), q!(1));
    }

    #[test]
    fn quadratic_entries_use_gauss_and_stay_exact() {
        let r2 = Quadratic::sqrt_of(&q!(2)).unwrap();
        let half = Quadratic::from_rational(q!(1 / 2));
        // [[1, √2], [√2/2, 1]] has det 1 - 1 = 0: singular.
        let one = Quadratic::from_rational(q!(1));
        let sing = Matrix::from_rows(vec![
            vec![one.clone(), r2.clone()],
            vec![r2.clone() * &half, one.clone()],
        ])
        .unwrap();
        assert!(Factorization::new(&sing).is_err());
        // [[√2, 1], [1, √2]]: det = 1, inverse [[√2, -1], [-1, √2]].
        let a = Matrix::from_rows(vec![
            vec![r2.clone(), one.clone()],
            vec![one.clone(), r2.clone()],
        ])
        .unwrap();
        let f = Factorization::new(&a).unwrap();
        assert_eq!(f.method(), Elimination::Gauss);
        assert_eq!(f.determinant(), one);
        assert_eq!(f.inverse().to_text(), "√2  -1\n-1  √2");
    }

    #[test]
    fn rational_matrix_with_irrational_right_hand_side() {
        let a = m(vec![vec![q!(1), q!(1)], vec![q!(1), q!(-1)]]);
        let aq = Matrix::from_fn(2, 2, |i, j| Quadratic::from_rational(a.get(i, j).clone()));
        let f = Factorization::new(&aq).unwrap();
        assert_eq!(f.method(), Elimination::FractionFree);
        let r2 = Quadratic::sqrt_of(&q!(2)).unwrap();
        let one = Quadratic::from_rational(q!(1));
        // x + y = 1 + √2, x - y = 1 - √2: x = 1, y = √2.
        let x = f.solve(&[one.clone() + &r2, one.clone() - &r2]).unwrap();
        assert_eq!(x, vec![one, r2]);
    }

    #[test]
    fn f64_uses_partial_pivoting() {
        // A tiny leading pivot would lose all precision without pivoting.
        let a = Matrix::from_rows(vec![vec![1e-20, 1.0], vec![1.0, 1.0]]).unwrap();
        let x = solve(&a, &[1.0, 2.0]).unwrap();
        assert!(
            (x[0] - 1.0).abs() < 1e-12 && (x[1] - 1.0).abs() < 1e-12,
            "{x:?}"
        );
        let sing = Matrix::from_rows(vec![vec![1.0, 2.0], vec![0.5, 1.0]]).unwrap();
        assert!(solve(&sing, &[1.0, 2.0])
            .unwrap_err()
            .to_string()
            .contains("column 1 has no pivot"));
    }
}
