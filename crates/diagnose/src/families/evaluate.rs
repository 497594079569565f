//! The answers of the De Casteljau evaluation mistakes
//! (`cagd_problem::diagnosis::EvaluateMistake`): each is the problem as the student misread
//! it, solved again: the parameters changed (1 − t; (v, u)), the weights dropped or put into
//! the points, the control points (or weights) divided by the binomial coefficients.

use crate::change::{binomial, grid_zip, int};
use crate::{Context, Mistaken};
use cagd_problem::diagnosis::EvaluateMistake;
use cagd_problem::input::{CurveIn, SurfaceIn};
use cagd_problem::problem::{Evaluate, Param};
use cagd_problem::spec::Num;
use cagd_problem::{Number, Op};
use cagd_surface::Grid;

/// The answer a student who made `m` writes, or `None` where it does not apply (a
/// triangular patch, a B-spline, a parametrization; a weights mistake on a polynomial one).
pub(crate) fn mistaken(m: EvaluateMistake, cx: &Context) -> Option<Mistaken> {
    match m {
        EvaluateMistake::OneMinusT => bezier(cx, |e| {
            // (1 − t) c_i + t c_{i+1} written t c_i + (1 − t) c_{i+1}: the value at 1 − t
            let one_minus = |Num(x): &Num| Num(int(1) - x.clone());
            for p in &mut e.params.as_mut()?.0 {
                *p = match p {
                    Param::One(t) => Param::One(one_minus(t)),
                    Param::Many(xs) => Param::Many(xs.iter().map(one_minus).collect()),
                };
            }
            Some(())
        }),
        EvaluateMistake::UvSwapped => bezier(cx, |e| {
            e.surface.as_ref()?;
            for p in &mut e.params.as_mut()?.0 {
                match p {
                    Param::Many(xs) if xs.len() == 2 => xs.swap(0, 1),
                    _ => return None,
                }
            }
            Some(())
        }),
        EvaluateMistake::WeightsIgnored => bezier(cx, |e| match (&mut e.curve, &mut e.surface) {
            (Some(CurveIn::Bezier { weights, .. }), _) => weights.take().map(|_| ()),
            (None, Some(SurfaceIn::Bezier { weights, .. })) => weights.take().map(|_| ()),
            _ => None,
        }),
        EvaluateMistake::NotDivided => bezier(cx, |e| {
            // Σ w_i c_i B_i: the polynomial curve of the points w_i c_i
            if let Some(CurveIn::Bezier { points, weights }) = &mut e.curve {
                let w = weights.take()?;
                if w.len() != points.len() {
                    return None;
                }
                *points = points.iter().zip(&w).map(|(p, w)| p.scale(w)).collect();
                return Some(());
            }
            if let Some(SurfaceIn::Bezier { mesh, weights }) = &mut e.surface {
                let w = weights.take()?;
                *mesh = grid_zip(mesh, &w, |p, w| p.scale(w))?;
                return Some(());
            }
            None
        }),
        EvaluateMistake::BinomialsForgotten => bezier(cx, |e| {
            // Σ t^i (1 − t)^{n−i} c_i = Σ (c_i / C(n, i)) B_i^n(t); a rational one loses the
            // binomials above and below: its weights w_i / C(n, i)
            if let Some(CurveIn::Bezier { points, weights }) = &mut e.curve {
                let n = points.len().checked_sub(1)?;
                let b: Option<Vec<Number>> = (0..=n).map(|i| binomial(n, i)).collect();
                let b = b?;
                match weights {
                    Some(w) => {
                        *w = w.iter().zip(&b).map(|(w, b)| w.clone() / b).collect();
                    }
                    None => {
                        *points = points
                            .iter()
                            .zip(&b)
                            .map(|(p, b)| p.scale(&(int(1) / b)))
                            .collect();
                    }
                }
                return Some(());
            }
            if let Some(SurfaceIn::Bezier { mesh, weights }) = &mut e.surface {
                let (m, n) = (mesh.rows().checked_sub(1)?, mesh.cols().checked_sub(1)?);
                let mut bad = false;
                let b = Grid::from_fn(m + 1, n + 1, |i, j| {
                    match (binomial(m, i), binomial(n, j)) {
                        (Some(a), Some(b)) => a * b,
                        _ => {
                            bad = true;
                            int(1)
                        }
                    }
                });
                if bad {
                    return None;
                }
                match weights {
                    Some(w) => *w = grid_zip(w, &b, |w, b| w.clone() / b)?,
                    None => *mesh = grid_zip(mesh, &b, |p, b| p.scale(&(int(1) / b)))?,
                }
                return Some(());
            }
            None
        }),
    }
}

/// The evaluation of a Bézier curve or patch (rational or not) as the student misread it:
/// `change` changes its arguments, `None` where it does not apply.
fn bezier(cx: &Context, change: impl FnOnce(&mut Evaluate) -> Option<()>) -> Option<Mistaken> {
    cx.solve_changed(|op| match op {
        Op::Evaluate(
            e @ Evaluate {
                triangle: None,
                curve: Some(CurveIn::Bezier { .. }),
                ..
            },
        )
        | Op::Evaluate(
            e @ Evaluate {
                triangle: None,
                curve: None,
                surface: Some(SurfaceIn::Bezier { .. }),
                ..
            },
        ) => change(e).is_some(),
        _ => false,
    })
}
