//! A problem solved at its `"values"` ([`crate::values`]): the field it runs in once the values
//! are in ([`field`]), the remark saying which values it was solved with, and which results a
//! special value changed, compared with the answer in letters ([`differences`]).

use crate::field::NumberField;
use crate::message::contract::{Contract, Decided, RootSource};
use crate::problem::Problem;
use crate::value::{Exact, Number, Quantity};
use crate::{Named, ProblemError};
use cagd_param::Name;
use cagd_scalar::Print;

/// The field the problem runs in with its values put in: the letters' root field Q or Q(√d)
/// when every parameter has a value without letters (a value's root joins the field's, two
/// different roots are an error naming the value), the letters otherwise.
pub(crate) fn field(problem: &Problem) -> Result<NumberField, ProblemError> {
    let NumberField::Letters(mut root) = problem.field else {
        return Ok(problem.field);
    };
    let valued = |n: &Name| problem.values.iter().any(|(k, _)| k == n);
    let numbers =
        problem.parameters.iter().all(valued) && problem.values.iter().all(|(_, x)| x.is_const());
    for (name, x) in &problem.values {
        let d = x.radicand();
        if d == 0 || d == root {
            continue;
        }
        if root != 0 {
            return Err(ProblemError::at(
                format!("values.{name}"),
                Contract::RootConflict {
                    root: d,
                    first: RootSource::Numbers,
                    first_root: root,
                },
            ));
        }
        root = d;
    }
    Ok(match (numbers, root) {
        (false, d) => NumberField::Letters(d),
        (true, 0) => NumberField::Rational,
        (true, d) => NumberField::Quadratic(d),
    })
}

/// The values as the key writes them: `k = 0, a = 1/2`.
pub(crate) fn given(values: &[(Name, Number)]) -> String {
    values
        .iter()
        .map(|(n, x)| format!("{n} = {}", x.to_text()))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The remark of an answer solved with the values put in.
pub(crate) fn solved_with(values: &[(Name, Number)]) -> Contract {
    Contract::SolvedWith {
        values: given(values),
    }
}

/// Whether a sentence is the order `infinite`.
fn infinite(m: &crate::Message) -> bool {
    use crate::message::curve::Curve;
    matches!(m, crate::Message::Curve(c) if **c == Curve::Infinite)
}

/// A verdict among the results: yes or no, an order (an integer, or `infinite`).
fn verdict(x: &Exact) -> Option<Decided> {
    match x {
        Exact::Bool(true) => Some(Decided::Yes),
        Exact::Bool(false) => Some(Decided::No),
        Exact::Int(k) => Some(Decided::Order(*k)),
        Exact::Text(t) if t == "infinite" => Some(Decided::Infinite),
        Exact::Sentence(m) if infinite(m) => Some(Decided::Infinite),
        _ => None,
    }
}

/// The verdicts where `general` and `special` differ, by path (`developable`,
/// `pieces[1].developable`), with their words in each: the values compared where both are
/// verdicts, lists and named values entry by entry.
fn verdicts(
    path: &str,
    general: &Exact,
    special: &Exact,
    out: &mut Vec<(String, Decided, Decided)>,
) {
    match (general, special) {
        (Exact::List(gs), Exact::List(ss)) if gs.len() == ss.len() => {
            for (i, (g, s)) in gs.iter().zip(ss).enumerate() {
                verdicts(&format!("{path}[{}]", i + 1), g, s, out);
            }
        }
        (Exact::Object(gs), Exact::Object(ss)) => {
            for (k, s) in ss {
                if let Some(g) = find(gs, k) {
                    verdicts(&format!("{path}.{}", k.name()), g, s, out);
                }
            }
        }
        _ => {
            if let (Some(g), Some(s)) = (verdict(general), verdict(special)) {
                if g != s {
                    out.push((path.to_string(), g, s));
                }
            }
        }
    }
}

/// The value of kind `k` among the fields `named` of a value.
fn find<'a>(named: &'a [(Quantity, Exact)], k: &Quantity) -> Option<&'a Exact> {
    named.iter().find(|(n, _)| n == k).map(|(_, x)| x)
}

/// The remarks on the verdicts (yes or no, an order) where the answer in letters (`general`,
/// decided for general values of the letters) differs from the answer solved at the problem's
/// values (`special`), one for each, with both values; none when they agree. The other
/// results follow from the verdicts (or, in letters, were not decided) and are not compared.
pub(crate) fn differences(
    general: &[Named],
    special: &[Named],
    problem: &Problem,
) -> Vec<Contract> {
    let letters: Vec<&str> = problem.values.iter().map(|(n, _)| n.as_str()).collect();
    let letters = letters.join(", ");
    let at = given(&problem.values);
    let mut found = Vec::new();
    for (k, s) in special {
        if let Some((_, g)) = general.iter().find(|(q, _)| q == k) {
            verdicts(&k.name(), g, s, &mut found);
        }
    }
    found
        .into_iter()
        .map(|(result, general, special)| Contract::Differs {
            letters: letters.clone(),
            result,
            general,
            at: at.clone(),
            special,
        })
        .collect()
}
