//! B-spline and NURBS tensor-product surfaces (chapter 5 of the notes,
//! `002_20d988b092ff1833.txt`, §2):
//!
//! ```text
//! c(u, v) = Σ_{i=0}^{p+M-1} Σ_{j=0}^{q+N-1} d_{i,j} N_i^p(u) N_j^q(v)                        (4)
//! c(u, v) = Σ Σ w_{i,j} d_{i,j} N_i^p(u) N_j^q(v) / Σ Σ w_{i,j} N_i^p(u) N_j^q(v)           (6)
//! ```
//!
//! of bidegree (p, q) (the notes' (m, n)) and M x N spans, with knots `u_0, ..., u_{2p+M-2}`,
//! `v_0, ..., v_{2q+N-2}` in the notes' convention and domain
//! `[u_{p-1}, u_{p+M-1}] x [v_{q-1}, v_{q+N-1}]`. The knot vectors are those of `cagd-bspline`
//! ([`KnotVector`]), read in either convention (the notes', or The
//! NURBS Book's with one more knot at each end) and written in the notes' by default.
//!
//! "Todos los algoritmos estudiados para curvas [...] sólo requieren que los apliquemos a la
//! malla de control en dos pasadas, una para las filas y otra para las columnas" (notes, §2):
//! every algorithm here is a curve algorithm of `cagd-bspline` run on every column of the mesh
//! (in u, [`Direction::U`]) or on every row (in v, [`Direction::V`]), with the rows of the mesh
//! along u as in `cagd-surface`. A NURBS surface runs them on its homogeneous mesh
//! `(w d, w)` (weight last) and projects back.
//!
//! One operation family per file:
//!
//! | file | what | notes |
//! | --- | --- | --- |
//! | `surface.rs`, `nurbs.rs` | the types, validation, homogeneous form | (4), (6) |
//! | `eval.rs` | De Boor in two passes (both orders), the basis sum, the quotient | (4), (6) |
//! | `insert.rs` | knot insertion and refinement in u or v | §2 |
//! | `extract.rs` | Bézier extraction: the grid of (rational) Bézier patches | §2 |
//! | `elevate.rs` | degree elevation in u, v or both | §2 |
//! | `derivative.rs` | partial derivative surfaces and partial derivatives at a point | |
//! | `convert.rs` | a Bézier patch as a B-spline surface and back | (1), (4) |
//! | `text.rs` | text and LaTeX for answer keys | |
//!
//! The slides' hemisphere: the quarter circle `{(1, 0, 0), (1, 0, 1), (0, 0, 1)}` with weights
//! `{1, √2/2, 1}` turned by the 9-point circle; every point satisfies x² + y² + z² = 1
//! exactly over a + b√2:
//!
//! ```
//! use cagd_spline_surface::NurbsSurface;
//! use cagd_surface::{Grid, Mesh};
//! use cagd_linalg::Point;
//! use cagd_scalar::{parse_number, FieldOps, Print, Quadratic};
//! let n = |t: &str| parse_number(t).unwrap();
//! let circle = [(1, 0), (1, 1), (0, 1), (-1, 1), (-1, 0), (-1, -1), (0, -1), (1, -1), (1, 0)];
//! let omega = |j: usize| if j % 2 == 0 { n("1") } else { n("sqrt2/2") };
//! let profile = [(1, 0, n("1")), (1, 1, n("sqrt2/2")), (0, 1, n("1"))]; // (x_i, z_i, w_i)
//! let mesh = Mesh::mesh(profile.iter().map(|(x, z, _)| {
//!     circle.iter().map(|(a, b)| Point::from_ints(&[x * a, x * b, *z])).collect()
//! }).collect()).unwrap();
//! let weights = Grid::from_fn(3, 9, |i, j| profile[i].2.clone() * omega(j));
//! let knots_v: Vec<Quadratic> = [0, 0, 1, 1, 2, 2, 3, 3, 4, 4].into_iter().map(Quadratic::from_i64).collect();
//! let (s, _) = NurbsSurface::read((2, 2), (vec![n("0"), n("0"), n("1"), n("1")], knots_v), mesh, weights).unwrap();
//! let p = s.eval(&n("1/3"), &n("5/2")).unwrap();
//! assert_eq!(p.dot(&p), Quadratic::from_i64(1));
//! assert_eq!(s.eval(&n("1/2"), &n("1/2")).unwrap().to_text(), "(1/2, 1/2, √2/2)");
//! ```

mod convert;
mod derivative;
mod elevate;
mod error;
mod eval;
mod extract;
mod insert;
mod lines;
mod nurbs;
mod surface;
mod text;

pub use error::{Direction, NotSingle, SplineSurfaceError};
pub use eval::DeBoorStep;
pub use extract::{BezierPatches, Rectangle};
pub use lines::LinesError;
pub use nurbs::NurbsSurface;
pub use surface::BSplineSurface;

pub use cagd_bspline::{KnotConvention, KnotVector};
