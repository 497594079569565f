//! The knots of a key in the convention its problem gave them: Piegl and Tiller's, with one more
//! knot at each end than the notes', when the problem's knots have their end knots.

use cagd_contract::input::{CurveIn, SurfaceIn};
use cagd_contract::{Argument, Exact, Number};

/// Whether a problem gives its knots with the end knots (Piegl and Tiller's convention, one
/// more knot at each end than the notes'): its keys then print the answer's knots so too.
pub(crate) fn full_knots(inputs: &[(Argument, Exact)]) -> bool {
    inputs.iter().any(|(_, v)| match v {
        Exact::Curve(CurveIn::BSpline {
            points,
            degree,
            knots,
            ..
        }) => knots.len() == points.len() + degree + 1,
        Exact::Surface(SurfaceIn::BSpline {
            mesh,
            degree,
            knots,
            ..
        }) => knots.0.len() == mesh.rows() + degree.0 + 1,
        _ => false,
    })
}

/// A knot vector of the notes' convention with one more knot at each end.
fn with_end_knots(knots: &[Number]) -> Vec<Number> {
    let mut out = Vec::with_capacity(knots.len() + 2);
    out.extend(knots.first().cloned());
    out.extend(knots.iter().cloned());
    out.extend(knots.last().cloned());
    out
}

/// A result with its knots in the full convention (the answer's are in the notes').
pub(crate) fn in_full_convention(value: &Exact) -> Option<Exact> {
    match value {
        Exact::Curve(CurveIn::BSpline {
            points,
            degree,
            knots,
            weights,
        }) => Some(Exact::Curve(CurveIn::BSpline {
            points: points.clone(),
            degree: *degree,
            knots: with_end_knots(knots),
            weights: weights.clone(),
        })),
        Exact::Surface(SurfaceIn::BSpline {
            mesh,
            degree,
            knots,
            weights,
        }) => Some(Exact::Surface(SurfaceIn::BSpline {
            mesh: mesh.clone(),
            degree: *degree,
            knots: (with_end_knots(&knots.0), with_end_knots(&knots.1)),
            weights: weights.clone(),
        })),
        _ => None,
    }
}
