//! Which scalar a problem runs in.
//!
//! Every number of a problem is read exactly, once ([`crate::spec`]), and the reading notes
//! the square roots it meets. If none has a square root, the problem runs over `BigRational`;
//! if they all live in one Q(√d), or the operation needs one (a surface of revolution needs
//! √2/2 for quarter circles), it runs over the quadratic field; two different roots are an
//! error naming both.

/// The deepest nesting of lists and objects a problem may have (as `serde_json` reads).
pub const MAX_NESTING: usize = 128;

/// The number field of a problem.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NumberField {
    /// The rationals Q.
    Rational,
    /// Q(√d).
    Quadratic(u64),
    /// Quotients of polynomials in the problem's parameters, with coefficients in Q (`0`) or
    /// Q(√d).
    Letters(u64),
}
