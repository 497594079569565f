//! The errata a formula fixture finds by computing: the notes' printed formula instantiated at
//! every entry of the engine's answer on a generic mesh and compared exactly
//! ([`derived_errata`]), and the comparison of an erratum's values ([`same_values`]).

use crate::formula::{Formula, Part};
use crate::message::check::{Check, ErratumPlace};
use crate::message::inner::Inner;
use crate::value::{Exact, Number};
use crate::Answer;
use cagd_param::{parse_param, Name};
use cagd_scalar::{Limits, Print};
use cagd_words::{said, Lang, Phrase};
use std::collections::BTreeMap;

/// The entries of a result: (index, coordinates) for a polygon, a mesh, or one point; or its
/// weights.
fn entries(x: &Exact, part: Part) -> Option<Vec<(Vec<usize>, Vec<Number>)>> {
    use crate::input::{CurveIn, SurfaceIn};
    let coords = |p: &cagd_linalg::Point<Number>| p.coords().to_vec();
    if part == Part::Weights {
        return match x {
            Exact::Surface(SurfaceIn::Bezier {
                weights: Some(w), ..
            }) => Some(
                w.indexed()
                    .map(|((i, j), x)| (vec![i, j], vec![x.clone()]))
                    .collect(),
            ),
            Exact::Curve(CurveIn::Bezier {
                weights: Some(w), ..
            }) => Some(
                w.iter()
                    .enumerate()
                    .map(|(i, x)| (vec![i], vec![x.clone()]))
                    .collect(),
            ),
            _ => None,
        };
    }
    match x {
        Exact::Surface(SurfaceIn::Bezier { mesh, .. }) => Some(
            mesh.indexed()
                .map(|((i, j), p)| (vec![i, j], coords(p)))
                .collect(),
        ),
        Exact::Curve(CurveIn::Bezier { points, .. }) | Exact::Points(points) => Some(
            points
                .iter()
                .enumerate()
                .map(|(i, p)| (vec![i], coords(p)))
                .collect(),
        ),
        Exact::Point(p) => Some(vec![(Vec::new(), coords(p))]),
        _ => None,
    }
}

/// The value of an index expression such as `i-1` or `m-r` at the given letters.
fn index_value(expr: &str, letters: &BTreeMap<String, i64>) -> Option<i64> {
    let mut text = String::new();
    for c in expr.chars() {
        match letters.get(&c.to_string()) {
            Some(v) if c.is_alphabetic() => text.push_str(&format!("({v})")),
            _ => text.push(c),
        }
    }
    let q = cagd_scalar::parse_rational(&text).ok()?;
    if !q.is_integer() {
        return None;
    }
    i64::try_from(q.to_integer()).ok()
}

/// The printed formula at one entry: subscripts evaluated (a point outside the input is 0),
/// the index letters replaced by their values.
fn instantiate(
    printed: &str,
    letters: &BTreeMap<String, i64>,
    input: &[usize],
) -> Result<String, Check> {
    let chars: Vec<char> = printed.chars().collect();
    let mut out = String::new();
    let mut k = 0;
    while let Some(&c) = chars.get(k) {
        if c.is_alphabetic() && chars.get(k + 1) == Some(&'_') && chars.get(k + 2) == Some(&'{') {
            let close = chars
                .iter()
                .skip(k + 3)
                .position(|&d| d == '}')
                .ok_or_else(|| Check::UnclosedSubscript {
                    printed: format!("{printed:?}"),
                })?;
            let inner: String = chars.iter().skip(k + 3).take(close).collect();
            let mut indices = Vec::new();
            for part in inner.split(',') {
                indices.push(index_value(part.trim(), letters).ok_or_else(|| {
                    Check::IndexNotInteger {
                        index: format!("{part:?}"),
                        printed: format!("{printed:?}"),
                    }
                })?);
            }
            let inside = indices.len() == input.len()
                && indices
                    .iter()
                    .zip(input)
                    .all(|(&x, &n)| x >= 0 && usize::try_from(x).is_ok_and(|x| x < n));
            if inside {
                let subs: Vec<String> = indices.iter().map(i64::to_string).collect();
                out.push_str(&format!("{c}_{{{}}}", subs.join(",")));
            } else {
                out.push_str("(0)");
            }
            k += 3 + close + 1;
        } else if c.is_alphabetic() && letters.contains_key(&c.to_string()) {
            let prev_alpha = k > 0 && chars.get(k - 1).is_some_and(|p| p.is_alphabetic());
            let next_alpha = chars.get(k + 1).is_some_and(|p| p.is_alphabetic());
            if prev_alpha || next_alpha {
                // part of a word (sqrt): kept
                out.push(c);
            } else {
                out.push_str(&format!(
                    "({})",
                    letters.get(&c.to_string()).copied().unwrap_or(0)
                ));
            }
            k += 1;
        } else {
            out.push(c);
            k += 1;
        }
    }
    Ok(out)
}

/// An erratum found by computing: where ([`ErratumPlace`]), the formulas as printed, the
/// value they give there and the value the engine derives; worded (its why) in English and
/// Spanish.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct DerivedErratum {
    /// Where: the equation (or the formula) at an entry.
    pub place: ErratumPlace,
    /// The formulas as printed, joined by `; `.
    pub formulas: String,
    /// What the printed formulas give there.
    pub printed: String,
    /// What the engine derives.
    pub exact: String,
}

/// Why a derived erratum is one.
impl cagd_words::Message for DerivedErratum {
    fn phrase(&self, lang: Lang) -> Phrase {
        said(
            lang,
            "the formula as printed, ‹›, gives ‹› there; the engine derives ‹›",
            "la fórmula tal como se imprime, ‹›, da ‹› ahí; el cálculo da ‹›",
            [
                (&self.formulas).into(),
                (&self.printed).into(),
                (&self.exact).into(),
            ],
        )
    }
}

cagd_words::display_english!(DerivedErratum);

/// The errata found by comparing the engine's derivation with the printed formula of
/// `equation` (the formula when the problem names none), or why the comparison could not be
/// made.
pub fn derived_errata(
    answer: &Answer,
    formula: &Formula,
    equation: Option<&str>,
) -> Result<Vec<DerivedErratum>, Check> {
    let result = answer
        .get(&formula.result)
        .or_else(|| answer.step(&formula.result))
        .ok_or_else(|| Check::FormulaNotAResult {
            result: formula.result.clone(),
        })?;
    let entries = entries(result, formula.part).ok_or_else(|| Check::FormulaNotGeneric {
        result: formula.result.clone(),
    })?;
    let names: Vec<Name> = answer.problem.parameters.clone();
    let mut found = Vec::new();
    for (index, derived) in entries {
        let formulas = formula.printed.formulas(index.get(1).copied());
        if derived.len() != formulas.len() {
            return Err(Check::FormulaCount {
                formulas: formulas.len(),
                coordinates: derived.len(),
            });
        }
        let mut letters = formula.constants.clone();
        for (letter, &x) in ["i", "j"].iter().zip(&index) {
            letters.insert((*letter).to_string(), i64::try_from(x).unwrap_or(i64::MAX));
        }
        let mut printed = Vec::with_capacity(formulas.len());
        for f in &formulas {
            let text = instantiate(f, &letters, &formula.input)?;
            printed.push(parse_param(&text, &names, &Limits::default()).map_err(|e| {
                Check::FormulaUnread {
                    text: format!("{text:?}"),
                    inner: Inner::new(e),
                }
            })?);
        }
        if printed != derived {
            let at: Vec<String> = index.iter().map(usize::to_string).collect();
            let show = |xs: &[Number]| match xs {
                [x] => x.to_text(),
                _ => format!(
                    "({})",
                    xs.iter().map(Print::to_text).collect::<Vec<_>>().join(", ")
                ),
            };
            let place = match (equation, at.is_empty()) {
                (Some(e), true) => ErratumPlace::Of {
                    equation: e.to_string(),
                    result: formula.result.clone(),
                },
                (Some(e), false) => ErratumPlace::At {
                    equation: e.to_string(),
                    at: at.join(", "),
                },
                (None, true) => ErratumPlace::FormulaOf {
                    result: formula.result.clone(),
                },
                (None, false) => ErratumPlace::FormulaAt { at: at.join(", ") },
            };
            found.push(DerivedErratum {
                place,
                formulas: formula.printed.all().join("; "),
                printed: show(&printed),
                exact: show(&derived),
            });
        }
    }
    Ok(found)
}

/// Whether two printed values of an erratum, one value or a tuple `(x, y, z)`, are the same
/// exact values (so that a recorded erratum does not depend on how a printer writes a value:
/// `2 a + c` and `c + 2 a` are the same). Text that does not read as values is compared as
/// text.
pub(crate) fn same_values(a: &str, b: &str, names: &[Name]) -> bool {
    match (read_values(a, names), read_values(b, names)) {
        (Some(x), Some(y)) => x == y,
        _ => a.trim() == b.trim(),
    }
}

/// Whether `exact` is `factor` times `printed` (values or tuples, as [`same_values`] reads
/// them), with a nonzero factor: an erratum of scale, the direction the same.
pub(crate) fn scaled(printed: &str, exact: &str, factor: &str, names: &[Name]) -> bool {
    let (Some(p), Some(e)) = (read_values(printed, names), read_values(exact, names)) else {
        return false;
    };
    let Ok(k) = parse_param(factor.trim(), names, &Limits::default()) else {
        return false;
    };
    k != <Number as cagd_scalar::FieldOps>::from_i64(0)
        && p.len() == e.len()
        && p.iter().zip(&e).all(|(x, y)| x.clone() * k.clone() == *y)
}

/// The values of `x` or `(x, y, z)`, split at the commas outside parentheses.
fn read_values(text: &str, names: &[Name]) -> Option<Vec<Number>> {
    let text = text.trim();
    let inner = text
        .strip_prefix('(')
        .and_then(|t| t.strip_suffix(')'))
        .filter(|t| top_level_commas(t) > 0)
        .unwrap_or(text);
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0usize, 0usize);
    for (k, c) in inner.char_indices() {
        match c {
            '(' | '{' | '[' => depth += 1,
            ')' | '}' | ']' => depth = depth.saturating_sub(1),
            ',' if depth == 0 => {
                parts.push(inner.get(start..k)?);
                start = k + 1;
            }
            _ => {}
        }
    }
    parts.push(inner.get(start..)?);
    parts
        .iter()
        .map(|p| parse_param(p.trim(), names, &Limits::default()).ok())
        .collect()
}

/// The commas of `text` outside parentheses and braces.
fn top_level_commas(text: &str) -> usize {
    let mut depth = 0usize;
    let mut n = 0;
    for c in text.chars() {
        match c {
            '(' | '{' | '[' => depth += 1,
            ')' | '}' | ']' => depth = depth.saturating_sub(1),
            ',' if depth == 0 => n += 1,
            _ => {}
        }
    }
    n
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn errata_values_compare_as_values_not_text() {
        let names: Vec<Name> = ["a", "c"].iter().map(|n| Name::new(n)).collect();
        assert!(same_values("(2 a + c)/3", "(c + 2 a)/3", &names));
        assert!(same_values("(1/2, 2 a + c)", "(2/4, c + 2*a)", &names));
        assert!(!same_values("(1/2, 2 a + c)", "(1/2, 2 a - c)", &names));
        assert!(!same_values("(1, 2)", "(1, 2, 3)", &names));
        // c_{1,0}: the comma inside braces does not split
        let generic: Vec<Name> = ["c_{1,0}", "c_{0,1}"]
            .iter()
            .map(|n| Name::new(n))
            .collect();
        assert!(same_values(
            "(c_{1,0} - c_{0,1})",
            "-c_{0,1} + c_{1,0}",
            &generic
        ));
        // text that is not a value is compared as text
        assert!(same_values("not a value", " not a value ", &names));
        assert!(!same_values("not a value", "another", &names));
    }

    #[test]
    fn derived_erratum_in_both_languages() {
        let e = DerivedErratum {
            place: ErratumPlace::At {
                equation: "(14)".into(),
                at: "1, 0".into(),
            },
            formulas: "a_{i} + b".into(),
            printed: "2".into(),
            exact: "3".into(),
        };
        assert_eq!(cagd_words::check_both(&e), Ok(()));
        assert_eq!(cagd_words::check_both(&DerivedErratum::default()), Ok(()));
        assert_eq!(
            cagd_words::Message::english(&e),
            "the formula as printed, a_{i} + b, gives 2 there; the engine derives 3"
        );
        assert_eq!(cagd_words::Message::english(&e.place), "(14) at (1, 0)");
    }
}
