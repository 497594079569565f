//! The convex-hull property (notes, chapter 5, §3, after eq. (8)), tested exactly.
//!
//! A point p lies in the convex hull of points `q_1, ..., q_N` exactly when it is a convex
//! combination of them. By Carathéodory's theorem it is then a convex combination of k + 1
//! affinely independent points among them, where k is the dimension of their affine hull. So
//! the test enumerates the subsets of k + 1 affinely independent points, solves
//! `p = q_0 + Σ μ_l (q_l - q_0)` exactly (Gaussian elimination, no rounding), and accepts p when
//! some subset gives barycentric coordinates `1 - Σ μ_l, μ_1, ..., μ_k` that are all `>= 0`.
//! No linear programming, no tolerance: every step is an exact comparison. The cost grows like
//! `C(N, k + 1)`, fine for the meshes of a course (a bicubic mesh: 1820 systems of 3 x 3).

use crate::{BezierSurface, Mesh, RationalBezierSurface, SurfaceError};
use cagd_linalg::Point;
use cagd_scalar::Scalar;

/// Row-reduces the columns `vectors` (each of dimension d) augmented with `rhs`. Returns the
/// rank of the vectors and, when they are independent and `rhs` lies in their span, the
/// coefficients μ with `Σ μ_l vectors[l] = rhs`.
fn solve_in_span<S: Scalar>(vectors: &[Point<S>], rhs: &Point<S>) -> (usize, Option<Vec<S>>) {
    let k = vectors.len();
    let d = rhs.dim();
    // rows[r] = (vectors[0][r], ..., vectors[k-1][r], rhs[r])
    let mut rows: Vec<Vec<S>> = (0..d)
        .map(|r| {
            let mut row: Vec<S> = vectors.iter().map(|v| v[r].clone()).collect();
            row.push(rhs[r].clone());
            row
        })
        .collect();
    let mut rank = 0;
    let mut pivots = Vec::with_capacity(k);
    for col in 0..k {
        let nonzero = |row: &Vec<S>| row.get(col).is_some_and(|x| !x.is_zero());
        let Some(p) = rows.iter().skip(rank).position(nonzero) else {
            continue;
        };
        rows.swap(rank, rank + p);
        // the rows above the pivot row, the pivot row, the rows below it
        let Some((above, pivot_and_below)) = rows.split_at_mut_checked(rank) else {
            break;
        };
        let Some((pivot_row, below)) = pivot_and_below.split_first_mut() else {
            break;
        };
        let Some(pivot) = pivot_row.get(col).cloned() else {
            break;
        };
        for row in above.iter_mut().chain(below) {
            let Some(factor) = row
                .get(col)
                .filter(|x| !x.is_zero())
                .and_then(|x| x.checked_div(&pivot))
            else {
                continue;
            };
            for (x, y) in row.iter_mut().zip(pivot_row.iter()).skip(col) {
                let delta = y.mul_ref(&factor);
                *x -= delta;
            }
        }
        pivots.push(col);
        rank += 1;
    }
    if rank < k {
        return (rank, None);
    }
    // consistent only if the rows below the pivots have a zero right-hand side
    let rhs_nonzero = |row: &Vec<S>| row.get(k).is_some_and(|x| !x.is_zero());
    if rows.iter().skip(rank).any(rhs_nonzero) {
        return (rank, None);
    }
    let mu = rows
        .iter()
        .zip(&pivots)
        .map(|(row, &col)| match (row.get(k), row.get(col)) {
            (Some(b), Some(a)) => b.checked_div(a).unwrap_or_else(S::zero),
            _ => S::zero(),
        })
        .collect();
    (rank, Some(mu))
}

/// The dimension of the affine hull of the points (the rank of `q_l - q_0`).
fn affine_dimension<S: Scalar>(points: &[Point<S>]) -> usize {
    let Some((first, rest)) = points.split_first() else {
        return 0;
    };
    let vectors: Vec<Point<S>> = rest.iter().map(|q| q - first).collect();
    solve_in_span(&vectors, &Point::zero(first.dim())).0
}

/// Calls `f` on every k-subset of `0..n` (as increasing indices) until it returns true.
fn any_subset(n: usize, k: usize, f: &mut impl FnMut(&[usize]) -> bool) -> bool {
    if k > n {
        return false;
    }
    let mut idx: Vec<usize> = (0..k).collect();
    loop {
        if f(&idx) {
            return true;
        }
        // next combination in lexicographic order: raise the last index that can grow, then
        // the ones after it follow consecutively
        let Some(pos) = idx.iter().enumerate().rposition(|(p, &i)| i < n - k + p) else {
            return false;
        };
        let Some((raised, after)) = idx.get_mut(pos..).and_then(<[usize]>::split_first_mut) else {
            return false;
        };
        *raised += 1;
        let mut next = *raised;
        for q in after {
            next += 1;
            *q = next;
        }
    }
}

/// Whether `p` lies in the convex hull of `points` (borders included), exactly: see the module
/// documentation for the method. An error when `points` is empty or the dimensions differ.
///
/// ```
/// use cagd_surface::in_convex_hull;
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let square: Vec<Point<BigRational>> = vec![
///     Point::from_ints(&[0, 0]), Point::from_ints(&[1, 0]),
///     Point::from_ints(&[0, 1]), Point::from_ints(&[1, 1]),
/// ];
/// assert!(in_convex_hull(&square, &Point::new(vec![q!(1/2), q!(1)])).unwrap());
/// assert!(!in_convex_hull(&square, &Point::new(vec![q!(1/2), q!(11/10)])).unwrap());
/// ```
pub fn in_convex_hull<S: Scalar>(points: &[Point<S>], p: &Point<S>) -> Result<bool, SurfaceError> {
    let first = points.first().ok_or(SurfaceError::EmptyMesh)?;
    for q in points.iter().chain(std::iter::once(p)) {
        if q.dim() != first.dim() {
            return Err(SurfaceError::Dimension {
                what: crate::Computation::ConvexHull,
                expected: first.dim(),
                found: q.dim(),
            });
        }
    }
    let mut distinct: Vec<Point<S>> = Vec::with_capacity(points.len());
    for q in points {
        if !distinct.contains(q) {
            distinct.push(q.clone());
        }
    }
    let k = affine_dimension(&distinct);
    let zero = S::zero();
    Ok(any_subset(distinct.len(), k + 1, &mut |idx| {
        // the indices come from 0..distinct.len(), and there are k + 1 >= 1 of them
        let Some((q0, others)) = idx
            .split_first()
            .and_then(|(&i0, others)| distinct.get(i0).map(|q0| (q0, others)))
        else {
            return false;
        };
        let vectors: Vec<Point<S>> = others
            .iter()
            .filter_map(|&l| distinct.get(l))
            .map(|q| q - q0)
            .collect();
        match solve_in_span(&vectors, &(p - q0)) {
            (_, Some(mu)) => {
                let sum = mu.iter().fold(S::zero(), |acc, x| acc + x);
                S::one() - sum >= zero && mu.iter().all(|x| *x >= zero)
            }
            _ => false,
        }
    }))
}

impl<S: Scalar> Mesh<S> {
    /// Whether `p` lies in the convex hull of the control points (see [`in_convex_hull`]).
    pub fn in_convex_hull(&self, p: &Point<S>) -> Result<bool, SurfaceError> {
        let points: Vec<Point<S>> = self.iter().cloned().collect();
        in_convex_hull(&points, p)
    }
}

impl<S: Scalar> BezierSurface<S> {
    /// Whether `p` lies in the convex hull of the control mesh. The patch lies in it (§3:
    /// eq. (1) is a barycentric combination with non-negative coefficients on the domain, by
    /// the partition of unity (7)), so a point of the patch always passes.
    pub fn in_convex_hull(&self, p: &Point<S>) -> Result<bool, SurfaceError> {
        self.mesh().in_convex_hull(p)
    }
}

impl<S: Scalar> RationalBezierSurface<S> {
    /// Whether `p` lies in the convex hull of the control mesh. The convex-hull property of the
    /// notes holds for positive weights only, so a patch with a weight `<= 0` is an error.
    pub fn in_convex_hull(&self, p: &Point<S>) -> Result<bool, SurfaceError> {
        if let Some(((i, j), w)) = self.weights().indexed().find(|(_, w)| **w <= S::zero()) {
            return Err(SurfaceError::NotPositive {
                what: crate::Positive::Weight { row: i, col: j },
                value: w.to_text(),
            });
        }
        self.mesh().in_convex_hull(p)
    }
}
