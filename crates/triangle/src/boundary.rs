//! The boundary of a triangular patch: three Bézier curves and three corners.

use crate::{Barycentric, TriangularPatch};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// An edge of the domain triangle, named by the barycentric coordinate that vanishes on it and
/// oriented counterclockwise in the parameter plane (u, v).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Edge {
    /// t = 0 (v = 0): from e1 = (0, 0) to e2 = (1, 0); control points b_{n-l,l,0}.
    T0,
    /// r = 0 (u + v = 1): from e2 = (1, 0) to e3 = (0, 1); control points b_{0,n-l,l}.
    R0,
    /// s = 0 (u = 0): from e3 = (0, 1) to e1 = (0, 0); control points b_{l,0,n-l}.
    S0,
}

impl Edge {
    /// The three edges, counterclockwise: t = 0, r = 0, s = 0.
    pub const ALL: [Edge; 3] = [Edge::T0, Edge::R0, Edge::S0];

    /// The first and last vertex of the edge.
    pub fn endpoints<S: Scalar>(self) -> (Barycentric<S>, Barycentric<S>) {
        match self {
            Edge::T0 => (Barycentric::e1(), Barycentric::e2()),
            Edge::R0 => (Barycentric::e2(), Barycentric::e3()),
            Edge::S0 => (Barycentric::e3(), Barycentric::e1()),
        }
    }

    /// The point (1 - λ) start + λ end of the edge.
    pub fn point_at<S: Scalar>(self, lambda: &S) -> Barycentric<S> {
        let (start, end) = self.endpoints::<S>();
        start.lerp(&end, lambda)
    }

    /// The multi-index of the l-th control point of the edge's curve (degree n).
    fn index(self, n: usize, l: usize) -> (usize, usize, usize) {
        match self {
            Edge::T0 => (n - l, l, 0),
            Edge::R0 => (0, n - l, l),
            Edge::S0 => (l, 0, n - l),
        }
    }
}

impl<S: Scalar> TriangularPatch<S> {
    /// The control polygon of the boundary curve over an edge: a Bézier curve of degree n,
    /// c(λ) = b((1 - λ) start + λ end) = Σ_l c_l B^n_l(λ), whose control points are the
    /// control points of the patch on that edge (the Bernstein polynomials with the vanishing
    /// coordinate's index nonzero vanish there):
    ///
    /// - t = 0: c_l = b_{n-l,l,0};  r = 0: c_l = b_{0,n-l,l};  s = 0: c_l = b_{l,0,n-l}.
    ///
    /// ```
    /// use cagd_linalg::Point;
    /// use cagd_scalar::BigRational;
    /// use cagd_triangle::{Edge, TriangularPatch};
    /// let net: Vec<Point<BigRational>> = (0..6).map(|m| Point::from_ints(&[m])).collect();
    /// let patch = TriangularPatch::try_new(2, net).unwrap();
    /// let texts = |e| patch.boundary_curve(e).iter().map(|p| p.to_text()).collect::<Vec<_>>();
    /// assert_eq!(texts(Edge::T0), ["(0)", "(1)", "(3)"]);
    /// assert_eq!(texts(Edge::R0), ["(3)", "(4)", "(5)"]);
    /// assert_eq!(texts(Edge::S0), ["(5)", "(2)", "(0)"]);
    /// ```
    pub fn boundary_curve(&self, edge: Edge) -> Vec<Point<S>> {
        let n = self.degree();
        (0..=n)
            .map(|l| {
                let (_, j, k) = edge.index(n, l);
                self.at(j, k).clone()
            })
            .collect()
    }

    /// The corners b_{n,0,0} = b(e1), b_{0,n,0} = b(e2), b_{0,0,n} = b(e3).
    pub fn corners(&self) -> [&Point<S>; 3] {
        let n = self.degree();
        [self.at(0, 0), self.at(n, 0), self.at(0, n)]
    }
}
