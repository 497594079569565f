//! The one exception class, `cagd_exact.CagdError`, and the settings read from keywords.

use crate::said::PyMessage;
use cagd_keys::Raise;
use cagd_problem::{Limit, Limits, ProblemError, Settings};
use pyo3::create_exception;
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

create_exception!(
    cagd_exact,
    CagdError,
    PyValueError,
    "A problem cagd-exact cannot answer, or input it cannot read.\n\n\
     `str(e)` is the command line's one-line message (`problem 3: field `c1.bezier[2]`: ...`);\n\
     `e.field` is the field path (empty when the whole problem is at fault), `e.index` the\n\
     problem's index in a batch (or None), `e.message` the message alone, `e.limit` the\n\
     keyword that raises the limit the problem is past (`max_degree`...) or None."
);

/// A `CagdError` of the module's own, with no field.
pub fn cagd_error(m: PyMessage) -> PyErr {
    cagd_error_at("", m)
}

/// A `CagdError` of the module's own at the field `field` (empty: none).
pub fn cagd_error_at(field: &str, m: PyMessage) -> PyErr {
    let message = m.to_string();
    let line = message.replace('\n', " ");
    let shown = if field.is_empty() {
        line
    } else {
        format!("field `{field}`: {line}")
    };
    exception(shown, &message, field, None, None)
}

/// The keyword of `solve`, `read`... that raises `limit` (the command line's flag without
/// `--`, with `_` for `-`).
fn keyword(limit: Limit) -> Option<&'static str> {
    Some(limit.name())
}

/// The sentence after an error past a limit: the keyword that raises it
/// (`(raise it with max_degree=N)`).
fn raise(limit: Limit) -> Option<Raise> {
    keyword(limit).map(|k| Raise::Keyword { keyword: k.into() })
}

/// The `CagdError` of a problem's error: the command line's message (where the command line
/// names the flag that raises a limit, the keyword that raises it), in English, and its parts.
pub fn problem_error(e: &ProblemError) -> PyErr {
    let limit = e.limit.and_then(keyword);
    let (mut message, mut shown) = (e.message.to_string(), e.to_string());
    if let Some(r) = e.limit.and_then(raise) {
        message = format!("{message} {r}");
        shown = format!("{shown} {r}");
    }
    exception(shown, &message, &e.field, e.index, limit)
}

/// A `CagdError` showing `shown`, its attributes `message`, `field`, `index` and `limit` set.
fn exception(
    shown: String,
    message: &str,
    field: &str,
    index: Option<usize>,
    limit: Option<&str>,
) -> PyErr {
    let err = CagdError::new_err(shown);
    Python::attach(|py| {
        let value = err.value(py);
        // setting attributes on a fresh exception object does not fail
        let _ = value.setattr("message", message);
        let _ = value.setattr("field", field);
        let _ = value.setattr("index", index);
        let _ = value.setattr("limit", limit);
    });
    err
}

/// The limits given as keywords (`max_degree=64`...); the others keep their defaults.
pub fn limits(kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Limits> {
    let mut limits = Limits::DEFAULT;
    let Some(kwargs) = kwargs else {
        return Ok(limits);
    };
    for (k, v) in kwargs.iter() {
        let key: String = k.extract()?;
        if key == "max_seconds" {
            // seconds one problem may take (0: no deadline), as the command line's flag
            let s: f64 = v.extract().map_err(|_| {
                PyTypeError::new_err(format!("max_seconds takes a number of seconds, found {v}"))
            })?;
            limits.max_seconds = match std::time::Duration::try_from_secs_f64(s) {
                Ok(d) if d.is_zero() => None,
                Ok(d) => Some(d),
                Err(_) => {
                    return Err(PyValueError::new_err(format!(
                        "max_seconds takes a number of seconds (0 for no deadline), found {v}"
                    )))
                }
            };
            continue;
        }
        let n: usize = v.extract().map_err(|_| {
            PyTypeError::new_err(format!("{key} takes a positive integer, found {v}"))
        })?;
        if n == 0 {
            return Err(PyValueError::new_err(format!(
                "{key} takes a positive integer, found 0"
            )));
        }
        match key.as_str() {
            "max_degree" => limits.max_degree = n,
            "max_points" => limits.max_points = n,
            "max_digits" => limits.max_digits = n,
            "max_batch" => limits.max_batch = n,
            "max_memory" => limits.max_memory = n,
            "max_depth" if n <= Limits::DEPTH_CEILING => limits.max_depth = n,
            "max_depth" => {
                return Err(PyValueError::new_err(format!(
                    "max_depth is at most {}",
                    Limits::DEPTH_CEILING
                )));
            }
            "max_exponent" => {
                limits.max_exponent = u32::try_from(n).map_err(|_| {
                    PyValueError::new_err(format!("max_exponent is at most {}", u32::MAX))
                })?
            }
            other => {
                return Err(PyTypeError::new_err(format!(
                    "unexpected keyword argument '{other}': the limits are max_degree, \
                     max_points, max_digits, max_batch, max_depth, max_exponent, max_seconds and \
                     max_memory"
                )));
            }
        }
    }
    Ok(limits)
}

/// The settings of a run: the limits given as keywords, with or without the steps.
pub fn settings(steps: bool, kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<Settings> {
    Ok(Settings {
        limits: limits(kwargs)?,
        steps,
    })
}

/// `en` or `es`.
pub fn lang(s: &str) -> PyResult<cagd_keys::Lang> {
    cagd_keys::Lang::parse(s)
        .ok_or_else(|| PyValueError::new_err(format!("lang is 'en' or 'es', found '{s}'")))
}
