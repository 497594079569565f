//! Degree reduction of rational Bézier, B-spline and NURBS curves, exact or refused with the
//! reason (issue 16, item 2); the polynomial Bézier curve's, exact or least squares, is in
//! `ops/control_points.rs` and shares [`reduce_polygon`].
//!
//! - A rational Bézier curve c = Σ w_i c_i B_i^n / Σ w_i B_i^n is of degree n - r exactly when
//!   its homogeneous polygon (w_i c_i, w_i) is the elevation of a polygon of degree n - r (the
//!   homogeneous curve is polynomial); the reduced homogeneous points give the points and the
//!   weights. A least-squares reduction of the homogeneous points is not done: it can make a
//!   weight zero or negative, and it is not the nearest curve.
//! - A B-spline (NURBS) curve of degree p is of degree p - r exactly when each of its Bézier
//!   pieces (the extraction, every breakpoint to multiplicity p) is. The reduced pieces, joined
//!   at full multiplicity p - r (C⁰), are one B-spline of degree p - r; then every interior
//!   knot is removed as often as exact knot removal allows (The NURBS Book §5.4), which gives
//!   back the continuity: elevating the result by r gives the curve given (an interior knot of
//!   multiplicity μ' becomes μ' + r by elevation, The NURBS Book §5.5).

use crate::any::AnyCurve as Curve;
use crate::message::curve::{Curve as Say, ReducedPart};
use crate::ops::explain;
use crate::ops::out::{at, Out, Run};
use crate::steps::{Fact, Formula};
use crate::value::{exact, exact_points, Exact, ExactScalar};
use crate::ProblemError;
use cagd_bezier::RationalBezierCurve;
use cagd_bspline::{BSplineCurve, KnotVector, NurbsCurve};
use cagd_linalg::{Matrix, NormalEquations, Point};
use std::cmp::Ordering;

/// A polygon reduced by least squares: c̃, its elevation E c̃, and the residual c - E c̃.
pub(crate) struct Reduced<S> {
    pub(crate) reduced: Vec<Point<S>>,
    pub(crate) back: Vec<Point<S>>,
    pub(crate) residual: Vec<Point<S>>,
}

impl<S: ExactScalar> Reduced<S> {
    /// Whether E c̃ = c: the polygon was of the lower degree.
    pub(crate) fn exact(&self) -> bool {
        self.residual.iter().all(Point::is_zero)
    }
}

/// The polygon c̃ of degree n - r whose elevation E c̃ is nearest the polygon c of degree n in
/// the least-squares sense, E^t E c̃ = E^t c (E the (n + 1) × (n - r + 1) matrix of elevating
/// by r, of full rank); exact (E c̃ = c) when c is of degree n - r.
pub(crate) fn reduce_polygon<S: ExactScalar>(
    points: &[Point<S>],
    r: usize,
    path: &str,
) -> Result<Reduced<S>, ProblemError> {
    let n = points.len().saturating_sub(1);
    let m = n.saturating_sub(r);
    // column j of E: the polygon of degree m with 1 at j, elevated by r
    let mut columns = Vec::with_capacity(m + 1);
    for j in 0..=m {
        let unit: Vec<Point<S>> = (0..=m)
            .map(|i| Point::new(vec![if i == j { S::one() } else { S::zero() }]))
            .collect();
        let col = cagd_bezier::elevate_degree(&unit, r).map_err(at(path))?;
        columns.push(
            col.into_iter()
                .map(|p| p.coords().first().cloned().unwrap_or_else(S::zero))
                .collect::<Vec<S>>(),
        );
    }
    let rows = rows_of_columns(&columns, n + 1);
    let e = Matrix::from_rows(rows).map_err(at(path))?;
    let reduced = NormalEquations::new(&e)
        .and_then(|ne| ne.solve_points(points))
        .map_err(at(path))?;
    let back = cagd_bezier::elevate_degree(&reduced, r).map_err(at(path))?;
    let residual: Vec<Point<S>> = points
        .iter()
        .zip(&back)
        .map(|(p, q)| p.checked_sub(q))
        .collect::<Result<_, _>>()
        .map_err(at(path))?;
    Ok(Reduced {
        reduced,
        back,
        residual,
    })
}

/// The homogeneous points (w c, w) reduced exactly, split into points and positive weights.
fn reduce_homogeneous<S: ExactScalar>(
    points: &[Point<S>],
    weights: &[S],
    r: usize,
    path: &str,
    piece: Option<&(S, S)>,
) -> Result<(Vec<Point<S>>, Vec<S>), ProblemError> {
    let homogeneous: Vec<Point<S>> = points
        .iter()
        .zip(weights)
        .map(|(p, w)| p.to_homogeneous(w))
        .collect();
    let m = points.len().saturating_sub(1 + r);
    let red = reduce_polygon(&homogeneous, r, path)?;
    if !red.exact() {
        let of = match piece {
            Some((a, b)) => ReducedPart::PieceOn {
                from: a.to_text(),
                to: b.to_text(),
            },
            None => ReducedPart::ThisRationalCurve,
        };
        return Err(ProblemError::at(
            path,
            Say::HomogeneousNotReducible { of, degree: m },
        ));
    }
    let mut out_points = Vec::with_capacity(m + 1);
    let mut out_weights = Vec::with_capacity(m + 1);
    for (i, h) in red.reduced.iter().enumerate() {
        let split = h.from_homogeneous();
        match split {
            Some((p, w)) if w.compare(&S::zero()) == Some(Ordering::Greater) => {
                out_points.push(p);
                out_weights.push(w);
            }
            _ => {
                let w = h.coords().last().cloned().unwrap_or_else(S::zero);
                return Err(ProblemError::at(
                    path,
                    Say::WeightNotPositive {
                        weight: w.to_text(),
                        index: i,
                    },
                ));
            }
        }
    }
    Ok((out_points, out_weights))
}

/// The error of a piece of a B-spline curve that is not of the lower degree.
fn not_reducible<S: ExactScalar>((a, b): &(S, S), m: usize) -> ProblemError {
    ProblemError::at(
        "curve",
        Say::PieceNotReducible {
            from: a.to_text(),
            to: b.to_text(),
            degree: m,
        },
    )
}

/// The knots of pieces of degree m on these intervals joined at full multiplicity (C⁰).
fn joined_knots<S: ExactScalar>(
    intervals: &[(S, S)],
    m: usize,
    path: &str,
) -> Result<KnotVector<S>, ProblemError> {
    let mut knots = Vec::new();
    for (k, (a, b)) in intervals.iter().enumerate() {
        if k == 0 {
            knots.extend(std::iter::repeat_n(a.clone(), m));
        }
        knots.extend(std::iter::repeat_n(b.clone(), m));
    }
    KnotVector::from_notes(knots, m).map_err(at(path))
}

/// Every interior breakpoint of `curve` removed as often as exact removal allows.
fn remove_all<S, C>(
    mut curve: C,
    interior: &[S],
    remove: impl Fn(&C, &S) -> Option<C>,
) -> (C, usize) {
    let mut removed = 0;
    for xi in interior {
        while let Some(c) = remove(&curve, xi) {
            cagd_scalar::cancel::checkpoint();
            curve = c;
            removed += 1;
        }
    }
    (curve, removed)
}

/// `reduce_degree` of a rational Bézier, B-spline or NURBS curve by `r`: exact or refused.
pub(crate) fn reduce_exactly<S: ExactScalar>(
    c: &Curve<S>,
    r: usize,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let cf = "curve";
    // the size of the extraction, known before the work: p + 1 points per span
    let pieces = match c {
        Curve::BSpline(b) => b.knots().spans().len().saturating_mul(b.degree() + 1),
        Curve::Nurbs(b) => b.knots().spans().len().saturating_mul(b.degree() + 1),
        _ => 0,
    };
    run.check_points(cf, pieces, crate::message::limited::Limited::BezierPieces)?;
    let mut out = run.out();
    let (curve, m, count) = match c {
        Curve::RationalBezier(b) => {
            let n = b.degree();
            let m = n.checked_sub(r).ok_or_else(|| too_far(n, r))?;
            explain_reduction(&mut out, n, m);
            let (points, weights) = reduce_homogeneous(b.points(), b.weights(), r, cf, None)?;
            let (a, z) = b.domain();
            let reduced = RationalBezierCurve::try_new(points, weights)
                .and_then(|c| c.with_domain(a.clone(), z.clone()))
                .map_err(at(cf))?;
            (Curve::RationalBezier(reduced), m, m + 1)
        }
        Curve::BSpline(b) => {
            let p = b.degree();
            let m = spline_target(p, r)?;
            out.formula(Formula::PiecewiseCurve);
            explain_reduction(&mut out, p, m);
            let pieces = b.bezier_pieces().map_err(at(cf))?;
            let mut points: Vec<Point<S>> = Vec::new();
            let mut intervals = Vec::new();
            for (k, piece) in pieces.iter().enumerate() {
                let red = reduce_polygon(&piece.points, r, cf)?;
                if !red.exact() {
                    return Err(not_reducible(&piece.interval, m));
                }
                explain_piece(&mut out, k, &piece.interval, &red.reduced, None);
                let skip = usize::from(!points.is_empty());
                points.extend(red.reduced.into_iter().skip(skip));
                intervals.push(piece.interval.clone());
            }
            let knots = joined_knots(&intervals, m, cf)?;
            let joined = BSplineCurve::try_new(knots, points).map_err(at(cf))?;
            let interior: Vec<S> = intervals.iter().skip(1).map(|(a, _)| a.clone()).collect();
            let (reduced, removed) =
                remove_all(joined, &interior, |c, xi| c.remove_knot(xi, 1).ok());
            explain_removed(&mut out, removed);
            let count = reduced.points().len();
            (Curve::BSpline(reduced), m, count)
        }
        Curve::Nurbs(b) => {
            let p = b.degree();
            let m = spline_target(p, r)?;
            out.formula(Formula::PiecewiseCurve);
            explain_reduction(&mut out, p, m);
            let pieces = b.bezier_pieces().map_err(at(cf))?;
            let (mut points, mut weights) = (Vec::new(), Vec::new());
            let mut intervals = Vec::new();
            for (k, piece) in pieces.iter().enumerate() {
                let (ps, ws) = reduce_homogeneous(
                    &piece.points,
                    &piece.weights,
                    r,
                    cf,
                    Some(&piece.interval),
                )?;
                explain_piece(&mut out, k, &piece.interval, &ps, Some(&ws));
                let skip = usize::from(!points.is_empty());
                points.extend(ps.into_iter().skip(skip));
                weights.extend(ws.into_iter().skip(skip));
                intervals.push(piece.interval.clone());
            }
            let knots = joined_knots(&intervals, m, cf)?;
            let joined = NurbsCurve::try_new(knots, points, weights).map_err(at(cf))?;
            let interior: Vec<S> = intervals.iter().skip(1).map(|(a, _)| a.clone()).collect();
            let (reduced, removed) =
                remove_all(joined, &interior, |c, xi| c.remove_knot(xi, 1).ok());
            explain_removed(&mut out, removed);
            let count = reduced.points().len();
            (Curve::Nurbs(reduced), m, count)
        }
        Curve::Bezier(_) | Curve::Map(_) => return Err(ProblemError::at(cf, Say::ReductionKinds)),
    };
    out.remark(Say::ReducedExactly {
        degree: m,
        points: count,
    });
    Ok(out
        .result("curve", curve.to_exact())
        .result("exact", crate::value::Exact::Bool(true)))
}

fn too_far(n: usize, r: usize) -> ProblemError {
    ProblemError::at("by", Say::CannotReduce { degree: n, by: r })
}

/// The degree p - r of a reduced B-spline, at least 1.
fn spline_target(p: usize, r: usize) -> Result<usize, ProblemError> {
    match p.checked_sub(r) {
        Some(m) if m >= 1 => Ok(m),
        _ => Err(ProblemError::at(
            "by",
            Say::SplineCannotReduce { degree: p, by: r },
        )),
    }
}

/// The exact reduction from degree `n` to `m`, with steps.
fn explain_reduction(out: &mut Out, n: usize, m: usize) {
    out.formula(Formula::ReduceExact);
    out.fact(Fact::Degree { from: n, to: m });
}

/// Bézier piece `k` of a spline on `interval`, reduced to the points `reduced` (and
/// `weights` for a NURBS piece), with steps.
fn explain_piece<S: ExactScalar>(
    out: &mut Out,
    k: usize,
    (a, b): &(S, S),
    reduced: &[Point<S>],
    weights: Option<&[S]>,
) {
    if !out.steps_on() {
        return;
    }
    out.fact(Fact::Piece {
        index: k,
        interval: vec![explain::number(a), explain::number(b)],
    });
    out.value("\\tilde{c}", Exact::Points(exact_points(reduced)));
    if let Some(w) = weights {
        out.value(
            "\\tilde{w}",
            Exact::List(w.iter().map(|x| Exact::Number(exact(x))).collect()),
        );
    }
}

/// The knot removals, with steps.
fn explain_removed(out: &mut Out, removed: usize) {
    if removed > 0 {
        out.formula(Formula::RemoveKnot);
    }
}

/// The `count` rows of the matrix whose columns are `columns` (an entry a column lacks is 0).
pub(crate) fn rows_of_columns<S: ExactScalar>(columns: &[Vec<S>], count: usize) -> Vec<Vec<S>> {
    (0..count)
        .map(|i| {
            columns
                .iter()
                .map(|c| c.get(i).cloned().unwrap_or_else(S::zero))
                .collect()
        })
        .collect()
}
