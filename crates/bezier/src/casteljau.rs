//! The algorithm of De Casteljau: evaluation, its triangle of intermediate points, subdivision.

use crate::polygon::{check_polygon, lerp_level};
use crate::BezierError;
use cagd_linalg::exact::{coordinate_matrix, to_scalar};
use cagd_linalg::Point;
use cagd_scalar::{BigInt, Scalar};

/// The whole triangle of De Casteljau at t: level r holds `c_i^r`, `i = 0..n-r`, with
///
/// `c_i^0 = c_i`, `c_i^r = (1 - t) c_i^{r-1} + t c_{i+1}^{r-1}`,
///
/// so level 0 is the control polygon and level n is the single point `c_0^n = c(t)`.
/// Any t is accepted (outside [0, 1] the steps extrapolate).
///
/// ```
/// use cagd_bezier::de_casteljau_triangle;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let c: Vec<Point<BigRational>> =
///     vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2]), Point::from_ints(&[3, 3])];
/// let tri = de_casteljau_triangle(&c, &q!(1/3)).unwrap();
/// assert_eq!(tri[1][0].to_text(), "(1/3, 2/3)");
/// assert_eq!(tri[1][1].to_text(), "(5/3, 7/3)");
/// assert_eq!(tri[2][0].to_text(), "(7/9, 11/9)");
/// ```
pub fn de_casteljau_triangle<S: Scalar>(
    points: &[Point<S>],
    t: &S,
) -> Result<Vec<Vec<Point<S>>>, BezierError> {
    check_polygon(points)?;
    if let Some(levels) = triangle_on_integers(points, t) {
        return Ok(levels);
    }
    let mut levels: Vec<Vec<Point<S>>> = vec![points.to_vec()];
    while let Some(last) = levels.last() {
        if last.len() <= 1 {
            break;
        }
        let next: Vec<Point<S>> = last
            .iter()
            .zip(last.iter().skip(1))
            .map(|(c_i, c_next)| c_i.lerp(c_next, t))
            .collect();
        levels.push(next);
    }
    Ok(levels)
}

/// [`de_casteljau_triangle`] on integers, when t and every coordinate are exact rationals: with
/// t = p/q and coordinate k of the polygon over a common denominator L_k,
///
/// `c_i^r = N_i^r / (L_k q^r)`,  `N_i^r = (q - p) N_i^{r-1} + p N_{i+1}^{r-1}`,
///
/// so no step reduces a fraction; each entry is reduced once, when it is written. `None`
/// otherwise (the caller takes the scalar route).
fn triangle_on_integers<S: Scalar>(points: &[Point<S>], t: &S) -> Option<Vec<Vec<Point<S>>>> {
    let t = t.as_rational()?;
    let (p, q) = (t.numer().clone(), t.denom().clone());
    let s = &q - &p;
    let dim = points.first()?.dim();
    let mut nums: Vec<Vec<BigInt>> = Vec::with_capacity(dim);
    let mut dens: Vec<BigInt> = Vec::with_capacity(dim);
    for k in 0..dim {
        let (column, den) = coordinate_matrix(points.len(), 1, points.iter(), k)?;
        nums.push((0..points.len()).map(|i| column.get(i, 0)).collect());
        dens.push(den);
    }
    let mut levels = vec![points.to_vec()];
    let mut scale = BigInt::from(1u8);
    while nums.first().is_some_and(|c| c.len() > 1) {
        cagd_scalar::cancel::checkpoint();
        scale *= &q;
        nums = nums
            .iter()
            .map(|c| {
                c.iter()
                    .zip(c.iter().skip(1))
                    .map(|(a, b)| &s * a + &p * b)
                    .collect()
            })
            .collect();
        let count = nums.first().map_or(0, Vec::len);
        let level = (0..count)
            .map(|i| {
                Point::new(
                    nums.iter()
                        .zip(&dens)
                        .map(|(c, den)| {
                            let x = c.get(i).cloned().unwrap_or_default();
                            to_scalar(x, &(den * &scale))
                        })
                        .collect(),
                )
            })
            .collect();
        levels.push(level);
    }
    Some(levels)
}

/// The point `c(t) = c_0^n` of the Bézier curve with control points `c_0, ..., c_n`, by
/// De Casteljau's algorithm `c_i^r = (1 - t) c_i^{r-1} + t c_{i+1}^{r-1}`.
///
/// Any t is accepted (outside [0, 1] the curve is extrapolated).
///
/// ```
/// use cagd_bezier::de_casteljau;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let c: Vec<Point<BigRational>> =
///     vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2]), Point::from_ints(&[3, 3])];
/// assert_eq!(de_casteljau(&c, &q!(1/3)).unwrap().to_text(), "(7/9, 11/9)");
/// ```
pub fn de_casteljau<S: Scalar>(points: &[Point<S>], t: &S) -> Result<Point<S>, BezierError> {
    check_polygon(points)?;
    let mut work = points.to_vec();
    for _ in 1..points.len() {
        lerp_level(&mut work, t);
    }
    work.into_iter().next().ok_or(BezierError::EmptyPolygon)
}

/// Subdivision at t: the control polygons of the two pieces `c([0, t])` and `c([t, 1])`,
/// read off the sides of the De Casteljau triangle:
///
/// left `= (c_0^0, c_0^1, ..., c_0^n)`, right `= (c_0^n, c_1^{n-1}, ..., c_n^0)`.
///
/// The left piece is the curve restricted to [0, t], the right one to [t, 1], each
/// reparametrized over [0, 1]. Any t is accepted (t outside (0, 1) gives the extrapolated
/// pieces, as [`crate::restrict`] does).
///
/// ```
/// use cagd_bezier::subdivide;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let c: Vec<Point<BigRational>> =
///     vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 2]), Point::from_ints(&[3, 3])];
/// let (l, r) = subdivide(&c, &q!(1/2)).unwrap();
/// let text = |v: &[Point<BigRational>]| v.iter().map(|p| p.to_text()).collect::<Vec<_>>();
/// assert_eq!(text(&l), ["(0, 0)", "(1/2, 1)", "(5/4, 7/4)"]);
/// assert_eq!(text(&r), ["(5/4, 7/4)", "(2, 5/2)", "(3, 3)"]);
/// ```
#[allow(clippy::type_complexity)]
pub fn subdivide<S: Scalar>(
    points: &[Point<S>],
    t: &S,
) -> Result<(Vec<Point<S>>, Vec<Point<S>>), BezierError> {
    let tri = de_casteljau_triangle(points, t)?;
    let left: Vec<Point<S>> = tri
        .iter()
        .filter_map(|level| level.first().cloned())
        .collect();
    let mut right: Vec<Point<S>> = tri
        .iter()
        .filter_map(|level| level.last().cloned())
        .collect();
    right.reverse();
    Ok((left, right))
}
