//! The parameter field of cagd-exact: numbers in letters.
//!
//! The notes teach with letters: the circle and the sphere of radius `R`, the truncated cone
//! over the segment `{(a, 0, b), (c, 0, d)}`, the elevation combinations `(2 c_{1,j} + c_{0,j})/3`
//! of a generic mesh. A [`Param`] is a quotient of polynomials in named parameters with
//! coefficients in Q or one Q(√d) (the generalized [`cagd_poly::Poly`] over the monomials
//! [`Letters`]), and it implements the scalar jobs of cagd-scalar ([`cagd_scalar::FieldOps`],
//! [`cagd_scalar::ExactRational`], [`cagd_scalar::SquareRoot`], [`cagd_scalar::Print`]), so every
//! algorithm of the engine runs over it unchanged.
//!
//! ```
//! use cagd_param::Param;
//! use cagd_scalar::{FieldOps, Print, SquareRoot};
//! let r = Param::var("R");
//! let w = <Param as SquareRoot>::sqrt_of(2).unwrap() / Param::from_i64(2);
//! assert_eq!((w * &r).to_text(), "√2 R/2");
//! let (a, c) = (Param::var("a"), Param::var("c"));
//! assert_eq!(((a.clone() * Param::from_i64(2) + &c) / Param::from_i64(3)).to_text(), "(2 a + c)/3");
//! assert_eq!((a.clone() * &a / &a).to_text(), "a");
//! assert_eq!(a.compare(&c), None); // a value in letters has no sign
//! ```
//!
//! See [`Param`] for the normal form (what is and is not reduced).

mod expr;
mod field;
mod letters;
mod parse;
mod print;
mod subst;

pub use expr::{parse_param_expr, ParamExpr};
pub use field::{exact_division, Param, ParamPoly, Ratio};
pub use letters::{Letters, Name};
pub use parse::{parse_param, ParamBuilder};
pub use print::{json, latex, text};

#[cfg(test)]
mod tests;
