//! Rectangular grids: control meshes and weight matrices.

use crate::SurfaceError;
use cagd_linalg::Point;
use cagd_scalar::{Print, Scalar};

/// A rectangular grid of values, stored row by row: entry (i, j) is row i (along u), column j
/// (along v), as the notes' meshes c_ij.
#[derive(Clone, PartialEq, Eq, Hash, Debug)]
pub struct Grid<T> {
    rows: usize,
    cols: usize,
    data: Vec<T>,
}

/// A control mesh: a grid of points.
pub type Mesh<S> = Grid<Point<S>>;

impl<T: Clone> Grid<T> {
    /// The grid with these rows; an error if there are none, or they differ in length.
    pub fn from_rows(rows: Vec<Vec<T>>) -> Result<Self, SurfaceError> {
        let cols = rows.first().map_or(0, Vec::len);
        if rows.is_empty() || cols == 0 {
            return Err(SurfaceError::EmptyMesh);
        }
        for (i, r) in rows.iter().enumerate() {
            if r.len() != cols {
                return Err(SurfaceError::RaggedMesh {
                    row: i,
                    len: r.len(),
                    expected: cols,
                });
            }
        }
        let n = rows.len();
        Ok(Grid {
            rows: n,
            cols,
            data: rows.into_iter().flatten().collect(),
        })
    }

    /// The grid with these columns (column j is the list of entries (i, j) for all i).
    pub fn from_columns(columns: Vec<Vec<T>>) -> Result<Self, SurfaceError> {
        Ok(Grid::from_rows(columns)?.transpose())
    }

    /// The `rows × cols` grid whose entry (i, j) is `f(i, j)`.
    ///
    /// An empty shape gives an empty grid; constructors that need a mesh check it.
    pub fn from_fn(rows: usize, cols: usize, mut f: impl FnMut(usize, usize) -> T) -> Self {
        let mut data = Vec::with_capacity(rows * cols);
        for i in 0..rows {
            for j in 0..cols {
                data.push(f(i, j));
            }
        }
        Grid { rows, cols, data }
    }

    /// Number of rows (m + 1 for bidegree (m, n)).
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// Number of columns (n + 1 for bidegree (m, n)).
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Entry (i, j), or `None` outside the grid.
    pub fn get(&self, i: usize, j: usize) -> Option<&T> {
        if i < self.rows && j < self.cols {
            self.data.get(i * self.cols + j)
        } else {
            None
        }
    }

    /// Row i, or `None` outside the grid.
    pub fn row(&self, i: usize) -> Option<&[T]> {
        if i < self.rows {
            self.data.get(i * self.cols..(i + 1) * self.cols)
        } else {
            None
        }
    }

    /// Column j (a copy), or `None` outside the grid.
    pub fn column(&self, j: usize) -> Option<Vec<T>> {
        (j < self.cols).then(|| {
            (0..self.rows)
                .filter_map(|i| self.data.get(i * self.cols + j).cloned())
                .collect()
        })
    }

    /// The rows, borrowed (no copy of the entries).
    pub fn row_slices(&self) -> impl Iterator<Item = &[T]> {
        self.data.chunks(self.cols.max(1))
    }

    /// The rows, as vectors.
    pub fn to_rows(&self) -> Vec<Vec<T>> {
        self.data
            .chunks(self.cols.max(1))
            .map(<[T]>::to_vec)
            .collect()
    }

    /// The columns, as vectors.
    pub fn to_columns(&self) -> Vec<Vec<T>> {
        self.transpose().to_rows()
    }

    /// All entries, row by row.
    pub fn iter(&self) -> impl Iterator<Item = &T> {
        self.data.iter()
    }

    /// All entries with their indices (i, j), row by row.
    pub fn indexed(&self) -> impl Iterator<Item = ((usize, usize), &T)> {
        let cols = self.cols.max(1);
        self.data
            .iter()
            .enumerate()
            .map(move |(k, x)| ((k / cols, k % cols), x))
    }

    /// The transpose: entry (j, i) becomes (i, j) (swaps the roles of u and v).
    pub fn transpose(&self) -> Self {
        let mut data = Vec::with_capacity(self.data.len());
        for j in 0..self.cols {
            for i in 0..self.rows {
                if let Some(x) = self.data.get(i * self.cols + j) {
                    data.push(x.clone());
                }
            }
        }
        Grid {
            rows: self.cols,
            cols: self.rows,
            data,
        }
    }

    /// The grid with `f` applied to every entry.
    pub fn map<U: Clone>(&self, f: impl FnMut(&T) -> U) -> Grid<U> {
        Grid {
            rows: self.rows,
            cols: self.cols,
            data: self.data.iter().map(f).collect(),
        }
    }

    /// The grid with `f` applied to every entry, or the first error `f` gives (entries in
    /// order, row by row): one vector built, no rows.
    pub fn try_map<U, E>(&self, mut f: impl FnMut(&T) -> Result<U, E>) -> Result<Grid<U>, E> {
        // reserved once: collecting `Result`s would grow the vector from empty
        let mut data = Vec::with_capacity(self.data.len());
        for x in &self.data {
            data.push(f(x)?);
        }
        Ok(Grid {
            rows: self.rows,
            cols: self.cols,
            data,
        })
    }

    /// The pass over rows: row i of the result is `f(row i)`. All results must have the same
    /// length (they do for every curve algorithm applied with the same arguments).
    pub fn map_rows<E>(&self, mut f: impl FnMut(&[T]) -> Result<Vec<T>, E>) -> Result<Self, E>
    where
        E: From<SurfaceError>,
    {
        let rows = self
            .data
            .chunks(self.cols.max(1))
            .map(&mut f)
            .collect::<Result<Vec<_>, E>>()?;
        Ok(Grid::from_rows(rows)?)
    }

    /// The pass over columns: column j of the result is `f(column j)`.
    pub fn map_columns<E>(&self, f: impl FnMut(&[T]) -> Result<Vec<T>, E>) -> Result<Self, E>
    where
        E: From<SurfaceError>,
    {
        Ok(self.transpose().map_rows(f)?.transpose())
    }
}

impl<S: Scalar> Mesh<S> {
    /// A control mesh from its rows, checking that it is rectangular, non-empty and that every
    /// point has the dimension of c_00.
    pub fn mesh(rows: Vec<Vec<Point<S>>>) -> Result<Self, SurfaceError> {
        Grid::from_rows(rows)?.checked()
    }

    /// This grid as a control mesh, checked where it lies (no copy of a point): non-empty,
    /// and every point of the dimension of c_00. A grid is rectangular by construction.
    pub fn checked(self) -> Result<Self, SurfaceError> {
        if self.data.is_empty() {
            return Err(SurfaceError::EmptyMesh);
        }
        let expected = self.data.first().map_or(0, Point::dim);
        if let Some(k) = self.data.iter().position(|p| p.dim() != expected) {
            let cols = self.cols.max(1);
            return Err(SurfaceError::MixedDimensions {
                row: k / cols,
                col: k % cols,
                found: self.data.get(k).map_or(0, Point::dim),
                expected,
            });
        }
        Ok(self)
    }

    /// The dimension of the control points.
    pub fn dim(&self) -> usize {
        self.data.first().map_or(0, Point::dim)
    }

    /// Plain text in the notes' notation: rows separated by `;`, e.g.
    /// `{(0, 0, 0), (0, 1, 0); (1, 0, 0), (1, 1, 1)}`.
    pub fn to_text(&self) -> String {
        self.text_with(Point::to_text)
    }

    /// LaTeX: a matrix of points, one mesh row per line.
    pub fn to_latex(&self) -> String {
        self.latex_with(Point::to_latex)
    }
}

impl<T: Clone> Grid<T> {
    /// Plain text with `cell` for each entry: `{a, b; c, d}`, rows separated by `;`.
    pub fn text_with(&self, cell: impl Fn(&T) -> String) -> String {
        let rows: Vec<String> = self
            .to_rows()
            .iter()
            .map(|r| r.iter().map(&cell).collect::<Vec<_>>().join(", "))
            .collect();
        format!("{{{}}}", rows.join("; "))
    }

    /// LaTeX with `cell` for each entry: `\begin{Bmatrix} a & b \\ c & d \end{Bmatrix}`, one
    /// row per line of the matrix.
    pub fn latex_with(&self, cell: impl Fn(&T) -> String) -> String {
        let rows: Vec<String> = self
            .to_rows()
            .iter()
            .map(|r| r.iter().map(&cell).collect::<Vec<_>>().join(" & "))
            .collect();
        format!(
            "\\begin{{Bmatrix}} {} \\end{{Bmatrix}}",
            rows.join(" \\\\ ")
        )
    }
}

impl<S: Scalar> Grid<S> {
    /// Plain text of a grid of numbers (weights): `{1, √2/2, 1; √2/2, 1/2, √2/2}`.
    pub fn to_text_numbers(&self) -> String {
        self.text_with(Print::to_text)
    }

    /// LaTeX of a grid of numbers (weights), one row per line of the matrix.
    pub fn to_latex_numbers(&self) -> String {
        self.latex_with(Print::to_latex)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::BigRational;

    fn p(c: &[i64]) -> Point<BigRational> {
        Point::from_ints(c)
    }

    #[test]
    fn rows_columns_and_errors() {
        let m = Mesh::mesh(vec![
            vec![p(&[0, 0, 0]), p(&[0, 1, 0])],
            vec![p(&[1, 0, 0]), p(&[1, 1, 1])],
        ])
        .unwrap();
        assert_eq!(m.to_text(), "{(0, 0, 0), (0, 1, 0); (1, 0, 0), (1, 1, 1)}");
        assert_eq!(m.column(1).unwrap(), vec![p(&[0, 1, 0]), p(&[1, 1, 1])]);
        assert_eq!(
            m.transpose().row(1).unwrap(),
            &[p(&[0, 1, 0]), p(&[1, 1, 1])][..]
        );
        let swapped: Result<_, SurfaceError> =
            m.map_rows(|r| Ok(r.iter().rev().cloned().collect()));
        assert_eq!(swapped.unwrap().get(0, 0), Some(&p(&[0, 1, 0])));
        let e = Mesh::mesh(vec![vec![p(&[0, 0, 0])], vec![p(&[1, 0])]]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "control point c_1,0 has 2 coordinates but c_0,0 has 3"
        );
        let e = Mesh::<BigRational>::mesh(vec![vec![p(&[0, 0])], vec![]]).unwrap_err();
        assert!(e
            .to_string()
            .starts_with("row 1 of the control mesh has 0 points"));
        assert_eq!(
            Mesh::<BigRational>::mesh(vec![]).unwrap_err(),
            SurfaceError::EmptyMesh
        );
        // checked in place: the same errors as from rows
        let flat = Grid::from_fn(2, 2, |i, j| {
            if (i, j) == (1, 0) {
                p(&[1, 0])
            } else {
                p(&[0, 0, 0])
            }
        });
        assert_eq!(
            flat.checked().unwrap_err().to_string(),
            "control point c_1,0 has 2 coordinates but c_0,0 has 3"
        );
        assert_eq!(
            Grid::from_fn(0, 3, |_, _| p(&[0])).checked().unwrap_err(),
            SurfaceError::EmptyMesh
        );
        let m = Grid::from_fn(2, 3, |i, j| p(&[i, j].map(|k| i64::try_from(k).unwrap())));
        let doubled: Result<_, ()> = m.try_map(|q| Ok(q.clone()));
        assert_eq!(doubled.unwrap().checked().unwrap(), m);
        let failed: Result<Grid<i32>, &str> = m.try_map(|_| Err("no"));
        assert_eq!(failed.unwrap_err(), "no");
    }
}
