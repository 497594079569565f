//! Degree reduction of Bézier curves: the polygon of degree n - r whose elevation is nearest
//! the given one (least squares, exact when the curve is of the lower degree), and the exact
//! reduction of a rational Bézier curve through its homogeneous polygon.
//!
//! - Elevating a polygon c̃ of degree m = n - r by r is linear, c = E c̃ with E the
//!   (n + 1) × (m + 1) matrix whose column j is the polygon of degree m with 1 at j elevated by
//!   r (notes, chapter 2, degree elevation); E has full rank, so the normal equations
//!   `E^t E c̃ = E^t c` have one solution, the least-squares reduction, and `E c̃ = c` exactly
//!   when the curve is of degree m ([`reduce_polygon`]).
//! - A rational Bézier curve c = Σ w_i c_i B_i^n / Σ w_i B_i^n is of degree n - r exactly when
//!   its homogeneous polygon (w_i c_i, w_i) is the elevation of a polygon of degree n - r (the
//!   homogeneous curve is polynomial); the reduced homogeneous points give the points and the
//!   weights ([`reduce_homogeneous`]). A least-squares reduction of the homogeneous points is
//!   not done: it can make a weight zero or negative, and it is not the nearest curve.

use crate::{elevate_degree, BezierError, RationalBezierCurve};
use cagd_linalg::{LinalgError, Matrix, NormalEquations, Point};
use cagd_scalar::Scalar;
use cagd_words::{said, Lang, Message, Phrase};
use std::cmp::Ordering;

/// Why a degree reduction is refused.
#[derive(Debug, Clone, PartialEq, Eq, strum::EnumIter)]
pub enum ReductionError {
    /// A reduction below degree 0.
    CannotReduce {
        /// The curve's degree.
        degree: usize,
        /// The reduction asked.
        by: usize,
    },
    /// The homogeneous polygon of a rational curve not of the lower degree.
    HomogeneousNotReducible {
        /// The lower degree.
        degree: usize,
    },
    /// An exact reduction with a weight not positive.
    WeightNotPositive {
        /// The weight.
        weight: String,
        /// The control point.
        index: usize,
    },
    /// Elevating a polygon or building the curve refused.
    Bezier(BezierError),
    /// The normal equations refused.
    Linalg(LinalgError),
}

impl Default for ReductionError {
    fn default() -> Self {
        ReductionError::HomogeneousNotReducible { degree: 1 }
    }
}

impl Message for ReductionError {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            ReductionError::CannotReduce { degree, by } => said(
                lang,
                "a curve of degree ‹› cannot be reduced by ‹›",
                "una curva de grado ‹› no se puede reducir en ‹›",
                [degree.into(), by.into()],
            ),
            ReductionError::HomogeneousNotReducible { degree } => said(
                lang,
                "the homogeneous polygon (w_i c_i, w_i) of this rational curve is not of degree ‹›, so the curve is not exactly of degree ‹›; a least-squares reduction of the homogeneous points can make a weight zero or negative (and is not the nearest curve), so it is not done",
                "el polígono homogéneo (w_i c_i, w_i) de esta curva racional no es de grado ‹›, así que la curva no es exactamente de grado ‹›; una reducción por mínimos cuadrados de los puntos homogéneos puede dar un peso nulo o negativo (y no es la curva más cercana), así que no se hace",
                [degree.into(), degree.into()],
            ),
            ReductionError::WeightNotPositive { weight, index } => said(
                lang,
                "the exact reduction has the weight ‹› at control point ‹›, not positive: it is the same curve, but not a rational curve with positive weights",
                "la reducción exacta tiene el peso ‹› en el punto de control ‹›, que no es positivo: es la misma curva, pero no una curva racional de pesos positivos",
                [weight.into(), index.into()],
            ),
            ReductionError::Bezier(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
            ReductionError::Linalg(e) => said(lang, "«»", "«»", [e.phrase(lang).into()]),
        }
    }
}

cagd_words::display_english!(ReductionError);

impl From<BezierError> for ReductionError {
    fn from(e: BezierError) -> Self {
        ReductionError::Bezier(e)
    }
}

impl From<LinalgError> for ReductionError {
    fn from(e: LinalgError) -> Self {
        ReductionError::Linalg(e)
    }
}

/// A polygon reduced by least squares: c̃, its elevation E c̃, and the residual c - E c̃.
#[derive(Debug, Clone, PartialEq)]
pub struct PolygonReduction<S> {
    /// The polygon c̃ of the lower degree.
    pub reduced: Vec<Point<S>>,
    /// Its elevation E c̃ back to the given degree.
    pub back: Vec<Point<S>>,
    /// The residual c - E c̃ (all zero when the reduction is exact).
    pub residual: Vec<Point<S>>,
}

impl<S: Scalar> PolygonReduction<S> {
    /// Whether E c̃ = c: the polygon was of the lower degree.
    pub fn exact(&self) -> bool {
        self.residual.iter().all(Point::is_zero)
    }
}

/// The `count` rows of the matrix whose columns are `columns` (an entry a column lacks is 0).
pub(crate) fn rows_of_columns<S: Scalar>(columns: &[Vec<S>], count: usize) -> Vec<Vec<S>> {
    (0..count)
        .map(|i| {
            columns
                .iter()
                .map(|c| c.get(i).cloned().unwrap_or_else(S::zero))
                .collect()
        })
        .collect()
}

/// The polygon c̃ of degree n - r whose elevation E c̃ is nearest the polygon c of degree n in
/// the least-squares sense, `E^t E c̃ = E^t c` (E the (n + 1) × (n - r + 1) matrix of
/// elevating by r, of full rank); exact (E c̃ = c) when c is of degree n - r.
///
/// ```
/// use cagd_bezier::reduce_polygon;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// // the line from 0 to 3 written in degree 3: 0, 1, 2, 3
/// let c: Vec<Point<BigRational>> = [q!(0), q!(1), q!(2), q!(3)].into_iter().map(|x| Point::new(vec![x])).collect();
/// let red = reduce_polygon(&c, 2).unwrap();
/// assert!(red.exact());
/// assert_eq!(red.reduced, [Point::new(vec![q!(0)]), Point::new(vec![q!(3)])]);
/// ```
pub fn reduce_polygon<S: Scalar>(
    points: &[Point<S>],
    r: usize,
) -> Result<PolygonReduction<S>, ReductionError> {
    let n = points.len().saturating_sub(1);
    let m = n.saturating_sub(r);
    // column j of E: the polygon of degree m with 1 at j, elevated by r
    let mut columns = Vec::with_capacity(m + 1);
    for j in 0..=m {
        let unit: Vec<Point<S>> = (0..=m)
            .map(|i| Point::new(vec![if i == j { S::one() } else { S::zero() }]))
            .collect();
        let col = elevate_degree(&unit, r)?;
        columns.push(
            col.into_iter()
                .map(|p| p.coords().first().cloned().unwrap_or_else(S::zero))
                .collect::<Vec<S>>(),
        );
    }
    let rows = rows_of_columns(&columns, n + 1);
    let e = Matrix::from_rows(rows)?;
    let reduced = NormalEquations::new(&e).and_then(|ne| ne.solve_points(points))?;
    let back = elevate_degree(&reduced, r)?;
    let residual: Vec<Point<S>> = points
        .iter()
        .zip(&back)
        .map(|(p, q)| p.checked_sub(q))
        .collect::<Result<_, _>>()?;
    Ok(PolygonReduction {
        reduced,
        back,
        residual,
    })
}

/// The points and weights of degree n - r of the rational Bézier curve of degree n with
/// `points` and `weights`, exactly: the homogeneous points (w c, w) reduced by
/// [`reduce_polygon`], which must be exact, split into points and positive weights.
///
/// ```
/// use cagd_bezier::reduce_homogeneous;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// // homogeneous (0, 1), (3/2, 2), (3, 3): the elevation of (0, 1), (3, 3)
/// let p = |x| Point::new(vec![x]);
/// let (pts, ws) = reduce_homogeneous(&[p(q!(0)), p(q!(3/4)), p(q!(1))], &[q!(1), q!(2), q!(3)], 1).unwrap();
/// assert_eq!((pts, ws), (vec![p(q!(0)), p(q!(1))], vec![q!(1), q!(3)]));
/// ```
pub fn reduce_homogeneous<S: Scalar>(
    points: &[Point<S>],
    weights: &[S],
    r: usize,
) -> Result<(Vec<Point<S>>, Vec<S>), ReductionError> {
    let homogeneous: Vec<Point<S>> = points
        .iter()
        .zip(weights)
        .map(|(p, w)| crate::rational::lift(p, w))
        .collect();
    let m = points.len().saturating_sub(1 + r);
    let red = reduce_polygon(&homogeneous, r)?;
    if !red.exact() {
        return Err(ReductionError::HomogeneousNotReducible { degree: m });
    }
    let mut out_points = Vec::with_capacity(m + 1);
    let mut out_weights = Vec::with_capacity(m + 1);
    for (i, h) in red.reduced.iter().enumerate() {
        match h.from_homogeneous() {
            Some((p, w)) if w.compare(&S::zero()) == Some(Ordering::Greater) => {
                out_points.push(p);
                out_weights.push(w);
            }
            _ => {
                let w = h.coords().last().cloned().unwrap_or_else(S::zero);
                return Err(ReductionError::WeightNotPositive {
                    weight: w.to_text(),
                    index: i,
                });
            }
        }
    }
    Ok((out_points, out_weights))
}

impl<S: Scalar> RationalBezierCurve<S> {
    /// The same curve of degree n - r, exactly ([`reduce_homogeneous`]), on the same domain;
    /// refused when the curve is not of that degree or a reduced weight is not positive.
    pub fn reduce_degree_exactly(&self, r: usize) -> Result<Self, ReductionError> {
        let n = self.degree();
        if r > n {
            return Err(ReductionError::CannotReduce { degree: n, by: r });
        }
        let (points, weights) = reduce_homogeneous(self.points(), self.weights(), r)?;
        let (a, b) = self.domain();
        Ok(RationalBezierCurve::try_new(points, weights)
            .and_then(|c| c.with_domain(a.clone(), b.clone()))?)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, BigRational};
    use strum::IntoEnumIterator;

    fn p(x: &[BigRational]) -> Point<BigRational> {
        Point::new(x.to_vec())
    }

    #[test]
    fn least_squares_reduction_of_a_parabola() {
        // 0, 1, 0 to degree 1: E = [[1, 0], [1/2, 1/2], [0, 1]], E^t E = [[5/4, 1/4], [1/4, 5/4]],
        // E^t c = (1/2, 1/2): c̃ = (1/3, 1/3), E c̃ = (1/3, 1/3, 1/3), residual (-1/3, 2/3, -1/3)
        let red = reduce_polygon(&[p(&[q!(0)]), p(&[q!(1)]), p(&[q!(0)])], 1).unwrap();
        assert!(!red.exact());
        assert_eq!(red.reduced, [p(&[q!(1 / 3)]), p(&[q!(1 / 3)])]);
        assert_eq!(
            red.residual,
            [p(&[q!(-1 / 3)]), p(&[q!(2 / 3)]), p(&[q!(-1 / 3)])]
        );
    }

    #[test]
    fn rational_reductions() {
        // the line (0, 0) → (2, 0) with weights 1, 3 elevated once: homogeneous (0, 0, 1),
        // (6, 0, 3) → (3, 0, 2) in the middle, the point (3/2, 0) with weight 2
        let c = RationalBezierCurve::try_new(
            vec![
                p(&[q!(0), q!(0)]),
                p(&[q!(3 / 2), q!(0)]),
                p(&[q!(2), q!(0)]),
            ],
            vec![q!(1), q!(2), q!(3)],
        )
        .unwrap();
        let line = c.reduce_degree_exactly(1).unwrap();
        assert_eq!(line.points(), [p(&[q!(0), q!(0)]), p(&[q!(2), q!(0)])]);
        assert_eq!(line.weights(), [q!(1), q!(3)]);
        assert_eq!(
            c.reduce_degree_exactly(3),
            Err(ReductionError::CannotReduce { degree: 2, by: 3 })
        );
        // the quarter circle (1, 0), (1, 1), (0, 1) with weights 1, 1, 2 is of degree 2
        let arc = RationalBezierCurve::try_new(
            vec![p(&[q!(1), q!(0)]), p(&[q!(1), q!(1)]), p(&[q!(0), q!(1)])],
            vec![q!(1), q!(1), q!(2)],
        )
        .unwrap();
        assert_eq!(
            arc.reduce_degree_exactly(1),
            Err(ReductionError::HomogeneousNotReducible { degree: 1 })
        );
    }

    #[test]
    fn a_weight_not_positive() {
        // the weights 1, -1/4, 1 elevated to degree 3 are 1, 1/6, 1/6, 1 (w'_1 = 1/3 + 2/3 (-1/4)):
        // positive, but the exact reduction gives back -1/4 at control point 1
        let zero = || p(&[q!(0)]);
        assert_eq!(
            reduce_homogeneous(
                &[zero(), zero(), zero(), zero()],
                &[q!(1), q!(1 / 6), q!(1 / 6), q!(1)],
                1
            ),
            Err(ReductionError::WeightNotPositive {
                weight: "-1/4".into(),
                index: 1
            })
        );
    }

    #[test]
    fn every_variant_in_both_languages() {
        for m in ReductionError::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
