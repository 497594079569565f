//! Exact numbers (`Num`: a JSON integer or a string of the grammar) and non-negative integers
//! (`Int`, `Degree`).

use super::context::{expected, fail, hint_repeating, limits, note_root, Typed, CONTEXT, QUICK};
use super::refuse::list_of;
use crate::input::quoted;
use crate::limits::{read_number, Limits};
use crate::message::found::Found;
use crate::message::read::{Read, Wanted};
use crate::value::exact::Number;
use cagd_param::parse_param;
use cagd_scalar::{FieldOps, Print, Quadratic, ScalarError};
use serde::de::{self, Deserializer, SeqAccess, Visitor};
use serde::Deserialize;
use std::cell::Cell;
use std::fmt;

/// Reads a number of the grammar; in letters when the problem declares parameters (and the
/// text has a letter besides `sqrt`).
pub(super) fn read_text(text: &str) -> Result<Number, ScalarError> {
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
pub(super) fn number_error(text: &str, e: ScalarError) -> Typed {
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
pub(super) fn decimal_comma(text: &str) -> Option<(String, String)> {
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
pub(super) const ROOT_WORDS: [&str; 6] = ["raiz", "raíz", "root", "sqr", "rt", "rad"];

/// A text with a square root written as a word of [`ROOT_WORDS`] (`raiz2`, `raíz(2)`): the
/// text with `sqrt` in its place, when that reads.
pub(super) fn root_word(text: &str) -> Option<String> {
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

pub(super) fn note_number<E: de::Error>(d: u64) -> Result<(), E> {
    match d {
        0 => Ok(()),
        d => note_root(d),
    }
}

/// An exact number: a JSON integer (of any length), or a string of the grammar (`"5/6"`,
/// `"sqrt2/2"`). A JSON number with a fraction part is refused (a JSON writer may already
/// have rounded it; strings are the exact way), one whose value is an integer (`1.0`, `2e3`,
/// `-0`) is that integer.
#[derive(Debug, Clone, PartialEq)]
pub struct Num(pub Number);

pub(super) struct NumVisitor;

/// The key under which serde_json (`arbitrary_precision`) hands over a number as written,
/// when it is no machine integer and no float that prints back as written.
pub(super) const JSON_NUMBER: &str = "$serde_json::private::Number";

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
pub(super) struct JsonNumberKey(bool);

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

/// A non-negative integer as written (degrees, counts, orders): its limits are the
/// operation's to check, where it knows what the integer counts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Int(pub u64);

pub(super) struct IntVisitor;

pub(super) const NON_NEGATIVE: &str = "expected a non-negative integer";

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
