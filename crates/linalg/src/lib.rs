//! Points, vectors and matrices over any [`Scalar`], and exact linear algebra.
//!
//! A [`Point`] is a point (or vector) of any dimension: the control points of curves and
//! surfaces, in R^2, R^3 or homogeneous R^4. A [`Matrix`] is a dense row-major matrix. Both are
//! generic over [`Scalar`]; nothing here rounds.
//!
//! Square systems are solved exactly by a [`Factorization`] computed once and reused for many
//! right-hand sides: scalars, points (one system per coordinate, as the notes' interpolation
//! problems need) and matrices. When every entry is rational the elimination is fraction-free
//! (Bareiss, on integer numerators); otherwise it is Gaussian elimination in the scalar type.
//! Overdetermined systems are solved in the least-squares sense by the normal equations
//! BᵗB c = Bᵗa ([`NormalEquations`], the notes' chapter 5, eq. (29)).

mod bareiss;
mod error;
pub mod exact;
mod least_squares;
mod matrix;
mod modular;
mod point;
mod solve;

pub use error::{LinalgError, Operands, Singularity};
pub use least_squares::{least_squares, least_squares_points, NormalEquations};
pub use matrix::Matrix;
pub use modular::on_this_thread;
pub use point::Point;
pub use solve::{
    determinant, inverse, solve, solve_matrix, solve_points, Elimination, Factorization,
};

pub use cagd_scalar::Scalar;
