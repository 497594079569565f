//! Multi-indices (i, j, k) with i + j + k = n and the order of the control net.
//!
//! The control points of a triangular patch of degree n are stored in **lexicographic
//! descending order in i, then in j**: row m = j + k = n - i holds the m + 1 points with first
//! index n - m, with k running from 0 to m. For n = 2:
//!
//! ```text
//! position  0      1      2      3      4      5
//! (i,j,k)   (2,0,0) (1,1,0) (1,0,1) (0,2,0) (0,1,1) (0,0,2)
//! ```
//!
//! Drawn as a triangle with b_{n,0,0} at the apex, row m is the m-th row below it. The position
//! of (i, j, k) is m(m + 1)/2 + k with m = j + k, which does not depend on n: the same formula
//! indexes every level of the De Casteljau algorithm.

/// A multi-index (i, j, k): the control point b_{i,j,k} sits at the barycentric point
/// (i/n, j/n, k/n) of the domain triangle.
pub type MultiIndex = (usize, usize, usize);

/// The number of control points of a triangular patch of degree n: (n + 1)(n + 2)/2, or `None`
/// when it does not fit in a `usize`.
///
/// ```
/// use cagd_triangle::control_point_count;
/// assert_eq!(control_point_count(0), Some(1));
/// assert_eq!(control_point_count(3), Some(10));
/// ```
pub fn control_point_count(degree: usize) -> Option<usize> {
    let a = degree.checked_add(1)?;
    let b = degree.checked_add(2)?;
    // One of two consecutive integers is even.
    if a % 2 == 0 {
        (a / 2).checked_mul(b)
    } else {
        a.checked_mul(b / 2)
    }
}

/// The position of b_{i,j,k} in the control net of degree n = i + j + k (see the module docs):
/// m(m + 1)/2 + k with m = j + k. `None` if i + j + k ≠ `degree`.
///
/// ```
/// use cagd_triangle::position;
/// assert_eq!(position(2, 1, 1, 0), Some(1));
/// assert_eq!(position(2, 0, 0, 2), Some(5));
/// assert_eq!(position(2, 1, 1, 1), None);
/// ```
pub fn position(degree: usize, i: usize, j: usize, k: usize) -> Option<usize> {
    let m = j.checked_add(k)?;
    if i.checked_add(m)? != degree {
        return None;
    }
    control_point_count(m)?.checked_sub(m + 1)?.checked_add(k)
}

/// The position of (·, j, k) in a net whose rows are already known to be valid; the unchecked
/// form of [`position`] used inside the algorithms.
pub(crate) fn pos(j: usize, k: usize) -> usize {
    let m = j + k;
    m * (m + 1) / 2 + k
}

/// All multi-indices of degree n, in the order of the control net (see the module docs).
///
/// ```
/// use cagd_triangle::multi_indices;
/// let v: Vec<_> = multi_indices(2).collect();
/// assert_eq!(v, [(2, 0, 0), (1, 1, 0), (1, 0, 1), (0, 2, 0), (0, 1, 1), (0, 0, 2)]);
/// ```
pub fn multi_indices(degree: usize) -> impl Iterator<Item = MultiIndex> + Clone {
    (0..=degree).flat_map(move |m| (0..=m).map(move |k| (degree - m, m - k, k)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn positions_follow_the_iteration_order() {
        for n in 0..7 {
            let all: Vec<_> = multi_indices(n).collect();
            assert_eq!(Some(all.len()), control_point_count(n));
            for (p, &(i, j, k)) in all.iter().enumerate() {
                assert_eq!(i + j + k, n);
                assert_eq!(position(n, i, j, k), Some(p));
                assert_eq!(pos(j, k), p);
            }
        }
        assert_eq!(control_point_count(usize::MAX), None);
        assert_eq!(position(usize::MAX, usize::MAX, 1, 0), None);
    }
}
