//! The answers of the normal mistakes (`cagd_problem::diagnosis::NormalMistake`): the key's
//! closed form and corner normals reversed or divided by mn (a sign or a factor of
//! n = c_u × c_v and (25) changed), or the problem solved with the mesh transposed.

use crate::change::{comparable, int, surface_mesh, times, transpose_surface};
use crate::{Context, Mistaken};
use cagd_problem::diagnosis::NormalMistake;
use cagd_problem::input::SurfaceIn;
use cagd_problem::{Exact, Number, Op, Quantity};
use cagd_scalar::FieldOps;

/// The answer a student who made `m` writes, or `None` where it does not apply.
pub(crate) fn mistaken(m: NormalMistake, cx: &Context) -> Option<Mistaken> {
    let Op::Normal(a) = &cx.problem.op else {
        return None;
    };
    let surface = a.surface.as_ref()?;
    if a.triangle.is_some() {
        return None;
    }
    match m {
        // c_v × c_u = −c_u × c_v: the closed form and every corner (a degenerate corner
        // said in words is left out)
        NormalMistake::CrossReversed => signed(cx, |_| true),
        NormalMistake::DegreeFactorsLeftOut => {
            let SurfaceIn::Bezier {
                mesh,
                weights: None,
            } = surface
            else {
                return None;
            };
            let mn =
                i64::try_from(mesh.rows().checked_sub(1)? * mesh.cols().checked_sub(1)?).ok()?;
            let c = (mn != 0).then(|| Number::from_ratio(1, mn))?;
            let out = cx.map_results(|q, x| match q {
                Quantity::ClosedForm(_) | Quantity::CornerNormal { limit: false, .. } => {
                    times(x, &c)
                }
                _ => None,
            });
            (!out.result.is_empty()).then_some(out)
        }
        NormalMistake::MeshTransposed => {
            surface_mesh(surface)?;
            cx.solve_changed(|op| match op {
                Op::Normal(n) => match n.surface.as_ref().and_then(transpose_surface) {
                    Some(t) => {
                        n.surface = Some(t);
                        true
                    }
                    None => false,
                },
                _ => false,
            })
            .map(|x| Mistaken {
                result: comparable(&cx.answer.result, x.result),
                steps: x.steps,
            })
        }
        NormalMistake::OutwardDifferences => {
            surface_mesh(surface)?;
            signed(cx, |q| {
                // the corners (1, 0) and (0, 1), where i ≠ j
                matches!(q, Quantity::CornerNormal { corner, limit: false } if corner.i != corner.j)
            })
        }
    }
}

/// The key's results that `reversed` picks, each with the opposite sign.
fn signed(cx: &Context, reversed: impl Fn(&Quantity) -> bool) -> Option<Mistaken> {
    let out = cx.map_results(|q, x: &Exact| {
        if reversed(q) {
            times(x, &int(-1))
        } else {
            None
        }
    });
    (!out.result.is_empty()).then_some(out)
}
