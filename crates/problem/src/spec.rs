//! The typed shapes of a problem's values, read with serde: exact numbers, points, meshes,
//! expressions, curves and surfaces (`docs/format.md`, Shapes).
//!
//! Each value is read once, by the one grammar, under the [`Limits`] of the run, and checked
//! where it is read (a point's dimension, a mesh's rows, the count of weights), so that an
//! error carries the path of the value at fault (`c1.bezier[2]`). The limits and the choice of
//! the number field are a per-thread reading context ([`read_with`]): serde's `Deserialize`
//! has no argument for them.
//!
//! An error of the reading is typed ([`Typed`]: a [`Message`], its [`Limit`], the path below
//! the value serde was reading). serde's `Deserialize` can only return an error made from a
//! text, so a reader stashes its typed error on the thread ([`Typed::serde`]) and returns its
//! English text; the one place that reads serde's errors takes it back by that text
//! ([`take_typed`]).

use crate::input::{quoted, CurveIn, SurfaceIn};
use crate::limits::{limit_of, read_number, Limit, Limits};
use crate::message::contract::Contract;
use crate::message::contract::Found;
use crate::message::read::{Read, Wanted};
use crate::value::{ExactScalar, Number};
use crate::Message;
use cagd_linalg::Point;
use cagd_param::{parse_param, parse_param_expr, Name, ParamExpr};
use cagd_poly::{parse_expr_with, Expr, VecPoly};
use cagd_scalar::{FieldOps, Print, Quadratic, ScalarError};
use cagd_surface::{Grid, Mesh};
use serde::de::{self, DeserializeSeed, Deserializer, IgnoredAny, SeqAccess, Visitor};
use serde::Deserialize;
use std::cell::{Cell, RefCell};
use std::fmt;

/// What a reading knows beyond the JSON: the limits, and the square root met first (the
/// number field), with where it was met when that is known.
struct Context {
    limits: Limits,
    /// The parameters the problem declares: the letters its numbers may use.
    parameters: Vec<Name>,
    /// The root, and whether the operation needs it (else a number of the problem did).
    root: Option<(u64, bool)>,
    /// Stop at the first number that needs √d (to find its path for an error message).
    locate: Option<u64>,
}

/// The limits the reading checks once per number or item, copied out of [`Context`] so that
/// they cost no borrow of it.
#[derive(Debug, Clone, Copy)]
struct Quick {
    max_digits: usize,
    max_points: usize,
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
    static CONTEXT: RefCell<Option<Context>> = const { RefCell::new(None) };
    /// [`Quick`] of the context (the defaults outside one).
    static QUICK: Cell<Quick> = const { Cell::new(Quick::DEFAULT) };
    /// Remarks on what was read (a decimal that looks like a truncated fraction), taken by
    /// [`take_hints`] once the problem is read.
    static HINTS: RefCell<Vec<Message>> = const { RefCell::new(Vec::new()) };
    /// The typed error of a reader on its way through serde, under its English text: taken
    /// by [`take_typed`].
    static STASH: RefCell<Option<(String, Typed)>> = const { RefCell::new(None) };
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
            limit: limit_of(&message),
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
    /// own words as they are ([`Contract::Serde`]).
    pub fn from_serde(text: String) -> Typed {
        take_typed(&text).unwrap_or_else(|| Typed {
            below: String::new(),
            message: Contract::Serde { text }.into(),
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
fn join(path: &str, key: &str) -> String {
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
fn hint_repeating(s: &str, x: &Number) {
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
fn note_root<E: de::Error>(d: u64) -> Result<(), E> {
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

/// Reads a number of the grammar; in letters when the problem declares parameters (and the
/// text has a letter besides `sqrt`).
fn read_text(text: &str) -> Result<Number, ScalarError> {
    let has_letter = || text.replace("sqrt", "").chars().any(|c| c.is_alphabetic());
    // the parameters are copied only for a text in letters
    let (limits, parameters) = CONTEXT.with(|c| {
        c.borrow()
            .as_ref()
            .map_or((Limits::DEFAULT, Vec::new()), |ctx| {
                let letters = !ctx.parameters.is_empty() && has_letter();
                (
                    ctx.limits,
                    if letters {
                        ctx.parameters.clone()
                    } else {
                        Vec::new()
                    },
                )
            })
    });
    if parameters.is_empty() {
        return read_number(text, &limits).map(Number::Const).map_err(|e| {
            // a letter in a problem without parameters: say how to declare it
            match (&e, has_letter()) {
                (ScalarError::Parse { .. }, true) => {
                    parse_param(text, &[], &limits.grammar()).err().unwrap_or(e)
                }
                _ => e,
            }
        });
    }
    parse_param(text, &parameters, &limits.grammar())
}

/// The error of a number's text that does not read (`e`, the grammar's), with the way to
/// write it when it is a habit of the notes' language: a decimal comma (`"1,5"`), a square
/// root written as a word (`"raiz2"`).
fn number_error(text: &str, e: ScalarError) -> Typed {
    let q = quoted(text);
    if let Some((exact, decimal)) = decimal_comma(text) {
        return Read::DecimalComma {
            text: q.into(),
            exact: exact.into(),
            decimal: decimal.into(),
        }
        .into();
    }
    if let Some(fixed) = root_word(text) {
        return Read::RootWord {
            text: q,
            fixed: quoted(&fixed),
        }
        .into();
    }
    Read::Quoted {
        text: q,
        error: e.into(),
    }
    .into()
}

/// A number written with one decimal comma between two digits (`1,5`): its exact value and
/// its text with a decimal point, when that reads.
fn decimal_comma(text: &str) -> Option<(String, String)> {
    let (a, b) = text.trim().split_once(',')?;
    if b.contains(',')
        || !a.ends_with(|c: char| c.is_ascii_digit())
        || !b.starts_with(|c: char| c.is_ascii_digit())
    {
        return None;
    }
    let decimal = format!("{a}.{b}");
    let x = read_text(&decimal).ok()?;
    Some((x.to_text(), decimal))
}

/// The words for a square root the grammar does not know (it reads `sqrt` and `√`).
const ROOT_WORDS: [&str; 6] = ["raiz", "raíz", "root", "sqr", "rt", "rad"];

/// A text with a square root written as a word of [`ROOT_WORDS`] (`raiz2`, `raíz(2)`): the
/// text with `sqrt` in its place, when that reads.
fn root_word(text: &str) -> Option<String> {
    fn flush(run: &mut String, fixed: &mut String) -> bool {
        let root = ROOT_WORDS.contains(&run.to_lowercase().as_str());
        fixed.push_str(if root { "sqrt" } else { run.as_str() });
        run.clear();
        root
    }
    let mut fixed = String::with_capacity(text.len() + 4);
    let mut run = String::new();
    let mut replaced = false;
    for c in text.chars() {
        if c.is_alphabetic() {
            run.push(c);
        } else {
            replaced |= flush(&mut run, &mut fixed);
            fixed.push(c);
        }
    }
    replaced |= flush(&mut run, &mut fixed);
    (replaced && read_text(&fixed).is_ok()).then_some(fixed)
}

fn note_number<E: de::Error>(d: u64) -> Result<(), E> {
    match d {
        0 => Ok(()),
        d => note_root(d),
    }
}

/// The kind of a list whose length is known (`a list of 3`).
fn list_of<'de, A: SeqAccess<'de>>(seq: &A) -> Found {
    match seq.size_hint() {
        Some(n) => Found::ListOf(n),
        None => Found::List,
    }
}

/// A visitor that refuses every JSON kind but the ones it overrides, saying what it expected.
macro_rules! refuse_others {
    ($what:expr) => {
        fn visit_bool<E: de::Error>(self, b: bool) -> Result<Self::Value, E> {
            Err(expected($what, Found::Bool(b)))
        }
        fn visit_str<E: de::Error>(self, s: &str) -> Result<Self::Value, E> {
            Err(expected($what, Found::Str(quoted(s))))
        }
        fn visit_unit<E: de::Error>(self) -> Result<Self::Value, E> {
            Err(expected($what, Found::Null))
        }
        fn visit_none<E: de::Error>(self) -> Result<Self::Value, E> {
            Err(expected($what, Found::Null))
        }
        fn visit_map<A: de::MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
            let found = match json_number(&mut map)? {
                Some(text) => Found::Number(text),
                None => Found::Object,
            };
            Err(expected($what, found))
        }
    };
}

macro_rules! refuse_numbers {
    ($what:expr) => {
        fn visit_i64<E: de::Error>(self, n: i64) -> Result<Self::Value, E> {
            Err(expected($what, Found::Number(n.to_string())))
        }
        fn visit_u64<E: de::Error>(self, n: u64) -> Result<Self::Value, E> {
            Err(expected($what, Found::Number(n.to_string())))
        }
        fn visit_f64<E: de::Error>(self, n: f64) -> Result<Self::Value, E> {
            Err(expected($what, Found::Number(n.to_string())))
        }
        fn visit_i128<E: de::Error>(self, n: i128) -> Result<Self::Value, E> {
            Err(expected($what, Found::Number(n.to_string())))
        }
        fn visit_u128<E: de::Error>(self, n: u128) -> Result<Self::Value, E> {
            Err(expected($what, Found::Number(n.to_string())))
        }
    };
}

macro_rules! refuse_lists {
    ($what:expr) => {
        fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Self::Value, A::Error> {
            Err(expected($what, list_of(&seq)))
        }
    };
}

/// An exact number: a JSON integer (of any length), or a string of the grammar (`"5/6"`,
/// `"sqrt2/2"`). A JSON number with a fraction part is refused (a JSON writer may already
/// have rounded it; strings are the exact way), one whose value is an integer (`1.0`, `2e3`,
/// `-0`) is that integer.
#[derive(Debug, Clone, PartialEq)]
pub struct Num(pub Number);

struct NumVisitor;

/// The key under which serde_json (`arbitrary_precision`) hands over a number as written,
/// when it is no machine integer and no float that prints back as written.
const JSON_NUMBER: &str = "$serde_json::private::Number";

/// The text of a JSON number a visitor meets as a map (`arbitrary_precision`), or `None` for
/// a map that is an object.
pub(crate) fn json_number<'de, A: de::MapAccess<'de>>(
    map: &mut A,
) -> Result<Option<String>, A::Error> {
    match map.next_key::<JsonNumberKey>()? {
        Some(JsonNumberKey(true)) => map.next_value::<String>().map(Some),
        _ => Ok(None),
    }
}

/// A key of a map: whether it is serde_json's key of a number as written (read without
/// copying any other key).
struct JsonNumberKey(bool);

impl<'de> Deserialize<'de> for JsonNumberKey {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl Visitor<'_> for V {
            type Value = JsonNumberKey;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a key")
            }
            fn visit_str<E: de::Error>(self, s: &str) -> Result<JsonNumberKey, E> {
                Ok(JsonNumberKey(s == JSON_NUMBER))
            }
        }
        d.deserialize_str(V)
    }
}

/// The integer a JSON number written as `text` (`-12`, `1.50e3`) equals, as decimal digits
/// with its sign, or `None` when it has a fraction part; an integer of more than
/// `max_digits` digits is an error, found before its digits are written.
pub(crate) fn json_integer(text: &str, max_digits: usize) -> Result<Option<String>, Read> {
    let (minus, body) = match text.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, text),
    };
    let (mantissa, exponent) = match body.find(['e', 'E']) {
        Some(k) => (body.get(..k).unwrap_or(""), body.get(k + 1..).unwrap_or("")),
        None => (body, "0"),
    };
    let (int_part, frac_part) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let exponent = exponent.strip_prefix('+').unwrap_or(exponent);
    // an exponent too long for a machine word is past every limit, or makes 0 of the digits
    let exponent: i64 = exponent.parse().unwrap_or(if exponent.starts_with('-') {
        i64::MIN / 2
    } else {
        i64::MAX / 2
    });
    let digits = format!("{int_part}{frac_part}");
    let leading = digits.len() - digits.trim_start_matches('0').len();
    let significant = digits.trim_matches('0');
    if significant.is_empty() {
        return Ok(Some("0".into()));
    }
    // the decimal point sits after `point` significant digits
    let len = |n: usize| i64::try_from(n).unwrap_or(i64::MAX / 4);
    let point = len(int_part.len()) - len(leading) + exponent;
    if point < len(significant.len()) {
        return Ok(None);
    }
    let count = usize::try_from(point).unwrap_or(usize::MAX);
    if count > max_digits {
        let number = text.to_string();
        return Err(if count == usize::MAX {
            Read::JsonDigitsMany {
                number,
                max: max_digits,
            }
        } else {
            Read::JsonDigits {
                number,
                digits: count,
                max: max_digits,
            }
        });
    }
    let mut out = String::with_capacity(count + 1);
    if minus {
        out.push('-');
    }
    out.push_str(significant);
    out.extend(std::iter::repeat_n('0', count - significant.len()));
    Ok(Some(out))
}

impl Num {
    /// The number a JSON number written as `text` stands for: an integer exactly; with a
    /// fraction part, refused with the way to write it exactly. The error is stashed for
    /// serde ([`Typed::stash`]): its text goes into `de::Error::custom`.
    pub(crate) fn from_json_number(text: &str) -> Result<Num, String> {
        Num::of_json_number(text).map_err(Typed::stash)
    }

    /// [`Num::from_json_number`], its error typed.
    fn of_json_number(text: &str) -> Result<Num, Typed> {
        let limits = limits();
        match json_integer(text, limits.max_digits)? {
            Some(digits) => read_number(&digits, &limits)
                .map(|x| Num(Number::Const(x)))
                .map_err(Typed::from),
            None => Err(Read::FractionPart {
                number: text.to_string(),
            }
            .into()),
        }
    }
}

impl<'de> Visitor<'de> for NumVisitor {
    type Value = Num;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a number")
    }
    fn visit_i64<E: de::Error>(self, n: i64) -> Result<Num, E> {
        let x = Quadratic::from_i64(n);
        // a machine integer has at most 19 digits
        if QUICK.with(Cell::get).max_digits < 19 {
            limits().check_digits(&x).map_err(fail::<E>)?;
        }
        Ok(Num(Number::Const(x)))
    }
    fn visit_u64<E: de::Error>(self, n: u64) -> Result<Num, E> {
        match i64::try_from(n) {
            Ok(i) => self.visit_i64(i),
            Err(_) => Num::of_json_number(&n.to_string()).map_err(Typed::serde),
        }
    }
    fn visit_i128<E: de::Error>(self, n: i128) -> Result<Num, E> {
        Num::of_json_number(&n.to_string()).map_err(Typed::serde)
    }
    fn visit_u128<E: de::Error>(self, n: u128) -> Result<Num, E> {
        Num::of_json_number(&n.to_string()).map_err(Typed::serde)
    }
    /// A float that prints back as written: its shortest decimal form is what was written.
    fn visit_f64<E: de::Error>(self, n: f64) -> Result<Num, E> {
        Num::of_json_number(&n.to_string()).map_err(Typed::serde)
    }
    fn visit_str<E: de::Error>(self, s: &str) -> Result<Num, E> {
        // `-9`, `3/4`: no grammar, no root, no remark (the grammar would read the same value;
        // the parameters do not matter to a text without letters)
        if let Some(x) = cagd_scalar::word_literal(s, QUICK.with(Cell::get).max_digits) {
            return Ok(Num(Number::Const(Quadratic::from_rat(x))));
        }
        let x = read_text(s).map_err(|e| number_error(s, e).serde::<E>())?;
        note_number(x.radicand())?;
        hint_repeating(s, &x);
        Ok(Num(x))
    }
    fn visit_bool<E: de::Error>(self, b: bool) -> Result<Num, E> {
        Err(expected(Wanted::Number, Found::Bool(b)))
    }
    fn visit_unit<E: de::Error>(self) -> Result<Num, E> {
        Err(expected(Wanted::Number, Found::Null))
    }
    fn visit_none<E: de::Error>(self) -> Result<Num, E> {
        self.visit_unit()
    }
    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Num, A::Error> {
        Err(expected(Wanted::Number, list_of(&seq)))
    }
    fn visit_map<A: de::MapAccess<'de>>(self, mut map: A) -> Result<Num, A::Error> {
        match json_number(&mut map)? {
            Some(text) => Num::of_json_number(&text).map_err(Typed::serde),
            None => Err(expected(Wanted::Number, Found::Object)),
        }
    }
}

impl<'de> Deserialize<'de> for Num {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(NumVisitor)
    }
}

impl Num {
    /// The number in the scalar `S` of the problem.
    pub fn to<S: ExactScalar>(&self) -> Result<S, Message> {
        S::from_number(&self.0)
    }
}

/// A non-negative integer as written (degrees, counts, orders): its limits are the
/// operation's to check, where it knows what the integer counts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Int(pub u64);

struct IntVisitor;

const NON_NEGATIVE: &str = "expected a non-negative integer";

impl<'de> Visitor<'de> for IntVisitor {
    type Value = Int;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(NON_NEGATIVE)
    }
    fn visit_u64<E: de::Error>(self, n: u64) -> Result<Int, E> {
        Ok(Int(n))
    }
    fn visit_i64<E: de::Error>(self, n: i64) -> Result<Int, E> {
        u64::try_from(n)
            .map(Int)
            .map_err(|_| expected(Wanted::NonNegative, Found::Number(n.to_string())))
    }
    fn visit_f64<E: de::Error>(self, n: f64) -> Result<Int, E> {
        Err(expected(Wanted::NonNegative, Found::Number(n.to_string())))
    }
    fn visit_i128<E: de::Error>(self, n: i128) -> Result<Int, E> {
        Err(expected(Wanted::NonNegative, Found::Number(n.to_string())))
    }
    fn visit_u128<E: de::Error>(self, n: u128) -> Result<Int, E> {
        Err(expected(Wanted::NonNegative, Found::Number(n.to_string())))
    }
    refuse_others!(Wanted::NonNegative);
    refuse_lists!(Wanted::NonNegative);
}

impl<'de> Deserialize<'de> for Int {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(IntVisitor)
    }
}

impl Int {
    /// As a `usize` (saturating: a count past `usize` is past every limit).
    pub fn get(self) -> usize {
        usize::try_from(self.0).unwrap_or(usize::MAX)
    }
}

/// A degree of a curve or surface: a non-negative integer of at most [`Limits::max_degree`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Degree(pub usize);

impl<'de> Deserialize<'de> for Degree {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let n = Int::deserialize(d)?;
        let max = limits().max_degree;
        if n.get() > max {
            return Err(fail(Read::DegreeAbove { degree: n.0, max }));
        }
        Ok(Degree(n.get()))
    }
}

/// A list of at most [`Limits::max_points`] items.
#[derive(Debug, Clone, PartialEq)]
pub struct List<T>(pub Vec<T>);

/// Refuses a list longer than the points limit, before reading its items.
fn check_length<E: de::Error>(hint: Option<usize>) -> Result<(), E> {
    let max = QUICK.with(Cell::get).max_points;
    match hint {
        Some(items) if items > max => Err(fail(Read::ListLonger { items, max })),
        _ => Ok(()),
    }
}

/// Refuses a list, as [`check_length`], once `count` items are read: a list read from a
/// problem's text has no length known before its items.
fn check_count<E: de::Error>(count: usize) -> Result<(), E> {
    if count <= QUICK.with(Cell::get).max_points {
        return Ok(());
    }
    check_length(Some(count))
}

struct ListVisitor<T>(std::marker::PhantomData<T>);

impl<'de, T: Deserialize<'de>> Visitor<'de> for ListVisitor<T> {
    type Value = List<T>;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a list")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<List<T>, A::Error> {
        check_length(seq.size_hint())?;
        let mut out = Vec::with_capacity(seq.size_hint().unwrap_or(0));
        while let Some(x) = seq.next_element()? {
            out.push(x);
            check_count(out.len())?;
        }
        Ok(List(out))
    }
    refuse_others!(Wanted::List);
    refuse_numbers!(Wanted::List);
}

impl<'de, T: Deserialize<'de>> Deserialize<'de> for List<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(ListVisitor(std::marker::PhantomData))
    }
}

/// A pair of numbers `[a, b]` (an interval, a parameter pair (u, v)).
#[derive(Debug, Clone, PartialEq)]
pub struct Pair(pub Num, pub Num);

impl<'de> Deserialize<'de> for Pair {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let List(v) = List::<Num>::deserialize(d)?;
        let n = v.len();
        match <[Num; 2]>::try_from(v) {
            Ok([a, b]) => Ok(Pair(a, b)),
            Err(_) => Err(fail(Read::TwoNumbers { found: n })),
        }
    }
}

impl Pair {
    /// Both numbers in the scalar `S`.
    pub fn to<S: ExactScalar>(&self) -> Result<(S, S), Message> {
        Ok((self.0.to()?, self.1.to()?))
    }
}

/// One integer or a pair `[r, s]` of non-negative integers (an elevation `by`, a derivative
/// `order`): a curve takes one, a surface two.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Orders {
    /// `r`.
    One(Int),
    /// `[r, s]`.
    Two(Int, Int),
}

struct OrdersVisitor;

impl<'de> Visitor<'de> for OrdersVisitor {
    type Value = Orders;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("an integer or two [r, s]")
    }
    fn visit_u64<E: de::Error>(self, n: u64) -> Result<Orders, E> {
        IntVisitor.visit_u64(n).map(Orders::One)
    }
    fn visit_i64<E: de::Error>(self, n: i64) -> Result<Orders, E> {
        IntVisitor.visit_i64(n).map(Orders::One)
    }
    fn visit_f64<E: de::Error>(self, n: f64) -> Result<Orders, E> {
        IntVisitor.visit_f64(n).map(Orders::One)
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Orders, A::Error> {
        let n = seq.size_hint();
        let mut items: Vec<Int> = Vec::new();
        while let Some(x) = seq.next_element::<Int>()? {
            items.push(x);
            if items.len() > 2 {
                break;
            }
        }
        match items.as_slice() {
            [a, b] => Ok(Orders::Two(*a, *b)),
            _ => Err(fail(Read::TwoIntegers {
                found: n.unwrap_or(items.len()),
            })),
        }
    }
    refuse_others!(Wanted::IntegerOrPair);
}

impl<'de> Deserialize<'de> for Orders {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(OrdersVisitor)
    }
}

/// A point `[x, y, z]` (any dimension ≥ 1); in a list, of the dimension of the first.
#[derive(Debug, Clone, PartialEq)]
pub struct PointIn(pub Point<Number>);

/// Reads a point whose dimension must be `dim` (when known).
struct PointSeed {
    dim: Option<usize>,
}

impl<'de> Visitor<'de> for PointSeed {
    type Value = PointIn;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a point")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<PointIn, A::Error> {
        check_length(seq.size_hint())?;
        let mut coords = Vec::with_capacity(seq.size_hint().unwrap_or(3));
        while let Some(Num(x)) = seq.next_element()? {
            coords.push(x);
            check_count(coords.len())?;
        }
        if coords.is_empty() {
            return Err(fail(Read::PointEmpty));
        }
        if let Some(first) = self.dim.filter(|d0| *d0 != coords.len()) {
            return Err(fail(Read::PointDim {
                found: coords.len(),
                first,
            }));
        }
        Ok(PointIn(Point::new(coords)))
    }
    refuse_others!(Wanted::Point);
    refuse_numbers!(Wanted::Point);
}

impl<'de> DeserializeSeed<'de> for PointSeed {
    type Value = PointIn;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<PointIn, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Deserialize<'de> for PointIn {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        PointSeed { dim: None }.deserialize(d)
    }
}

/// A non-empty list of points of one dimension.
#[derive(Debug, Clone, PartialEq)]
pub struct Points(pub Vec<Point<Number>>);

/// Reads a list of points, of dimension `dim` when known (the rows of a mesh), and of
/// `len` points when known (every row as long as the first).
struct PointsSeed {
    dim: Option<usize>,
    len: Option<usize>,
    row: usize,
}

impl<'de> Visitor<'de> for PointsSeed {
    type Value = Points;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a list of points")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Points, A::Error> {
        check_length(seq.size_hint())?;
        if let (Some(n), Some(first)) = (seq.size_hint(), self.len) {
            if n != first {
                return Err(fail(Read::RowLength {
                    row: self.row,
                    found: n,
                    first,
                }));
            }
        }
        let mut pts: Vec<Point<Number>> =
            Vec::with_capacity(self.len.or(seq.size_hint()).unwrap_or(4));
        let mut dim = None;
        while let Some(PointIn(p)) = seq.next_element_seed(PointSeed { dim })? {
            dim = Some(p.dim());
            pts.push(p);
            check_count(pts.len())?;
        }
        if pts.is_empty() {
            return Err(fail(Read::NoPoint));
        }
        if let Some(first) = self.len.filter(|first| *first != pts.len()) {
            // a list read without its length known before (from a problem's text)
            return Err(fail(Read::RowLength {
                row: self.row,
                found: pts.len(),
                first,
            }));
        }
        if let (Some(first), Some(found)) = (self.dim, dim) {
            if first != found {
                return Err(fail(Read::RowDim { found, first }));
            }
        }
        Ok(Points(pts))
    }
    refuse_others!(Wanted::List);
    refuse_numbers!(Wanted::List);
}

impl<'de> DeserializeSeed<'de> for PointsSeed {
    type Value = Points;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<Points, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Deserialize<'de> for Points {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        PointsSeed {
            dim: None,
            len: None,
            row: 0,
        }
        .deserialize(d)
    }
}

/// A mesh: a non-empty list of rows of points (outer index i along u), of equal lengths and
/// one dimension, at most [`Limits::max_points`] points in all.
#[derive(Debug, Clone, PartialEq)]
pub struct MeshIn(pub Mesh<Number>);

/// Counts the points of the rows left, without reading their numbers.
struct CountRow;

impl<'de> DeserializeSeed<'de> for CountRow {
    type Value = usize;
    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<usize, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = usize;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a row")
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<usize, A::Error> {
                let mut n = 0usize;
                while seq.next_element::<IgnoredAny>()?.is_some() {
                    n = n.saturating_add(1);
                }
                Ok(n)
            }
        }
        d.deserialize_any(V).or(Ok(0))
    }
}

struct MeshVisitor;

impl<'de> Visitor<'de> for MeshVisitor {
    type Value = MeshIn;
    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a mesh")
    }
    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<MeshIn, A::Error> {
        check_length(seq.size_hint())?;
        let max = QUICK.with(Cell::get).max_points;
        // the points row after row: each row as long as row 0 and of its dimension, as
        // `PointsSeed` checks
        let mut points: Vec<Point<Number>> = Vec::new();
        let (mut rows, mut first) = (0usize, None::<(usize, usize)>);
        let mut total = 0usize;
        loop {
            let seed = PointsSeed {
                dim: first.map(|(_, dim)| dim),
                len: first.map(|(len, _)| len),
                row: rows,
            };
            let Some(Points(row)) = seq.next_element_seed(seed)? else {
                break;
            };
            total = total.saturating_add(row.len());
            if first.is_none() {
                first = Some((row.len(), row.first().map_or(0, Point::dim)));
                // as many rows as columns, most often
                points.reserve(
                    row.len()
                        .saturating_mul(seq.size_hint().unwrap_or(row.len())),
                );
            }
            points.extend(row);
            rows += 1;
            check_count(rows)?;
            if total > max {
                // count the rest without reading it, to say how large the mesh is
                while let Some(n) = seq.next_element_seed(CountRow)? {
                    total = total.saturating_add(n);
                }
                return Err(fail(Read::MeshLarger { points: total, max }));
            }
        }
        let Some((cols, _)) = first else {
            return Err(fail(Read::MeshEmpty));
        };
        // rows × cols points, checked as read: the grid takes them in order
        let mut points = points.into_iter();
        Ok(MeshIn(Grid::from_fn(rows, cols, |_, _| {
            points.next().unwrap_or_else(|| Point::new(Vec::new()))
        })))
    }
    refuse_others!(Wanted::List);
    refuse_numbers!(Wanted::List);
}

impl<'de> Deserialize<'de> for MeshIn {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        d.deserialize_any(MeshVisitor)
    }
}

/// A grid of numbers (weights), rows like a mesh.
#[derive(Debug, Clone, PartialEq)]
pub struct GridIn(pub Grid<Number>);

impl<'de> Deserialize<'de> for GridIn {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let List(rows) = List::<List<Num>>::deserialize(d)?;
        let rows: Vec<Vec<Number>> = rows
            .into_iter()
            .map(|List(r)| r.into_iter().map(|Num(x)| x).collect())
            .collect();
        Grid::from_rows(rows).map(GridIn).map_err(fail)
    }
}

/// An expression of the grammar (`"(u, 0, u^2)"`, `"x*y"`), read under the limits: its
/// degree is at most [`Limits::max_degree`], its coefficients have at most
/// [`Limits::max_digits`] digits.
#[derive(Debug, Clone, PartialEq)]
pub struct ExprIn {
    /// The text as written.
    pub text: String,
    /// What it reads as.
    pub expr: Expr,
    /// What it reads as when its coefficients use the problem's parameters (`(f, 0, g)`,
    /// `(a u, 0, b)`); `expr` is then unused.
    pub letters: Option<ParamExpr>,
}

impl<'de> Deserialize<'de> for ExprIn {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = ExprIn;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("an expression")
            }
            fn visit_str<E: de::Error>(self, text: &str) -> Result<ExprIn, E> {
                read_expr::<E>(text)
            }
            fn visit_bool<E: de::Error>(self, b: bool) -> Result<ExprIn, E> {
                Err(expected(Wanted::Str, Found::Bool(b)))
            }
            fn visit_unit<E: de::Error>(self) -> Result<ExprIn, E> {
                Err(expected(Wanted::Str, Found::Null))
            }
            fn visit_map<A: de::MapAccess<'de>>(self, mut map: A) -> Result<ExprIn, A::Error> {
                Err(expected(
                    Wanted::Str,
                    match json_number(&mut map)? {
                        Some(text) => Found::Number(text),
                        None => Found::Object,
                    },
                ))
            }
            refuse_numbers!(Wanted::Str);
            refuse_lists!(Wanted::Str);
        }
        d.deserialize_any(V)
    }
}

/// Reads an expression under the limits of the reading context.
fn read_expr<E: de::Error>(text: &str) -> Result<ExprIn, E> {
    let limits = limits();
    let q = quoted(text);
    let parameters = CONTEXT.with(|c| {
        c.borrow()
            .as_ref()
            .map(|ctx| ctx.parameters.clone())
            .unwrap_or_default()
    });
    let expr = match parse_expr_with(text, &limits.grammar()) {
        Ok(expr) => expr,
        Err(_) if !parameters.is_empty() => return read_expr_in_letters(text, &parameters),
        Err(e) => {
            return Err(fail(Read::Quoted {
                text: q,
                error: e.into(),
            }))
        }
    };
    let polys = match &expr {
        Expr::Scalar(p) => std::slice::from_ref(p),
        Expr::Vector(m) => m.components(),
    };
    for p in polys {
        check_expr_degree::<E>(&q, p.degree(), &limits)?;
        for (_, c) in p.terms() {
            limits.check_digits(c).map_err(|m| {
                fail::<E>(Read::Quoted {
                    text: q.clone(),
                    error: m.into(),
                })
            })?;
            note_number::<E>(c.radicand())?;
        }
    }
    Ok(ExprIn {
        text: text.to_string(),
        expr,
        letters: None,
    })
}

/// The degree of an expression's polynomial against the limit.
fn check_expr_degree<E: de::Error>(q: &str, degree: u32, limits: &Limits) -> Result<(), E> {
    let degree = usize::try_from(degree).unwrap_or(usize::MAX);
    if degree > limits.max_degree {
        return Err(fail(Read::ExprDegree {
            text: q.to_string(),
            degree,
            max: limits.max_degree,
        }));
    }
    Ok(())
}

/// Reads an expression whose coefficients use the declared parameters.
fn read_expr_in_letters<E: de::Error>(text: &str, parameters: &[Name]) -> Result<ExprIn, E> {
    let limits = limits();
    let q = quoted(text);
    let letters = parse_param_expr(text, parameters, &limits.grammar()).map_err(|e| {
        fail::<E>(Read::Quoted {
            text: q.clone(),
            error: e.into(),
        })
    })?;
    let polys = match &letters {
        ParamExpr::Scalar(p) => std::slice::from_ref(p),
        ParamExpr::Vector(m) => m.components(),
    };
    for p in polys {
        check_expr_degree::<E>(&q, p.degree(), &limits)?;
        for (_, c) in p.terms() {
            note_number::<E>(c.radicand())?;
        }
    }
    Ok(ExprIn {
        text: text.to_string(),
        expr: Expr::Scalar(cagd_poly::Poly::zero()),
        letters: Some(letters),
    })
}

impl ExprIn {
    /// The polynomial map over `S` (`"(u, 0, u^2)"`).
    pub fn vector<S: ExactScalar>(&self) -> Result<VecPoly<S>, Read> {
        let text = quoted(&self.text);
        let quoted = |e: Message| Read::Quoted {
            text: text.clone(),
            error: e.into(),
        };
        match &self.letters {
            Some(ParamExpr::Vector(m)) => {
                let comps = m
                    .components()
                    .iter()
                    .map(|p| p.try_map_coeffs(S::from_number))
                    .collect::<Result<Vec<_>, _>>()
                    .map_err(quoted)?;
                Ok(VecPoly::new(comps))
            }
            Some(ParamExpr::Scalar(p)) => Err(Read::NotTuple {
                text,
                poly: p.to_string(),
            }),
            None => self.expr.vector::<S>().map_err(|e| quoted(e.into())),
        }
    }

    /// The scalar polynomial over `S` (`"x*y"`).
    pub fn scalar<S: ExactScalar>(&self) -> Result<cagd_poly::Poly<S>, Read> {
        let text = quoted(&self.text);
        let quoted = |e: Message| Read::Quoted {
            text: text.clone(),
            error: e.into(),
        };
        match &self.letters {
            Some(ParamExpr::Scalar(p)) => p.try_map_coeffs(S::from_number).map_err(quoted),
            Some(ParamExpr::Vector(_)) => Err(Read::NotScalar { text }),
            None => self.expr.scalar::<S>().map_err(|e| quoted(e.into())),
        }
    }
}

/// A curve or surface as written: the keys of the three shapes; `P` is the type of its
/// control points ([`Points`] for a curve, [`MeshIn`] for a surface).
#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawShape<P> {
    bezier: Option<Control<P>>,
    bspline: Option<Control<P>>,
    degree: Option<Deferred>,
    knots: Option<Deferred>,
    weights: Option<Deferred>,
    expr: Option<ExprIn>,
    /// The letter of a generic polygon or mesh (`"c"`: points c_{0}, ..., c_{n} or c_{i,j}).
    generic: Option<String>,
    /// The dimension of a generic polygon or mesh: 1 (default, the point is the letter),
    /// 2 and 3 (the coordinates x_{i,j}, y_{i,j}, z_{i,j}), or `"xz"` (a profile of the XZ
    /// plane, (x_{i}, 0, z_{i}), for a surface of revolution).
    dim: Option<serde_json::Value>,
}

/// The control points of a shape (`bezier`, `bspline`). Read from a problem's text, they are
/// read where they stand, straight from the text (no copy of it, no second pass); given as a
/// JSON value, they are read once the shape's keys are known, with the path of an error.
enum Control<P> {
    Read(P),
    Later(Deferred),
}

impl<'de, P: Deserialize<'de>> Deserialize<'de> for Control<P> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        if FROM_TEXT.with(Cell::get) {
            P::deserialize(d).map(Control::Read)
        } else {
            Deferred::deserialize(d).map(Control::Later)
        }
    }
}

impl<P: serde::de::DeserializeOwned> Control<P> {
    /// The points, read (an error below `key`).
    fn points(self, key: &str) -> Result<P, Typed> {
        match self {
            Control::Read(p) => Ok(p),
            Control::Later(v) => member(key, &v),
        }
    }
}

impl<P> RawShape<P> {
    /// `Err` when points were read from the text that the shape does not use (a generic
    /// shape's, or `bspline` beside `bezier`): their numbers may have set the field. The
    /// problem is then read again as a value ([`crate::Problem::read_text`]), which reads
    /// only what is used.
    fn unused_points_read(&self) -> Result<(), Typed> {
        let read = |c: &Option<Control<P>>| matches!(c, Some(Control::Read(_)));
        if (self.generic.is_some() && (read(&self.bezier) || read(&self.bspline)))
            || (self.bezier.is_some() && read(&self.bspline))
        {
            return Err(Read::UnusedPoints.into());
        }
        Ok(())
    }
}

/// The largest degree of a generic polygon or mesh (its answers are general formulas: a
/// degree past this is no clearer and much slower).
pub const MAX_GENERIC_DEGREE: usize = 6;

/// The letter of a generic shape, or of its weights.
fn generic_letter(key: &str, letter: &str) -> Result<String, Typed> {
    let mut chars = letter.chars();
    match (chars.next(), chars.next()) {
        (Some(c), None) if c.is_alphabetic() => Ok(letter.to_string()),
        _ => Err(Typed::from(Read::GenericLetter {
            found: quoted(letter),
        })
        .below(key)),
    }
}

/// The symbolic number `letter_{indices}`, declared as a parameter of the problem being read
/// (so that `expected` and `values` may use it).
fn generic_number(letter: &str, indices: &[usize]) -> Number {
    let sub: Vec<String> = indices.iter().map(usize::to_string).collect();
    let name = Name::new(&format!("{letter}_{{{}}}", sub.join(",")));
    CONTEXT.with(|c| {
        if let Some(ctx) = c.borrow_mut().as_mut() {
            if !ctx.parameters.contains(&name) {
                ctx.parameters.push(name.clone());
            }
        }
    });
    Number::named(name)
}

fn generic_degree(degree: usize, key: &str) -> Result<usize, Typed> {
    if degree > MAX_GENERIC_DEGREE {
        return Err(Typed::from(Read::GenericDegree {
            max: MAX_GENERIC_DEGREE,
            found: degree,
        })
        .below(key));
    }
    Ok(degree)
}

/// The point of a generic shape at `indices`: `(c_{i,j})`, `(x_{i,j}, y_{i,j}, z_{i,j})`, or
/// `(x_{i}, 0, z_{i})` in the XZ plane (`dim` 0).
fn generic_point(letter: &str, dim: usize, indices: &[usize]) -> Point<Number> {
    match dim {
        0 => Point::new(vec![
            generic_number("x", indices),
            <Number as num_traits::Zero>::zero(),
            generic_number("z", indices),
        ]),
        2 | 3 => Point::new(
            ["x", "y", "z"]
                .iter()
                .take(dim)
                .map(|l| generic_number(l, indices))
                .collect(),
        ),
        _ => Point::new(vec![generic_number(letter, indices)]),
    }
}

/// The dimension of a generic shape (1, 2 or 3; 0 for `"xz"`).
fn generic_dim<P>(raw: &RawShape<P>) -> Result<usize, Typed> {
    match &raw.dim {
        None => Ok(1),
        Some(serde_json::Value::String(s)) if s == "xz" => Ok(0),
        Some(d) => match d.as_u64() {
            Some(d @ 1..=3) => Ok(usize::try_from(d).unwrap_or(1)),
            _ => Err(Typed::from(Read::GenericDim {
                found: d.to_string(),
            })
            .below("dim")),
        },
    }
}

/// The weights of a generic shape: a letter (`"w"`, the weights w_{i} or w_{i,j}) or numbers.
fn generic_weights<P>(raw: &RawShape<P>) -> Result<Option<String>, Typed> {
    match raw.weights.as_ref().map(Deferred::value) {
        Some(Some(serde_json::Value::String(w))) => generic_letter("weights", &w).map(Some),
        _ => Ok(None),
    }
}

thread_local! {
    /// Whether the problem being read on this thread is read from its text
    /// ([`crate::Problem::read_text`]): its shapes' members are then kept as text.
    static FROM_TEXT: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Runs `read` with the members of shapes kept as text (the problem is read from its text).
pub(crate) fn from_text<T>(read: impl FnOnce() -> T) -> T {
    let before = FROM_TEXT.with(|f| f.replace(true));
    let out = read();
    FROM_TEXT.with(|f| f.set(before));
    out
}

/// serde_json's name of a value kept as its text (`RawValue`).
const RAW_VALUE: &str = "$serde_json::private::RawValue";

/// A member of a shape, read once the shape's keys are known: as a JSON value, or, when the
/// problem is read from its text, as the text of that value (no value is built: a mesh's
/// numbers go from the text straight into its points).
#[derive(Debug, Clone, PartialEq)]
pub(crate) enum Deferred {
    Value(serde_json::Value),
    Text(String),
}

impl Deferred {
    /// The member as a JSON value (for the small members looked at before reading).
    fn value(&self) -> Option<serde_json::Value> {
        match self {
            Deferred::Value(v) => Some(v.clone()),
            Deferred::Text(t) => serde_json::from_str(t).ok(),
        }
    }
}

impl<'de> Deserialize<'de> for Deferred {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = Deferred;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a value")
            }
            fn visit_map<A: de::MapAccess<'de>>(self, mut map: A) -> Result<Deferred, A::Error> {
                // serde_json hands a raw value over as a map of one entry: its text
                let _ = map.next_key::<IgnoredAny>()?;
                map.next_value::<String>().map(Deferred::Text)
            }
        }
        if FROM_TEXT.with(std::cell::Cell::get) {
            d.deserialize_newtype_struct(RAW_VALUE, V)
        } else {
            serde_json::Value::deserialize(d).map(Deferred::Value)
        }
    }
}

/// Reads the member `key` of a shape, errors below it. Kept as text, the member is read
/// without tracking its path: an error there makes the problem be read again as a value
/// ([`crate::Problem::read_text`]), where it is named.
pub(crate) fn member<T: serde::de::DeserializeOwned>(key: &str, v: &Deferred) -> Result<T, Typed> {
    match v {
        Deferred::Value(v) => member_value(key, v),
        Deferred::Text(t) => {
            serde_json::from_str(t).map_err(|e| Typed::from_serde(e.to_string()).below(key))
        }
    }
}

/// Reads the member `key` of a shape given as a JSON value, errors below it.
pub(crate) fn member_value<T: serde::de::DeserializeOwned>(
    key: &str,
    v: &serde_json::Value,
) -> Result<T, Typed> {
    match serde_path_to_error::deserialize::<_, T>(v) {
        Ok(x) => Ok(x),
        Err(e) => {
            let path = e.path().to_string();
            let inner = e.into_inner().to_string();
            let sub = if path == "." || path.is_empty() {
                key.to_string()
            } else if path.starts_with('[') || key.is_empty() {
                format!("{key}{path}")
            } else {
                format!("{key}.{path}")
            };
            Err(Typed::from_serde(inner).below(&sub))
        }
    }
}

fn missing(key: &str) -> Typed {
    Typed::from(Read::Missing).below(key)
}

/// The degree of a Bézier curve (or of a patch in one direction) of `n` control points, n - 1,
/// within [`Limits::max_degree`]: the limit bounds a degree given by its points as it bounds
/// a `degree` written.
fn bezier_degree(points: usize, what: fn(usize, usize, usize) -> Read) -> Result<(), Typed> {
    let max = limits().max_degree;
    let degree = points.saturating_sub(1);
    if degree > max {
        return Err(Typed::from(what(points, degree, max)).below("bezier"));
    }
    Ok(())
}

fn weights_count(points: usize, w: &[Number]) -> Result<(), Typed> {
    if w.len() != points {
        return Err(Typed::from(Read::WeightsCount {
            weights: w.len(),
            points,
        })
        .below("weights"));
    }
    Ok(())
}

impl<'de> Deserialize<'de> for CurveIn<Number> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let raw = RawShape::deserialize(d)?;
        curve(raw).map_err(Typed::serde)
    }
}

fn numbers(key: &str, v: &Deferred) -> Result<Vec<Number>, Typed> {
    let List(xs) = member::<List<Num>>(key, v)?;
    Ok(xs.into_iter().map(|Num(x)| x).collect())
}

fn curve(mut raw: RawShape<Points>) -> Result<CurveIn<Number>, Typed> {
    raw.unused_points_read()?;
    if let Some(letter) = &raw.generic {
        let letter = generic_letter("generic", letter)?;
        let Degree(n) = member(
            "degree",
            raw.degree.as_ref().ok_or_else(|| missing("degree"))?,
        )?;
        let n = generic_degree(n, "degree")?;
        let dim = generic_dim(&raw)?;
        let points = (0..=n).map(|i| generic_point(&letter, dim, &[i])).collect();
        let weights = match (generic_weights(&raw)?, &raw.weights) {
            (Some(w), _) => Some((0..=n).map(|i| generic_number(&w, &[i])).collect()),
            (None, Some(w)) => Some(numbers("weights", w)?),
            (None, None) => None,
        };
        if let Some(w) = &weights {
            weights_count(n + 1, w)?;
        }
        return Ok(CurveIn::Bezier { points, weights });
    }
    if let Some(pts) = raw.bezier.take() {
        let Points(points) = pts.points("bezier")?;
        bezier_degree(points.len(), |points, degree, max| Read::CurveDegree {
            points,
            degree,
            max,
        })?;
        let weights = raw
            .weights
            .as_ref()
            .map(|w| numbers("weights", w))
            .transpose()?;
        if let Some(w) = &weights {
            weights_count(points.len(), w)?;
        }
        return Ok(CurveIn::Bezier { points, weights });
    }
    if let Some(pts) = raw.bspline.take() {
        let Points(points) = pts.points("bspline")?;
        let Degree(degree) = member(
            "degree",
            raw.degree.as_ref().ok_or_else(|| missing("degree"))?,
        )?;
        let knots = numbers("knots", raw.knots.as_ref().ok_or_else(|| missing("knots"))?)?;
        let weights = raw
            .weights
            .as_ref()
            .map(|w| numbers("weights", w))
            .transpose()?;
        if let Some(w) = &weights {
            weights_count(points.len(), w)?;
        }
        return Ok(CurveIn::BSpline {
            points,
            degree,
            knots,
            weights,
        });
    }
    if let Some(e) = raw.expr {
        return e.vector::<Number>().map(CurveIn::Expr).map_err(Typed::from);
    }
    Err(Read::NotCurve.into())
}

fn weights_shape(w: &Grid<Number>, mesh: &Mesh<Number>) -> Result<(), Typed> {
    if (w.rows(), w.cols()) != (mesh.rows(), mesh.cols()) {
        return Err(Typed::from(Read::WeightsGrid {
            rows: w.rows(),
            cols: w.cols(),
            mesh_rows: mesh.rows(),
            mesh_cols: mesh.cols(),
        })
        .below("weights"));
    }
    Ok(())
}

impl<'de> Deserialize<'de> for SurfaceIn<Number> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let raw = RawShape::deserialize(d)?;
        surface(raw).map_err(Typed::serde)
    }
}

/// Two degrees `[p, q]`, each within the degree limit.
struct DegreePair(usize, usize);

impl<'de> Deserialize<'de> for DegreePair {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = DegreePair;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("two degrees")
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<DegreePair, A::Error> {
                let n = seq.size_hint();
                let mut items = Vec::new();
                while let Some(Degree(x)) = seq.next_element()? {
                    items.push(x);
                    if items.len() > 2 {
                        break;
                    }
                }
                match items.as_slice() {
                    [a, b] => Ok(DegreePair(*a, *b)),
                    _ => Err(fail(Read::TwoIntegers {
                        found: n.unwrap_or(items.len()),
                    })),
                }
            }
            refuse_others!(Wanted::List);
            refuse_numbers!(Wanted::List);
        }
        d.deserialize_any(V)
    }
}

fn surface(mut raw: RawShape<MeshIn>) -> Result<SurfaceIn<Number>, Typed> {
    raw.unused_points_read()?;
    if let Some(letter) = &raw.generic {
        let letter = generic_letter("generic", letter)?;
        let DegreePair(m, n) = member(
            "degree",
            raw.degree.as_ref().ok_or_else(|| missing("degree"))?,
        )?;
        let (m, n) = (
            generic_degree(m, "degree[0]")?,
            generic_degree(n, "degree[1]")?,
        );
        let dim = generic_dim(&raw)?;
        let mesh = Grid::from_fn(m + 1, n + 1, |i, j| generic_point(&letter, dim, &[i, j]));
        let weights = match (generic_weights(&raw)?, &raw.weights) {
            (Some(w), _) => Some(Grid::from_fn(m + 1, n + 1, |i, j| {
                generic_number(&w, &[i, j])
            })),
            (None, Some(w)) => {
                let GridIn(g) = member("weights", w)?;
                weights_shape(&g, &mesh)?;
                Some(g)
            }
            (None, None) => None,
        };
        return Ok(SurfaceIn::Bezier { mesh, weights });
    }
    let weights = |mesh: &Mesh<Number>| -> Result<Option<Grid<Number>>, Typed> {
        let w = raw
            .weights
            .as_ref()
            .map(|w| member::<GridIn>("weights", w).map(|g| g.0))
            .transpose()?;
        if let Some(w) = &w {
            weights_shape(w, mesh)?;
        }
        Ok(w)
    };
    if let Some(m) = raw.bezier.take() {
        let MeshIn(mesh) = m.points("bezier")?;
        bezier_degree(mesh.rows(), |points, degree, max| Read::PatchDegreeU {
            points,
            degree,
            max,
        })?;
        bezier_degree(mesh.cols(), |points, degree, max| Read::PatchDegreeV {
            points,
            degree,
            max,
        })?;
        let weights = weights(&mesh)?;
        return Ok(SurfaceIn::Bezier { mesh, weights });
    }
    if let Some(m) = raw.bspline.take() {
        let MeshIn(mesh) = m.points("bspline")?;
        let DegreePair(p, q) = member(
            "degree",
            raw.degree.as_ref().ok_or_else(|| missing("degree"))?,
        )?;
        let knots = raw.knots.as_ref().ok_or_else(|| missing("knots"))?;
        let List(lists) = member::<List<Deferred>>("knots", knots)?;
        let (ku, kv) = match lists.as_slice() {
            [a, b] => (numbers("knots[0]", a)?, numbers("knots[1]", b)?),
            _ => {
                return Err(Typed::from(Read::TwoKnotVectors { found: lists.len() }).below("knots"))
            }
        };
        let weights = weights(&mesh)?;
        return Ok(SurfaceIn::BSpline {
            mesh,
            degree: (p, q),
            knots: (ku, kv),
            weights,
        });
    }
    if let Some(e) = raw.expr {
        return e
            .vector::<Number>()
            .map(SurfaceIn::Expr)
            .map_err(Typed::from);
    }
    Err(Read::NotSurface.into())
}

/// Data points: a grid (a list of rows of points, for a surface) or a list of points (for a
/// curve), told apart by their shape.
#[derive(Debug, Clone, PartialEq)]
pub enum PointData {
    /// Rows of points.
    Grid(MeshIn),
    /// Points.
    List(Points),
}

impl<'de> Deserialize<'de> for PointData {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let v = Deferred::deserialize(d)?;
        let grid = match &v {
            Deferred::Value(v) => v
                .as_array()
                .and_then(|rows| rows.first())
                .and_then(serde_json::Value::as_array)
                .and_then(|row| row.first())
                .is_some_and(serde_json::Value::is_array),
            // a list whose first item is a list whose first item is a list
            Deferred::Text(t) => ["[", "[", "["]
                .iter()
                .try_fold(t.as_str(), |rest, open| {
                    rest.trim_start().strip_prefix(open)
                })
                .is_some(),
        };
        if grid {
            member::<MeshIn>("", &v).map(PointData::Grid)
        } else {
            member::<Points>("", &v).map(PointData::List)
        }
        .map_err(Typed::serde)
    }
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

#[cfg(test)]
mod tests {
    use crate::{solve_with, Limit, Limits, ProblemError};
    use cagd_words::{english_in, Lang, Message as _};
    use serde_json::{json, Value};

    fn refused(p: &Value, limits: &Limits) -> ProblemError {
        solve_with(p, limits).unwrap_err()
    }

    fn point(y: Value) -> Value {
        json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, y]]}, "params": ["1/2"]})
    }

    /// The error in both languages: its field, its English, and its Spanish without an English
    /// word and without the marks the reading once carried in its text.
    fn said(e: &ProblemError) -> (String, String) {
        let en = e.message.phrase(Lang::En).text();
        let es = e.message.phrase(Lang::Es);
        assert_eq!(english_in(&es), Vec::<String>::new(), "{}", es.text());
        let text = e.to_string();
        assert!(!text.contains(['\u{1}', '\u{2}', '\u{3}']), "{text:?}");
        (en, es.text())
    }

    #[test]
    fn a_decimal_comma_is_told_how_to_write_it() {
        let e = refused(&point(json!("1,5")), &Limits::DEFAULT);
        assert_eq!(e.field, "curve.bezier[1][1]");
        assert_eq!(
            said(&e),
            (
                "\"1,5\": the decimal mark is a point: write 3/2 or 1.5".to_string(),
                "\"1,5\": la marca decimal es el punto: escriba 3/2 o 1.5".to_string()
            )
        );
        let e = refused(&point(json!("-0,25")), &Limits::DEFAULT);
        assert_eq!(
            e.message.to_string(),
            "\"-0,25\": the decimal mark is a point: write -1/4 or -0.25"
        );
        // two commas are no decimal: the grammar's error stands
        let e = refused(&point(json!("1,5,2")), &Limits::DEFAULT);
        assert!(e.message.to_string().starts_with("\"1,5,2\": at column 2"));
    }

    #[test]
    fn a_square_root_in_words_is_told_how_to_write_it() {
        for (text, fixed) in [
            ("raiz2", "sqrt2"),
            ("raíz2", "sqrt2"),
            ("Raiz(2)", "sqrt(2)"),
            ("3*raiz 5/2", "3*sqrt 5/2"),
            ("root2", "sqrt2"),
        ] {
            let e = refused(&point(json!(text)), &Limits::DEFAULT);
            assert_eq!(e.field, "curve.bezier[1][1]");
            let (en, es) = said(&e);
            assert_eq!(
                en,
                format!("\"{text}\": a square root is written √2 or sqrt(2): write \"{fixed}\"")
            );
            assert_eq!(
                es,
                format!(
                    "\"{text}\": una raíz cuadrada se escribe √2 o sqrt(2): escriba \"{fixed}\""
                )
            );
        }
        // a word that is no root: the grammar's error stands
        let e = refused(&point(json!("abc2")), &Limits::DEFAULT);
        assert!(e.message.to_string().starts_with("\"abc2\": at column 1"));
    }

    #[test]
    fn shapes_that_do_not_read_are_said_in_spanish() {
        let cases = [
            (point(json!(true)), "curve.bezier[1][1]", "expected a number, found true", "se esperaba un número, se encontró true"),
            (
                json!({"op": "evaluate", "curve": {"bezier": [[0, 0], {"x": 1}]}, "params": [0]}),
                "curve.bezier[1]",
                "expected a point [x, y, z], found an object",
                "se esperaba un punto [x, y, z], se encontró un objeto",
            ),
            (
                json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1]]}, "params": [0]}),
                "curve.bezier[1]",
                "this point has 1 coordinates but the first has 2",
                "este punto tiene 1 coordenadas, pero el primero tiene 2",
            ),
            (
                json!({"op": "evaluate", "curve": {"bezier": [[0, 0]], "weights": [1, 2]}, "params": [0]}),
                "curve.weights",
                "2 weights for 1 control points",
                "2 pesos para 1 puntos de control",
            ),
            (
                json!({"op": "evaluate", "curve": {"bspline": [[0, 0], [1, 1]], "knots": [0, 1]}, "params": [0]}),
                "curve.degree",
                "missing (this operation needs it)",
                "falta (esta operación lo necesita)",
            ),
            (
                json!({"op": "evaluate", "surface": {"bezier": [[[0, 0, 0]], [[1, 0, 0], [1, 1, 0]]]}, "params": [0, 0]}),
                "surface.bezier[1]",
                "row 1 has 2 points but row 0 has 1: a mesh needs rows of equal length",
                "la fila 1 tiene 2 puntos, pero la fila 0 tiene 1: las filas de una malla de control han de tener la misma longitud",
            ),
            (
                json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 1.5]]}, "params": [0]}),
                "curve.bezier[1][1]",
                "the number 1.5 has a fraction part; write it as a string (\"1.5\") so it is read exactly",
                "el número 1.5 tiene parte decimal; escríbalo como cadena (\"1.5\") para leerlo exactamente",
            ),
        ];
        for (p, field, en, es) in cases {
            let e = refused(&p, &Limits::DEFAULT);
            assert_eq!(e.field, field, "{p}");
            assert_eq!(said(&e), (en.to_string(), es.to_string()), "{p}");
            assert_eq!(e.limit, None);
        }
    }

    #[test]
    fn a_limit_is_carried_typed() {
        let tight = Limits {
            max_degree: 2,
            max_points: 4,
            max_digits: 10,
            ..Limits::default()
        };
        let cases = [
            (
                json!({"op": "evaluate", "curve": {"bezier": [[0], [1], [2], [3]]}, "params": [0]}),
                "curve.bezier",
                "4 control points make a Bézier curve of degree 3, above the limit of 2 for degrees",
                Limit::Degree,
            ),
            (
                json!({"op": "evaluate", "curve": {"bezier": [[0], [1], [2], [3], [4]]}, "params": [0]}),
                "curve.bezier",
                "a list of 5 items is longer than the limit of 4",
                Limit::Points,
            ),
            (
                point(json!("10^10")),
                "curve.bezier[1][1]",
                "\"10^10\": limit exceeded: a number of 11 digits is longer than the limit of 10 digits",
                Limit::Digits,
            ),
            (
                point(json!(123_456_789_012_i64)),
                "curve.bezier[1][1]",
                "a number of 12 digits is longer than the limit of 10 digits",
                Limit::Digits,
            ),
        ];
        for (p, field, en, limit) in cases {
            let e = refused(&p, &tight);
            assert_eq!(e.field, field, "{p}");
            assert_eq!(said(&e).0, en, "{p}");
            assert_eq!(e.limit, Some(limit), "{p}");
        }
    }

    #[test]
    fn a_second_root_names_the_first() {
        let p = json!({"op": "evaluate", "curve": {"bezier": [[0, "sqrt2"], [1, "sqrt3"]]}, "params": [0]});
        let e = refused(&p, &Limits::DEFAULT);
        assert_eq!(e.field, "curve.bezier[1][1]");
        assert_eq!(
            said(&e),
            (
                "this number needs √3, but curve.bezier[0][1] needs √2: a problem runs in one field a + b√d".to_string(),
                "este número necesita √3, pero curve.bezier[0][1] necesita √2: un problema se resuelve en un solo cuerpo a + b√d".to_string()
            )
        );
    }

    #[test]
    fn a_repeating_decimal_is_remarked_typed() {
        let a = solve_with(&point(json!("0.3333")), &Limits::DEFAULT).unwrap();
        let remark = a.remarks.first().unwrap();
        assert_eq!(
            remark.to_string(),
            "\"0.3333\" is read exactly as 3333/10000; if 1/3 is meant, write \"1/3\""
        );
        assert_eq!(
            remark.phrase(Lang::Es).text(),
            "\"0.3333\" se lee exactamente como 3333/10000; si se quiere decir 1/3, escriba \"1/3\""
        );
    }
}
