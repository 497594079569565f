//! A problem's `"values"`: the problem is solved with the values put into its numbers, so
//! that every decision (developable, exact, a sign, an order of continuity, the zeros, the
//! condition that fails) is taken at the values given, and the answer equals that of the
//! problem with the numbers written in.
//!
//! The values are put in where the problem's numbers enter the scalar of the solve
//! ([`ExactScalar::from_number`](crate::ExactScalar::from_number), the one door every number
//! of a problem goes through): [`with_values`] sets them for the solve on this thread. The
//! problem then runs in the field its numbers have once the values are in ([`field`]): Q or
//! Q(√d) when every letter has a number, the letters otherwise.
//!
//! The answer in letters is solved too, to compare: where it differs from the answer at the
//! values once they are put into it ([`differences`]), a remark says which results a special
//! value changed.

use crate::field::NumberField;
use crate::problem::Problem;
use crate::value::{Exact, Number};
use crate::{Named, ProblemError};
use cagd_param::Name;
use cagd_scalar::Print;
use std::borrow::Cow;
use std::cell::RefCell;
use std::rc::Rc;

thread_local! {
    /// The values put into the problem's numbers by the solve running on this thread.
    static PUT_IN: RefCell<Option<Rc<[(Name, Number)]>>> = const { RefCell::new(None) };
}

/// Restores the values of an enclosing call when dropped (also on an unwinding: a problem
/// stopped at its deadline).
struct Restore(Option<Rc<[(Name, Number)]>>);

impl Drop for Restore {
    fn drop(&mut self) {
        let outer = self.0.take();
        PUT_IN.with(|p| *p.borrow_mut() = outer);
    }
}

/// Runs `f` with `values` put into every number of the problem read on this thread (through
/// [`put_in`]); the values of an enclosing call are restored afterwards.
pub(crate) fn with_values<R>(values: &[(Name, Number)], f: impl FnOnce() -> R) -> R {
    let mine: Rc<[(Name, Number)]> = values.into();
    let outer = PUT_IN.with(|p| p.borrow_mut().replace(mine));
    let _restore = Restore(outer);
    f()
}

/// A number of the problem with the values of the running solve put in (itself outside
/// [`with_values`]), or why it has no value there (a denominator that vanishes).
pub(crate) fn put_in(x: &Number) -> Result<Cow<'_, Number>, String> {
    if x.is_const() {
        return Ok(Cow::Borrowed(x));
    }
    PUT_IN.with(|p| match p.borrow().as_deref() {
        None => Ok(Cow::Borrowed(x)),
        Some(values) => x.substitute(values).map(Cow::Owned).ok_or_else(|| {
            format!(
                "the value {} has a denominator that vanishes at these values",
                x.to_text()
            )
        }),
    })
}

/// The field the problem runs in with its values put in: the letters' root field Q or Q(√d)
/// when every parameter has a value without letters (a value's root joins the field's, two
/// different roots are an error naming the value), the letters otherwise.
pub(crate) fn field(problem: &Problem) -> Result<NumberField, ProblemError> {
    let NumberField::Letters(mut root) = problem.field else {
        return Ok(problem.field);
    };
    let valued = |n: &Name| problem.values.iter().any(|(k, _)| k == n);
    let numbers = problem.parameters.iter().all(valued)
        && problem.values.iter().all(|(_, x)| x.is_const());
    for (name, x) in &problem.values {
        let d = x.radicand();
        if d == 0 || d == root {
            continue;
        }
        if root != 0 {
            return Err(ProblemError::at(
                &format!("values.{name}"),
                format!(
                    "this number needs √{d}, but the problem's numbers need √{root}: a problem \
                     runs in one field a + b√d"
                ),
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
pub(crate) fn solved_with(values: &[(Name, Number)]) -> String {
    format!("the problem solved with {} put in", given(values))
}

/// Whether two results are the same value: exactly equal, a rational map up to the factor
/// its numerator and denominator share (p/q = r/s when p s = r q).
fn same(a: &Exact, b: &Exact) -> bool {
    match (a, b) {
        (Exact::Rational(x), Exact::Rational(y)) => {
            x.numerator().mul_poly(y.denominator()) == y.numerator().mul_poly(x.denominator())
        }
        (Exact::List(xs), Exact::List(ys)) => {
            xs.len() == ys.len() && xs.iter().zip(ys).all(|(x, y)| same(x, y))
        }
        (Exact::Object(xs), Exact::Object(ys)) => {
            xs.len() == ys.len()
                && xs
                    .iter()
                    .zip(ys)
                    .all(|((k, x), (l, y))| k == l && same(x, y))
        }
        _ => a == b,
    }
}

/// The value named `k` among `named`.
fn find<'a>(named: &'a [Named], k: &str) -> Option<&'a Exact> {
    named.iter().find(|(n, _)| n == k).map(|(_, x)| x)
}

/// The remarks on the results where the answer in letters (`general`), with the values put
/// in, differs from the answer solved at the values (`special`): a verdict (yes or no) or an
/// order is said with both values, the other results are named; none when they agree.
pub(crate) fn differences(
    general: &[Named],
    special: &[Named],
    problem: &Problem,
) -> Vec<String> {
    let values = &problem.values;
    let letters: Vec<&str> = values.iter().map(|(n, _)| n.as_str()).collect();
    let letters = letters.join(", ");
    let at = given(values);
    let mut keys: Vec<&str> = special.iter().map(|(k, _)| k.as_str()).collect();
    keys.extend(
        general
            .iter()
            .map(|(k, _)| k.as_str())
            .filter(|k| find(special, k).is_none()),
    );
    let mut remarks = Vec::new();
    let mut others = Vec::new();
    for k in keys {
        let g = find(general, k).map(|g| g.substitute(values));
        let s = find(special, k);
        match (g, s) {
            (Some(Ok(g)), Some(s)) if same(&g, s) => {}
            (Some(Ok(Exact::Bool(g))), Some(Exact::Bool(s))) => {
                let word = |b: bool| if b { "yes" } else { "no" };
                remarks.push(format!(
                    "for general values of {letters}, `{k}` is {}; at {at} it is {}",
                    word(g),
                    word(*s)
                ));
            }
            (Some(Ok(Exact::Int(g))), Some(Exact::Int(s))) => remarks.push(format!(
                "for general values of {letters}, `{k}` is {g}; at {at} it is {s}"
            )),
            _ => others.push(format!("`{k}`")),
        }
    }
    match others.as_slice() {
        [] => {}
        [one] => remarks.push(format!(
            "for general values of {letters}, the result {one} differs from the one at {at}"
        )),
        many => remarks.push(format!(
            "for general values of {letters}, the results {} differ from the ones at {at}",
            many.join(", ")
        )),
    }
    remarks
}
