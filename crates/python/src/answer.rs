//! `Answer` and `Problem`: the Rust values inside Python objects, converted only when read.
//!
//! An `Answer` keeps the engine's typed answer (its exact values as the engine computed them);
//! nothing is printed or converted to Python until a property or method asks for it
//! (`answer.result`, `answer["surface"]`, `.to_json()`, `.fractions()`, a repr). A `Problem`
//! is a problem read once (every number through the grammar): solving it again pays the
//! reading once.

use crate::convert::{to_python, to_python_at, Numbers};
use crate::error::{lang, problem_error};
use crate::figures::Figure;
use cagd_keys::{example_latex, example_markdown, example_text, latex, latex_name, Lang};
use cagd_problem::{
    check_problem, Answer, Exact, NumberField, Problem, Quantity, Settings, Verdict,
};
use pyo3::exceptions::{PyKeyError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use serde_json::Value;
use std::sync::Arc;

/// The answer to one problem, exact. Values are converted only when read.
///
/// `answer.result` (and `answer["surface"]`) gives the results in the JSON form of
/// `cagd solve --format json` (numbers as strings of the grammar, `"5/6"`, `"sqrt2/2"`);
/// `answer.fractions()` with `fractions.Fraction`s, `answer.sympy()` with SymPy numbers and
/// expressions. In Jupyter it shows itself as its answer key (Markdown, or LaTeX), with its
/// steps when it was solved with `steps=True`, in `lang` (`answer.show(lang="es")`).
#[pyclass(module = "cagd_exact", name = "Answer", frozen)]
pub struct PyAnswer {
    verdict: Verdict,
    steps: bool,
    lang: Lang,
}

impl PyAnswer {
    /// The answer of a verdict, or the `CagdError` of a failed problem. Steps recorded only to
    /// check a fixture's `expected` are dropped when they were not asked for, as `cagd solve`
    /// drops them.
    pub fn from_verdict(mut verdict: Verdict, steps: bool, lang: Lang) -> PyResult<Self> {
        match &mut verdict.answer {
            Err(e) => Err(problem_error(e)),
            Ok(a) => {
                if !steps {
                    a.steps.clear();
                }
                Ok(PyAnswer {
                    verdict,
                    steps,
                    lang,
                })
            }
        }
    }

    /// The figure of the answer (see the Python method `figure`).
    pub fn figure_of(&self, steps: bool) -> PyResult<Figure> {
        Figure::of_answer(self.answer()?, steps)
    }

    fn answer(&self) -> PyResult<&Answer> {
        self.verdict.answer.as_ref().map_err(problem_error)
    }

    fn lang_or(&self, given: Option<&str>) -> PyResult<Lang> {
        given.map_or(Ok(self.lang), lang)
    }

    fn named<'py>(
        &self,
        py: Python<'py>,
        items: &[(Quantity, Exact)],
        mode: Numbers,
        prefix: &str,
    ) -> PyResult<Bound<'py, PyDict>> {
        let dict = PyDict::new(py);
        for (k, v) in items {
            let k = k.name();
            let path = format!("{prefix}{k}");
            dict.set_item(k, to_python_at(py, &v.to_json(), mode, &path)?)?;
        }
        Ok(dict)
    }

    /// The results (or the steps) with the numbers as `mode` says.
    fn part<'py>(
        &self,
        py: Python<'py>,
        part: &str,
        mode: Numbers,
    ) -> PyResult<Bound<'py, PyDict>> {
        let a = self.answer()?;
        match part {
            "result" => self.named(py, &a.result, mode, ""),
            "steps" => self.named(py, &a.steps, mode, "steps."),
            other => Err(PyValueError::new_err(format!(
                "part is 'result' or 'steps', found '{other}'"
            ))),
        }
    }

    /// Display math of the results (and steps): `name = value` lines, aligned.
    fn math(&self, lang: Lang) -> PyResult<String> {
        let a = self.answer()?;
        let lines: Vec<String> = a
            .steps
            .iter()
            .chain(&a.result)
            // words (a sentence, a keyword) are not mathematics
            .filter(|(_, v)| !matches!(v, Exact::Text(_) | Exact::Sentence(_)))
            .map(|(k, v)| format!("{} &= {}", latex_name(&k.name()), latex(v, lang)))
            .collect();
        Ok(format!(
            "$$\\begin{{aligned}}\n{}\n\\end{{aligned}}$$",
            lines.join(" \\\\\n")
        ))
    }
}

#[pymethods]
impl PyAnswer {
    /// The operation (`coons`, `elevate`...).
    #[getter]
    fn op(&self) -> PyResult<String> {
        Ok(self.answer()?.op.clone())
    }

    /// The number field the problem ran in: `Q`, `Q(√2)`, or `Q(letters)` for a problem in
    /// letters.
    #[getter]
    fn field(&self) -> PyResult<String> {
        Ok(match self.answer()?.field {
            NumberField::Rational => "Q".into(),
            NumberField::Quadratic(d) => format!("Q(√{d})"),
            // quotients of polynomials in the problem's letters
            NumberField::Letters(0) => "Q(letters)".into(),
            NumberField::Letters(d) => format!("Q(√{d})(letters)"),
        })
    }

    /// The results by name, in the JSON form (numbers as strings of the grammar).
    #[getter]
    fn result<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.part(py, "result", Numbers::Json)
    }

    /// The intermediate values by name, in order (empty unless solved with `steps=True`).
    #[getter]
    fn steps<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.part(py, "steps", Numbers::Json)
    }

    /// Remarks in words (a curve elevated to match the other...).
    #[getter]
    fn remarks(&self) -> PyResult<Vec<String>> {
        Ok(self
            .answer()?
            .remarks
            .iter()
            .map(ToString::to_string)
            .collect())
    }

    /// Whether the problem says what to expect (`expected` or `errata`).
    #[getter]
    fn checked(&self) -> bool {
        self.verdict.checked
    }

    /// The answer equals the problem's `expected` (true when nothing was expected).
    #[getter]
    fn passed(&self) -> bool {
        self.verdict.passed()
    }

    /// Where the answer differs from `expected`, one line each.
    #[getter]
    fn mismatches(&self) -> Vec<String> {
        self.verdict
            .mismatches
            .iter()
            .map(ToString::to_string)
            .collect()
    }

    /// The diagnosis of a student's answer (`check`): every entry of each result right or
    /// wrong, the score, and the common mistakes that explain it, as the `assessment` of the
    /// JSON (docs/format.md, "Checking a student's answer"); `None` when nothing was assessed.
    #[getter]
    fn assessment<'py>(&self, py: Python<'py>) -> PyResult<Option<Bound<'py, PyAny>>> {
        self.verdict
            .assessment
            .as_ref()
            .map(|a| to_python(py, &a.to_json(), Numbers::Json))
            .transpose()
    }

    /// The notes' misprints this fixture records: dicts of `where`, `printed`, `exact`, `why`.
    #[getter]
    fn errata<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        let items = self
            .verdict
            .errata
            .iter()
            .map(|e| {
                let d = PyDict::new(py);
                d.set_item("where", &e.place)?;
                d.set_item("printed", &e.printed)?;
                d.set_item("exact", &e.exact)?;
                d.set_item("why", &e.why)?;
                Ok(d)
            })
            .collect::<PyResult<Vec<_>>>()?;
        PyList::new(py, items)
    }

    /// The problem answered, as read.
    #[getter]
    fn problem(&self) -> PyResult<PyProblem> {
        Ok(PyProblem {
            problem: Arc::clone(&self.answer()?.problem),
            settings: Settings {
                steps: self.steps,
                ..Settings::default()
            },
        })
    }

    /// The language of the key shown in Jupyter (`en` or `es`).
    #[getter(lang)]
    fn lang_name(&self) -> &'static str {
        match self.lang {
            Lang::En => "en",
            Lang::Es => "es",
        }
    }

    /// One result in the JSON form: `answer["surface"]`.
    fn __getitem__<'py>(&self, py: Python<'py>, name: &str) -> PyResult<Bound<'py, PyAny>> {
        let a = self.answer()?;
        match a.get(name) {
            Some(v) => to_python(py, &v.to_json(), Numbers::Json),
            None => Err(PyKeyError::new_err(format!(
                "{name}: the results are {}",
                a.result
                    .iter()
                    .map(|(k, _)| k.name())
                    .collect::<Vec<_>>()
                    .join(", ")
            ))),
        }
    }

    /// The names of the results.
    fn keys(&self) -> PyResult<Vec<String>> {
        Ok(self
            .answer()?
            .result
            .iter()
            .map(|(k, _)| k.name().into_owned())
            .collect())
    }

    /// The answer as `cagd solve --format json` prints it, as a dict: `{"ok": true, "op":
    /// ..., "result": {...}}` (with `passed` and `mismatches` when the problem says what to
    /// expect). `steps` defaults to whether the problem was solved with its steps.
    #[pyo3(signature = (steps=None))]
    fn to_json<'py>(&self, py: Python<'py>, steps: Option<bool>) -> PyResult<Bound<'py, PyAny>> {
        let json = self.verdict.to_json(steps.unwrap_or(self.steps));
        to_python(py, &json, Numbers::Json)
    }

    /// [`to_json`] as a string: the bytes `cagd solve --format json` prints for one problem
    /// (without the final newline).
    #[pyo3(signature = (steps=None))]
    fn json(&self, steps: Option<bool>) -> String {
        let json: Value = self.verdict.to_json(steps.unwrap_or(self.steps));
        serde_json::to_string_pretty(&json).unwrap_or_default()
    }

    /// The results (or with `part="steps"` the steps) with every number a
    /// `fractions.Fraction`; a number with a square root is a `CagdError` (use `sympy()`).
    #[pyo3(signature = (part="result"))]
    fn fractions<'py>(&self, py: Python<'py>, part: &str) -> PyResult<Bound<'py, PyDict>> {
        self.part(py, part, Numbers::Fraction)
    }

    /// The results (or the steps) with every number a SymPy number (√2 as `sqrt(2)`), and
    /// closed forms as SymPy expressions in u and v. Needs SymPy.
    #[pyo3(signature = (part="result"))]
    fn sympy<'py>(&self, py: Python<'py>, part: &str) -> PyResult<Bound<'py, PyDict>> {
        self.part(py, part, Numbers::Sympy)
    }

    /// The answer key as plain text, in `lang` (`en` or `es`; by default the answer's).
    #[pyo3(signature = (lang=None))]
    fn text(&self, lang: Option<&str>) -> PyResult<String> {
        Ok(example_text(&self.verdict, self.lang_or(lang)?))
    }

    /// The answer key as a LaTeX section (as `cagd solve --format latex` writes each problem).
    #[pyo3(signature = (lang=None))]
    fn latex(&self, lang: Option<&str>) -> PyResult<String> {
        Ok(example_latex(&self.verdict, self.lang_or(lang)?))
    }

    /// The answer key as Markdown with `$...$` math (as `cagd solve --format markdown`).
    #[pyo3(signature = (lang=None))]
    fn markdown(&self, lang: Option<&str>) -> PyResult<String> {
        Ok(example_markdown(&self.verdict, self.lang_or(lang)?))
    }

    /// The same answer shown in another language, or without its steps.
    #[pyo3(signature = (lang=None, steps=None))]
    fn show(&self, lang: Option<&str>, steps: Option<bool>) -> PyResult<PyAnswer> {
        let steps = steps.unwrap_or(self.steps) && self.steps;
        PyAnswer::from_verdict(self.verdict.clone(), steps, self.lang_or(lang)?)
    }

    /// The figure of the answer: its surfaces, the problem's curves, and with `steps` the
    /// surfaces among the steps (c_c, c_d, c_cd of a Coons patch).
    #[pyo3(signature = (steps=false))]
    fn figure(&self, steps: bool) -> PyResult<Figure> {
        self.figure_of(steps)
    }

    fn _repr_markdown_(&self) -> String {
        example_markdown(&self.verdict, self.lang)
    }

    fn _repr_latex_(&self) -> PyResult<String> {
        self.math(self.lang)
    }

    fn __str__(&self) -> String {
        example_text(&self.verdict, self.lang)
    }

    fn __repr__(&self) -> PyResult<String> {
        let a = self.answer()?;
        let names: Vec<_> = a.result.iter().map(|(k, _)| k.name()).collect();
        Ok(format!(
            "<cagd_exact.Answer {} in {}: {}>",
            a.op,
            self.field()?,
            names.join(", ")
        ))
    }
}

/// A problem read once: every number read by the grammar, under the limits given to `read`.
/// `problem.solve()` answers it (again) without reading it again.
#[pyclass(module = "cagd_exact", name = "Problem", frozen)]
pub struct PyProblem {
    problem: Arc<Problem>,
    settings: Settings,
}

impl PyProblem {
    /// Reads a problem under `settings`' limits.
    pub fn read(value: &Value, settings: Settings) -> PyResult<Self> {
        let problem = Problem::read(value, &settings.limits).map_err(|e| problem_error(&e))?;
        Ok(PyProblem {
            problem: Arc::new(problem),
            settings,
        })
    }

    /// Reads a problem from its JSON text under `settings`' limits, straight into the typed
    /// problem ([`Problem::read_text`]: the same problem, and the same errors, as from its
    /// JSON value).
    pub fn read_text(text: &str, settings: Settings) -> PyResult<Self> {
        let problem =
            Problem::read_text(text, &settings.limits, |e| crate::convert::invalid_json(&e))
                .map_err(|e| problem_error(&e))?;
        Ok(PyProblem {
            problem: Arc::new(problem),
            settings,
        })
    }

    /// Solves (and checks against `expected`) with or without the steps.
    pub fn verdict(&self, py: Python<'_>, steps: bool) -> Verdict {
        let settings = Settings {
            steps,
            ..self.settings.clone()
        };
        py.detach(|| check_problem(&self.problem, &settings))
    }

    /// The verdict of `cagd check` on the problem's `expected` (a student's answer): the
    /// problem solved with its steps into its key, the answer compared and diagnosed (the
    /// verdict's assessment); a fixture's formula and errata checked as [`check_problem`]
    /// checks them.
    pub fn diagnosed(&self, py: Python<'_>) -> Verdict {
        let settings = Settings {
            steps: true,
            ..self.settings.clone()
        };
        py.detach(|| {
            let key = cagd_diagnose::Key::new(&self.problem, &settings);
            cagd_diagnose::diagnose_with(&key, &self.problem, &settings)
        })
    }
}

#[pymethods]
impl PyProblem {
    /// Solves the problem: an `Answer`, or a `CagdError`. With `steps=True` the intermediate
    /// values the notes show are recorded (and shown); `lang` is the language of its key.
    #[pyo3(signature = (*, steps=false, lang="en"))]
    fn solve(&self, py: Python<'_>, steps: bool, lang: &str) -> PyResult<PyAnswer> {
        let lang = crate::error::lang(lang)?;
        PyAnswer::from_verdict(self.verdict(py, steps), steps, lang)
    }

    /// The operation.
    #[getter]
    fn op(&self) -> &'static str {
        self.problem.op.name()
    }

    /// The fixture's `name`, if any.
    #[getter]
    fn name(&self) -> Option<String> {
        self.problem.meta.name.clone()
    }

    /// The fixture's `title`, if any.
    #[getter]
    fn title(&self) -> Option<String> {
        self.problem.meta.title.clone()
    }

    fn __repr__(&self) -> String {
        match &self.problem.meta.name {
            Some(n) => format!("<cagd_exact.Problem {} ({n})>", self.problem.op.name()),
            None => format!("<cagd_exact.Problem {}>", self.problem.op.name()),
        }
    }
}
