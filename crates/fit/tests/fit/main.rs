//! Integration tests of cagd-fit (one test binary): every fit checked exactly against an
//! independent route (De Boor evaluation, Bézier pieces, Bernstein sums, the matrix form).

mod common;
mod curves;
mod fast_paths;
mod grid;
mod scattered;
mod spline_grid;
