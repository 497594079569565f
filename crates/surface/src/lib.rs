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
//! mesh; [`Grid::map_rows`] and [`Grid::map_columns`] are those passes, and the curve
//! algorithms are those of `cagd-bezier`. Rational patches (5) run the polynomial algorithm on
//! the homogeneous mesh `(w c, w)` and project.
//!
//! One operation family per file:
//!
//! | file | what | notes |
//! | --- | --- | --- |
//! | `eval.rs` | matrix form, De Casteljau in both orders, rational quotient | (1), (5), (9)-(11) |
//! | `closed_form.rs` | closed forms, the graph of f(x, y) | (1)-(3), (5) |
//! | `boundary.rs` | boundary curves and corners | §3 |
//! | `hull.rs` | exact convex-hull test | §3 |
//! | `blossom.rs` | polar form, restriction, subdivision | (12), (13) |
//! | `elevate.rs` | degree elevation | (14), (15) |
//! | `derivative.rs` | differences, partial and cross-boundary derivatives, twists | (16)-(20), (24) |
//! | `normal.rs` | normal field and normals at the corners | (25) |
//! | `join.rs` | C^r joins and C^r neighbours | (21)-(23) |
//!
//! Every parameter a method takes is a parameter of the patch's [`Domain`] (by default
//! [0, 1] x [0, 1]); the typed `eval` rejects parameters outside it, the raw algorithms
//! extrapolate.
//!
//! ```
//! use cagd_surface::BezierSurface;
//! use cagd_linalg::Point;
//! use cagd_scalar::{q, BigRational};
//! let p = |c: &[i64]| Point::from_ints(c);
//! let s = BezierSurface::<BigRational>::from_rows(vec![
//!     vec![p(&[0, 0, 0]), p(&[1, 0, 4]), p(&[2, 0, 3])],
//!     vec![p(&[0, 2, 1]), p(&[1, 2, 5]), p(&[2, 2, 4])],
//!     vec![p(&[0, 4, 0]), p(&[1, 4, 4]), p(&[2, 4, 3])],
//! ]).unwrap();
//! let (u, v) = (q!(1/2), q!(1/3));
//! let x = s.eval(&u, &v).unwrap();
//! assert_eq!(x, s.eval_matrix(&u, &v));
//! assert_eq!(x, s.de_casteljau_rows_first(&u, &v).unwrap());
//! assert_eq!(x.to_text(), "(2/3, 2, 47/18)");
//! ```

mod blossom;
mod boundary;
mod closed_form;
mod curvature;
mod derivative;
mod domain;
mod elevate;
mod error;
mod eval;
mod fast;
mod grid;
mod hull;
mod join;
mod normal;
mod patch;

pub use blossom::{Quadrants, Restriction};
pub use curvature::{gaussian_numerator, gaussian_numerator_rational, CurvatureError};
pub use domain::{Border, Corner, Domain};
pub use error::{Computation, Positive, SurfaceError};
pub use eval::DeCasteljauStep;
pub use grid::{Grid, Mesh};
pub use hull::in_convex_hull;
pub use join::{
    c1_neighbour_columns, c1_neighbour_rows, continuity, ConditionFails, Continuity,
    FailedCondition, Join, Smoothness,
};
pub use normal::{CornerNormal, Degeneracy, DegenerateCorner, LimitDirection, NormalAtCorner};
pub use patch::{BezierSurface, RationalBezierSurface};

pub use cagd_linalg::Point;
pub use cagd_scalar::Scalar;
