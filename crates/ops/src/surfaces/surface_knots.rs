//! B-spline and NURBS surfaces split at a parameter (`subdivide`) and their knots removed in
//! one direction (`remove_knot`): the curve algorithms on every column (u) or row (v) of the
//! mesh, a NURBS surface through its homogeneous mesh, are cagd-spline-surface's
//! ([`BSplineSurface::split_at`], [`BSplineSurface::remove_knot_in`]); here the surface read,
//! the answer written, the refusals in the problem's words.

use crate::any::AnySurface as Patch;
use crate::curves::split::split_refusal;
use crate::message::surface::Surface;
use crate::out::{at, Out};
use crate::problem::UorV;
use crate::value::ExactScalar;
use crate::value::Quantity;
use crate::ProblemError;
use cagd_spline_surface::{BSplineSurface, Direction, LinesError, NurbsSurface};

/// The direction of the problem as cagd-spline-surface's.
fn direction(dir: UorV) -> Direction {
    match dir {
        UorV::U => Direction::U,
        UorV::V => Direction::V,
    }
}

/// A refusal of a split or a removal on the lines of the mesh, at `key`: cagd-spline-surface's
/// words, an inner refusal of a line's split, of the mesh or of the surface as its own.
fn refusal(e: LinesError, key: &str) -> ProblemError {
    match e {
        LinesError::Split(e) => split_refusal(*e, key),
        LinesError::Surface(e) => ProblemError::at(key, *e),
        LinesError::SplineSurface(e) => ProblemError::at(key, *e),
        e => ProblemError::at(key, e),
    }
}

/// A B-spline surface split at `x` in `dir` ([`BSplineSurface::split_at`]).
fn split_polynomial<S: ExactScalar>(
    s: &BSplineSurface<S>,
    dir: UorV,
    x: &S,
    key: &str,
) -> Result<(BSplineSurface<S>, BSplineSurface<S>), ProblemError> {
    s.split_at(direction(dir), x).map_err(|e| refusal(e, key))
}

/// A B-spline surface with the knot `x` removed `times` times in `dir`
/// ([`BSplineSurface::remove_knot_in`]).
fn remove_polynomial<S: ExactScalar>(
    s: &BSplineSurface<S>,
    dir: UorV,
    x: &S,
    times: usize,
) -> Result<BSplineSurface<S>, ProblemError> {
    s.remove_knot_in(direction(dir), x, times)
        .map_err(|e| refusal(e, "knot"))
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
        _ => {
            return Err(ProblemError::at(
                "surface",
                crate::message::curve::Curve::ExpectedSplineSurface,
            ))
        }
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
    Ok(out.result(Quantity::Surfaces, crate::value::Exact::List(list)))
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
    Ok(out.result(Quantity::Surface, p.to_exact()))
}
