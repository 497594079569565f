//! Python objects to the JSON values `cagd solve` reads, and answers back to Python, exactly.
//!
//! In: a dict, a list or a JSON string; numbers as `int`, `fractions.Fraction`, SymPy numbers
//! (and expressions, for `expr`), python-flint or gmpy2 rationals, `decimal.Decimal`, numpy
//! integers and integer arrays, or strings of the grammar.
//! Each exact number other than an `int` becomes the string of the grammar it prints as
//! (`5/6`, `sqrt(2)/2`), so every number is read once, by the one grammar, under the limits,
//! as from a file. A `float` is passed on as a JSON number with a fraction part, which the
//! reader refuses with the command line's message. What cannot be a number is an error naming
//! its field path.
//!
//! Out: the JSON form of an answer (numbers as strings, the default), or with every number
//! as a `Fraction` or a SymPy number ([`Numbers`]).

use crate::said::PyMessage;
use cagd_problem::message::contract::Contract;
use cagd_problem::problem::serde_error;
use cagd_problem::ProblemError;
use cagd_scalar::{parse_number, Quadratic};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use serde_json::{Number, Value};

/// The deepest nesting of lists and dicts read, as the JSON reader of `cagd solve`.
const MAX_NESTING: usize = cagd_problem::field::MAX_NESTING;

/// A problem given from Python (a dict, a list or a JSON string) as a JSON value.
pub fn problem_value(obj: &Bound<'_, PyAny>) -> Result<Value, ProblemError> {
    let text = problem_text(obj)?;
    serde_json::from_str(&text).map_err(|e| {
        if obj.cast::<PyString>().is_ok() {
            invalid_json(&e)
        } else {
            // the text written from lists and dicts is JSON: only its depth can be refused
            ProblemError::at("", Contract::NestedTooDeep { max: MAX_NESTING })
        }
    })
}

/// The error of a JSON string that is not JSON.
pub fn invalid_json(e: &serde_json::Error) -> ProblemError {
    ProblemError::at(
        "",
        Contract::JsonStringNotJson {
            line: e.line(),
            column: e.column(),
            why: Box::new(serde_error(e)),
        },
    )
}

/// A problem given from Python (a dict, a list or a JSON string) as JSON text: a string as
/// it is, lists and dicts written out (the problem's reader reads the text straight into the
/// typed problem, [`cagd_problem::Problem::read_text`]).
pub fn problem_text(obj: &Bound<'_, PyAny>) -> Result<String, ProblemError> {
    if let Ok(s) = obj.cast::<PyString>() {
        return s.to_cow().map(std::borrow::Cow::into_owned).map_err(|e| {
            let why = e.to_string();
            ProblemError::at("", Contract::UnreadableString { why })
        });
    }
    let mut out = String::with_capacity(1024);
    write_json(obj, &mut Vec::new(), &mut out)?;
    Ok(out)
}

/// One step of a field path: a key of a dict or an index of a list.
enum Step {
    Key(String),
    Index(usize),
}

/// The field path of `steps` as the reader writes it: `c1.bezier[2]`. Written only for an
/// error: reading a problem builds no path.
fn path_text(steps: &[Step]) -> String {
    let mut out = String::new();
    for step in steps {
        match step {
            Step::Key(k) if out.is_empty() => out.push_str(k),
            Step::Key(k) => {
                out.push('.');
                out.push_str(k);
            }
            Step::Index(i) => out.push_str(&format!("[{i}]")),
        }
    }
    out
}

/// A string as JSON, quoted and escaped.
fn write_string(s: &str, out: &mut String) {
    // writing to a String cannot fail
    out.push_str(&serde_json::to_string(s).unwrap_or_default());
}

/// The items of a list or tuple as a JSON list.
fn write_items<'py>(
    items: impl Iterator<Item = Bound<'py, PyAny>>,
    path: &mut Vec<Step>,
    out: &mut String,
) -> Result<(), ProblemError> {
    out.push('[');
    for (i, item) in items.enumerate() {
        if i > 0 {
            out.push(',');
        }
        path.push(Step::Index(i));
        write_json(&item, path, out)?;
        path.pop();
    }
    out.push(']');
    Ok(())
}

/// One Python value as JSON text, appended to `out`, `path` being where it sits.
fn write_json(
    obj: &Bound<'_, PyAny>,
    path: &mut Vec<Step>,
    out: &mut String,
) -> Result<(), ProblemError> {
    let fail = |path: &[Step], message: Contract| ProblemError::at(path_text(path), message);
    let host = |path: &[Step], e: PyErr| {
        fail(
            path,
            Contract::Host {
                what: e.to_string(),
            },
        )
    };
    if path.len() > MAX_NESTING {
        return Err(fail(path, Contract::NestedTooDeep { max: MAX_NESTING }));
    }
    if let Ok(s) = obj.cast::<PyString>() {
        let s = s.to_cow().map_err(|e| host(path, e))?;
        write_string(&s, out);
        return Ok(());
    }
    if let Ok(list) = obj.cast::<PyList>() {
        return write_items(list.iter(), path, out);
    }
    if obj.is_none() {
        out.push_str("null");
        return Ok(());
    }
    if let Ok(b) = obj.cast::<PyBool>() {
        out.push_str(if b.is_true() { "true" } else { "false" });
        return Ok(());
    }
    if let Ok(i) = obj.cast::<PyInt>() {
        match i.extract::<i64>() {
            Ok(n) => out.push_str(&n.to_string()),
            // past 64 bits: the decimal digits, read by the grammar under the digit limit
            Err(_) => write_string(&text_of(obj).map_err(|e| host(path, e))?, out),
        }
        return Ok(());
    }
    if let Ok(f) = obj.cast::<PyFloat>() {
        // the reader refuses a number with a fraction part, with the command line's message
        let n = Number::from_f64(f.value()).ok_or_else(|| {
            let value = f.value().to_string();
            fail(path, Contract::NotExact { value })
        })?;
        out.push_str(&n.to_string());
        return Ok(());
    }
    if let Ok(d) = obj.cast::<PyDict>() {
        out.push('{');
        for (i, (k, v)) in d.iter().enumerate() {
            let Ok(key) = k.cast::<PyString>() else {
                let found = type_name(&k);
                return Err(fail(path, Contract::KeyNotAString { found }));
            };
            let key = key.to_cow().map_err(|e| host(path, e))?.into_owned();
            if i > 0 {
                out.push(',');
            }
            write_string(&key, out);
            out.push(':');
            path.push(Step::Key(key));
            write_json(&v, path, out)?;
            path.pop();
        }
        out.push('}');
        return Ok(());
    }
    if let Ok(tuple) = obj.cast::<PyTuple>() {
        return write_items(tuple.iter(), path, out);
    }
    exact_number(obj, path, out)
}

/// An exact number of another library, as the string of the grammar it prints as.
fn exact_number(
    obj: &Bound<'_, PyAny>,
    path: &mut Vec<Step>,
    out: &mut String,
) -> Result<(), ProblemError> {
    let fail = |message: Contract| ProblemError::at(path_text(path), message);
    let host = |e: PyErr| {
        fail(Contract::Host {
            what: e.to_string(),
        })
    };
    let module = obj
        .get_type()
        .module()
        .map(|m| m.to_string())
        .unwrap_or_default();
    if module.starts_with("numpy") && obj.hasattr("tolist").unwrap_or(false) {
        // an array (or a numpy scalar) as lists of Python numbers: integers read, floats refused
        let list = obj.call_method0("tolist").map_err(host)?;
        if list.cast::<PyList>().is_ok()
            || list.cast::<PyInt>().is_ok()
            || list.cast::<PyFloat>().is_ok()
        {
            return write_json(&list, path, out);
        }
    }
    let exact_library = module == "fractions"
        || module == "decimal"
        || module == "flint"
        || module.starts_with("flint.")
        || module.starts_with("gmpy2")
        || module.starts_with("sympy");
    if exact_library {
        if module.starts_with("sympy") && holds_sympy_float(obj).map_err(host)? {
            return Err(fail(Contract::HoldsFloat {
                shown: repr_of(obj),
            }));
        }
        // SymPy prints powers as **; the grammar writes ^
        let text = text_of(obj).map_err(host)?;
        write_string(&text.replace("**", "^"), out);
        return Ok(());
    }
    // numpy integers and other integer types
    if let Ok(i) = obj.call_method0("__index__") {
        return write_json(&i, path, out);
    }
    Err(fail(Contract::NotANumber {
        kind: type_name(obj),
        shown: repr_of(obj),
    }))
}

/// Whether a SymPy value has a `Float` in it (not exact: refused, as a float).
fn holds_sympy_float(obj: &Bound<'_, PyAny>) -> PyResult<bool> {
    let float = obj.py().import("sympy")?.getattr("Float")?;
    Ok(obj.hasattr("atoms")? && obj.call_method1("atoms", (float,))?.len()? > 0)
}

fn text_of(obj: &Bound<'_, PyAny>) -> PyResult<String> {
    Ok(obj.str()?.to_cow()?.into_owned())
}

fn repr_of(obj: &Bound<'_, PyAny>) -> String {
    obj.repr()
        .ok()
        .and_then(|r| r.to_cow().ok().map(std::borrow::Cow::into_owned))
        .unwrap_or_default()
}

/// `module.Name` of an object's type.
pub fn type_name(obj: &Bound<'_, PyAny>) -> String {
    let ty = obj.get_type();
    let name = ty.name().map(|n| n.to_string()).unwrap_or_default();
    match ty.module().map(|m| m.to_string()) {
        Ok(m) if m != "builtins" => format!("{m}.{name}"),
        _ => name,
    }
}

/// How the numbers of an answer come out.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Numbers {
    /// Strings of the grammar, as in the JSON answer (`"5/6"`, `"sqrt2/2"`).
    Json,
    /// `fractions.Fraction` (an irrational number is an error).
    Fraction,
    /// SymPy numbers (`sqrt(2)/2`); closed forms as SymPy expressions.
    Sympy,
}

/// What converting numbers needs from Python, looked up once per conversion.
struct Converter<'py> {
    mode: Numbers,
    fraction: Option<Bound<'py, PyAny>>,
    sympy: Option<Bound<'py, PyAny>>,
    expr: Option<Bound<'py, PyAny>>,
}

impl<'py> Converter<'py> {
    fn new(py: Python<'py>, mode: Numbers) -> PyResult<Self> {
        let (mut fraction, mut sympy, mut expr) = (None, None, None);
        match mode {
            Numbers::Json => {}
            Numbers::Fraction => fraction = Some(py.import("fractions")?.getattr("Fraction")?),
            Numbers::Sympy => {
                let module = py.import("sympy").map_err(|_| {
                    pyo3::exceptions::PyImportError::new_err(
                        "SymPy is not installed: pip install sympy",
                    )
                })?;
                sympy = Some(module.into_any());
                expr = Some(py.import("cagd_exact._convert")?.getattr("sympy_expr")?);
            }
        }
        Ok(Converter {
            mode,
            fraction,
            sympy,
            expr,
        })
    }

    fn value(&self, py: Python<'py>, v: &Value, path: &mut String) -> PyResult<Bound<'py, PyAny>> {
        Ok(match v {
            Value::Null => py.None().into_bound(py),
            Value::Bool(b) => PyBool::new(py, *b).to_owned().into_any(),
            Value::Number(n) => match (n.as_i64(), n.as_u64()) {
                (Some(i), _) => i.into_pyobject(py)?.into_any(),
                (_, Some(u)) => u.into_pyobject(py)?.into_any(),
                _ => n.to_string().into_pyobject(py)?.into_any(),
            },
            Value::String(s) => self.string(py, s, path)?,
            Value::Array(items) => {
                let mut out = Vec::with_capacity(items.len());
                for (i, item) in items.iter().enumerate() {
                    let len = path.len();
                    path.push_str(&format!("[{i}]"));
                    out.push(self.value(py, item, path)?);
                    path.truncate(len);
                }
                PyList::new(py, out)?.into_any()
            }
            Value::Object(map) => {
                let dict = PyDict::new(py);
                for (k, item) in map {
                    let len = path.len();
                    if !path.is_empty() {
                        path.push('.');
                    }
                    path.push_str(k);
                    dict.set_item(k, self.value(py, item, path)?)?;
                    path.truncate(len);
                }
                dict.into_any()
            }
        })
    }

    /// A string of an answer: a number of the grammar, or words, or a closed form.
    fn string(&self, py: Python<'py>, s: &str, path: &str) -> PyResult<Bound<'py, PyAny>> {
        if self.mode == Numbers::Json {
            return Ok(PyString::new(py, s).into_any());
        }
        match parse_number(s) {
            Ok(x) => self.number(py, &x, s, path),
            Err(_) => match &self.expr {
                Some(expr) => expr.call1((s,)),
                None => Ok(PyString::new(py, s).into_any()),
            },
        }
    }

    fn number(
        &self,
        py: Python<'py>,
        x: &Quadratic,
        text: &str,
        path: &str,
    ) -> PyResult<Bound<'py, PyAny>> {
        let rational = |r: &cagd_scalar::BigRational, class: &Bound<'py, PyAny>| {
            class.call1((r.numer().clone(), r.denom().clone()))
        };
        match (&self.fraction, &self.sympy) {
            (Some(fraction), _) => match x.to_rational() {
                Some(r) => rational(&r, fraction),
                None => Err(crate::error::cagd_error_at(
                    path,
                    PyMessage::NotRational {
                        text: text.to_string(),
                        radicand: x.radicand(),
                    },
                )),
            },
            (None, Some(sympy)) => {
                let class = sympy.getattr("Rational")?;
                let a = rational(&x.rational_part().to_big(), &class)?;
                match x.to_rational() {
                    Some(_) => Ok(a),
                    None => {
                        let b = rational(&x.root_part().to_big(), &class)?;
                        let root = sympy.getattr("sqrt")?.call1((x.radicand(),))?;
                        a.add(b.mul(root)?)
                    }
                }
            }
            (None, None) => Ok(PyString::new(py, text).into_any()),
        }
    }
}

/// A JSON value as Python objects, its numbers as `mode` says.
pub fn to_python<'py>(py: Python<'py>, v: &Value, mode: Numbers) -> PyResult<Bound<'py, PyAny>> {
    Converter::new(py, mode)?.value(py, v, &mut String::new())
}

/// A JSON value as Python objects, `path` naming where it sits (for errors).
pub fn to_python_at<'py>(
    py: Python<'py>,
    v: &Value,
    mode: Numbers,
    path: &str,
) -> PyResult<Bound<'py, PyAny>> {
    Converter::new(py, mode)?.value(py, v, &mut path.to_string())
}
