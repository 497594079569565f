//! Dense matrices over any [`Scalar`].

use crate::{LinalgError, Operands};
use cagd_scalar::Scalar;
use std::fmt;

/// A dense `rows × cols` matrix, stored row by row.
#[derive(Clone, PartialEq, Eq, Hash)]
pub struct Matrix<S> {
    rows: usize,
    cols: usize,
    data: Vec<S>,
}

impl<S: Scalar> Matrix<S> {
    /// The `rows × cols` zero matrix.
    pub fn zeros(rows: usize, cols: usize) -> Self {
        Matrix {
            rows,
            cols,
            data: vec![S::zero(); rows * cols],
        }
    }

    /// The `n × n` identity.
    pub fn identity(n: usize) -> Self {
        let mut m = Self::zeros(n, n);
        for i in 0..n {
            m.set(i, i, S::one());
        }
        m
    }

    /// The matrix with these rows; an error if they differ in length.
    pub fn from_rows(rows: Vec<Vec<S>>) -> Result<Self, LinalgError> {
        let cols = rows.first().map_or(0, Vec::len);
        for (i, r) in rows.iter().enumerate() {
            if r.len() != cols {
                return Err(LinalgError::Ragged {
                    row: i,
                    len: r.len(),
                    expected: cols,
                });
            }
        }
        let n = rows.len();
        Ok(Matrix {
            rows: n,
            cols,
            data: rows.into_iter().flatten().collect(),
        })
    }

    /// The matrix whose entry (i, j) is `f(i, j)`.
    pub fn from_fn(rows: usize, cols: usize, mut f: impl FnMut(usize, usize) -> S) -> Self {
        let mut data = Vec::with_capacity(rows * cols);
        for i in 0..rows {
            for j in 0..cols {
                data.push(f(i, j));
            }
        }
        Matrix { rows, cols, data }
    }

    /// Number of rows.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Number of columns.
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// The `rows` rows, as slices (`data` holds exactly `rows · cols` entries).
    fn row_slices(&self) -> impl Iterator<Item = &[S]> + '_ {
        (0..self.rows).map(move |i| {
            self.data
                .get(i * self.cols..(i + 1) * self.cols)
                .unwrap_or(&[])
        })
    }

    /// The rows, as vectors.
    pub fn to_rows(&self) -> Vec<Vec<S>> {
        self.row_slices().map(<[S]>::to_vec).collect()
    }

    /// The transpose.
    pub fn transpose(&self) -> Self {
        Matrix::from_fn(self.cols, self.rows, |i, j| self.get(j, i).clone())
    }

    /// The product `self · rhs`.
    pub fn mul(&self, rhs: &Self) -> Result<Self, LinalgError> {
        if self.cols != rhs.rows {
            return Err(LinalgError::DimensionMismatch {
                what: Operands::MatrixProduct,
                expected: self.cols,
                found: rhs.rows,
            });
        }
        Ok(Matrix::from_fn(self.rows, rhs.cols, |i, j| {
            (0..self.cols).fold(S::zero(), |acc, k| {
                acc + self.get(i, k).mul_ref(rhs.get(k, j))
            })
        }))
    }

    /// `c · self`.
    pub fn scale(&self, c: &S) -> Self {
        Matrix {
            rows: self.rows,
            cols: self.cols,
            data: self.data.iter().map(|x| x.mul_ref(c)).collect(),
        }
    }

    /// Plain text, one row per line: `[1, 0, 0; 1/4, 1/2, 1/4; 0, 0, 1]` style rows.
    pub fn to_text(&self) -> String {
        self.row_slices()
            .map(|row| {
                let r: Vec<String> = row.iter().map(|x| x.to_text()).collect();
                r.join("  ")
            })
            .collect::<Vec<_>>()
            .join("\n")
    }

    /// LaTeX `pmatrix`.
    pub fn to_latex(&self) -> String {
        let rows: Vec<String> = self
            .row_slices()
            .map(|row| {
                let r: Vec<String> = row.iter().map(|x| x.to_latex()).collect();
                r.join(" & ")
            })
            .collect();
        format!(
            "\\begin{{pmatrix}} {} \\end{{pmatrix}}",
            rows.join(" \\\\ ")
        )
    }
}

/// The accessors by index. Like slice indexing, an index outside the matrix is a bug of the
/// caller, not bad input: these panic (see `# Panics`) rather than return an error.
#[allow(clippy::indexing_slicing)]
impl<S: Scalar> Matrix<S> {
    /// Entry (i, j).
    ///
    /// # Panics
    /// If (i, j) is outside the matrix.
    pub fn get(&self, i: usize, j: usize) -> &S {
        assert!(i < self.rows && j < self.cols, "matrix index out of range");
        &self.data[i * self.cols + j]
    }

    /// Sets entry (i, j).
    ///
    /// # Panics
    /// If (i, j) is outside the matrix.
    pub fn set(&mut self, i: usize, j: usize, value: S) {
        assert!(i < self.rows && j < self.cols, "matrix index out of range");
        self.data[i * self.cols + j] = value;
    }

    /// Row i.
    ///
    /// # Panics
    /// If `i >= rows()` (and the matrix has columns).
    pub fn row(&self, i: usize) -> &[S] {
        &self.data[i * self.cols..(i + 1) * self.cols]
    }
}

impl<S: Scalar> fmt::Debug for Matrix<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "Matrix {}x{} [\n{}\n]",
            self.rows,
            self.cols,
            self.to_text()
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, BigRational};

    #[test]
    fn products_and_errors() {
        let a: Matrix<BigRational> =
            Matrix::from_rows(vec![vec![q!(1), q!(2)], vec![q!(1 / 2), q!(0)]]).unwrap();
        let i = Matrix::identity(2);
        assert_eq!(a.mul(&i).unwrap(), a);
        assert_eq!(a.transpose().get(0, 1), &q!(1 / 2));
        assert_eq!(a.to_text(), "1  2\n1/2  0");
        let r = Matrix::<BigRational>::from_rows(vec![vec![q!(1)], vec![q!(1), q!(2)]]);
        assert!(r
            .unwrap_err()
            .to_string()
            .contains("row 1 has 2 entries but row 0 has 1"));
        assert!(a.mul(&Matrix::zeros(3, 1)).is_err());
    }
}
