//! Directional derivatives, derivative patches and the normal vector.

use crate::bernstein::int;
use crate::de_casteljau::step;
use crate::{Barycentric, Direction, TriangleError, TriangularPatch};
use cagd_linalg::Point;
use cagd_record::NoSteps;
use cagd_scalar::Scalar;

impl<S: Scalar> TriangularPatch<S> {
    /// The derivative of the patch in the direction d (a + b + c = 0), as a patch of degree
    /// n - 1 whose control points are vectors: one De Casteljau step with d, times n,
    ///
    /// D_d b = n Σ_{i+j+k=n-1} (d_1 b_{i+1,j,k} + d_2 b_{i,j+1,k} + d_3 b_{i,j,k+1}) B^{n-1}_{ijk}.
    ///
    /// For a patch of degree 0 (a constant) it is the zero vector, as a patch of degree 0.
    ///
    /// ```
    /// use cagd_linalg::Point;
    /// use cagd_scalar::BigRational;
    /// use cagd_triangle::{Direction, TriangularPatch};
    /// // the plane z = 2u + 3v as a linear patch over the corners (0,0), (1,0), (0,1)
    /// let net = vec![
    ///     Point::from_ints(&[0, 0, 0]),
    ///     Point::from_ints(&[1, 0, 2]),
    ///     Point::from_ints(&[0, 1, 3]),
    /// ];
    /// let patch = TriangularPatch::<BigRational>::try_new(1, net).unwrap();
    /// assert_eq!(patch.derivative(&Direction::du()).points()[0].to_text(), "(1, 0, 2)");
    /// assert_eq!(patch.derivative(&Direction::dv()).points()[0].to_text(), "(0, 1, 3)");
    /// ```
    pub fn derivative(&self, d: &Direction<S>) -> Self {
        let n = self.degree();
        match n.checked_sub(1) {
            None => TriangularPatch::from_valid(0, vec![Point::zero(self.dim())]),
            Some(m) => {
                let factor = int::<S>(n);
                let points = step(self.points(), m, d.coords())
                    .into_iter()
                    .map(|p| p.scale(&factor))
                    .collect();
                TriangularPatch::from_valid(m, points)
            }
        }
    }

    /// The directional derivative D_d b(x) at the point x: the first De Casteljau step in the
    /// direction d, the remaining n - 1 steps at x, times n,
    ///
    /// D_d b(x) = n Σ_{i+j+k=n-1} (d_1 b_{i+1,j,k} + d_2 b_{i,j+1,k} + d_3 b_{i,j,k+1}) B^{n-1}_{ijk}(x)
    ///          = n b[d, x, ..., x]  (the blossom with one direction).
    ///
    /// The partial derivatives are ∂b/∂u = D_{e2-e1} b and ∂b/∂v = D_{e3-e1} b
    /// ([`Direction::du`], [`Direction::dv`]).
    pub fn directional_derivative(&self, x: &Barycentric<S>, d: &Direction<S>) -> Point<S> {
        self.derivative(d).evaluate(x)
    }

    /// The mixed directional derivative D_{d_1} ... D_{d_r} b(x) of order r:
    ///
    /// n!/(n - r)! · b[d_1, ..., d_r, x, ..., x]  (x repeated n - r times),
    ///
    /// the blossom extended multilinearly to directions; zero when r > n.
    pub fn higher_derivative(&self, x: &Barycentric<S>, directions: &[Direction<S>]) -> Point<S> {
        let n = self.degree();
        let r = directions.len();
        if r > n {
            return Point::zero(self.dim());
        }
        let factor = (n - r + 1..=n).fold(S::one(), |acc, m| acc * int::<S>(m));
        let args = directions
            .iter()
            .map(Direction::coords)
            .chain(std::iter::repeat_n(x.coords(), n - r));
        self.blossom_triples(args, &mut NoSteps).scale(&factor)
    }

    /// The normal vector ∂b/∂u × ∂b/∂v at x, not normalized (so that it stays exact). Errors
    /// with [`TriangleError::DimensionNotThree`] unless the control points are in R^3.
    pub fn normal(&self, x: &Barycentric<S>) -> Result<Point<S>, TriangleError> {
        let bu = self.directional_derivative(x, &Direction::du());
        let bv = self.directional_derivative(x, &Direction::dv());
        bu.cross(&bv).map_err(|_| TriangleError::DimensionNotThree {
            what: crate::Spatial::NormalVector,
            found: self.dim(),
        })
    }
}
