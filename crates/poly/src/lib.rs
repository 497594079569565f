//! Exact polynomials for cagd-exact: closed forms such as `(u, v, -u^3 v + u^3 + u^2 v)`.
//!
//! - [`Poly`]: a polynomial in the variables `u, v, w, t, s, x, y, z` ([`Var`]) with
//!   coefficients in any [`Scalar`], stored sparsely so that `==` is exact; ring operations,
//!   [`Poly::partial`], [`Poly::eval`], [`Poly::substitute`], affine reparametrizations.
//! - [`VecPoly`]: a polynomial map into R^d (curves and surfaces; `dot`, `cross`).
//! - [`RationalMap`]: a vector numerator over a common denominator (rational curves and
//!   surfaces, from homogeneous maps with the weight last).
//! - The Bernstein basis `B_i^n(t) = C(n, i) t^i (1 - t)^(n - i)` ([`bernstein`]) and the change
//!   of basis in one variable ([`poly_from_bernstein_1d`], [`to_bernstein_1d`],
//!   [`from_bernstein_1d`], [`control_polygon`]) and in two ([`poly_from_bernstein_2d`],
//!   [`to_bernstein_2d`], [`from_bernstein_2d`], [`control_mesh`]).
//! - [`parse_expr`]: expressions of the one grammar of `cagd-scalar`, read with its parser.
//!
//! # Term order
//!
//! The printers ([`Poly::to_text`], [`Poly::to_latex`], [`Poly::to_json_string`]) list the
//! terms from the largest monomial down in the **graded lexicographic order** with
//! `u > v > w > t > s > x > y > z`: descending total degree, and among terms of the same total
//! degree, the higher power of `u` first, then of `v`, and so on. So the ruled surface of
//! chapter 6, printed in the notes as `u^3 - u^3v + u^2v`, prints here as
//! `-u^3 v + u^3 + u^2 v`:
//!
//! ```
//! use cagd_poly::parse_expr;
//! let c = parse_expr("(1 - v)*(u, 0, u^3) + v*(u, 1, u^2)").unwrap();
//! assert_eq!(c.to_text(), "(u, v, -u^3 v + u^3 + u^2 v)");
//! assert_eq!(c.to_latex(), r"\left(u, v, -u^{3} v + u^{3} + u^{2} v\right)");
//! assert_eq!(c.to_json_string(), "(u, v, -u^3*v + u^3 + u^2*v)");
//! assert_eq!(parse_expr(&c.to_json_string()).unwrap(), c);
//! assert_eq!(parse_expr(&c.to_text()).unwrap(), c);
//! ```
//!
//! Coefficients print with [`cagd_scalar::Print::to_text`] (`3/2 u^2`, `√2/2 v`, `-u`); a
//! coefficient of two terms is parenthesized (`(1/2 + √2) u`); factors are separated by a space
//! (`u^2 v`).

mod bernstein;
mod calculus;
mod error;
mod fast;
mod form;
mod integral;
mod parse;
mod poly;
mod print;
mod rational;
mod roots;
mod sign;
mod square_root;
mod terms;
mod var;
mod vecpoly;

pub use bernstein::{
    bernstein, control_mesh, control_polygon, from_bernstein_1d, from_bernstein_2d,
    from_bernstein_2d_rational, poly_from_bernstein_1d, poly_from_bernstein_2d, to_bernstein_1d,
    to_bernstein_2d,
};
pub use error::{
    BadRoot, Control, Form, Misuse, Operands, PolyError, TooLarge, Unconvertible, Vanishes,
};
pub use form::{contact_order, ClosedForm};
pub use integral::{enclosed_area, planar_patch_area, AreaError, EnclosedArea, PatchArea};
pub use parse::{
    parse_expr, parse_expr_with, parse_poly, parse_vec_poly, Expr, MAX_COEFFICIENT_WORDS,
    MAX_DEGREE, MAX_PRODUCTS,
};
pub use poly::{Poly, Term};
pub use rational::RationalMap;
pub use roots::{common_roots, ExactRoot, Roots, RootsError};
pub use sign::{
    bernstein_halves, combine_zero_sets, sign_on, zero_set, PieceZeros, ZeroSet, SIGN_HALVINGS,
    ZERO_SET_LEVELS,
};
pub use var::{Monomial, Var, NVARS};
pub use vecpoly::VecPoly;

pub use cagd_scalar::Scalar;

#[cfg(test)]
mod props;
#[cfg(test)]
mod tests;
