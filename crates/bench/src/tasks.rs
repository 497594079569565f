//! The tasks T1-T6, the worked examples and the generated problem sets, as functions the
//! benchmarks and the peers' data writer call.

use crate::input::Prepared;
use cagd_fit::{approximate_bezier_surface, interpolate_bezier_surface};
use cagd_linalg::Point;
use cagd_poly::{Monomial, Var, VecPoly};
use cagd_scalar::Scalar;
use cagd_surface::BezierSurface;
use serde_json::Value;
use std::path::{Path, PathBuf};

/// Which task.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Kind {
    /// T1: evaluate at 100 parameter pairs.
    Evaluate = 1,
    /// T2: elevate by k in both directions.
    Elevate = 2,
    /// T3: restrict to [1/3, 3/4] x [1/5, 1/2].
    Restrict = 3,
    /// T4: grid interpolation at uniform parameters.
    Interpolate = 4,
    /// T5: closed form.
    ClosedForm = 5,
    /// T6: least squares from M scattered points.
    LeastSquares = 6,
}

/// A task at one size: bidegree (n, n), and k (T2) or M (T6).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Task {
    /// Which task.
    pub kind: Kind,
    /// The bidegree (n, n).
    pub n: usize,
    /// k for T2, M for T6, 0 otherwise.
    pub extra: usize,
}

const fn t(kind: Kind, n: usize, extra: usize) -> Task {
    Task { kind, n, extra }
}

/// Every task and size of the issue.
pub const TASKS: &[Task] = &[
    t(Kind::Evaluate, 3, 0),
    t(Kind::Evaluate, 6, 0),
    t(Kind::Evaluate, 10, 0),
    t(Kind::Evaluate, 20, 0),
    t(Kind::Elevate, 3, 1),
    t(Kind::Elevate, 3, 5),
    t(Kind::Elevate, 10, 1),
    t(Kind::Elevate, 10, 5),
    t(Kind::Elevate, 20, 1),
    t(Kind::Elevate, 20, 5),
    t(Kind::Restrict, 3, 0),
    t(Kind::Restrict, 10, 0),
    t(Kind::Restrict, 20, 0),
    t(Kind::Interpolate, 3, 0),
    t(Kind::Interpolate, 6, 0),
    t(Kind::Interpolate, 10, 0),
    t(Kind::Interpolate, 20, 0),
    t(Kind::Interpolate, 30, 0),
    t(Kind::ClosedForm, 3, 0),
    t(Kind::ClosedForm, 6, 0),
    t(Kind::ClosedForm, 10, 0),
    t(Kind::LeastSquares, 2, 50),
    t(Kind::LeastSquares, 2, 200),
    t(Kind::LeastSquares, 4, 50),
    t(Kind::LeastSquares, 4, 200),
    t(Kind::LeastSquares, 6, 50),
    t(Kind::LeastSquares, 6, 200),
];

/// What a task computed, before flattening.
#[derive(Clone, Debug)]
pub enum Answer<S: Scalar> {
    /// Points (T1).
    Points(Vec<Point<S>>),
    /// A patch (T2, T3, T4, T6).
    Surface(BezierSurface<S>),
    /// A polynomial map (T5).
    Closed(VecPoly<S>),
}

impl Task {
    /// `T1`, ..., `T6`.
    pub fn label(&self) -> String {
        format!("T{}", self.kind as u8)
    }

    /// A name for benchmark ids and JSON keys: `T2 n=10 k=5`.
    pub fn name(&self) -> String {
        match self.kind {
            Kind::Elevate => format!("{} n={} k={}", self.label(), self.n, self.extra),
            Kind::LeastSquares => format!("{} n={} M={}", self.label(), self.n, self.extra),
            _ => format!("{} n={}", self.label(), self.n),
        }
    }

    /// One line describing the task.
    pub fn describe(&self) -> String {
        let n = self.n;
        match self.kind {
            Kind::Evaluate => format!("100 points on a ({n}, {n}) patch"),
            Kind::Elevate => format!("elevate ({n}, {n}) by {}", self.extra),
            Kind::Restrict => format!("restrict ({n}, {n}) to [1/3, 3/4] x [1/5, 1/2]"),
            Kind::Interpolate => format!("interpolate a ({n}, {n}) grid"),
            Kind::ClosedForm => format!("closed form of ({n}, {n})"),
            Kind::LeastSquares => format!("least squares ({n}, {n}), {} points", self.extra),
        }
    }

    /// Runs the task through the public API of the engine; the engine's message when it
    /// refuses (it does not for the exact inputs, which are valid by construction; over f64
    /// the normal matrix of T6 can be too ill-conditioned to factor).
    pub fn run<S: Scalar>(&self, input: &Prepared<S>) -> Result<Answer<S>, String> {
        let text = |e: &dyn std::fmt::Display| e.to_string();
        let surface = || {
            input
                .surface
                .as_ref()
                .ok_or_else(|| "the input has no patch".to_string())
        };
        Ok(match self.kind {
            Kind::Evaluate => {
                let s = surface()?;
                Answer::Points(
                    input
                        .params
                        .iter()
                        .map(|(u, v)| s.eval(u, v).map_err(|e| text(&e)))
                        .collect::<Result<_, _>>()?,
                )
            }
            Kind::Elevate => Answer::Surface(
                surface()?
                    .elevate(self.extra, self.extra)
                    .map_err(|e| text(&e))?,
            ),
            Kind::Restrict => {
                let r = surface()?
                    .restrict(
                        &S::from_ratio(1, 3),
                        &S::from_ratio(3, 4),
                        &S::from_ratio(1, 5),
                        &S::from_ratio(1, 2),
                    )
                    .map_err(|e| text(&e))?;
                Answer::Surface(r.result)
            }
            Kind::Interpolate => {
                let grid = input.grid.as_ref().ok_or("the input has no grid")?;
                Answer::Surface(
                    interpolate_bezier_surface(&input.uniform, &input.uniform, grid)
                        .map_err(|e| text(&e))?,
                )
            }
            Kind::ClosedForm => Answer::Closed(surface()?.closed_form().map_err(|e| text(&e))?),
            Kind::LeastSquares => Answer::Surface(
                approximate_bezier_surface(self.n, self.n, &input.params, &input.points)
                    .map_err(|e| text(&e))?,
            ),
        })
    }

    /// The numbers of an answer in the order the peers' script writes them: points one after
    /// the other (T1), meshes row by row (T2, T3, T4, T6), each point x, y, z; closed forms
    /// (T5) as the coefficient of u^k v^l for each coordinate, then k = 0..n, then l = 0..n.
    pub fn flatten<S: Scalar>(&self, answer: &Answer<S>) -> Vec<S> {
        match answer {
            Answer::Points(points) => points.iter().flat_map(|p| p.coords().to_vec()).collect(),
            Answer::Surface(s) => s.mesh().iter().flat_map(|p| p.coords().to_vec()).collect(),
            Answer::Closed(c) => {
                let n = u32::try_from(self.n).unwrap_or(0);
                let mut out = Vec::new();
                for poly in c.components() {
                    for k in 0..=n {
                        for l in 0..=n {
                            out.push(
                                poly.coeff(&Monomial::from_powers(&[(Var::U, k), (Var::V, l)])),
                            );
                        }
                    }
                }
                out
            }
        }
    }
}

/// The fixtures of `cagd examples`: every JSON file under `fixtures/` (the repository's), in
/// order of path.
pub fn examples_fixtures() -> Vec<Value> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fixtures");
    let mut files = Vec::new();
    walk(&root, &mut files);
    files
        .iter()
        .filter_map(|f| std::fs::read_to_string(f).ok())
        .filter_map(|text| serde_json::from_str(&text).ok())
        .collect()
}

fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut paths: Vec<PathBuf> = entries.filter_map(Result::ok).map(|e| e.path()).collect();
    paths.sort();
    for p in paths {
        if p.is_dir() {
            walk(&p, out);
        } else if p.extension().is_some_and(|e| e == "json") {
            out.push(p);
        }
    }
}

/// `cagd examples`: checks every fixture; returns how many passed.
pub fn run_examples(fixtures: &[Value]) -> usize {
    fixtures
        .iter()
        .filter(|f| cagd_problem::check(f).passed())
        .count()
}

/// 1,000 generated problems: the topics of `cagd generate` in turn, as many of each as it
/// takes (seed 2026).
pub fn generated_problems(count: usize) -> Vec<Value> {
    let topics = cagd_exercises::topics();
    let per = count.div_ceil(topics.len().max(1));
    let mut out = Vec::with_capacity(count);
    for t in topics {
        if let Ok(set) = cagd_exercises::generate(t.name, per, 2026) {
            out.extend(set);
        }
    }
    out.truncate(count);
    out
}

/// `cagd solve` on a problem set; returns how many were solved.
pub fn run_problems(problems: &[Value]) -> usize {
    problems
        .iter()
        .filter(|p| cagd_problem::solve(p).is_ok())
        .count()
}
