//! The answers of the degree elevation mistakes (`cagd_problem::diagnosis::ElevateMistake`):
//! the elevation of eq. (14)-(15) with a coefficient changed, or the points and weights of a
//! rational one elevated apart, written directly over the problem's control points; or the
//! problem solved with `by` in the other direction.

use crate::change::{grid_zip, int};
use crate::{Context, Mistaken};
use cagd_linalg::Point;
use cagd_problem::diagnosis::ElevateMistake;
use cagd_problem::input::{CurveIn, SurfaceIn};
use cagd_problem::problem::Elevate;
use cagd_problem::spec::Orders;
use cagd_problem::{Exact, Number, Op, Quantity};
use cagd_surface::Grid;

/// The coefficients of one step of degree elevation, `c_i^1 = (1 − α_i) c_i + α_i c_{i−1}`
/// for i = 1, ..., n (the end points kept).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Rule {
    /// The notes' `α_i = i/(n + 1)` (eq. (14)).
    Right,
    /// `α_i = i/n`.
    DividedByN,
    /// The two coefficients swapped: `α_i = 1 − i/(n + 1)`.
    Swapped,
}

/// The answer a student who made `m` writes, or `None` where it does not apply (a triangular
/// patch, a B-spline; a weights mistake on a polynomial one; a patch elevated alike in u and
/// v).
pub(crate) fn mistaken(m: ElevateMistake, cx: &Context) -> Option<Mistaken> {
    match m {
        ElevateMistake::DividedByM => elevated(cx, Rule::DividedByN, false),
        ElevateMistake::CoefficientsSwapped => elevated(cx, Rule::Swapped, false),
        ElevateMistake::WeightsApart => elevated(cx, Rule::Right, true),
        ElevateMistake::OtherDirection => cx.solve_changed(|op| match op {
            Op::Elevate(Elevate {
                surface: Some(_),
                triangle: None,
                by: Some(by @ Orders::Two(..)),
                ..
            }) => {
                let Orders::Two(r, s) = *by else {
                    return false;
                };
                *by = Orders::Two(s, r);
                r != s
            }
            _ => false,
        }),
    }
}

/// One step of degree elevation of the polygon `c` by `rule`.
fn elevate_once(c: &[Point<Number>], rule: Rule) -> Option<Vec<Point<Number>>> {
    let n = c.len().checked_sub(1)?;
    let mut out = vec![c.first()?.clone()];
    let ratio = |a: usize, b: usize| -> Option<Number> {
        Some(int(i64::try_from(a).ok()?) / int(i64::try_from(b).ok()?))
    };
    for i in 1..=n {
        let alpha = match rule {
            Rule::Right => ratio(i, n + 1)?,
            Rule::DividedByN => ratio(i, n)?,
            Rule::Swapped => int(1) - ratio(i, n + 1)?,
        };
        out.push(c.get(i)?.lerp(c.get(i - 1)?, &alpha));
    }
    out.push(c.last()?.clone());
    Some(out)
}

/// The polygon `c` elevated `r` times by `rule`.
fn elevate_by(c: &[Point<Number>], r: usize, rule: Rule) -> Option<Vec<Point<Number>>> {
    let mut c = c.to_vec();
    for _ in 0..r {
        c = elevate_once(&c, rule)?;
    }
    Some(c)
}

/// Numbers as points of one coordinate (a list of weights elevated as a polygon).
fn as_points(w: &[Number]) -> Vec<Point<Number>> {
    w.iter().map(|w| Point::new(vec![w.clone()])).collect()
}

/// The first coordinate of each point.
fn firsts(ps: &[Point<Number>]) -> Option<Vec<Number>> {
    ps.iter().map(|p| p.coords().first().cloned()).collect()
}

/// The mesh `g` elevated r times in u (each column) and s times in v (each row) by `rule`.
fn elevate_grid(
    g: &Grid<Point<Number>>,
    (r, s): (usize, usize),
    rule: Rule,
) -> Option<Grid<Point<Number>>> {
    let columns: Option<Vec<_>> = g
        .to_columns()
        .iter()
        .map(|c| elevate_by(c, r, rule))
        .collect();
    let g = Grid::from_columns(columns?).ok()?;
    let rows: Option<Vec<_>> = g.to_rows().iter().map(|c| elevate_by(c, s, rule)).collect();
    Grid::from_rows(rows?).ok()
}

/// The projection of homogeneous points `(w c, w)` to points and weights; `None` where a
/// weight is zero.
fn project(h: &[Point<Number>]) -> Option<(Vec<Point<Number>>, Vec<Number>)> {
    h.iter()
        .map(Point::from_homogeneous)
        .collect::<Option<Vec<_>>>()
        .map(|pw| pw.into_iter().unzip())
}

/// [`project`] row by row: the mesh and the weights of homogeneous points.
fn project_grid(h: &Grid<Point<Number>>) -> Option<(Grid<Point<Number>>, Grid<Number>)> {
    let (points, weights): (Vec<_>, Vec<_>) = h
        .to_rows()
        .iter()
        .map(|r| project(r))
        .collect::<Option<Vec<_>>>()?
        .into_iter()
        .unzip();
    Some((
        Grid::from_rows(points).ok()?,
        Grid::from_rows(weights).ok()?,
    ))
}

/// The problem's Bézier curve or patch elevated by `rule`: a rational one in homogeneous
/// coordinates, or (`apart`) its points and weights elevated separately (then only a
/// rational one).
fn elevated(cx: &Context, rule: Rule, apart: bool) -> Option<Mistaken> {
    let Op::Elevate(e) = &cx.problem.op else {
        return None;
    };
    // the direct computation reads the problem's numbers: without the values put in
    if e.triangle.is_some() || !cx.problem.values.is_empty() {
        return None;
    }
    let result = match (&e.curve, &e.surface, e.by?) {
        (Some(CurveIn::Bezier { points, weights }), _, Orders::One(r)) => {
            let r = r.get();
            let (points, weights) = match weights {
                None if apart => return None,
                None => (elevate_by(points, r, rule)?, None),
                Some(w) if apart => (
                    elevate_by(points, r, rule)?,
                    Some(firsts(&elevate_by(&as_points(w), r, rule)?)?),
                ),
                Some(w) => {
                    if w.len() != points.len() {
                        return None;
                    }
                    let h: Vec<_> = points
                        .iter()
                        .zip(w)
                        .map(|(p, w)| p.to_homogeneous(w))
                        .collect();
                    let (p, w) = project(&elevate_by(&h, r, rule)?)?;
                    (p, Some(w))
                }
            };
            (
                Quantity::Curve,
                Exact::Curve(CurveIn::Bezier { points, weights }),
            )
        }
        (None, Some(SurfaceIn::Bezier { mesh, weights }), Orders::Two(r, s)) => {
            let by = (r.get(), s.get());
            let (mesh, weights) = match weights {
                None if apart => return None,
                None => (elevate_grid(mesh, by, rule)?, None),
                Some(w) if apart => {
                    let w = elevate_grid(&w.map(|w| Point::new(vec![w.clone()])), by, rule)?;
                    let mut bad = false;
                    let w = w.map(|p| {
                        p.coords().first().cloned().unwrap_or_else(|| {
                            bad = true;
                            int(0)
                        })
                    });
                    if bad {
                        return None;
                    }
                    (elevate_grid(mesh, by, rule)?, Some(w))
                }
                Some(w) => {
                    let h = grid_zip(mesh, w, |p, w| p.to_homogeneous(w))?;
                    let (p, w) = project_grid(&elevate_grid(&h, by, rule)?)?;
                    (p, Some(w))
                }
            };
            (
                Quantity::Surface,
                Exact::Surface(SurfaceIn::Bezier { mesh, weights }),
            )
        }
        _ => return None,
    };
    Some(Mistaken {
        result: vec![result],
        steps: Vec::new(),
    })
}
