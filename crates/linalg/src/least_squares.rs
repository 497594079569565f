//! Least-squares solutions of overdetermined systems by the normal equations.

use crate::{Factorization, LinalgError, Matrix, Operands, Point, Singularity};
use cagd_scalar::Scalar;

/// The normal matrix BᵗB and, through [`Factorization`], its solves: the notes' eq. (29),
/// B^t B C = B^t A, with B the (M+1)×(k) collocation matrix of the data.
///
/// `least_squares` and `least_squares_points` call this; use it directly to see BᵗB, or to fit
/// several data sets with the same parameters.
#[derive(Clone)]
pub struct NormalEquations<S> {
    b: Matrix<S>,
    normal: Matrix<S>,
    factorization: Factorization<S>,
}

impl<S: Scalar> std::fmt::Debug for NormalEquations<S> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("NormalEquations")
            .field("b", &self.b)
            .field("normal", &self.normal)
            .finish()
    }
}

impl<S: Scalar> NormalEquations<S> {
    /// Forms and factors BᵗB. An error when B has fewer rows than columns
    /// ([`LinalgError::Underdetermined`]) or BᵗB is singular (the columns of B are linearly
    /// dependent: the data do not determine every unknown).
    pub fn new(b: &Matrix<S>) -> Result<Self, LinalgError> {
        if b.rows() < b.cols() {
            return Err(LinalgError::Underdetermined {
                equations: b.rows(),
                unknowns: b.cols(),
            });
        }
        let normal = b.transpose().mul(b)?;
        let factorization = Factorization::new(&normal).map_err(|e| match e {
            LinalgError::Singular {
                detail: Singularity::NoPivot { column },
            } => LinalgError::Singular {
                detail: Singularity::NormalNoPivot { column },
            },
            e => e,
        })?;
        Ok(NormalEquations {
            b: b.clone(),
            normal,
            factorization,
        })
    }

    /// The normal matrix BᵗB.
    pub fn normal_matrix(&self) -> &Matrix<S> {
        &self.normal
    }

    /// The right-hand side Bᵗa for scalar data a.
    pub fn rhs(&self, a: &[S]) -> Result<Vec<S>, LinalgError> {
        self.check_len(a.len())?;
        Ok((0..self.b.cols())
            .map(|j| {
                a.iter()
                    .enumerate()
                    .fold(S::zero(), |acc, (i, ai)| acc + self.b.get(i, j).mul_ref(ai))
            })
            .collect())
    }

    /// The right-hand side Bᵗa for point data a_i (all of one dimension).
    pub fn rhs_points(&self, a: &[Point<S>]) -> Result<Vec<Point<S>>, LinalgError> {
        self.check_len(a.len())?;
        let dim = a.first().map_or(0, Point::dim);
        for (i, p) in a.iter().enumerate() {
            if p.dim() != dim {
                return Err(LinalgError::DimensionMismatch {
                    what: Operands::DataPoint { index: i },
                    expected: dim,
                    found: p.dim(),
                });
            }
        }
        Ok((0..self.b.cols())
            .map(|j| {
                let coefs: Vec<S> = (0..self.b.rows())
                    .map(|i| self.b.get(i, j).clone())
                    .collect();
                Point::combination(a, &coefs, dim)
            })
            .collect())
    }

    /// The c minimizing |B c − a|², from BᵗB c = Bᵗa.
    pub fn solve(&self, a: &[S]) -> Result<Vec<S>, LinalgError> {
        self.factorization.solve(&self.rhs(a)?)
    }

    /// The points c_j minimizing Σ_i |Σ_j b_ij c_j − a_i|², from BᵗB C = Bᵗ A (eq. (29)).
    pub fn solve_points(&self, a: &[Point<S>]) -> Result<Vec<Point<S>>, LinalgError> {
        self.factorization.solve_points(&self.rhs_points(a)?)
    }

    fn check_len(&self, len: usize) -> Result<(), LinalgError> {
        if len == self.b.rows() {
            Ok(())
        } else {
            Err(LinalgError::DimensionMismatch {
                what: Operands::LeastSquaresData,
                expected: self.b.rows(),
                found: len,
            })
        }
    }
}

/// The least-squares solution of B c ≈ a: c = (BᵗB)⁻¹ Bᵗ a (the notes' eq. (29)).
///
/// ```
/// use cagd_linalg::{least_squares, Matrix};
/// use cagd_scalar::{q, BigRational};
/// // The line y = c0 + c1 x closest to (0, 0), (1, 1), (2, 1).
/// let b: Matrix<BigRational> = Matrix::from_rows(vec![
///     vec![q!(1), q!(0)], vec![q!(1), q!(1)], vec![q!(1), q!(2)],
/// ]).unwrap();
/// assert_eq!(least_squares(&b, &[q!(0), q!(1), q!(1)]).unwrap(), vec![q!(1/6), q!(1/2)]);
/// ```
pub fn least_squares<S: Scalar>(b: &Matrix<S>, a: &[S]) -> Result<Vec<S>, LinalgError> {
    NormalEquations::new(b)?.solve(a)
}

/// The least-squares control points C of B C ≈ A, one system per coordinate: C = (BᵗB)⁻¹ BᵗA.
pub fn least_squares_points<S: Scalar>(
    b: &Matrix<S>,
    a: &[Point<S>],
) -> Result<Vec<Point<S>>, LinalgError> {
    NormalEquations::new(b)?.solve_points(a)
}
