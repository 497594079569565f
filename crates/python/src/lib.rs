//! `cagd_exact._native`: cagd-exact inside the Python interpreter (PyO3).
//!
//! The pure-Python package `cagd_exact` (python/cagd_exact) re-exports what is here. Problems
//! are the JSON problems of `cagd solve` (docs/format.md), given as a dict, a list or a JSON
//! string; they are read once by the same reader (`cagd_problem::Problem::read`), solved by the
//! same `check_problem`/`check_batch`, and answered as `Answer` objects that keep the engine's
//! typed answer and convert it only when asked. Errors are one exception class, `CagdError`,
//! with the command line's message and the field path.

mod answer;
mod convert;
mod error;
mod figures;
mod said;

use answer::{PyAnswer, PyProblem};
use cagd_poly::{parse_expr, Expr};
use cagd_problem::{check_batch, ProblemError, Verdict};
use convert::{problem_text, problem_value, to_python, Numbers};
use error::{cagd_error, lang, problem_error, settings, CagdError};
use figures::{Figure, Page};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use said::PyMessage;
use serde_json::Value;

/// The allocator of the module's own values (Python's objects keep Python's): mimalloc, as in
/// `cagd solve`. Reading a problem from a dict and answering it allocate many small values
/// (strings, big integers, vectors), a third of the time of reading with the system's malloc.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

/// A problem given from Python as JSON, or the `CagdError` naming what cannot be read.
fn value_of(problem: &Bound<'_, PyAny>) -> PyResult<Value> {
    problem_value(problem).map_err(|e| problem_error(&e))
}

/// Reads one problem once (every number through the grammar, under the limits given as
/// keywords: `max_degree=64`...): a `Problem` to solve, and solve again, without reading it
/// again.
#[pyfunction]
#[pyo3(signature = (problem, **limits))]
fn read(problem: &Bound<'_, PyAny>, limits: Option<&Bound<'_, PyDict>>) -> PyResult<PyProblem> {
    let value = value_of(problem)?;
    if value.is_array() {
        return Err(cagd_error(PyMessage::ReadTakesOne));
    }
    PyProblem::read(&value, settings(false, limits)?)
}

/// Solves one problem exactly: a dict, a JSON string, or a `Problem` from `read`. Returns an
/// `Answer`; a problem that cannot be answered raises `CagdError` with the command line's
/// message and field path. With `steps=True` the intermediate values the notes show are
/// recorded; `lang` (`en`, `es`) is the language of the key the answer shows. A list (or a JSON
/// array) is solved as `solve_batch` does.
#[pyfunction]
#[pyo3(signature = (problem, *, steps=false, lang="en", **limits))]
fn solve(
    py: Python<'_>,
    problem: &Bound<'_, PyAny>,
    steps: bool,
    lang: &str,
    limits: Option<&Bound<'_, PyDict>>,
) -> PyResult<Py<PyAny>> {
    let language = error::lang(lang)?;
    if let Ok(p) = problem.cast::<PyProblem>() {
        if limits.is_some_and(|l| !l.is_empty()) {
            return Err(cagd_error(PyMessage::ReadUnderLimits));
        }
        let answer = PyAnswer::from_verdict(p.get().verdict(py, steps), steps, language)?;
        return Ok(Bound::new(py, answer)?.into_any().unbind());
    }
    if problem.cast::<PyList>().is_ok() {
        return solve_batch(py, problem, steps, lang, 1, "raise", limits)
            .map(|l| l.into_any().unbind());
    }
    if problem.cast::<PyDict>().is_ok() {
        // one problem: its text read straight into the typed problem
        let text = problem_text(problem).map_err(|e| problem_error(&e))?;
        let parsed = PyProblem::read_text(&text, settings(steps, limits)?)?;
        let answer = PyAnswer::from_verdict(parsed.verdict(py, steps), steps, language)?;
        return Ok(Bound::new(py, answer)?.into_any().unbind());
    }
    let value = value_of(problem)?;
    if value.is_array() {
        let list = to_python(py, &value, Numbers::Json)?;
        return solve_batch(py, &list, steps, lang, 1, "raise", limits)
            .map(|l| l.into_any().unbind());
    }
    let parsed = PyProblem::read(&value, settings(steps, limits)?)?;
    let answer = PyAnswer::from_verdict(parsed.verdict(py, steps), steps, language)?;
    Ok(Bound::new(py, answer)?.into_any().unbind())
}

/// Solves a batch (a list of problems, or a JSON array) as `cagd solve` does: each problem on
/// its own, on `threads` threads, the answers in order. With `errors="raise"` (the default)
/// the first problem that fails raises its `CagdError` (the message names its index); with
/// `errors="return"` its place in the list holds the `CagdError` and the others are answered.
#[pyfunction]
#[pyo3(signature = (problems, *, steps=false, lang="en", threads=1, errors="raise", **limits))]
fn solve_batch<'py>(
    py: Python<'py>,
    problems: &Bound<'py, PyAny>,
    steps: bool,
    lang: &str,
    threads: usize,
    errors: &str,
    limits: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyList>> {
    let language = error::lang(lang)?;
    let raise = match errors {
        "raise" => true,
        "return" => false,
        other => {
            return Err(PyValueError::new_err(format!(
                "errors is 'raise' or 'return', found '{other}'"
            )))
        }
    };
    let settings = settings(steps, limits)?;
    // each problem converted on its own, so that one that cannot be read fails alone
    let mut unread: Vec<Option<ProblemError>> = Vec::new();
    let mut values = Vec::new();
    if let Ok(list) = problems.cast::<PyList>() {
        for (i, item) in list.iter().enumerate() {
            match problem_value(&item) {
                Ok(v) => {
                    values.push(v);
                    unread.push(None);
                }
                Err(e) => {
                    values.push(Value::Null);
                    unread.push(Some(e.in_problem(i)));
                }
            }
        }
    } else {
        match value_of(problems)? {
            Value::Array(items) => values = items,
            one => values.push(one),
        }
        unread.resize(values.len(), None);
    }
    let batch = Value::Array(values);
    let verdicts: Vec<Verdict> = py.detach(|| check_batch(&batch, &settings, threads.max(1)));
    let mut out = Vec::with_capacity(verdicts.len());
    for (i, verdict) in verdicts.into_iter().enumerate() {
        let verdict = match unread.get_mut(i).and_then(Option::take) {
            Some(e) => Verdict::failed(e),
            None => verdict,
        };
        match PyAnswer::from_verdict(verdict, steps, language) {
            Ok(a) => out.push(Bound::new(py, a)?.into_any()),
            Err(e) if raise => return Err(e),
            Err(e) => out.push(e.into_value(py).into_bound(py).into_any()),
        }
    }
    PyList::new(py, out)
}

/// Checks an answer written under `"expected"`, a teacher's or a student's (as `cagd check`):
/// the `Answer`, whose `passed` and `mismatches` say where it differs and whose `assessment`
/// diagnoses it (every entry right or wrong, the score, the common mistakes that explain it);
/// its `to_json()` is the JSON of `cagd check --format json` for the problem. A problem with
/// no `expected` does not pass ("nothing to check").
#[pyfunction]
#[pyo3(signature = (problem, *, lang="en", **limits))]
fn check(
    py: Python<'_>,
    problem: &Bound<'_, PyAny>,
    lang: &str,
    limits: Option<&Bound<'_, PyDict>>,
) -> PyResult<PyAnswer> {
    let language = error::lang(lang)?;
    let value = value_of(problem)?;
    let parsed = PyProblem::read(&value, settings(true, limits)?)?;
    let verdict = parsed.diagnosed(py).require_expected(&value);
    PyAnswer::from_verdict(verdict, true, language)
}

/// The expanded closed form of a polynomial expression (as `cagd expand`).
#[pyclass(module = "cagd_exact", name = "Expression", frozen)]
struct Expression {
    expr: Expr,
}

#[pymethods]
impl Expression {
    /// The closed form as text: `(u, v, -u^3 v + u^3 + u^2 v)`.
    fn text(&self) -> String {
        self.expr.to_text()
    }

    /// The closed form in LaTeX.
    fn latex(&self) -> String {
        self.expr.to_latex()
    }

    /// The closed form in the grammar, which reads back exactly: `(u, v, -u^3*v + ...)`.
    fn json(&self) -> String {
        self.expr.to_json_string()
    }

    /// The closed form as a SymPy expression (a `Tuple` for a point). Needs SymPy.
    fn sympy<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        py.import("cagd_exact._convert")?
            .getattr("sympy_expr")?
            .call1((self.expr.to_json_string(),))
    }

    fn _repr_latex_(&self) -> String {
        format!("${}$", self.expr.to_latex())
    }

    fn __str__(&self) -> String {
        self.expr.to_text()
    }

    fn __repr__(&self) -> String {
        format!("cagd_exact.expand({:?})", self.expr.to_json_string())
    }
}

/// Expands a polynomial expression in u, v, w, t, s, x, y, z with exact coefficients to its
/// closed form: `expand("(1 - v)*(u, 0, u^3) + v*(u, 1, u^2)")`.
#[pyfunction]
fn expand(expr: &str) -> PyResult<Expression> {
    parse_expr(expr)
        .map(|expr| Expression { expr })
        .map_err(|e| cagd_error(PyMessage::Expression(e)))
}

/// The worked examples of the notes (the fixtures of `cagd examples`), as problems: dicts
/// with `name`, `title`, `source`, `expected`... ready for `solve` or `check`. With names (or
/// prefixes such as `ch5`), only those.
#[pyfunction]
#[pyo3(signature = (*names))]
fn examples<'py>(py: Python<'py>, names: Vec<String>) -> PyResult<Bound<'py, PyList>> {
    let mut out = Vec::new();
    for (path, text) in cagd_fixtures::FIXTURES {
        let value: Value = serde_json::from_str(text).map_err(|e| {
            cagd_error(PyMessage::FixtureNotJson {
                path: path.to_string(),
                why: Box::new(cagd_problem::problem::serde_error(&e)),
            })
        })?;
        let name = value.get("name").and_then(Value::as_str).unwrap_or(path);
        if names.is_empty() || names.iter().any(|n| name.starts_with(n.as_str())) {
            out.push(to_python(py, &value, Numbers::Json)?);
        }
    }
    if out.is_empty() {
        return Err(cagd_error(PyMessage::NoExample {
            names: names.join(", "),
        }));
    }
    PyList::new(py, out)
}

/// A problem set for students: `count` random problems of `topic` with friendly numbers,
/// the same for the same seed (as `cagd generate`), as a list of problem dicts.
#[pyfunction]
#[pyo3(signature = (topic, count=10, seed=1, lang="en"))]
fn generate<'py>(
    py: Python<'py>,
    topic: &str,
    count: usize,
    seed: u64,
    lang: &str,
) -> PyResult<Bound<'py, PyList>> {
    let problems = cagd_exercises::generate_in(topic, count, seed, error::lang(lang)?)
        .map_err(|e| cagd_error(PyMessage::Exercises(e)))?;
    let items = problems
        .iter()
        .map(|p| to_python(py, p, Numbers::Json))
        .collect::<PyResult<Vec<_>>>()?;
    PyList::new(py, items)
}

/// The topics of `generate`: name → description.
#[pyfunction]
fn topics<'py>(py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    for t in cagd_exercises::topics() {
        dict.set_item(t.name, t.description)?;
    }
    Ok(dict)
}

/// The operations `solve` knows.
#[pyfunction]
fn operations() -> Vec<&'static str> {
    cagd_problem::operations().to_vec()
}

/// The figure of an `Answer`, of a problem (solved first), or of an answer of
/// `cagd solve --format json` or a bare surface or curve given as a dict or JSON string.
/// With `steps`, the intermediate surfaces too (c_c, c_d, c_cd of a Coons patch).
#[pyfunction]
#[pyo3(signature = (obj, *, steps=false))]
fn figure(py: Python<'_>, obj: &Bound<'_, PyAny>, steps: bool) -> PyResult<Figure> {
    if let Ok(a) = obj.cast::<PyAnswer>() {
        return a.get().figure_of(steps);
    }
    let value = value_of(obj)?;
    if value.get("op").is_some() && value.get("ok").is_none() {
        let problem = PyProblem::read(&value, settings(steps, None)?)?;
        let answer = PyAnswer::from_verdict(problem.verdict(py, steps), steps, lang("en")?)?;
        return answer.figure_of(steps);
    }
    Figure::of_json(&value, steps)
}

/// The module.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("CagdError", m.py().get_type::<CagdError>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add_class::<PyAnswer>()?;
    m.add_class::<PyProblem>()?;
    m.add_class::<Figure>()?;
    m.add_class::<Page>()?;
    m.add_class::<Expression>()?;
    m.add_function(wrap_pyfunction!(read, m)?)?;
    m.add_function(wrap_pyfunction!(solve, m)?)?;
    m.add_function(wrap_pyfunction!(solve_batch, m)?)?;
    m.add_function(wrap_pyfunction!(check, m)?)?;
    m.add_function(wrap_pyfunction!(expand, m)?)?;
    m.add_function(wrap_pyfunction!(examples, m)?)?;
    m.add_function(wrap_pyfunction!(generate, m)?)?;
    m.add_function(wrap_pyfunction!(topics, m)?)?;
    m.add_function(wrap_pyfunction!(operations, m)?)?;
    m.add_function(wrap_pyfunction!(figure, m)?)?;
    Ok(())
}
