//! Degree reduction of rational Bézier, B-spline and NURBS curves, exact or refused with the
//! reason; the polynomial Bézier curve's, exact or least squares, is in `control_points.rs` and shares
//! [`reduce_polygon`]. The mathematics is cagd-bezier's ([`cagd_bezier::reduce_polygon`],
//! [`cagd_bezier::RationalBezierCurve::reduce_degree_exactly`]) and cagd-bspline's
//! ([`cagd_bspline::BSplineCurve::reduce_degree_exactly`], the pieces reduced and joined, then
//! the knots removed); here the curve read, the steps and the answer written, the refusals in
//! the problem's words.

use crate::any::AnyCurve as Curve;
use crate::value::Quantity;

use crate::explain;
use crate::message::curve::Curve as Say;
use crate::out::{Out, Run};
use crate::steps::{Fact, Formula};
use crate::value::{exact, exact_points, Exact, ExactScalar};
use crate::ProblemError;
use cagd_bezier::ReductionError;
use cagd_bspline::{ReducedPiece, SplineReduction, SplineReductionError};
use cagd_linalg::Point;

/// A polygon reduced by least squares: c̃, its elevation E c̃, and the residual c - E c̃.
pub(crate) use cagd_bezier::PolygonReduction as Reduced;

/// The polygon c̃ of degree n - r whose elevation E c̃ is nearest the polygon c of degree n in
/// the least-squares sense ([`cagd_bezier::reduce_polygon`]); a refusal at `path`.
pub(crate) fn reduce_polygon<S: ExactScalar>(
    points: &[Point<S>],
    r: usize,
    path: &str,
) -> Result<Reduced<S>, ProblemError> {
    cagd_bezier::reduce_polygon(points, r).map_err(|e| refusal(e, path))
}

/// A refusal of a Bézier reduction: cagd-bezier's words, at `by` when the reduction asked is
/// too large, else at `path`; an inner refusal of the Bézier or linear algorithms as its own.
fn refusal(e: ReductionError, path: &str) -> ProblemError {
    match e {
        ReductionError::CannotReduce { .. } => ProblemError::at("by", e),
        ReductionError::Bezier(e) => ProblemError::at(path, e),
        ReductionError::Linalg(e) => ProblemError::at(path, e),
        e => ProblemError::at(path, e),
    }
}

/// A refusal of a spline reduction: cagd-bspline's words, at `by` when the reduction asked is
/// too large, else at the curve; a piece's refusal as a Bézier reduction's.
fn spline_refusal(e: SplineReductionError) -> ProblemError {
    let cf = "curve";
    match e {
        SplineReductionError::SplineCannotReduce { .. } => ProblemError::at("by", e),
        SplineReductionError::Reduction(e) => refusal(e, cf),
        SplineReductionError::BSpline(e) => ProblemError::at(cf, e),
        e => ProblemError::at(cf, e),
    }
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
            let reduced = b.reduce_degree_exactly(r).map_err(|e| refusal(e, cf))?;
            let (n, m) = (b.degree(), reduced.degree());
            explain_reduction(&mut out, n, m);
            (Curve::RationalBezier(reduced), m, m + 1)
        }
        Curve::BSpline(b) => {
            let red = b.reduce_degree_exactly(r).map_err(spline_refusal)?;
            explain_spline(&mut out, b.degree(), &red);
            let count = red.curve.points().len();
            (Curve::BSpline(red.curve), red.degree, count)
        }
        Curve::Nurbs(b) => {
            let red = b.reduce_degree_exactly(r).map_err(spline_refusal)?;
            explain_spline(&mut out, b.degree(), &red);
            let count = red.curve.points().len();
            (Curve::Nurbs(red.curve), red.degree, count)
        }
        Curve::Bezier(_) | Curve::Map(_) => return Err(ProblemError::at(cf, Say::ReductionKinds)),
    };
    out.remark(Say::ReducedExactly {
        degree: m,
        points: count,
    });
    Ok(out
        .result(Quantity::Curve, curve.to_exact())
        .result(Quantity::IsExact, crate::value::Exact::Bool(true)))
}

/// The steps of a spline of degree `p` reduced: the pieces, each reduced, then the knots
/// removed.
fn explain_spline<S: ExactScalar, C>(out: &mut Out, p: usize, red: &SplineReduction<C, S>) {
    out.formula(Formula::PiecewiseCurve);
    explain_reduction(out, p, red.degree);
    for (k, piece) in red.pieces.iter().enumerate() {
        let ReducedPiece {
            interval,
            points,
            weights,
        } = piece;
        explain_piece(out, k, interval, points, weights.as_deref());
    }
    explain_removed(out, red.removed);
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
