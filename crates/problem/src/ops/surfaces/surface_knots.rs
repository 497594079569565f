//! B-spline and NURBS surfaces split at a parameter (`subdivide`) and their knots removed in
//! one direction (`remove_knot`), issue 16: the curve algorithms on every column of the mesh
//! (direction u: each column d_{0,j}, ..., d_{n,j} is a B-spline curve on the knots in u) or
//! every row (direction v), the notes' "two passes" (chapter 5 §4). A NURBS surface goes
//! through its homogeneous mesh (w d, w), whose columns and rows are B-spline curves of one
//! dimension more.
//!
//! - Split at u = ξ strictly inside: ξ inserted in every column until its multiplicity is p
//!   (Boehm), then each column split as a curve (The NURBS Book, A5.6 applied to curves): the
//!   surface on [a, ξ] × [c, d] and the one on [ξ, b] × [c, d], each on its own knots.
//! - Knot removal in u: the knot removed from every column (The NURBS Book §5.4); it is exact
//!   only when it is exact for every column, else refused naming the first column where not.

use crate::any::AnySurface as Patch;
use crate::message::surface::{Inner, Surface};
use crate::ops::curves::split::split_bspline;
use crate::ops::out::{at, Out};
use crate::problem::UorV;
use crate::value::ExactScalar;
use crate::ProblemError;
use cagd_bspline::{BSplineCurve, KnotVector};
use cagd_linalg::Point;
use cagd_spline_surface::{BSplineSurface, NurbsSurface};
use cagd_surface::{Grid, Mesh};

/// The curves of a surface in a direction: its knots there and the columns (u) or rows (v).
fn curves<S: ExactScalar>(s: &BSplineSurface<S>, dir: UorV) -> (KnotVector<S>, Vec<Vec<Point<S>>>) {
    match dir {
        UorV::U => (s.knots_u().clone(), s.mesh().to_columns()),
        UorV::V => (s.knots_v().clone(), s.mesh().to_rows()),
    }
}

/// The surface with new knots and curves in `dir`, the other direction's knots kept.
fn rebuild<S: ExactScalar>(
    s: &BSplineSurface<S>,
    dir: UorV,
    knots: KnotVector<S>,
    lines: Vec<Vec<Point<S>>>,
    path: &str,
) -> Result<BSplineSurface<S>, ProblemError> {
    let (ku, kv, mesh) = match dir {
        UorV::U => (knots, s.knots_v().clone(), Grid::from_columns(lines)),
        UorV::V => (s.knots_u().clone(), knots, Grid::from_rows(lines)),
    };
    let mesh: Mesh<S> = mesh.map_err(at(path))?;
    BSplineSurface::try_new(ku, kv, mesh).map_err(at(path))
}

/// A B-spline surface split at `x` in `dir` (see the module).
fn split_polynomial<S: ExactScalar>(
    s: &BSplineSurface<S>,
    dir: UorV,
    x: &S,
    key: &str,
) -> Result<(BSplineSurface<S>, BSplineSurface<S>), ProblemError> {
    let (knots, lines) = curves(s, dir);
    let (a, b) = (knots.start(), knots.end());
    let inside = x.compare(a) == Some(std::cmp::Ordering::Greater)
        && x.compare(b) == Some(std::cmp::Ordering::Less);
    if !inside {
        return Err(ProblemError::at(
            key,
            Surface::NotStrictlyInside {
                x: x.to_text(),
                a: a.to_text(),
                b: b.to_text(),
                key: key.into(),
            },
        ));
    }
    let (mut left, mut right) = (Vec::new(), Vec::new());
    let (mut lk, mut rk) = (None, None);
    for line in lines {
        let c = BSplineCurve::try_new(knots.clone(), line).map_err(at(key))?;
        let (l, r) = split_bspline(&c, x, key)?;
        lk = Some(l.knots().clone());
        rk = Some(r.knots().clone());
        left.push(l.points().to_vec());
        right.push(r.points().to_vec());
    }
    let (Some(lk), Some(rk)) = (lk, rk) else {
        return Err(ProblemError::at(key, Surface::NoControlPoints));
    };
    Ok((
        rebuild(s, dir, lk, left, key)?,
        rebuild(s, dir, rk, right, key)?,
    ))
}

/// A B-spline surface with the knot `x` removed `times` times in `dir` (see the module).
fn remove_polynomial<S: ExactScalar>(
    s: &BSplineSurface<S>,
    dir: UorV,
    x: &S,
    times: usize,
) -> Result<BSplineSurface<S>, ProblemError> {
    let (knots, lines) = curves(s, dir);
    let mut out = Vec::with_capacity(lines.len());
    let mut new_knots = None;
    for (j, line) in lines.into_iter().enumerate() {
        let (k, points) = cagd_bspline::remove_knot(&knots, &line, x, times).map_err(|e| {
            let because = Inner::of(e);
            let words = match dir {
                UorV::U => Surface::OnColumn {
                    param: "u".into(),
                    index: j,
                    because,
                },
                UorV::V => Surface::OnRow {
                    param: "v".into(),
                    index: j,
                    because,
                },
            };
            ProblemError::at("knot", words)
        })?;
        new_knots = Some(k);
        out.push(points);
    }
    let Some(k) = new_knots else {
        return Err(ProblemError::at("knot", Surface::NoControlPoints));
    };
    rebuild(s, dir, k, out, "knot")
}

/// `subdivide` of a B-spline or NURBS surface at `u`, `v` or both: 2 or 4 surfaces, in the
/// order [a, u] × [c, v], [a, u] × [v, d], [u, b] × [c, v], [u, b] × [v, d] (as the patches').
pub(crate) fn subdivide<S: ExactScalar>(
    patch: &Patch<S>,
    u: Option<&S>,
    v: Option<&S>,
    out: Out,
) -> Result<Out, ProblemError> {
    let (rational, h) = match patch {
        Patch::BSpline(s) => (false, s.clone()),
        Patch::Nurbs(s) => (true, s.homogeneous()),
        _ => return Err(ProblemError::at("surface", Surface::ExpectedSplineSurface)),
    };
    let halves = |s: BSplineSurface<S>, dir: UorV, x: Option<&S>, key: &str| match x {
        Some(x) => split_polynomial(&s, dir, x, key).map(|(a, b)| vec![a, b]),
        None => Ok(vec![s]),
    };
    let mut parts = Vec::new();
    for s in halves(h, UorV::U, u, "u")? {
        parts.extend(halves(s, UorV::V, v, "v")?);
    }
    let list = parts
        .into_iter()
        .map(|s| {
            let p = if rational {
                Patch::Nurbs(NurbsSurface::from_homogeneous(s).map_err(at("surface"))?)
            } else {
                Patch::BSpline(s)
            };
            Ok(p.to_exact())
        })
        .collect::<Result<Vec<_>, ProblemError>>()?;
    Ok(out.result("surfaces", crate::value::Exact::List(list)))
}

/// `remove_knot` from a B-spline or NURBS surface in `direction` (u when not given).
pub(crate) fn remove_knot<S: ExactScalar>(
    patch: &Patch<S>,
    dir: UorV,
    x: &S,
    times: usize,
    out: Out,
) -> Result<Out, ProblemError> {
    let p = match patch {
        Patch::BSpline(s) => Patch::BSpline(remove_polynomial(s, dir, x, times)?),
        Patch::Nurbs(s) => {
            let h = remove_polynomial(&s.homogeneous(), dir, x, times)?;
            Patch::Nurbs(NurbsSurface::from_homogeneous(h).map_err(at("surface"))?)
        }
        _ => return Err(ProblemError::at("surface", Surface::KnotRemovalNeedsSpline)),
    };
    Ok(out.result("surface", p.to_exact()))
}
