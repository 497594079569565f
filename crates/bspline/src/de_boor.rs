//! The De Boor algorithm (evaluation, with its triangle of intermediate points) and the
//! blossom of a B-spline piece.

use crate::basis::div_knots;
use crate::checked::{at, slice};
use crate::{check_control_points, BSplineError, KnotVector};
use cagd_bezier::BezierError;
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// One column of the De Boor triangle: the points `d_i^r` for i = `first`, `first + 1`, ...
#[derive(Clone, Debug, PartialEq)]
pub struct DeBoorLevel<S: Scalar> {
    /// The index i of the first point of this level.
    pub first: usize,
    /// The ratios `α_i^r` used for each point (empty for level 0, the control points).
    pub alphas: Vec<S>,
    /// The points `d_first^r, d_{first+1}^r, ...`.
    pub points: Vec<Point<S>>,
}

/// Every intermediate point of the De Boor algorithm at one parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct DeBoorTriangle<S: Scalar> {
    /// The parameter.
    pub t: S,
    /// The span k (full convention: `u_k <= t < u_{k+1}`; notes: `u_{k-1} <= t < u_k`).
    pub span: usize,
    /// How many of the knots `u_{k-p+1}, ..., u_k` (full convention) equal t: the steps saved.
    pub multiplicity: usize,
    /// Level 0 is the control points `d_{k-p}, ..., d_{k-s}`; level r holds the points
    /// `d_i^r`, i = k-p+r, ..., k-s; the last level has one point, the point of the curve.
    pub levels: Vec<DeBoorLevel<S>>,
}

impl<S: Scalar> DeBoorTriangle<S> {
    /// The point of the curve: the single point of the last level.
    pub fn point(&self) -> Option<&Point<S>> {
        self.levels.last().and_then(|l| l.points.first())
    }
}

/// The De Boor triangle at t (Farin, ch. 8; Piegl and Tiller, eq. 5.1 repeated): with k the span of t
/// and s the number of knots among `u_{k-p+1}, ..., u_k` equal to t, for r = 1, ..., p - s
/// and i = k-p+r, ..., k-s
///
/// `d_i^r = (1 - α_i^r) d_{i-1}^{r-1} + α_i^r d_i^{r-1}`,
/// `α_i^r = (t - u_i)/(u_{i+p-r+1} - u_i)` (full convention; in the notes' convention
/// `α_i^r = (t - u_{i-1})/(u_{i+p-r} - u_{i-1})`),
///
/// and the point of the curve is `d_{k-s}^{p-s}`.
///
/// ```
/// use cagd_bspline::{de_boor_triangle, KnotVector};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let u = KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap();
/// let d: Vec<Point<BigRational>> =
///     [[0, 0], [1, 2], [3, 2], [4, 0]].iter().map(|c| Point::from_ints(c)).collect();
/// let tri = de_boor_triangle(&u, &d, &q!(3/2)).unwrap();
/// assert_eq!(tri.levels[1].alphas, vec![q!(3/4), q!(1/2)]);
/// let level1: Vec<String> = tri.levels[1].points.iter().map(|p| p.to_text()).collect();
/// assert_eq!(level1, ["(5/2, 2)", "(7/2, 1)"]);
/// assert_eq!(tri.point().unwrap().to_text(), "(3, 3/2)");
/// ```
pub fn de_boor_triangle<S: Scalar>(
    knots: &KnotVector<S>,
    points: &[Point<S>],
    t: &S,
) -> Result<DeBoorTriangle<S>, BSplineError> {
    check_control_points(knots, points)?;
    let k = knots.find_span(t)?;
    let p = knots.degree();
    let u = knots.full();
    // find_span gives p <= k < n: every index below is in range
    let s = slice(u, k + 1 - p, k, k)?
        .iter()
        .filter(|x| *x == t)
        .count();
    let mut levels = vec![DeBoorLevel {
        first: k - p,
        alphas: Vec::new(),
        points: slice(points, k - p, k - s, k)?.to_vec(),
    }];
    for r in 1..=p - s {
        let prev = &levels
            .last()
            .ok_or(BSplineError::InvalidSpan { span: k })?
            .points;
        let first = k - p + r;
        let mut alphas = Vec::with_capacity(prev.len().saturating_sub(1));
        let mut next = Vec::with_capacity(prev.len().saturating_sub(1));
        for ((i, a), b) in (first..=k - s).zip(prev).zip(prev.iter().skip(1)) {
            let ui = at(u, i, k)?;
            let alpha = div_knots(&t.sub_ref(ui), &at(u, i + p - r + 1, k)?.sub_ref(ui), k)?;
            next.push(a.lerp(b, &alpha));
            alphas.push(alpha);
        }
        levels.push(DeBoorLevel {
            first,
            alphas,
            points: next,
        });
    }
    Ok(DeBoorTriangle {
        t: t.clone(),
        span: k,
        multiplicity: s,
        levels,
    })
}

/// The point `c(t) = Σ d_i N_i^p(t)` of the B-spline curve, by the De Boor algorithm (the
/// last point of [`de_boor_triangle`]).
///
/// ```
/// use cagd_bspline::{de_boor, KnotVector};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let u = KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap();
/// let d: Vec<Point<BigRational>> =
///     [[0, 0], [1, 2], [3, 2], [4, 0]].iter().map(|c| Point::from_ints(c)).collect();
/// // At the simple knot t = 1 the curve is the midpoint of d_1 d_2.
/// assert_eq!(de_boor(&u, &d, &q!(1)).unwrap().to_text(), "(2, 2)");
/// ```
pub fn de_boor<S: Scalar>(
    knots: &KnotVector<S>,
    points: &[Point<S>],
    t: &S,
) -> Result<Point<S>, BSplineError> {
    let triangle = de_boor_triangle(knots, points, t)?;
    triangle.point().cloned().ok_or(BSplineError::InvalidSpan {
        span: triangle.span,
    })
}

/// The blossom (polar form) `b_k[t_1, ..., t_p]` of the polynomial piece of the curve on the
/// span k (full convention): the De Boor recursion with a different argument at each level,
///
/// `d_i^r = ((u_{i+p-r+1} - t_r) d_{i-1}^{r-1} + (t_r - u_i) d_i^{r-1}) / (u_{i+p-r+1} - u_i)`,
/// i = k-p+r, ..., k.
///
/// It is symmetric in its arguments, `b_k[t, ..., t]` is the point of the piece at t, and the
/// control points are `d_i = b_k[u_{i+1}, ..., u_{i+p}]` for i = k-p, ..., k (full convention).
///
/// ```
/// use cagd_bspline::{blossom, KnotVector};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let u = KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap();
/// let d: Vec<Point<BigRational>> =
///     [[0, 0], [1, 2], [3, 2], [4, 0]].iter().map(|c| Point::from_ints(c)).collect();
/// // d_1 = b[u_2, u_3] = b[0, 1] on the first span.
/// assert_eq!(blossom(&u, &d, 2, &[q!(0), q!(1)]).unwrap(), d[1]);
/// ```
pub fn blossom<S: Scalar>(
    knots: &KnotVector<S>,
    points: &[Point<S>],
    span: usize,
    args: &[S],
) -> Result<Point<S>, BSplineError> {
    check_control_points(knots, points)?;
    knots.check_span(span)?;
    let p = knots.degree();
    if args.len() != p {
        return Err(BezierError::BlossomArguments {
            degree: p,
            found: args.len(),
        }
        .into());
    }
    let u = knots.full();
    let k = span;
    let first = k.checked_sub(p).ok_or(BSplineError::InvalidSpan { span })?;
    let mut level: Vec<Point<S>> = slice(points, first, k, k)?.to_vec();
    for (r, t) in (1..=p).zip(args) {
        let mut next = Vec::with_capacity(level.len().saturating_sub(1));
        for ((i, a), b) in (first + r..=k).zip(&level).zip(level.iter().skip(1)) {
            let ui = at(u, i, k)?;
            let alpha = div_knots(&t.sub_ref(ui), &at(u, i + p - r + 1, k)?.sub_ref(ui), k)?;
            next.push(a.lerp(b, &alpha));
        }
        level = next;
    }
    level.pop().ok_or(BSplineError::InvalidSpan { span })
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, BigRational};

    fn pts(c: &[[i64; 2]]) -> Vec<Point<BigRational>> {
        c.iter().map(|x| Point::from_ints(x)).collect()
    }

    #[test]
    fn triangle_at_a_double_knot_and_inside_a_span() {
        // Cubic with a double interior knot at 1: notes {0, 0, 0, 1, 1, 2, 2, 2}, 6 points.
        let u = KnotVector::from_notes(
            vec![q!(0), q!(0), q!(0), q!(1), q!(1), q!(2), q!(2), q!(2)],
            3,
        )
        .unwrap();
        let d = pts(&[[0, 0], [0, 3], [3, 6], [6, 6], [9, 3], [9, 0]]);
        // At the double knot: one step (p - s = 1), d_2^1 = (1/2) d_2 + (1/2) d_3 for α = 1/2.
        let tri = de_boor_triangle(&u, &d, &q!(1)).unwrap();
        assert_eq!((tri.span, tri.multiplicity), (5, 2));
        assert_eq!(tri.levels.len(), 2);
        assert_eq!(tri.levels[1].alphas, vec![q!(1 / 2)]);
        assert_eq!(tri.point().unwrap().to_text(), "(9/2, 6)");
        // Inside the first span, t = 1/2, by hand (full knots {0, 0, 0, 0, 1, 1, 2, 2, 2, 2}):
        // level 1: α = 1/2, 1/2, 1/4: (0, 3/2), (3/2, 9/2), (15/4, 6);
        // level 2: α = 1/2, 1/2: (3/4, 3), (21/8, 21/4);
        // level 3: α = 1/2: (27/16, 33/8). Check: the Bézier points of [0, 1] are
        // b[0,0,0] = d_0, b[0,0,1] = d_1, b[0,1,1] = d_2, b[1,1,1] = (d_2 + d_3)/2 = (9/2, 6),
        // and (0 + 3·0 + 3·3 + 9/2)/8 = 27/16, (0 + 3·3 + 3·6 + 6)/8 = 33/8.
        let tri = de_boor_triangle(&u, &d, &q!(1 / 2)).unwrap();
        assert_eq!(tri.levels[1].alphas, vec![q!(1 / 2), q!(1 / 2), q!(1 / 4)]);
        let l1: Vec<String> = tri.levels[1].points.iter().map(|p| p.to_text()).collect();
        assert_eq!(l1, ["(0, 3/2)", "(3/2, 9/2)", "(15/4, 6)"]);
        let l2: Vec<String> = tri.levels[2].points.iter().map(|p| p.to_text()).collect();
        assert_eq!(l2, ["(3/4, 3)", "(21/8, 21/4)"]);
        assert_eq!(tri.point().unwrap().to_text(), "(27/16, 33/8)");
        // The ends of a clamped curve are its end control points.
        assert_eq!(de_boor(&u, &d, &q!(0)).unwrap(), d[0]);
        assert_eq!(de_boor(&u, &d, &q!(2)).unwrap(), d[5]);
    }

    #[test]
    fn errors() {
        let u = KnotVector::clamped(2, &[q!(0), q!(1)]).unwrap();
        let d = pts(&[[0, 0], [1, 1], [2, 0]]);
        assert_eq!(
            de_boor(&u, &d, &q!(3 / 2)).unwrap_err().to_string(),
            "parameter t = 3/2 is outside the domain [0, 1]"
        );
        assert!(de_boor(&u, &d[..2], &q!(0)).is_err());
        assert_eq!(
            blossom(&u, &d, 2, &[q!(0)]).unwrap_err().to_string(),
            "the blossom of a curve of degree 2 takes 2 arguments, but 1 were given"
        );
        assert!(blossom(&u, &d, 1, &[q!(0), q!(0)]).is_err());
    }
}
