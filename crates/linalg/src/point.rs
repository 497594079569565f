//! Points and vectors of any dimension.

use crate::{LinalgError, Operands};
use cagd_scalar::cancel::checkpoint;
use cagd_scalar::Scalar;
use std::fmt;
use std::ops::{Add, Index, IndexMut, Mul, Neg, Sub};

/// A point (or vector) with coordinates in a [`Scalar`]: `(1/2, 5/6, 31/6)`.
///
/// The arithmetic operators require both operands to have the same dimension and panic
/// otherwise; the constructors of curves and surfaces check the dimension of every control
/// point once, so the algorithms never meet mixed dimensions. [`Point::checked_add`] and
/// [`Point::checked_sub`] return an error instead.
#[derive(Clone, PartialEq, Eq, Hash, Default)]
pub struct Point<S> {
    coords: Vec<S>,
}

impl<S: Scalar> Point<S> {
    /// The point with these coordinates.
    pub fn new(coords: Vec<S>) -> Self {
        Point { coords }
    }

    /// The point of integer coordinates, e.g. `Point::from_ints(&[1, 0, -1])`.
    pub fn from_ints(coords: &[i64]) -> Self {
        Point::new(coords.iter().map(|&c| S::from_i64(c)).collect())
    }

    /// The origin (zero vector) of dimension `dim`.
    pub fn zero(dim: usize) -> Self {
        Point::new(vec![S::zero(); dim])
    }

    /// The number of coordinates.
    pub fn dim(&self) -> usize {
        self.coords.len()
    }

    /// The coordinates.
    pub fn coords(&self) -> &[S] {
        &self.coords
    }

    /// The coordinates, consuming the point.
    pub fn into_coords(self) -> Vec<S> {
        self.coords
    }

    /// Every coordinate is zero.
    pub fn is_zero(&self) -> bool {
        self.coords.iter().all(|c| c.is_zero())
    }

    /// `t · self`.
    pub fn scale(&self, t: &S) -> Self {
        checkpoint();
        Point::new(self.coords.iter().map(|c| c.mul_ref(t)).collect())
    }

    /// The affine combination `(1 - t) self + t other`, the step of De Casteljau.
    pub fn lerp(&self, other: &Self, t: &S) -> Self {
        checkpoint();
        let s = S::one() - t;
        Point::new(
            self.coords
                .iter()
                .zip(&other.coords)
                .map(|(a, b)| a.mul_ref(&s) + b.mul_ref(t))
                .collect(),
        )
    }

    /// `Σ coefs[k] · points[k]`; `dim` is the dimension of the result when the list is empty.
    pub fn combination<'a>(
        points: impl IntoIterator<Item = &'a Point<S>>,
        coefs: impl IntoIterator<Item = &'a S>,
        dim: usize,
    ) -> Self {
        let mut acc = Point::zero(dim);
        for (p, c) in points.into_iter().zip(coefs) {
            acc.add_scaled(p, c);
        }
        acc
    }

    /// `self += t · other`, in place.
    pub fn add_scaled(&mut self, other: &Self, t: &S) {
        checkpoint();
        for (a, b) in self.coords.iter_mut().zip(&other.coords) {
            *a += b.mul_ref(t);
        }
    }

    /// The dot product.
    pub fn dot(&self, other: &Self) -> S {
        checkpoint();
        self.coords
            .iter()
            .zip(&other.coords)
            .fold(S::zero(), |acc, (a, b)| acc + a.mul_ref(b))
    }

    /// The cross product of two vectors of R^3.
    pub fn cross(&self, other: &Self) -> Result<Self, LinalgError> {
        match (self.coords(), other.coords()) {
            ([a0, a1, a2], [b0, b1, b2]) => Ok(Point::new(vec![
                a1.mul_ref(b2) - a2.mul_ref(b1),
                a2.mul_ref(b0) - a0.mul_ref(b2),
                a0.mul_ref(b1) - a1.mul_ref(b0),
            ])),
            _ => Err(LinalgError::DimensionMismatch {
                what: Operands::CrossProduct,
                expected: 3,
                found: if self.dim() == 3 {
                    other.dim()
                } else {
                    self.dim()
                },
            }),
        }
    }

    /// `self + other`, or an error when the dimensions differ.
    pub fn checked_add(&self, other: &Self) -> Result<Self, LinalgError> {
        self.same_dim(other, Operands::AddingPoints)?;
        Ok(self + other)
    }

    /// `self - other`, or an error when the dimensions differ.
    pub fn checked_sub(&self, other: &Self) -> Result<Self, LinalgError> {
        self.same_dim(other, Operands::SubtractingPoints)?;
        Ok(self - other)
    }

    /// An error when `other` has another dimension.
    pub fn same_dim(&self, other: &Self, what: Operands) -> Result<(), LinalgError> {
        if self.dim() == other.dim() {
            Ok(())
        } else {
            Err(LinalgError::DimensionMismatch {
                what,
                expected: self.dim(),
                found: other.dim(),
            })
        }
    }

    /// The homogeneous point `(w x, w y, ..., w)` of R^{d+1} (weight last).
    pub fn to_homogeneous(&self, w: &S) -> Self {
        let mut coords: Vec<S> = self.coords.iter().map(|c| c.mul_ref(w)).collect();
        coords.push(w.clone());
        Point::new(coords)
    }

    /// The affine point and weight of a homogeneous point `(w x, ..., w)`; `None` when `w = 0`
    /// (a point at infinity) or the point has no coordinates.
    pub fn from_homogeneous(&self) -> Option<(Self, S)> {
        let (w, rest) = self.coords.split_last()?;
        if w.is_zero() {
            return None;
        }
        Some((
            Point::new(rest.iter().map(|c| c.clone() / w).collect()),
            w.clone(),
        ))
    }

    /// The coordinates as f64, for figures.
    pub fn to_f64(&self) -> Vec<f64> {
        self.coords.iter().map(|c| c.to_f64()).collect()
    }

    /// Plain text: `(1/2, 5/6, 31/6)`.
    pub fn to_text(&self) -> String {
        let parts: Vec<String> = self.coords.iter().map(|c| c.to_text()).collect();
        format!("({})", parts.join(", "))
    }

    /// LaTeX: `\left(\frac{1}{2}, \frac{5}{6}, \frac{31}{6}\right)`.
    pub fn to_latex(&self) -> String {
        let parts: Vec<String> = self.coords.iter().map(|c| c.to_latex()).collect();
        format!("\\left({}\\right)", parts.join(", "))
    }

    /// The JSON form: one exact-number string per coordinate.
    pub fn to_json_strings(&self) -> Vec<String> {
        self.coords.iter().map(|c| c.to_json_string()).collect()
    }
}

impl<S: Scalar> fmt::Display for Point<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.to_text())
    }
}

impl<S: fmt::Debug> fmt::Debug for Point<S> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("Point")?;
        f.debug_list().entries(&self.coords).finish()
    }
}

/// Coordinate i. Like slice indexing, `Index` panics when `i >= dim()` (its contract: it
/// cannot return an error); use `coords().get(i)` where i comes from input.
#[allow(clippy::indexing_slicing)]
impl<S> Index<usize> for Point<S> {
    type Output = S;
    fn index(&self, i: usize) -> &S {
        &self.coords[i]
    }
}

/// Coordinate i, mutably; panics as [`Index`] does.
#[allow(clippy::indexing_slicing)]
impl<S> IndexMut<usize> for Point<S> {
    fn index_mut(&mut self, i: usize) -> &mut S {
        &mut self.coords[i]
    }
}

fn zip_with<S: Scalar>(a: &Point<S>, b: &Point<S>, f: impl Fn(&S, &S) -> S) -> Point<S> {
    checkpoint();
    assert_eq!(a.dim(), b.dim(), "points of different dimensions");
    Point::new(
        a.coords
            .iter()
            .zip(&b.coords)
            .map(|(x, y)| f(x, y))
            .collect(),
    )
}

impl<'a, S: Scalar> Add<&'a Point<S>> for &'a Point<S> {
    type Output = Point<S>;
    fn add(self, rhs: &'a Point<S>) -> Point<S> {
        zip_with(self, rhs, |x, y| x.add_ref(y))
    }
}

impl<'a, S: Scalar> Sub<&'a Point<S>> for &'a Point<S> {
    type Output = Point<S>;
    fn sub(self, rhs: &'a Point<S>) -> Point<S> {
        zip_with(self, rhs, |x, y| x.sub_ref(y))
    }
}

impl<S: Scalar> Add for Point<S> {
    type Output = Point<S>;
    fn add(self, rhs: Point<S>) -> Point<S> {
        &self + &rhs
    }
}

impl<S: Scalar> Sub for Point<S> {
    type Output = Point<S>;
    fn sub(self, rhs: Point<S>) -> Point<S> {
        &self - &rhs
    }
}

impl<'a, S: Scalar> Mul<&'a S> for &'a Point<S> {
    type Output = Point<S>;
    fn mul(self, t: &'a S) -> Point<S> {
        self.scale(t)
    }
}

impl<S: Scalar> Neg for Point<S> {
    type Output = Point<S>;
    fn neg(self) -> Point<S> {
        Point::new(self.coords.into_iter().map(|c| -c).collect())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, BigRational};

    #[test]
    fn arithmetic_and_printing() {
        let a: Point<BigRational> = Point::new(vec![q!(1 / 2), q!(0), q!(2)]);
        let b = Point::from_ints(&[1, 2, 4]);
        assert_eq!((&a + &b).to_text(), "(3/2, 2, 6)");
        assert_eq!(a.lerp(&b, &q!(1 / 3)).to_text(), "(2/3, 2/3, 8/3)");
        assert_eq!(a.to_latex(), r"\left(\frac{1}{2}, 0, 2\right)");
        assert_eq!(a.to_json_strings(), vec!["1/2", "0", "2"]);
        let x = Point::<BigRational>::from_ints(&[1, 0, 0]);
        let y = Point::from_ints(&[0, 1, 0]);
        assert_eq!(x.cross(&y).unwrap(), Point::from_ints(&[0, 0, 1]));
        assert!(Point::<BigRational>::from_ints(&[1, 0])
            .cross(&y)
            .unwrap_err()
            .to_string()
            .contains("expected dimension 3, found 2"));
        let h = a.to_homogeneous(&q!(2));
        assert_eq!(h.to_text(), "(1, 0, 4, 2)");
        assert_eq!(h.from_homogeneous(), Some((a.clone(), q!(2))));
        assert_eq!(
            Point::<BigRational>::from_ints(&[1, 0]).from_homogeneous(),
            None
        );
    }
}
