//! Triangular Bézier patches over any [`Scalar`](cagd_scalar::Scalar).
//!
//! Chapter 6 of the notes closes its introduction with the motivation: tensor-product patches
//! need degenerate meshes to close a sphere and fit scattered data badly, so one generalizes
//! Bézier curves to *triangular* control nets. This crate is that generalization, in the
//! barycentric form of Farin (*Curves and Surfaces for CAGD*, chapter "Triangular Bézier
//! patches"; "Triangular Bernstein-Bézier patches", CAGD 3, 1986):
//!
//! - the domain is a triangle; a point of it has barycentric coordinates (r, s, t),
//!   r + s + t = 1 ([`Barycentric`]); in the parameters (u, v) of the triangle
//!   (0, 0), (1, 0), (0, 1), r = 1 - u - v, s = u, t = v;
//! - a patch of degree n has (n + 1)(n + 2)/2 control points b_{ijk}, i + j + k = n
//!   ([`TriangularPatch`], ordered as [`multi_indices`]), and is
//!   b(r, s, t) = Σ b_{ijk} B^n_{ijk}(r, s, t) with the Bernstein polynomials
//!   B^n_{ijk} = n!/(i! j! k!) r^i s^j t^k ([`bernstein`]);
//! - it is evaluated by that sum or by De Casteljau on triangles, with every level available
//!   ([`TriangularPatch::de_casteljau`]); its blossom b[x_1, ..., x_n]
//!   ([`TriangularPatch::blossom`]) gives subdivision ([`TriangularPatch::restrict`],
//!   [`TriangularPatch::split`]); degree elevation, directional derivatives along a
//!   [`Direction`] (a + b + c = 0), the boundary curves and the closed form in (u, v)
//!   ([`TriangularPatch::closed_form`], a `cagd_poly::VecPoly`) complete the toolkit.
//!
//! Nothing rounds: over `BigRational` or `Quadratic` every answer is exact.
//!
//! ```
//! use cagd_linalg::Point;
//! use cagd_scalar::{q, BigRational};
//! use cagd_triangle::{Barycentric, TriangularPatch};
//! // a quadratic patch: the graph of z = u v over the domain triangle
//! // (b_{ijk} = (j/2, k/2, z_{ijk}) with z_{011} = 1/2 and all other z = 0)
//! let half = |m: usize| BigRational::new((m as i64).into(), 2.into());
//! let net: Vec<Point<BigRational>> = cagd_triangle::multi_indices(2)
//!     .map(|(_, j, k)| {
//!         let z = if (j, k) == (1, 1) { q!(1/2) } else { q!(0) };
//!         Point::new(vec![half(j), half(k), z])
//!     })
//!     .collect();
//! let patch = TriangularPatch::try_new(2, net).unwrap();
//! let x = Barycentric::from_uv(q!(1/2), q!(1/3));
//! assert_eq!(patch.evaluate(&x).to_text(), "(1/2, 1/3, 1/6)");
//! assert_eq!(patch.evaluate(&x), patch.evaluate_bernstein(&x));
//! ```

mod barycentric;
mod bernstein;
mod blossom;
mod boundary;
mod closed_form;
mod de_casteljau;
mod derivative;
mod elevation;
mod error;
mod index;
mod patch;
mod subdivision;

pub use barycentric::{Barycentric, Direction};
pub use bernstein::{bernstein, bernstein_basis, multinomial};
pub use boundary::Edge;
pub use de_casteljau::{DeCasteljau, Level};
pub use error::{Spatial, TriangleError};
pub use index::{control_point_count, multi_indices, position, MultiIndex};
pub use patch::TriangularPatch;
