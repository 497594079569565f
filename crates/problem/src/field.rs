//! Which scalar a problem runs in.
//!
//! Every number of a problem is read exactly first. If none has a square root, the problem runs
//! over `BigRational`; if they all live in one Q(√d), or the operation needs one (a surface of
//! revolution needs √2/2 for quarter circles), it runs over the quadratic field; two different
//! roots are an error naming both.

use crate::limits::{read_number, Limits, DEFAULT_LIMITS};
use crate::ProblemError;
use cagd_poly::parse_expr_with;
use cagd_scalar::Quadratic;
use serde_json::Value;

/// The deepest nesting of lists and objects a problem may have (as `serde_json` reads).
pub const MAX_NESTING: usize = 128;

/// The number field of a problem.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NumberField {
    /// The rationals Q.
    Rational,
    /// Q(√d).
    Quadratic(u64),
}

/// Keys that hold words or answers, not input numbers.
const NOT_INPUT: &[&str] = &[
    "name",
    "title",
    "source",
    "equation",
    "note",
    "op",
    "expected",
    "printed",
    "errata",
    "basis",
    "end",
    "border",
    "direction",
    "blend",
    "form",
];

/// The field of a problem: the radicands of its numbers and expressions, plus `needed` (a root
/// the operation itself requires, e.g. 2 for quarter circles).
pub fn choose(problem: &Value, needed: Option<u64>) -> Result<NumberField, ProblemError> {
    choose_with(problem, needed, &DEFAULT_LIMITS)
}

/// [`choose`], reading the numbers and expressions under `limits` (a number or expression
/// that breaks them is skipped here, and refused with its field when it is read). A problem
/// nested deeper than [`MAX_NESTING`] is an error.
pub fn choose_with(
    problem: &Value,
    needed: Option<u64>,
    limits: &Limits,
) -> Result<NumberField, ProblemError> {
    let mut found: Vec<(u64, String)> = Vec::new();
    if let Some(d) = needed {
        found.push((d, "the operation".into()));
    }
    scan(problem, "", 0, limits, &mut found)?;
    let mut field = NumberField::Rational;
    let mut first: Option<&(u64, String)> = None;
    for entry in &found {
        match first {
            None => {
                first = Some(entry);
                field = NumberField::Quadratic(entry.0);
            }
            Some((d, where_d)) if *d != entry.0 => {
                return Err(ProblemError::at(
                    entry.1.clone(),
                    format!(
                        "this number needs √{}, but {where_d} needs √{d}: a problem runs in one field a + b√d",
                        entry.0
                    ),
                ));
            }
            Some(_) => {}
        }
    }
    Ok(field)
}

fn radicand(x: &Quadratic) -> Option<u64> {
    (x.radicand() != 0).then(|| x.radicand())
}

fn scan(
    v: &Value,
    path: &str,
    depth: usize,
    limits: &Limits,
    found: &mut Vec<(u64, String)>,
) -> Result<(), ProblemError> {
    if depth > MAX_NESTING {
        return Err(ProblemError::at(
            path,
            format!("lists and objects nested deeper than {MAX_NESTING}"),
        ));
    }
    match v {
        Value::String(s) => {
            if let Ok(x) = read_number(s, limits) {
                if let Some(d) = radicand(&x) {
                    found.push((d, path.to_string()));
                }
            } else if let Ok(e) = parse_expr_with(s, &limits.grammar()) {
                if let Ok(m) = e.vector::<Quadratic>() {
                    for p in m.components() {
                        for (_, c) in p.terms() {
                            if let Some(d) = radicand(c) {
                                found.push((d, path.to_string()));
                            }
                        }
                    }
                }
            }
        }
        Value::Array(items) => {
            for (i, x) in items.iter().enumerate() {
                scan(x, &format!("{path}[{i}]"), depth + 1, limits, found)?;
            }
        }
        Value::Object(map) => {
            for (k, x) in map {
                if !NOT_INPUT.contains(&k.as_str()) {
                    let p = if path.is_empty() {
                        k.clone()
                    } else {
                        format!("{path}.{k}")
                    };
                    scan(x, &p, depth + 1, limits, found)?;
                }
            }
        }
        _ => {}
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn fields() {
        assert_eq!(
            choose(
                &json!({"op": "evaluate", "surface": {"bezier": [[[0, "1/2", 1]]]}}),
                None
            ),
            Ok(NumberField::Rational)
        );
        assert_eq!(
            choose(
                &json!({"curve": {"bezier": [[1, 0], [1, 1]], "weights": [1, "sqrt2/2"]}}),
                None
            ),
            Ok(NumberField::Quadratic(2))
        );
        assert_eq!(
            choose(&json!({"curve": {"expr": "(u, sqrt3/2*u)"}}), None),
            Ok(NumberField::Quadratic(3))
        );
        assert_eq!(
            choose(&json!({"arcs": 4}), Some(2)),
            Ok(NumberField::Quadratic(2))
        );
        let e = choose(&json!({"w": ["sqrt2", 1, "sqrt3"]}), None).unwrap_err();
        assert_eq!(
            e.to_string(),
            "field `w[2]`: this number needs √3, but w[0] needs √2: a problem runs in one field a + b√d"
        );
        // words and expected answers are not inputs
        assert_eq!(
            choose(&json!({"name": "sqrt5", "expected": {"w": "sqrt7"}}), None),
            Ok(NumberField::Rational)
        );
    }
}
