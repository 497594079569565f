//! The triangular Bézier patch: its control net and how to read it.

use crate::index::{control_point_count, multi_indices, pos, position};
use crate::{MultiIndex, TriangleError};
use cagd_linalg::Point;
use cagd_scalar::Scalar;
use std::fmt;

/// A triangular Bézier patch of degree n,
///
/// b(r, s, t) = Σ_{i+j+k=n} b_{ijk} B^n_{ijk}(r, s, t),  r + s + t = 1,
///
/// with (n + 1)(n + 2)/2 control points b_{ijk} stored in the order of
/// [`crate::multi_indices`]: b_{n,0,0}; b_{n-1,1,0}, b_{n-1,0,1}; b_{n-2,2,0}, ... ; b_{0,0,n}
/// (lexicographic descending in i, then in j).
///
/// The corners are b_{n,0,0} = b(e1), b_{0,n,0} = b(e2), b_{0,0,n} = b(e3); in the parameters
/// (u, v) of the domain triangle (0, 0), (1, 0), (0, 1), r = 1 - u - v, s = u, t = v.
#[derive(Clone, PartialEq)]
pub struct TriangularPatch<S> {
    degree: usize,
    points: Vec<Point<S>>,
}

impl<S: Scalar> TriangularPatch<S> {
    /// The patch of degree n with these control points, in the order of
    /// [`crate::multi_indices`].
    ///
    /// Errors: [`TriangleError::WrongPointCount`] unless there are (n + 1)(n + 2)/2 points,
    /// [`TriangleError::MixedDimensions`] if two points have different dimensions.
    ///
    /// ```
    /// use cagd_linalg::Point;
    /// use cagd_scalar::BigRational;
    /// use cagd_triangle::TriangularPatch;
    /// let pts: Vec<Point<BigRational>> = (0..5).map(|m| Point::from_ints(&[m, 0, 0])).collect();
    /// let err = TriangularPatch::try_new(2, pts).unwrap_err();
    /// assert_eq!(
    ///     err.to_string(),
    ///     "a triangular patch of degree 2 needs (2 + 1)(2 + 2)/2 = 6 control points, found 5"
    /// );
    /// ```
    pub fn try_new(degree: usize, points: Vec<Point<S>>) -> Result<Self, TriangleError> {
        let needed = control_point_count(degree).ok_or_else(|| TriangleError::DegreeTooLarge {
            degree: degree.to_string(),
        })?;
        if points.len() != needed {
            return Err(TriangleError::WrongPointCount {
                degree,
                needed,
                found: points.len(),
            });
        }
        let expected = points.first().map_or(0, Point::dim);
        for (index, p) in multi_indices(degree).zip(&points) {
            if p.dim() != expected {
                return Err(TriangleError::MixedDimensions {
                    index,
                    found: p.dim(),
                    expected,
                });
            }
        }
        Ok(TriangularPatch { degree, points })
    }

    /// The patch of degree n whose control points are given by a function of (i, j, k), e.g.
    /// the points b_{ijk} = (i/n, j/n, f(i, j, k)) of a function over the domain.
    pub fn from_fn(
        degree: usize,
        f: impl FnMut(MultiIndex) -> Point<S>,
    ) -> Result<Self, TriangleError> {
        Self::try_new(degree, multi_indices(degree).map(f).collect())
    }

    /// A net whose count and dimensions are right by construction (the algorithms of the crate).
    pub(crate) fn from_valid(degree: usize, points: Vec<Point<S>>) -> Self {
        TriangularPatch { degree, points }
    }

    /// The degree n.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The dimension of the control points (2, 3, 4 for homogeneous points, ...).
    pub fn dim(&self) -> usize {
        self.points.first().map_or(0, Point::dim)
    }

    /// The control points, in the order of [`crate::multi_indices`].
    pub fn points(&self) -> &[Point<S>] {
        &self.points
    }

    /// The control points, consuming the patch.
    pub fn into_points(self) -> Vec<Point<S>> {
        self.points
    }

    /// The control point b_{ijk}, or [`TriangleError::NotAnIndex`] unless i + j + k = n.
    ///
    /// ```
    /// use cagd_linalg::Point;
    /// use cagd_scalar::BigRational;
    /// use cagd_triangle::TriangularPatch;
    /// let pts: Vec<Point<BigRational>> = (0..6).map(|m| Point::from_ints(&[m])).collect();
    /// let patch = TriangularPatch::try_new(2, pts).unwrap();
    /// assert_eq!(patch.point(0, 1, 1).unwrap().to_text(), "(4)");
    /// assert_eq!(
    ///     patch.point(1, 1, 1).unwrap_err().to_string(),
    ///     "b_{1,1,1} is not a control point of a patch of degree 2: 1 + 1 + 1 = 3, not 2"
    /// );
    /// ```
    pub fn point(&self, i: usize, j: usize, k: usize) -> Result<&Point<S>, TriangleError> {
        position(self.degree, i, j, k)
            .and_then(|p| self.points.get(p))
            .ok_or(TriangleError::NotAnIndex {
                index: (i, j, k),
                degree: self.degree,
            })
    }

    /// The control points with their multi-indices, in order.
    pub fn indexed_points(&self) -> impl Iterator<Item = (MultiIndex, &Point<S>)> {
        multi_indices(self.degree).zip(&self.points)
    }

    /// b_{ijk} for a multi-index known to be valid (i is implied by j, k).
    ///
    /// The one indexing of the crate: a patch holds (n + 1)(n + 2)/2 points (checked by
    /// `try_new`, kept by every constructor), so every valid multi-index has its point.
    #[allow(clippy::indexing_slicing)]
    pub(crate) fn at(&self, j: usize, k: usize) -> &Point<S> {
        &self.points[pos(j, k)]
    }

    /// The control net as text, one point a line: `b_{2,0,0} = (0, 0, 0)`.
    pub fn to_text(&self) -> String {
        self.indexed_points()
            .map(|((i, j, k), p)| format!("b_{{{i},{j},{k}}} = {}", p.to_text()))
            .collect::<Vec<_>>()
            .join("\n")
    }

    /// The control net in LaTeX, one `b_{2,0,0} = \left(...\right)` a line, joined by `\\`.
    pub fn to_latex(&self) -> String {
        self.indexed_points()
            .map(|((i, j, k), p)| format!("b_{{{i},{j},{k}}} = {}", p.to_latex()))
            .collect::<Vec<_>>()
            .join(" \\\\\n")
    }
}

impl<S: Scalar> fmt::Display for TriangularPatch<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}

impl<S: Scalar> fmt::Debug for TriangularPatch<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "TriangularPatch(degree {}; ", self.degree)?;
        let parts: Vec<String> = self.points.iter().map(Point::to_text).collect();
        write!(f, "{})", parts.join(", "))
    }
}
