//! Tensor-product surfaces (chapter 5 of the notes, `002_20d988b092ff1833.txt`).
//!
//! A patch of bidegree (m, n) has a control mesh c_ij, i = 0..m along u (the rows of the mesh),
//! j = 0..n along v (the columns), as the notes write it:
//!
//! ```text
//! c(u, v) = Σ_i Σ_j c_ij B_i^m(u) B_j^n(v)                                    (1)
//! ```
//!
//! Most algorithms are curve algorithms applied "in two passes" to the rows and columns of the
//! mesh; [`Grid::map_rows`] and [`Grid::map_columns`] are those passes.

mod error;
mod grid;
mod patch;

pub use error::SurfaceError;
pub use grid::{Grid, Mesh};
pub use patch::{BezierSurface, RationalBezierSurface};

pub use cagd_linalg::Point;
pub use cagd_scalar::Scalar;
