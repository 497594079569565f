//! Benchmarks of cagd-exact: the tasks T1-T6 of the performance issue, the worked examples
//! and generated problem sets, and the inputs of the side-by-side comparison with SymPy and
//! python-flint (`peers/run.sh`).
//!
//! Every input is drawn from a fixed seed: coordinates are small rationals p/q with
//! p in [-9, 9] and q in 1..9; parameters are rationals p/q in [0, 1] with q in 1..9.
//!
//! | task | what |
//! | --- | --- |
//! | T1 | evaluate an (n, n) patch at 100 parameter pairs (u, v) |
//! | T2 | elevate an (n, n) patch to (n + k, n + k) |
//! | T3 | restrict an (n, n) patch to [1/3, 3/4] x [1/5, 1/2] |
//! | T4 | interpolate an (n + 1) x (n + 1) grid at u_i = i/n, v_j = j/n by an (n, n) patch |
//! | T5 | the closed form (monomial coefficients) of an (n, n) patch |
//! | T6 | least squares by an (n, n) patch from M scattered points |
//!
//! The task functions are generic over [`Scalar`], so the same code runs over `BigRational`
//! (the product) and over `f64` (the ratio "exact vs f64" of `docs/performance.md`).

mod input;
mod rng;
mod tasks;

pub use input::{Input, Prepared, Rational};
pub use rng::Rng;
pub use tasks::{
    examples_fixtures, generated_problems, run_examples, run_problems, Answer, Kind, Task, TASKS,
};

pub use cagd_scalar::Scalar;
