//! A problem checked against what it expects: the results and named steps compared exactly,
//! and a formula fixture's errata.

use crate::errata::{self, DerivedErratum};
use crate::message::check::Check;
use crate::message::found::Found;
use crate::{
    solve_problem, Answer, Erratum, ErratumKind, Limits, Message, Problem, Settings, Verdict,
};
use serde_json::Value;
use std::sync::Arc;

/// The differences between an answer and what its problem expects: each key of `expected`
/// must name a result (or `steps`, steps by name) and equal it exactly. An `expected` that is
/// not an object of results, or is empty, checks nothing and is itself a mismatch, naming the
/// results the operation gives.
///
/// The `result` of an answer (`cagd solve --format json`, with or without `--steps`) reads
/// back whole as `expected`: its `steps`, a list of `{"name", "value"}`, is compared whole (the
/// same names in the same order, each value exactly); its `remarks` and `derivation`, the
/// words and layout of the key ([`WORDS_NOT_COMPARED`]), must have their shape (a list of
/// strings, a list of objects) and are not compared. A key that is not a result, and a
/// malformed `steps`, `remarks` or `derivation`, is a mismatch naming it.
fn compare(a: &Answer, expected: &Value) -> Vec<Check> {
    let names = || {
        let names: Vec<String> = a
            .result
            .iter()
            .map(|(k, _)| format!("`{}`", k.name()))
            .collect();
        names.join(", ")
    };
    let op = || a.op.clone();
    let Some(obj) = expected.as_object() else {
        return vec![Check::NotAnObject {
            op: op(),
            names: names(),
            found: Found::of(expected),
        }];
    };
    if obj.is_empty() {
        return vec![Check::EmptyExpected {
            op: op(),
            names: names(),
        }];
    }
    if obj.keys().all(|k| WORDS_NOT_COMPARED.contains(&k.as_str())) {
        return vec![Check::OnlyWords {
            op: op(),
            names: names(),
        }];
    }
    let mut mismatches = Vec::new();
    for (key, e) in obj {
        match key.as_str() {
            "steps" => compare_steps(a, e, &mut mismatches),
            "remarks" => {
                let words = e.as_array().is_some_and(|l| l.iter().all(Value::is_string));
                if !words {
                    mismatches.push(Check::RemarksShape {
                        found: Found::of(e),
                    });
                }
            }
            "derivation" => {
                let steps = e.as_array().is_some_and(|l| l.iter().all(Value::is_object));
                if !steps {
                    mismatches.push(Check::DerivationShape {
                        found: Found::of(e),
                    });
                }
            }
            _ => match a.get(key) {
                None => mismatches.push(Check::NotAResult {
                    key: key.clone(),
                    op: op(),
                    names: names(),
                }),
                Some(x) => {
                    if let Err(m) = x.check_in(e, &a.problem.parameters) {
                        mismatches.push(Check::Result {
                            key: key.clone(),
                            inner: Box::new(m),
                        });
                    }
                }
            },
        }
    }
    mismatches
}

/// The mismatches of an answer against an `expected` (a teacher's key or a student's
/// answer), as [`check_problem`] finds them: typed messages, the first difference of each
/// result.
pub fn compare_expected(a: &Answer, expected: &Value) -> Vec<Message> {
    compare(a, expected)
        .into_iter()
        .map(Message::from)
        .collect()
}

/// The keys of an answer's `result` that are words and layout, not values: read back in
/// `expected` (so that a result feeds back whole) and not compared.
pub const WORDS_NOT_COMPARED: [&str; 2] = ["remarks", "derivation"];

/// The mismatches of the `steps` of `expected`: an object of steps by name (each compared
/// with the step of that name), or the list of `{"name", "value"}` an answer writes (compared
/// whole: the same steps in the same order). Anything else, an empty object, or an item of the
/// list without a string `name` and a `value`, is a mismatch naming `steps`.
fn compare_steps(a: &Answer, e: &Value, mismatches: &mut Vec<Check>) {
    let params = &a.problem.parameters;
    let step = |name: &str, m: Check| Check::Step {
        name: name.to_string(),
        inner: Box::new(m),
    };
    match e {
        Value::Object(by_name) if by_name.is_empty() => mismatches.push(Check::EmptySteps),
        Value::Object(by_name) => {
            for (name, es) in by_name {
                match a.step(name) {
                    None => mismatches.push(not_a_step(a, name)),
                    Some(x) => {
                        if let Err(m) = x.check_in(es, params) {
                            mismatches.push(step(name, m));
                        }
                    }
                }
            }
        }
        Value::Array(list) => {
            let mut named = Vec::with_capacity(list.len());
            for (i, item) in list.iter().enumerate() {
                let name = item.get("name").and_then(Value::as_str);
                match (name, item.get("value")) {
                    (Some(name), Some(value)) if item.as_object().is_some_and(|o| o.len() == 2) => {
                        named.push((name, value));
                    }
                    _ => mismatches.push(Check::StepItem {
                        index: i,
                        found: Found::of(item),
                    }),
                }
            }
            if named.len() < list.len() {
                return;
            }
            if named.len() != a.steps.len() {
                mismatches.push(Check::StepCount {
                    expected: named.len(),
                    computed: a.steps.len(),
                });
            }
            for (i, ((name, es), (k, x))) in named.iter().zip(&a.steps).enumerate() {
                if *name != k.name() {
                    mismatches.push(Check::StepName {
                        index: i,
                        expected: (*name).to_string(),
                        computed: k.name().into_owned(),
                    });
                } else if let Err(m) = x.check_in(es, params) {
                    mismatches.push(step(name, m));
                }
            }
        }
        other => mismatches.push(Check::StepsShape {
            found: Found::of(other),
        }),
    }
}

/// The most step names a mismatch lists: past it, how many more.
pub(crate) const STEP_NAMES_LISTED: usize = 20;

/// The mismatch of a step named in `expected` that the answer does not record (a typo, or a
/// step of another operation): that the operation records no step of that name, and the
/// names of the steps it records here, which `expected` can check, in the order recorded
/// (the first [`STEP_NAMES_LISTED`], then how many more), so that the name can be corrected.
pub(crate) fn not_a_step(a: &Answer, name: &str) -> Check {
    let mut names: Vec<std::borrow::Cow<'static, str>> = Vec::new();
    for (k, _) in &a.steps {
        let k = k.name();
        if !names.contains(&k) {
            names.push(k);
        }
    }
    let (name, op) = (name.to_string(), a.op.clone());
    if names.is_empty() {
        return Check::NoNamedSteps { name, op };
    }
    let listed: Vec<String> = names
        .iter()
        .take(STEP_NAMES_LISTED)
        .map(|k| format!("`{k}`"))
        .collect();
    let listed = listed.join(", ");
    match names.len().saturating_sub(STEP_NAMES_LISTED) {
        0 => Check::NoSuchStep { name, op, listed },
        more => Check::NoSuchStepOfMany {
            name,
            op,
            listed,
            more,
        },
    }
}

/// Solves a fixture (or a teacher's problem with `expected`) and compares with `expected`:
/// each key of `expected` must equal the result of that name (`steps` compares steps by
/// name), exactly.
pub fn check(fixture: &Value) -> Verdict {
    check_with(fixture, &Limits::DEFAULT)
}

/// [`check`] under `limits`.
pub fn check_with(fixture: &Value, limits: &Limits) -> Verdict {
    check_with_settings(
        fixture,
        &Settings {
            limits: *limits,
            steps: true,
        },
    )
}

/// Reads, solves and checks one problem. A problem whose `expected` names steps is solved
/// with its steps whatever `settings` says: the comparison needs them.
pub fn check_with_settings(problem: &Value, settings: &Settings) -> Verdict {
    match Problem::read(problem, &settings.limits) {
        Ok(p) => check_problem(&Arc::new(p), settings),
        Err(e) => Verdict::failed(e),
    }
}

/// The errata the formula check found against the ones the fixture records: each found one
/// must be recorded (same place and values), and each recorded one of the formula found.
fn errata_agree(
    found: &[DerivedErratum],
    recorded: &[Erratum],
    names: &[cagd_param::Name],
) -> Vec<Check> {
    let mut out = Vec::new();
    let places: Vec<String> = found.iter().map(|f| f.place.to_string()).collect();
    for (f, place) in found.iter().zip(&places) {
        let ok = recorded.iter().any(|r| {
            &r.place == place
                && match r.kind {
                    ErratumKind::Value => {
                        errata::same_values(&r.printed, &f.printed, names)
                            && errata::same_values(&r.exact, &f.exact, names)
                    }
                    // the notes' factored formulas are recorded: the factor is checked
                    ErratumKind::Scale => errata::scaled(&f.printed, &f.exact, &r.factor, names),
                }
        });
        if !ok {
            out.push(Check::Unrecorded {
                place: f.place.clone(),
                printed: f.printed.clone(),
                exact: f.exact.clone(),
            });
        }
    }
    for r in recorded {
        let formula_place = places.contains(&r.place);
        let of_formula = problem_formula_place(&r.place);
        if !formula_place && of_formula {
            out.push(Check::NotAnErratum {
                place: r.place.clone(),
            });
        }
    }
    out
}

/// Whether an erratum's place is one the formula check writes (`(14) at (1, 0)`, `(25)
/// (corner_00)`).
fn problem_formula_place(place: &str) -> bool {
    place.contains(" at (")
        || (place.starts_with('(') && place.ends_with(')') && place.contains(") ("))
}

/// Solves and checks a problem already read (a front end that reads a problem once and
/// solves it again, as the Python module's `Problem.solve`, pays the reading once). A problem
/// whose `expected` names steps is solved with its steps whatever `settings` says.
pub fn check_problem(problem: &Arc<Problem>, settings: &Settings) -> Verdict {
    let expected = problem.meta.expected.as_ref();
    let wants_steps =
        expected.is_some_and(|e| e.get("steps").is_some()) || problem.meta.formula.is_some();
    let settings = if wants_steps && !settings.steps {
        std::borrow::Cow::Owned(Settings {
            steps: true,
            ..settings.clone()
        })
    } else {
        std::borrow::Cow::Borrowed(settings)
    };
    let answer = solve_problem(problem, &settings);
    let mut mismatches: Vec<Message> = match (&answer, expected) {
        (Ok(a), Some(expected)) => compare(a, expected)
            .into_iter()
            .map(Message::from)
            .collect(),
        _ => Vec::new(),
    };
    if let (Ok(a), Some(fs)) = (&answer, &problem.meta.formula) {
        let equation = problem.meta.equation.as_deref();
        let mut found = Vec::new();
        for f in fs.list() {
            match errata::derived_errata(a, f, equation) {
                Ok(errata) => found.extend(errata),
                Err(m) => mismatches.push(m.into()),
            }
        }
        mismatches.extend(
            errata_agree(&found, &problem.meta.errata, &problem.parameters)
                .into_iter()
                .map(Message::from),
        );
    }
    let checked =
        expected.is_some() || !problem.meta.errata.is_empty() || problem.meta.formula.is_some();
    Verdict {
        errata: problem.meta.errata.clone(),
        problem: Some(Arc::clone(problem)),
        answer,
        mismatches,
        checked,
        index: None,
        assessment: None,
    }
}
