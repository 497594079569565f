use cagd_words::{said, Lang, Message, Phrase};

/// What can go wrong in linear algebra.
/// Each variant is worded in English and in the notes' Spanish ([`Message`]); `Display` writes
/// the English.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
#[non_exhaustive]
pub enum LinalgError {
    /// Two operands have different dimensions (points of R^2 and R^3, matrices that do not fit).
    DimensionMismatch {
        /// What was being done.
        what: Operands,
        /// The dimension expected.
        expected: usize,
        /// The dimension found.
        found: usize,
    },
    /// The system has no unique solution.
    Singular {
        /// Why (the first column without a pivot).
        detail: Singularity,
    },
    /// A least-squares problem with fewer equations (data) than unknowns: the normal matrix
    /// BᵗB is singular whatever the data.
    Underdetermined {
        /// The number of equations (rows of B, data points).
        equations: usize,
        /// The number of unknowns (columns of B, coefficients).
        unknowns: usize,
    },
    /// A matrix given as rows has rows of different lengths.
    Ragged {
        /// The row that differs.
        row: usize,
        /// Its length.
        len: usize,
        /// The length of the first row.
        expected: usize,
    },
}

impl Default for LinalgError {
    fn default() -> Self {
        LinalgError::Singular {
            detail: Singularity::default(),
        }
    }
}

/// What was being done when two dimensions differed (the `what` of
/// [`LinalgError::DimensionMismatch`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, strum::EnumIter)]
#[non_exhaustive]
pub enum Operands {
    /// A matrix product.
    #[default]
    MatrixProduct,
    /// A data point of a least-squares problem.
    DataPoint {
        /// Its index.
        index: usize,
    },
    /// The data of a least-squares problem.
    LeastSquaresData,
    /// A cross product (of 3-vectors).
    CrossProduct,
    /// A sum of points.
    AddingPoints,
    /// A difference of points.
    SubtractingPoints,
    /// A linear solve with a matrix that is not square.
    Square {
        /// Its rows.
        rows: usize,
        /// Its columns.
        cols: usize,
    },
    /// The right-hand side of a linear system.
    RightHandSide,
    /// The points on the right-hand side.
    RightHandPoints,
    /// A point on the right-hand side.
    RightHandPoint {
        /// Its index.
        index: usize,
    },
    /// The rows of a right-hand side matrix.
    RightHandRows,
}

/// Why a linear system has no unique solution (the `detail` of [`LinalgError::Singular`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, strum::EnumIter)]
#[non_exhaustive]
pub enum Singularity {
    /// A column without a pivot.
    NoPivot {
        /// The column.
        column: usize,
    },
    /// A column without a pivot in the normal matrix of a least-squares problem.
    NormalNoPivot {
        /// The column.
        column: usize,
    },
}

impl Default for Singularity {
    fn default() -> Self {
        Singularity::NoPivot { column: 0 }
    }
}

impl Message for LinalgError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            LinalgError::DimensionMismatch {
                what,
                expected,
                found,
            } => said(
                lang,
                "«»: expected dimension ‹›, found ‹›",
                "«»: se esperaba dimensión ‹›, se encontró ‹›",
                [what.phrase(lang).into(), expected.into(), found.into()],
            ),
            LinalgError::Singular { detail } => said(
                lang,
                "the linear system is singular (no unique solution): «»",
                "el sistema lineal es singular (no tiene solución única): «»",
                [detail.phrase(lang).into()],
            ),
            LinalgError::Underdetermined {
                equations,
                unknowns,
            } => said(
                lang,
                "least squares with ‹› equations for ‹› unknowns: the normal matrix BᵗB is singular; give at least ‹› data",
                "mínimos cuadrados con ‹› ecuaciones para ‹› incógnitas: la matriz normal BᵗB es singular; dé al menos ‹› datos",
                [equations.into(), unknowns.into(), unknowns.into()],
            ),
            LinalgError::Ragged { row, len, expected } => said(
                lang,
                "row ‹› has ‹› entries but row 0 has ‹›: a matrix needs rows of equal length",
                "la fila ‹› tiene ‹› elementos, pero la fila 0 tiene ‹›: las filas de una matriz han de tener la misma longitud",
                [row.into(), len.into(), expected.into()],
            ),
        }
    }
}

impl Message for Operands {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Operands::MatrixProduct => said(
                lang,
                "matrix product (columns of the left = rows of the right)",
                "producto de matrices (columnas de la izquierda = filas de la derecha)",
                [],
            ),
            Operands::DataPoint { index } => said(
                lang,
                "data point ‹› (point 0 sets the dimension)",
                "el punto dato ‹› (el punto 0 fija la dimensión)",
                [index.into()],
            ),
            Operands::LeastSquaresData => said(
                lang,
                "data for least squares (one per row of B)",
                "los datos de los mínimos cuadrados (uno por fila de B)",
                [],
            ),
            Operands::CrossProduct => said(lang, "cross product", "producto vectorial", []),
            Operands::AddingPoints => said(lang, "adding points", "al sumar puntos", []),
            Operands::SubtractingPoints => {
                said(lang, "subtracting points", "al restar puntos", [])
            }
            Operands::Square { rows, cols } => said(
                lang,
                "solving needs a square matrix, this one is ‹›×‹› (columns must equal rows)",
                "resolver necesita una matriz cuadrada, esta es de ‹›×‹› (tantas columnas como filas)",
                [rows.into(), cols.into()],
            ),
            Operands::RightHandSide => said(
                lang,
                "right-hand side of a linear system (one entry per row)",
                "el segundo miembro de un sistema lineal (un elemento por fila)",
                [],
            ),
            Operands::RightHandPoints => said(
                lang,
                "points on the right-hand side (one per row)",
                "los puntos del segundo miembro (uno por fila)",
                [],
            ),
            Operands::RightHandPoint { index } => said(
                lang,
                "right-hand side point ‹› (point 0 sets the dimension)",
                "el punto ‹› del segundo miembro (el punto 0 fija la dimensión)",
                [index.into()],
            ),
            Operands::RightHandRows => said(
                lang,
                "rows of the right-hand side matrix",
                "las filas de la matriz del segundo miembro",
                [],
            ),
        }
    }
}

impl Message for Singularity {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Singularity::NoPivot { column } => said(
                lang,
                "column ‹› has no pivot (after eliminating columns 0..‹›, its entries in rows ‹› and below are all zero): the rows are linearly dependent",
                "la columna ‹› no tiene pivote (tras eliminar las columnas 0..‹›, sus elementos de las filas ‹› en adelante son todos cero): las filas son linealmente dependientes",
                [column.into(), column.into(), column.into()],
            ),
            Singularity::NormalNoPivot { column } => said(
                lang,
                "the normal matrix BᵗB is singular, so the columns of B are linearly dependent (the data do not determine every unknown); «»",
                "la matriz normal BᵗB es singular, así que las columnas de B son linealmente dependientes (los datos no determinan todas las incógnitas); «»",
                [Singularity::NoPivot { column: *column }.phrase(lang).into()],
            ),
        }
    }
}

cagd_words::display_english!(LinalgError, Operands, Singularity);

impl std::error::Error for LinalgError {}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    fn check(m: &LinalgError) {
        assert_eq!(cagd_words::check_both(m), Ok(()), "{m:?}");
    }

    #[test]
    fn every_variant_in_both_languages() {
        for m in LinalgError::iter() {
            check(&m);
        }
        // the parts, each inside the sentence that carries it
        for what in Operands::iter() {
            check(&LinalgError::DimensionMismatch {
                what,
                expected: 2,
                found: 3,
            });
        }
        for detail in Singularity::iter() {
            check(&LinalgError::Singular { detail });
        }
    }
}
