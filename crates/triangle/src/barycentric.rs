//! Barycentric points (r, s, t), r + s + t = 1, and directions (a, b, c), a + b + c = 0.
//!
//! The domain triangle has the vertices e1 = (1, 0, 0), e2 = (0, 1, 0), e3 = (0, 0, 1). In the
//! plane of the parameters (u, v) it is the triangle (0, 0), (1, 0), (0, 1), with
//! r = 1 - u - v, s = u, t = v.

use crate::TriangleError;
use cagd_scalar::Scalar;
use std::fmt;

fn triple_text<S: Scalar>(c: &[S; 3]) -> String {
    format!(
        "({}, {}, {})",
        c[0].to_text(),
        c[1].to_text(),
        c[2].to_text()
    )
}

fn sum<S: Scalar>(c: &[S; 3]) -> S {
    c[0].add_ref(&c[1]) + &c[2]
}

/// A point of the plane of the domain triangle in barycentric coordinates (r, s, t),
/// r + s + t = 1. Inside the triangle all three are ≥ 0; outside some is negative
/// (evaluation there extrapolates the patch).
#[derive(Clone, PartialEq)]
pub struct Barycentric<S> {
    coords: [S; 3],
}

impl<S: Scalar> Barycentric<S> {
    /// The point (r, s, t), or [`TriangleError::BarycentricSum`] unless r + s + t = 1.
    ///
    /// The check is exact for the exact scalar types. For `f64` it is the floating-point sum, so
    /// `(0.3, 0.6, 0.1)` is rejected (it sums to 0.9999999999999999); build such points with
    /// [`Barycentric::from_uv`], which is valid by construction.
    ///
    /// ```
    /// use cagd_scalar::{q, BigRational};
    /// use cagd_triangle::Barycentric;
    /// assert!(Barycentric::try_new(q!(1/2), q!(1/4), q!(1/4)).is_ok());
    /// let err = Barycentric::try_new(q!(1/2), q!(1/3), q!(1/3)).unwrap_err();
    /// assert_eq!(
    ///     err.to_string(),
    ///     "barycentric coordinates (1/2, 1/3, 1/3) sum to 7/6, not 1 (r + s + t = 1 is needed)"
    /// );
    /// ```
    pub fn try_new(r: S, s: S, t: S) -> Result<Self, TriangleError> {
        let coords = [r, s, t];
        let total = sum(&coords);
        if total.is_one() {
            Ok(Barycentric { coords })
        } else {
            Err(TriangleError::BarycentricSum {
                coords: triple_text(&coords),
                sum: total.to_text(),
            })
        }
    }

    /// The point (u, v) of the parameter plane: (r, s, t) = (1 - u - v, u, v).
    ///
    /// ```
    /// use cagd_scalar::{q, BigRational};
    /// use cagd_triangle::Barycentric;
    /// let x = Barycentric::from_uv(q!(1/2), q!(1/3));
    /// assert_eq!(x.to_text(), "(1/6, 1/2, 1/3)");
    /// ```
    pub fn from_uv(u: S, v: S) -> Self {
        let r = S::one() - &u - &v;
        Barycentric { coords: [r, u, v] }
    }

    /// The first negative coordinate, 0, 1 or 2 for r, s or t, with its value: `None` when
    /// the point lies in the closed domain triangle (r, s, t ≥ 0). A coordinate whose sign is
    /// not decided (in letters) counts as inside, as a curve's domain check takes a parameter
    /// in letters.
    ///
    /// ```
    /// use cagd_scalar::{q, BigRational};
    /// use cagd_triangle::Barycentric;
    /// assert!(Barycentric::from_uv(q!(1/2), q!(1/2)).first_negative().is_none());
    /// let x = Barycentric::from_uv(q!(2/3), q!(2/3));
    /// assert_eq!(x.first_negative(), Some((0, &q!(-1/3))));
    /// ```
    pub fn first_negative(&self) -> Option<(usize, &S)> {
        let zero = S::zero();
        self.coords.iter().enumerate().find(|(_, c)| **c < zero)
    }

    /// The vertex e1 = (1, 0, 0), the corner (u, v) = (0, 0).
    pub fn e1() -> Self {
        Barycentric {
            coords: [S::one(), S::zero(), S::zero()],
        }
    }

    /// The vertex e2 = (0, 1, 0), the corner (u, v) = (1, 0).
    pub fn e2() -> Self {
        Barycentric {
            coords: [S::zero(), S::one(), S::zero()],
        }
    }

    /// The vertex e3 = (0, 0, 1), the corner (u, v) = (0, 1).
    pub fn e3() -> Self {
        Barycentric {
            coords: [S::zero(), S::zero(), S::one()],
        }
    }

    /// The vertices e1, e2, e3.
    pub fn vertices() -> [Self; 3] {
        [Self::e1(), Self::e2(), Self::e3()]
    }

    /// The centroid (1/3, 1/3, 1/3).
    pub fn centroid() -> Self {
        let third = S::from_ratio(1, 3);
        Barycentric {
            coords: [third.clone(), third.clone(), third],
        }
    }

    /// The affine combination (1 - λ) self + λ other, a point of the line through both.
    pub fn lerp(&self, other: &Self, lambda: &S) -> Self {
        let mu = S::one() - lambda;
        // (1 - λ)(r + s + t) + λ(r' + s' + t') = 1, so the sum stays 1 by construction.
        let [a0, a1, a2] = &self.coords;
        let [b0, b1, b2] = &other.coords;
        let mix = |a: &S, b: &S| a.mul_ref(&mu) + b.mul_ref(lambda);
        Barycentric {
            coords: [mix(a0, b0), mix(a1, b1), mix(a2, b2)],
        }
    }

    /// r, the weight of the vertex e1.
    pub fn r(&self) -> &S {
        &self.coords[0]
    }

    /// s = u, the weight of the vertex e2.
    pub fn s(&self) -> &S {
        &self.coords[1]
    }

    /// t = v, the weight of the vertex e3.
    pub fn t(&self) -> &S {
        &self.coords[2]
    }

    /// (r, s, t).
    pub fn coords(&self) -> &[S; 3] {
        &self.coords
    }

    /// The parameters (u, v) = (s, t).
    pub fn to_uv(&self) -> (S, S) {
        (self.coords[1].clone(), self.coords[2].clone())
    }

    /// Plain text: `(1/3, 1/3, 1/3)`.
    pub fn to_text(&self) -> String {
        triple_text(&self.coords)
    }
}

impl<S: Scalar> fmt::Display for Barycentric<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}

impl<S: Scalar> fmt::Debug for Barycentric<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Barycentric{}", self.to_text())
    }
}

/// A direction in the plane of the domain triangle, as a barycentric vector (a, b, c) with
/// a + b + c = 0: the difference of two barycentric points.
///
/// The partial derivatives in u and v are the directional derivatives along
/// [`Direction::du`] = e2 - e1 = (-1, 1, 0) and [`Direction::dv`] = e3 - e1 = (-1, 0, 1).
#[derive(Clone, PartialEq)]
pub struct Direction<S> {
    coords: [S; 3],
}

impl<S: Scalar> Direction<S> {
    /// The direction (a, b, c), or [`TriangleError::DirectionSum`] unless a + b + c = 0.
    ///
    /// ```
    /// use cagd_scalar::{q, BigRational};
    /// use cagd_triangle::Direction;
    /// assert!(Direction::try_new(q!(-1), q!(1/2), q!(1/2)).is_ok());
    /// let err = Direction::try_new(q!(1), q!(1), q!(0)).unwrap_err();
    /// assert_eq!(
    ///     err.to_string(),
    ///     "direction (1, 1, 0) has components summing to 2, not 0 \
    ///      (a direction is a difference of two barycentric points)"
    /// );
    /// ```
    pub fn try_new(a: S, b: S, c: S) -> Result<Self, TriangleError> {
        let coords = [a, b, c];
        let total = sum(&coords);
        if total.is_zero() {
            Ok(Direction { coords })
        } else {
            Err(TriangleError::DirectionSum {
                components: triple_text(&coords),
                sum: total.to_text(),
            })
        }
    }

    /// The direction `to - from`.
    pub fn between(from: &Barycentric<S>, to: &Barycentric<S>) -> Self {
        Direction {
            coords: {
                let [a0, a1, a2] = &from.coords;
                let [b0, b1, b2] = &to.coords;
                [b0.sub_ref(a0), b1.sub_ref(a1), b2.sub_ref(a2)]
            },
        }
    }

    /// The vector (du, dv) of the parameter plane: (-du - dv, du, dv).
    pub fn from_uv(du: S, dv: S) -> Self {
        let a = -(du.add_ref(&dv));
        Direction {
            coords: [a, du, dv],
        }
    }

    /// e2 - e1 = (-1, 1, 0): the direction of ∂/∂u.
    pub fn du() -> Self {
        Direction {
            coords: [-S::one(), S::one(), S::zero()],
        }
    }

    /// e3 - e1 = (-1, 0, 1): the direction of ∂/∂v.
    pub fn dv() -> Self {
        Direction {
            coords: [-S::one(), S::zero(), S::one()],
        }
    }

    /// (a, b, c).
    pub fn coords(&self) -> &[S; 3] {
        &self.coords
    }

    /// Plain text: `(-1, 1, 0)`.
    pub fn to_text(&self) -> String {
        triple_text(&self.coords)
    }
}

impl<S: Scalar> fmt::Display for Direction<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}

impl<S: Scalar> fmt::Debug for Direction<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Direction{}", self.to_text())
    }
}
