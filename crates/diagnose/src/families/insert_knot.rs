//! The answers of the knot insertion mistakes (`cagd_problem::diagnosis::InsertKnotMistake`):
//! Boehm's algorithm run again on the problem's curve (the columns or rows of its surface)
//! with the one-line change the student made in the step
//! d̂_i = (1 − α_i) d_{i−1} + α_i d_i, α_i = (t − u_i)/(u_{i+p} − u_i) (full convention:
//! the notes' u_{i−1}, u_{i+p−1}), the knots of the key kept; or the problem solved with the
//! other direction.

use crate::{Context, Mistaken};
use cagd_bspline::KnotVector;
use cagd_linalg::Point;
use cagd_problem::diagnosis::InsertKnotMistake;
use cagd_problem::input::{CurveIn, SurfaceIn};
use cagd_problem::problem::UorV;
use cagd_problem::{Exact, Number, Op, Quantity};
use cagd_scalar::FieldOps;
use cagd_surface::Grid;

/// The answer a student who made `m` writes, or `None` where it does not apply.
pub(crate) fn mistaken(m: InsertKnotMistake, cx: &Context) -> Option<Mistaken> {
    match m {
        InsertKnotMistake::AlphaSwapped => boehm_changed(cx, Step::AlphaSwapped),
        InsertKnotMistake::OrderForDegree => boehm_changed(cx, Step::OrderForDegree),
        InsertKnotMistake::NotHomogeneous => boehm_changed(cx, Step::NotHomogeneous),
        InsertKnotMistake::VForU => other_direction(cx, UorV::U, UorV::V),
        InsertKnotMistake::UForV => other_direction(cx, UorV::V, UorV::U),
    }
}

/// The surface's knot inserted in direction `used` where `asked` is asked: the problem
/// solved with the direction changed.
fn other_direction(cx: &Context, asked: UorV, used: UorV) -> Option<Mistaken> {
    cx.solve_changed(|op| match op {
        Op::InsertKnot(a) if a.surface.is_some() && a.direction == Some(asked) => {
            a.direction = Some(used);
            true
        }
        _ => false,
    })
}

/// Boehm's step as the student ran it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Step {
    /// d̂_i = α_i d_{i−1} + (1 − α_i) d_i.
    AlphaSwapped,
    /// α_i = (t − u_i)/(u_{i+p+1} − u_i) (full convention).
    OrderForDegree,
    /// The notes' step on the points and on the weights apart (no homogeneous form).
    NotHomogeneous,
}

/// The problem's curve (or surface) with the knot inserted by the changed step, written on
/// the key's knots.
fn boehm_changed(cx: &Context, step: Step) -> Option<Mistaken> {
    let Op::InsertKnot(a) = &cx.problem.op else {
        return None;
    };
    if let Some(CurveIn::BSpline {
        points,
        degree,
        knots,
        weights,
    }) = &a.curve
    {
        let key = cx.result(&Quantity::Curve)?;
        let Exact::Curve(CurveIn::BSpline {
            points: new_points,
            knots: new_knots,
            degree: new_degree,
            ..
        }) = key
        else {
            return None;
        };
        let before = full_knots(knots, *degree, points.len())?;
        let after = full_knots(new_knots, *degree, new_points.len())?;
        let (t, times) = inserted_knot(&before, &after)?;
        let line = to_line(points, weights.as_deref(), step)?;
        let line = insert(&before, *degree, line, &t, times, step)?;
        let (points, weights) = from_line(&line, weights.is_some(), step)?;
        let curve = CurveIn::BSpline {
            points,
            degree: *new_degree,
            knots: new_knots.clone(),
            weights,
        };
        return Some(Mistaken {
            result: vec![(Quantity::Curve, Exact::Curve(curve))],
            steps: Vec::new(),
        });
    }
    let SurfaceIn::BSpline {
        mesh,
        degree,
        knots,
        weights,
    } = a.surface.as_ref()?
    else {
        return None;
    };
    let key = cx.result(&Quantity::Surface)?;
    let Exact::Surface(SurfaceIn::BSpline {
        mesh: new_mesh,
        knots: new_knots,
        degree: new_degree,
        ..
    }) = key
    else {
        return None;
    };
    let along_u = match a.direction? {
        UorV::U => true,
        UorV::V => false,
    };
    let (p, old, new, count, new_count) = if along_u {
        (
            degree.0,
            &knots.0,
            &new_knots.0,
            mesh.rows(),
            new_mesh.rows(),
        )
    } else {
        (
            degree.1,
            &knots.1,
            &new_knots.1,
            mesh.cols(),
            new_mesh.cols(),
        )
    };
    let before = full_knots(old, p, count)?;
    let after = full_knots(new, p, new_count)?;
    let (t, times) = inserted_knot(&before, &after)?;
    // the lines along the direction of the insertion: the columns for u, the rows for v
    let (mesh_lines, weight_lines) = if along_u {
        (mesh.to_columns(), weights.as_ref().map(Grid::to_columns))
    } else {
        (mesh.to_rows(), weights.as_ref().map(Grid::to_rows))
    };
    let mut new_points = Vec::with_capacity(mesh_lines.len());
    let mut new_weights = Vec::with_capacity(mesh_lines.len());
    for (l, line) in mesh_lines.iter().enumerate() {
        let w = match &weight_lines {
            Some(ws) => Some(ws.get(l)?.as_slice()),
            None => None,
        };
        let inserted = insert(&before, p, to_line(line, w, step)?, &t, times, step)?;
        let (pts, ws) = from_line(&inserted, w.is_some(), step)?;
        new_points.push(pts);
        new_weights.push(ws);
    }
    let new_weights: Option<Vec<Vec<Number>>> = new_weights.into_iter().collect();
    let (mesh, weights) = if along_u {
        (
            Grid::from_columns(new_points).ok()?,
            new_weights.map(Grid::from_columns).transpose().ok()?,
        )
    } else {
        (
            Grid::from_rows(new_points).ok()?,
            new_weights.map(Grid::from_rows).transpose().ok()?,
        )
    };
    let surface = SurfaceIn::BSpline {
        mesh,
        degree: *new_degree,
        knots: new_knots.clone(),
        weights,
    };
    Some(Mistaken {
        result: vec![(Quantity::Surface, Exact::Surface(surface))],
        steps: Vec::new(),
    })
}

/// A knot vector in the full convention, read in either for `points` control points.
fn full_knots(knots: &[Number], degree: usize, points: usize) -> Option<Vec<Number>> {
    KnotVector::read(knots.to_vec(), degree, points)
        .ok()
        .map(|(u, _)| u.full().to_vec())
}

/// The knot the key inserted and how many times: the first knot of `after` not matched in
/// `before`, and the difference of the lengths (both in the full convention).
fn inserted_knot(before: &[Number], after: &[Number]) -> Option<(Number, usize)> {
    let times = after.len().checked_sub(before.len())?;
    let at = before
        .iter()
        .zip(after)
        .position(|(a, b)| a != b)
        .unwrap_or(before.len());
    Some((after.get(at)?.clone(), times))
}

/// The points the step combines: homogeneous (w x, w) for the notes' step on a rational
/// polygon, (x, w) for the step without the homogeneous form (`None` without weights), the
/// points themselves without weights.
fn to_line(
    points: &[Point<Number>],
    weights: Option<&[Number]>,
    step: Step,
) -> Option<Vec<Point<Number>>> {
    match (weights, step) {
        (None, Step::NotHomogeneous) => None,
        (None, _) => Some(points.to_vec()),
        (Some(ws), _) if ws.len() != points.len() => None,
        (Some(ws), Step::NotHomogeneous) => Some(
            points
                .iter()
                .zip(ws)
                .map(|(p, w)| {
                    let mut c = p.coords().to_vec();
                    c.push(w.clone());
                    Point::new(c)
                })
                .collect(),
        ),
        (Some(ws), _) => Some(
            points
                .iter()
                .zip(ws)
                .map(|(p, w)| p.to_homogeneous(w))
                .collect(),
        ),
    }
}

/// The points and weights of a combined line ([`to_line`] undone).
#[allow(clippy::type_complexity)]
fn from_line(
    line: &[Point<Number>],
    rational: bool,
    step: Step,
) -> Option<(Vec<Point<Number>>, Option<Vec<Number>>)> {
    if !rational {
        return Some((line.to_vec(), None));
    }
    let mut points = Vec::with_capacity(line.len());
    let mut weights = Vec::with_capacity(line.len());
    for q in line {
        let (p, w) = if step == Step::NotHomogeneous {
            let (w, rest) = q.coords().split_last()?;
            (Point::new(rest.to_vec()), w.clone())
        } else {
            q.from_homogeneous()?
        };
        points.push(p);
        weights.push(w);
    }
    Some((points, Some(weights)))
}

/// Boehm's insertion of t, `times` times, into the polygon `points` on the full knot vector
/// `knots` of degree p, each step changed as the student did.
fn insert(
    knots: &[Number],
    p: usize,
    mut points: Vec<Point<Number>>,
    t: &Number,
    times: usize,
    step: Step,
) -> Option<Vec<Point<Number>>> {
    let mut u = knots.to_vec();
    for _ in 0..times {
        let k = KnotVector::from_full(u.clone(), p)
            .ok()?
            .find_span(t)
            .ok()?;
        let first = (k + 1).checked_sub(p)?;
        let mut next = points.get(..first)?.to_vec();
        for i in first..=k {
            let ui = u.get(i)?;
            let top = match step {
                // u_{i+p+1}: past the last knot of the notes' convention, the student has none
                Step::OrderForDegree if i + p + 2 >= u.len() => return None,
                Step::OrderForDegree => u.get(i + p + 1)?,
                _ => u.get(i + p)?,
            };
            let alpha = t.sub_ref(ui).checked_div(&top.sub_ref(ui))?;
            let (left, right) = (points.get(i.checked_sub(1)?)?, points.get(i)?);
            next.push(match step {
                Step::AlphaSwapped => right.lerp(left, &alpha),
                _ => left.lerp(right, &alpha),
            });
        }
        next.extend_from_slice(points.get(k..)?);
        u.insert(k + 1, t.clone());
        points = next;
    }
    Some(points)
}
