//! The answers of the restriction and subdivision mistakes
//! (`cagd_problem::diagnosis::SubdivideMistake`): the problem solved at 1 − t or with u and
//! v exchanged; the key's pieces over [t, 1] reversed; the restriction's control points
//! taken as points of the curve or patch (eq. (13) left aside), written directly.

use crate::change::{int, reverse};
use crate::{Context, Mistaken};
use cagd_linalg::Point;
use cagd_problem::diagnosis::SubdivideMistake;
use cagd_problem::input::{CurveIn, SurfaceIn};
use cagd_problem::problem::{Restrict, Subdivide};
use cagd_problem::spec::{Num, Pair};
use cagd_problem::{Exact, Number, Op, Quantity};
use cagd_surface::Grid;

/// The answer a student who made `m` writes, or `None` where it does not apply (a
/// triangular patch, a B-spline; a patch mistake on a curve).
pub(crate) fn mistaken(m: SubdivideMistake, cx: &Context) -> Option<Mistaken> {
    match m {
        SubdivideMistake::AtOneMinusT => cx.solve_changed(|op| match op {
            Op::Subdivide(s) if is_bezier(&s.curve, &s.surface) && s.triangle.is_none() => {
                let one_minus = |x: &mut Option<Num>| {
                    if let Some(Num(x)) = x {
                        *x = int(1) - x.clone();
                    }
                };
                one_minus(&mut s.t);
                one_minus(&mut s.u);
                one_minus(&mut s.v);
                true
            }
            _ => false,
        }),
        SubdivideMistake::RightPieceReversed => right_piece_reversed(cx),
        SubdivideMistake::PointsOnCurve => points_on_curve(cx),
        SubdivideMistake::UvSwapped => cx.solve_changed(|op| match op {
            Op::Restrict(Restrict {
                surface: Some(_),
                triangle: None,
                vertices: None,
                u,
                v,
                ..
            }) => {
                std::mem::swap(u, v);
                true
            }
            Op::Subdivide(Subdivide {
                surface: Some(_),
                triangle: None,
                u,
                v,
                ..
            }) => {
                std::mem::swap(u, v);
                true
            }
            _ => false,
        }),
    }
}

/// Whether the curve or surface is a Bézier one (rational or not).
fn is_bezier(curve: &Option<CurveIn<Number>>, surface: &Option<SurfaceIn<Number>>) -> bool {
    matches!(
        (curve, surface),
        (Some(CurveIn::Bezier { .. }), _) | (None, Some(SurfaceIn::Bezier { .. }))
    )
}

/// The key's subdivision with each piece over [t, 1] in reverse order: a curve's second
/// polygon; a patch's pieces over [u, 1] with their mesh reversed in u, those over [v, 1]
/// reversed in v.
fn right_piece_reversed(cx: &Context) -> Option<Mistaken> {
    let Op::Subdivide(s) = &cx.problem.op else {
        return None;
    };
    if s.triangle.is_some() || !is_bezier(&s.curve, &s.surface) {
        return None;
    }
    // which pieces are over [u, 1] and [v, 1], in the order of the answer
    let right: Vec<(bool, bool)> = match (&s.curve, &s.u, &s.v) {
        (Some(_), _, _) => vec![(false, false), (true, false)],
        (None, Some(_), Some(_)) => {
            vec![(false, false), (false, true), (true, false), (true, true)]
        }
        (None, Some(_), None) => vec![(false, false), (true, false)],
        (None, None, Some(_)) => vec![(false, false), (false, true)],
        (None, None, None) => return None,
    };
    let mistaken = cx.map_results(|q, x| {
        let Exact::List(pieces) = x else {
            return None;
        };
        if pieces.len() != right.len() {
            return None;
        }
        let pieces: Option<Vec<Exact>> = pieces
            .iter()
            .zip(&right)
            .map(|(p, &(in_u, in_v))| match (q, p) {
                (Quantity::Curves, _) if in_u => reverse(p),
                (Quantity::Surfaces, Exact::Surface(s)) => {
                    reverse_surface(s, in_u, in_v).map(Exact::Surface)
                }
                _ => Some(p.clone()),
            })
            .collect();
        pieces.map(Exact::List)
    });
    (!mistaken.result.is_empty()).then_some(mistaken)
}

/// A Bézier patch's mesh (and weights) in reverse order in u (its rows) and in v (each row).
fn reverse_surface(s: &SurfaceIn<Number>, in_u: bool, in_v: bool) -> Option<SurfaceIn<Number>> {
    fn flip<T: Clone>(g: &Grid<T>, in_u: bool, in_v: bool) -> Option<Grid<T>> {
        let mut rows = g.to_rows();
        if in_u {
            rows.reverse();
        }
        if in_v {
            rows.iter_mut().for_each(|r| r.reverse());
        }
        Grid::from_rows(rows).ok()
    }
    match s {
        SurfaceIn::Bezier { mesh, weights } => Some(SurfaceIn::Bezier {
            mesh: flip(mesh, in_u, in_v)?,
            weights: match weights {
                Some(w) => Some(flip(w, in_u, in_v)?),
                None => None,
            },
        }),
        _ => None,
    }
}

/// The point of the polygon `c` at t (De Casteljau).
fn at(c: &[Point<Number>], t: &Number) -> Option<Point<Number>> {
    cagd_bezier::de_casteljau(c, t).ok()
}

/// The parameters `a + i(b − a)/n`, i = 0, ..., n.
fn spaced(Pair(Num(a), Num(b)): &Pair, n: usize) -> Option<Vec<Number>> {
    let n_ = int(i64::try_from(n).ok()?);
    (0..=n)
        .map(|i| {
            let i = int(i64::try_from(i).ok()?);
            Some(if n == 0 {
                a.clone()
            } else {
                a.clone() + (b.clone() - a.clone()) * i / n_.clone()
            })
        })
        .collect()
}

/// The restriction of a polynomial Bézier curve (patch) with its control points taken as the
/// points `c(a + i(b − a)/n)` (`c(a + i(b − a)/m, c + j(d − c)/n)`).
fn points_on_curve(cx: &Context) -> Option<Mistaken> {
    let Op::Restrict(r) = &cx.problem.op else {
        return None;
    };
    // the direct computation reads the problem's numbers: without the values put in
    if r.triangle.is_some() || r.vertices.is_some() || !cx.problem.values.is_empty() {
        return None;
    }
    let unit = || Pair(Num(int(0)), Num(int(1)));
    let result = match (&r.curve, &r.surface) {
        (
            Some(CurveIn::Bezier {
                points,
                weights: None,
            }),
            _,
        ) => {
            let ts = spaced(r.t.as_ref()?, points.len().checked_sub(1)?)?;
            let points: Option<Vec<_>> = ts.iter().map(|t| at(points, t)).collect();
            (
                Quantity::Curve,
                Exact::Curve(CurveIn::Bezier {
                    points: points?,
                    weights: None,
                }),
            )
        }
        (
            None,
            Some(SurfaceIn::Bezier {
                mesh,
                weights: None,
            }),
        ) => {
            let us = spaced(r.u.as_ref().unwrap_or(&unit()), mesh.rows().checked_sub(1)?)?;
            let vs = spaced(r.v.as_ref().unwrap_or(&unit()), mesh.cols().checked_sub(1)?)?;
            let columns = mesh.to_columns();
            let rows: Option<Vec<Vec<_>>> = us
                .iter()
                .map(|u| {
                    // the polygon in v of the isocurve at u, evaluated at each v
                    let row: Option<Vec<_>> = columns.iter().map(|c| at(c, u)).collect();
                    let row = row?;
                    vs.iter().map(|v| at(&row, v)).collect()
                })
                .collect();
            (
                Quantity::Surface,
                Exact::Surface(SurfaceIn::Bezier {
                    mesh: Grid::from_rows(rows?).ok()?,
                    weights: None,
                }),
            )
        }
        _ => return None,
    };
    Some(Mistaken {
        result: vec![result],
        steps: Vec::new(),
    })
}
