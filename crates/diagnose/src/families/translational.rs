//! The answers of the translational-surface mistakes
//! (`cagd_problem::diagnosis::TranslationalMistake`): the key translated (the common point
//! a kept, or the other end c₁(1) subtracted instead: c₁(u) + d₁(v) − a moved by a or by
//! a − c₁(1), eq. (1)), its mesh transposed (eq. (4)), or its weights recomputed as sums
//! (eq. (5)).

use crate::change::{int, surface_mesh, swap_uv, translate, transpose};
use crate::{Context, Mistaken};
use cagd_linalg::Point;
use cagd_poly::Var;
use cagd_problem::diagnosis::TranslationalMistake;
use cagd_problem::input::{CurveIn, SurfaceIn};
use cagd_problem::{Exact, Number, Op, Quantity};
use cagd_scalar::FieldOps;

/// The answer a student who made `m` writes, or `None` where it does not apply.
pub(crate) fn mistaken(m: TranslationalMistake, cx: &Context) -> Option<Mistaken> {
    if !matches!(cx.problem.op, Op::Translational(_)) {
        return None;
    }
    match m {
        // c₁(u) + d₁(v) = (c₁(u) + d₁(v) − a) + a
        TranslationalMistake::CommonPointKept => {
            let a = corner(cx, 0)?;
            Some(cx.map_results(|_, x| translate(x, &a)))
        }
        // c₁(u) + d₁(v) − c₁(1) = (c₁(u) + d₁(v) − a) + (a − c₁(1))
        TranslationalMistake::OtherEndSubtracted => {
            let shift = corner(cx, 0)?.checked_sub(&corner(cx, 1)?).ok()?;
            Some(cx.map_results(|_, x| translate(x, &shift)))
        }
        // c_{j,i} = c_{1i} + d_{1j} − a; its closed form c(v, u) (a problem with a mesh)
        TranslationalMistake::MeshTransposed => {
            let Some(Exact::Surface(SurfaceIn::Bezier { .. } | SurfaceIn::BSpline { .. })) =
                cx.result(&Quantity::Surface)
            else {
                return None;
            };
            Some(cx.map_results(|q, x| match (q, x) {
                (
                    Quantity::Surface,
                    Exact::Surface(SurfaceIn::Bezier { .. } | SurfaceIn::BSpline { .. }),
                ) => transpose(x),
                (Quantity::ClosedForm(_), Exact::Map(m)) => Some(Exact::Map(swap_uv(m))),
                _ => None,
            }))
        }
        // w_{i,j} = w_{1i} + ω_{1j} − w_{10}, the mesh kept
        TranslationalMistake::WeightsAdded => {
            let Op::Translational(t) = &cx.problem.op else {
                return None;
            };
            let (w, omega) = (weights(t.c.as_ref()?)?, weights(t.d.as_ref()?)?);
            let (w0, o0) = (w.first()?, omega.first()?);
            if w0 != o0 {
                return None;
            }
            let zero = int(0);
            let mut positive = true;
            let grid = cagd_surface::Grid::from_fn(w.len(), omega.len(), |i, j| {
                let s = match (w.get(i), omega.get(j)) {
                    (Some(a), Some(b)) => a.clone() + b.clone() - w0.clone(),
                    _ => zero.clone(),
                };
                positive &= s.compare(&zero) == Some(std::cmp::Ordering::Greater);
                s
            });
            if !positive {
                return None;
            }
            Some(cx.map_results(|q, x| match (q, x) {
                (Quantity::Surface, Exact::Surface(s)) => {
                    let mut s = s.clone();
                    match &mut s {
                        SurfaceIn::Bezier { mesh, weights }
                        | SurfaceIn::BSpline { mesh, weights, .. }
                            if weights.is_some()
                                && (mesh.rows(), mesh.cols()) == (grid.rows(), grid.cols()) =>
                        {
                            *weights = Some(grid.clone());
                        }
                        _ => return None,
                    }
                    Some(Exact::Surface(s))
                }
                _ => None,
            }))
        }
    }
}

/// The weights of a curve of control points (1 for a polynomial one); `None` for a
/// parametrization.
fn weights(c: &CurveIn<Number>) -> Option<Vec<Number>> {
    match c {
        CurveIn::Bezier { points, weights }
        | CurveIn::BSpline {
            points, weights, ..
        } => Some(
            weights
                .clone()
                .unwrap_or_else(|| vec![int(1); points.len()]),
        ),
        CurveIn::Expr(_) => None,
    }
}

/// The key's surface at (u, 0) for u = 0 (the common point a = c₁(0)) or u = 1 (c₁(1)): the
/// corner of its mesh, or its closed form there.
fn corner(cx: &Context, u: i64) -> Option<Point<Number>> {
    if let Some(Exact::Surface(s)) = cx.result(&Quantity::Surface) {
        if let Some(mesh) = surface_mesh(s) {
            let i = if u == 0 {
                0
            } else {
                mesh.rows().checked_sub(1)?
            };
            return mesh.get(i, 0).cloned();
        }
    }
    let map = cx.answer.result.iter().find_map(|(q, x)| match (q, x) {
        (Quantity::ClosedForm(_), Exact::Map(m))
        | (Quantity::Surface, Exact::Surface(SurfaceIn::Expr(m))) => Some(m),
        _ => None,
    })?;
    map.eval(&[
        (Var::U, <Number as FieldOps>::from_i64(u)),
        (Var::V, int(0)),
    ])
    .ok()
}
