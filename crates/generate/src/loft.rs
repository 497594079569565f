//! Lofting (skinning): the surface through K ≥ 2 section curves (The NURBS Book §10.3,
//! "skinned surfaces"; the notes' chapter 6 idea of interpolating over curves, taken past
//! Coons). The sections are made compatible (raised to a common degree p and refined to one
//! knot vector, as [`make_compatible`] does for two), then each column of control points
//! `P_{i,0}, ..., P_{i,K-1}` (control point i of every section) is interpolated at the
//! parameters `v_0 < ... < v_{K-1}` by a B-spline of degree q on the averaged knots (The NURBS
//! Book (9.8)): `Σ_k Q_{i,k} N_k^q(v_l) = P_{i,l}`. The surface
//! `c(u, v) = Σ_i Σ_k Q_{i,k} N_i^p(u) N_k^q(v)` contains section l as its isocurve v = v_l,
//! since at v = v_l its control points are `Σ_k Q_{i,k} N_k^q(v_l) = P_{i,l}`. With
//! q = K - 1 the knots in v are one span: a Bézier interpolation in v.

use crate::{make_compatible, GenerateError, Note};
use cagd_bspline::{basis_functions_at, BSplineCurve, KnotVector};
use cagd_linalg::{Factorization, Matrix, Point};
use cagd_scalar::Scalar;
use std::cmp::Ordering;

/// A lofted surface: the compatible sections, the knots in v and the control net.
#[derive(Clone, Debug, PartialEq)]
pub struct Lofted<S: Scalar> {
    /// The sections rewritten with one degree and one knot vector (in u).
    pub sections: Vec<BSplineCurve<S>>,
    /// The knots in v (averaged from the parameters), of degree q.
    pub knots_v: KnotVector<S>,
    /// The control net: `net[i][k]` = Q_{i,k}, i along u (a section's control point), k along
    /// v; column i interpolates control point i of every section.
    pub net: Vec<Vec<Point<S>>>,
    /// What made the sections compatible (elevations, insertions).
    pub notes: Vec<Note>,
}

/// The uniform parameters `v_k = k/(K - 1)` of K sections.
pub fn uniform_parameters<S: Scalar>(k: usize) -> Vec<S> {
    let last = S::from_i64(i64::try_from(k.saturating_sub(1).max(1)).unwrap_or(1));
    (0..k)
        .map(|i| S::from_i64(i64::try_from(i).unwrap_or(0)) / last.clone())
        .collect()
}

/// The surface through the `sections` (clamped B-spline curves on one domain; a Bézier curve
/// is one with knots of one span) at the parameters `params` (increasing, one per section),
/// of degree `q` in v (1 ≤ q ≤ K - 1).
///
/// ```
/// use cagd_bspline::{BSplineCurve, KnotVector};
/// use cagd_generate::{loft, uniform_parameters};
/// use cagd_linalg::Point;
/// use cagd_scalar::{q, BigRational};
/// let line = |z: i64, h: i64| {
///     BSplineCurve::try_new(
///         KnotVector::bezier(1, q!(0), q!(1)).unwrap(),
///         vec![Point::from_ints(&[0, 0, z]), Point::from_ints(&[2, h, z])],
///     )
///     .unwrap()
/// };
/// let sections: Vec<BSplineCurve<BigRational>> = vec![line(0, 0), line(1, 2), line(2, 0)];
/// let s = loft(&sections, &uniform_parameters(3), 2).unwrap();
/// // column 1 through (2, 0, 0), (2, 2, 1), (2, 0, 2) at v = 0, 1/2, 1: middle point (2, 4, 1)
/// assert_eq!(s.net[1][1].to_text(), "(2, 4, 1)");
/// ```
pub fn loft<S: Scalar>(
    sections: &[BSplineCurve<S>],
    params: &[S],
    q: usize,
) -> Result<Lofted<S>, GenerateError> {
    let k = sections.len();
    if k < 2 {
        return Err(GenerateError::LoftSections { found: k });
    }
    if params.len() != k {
        return Err(GenerateError::LoftParameters {
            found: params.len(),
            sections: k,
        });
    }
    if params
        .windows(2)
        .any(|w| matches!(w, [a, b] if a.compare(b) != Some(Ordering::Less)))
    {
        return Err(GenerateError::LoftNotIncreasing);
    }
    if q == 0 || q >= k {
        return Err(GenerateError::LoftDegree {
            degree: q,
            max: k - 1,
        });
    }
    let name = |i: usize| format!("c_{i}");
    // one curve compatible with every section, then each section made compatible with it
    let Some(first) = sections.first() else {
        return Err(GenerateError::LoftSections { found: 0 });
    };
    let mut target = first.clone();
    for (i, c) in sections.iter().enumerate().skip(1) {
        target = make_compatible(&target, c, (&name(0), &name(i)))?.first;
    }
    let mut notes = Vec::new();
    let mut compatible = Vec::with_capacity(k);
    for (i, c) in sections.iter().enumerate() {
        let both = make_compatible(&target, c, ("", &name(i)))?;
        // the target has every section's degree and knots: only section i changes
        notes.extend(both.notes);
        compatible.push(both.second);
    }
    // the collocation matrix N_k^q(v_l), one factorization for every column
    let knots_v = KnotVector::from_notes(cagd_fit::averaged_knots(params, q), q)?;
    let mut rows = Vec::with_capacity(k);
    for v in params {
        let (first, values) = basis_functions_at(&knots_v, v)?;
        let mut row = vec![S::zero(); k];
        for (j, x) in values.into_iter().enumerate() {
            if let Some(slot) = row.get_mut(first + j) {
                *slot = x;
            }
        }
        rows.push(row);
    }
    let factor = Factorization::new(&Matrix::from_rows(rows)?)?;
    let n = compatible.first().map_or(0, |c| c.points().len());
    let mut net = Vec::with_capacity(n);
    for i in 0..n {
        let column: Vec<Point<S>> = compatible
            .iter()
            .filter_map(|c| c.points().get(i).cloned())
            .collect();
        net.push(factor.solve_points(&column)?);
    }
    Ok(Lofted {
        sections: compatible,
        knots_v,
        net,
        notes,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_scalar::{q, BigRational};
    use proptest::prelude::*;

    type Q = BigRational;

    /// c(u, v) at (u, v) from the net: De Boor in v on each column, then in u.
    fn eval(s: &Lofted<Q>, u: &Q, v: &Q) -> Point<Q> {
        let row: Vec<Point<Q>> = s
            .net
            .iter()
            .map(|col| {
                BSplineCurve::try_new(s.knots_v.clone(), col.clone())
                    .unwrap()
                    .eval(v)
                    .unwrap()
            })
            .collect();
        let knots_u = s.sections[0].knots().clone();
        BSplineCurve::try_new(knots_u, row)
            .unwrap()
            .eval(u)
            .unwrap()
    }

    fn section(degree: usize, ys: &[i64], z: i64) -> BSplineCurve<Q> {
        let n = ys.len();
        let pts: Vec<Point<Q>> = ys
            .iter()
            .enumerate()
            .map(|(i, &y)| Point::from_ints(&[i64::try_from(i).unwrap(), y, z]))
            .collect();
        // clamped, uniform inner knots on [0, 1]
        let spans = n - degree;
        let breaks: Vec<Q> = (0..=spans)
            .map(|j| {
                Q::new(
                    i64::try_from(j).unwrap().into(),
                    i64::try_from(spans).unwrap().into(),
                )
            })
            .collect();
        BSplineCurve::try_new(KnotVector::clamped(degree, &breaks).unwrap(), pts).unwrap()
    }

    #[test]
    fn refusals() {
        let c = section(1, &[0, 1], 0);
        assert_eq!(
            loft(std::slice::from_ref(&c), &[q!(0)], 1),
            Err(GenerateError::LoftSections { found: 1 })
        );
        let two = [c.clone(), section(1, &[1, 0], 1)];
        assert_eq!(
            loft(&two, &[q!(0), q!(0)], 1),
            Err(GenerateError::LoftNotIncreasing)
        );
        assert_eq!(
            loft(&two, &[q!(0), q!(1)], 2),
            Err(GenerateError::LoftDegree { degree: 2, max: 1 })
        );
    }

    proptest! {
        /// The lofted surface contains its sections: the isocurve v = v_k is section k, at
        /// random rational u.
        #[test]
        fn contains_its_sections(
            ys in proptest::collection::vec(proptest::collection::vec(-5i64..5, 2..5), 2..5),
            degrees in proptest::collection::vec(1usize..3, 4),
            q in 1usize..4,
            us in proptest::collection::vec(0i64..=12, 3),
        ) {
            let k = ys.len();
            let q = q.min(k - 1);
            let sections: Vec<BSplineCurve<Q>> = ys
                .iter()
                .enumerate()
                .map(|(i, y)| {
                    let p = degrees[i % degrees.len()].min(y.len() - 1);
                    section(p, y, i64::try_from(i).unwrap())
                })
                .collect();
            let params: Vec<Q> = (0..k)
                .map(|i| Q::new((i64::try_from(i * i + i).unwrap()).into(), 1.into()))
                .collect();
            let s = loft(&sections, &params, q).unwrap();
            for (c, v) in sections.iter().zip(&params) {
                for u in &us {
                    let u = Q::new((*u).into(), 12.into());
                    prop_assert_eq!(eval(&s, &u, v), c.eval(&u).unwrap());
                }
            }
        }
    }
}
