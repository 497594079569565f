//! Dispatch: one `match` on the operation, run over the problem's scalar.

mod curve;
mod fit;
mod generate;
mod patch;
mod surface;

use crate::field::{self, NumberField};
use crate::input::Field;
use crate::limits::Limits;
use crate::value::ExactScalar;
use crate::{Answer, Named, ProblemError};
use cagd_scalar::{BigRational, Quadratic};
use serde_json::Value;

/// Every operation `solve` knows.
pub const NAMES: &[&str] = &[
    "evaluate",
    "closed_form",
    "restrict",
    "elevate",
    "derivative",
    "normal",
    "continuity",
    "interpolate",
    "approximate",
    "translational",
    "ruled",
    "developable",
    "coons",
    "revolution",
    "insert_knot",
    "graph",
    "circle",
];

/// What an operation produces.
#[derive(Default)]
pub(crate) struct Out {
    pub result: Vec<Named>,
    pub steps: Vec<Named>,
    pub remarks: Vec<String>,
}

impl Out {
    pub fn result(mut self, name: &str, value: crate::Exact) -> Self {
        self.result.push((name.to_string(), value));
        self
    }
    pub fn step(mut self, name: &str, value: crate::Exact) -> Self {
        self.steps.push((name.to_string(), value));
        self
    }
}

pub(crate) fn solve(problem: &Value, limits: &Limits) -> Result<Answer, ProblemError> {
    let root = Field::root_with(problem, limits);
    if !problem.is_object() {
        return Err(root.error(format!(
            "expected a problem object {{\"op\": ...}}, found {}",
            crate::input::kind(problem)
        )));
    }
    let op_field = root.req("op")?;
    let op = op_field.str()?;
    if !NAMES.contains(&op) {
        return Err(op_field.error(format!(
            "unknown operation {op:?}; the operations are: {}",
            NAMES.join(", ")
        )));
    }
    let field = field::choose_with(problem, needed_root(op, &root), limits)?;
    let out = match field {
        NumberField::Rational => run::<BigRational>(op, &root)?,
        NumberField::Quadratic(_) => run::<Quadratic>(op, &root)?,
    };
    Ok(Answer {
        op: op.to_string(),
        field,
        result: out.result,
        steps: out.steps,
        remarks: out.remarks,
    })
}

/// A root the operation itself needs: circles of quarter arcs (1 or 4) need √2/2 for their
/// weights; of 3 or 6 arcs, √3 (their control points lie on equilateral triangles).
fn needed_root(op: &str, root: &Field<'_>) -> Option<u64> {
    let arcs = root.get("arcs").and_then(|a| a.usize().ok());
    match (op, arcs) {
        ("revolution" | "circle", Some(3 | 6)) => Some(3),
        ("revolution" | "circle", _) => Some(2),
        _ => None,
    }
}

fn run<S: ExactScalar>(op: &str, p: &Field<'_>) -> Result<Out, ProblemError> {
    match op {
        "closed_form" => surface::closed_form::<S>(p),
        "graph" => surface::graph::<S>(p),
        "circle" => curve::circle::<S>(p),
        // operations on a curve
        "evaluate" if p.get("curve").is_some() => curve::evaluate::<S>(p),
        "elevate" if p.get("curve").is_some() => curve::elevate::<S>(p),
        "restrict" if p.get("curve").is_some() => curve::restrict::<S>(p),
        "derivative" if p.get("curve").is_some() => curve::derivative::<S>(p),
        "insert_knot" if p.get("curve").is_some() => curve::insert_knot::<S>(p),
        // operations on a surface
        "evaluate" => patch::evaluate::<S>(p),
        "restrict" => patch::restrict::<S>(p),
        "elevate" => patch::elevate::<S>(p),
        "derivative" => patch::derivative::<S>(p),
        "normal" => patch::normal::<S>(p),
        "continuity" => patch::continuity::<S>(p),
        "insert_knot" => patch::insert_knot::<S>(p),
        "interpolate" => fit::interpolate::<S>(p),
        "approximate" => fit::approximate::<S>(p),
        // chapter 6
        "translational" => generate::translational::<S>(p),
        "ruled" => generate::ruled::<S>(p),
        "developable" => generate::developable::<S>(p),
        "coons" => generate::coons::<S>(p),
        "revolution" => generate::revolution::<S>(p),
        other => Err(p.error(format!(
            "the operation {other:?} is not available yet in this build"
        ))),
    }
}
