//! The answers of the surface of revolution mistakes
//! (`cagd_problem::diagnosis::RevolutionMistake`): the key's mesh (row i the polygon of the
//! circle C_i described by the profile's vertex c_i) and weights w_{i,j} = w_i ω_j changed
//! as the student wrote them (chapter 6, §6, eq. (21)). Column 0 is the profile, so
//! w_i = w_{i,0} and the circle's normalized weights are ω_j = w_{i,j}/w_{i,0}.

use crate::change::{drop_weights, surface_mesh, transpose, with_mesh};
use crate::{Context, Mistaken};
use cagd_problem::diagnosis::RevolutionMistake;
use cagd_problem::input::SurfaceIn;
use cagd_problem::{Exact, Number, Op, Quantity};
use cagd_scalar::FieldOps;
use cagd_surface::Grid;

/// The answer a student who made `m` writes, or `None` where it does not apply.
pub(crate) fn mistaken(m: RevolutionMistake, cx: &Context) -> Option<Mistaken> {
    if !matches!(cx.problem.op, Op::Revolution(_)) {
        return None;
    }
    let key = cx.result(&Quantity::Surface)?;
    let Exact::Surface(surface) = key else {
        return None;
    };
    let weights = surface_weights(surface)?;
    let mesh = surface_mesh(surface)?;
    // ω_j = w_{i,j}/w_{i,0}
    let omega = |i: usize, j: usize| -> Option<Number> {
        weights.get(i, j)?.checked_div(weights.get(i, 0)?)
    };
    let changed = match m {
        RevolutionMistake::ProfileWeightLeftOut => {
            let w = try_grid(weights.rows(), weights.cols(), omega)?;
            with_weights(surface, w)
        }
        RevolutionMistake::MiddleWeightOne => {
            let w = try_grid(weights.rows(), weights.cols(), |i, _| {
                weights.get(i, 0).cloned()
            })?;
            with_weights(surface, w)
        }
        RevolutionMistake::MiddleVertexOnParallel => {
            // (x, y, z) ↦ (ω_j x, ω_j y, z): the vertex pulled onto the parallel of radius r_i
            let moved = try_grid(mesh.rows(), mesh.cols(), |i, j| {
                let (q, w) = (mesh.get(i, j)?, omega(i, j)?);
                let mut c = q.coords().to_vec();
                for x in c.iter_mut().take(2) {
                    *x = x.mul_ref(&w);
                }
                Some(cagd_linalg::Point::new(c))
            })?;
            with_mesh(surface, moved)
        }
        RevolutionMistake::WeightsLeftOut => {
            return Some(Mistaken {
                result: vec![(Quantity::Surface, drop_weights(key)?)],
                steps: Vec::new(),
            });
        }
        RevolutionMistake::Transposed => {
            return Some(Mistaken {
                result: vec![(Quantity::Surface, transpose(key)?)],
                steps: Vec::new(),
            })
        }
    };
    Some(Mistaken {
        result: vec![(Quantity::Surface, Exact::Surface(changed))],
        steps: Vec::new(),
    })
}

/// A rational surface's weights (`None` without weights or for a parametrization).
fn surface_weights(s: &SurfaceIn<Number>) -> Option<&Grid<Number>> {
    match s {
        SurfaceIn::Bezier { weights, .. } | SurfaceIn::BSpline { weights, .. } => weights.as_ref(),
        SurfaceIn::Expr(_) => None,
    }
}

/// The surface with its weights replaced (same kind, mesh, degree and knots).
fn with_weights(s: &SurfaceIn<Number>, w: Grid<Number>) -> SurfaceIn<Number> {
    let mut s = s.clone();
    match &mut s {
        SurfaceIn::Bezier { weights, .. } | SurfaceIn::BSpline { weights, .. } => {
            *weights = Some(w);
        }
        SurfaceIn::Expr(_) => {}
    }
    s
}

/// The grid of `f(i, j)`, `None` when one entry is.
fn try_grid<T: Clone>(
    rows: usize,
    cols: usize,
    f: impl Fn(usize, usize) -> Option<T>,
) -> Option<Grid<T>> {
    let rows: Option<Vec<Vec<T>>> = (0..rows)
        .map(|i| (0..cols).map(|j| f(i, j)).collect())
        .collect();
    Grid::from_rows(rows?).ok()
}
