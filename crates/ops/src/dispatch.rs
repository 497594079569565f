//! Dispatch: one `match` on the typed operation, run over the problem's scalar.

use super::curves::{self, curve};
use super::fitting::fit;
use super::generation::{generate, shapes};
use super::out::{Out, Run};
use super::surfaces::{continuity, curvature, patch, surface};
use super::triangles::triangle;
use super::{control_points, reverse};
use crate::field::NumberField;
use crate::limits::Limits;
use crate::problem::{Op, Problem};
use crate::value::ExactScalar;
use crate::ProblemError;
use cagd_scalar::{Quadratic, Rat};

/// Solves a typed problem in `field` (its own, or the one its `values` give); `steps` records
/// the intermediate values.
pub fn solve(
    problem: &Problem,
    field: NumberField,
    limits: &Limits,
    steps: bool,
) -> Result<Out, ProblemError> {
    let checked: Vec<String> = match &problem.meta.expected {
        Some(expected) if steps => expected
            .get("steps")
            .and_then(serde_json::Value::as_object)
            .map(|names| names.keys().cloned().collect())
            .unwrap_or_default(),
        _ => Vec::new(),
    };
    let run = Run {
        limits,
        steps,
        checked: &checked,
    };
    match field {
        NumberField::Rational => run_in::<Rat>(&problem.op, run),
        NumberField::Quadratic(_) => run_in::<Quadratic>(&problem.op, run),
        NumberField::Letters(_) => run_in::<crate::value::Number>(&problem.op, run),
    }
}

fn run_in<S: ExactScalar>(op: &Op, run: Run<'_>) -> Result<Out, ProblemError> {
    match op {
        Op::Evaluate(a) if a.triangle.is_some() => triangle::evaluate::<S>(a, run),
        Op::ClosedForm(a) if a.triangle.is_some() => triangle::closed_form::<S>(a, run),
        Op::Elevate(a) if a.triangle.is_some() => triangle::elevate::<S>(a, run),
        Op::Derivative(a) if a.triangle.is_some() => triangle::derivative::<S>(a, run),
        Op::Blossom(a) if a.triangle.is_some() => triangle::blossom::<S>(a, run),
        Op::Subdivide(a) if a.triangle.is_some() => triangle::subdivide::<S>(a, run),
        Op::Boundary(a) if a.triangle.is_some() => triangle::boundary::<S>(a, run),
        Op::Normal(a) if a.triangle.is_some() => triangle::normal::<S>(a, run),
        Op::Restrict(a) if a.triangle.is_some() || a.vertices.is_some() => {
            triangle::restrict::<S>(a, run)
        }
        Op::Isocurve(a) if a.triangle.is_some() || a.w.is_some() => triangle::isocurve::<S>(a, run),
        Op::Reverse(a) if a.triangle.is_some() || a.order.is_some() => {
            triangle::reverse::<S>(a, run)
        }
        Op::Reverse(a) if a.surface.is_some() || a.direction.is_some() => {
            reverse::surface::<S>(a, run)
        }
        Op::Graph(a) if a.domain.is_some() => triangle::graph::<S>(a, run),
        Op::GaussianCurvature(a) if a.triangle.is_some() => {
            triangle::gaussian_curvature::<S>(a, run)
        }
        Op::ReduceDegree(a) if a.triangle.is_some() => triangle::reduce_degree::<S>(a, run),
        Op::Blossom(a) => control_points::blossom::<S>(a, run),
        Op::Subdivide(a) => control_points::subdivide::<S>(a, run),
        Op::Boundary(a) => control_points::boundary::<S>(a, run),
        Op::Isocurve(a) => control_points::isocurve::<S>(a, run),
        Op::Extract(a) => control_points::extract::<S>(a, run),
        Op::RemoveKnot(a) => control_points::remove_knot::<S>(a, run),
        Op::Reverse(a) => reverse::curve::<S>(a, run),
        Op::ReduceDegree(a) => control_points::reduce_degree::<S>(a, run),
        Op::ClosedForm(a) => surface::closed_form::<S>(a, run),
        Op::Graph(a) => surface::graph::<S>(a, run),
        Op::Circle(a) => curve::circle::<S>(a, run),
        Op::Evaluate(a) if a.curve.is_some() => curve::evaluate::<S>(a, run),
        Op::Evaluate(a) => patch::evaluate::<S>(a, run),
        Op::Elevate(a) if a.curve.is_some() => curve::elevate::<S>(a, run),
        Op::Elevate(a) => patch::elevate::<S>(a, run),
        Op::Restrict(a) if a.curve.is_some() => curve::restrict::<S>(a, run),
        Op::Restrict(a) => patch::restrict::<S>(a, run),
        Op::Derivative(a) if a.curve.is_some() => curve::derivative::<S>(a, run),
        Op::Derivative(a) => patch::derivative::<S>(a, run),
        Op::InsertKnot(a) if a.curve.is_some() => curve::insert_knot::<S>(a, run),
        Op::InsertKnot(a) => patch::insert_knot::<S>(a, run),
        Op::Normal(a) => patch::normal::<S>(a, run),
        Op::Continuity(a) if a.surface.is_some() => continuity::knot_lines::<S>(a, run),
        Op::Continuity(a) => continuity::continuity::<S>(a, run),
        Op::CurveContinuity(a) => curves::join::curve_continuity::<S>(a, run),
        Op::Interpolate(a) => fit::interpolate::<S>(a, run),
        Op::Approximate(a) => fit::approximate::<S>(a, run),
        Op::Translational(a) => generate::translational::<S>(a, run),
        Op::Ruled(a) => generate::ruled::<S>(a, run),
        Op::Developable(a) => generate::developable::<S>(a, run),
        Op::GaussianCurvature(a) => curvature::gaussian_curvature::<S>(a, run),
        Op::TangentDevelopable(a) => shapes::tangent_developable::<S>(a, run),
        Op::Conic(a) => shapes::conic::<S>(a, run),
        Op::ArcLength(a) => curves::length::arc_length::<S>(a, run),
        Op::KnotVector(a) => curves::knots::knot_vector::<S>(a, run),
        Op::Normalize(a) => curves::knots::normalize::<S>(a, run),
        Op::InvertPoint(a) => curves::inversion::invert_point::<S>(a, run),
        Op::Integral(a) => curves::integral::integral::<S>(a, run),
        Op::Area(a) if a.surface.is_some() => crate::surfaces::area::patch_area::<S>(a, run),
        Op::Area(a) => curves::integral::enclosed::<S>(a, run),
        Op::Loft(a) => crate::generation::loft::loft::<S>(a, run),
        Op::Coons(a) => generate::coons::<S>(a, run),
        Op::Revolution(a) => generate::revolution::<S>(a, run),
    }
}
