//! Dispatch: one `match` on the typed operation, run over the problem's scalar.

mod arc;
mod breadth;
mod curvature;
mod curve;
mod explain;
mod fit;
mod generate;
mod join;
mod length;
mod length_rational;
mod params;
mod patch;
mod pieces;
mod reduce;
mod reversal;
mod shapes;
mod surface;
mod surface_knots;
mod triangle;
mod zeros;

pub(crate) use curve::{convert, convert_points};

use crate::field::NumberField;
use crate::limits::{Limit, Limits};
use crate::message::check::Inner;
use crate::message::fitting::Fitting;
use crate::problem::{Op, Problem};
use crate::steps::{Fact, Formula, Step};
use crate::value::ExactScalar;
use crate::{Exact, Named, ProblemError};
use cagd_scalar::{Quadratic, Rat};

pub(crate) use arc::{default_arcs, root_of_angles};

/// What an operation produces, and whether its steps are asked for: the one recorder of the
/// problem layer. Without steps, [`Out::step`] keeps nothing and the operations take the fast
/// kernels (`Out::steps_on` is false); with them, the step-by-step routes whose intermediate
/// values the notes show.
pub(crate) struct Out {
    pub result: Vec<Named>,
    pub steps: Vec<Named>,
    /// The steps as a teacher writes them (formula, substitution, tables): typed, rendered
    /// by cagd-keys.
    pub derivation: Vec<Step>,
    pub remarks: Vec<crate::Message>,
    record: bool,
    /// The named steps the problem's `expected` checks (under `"steps"`): an operation that
    /// summarises a big step in its derivation still computes these in full.
    checked: Vec<String>,
}

impl Out {
    /// Adds a remark.
    pub fn remark(&mut self, m: impl Into<crate::Message>) {
        self.remarks.push(m.into());
    }

    pub fn new(record: bool) -> Self {
        Out {
            result: Vec::new(),
            steps: Vec::new(),
            derivation: Vec::new(),
            remarks: Vec::new(),
            record,
            checked: Vec::new(),
        }
    }

    /// Whether the problem's `expected` checks the named step `name` (so it must be computed
    /// in full, whatever the key shows of it).
    pub fn checks(&self, name: &str) -> bool {
        self.record && self.checked.iter().any(|c| c == name)
    }

    /// Whether the problem's `expected` checks any of the named steps `names`.
    pub fn checks_any(&self, names: &[&str]) -> bool {
        names.iter().any(|n| self.checks(n))
    }

    /// Whether the steps are asked for.
    pub fn steps_on(&self) -> bool {
        self.record
    }

    pub fn result(mut self, name: &str, value: Exact) -> Self {
        self.result.push((name.to_string(), value));
        self
    }

    /// Records a step of the derivation (nothing when no steps are asked). The caller computes
    /// what it records only when [`Out::steps_on`].
    pub fn explain(&mut self, step: Step) {
        if self.record {
            self.derivation.push(step);
        }
    }

    /// Records the formula `f` (nothing when no steps are asked).
    pub fn formula(&mut self, f: Formula) {
        self.explain(Step::formula(f));
    }

    /// Records `symbol = value` (nothing when no steps are asked).
    pub fn value(&mut self, symbol: impl Into<String>, value: Exact) {
        self.explain(Step::value(symbol, value));
    }

    /// Records a fact (nothing when no steps are asked).
    pub fn fact(&mut self, fact: Fact) {
        self.explain(Step::Fact(fact));
    }

    /// Records a step (nothing when no steps are asked).
    pub fn step(mut self, name: &str, value: Exact) -> Self {
        if self.record {
            self.steps.push((name.to_string(), value));
        }
        self
    }
}

/// The reading of a run: limits, whether steps are recorded, and which named steps the
/// problem's `expected` checks.
#[derive(Clone, Copy)]
pub(crate) struct Run<'a> {
    pub limits: &'a Limits,
    pub steps: bool,
    pub checked: &'a [String],
}

impl Run<'_> {
    pub fn out(&self) -> Out {
        let mut out = Out::new(self.steps);
        out.checked = self.checked.to_vec();
        out
    }

    /// `Err` at `path` when a result of `points` points (`what`, words) would exceed the
    /// points limit.
    pub fn check_points(
        &self,
        path: &str,
        points: usize,
        what: impl Subject,
    ) -> Result<(), ProblemError> {
        let max = self.limits.max_points;
        if points > max {
            return Err(ProblemError::limit(
                path,
                Fitting::TooManyPoints {
                    what: Inner::new(what.said()),
                    points,
                    max,
                },
                Limit::Points,
            ));
        }
        Ok(())
    }

    /// `Err` at `path` when a computed degree (of `what`, words) would exceed the degree
    /// limit.
    pub fn check_degree(
        &self,
        path: &str,
        degree: usize,
        what: impl Subject,
    ) -> Result<(), ProblemError> {
        let max = self.limits.max_degree;
        if degree > max {
            return Err(ProblemError::limit(
                path,
                Fitting::DegreeAbove {
                    what: Inner::new(what.said()),
                    degree,
                    max,
                },
                Limit::Degree,
            ));
        }
        Ok(())
    }

    /// A degree (or order) given by the problem, within the degree limit.
    pub fn degree(&self, path: &str, n: crate::spec::Int) -> Result<usize, ProblemError> {
        let max = self.limits.max_degree;
        if n.get() > max {
            return Err(ProblemError::limit(
                path,
                Fitting::DegreeLimit { n: n.0, max },
                Limit::Degree,
            ));
        }
        Ok(n.get())
    }

    /// How many times a knot is inserted or removed (`times`, default 1), within the degree
    /// limit (a knot's multiplicity is at most the degree plus one).
    pub fn times(&self, times: Option<crate::spec::Int>) -> Result<usize, ProblemError> {
        times
            .map(|t| self.degree("times", t))
            .transpose()
            .map(|t| t.unwrap_or(1))
    }

    /// A count (of arcs) given by the problem, within the points limit.
    pub fn count(&self, path: &str, n: crate::spec::Int) -> Result<usize, ProblemError> {
        let max = self.limits.max_points;
        if n.get() > max {
            return Err(ProblemError::limit(
                path,
                Fitting::CountLimit { n: n.0, max },
                Limit::Points,
            ));
        }
        Ok(n.get())
    }
}

/// What a limit refuses (the subject of its sentence): a typed sentence.
pub(crate) trait Subject {
    /// The words.
    fn said(self) -> crate::Message;
}

impl Subject for crate::Message {
    fn said(self) -> crate::Message {
        self
    }
}

macro_rules! subject {
    ($($t:ty),+) => {$(
        impl Subject for $t {
            fn said(self) -> crate::Message {
                self.into()
            }
        }
    )+};
}

subject!(
    Fitting,
    crate::message::curve::Curve,
    crate::message::surface::Surface,
    crate::message::limited::Limited
);

/// An error of an algorithm, at `path`.
pub(crate) fn at<E: Into<crate::Message>>(path: &str) -> impl Fn(E) -> ProblemError + '_ {
    move |e| ProblemError::at(path, e)
}

/// A required argument.
pub(crate) fn req<'a, T>(x: &'a Option<T>, path: &str) -> Result<&'a T, ProblemError> {
    x.as_ref()
        .ok_or_else(|| ProblemError::at(path, Fitting::Missing))
}

/// A number of the problem in its scalar.
pub(crate) fn num<S: ExactScalar>(x: &crate::spec::Num, path: &str) -> Result<S, ProblemError> {
    x.to::<S>().map_err(|e| ProblemError::at(path, e))
}

/// A pair of numbers of the problem in its scalar.
pub(crate) fn pair<S: ExactScalar>(
    x: &crate::spec::Pair,
    path: &str,
) -> Result<(S, S), ProblemError> {
    x.to::<S>().map_err(|e| ProblemError::at(path, e))
}

/// Solves a typed problem in `field` (its own, or the one its `values` give); `steps` records
/// the intermediate values.
pub(crate) fn solve(
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
            reversal::surface::<S>(a, run)
        }
        Op::Graph(a) if a.domain.is_some() => triangle::graph::<S>(a, run),
        Op::GaussianCurvature(a) if a.triangle.is_some() => {
            triangle::gaussian_curvature::<S>(a, run)
        }
        Op::ReduceDegree(a) if a.triangle.is_some() => triangle::reduce_degree::<S>(a, run),
        Op::Blossom(a) => breadth::blossom::<S>(a, run),
        Op::Subdivide(a) => breadth::subdivide::<S>(a, run),
        Op::Boundary(a) => breadth::boundary::<S>(a, run),
        Op::Isocurve(a) => breadth::isocurve::<S>(a, run),
        Op::Extract(a) => breadth::extract::<S>(a, run),
        Op::RemoveKnot(a) => breadth::remove_knot::<S>(a, run),
        Op::Reverse(a) => breadth::reverse::<S>(a, run),
        Op::ReduceDegree(a) => breadth::reduce_degree::<S>(a, run),
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
        Op::Continuity(a) if a.surface.is_some() => patch::knot_lines::<S>(a, run),
        Op::Continuity(a) => patch::continuity::<S>(a, run),
        Op::CurveContinuity(a) => join::curve_continuity::<S>(a, run),
        Op::Interpolate(a) => fit::interpolate::<S>(a, run),
        Op::Approximate(a) => fit::approximate::<S>(a, run),
        Op::Translational(a) => generate::translational::<S>(a, run),
        Op::Ruled(a) => generate::ruled::<S>(a, run),
        Op::Developable(a) => generate::developable::<S>(a, run),
        Op::GaussianCurvature(a) => curvature::gaussian_curvature::<S>(a, run),
        Op::TangentDevelopable(a) => shapes::tangent_developable::<S>(a, run),
        Op::Conic(a) => shapes::conic::<S>(a, run),
        Op::ArcLength(a) => length::arc_length::<S>(a, run),
        Op::Coons(a) => generate::coons::<S>(a, run),
        Op::Revolution(a) => generate::revolution::<S>(a, run),
    }
}
