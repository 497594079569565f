//! What an operation produces ([`Out`], the one recorder of the problem layer) and the reading
//! of a run ([`Run`]: limits, steps, the checked step names), shared by every operation.

use crate::limits::{Limit, Limits};
use crate::message::fitting::Fitting;
use crate::message::inner::Inner;
use crate::steps::{Fact, Formula, Step};
use crate::{Exact, Named, ProblemError, Quantity};

pub(crate) use crate::convert::{at, num, pair, req};

/// What an operation produces, and whether its steps are asked for: the one recorder of the
/// problem layer. Without steps, [`Out::step`] keeps nothing and the operations take the fast
/// kernels (`Out::steps_on` is false); with them, the step-by-step routes whose intermediate
/// values the notes show.
pub struct Out {
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

    /// Whether the problem's `expected` checks the step `quantity` (so it must be computed
    /// in full, whatever the key shows of it).
    pub fn checks(&self, quantity: &Quantity) -> bool {
        self.record && self.checked.iter().any(|c| *c == quantity.name())
    }

    /// Whether the problem's `expected` checks any of the steps `quantities`.
    pub fn checks_any(&self, quantities: &[Quantity]) -> bool {
        quantities.iter().any(|q| self.checks(q))
    }

    /// Whether the steps are asked for.
    pub fn steps_on(&self) -> bool {
        self.record
    }

    /// Adds the result `quantity` = `value`.
    pub fn result(mut self, quantity: Quantity, value: Exact) -> Self {
        self.result.push((quantity, value));
        self
    }

    /// Adds the closed form `value`, in its variables.
    pub fn closed_form(self, value: Exact) -> Self {
        self.result(Quantity::ClosedForm(value.variables()), value)
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
    pub fn step(mut self, quantity: Quantity, value: Exact) -> Self {
        if self.record {
            self.steps.push((quantity, value));
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
                crate::message::read::Read::DegreeAbove { degree: n.0, max },
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
