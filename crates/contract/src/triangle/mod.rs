//! The shape of a triangular Bézier patch: `{"triangle": [[b_{n,0,0}], [b_{n-1,1,0},
//! b_{n-1,0,1}], ..., [b_{0,n,0}, ..., b_{0,0,n}]]}`, row m holding the m + 1 points
//! b_{n-m, m-k, k}, k = 0, ..., m (the order of `cagd_triangle::multi_indices`); the degree n is
//! the number of rows less one. The same shape in problems and in answers, so an answer feeds
//! back.

pub mod net;
mod patch;

pub use net::TriangleIn;
pub use patch::{exact_input, exact_triangle, weight_rows};
pub use patch::{square_map, square_surface};
