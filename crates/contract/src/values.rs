//! A problem's `"values"`: the problem is solved with the values put into its numbers, so
//! that every decision (developable, exact, a sign, an order of continuity, the zeros, the
//! condition that fails) is taken at the values given, and the answer equals that of the
//! problem with the numbers written in.
//!
//! The values are put in where the problem's numbers enter the scalar of the solve
//! ([`ExactScalar::from_number`](crate::ExactScalar::from_number), the one door every number
//! of a problem goes through): [`with_values`] sets them for the solve on this thread. The
//! problem then runs in the field its numbers have once the values are in ([`crate::specialize::field`]): Q or
//! Q(√d) when every letter has a number, the letters otherwise.
//!
//! The answer in letters is solved too, to compare: where it differs from the answer at the
//! values once they are put into it ([`crate::specialize::differences`]), a remark says which results a special
//! value changed.

use crate::message::contract::Contract;
use crate::value::exact::Number;
use cagd_param::Name;
use cagd_scalar::Print;
use std::borrow::Cow;
use std::cell::RefCell;
use std::rc::Rc;

/// The values of a problem, shared by the solve that puts them in.
type Values = Rc<[(Name, Number)]>;

thread_local! {
    /// The values put into the problem's numbers by the solve running on this thread.
    static PUT_IN: RefCell<Option<Values>> = const { RefCell::new(None) };
}

/// Restores the values of an enclosing call when dropped (also on an unwinding: a problem
/// stopped at its deadline).
struct Restore(Option<Values>);

impl Drop for Restore {
    fn drop(&mut self) {
        let outer = self.0.take();
        PUT_IN.with(|p| *p.borrow_mut() = outer);
    }
}

/// Runs `f` with `values` put into every number of the problem read on this thread (through
/// [`put_in`]); the values of an enclosing call are restored afterwards.
pub fn with_values<R>(values: &[(Name, Number)], f: impl FnOnce() -> R) -> R {
    let mine: Values = values.into();
    let outer = PUT_IN.with(|p| p.borrow_mut().replace(mine));
    let _restore = Restore(outer);
    f()
}

/// A number of the problem with the values of the running solve put in (itself outside
/// [`with_values`]), or why it has no value there (a denominator that vanishes).
pub(crate) fn put_in(x: &Number) -> Result<Cow<'_, Number>, Contract> {
    if x.is_const() {
        return Ok(Cow::Borrowed(x));
    }
    PUT_IN.with(|p| match p.borrow().as_deref() {
        None => Ok(Cow::Borrowed(x)),
        Some(values) => x
            .substitute(values)
            .map(Cow::Owned)
            .ok_or_else(|| Contract::VanishingAtValues { value: x.to_text() }),
    })
}
