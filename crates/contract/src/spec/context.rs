//! The reading context of a problem (its limits, the number field met so far, the hints) on
//! the thread, and the typed errors of a reading ([`Typed`]).

use crate::limits::{read_number, Limit, Limits};
use crate::message::found::Found;
use crate::message::read::{Read, Wanted};
use crate::value::exact::Number;
use crate::Message;
use cagd_param::Name;
use cagd_scalar::Print;
use serde::de::{self};
use std::cell::{Cell, RefCell};

/// What a reading knows beyond the JSON: the limits, and the square root met first (the
/// number field), with where it was met when that is known.
pub(super) struct Context {
    pub(super) limits: Limits,
    /// The parameters the problem declares: the letters its numbers may use.
    pub(super) parameters: Vec<Name>,
    /// The root, and whether the operation needs it (else a number of the problem did).
    root: Option<(u64, bool)>,
    /// Stop at the first number that needs √d (to find its path for an error message).
    locate: Option<u64>,
}

/// The limits the reading checks once per number or item, copied out of [`Context`] so that
/// they cost no borrow of it.
#[derive(Debug, Clone, Copy)]
pub(super) struct Quick {
    pub(super) max_digits: usize,
    pub(super) max_points: usize,
}

impl Quick {
    const DEFAULT: Quick = Quick::of(&Limits::DEFAULT);

    const fn of(limits: &Limits) -> Quick {
        Quick {
            max_digits: limits.max_digits,
            max_points: limits.max_points,
        }
    }
}

thread_local! {
    pub(super) static CONTEXT: RefCell<Option<Context>> = const { RefCell::new(None) };
    /// [`Quick`] of the context (the defaults outside one).
    pub(super) static QUICK: Cell<Quick> = const { Cell::new(Quick::DEFAULT) };
    /// Remarks on what was read (a decimal that looks like a truncated fraction), taken by
    /// [`take_hints`] once the problem is read.
    pub(super) static HINTS: RefCell<Vec<Message>> = const { RefCell::new(Vec::new()) };
    /// The typed error of a reader on its way through serde, under its English text: taken
    /// by [`take_typed`].
    pub(super) static STASH: RefCell<Option<(String, Typed)>> = const { RefCell::new(None) };
}

thread_local! {
    /// Whether a shape read on this thread since [`take_homogeneous`] was written with
    /// homogeneous control points (`"homogeneous": true`).
    static HOMOGENEOUS: Cell<bool> = const { Cell::new(false) };
}

/// Notes that a shape was written with homogeneous control points.
pub(crate) fn note_homogeneous() {
    HOMOGENEOUS.with(|h| h.set(true));
}

/// Whether a shape read on this thread since the last call was written homogeneous.
pub(crate) fn take_homogeneous() -> bool {
    HOMOGENEOUS.with(|h| h.replace(false))
}

/// The remarks the reading of this thread made since the last call (none is an error).
pub(crate) fn take_hints() -> Vec<Message> {
    HINTS.with(|h| std::mem::take(&mut *h.borrow_mut()))
}

/// A typed error of the reading: what is wrong, the limit it is a refusal by, and where below
/// the value being read (`bezier[1]`; empty at the value itself).
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Typed {
    /// The path below the value serde was reading, as a field path (`weights[2]`).
    pub below: String,
    /// What is wrong.
    pub message: Message,
    /// The limit, when the error is a refusal by one.
    pub limit: Option<Limit>,
}

impl<M: Into<Message>> From<M> for Typed {
    fn from(m: M) -> Typed {
        let message = m.into();
        Typed {
            below: String::new(),
            limit: message.limit(),
            message,
        }
    }
}

impl Typed {
    /// The error, below the member `key` of the value being read.
    pub fn below(mut self, key: &str) -> Typed {
        self.below = join(key, &self.below);
        self
    }

    /// Stashes the error on the thread for [`take_typed`] and returns its English text (what
    /// serde carries).
    pub fn stash(self) -> String {
        let english = self.message.to_string();
        STASH.with(|s| *s.borrow_mut() = Some((english.clone(), self)));
        english
    }

    /// The error as serde's (stashed: [`Typed::stash`]).
    pub fn serde<E: de::Error>(self) -> E {
        E::custom(self.stash())
    }

    /// The error serde gave back as `text`: the typed error stashed under it, else serde's
    /// own words as they are ([`Contract::Serde`](crate::message::contract::Contract::Serde)).
    pub fn from_serde(text: String) -> Typed {
        take_typed(&text).unwrap_or_else(|| Typed {
            below: String::new(),
            message: crate::message::contract::Contract::Serde { text }.into(),
            limit: None,
        })
    }
}

/// The typed error stashed by a reader under the English `text` of the error serde gives back
/// (serde_json may add its position: ` at line 1 column 5`); `None` for serde's own errors.
/// The stash is emptied.
pub(crate) fn take_typed(text: &str) -> Option<Typed> {
    let (english, typed) = STASH.with(|s| s.borrow_mut().take())?;
    let same = text == english
        || text
            .strip_prefix(english.as_str())
            .is_some_and(|rest| rest.starts_with(" at line "));
    same.then_some(typed)
}

/// A key below a path: `c1` + `bezier[2]` = `c1.bezier[2]` (either may be empty).
pub(super) fn join(path: &str, key: &str) -> String {
    match (path.is_empty(), key.is_empty(), key.starts_with('[')) {
        (true, _, _) => key.to_string(),
        (false, true, _) => path.to_string(),
        (false, false, true) => format!("{path}{key}"),
        (false, false, false) => format!("{path}.{key}"),
    }
}

/// A reader's error, for serde: stashed typed ([`Typed::serde`]), its English for serde. Any
/// `Deserialize` of the problem reports its own sentences so.
pub(crate) fn fail<E: de::Error>(m: impl Into<Message>) -> E {
    Typed::from(m).serde()
}

/// `expected «what», found «found»`, for serde.
pub(crate) fn expected<E: de::Error>(wanted: Wanted, found: Found) -> E {
    fail(Read::Expected { wanted, found })
}

/// The fraction a decimal that ends in a run of one repeated digit (at least four of them, or
/// three and the last rounded up: `0.3333`, `0.16667`, `2.1111`) stands for when the run is
/// taken to repeat forever (`1/3`, `1/6`, `19/9`); `None` for any other number. Runs of 0 and
/// 9 are left alone (they are exact decimals already).
pub fn repeating_decimal(s: &str) -> Option<String> {
    let s = s.trim();
    let (sign, body) = match s.strip_prefix('-') {
        Some(b) => ("-", b),
        None => ("", s),
    };
    let (int, frac) = body.split_once('.')?;
    if int.is_empty() || !int.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let f = frac.as_bytes();
    if f.len() < 4 || !f.iter().all(u8::is_ascii_digit) {
        return None;
    }
    let run = |end: usize| {
        let d = *f.get(end.checked_sub(1)?)?;
        let n = f.get(..end)?.iter().rev().take_while(|&&b| b == d).count();
        Some((d, n))
    };
    let (d, start) = match run(f.len())? {
        (d, n) if n >= 4 => (d, f.len() - n),
        (last, 1) => match run(f.len() - 1)? {
            (d, n) if n >= 3 && d + 1 == last => (d, f.len() - 1 - n),
            _ => return None,
        },
        _ => return None,
    };
    if d == b'0' || d == b'9' {
        return None;
    }
    let head = std::str::from_utf8(f.get(..start)?).ok()?;
    let head = if head.is_empty() { "0" } else { head };
    // I + (9 N + d) / (9 · 10^r), N the digits before the run, r their count
    Some(format!(
        "{sign}({int} + ({head}*9 + {})/(9*10^{start}))",
        char::from(d)
    ))
}

/// Remarks when the decimal `s` (read as `x`) looks like a truncated repeating fraction.
pub(super) fn hint_repeating(s: &str, x: &Number) {
    // only a decimal can look truncated: most numbers are `p/q`, read without looking further
    if !s.contains('.') {
        return;
    }
    let Some(q) = repeating_decimal(s).and_then(|e| read_number(&e, &limits()).ok()) else {
        return;
    };
    let hint = Message::from(Read::Repeating {
        text: s.into(),
        exact: x.to_text().into(),
        meant: q.to_text().into(),
    });
    HINTS.with(|h| {
        let mut h = h.borrow_mut();
        if !h.contains(&hint) {
            h.push(hint);
        }
    });
}

/// Runs `read` with `limits` as the reading context of this thread; `root` is a square root
/// the operation needs itself (circles of quarter arcs need √2), `locate` the root whose
/// first number should stop the reading. Returns the root met (the number field) and the
/// parameters declared at the end (a generic mesh declares its letters c_{i,j}).
pub(crate) fn read_with<T>(
    limits: &Limits,
    parameters: &[Name],
    root: Option<u64>,
    locate: Option<u64>,
    read: impl FnOnce() -> T,
) -> (T, Option<u64>, Vec<Name>) {
    let quick = QUICK.with(|q| q.replace(Quick::of(limits)));
    // an error stashed by an earlier reading is not this one's
    STASH.with(|s| s.borrow_mut().take());
    let previous = CONTEXT.with(|c| {
        c.borrow_mut().replace(Context {
            limits: *limits,
            parameters: parameters.to_vec(),
            root: root.map(|d| (d, true)),
            locate,
        })
    });
    let out = read();
    let found = CONTEXT.with(|c| {
        let mut c = c.borrow_mut();
        let found = c.as_ref().and_then(|ctx| ctx.root.as_ref().map(|r| r.0));
        let declared = c
            .as_ref()
            .map(|ctx| ctx.parameters.clone())
            .unwrap_or_default();
        *c = previous;
        (found, declared)
    });
    QUICK.with(|q| q.set(quick));
    (out, found.0, found.1)
}

pub(crate) fn limits() -> Limits {
    CONTEXT.with(|c| {
        c.borrow()
            .as_ref()
            .map_or(Limits::DEFAULT, |ctx| ctx.limits)
    })
}

/// Notes that a number needs √d: an error when another root came first.
pub(super) fn note_root<E: de::Error>(d: u64) -> Result<(), E> {
    CONTEXT.with(|c| {
        let mut c = c.borrow_mut();
        let Some(ctx) = c.as_mut() else {
            return Ok(());
        };
        if ctx.locate == Some(d) {
            return Err(Typed::from(Read::Located).serde());
        }
        match ctx.root {
            None => {
                ctx.root = Some((d, false));
                Ok(())
            }
            Some((d0, _)) if d0 == d => Ok(()),
            Some((first, true)) => Err(fail(Read::RootAgainstOperation { needs: d, first })),
            Some((first, false)) => Err(fail(Read::RootAgainstEarlier { needs: d, first })),
        }
    })
}

/// Reads a value of an answer's shape (a fixture's `expected` value) under the default
/// limits; an error says where in the value it is (its English text: [`read_value_typed`]
/// says it typed).
pub fn read_value<T: serde::de::DeserializeOwned>(
    value: &serde_json::Value,
    parameters: &[Name],
) -> Result<T, Message> {
    read_value_typed(value, parameters).map_err(|t| t.message)
}

/// [`read_value`], its error typed.
pub(crate) fn read_value_typed<T: serde::de::DeserializeOwned>(
    value: &serde_json::Value,
    parameters: &[Name],
) -> Result<T, Typed> {
    let (result, _, _) = read_with(&Limits::DEFAULT, parameters, None, None, || {
        serde_path_to_error::deserialize::<_, T>(value)
    });
    result.map_err(|e| {
        let path = e.path().to_string();
        let typed = Typed::from_serde(e.into_inner().to_string());
        let at = join(if path == "." { "" } else { &path }, &typed.below);
        if at.is_empty() {
            Typed {
                below: String::new(),
                ..typed
            }
        } else {
            Typed::from(Read::At {
                at,
                inner: typed.message.into(),
            })
        }
    })
}
