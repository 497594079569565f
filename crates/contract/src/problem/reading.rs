//! Reading a problem from JSON: the operation's arguments in one pass where it can, the fixture
//! block, the parameters and values, and the errors of serde turned into typed messages.

use super::meta::Meta;
use super::names::NAMES;
use super::op::{Op, Problem};
use crate::field::NumberField;
use crate::limits::Limits;
use crate::message::contract::Contract;
use crate::message::found::Found;
use crate::message::read::Read;
use crate::spec::{self};
use crate::value::Number;
use crate::ProblemError;
use cagd_param::Name;
use serde::de::{self, Deserializer, Visitor};
use serde::Deserialize;
use serde_json::value::RawValue;
use serde_json::Value;

/// The field names of a struct read with serde's derive (its `deserialize_struct` call).
fn struct_fields<'de, T: Deserialize<'de>>() -> &'static [&'static str] {
    struct Fields(&'static [&'static str]);
    #[derive(Debug)]
    struct Stop;
    impl std::fmt::Display for Stop {
        fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
            f.write_str("stop")
        }
    }
    impl std::error::Error for Stop {}
    impl de::Error for Stop {
        fn custom<T: std::fmt::Display>(_: T) -> Self {
            Stop
        }
    }
    struct Probe<'a>(&'a mut Fields);
    impl<'de> Deserializer<'de> for Probe<'_> {
        type Error = Stop;
        fn deserialize_any<V: Visitor<'de>>(self, _: V) -> Result<V::Value, Stop> {
            Err(Stop)
        }
        fn deserialize_struct<V: Visitor<'de>>(
            self,
            _: &'static str,
            fields: &'static [&'static str],
            _: V,
        ) -> Result<V::Value, Stop> {
            self.0 .0 = fields;
            Err(Stop)
        }
        serde::forward_to_deserialize_any! {
            bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string
            bytes byte_buf option unit unit_struct newtype_struct seq tuple
            tuple_struct map enum identifier ignored_any
        }
    }
    let mut fields = Fields(&[]);
    let _ = T::deserialize(Probe(&mut fields));
    fields.0
}

/// The key nearest to `key` among `keys`, when near enough to be a misspelling.
fn nearest<'a>(key: &str, keys: &[&'a str]) -> Option<&'a str> {
    keys.iter()
        .map(|k| (strsim::damerau_levenshtein(key, k), *k))
        .filter(|(d, k)| *d <= 2.max(k.len() / 3) && *d < k.len().max(key.len()))
        .min_by_key(|(d, _)| *d)
        .map(|(_, k)| k)
}

/// The names between backticks in a serde message (`unknown field `x`, expected one of `a`,
/// `b``): the first is the unknown name, the rest the valid ones.
fn backticked(message: &str) -> Vec<&str> {
    message.split('`').skip(1).step_by(2).collect()
}

/// Joins a path and a key: `c1` + `bezier[2]` = `c1.bezier[2]`.
fn join(path: &str, key: &str) -> String {
    match (path.is_empty(), key.starts_with('[')) {
        (true, _) => key.to_string(),
        (false, true) => format!("{path}{key}"),
        (false, false) => format!("{path}.{key}"),
    }
}

/// A leaf's error, typed, as the reading of the leaves hands it over: the keys below the value
/// that raised it, the message, and the limit it names.
type Leaf = (Vec<String>, crate::Message, Option<crate::Limit>);

/// A leaf reader (spec/, limits.rs, input.rs, triangle/, any.rs) stashes its typed error
/// in a thread-local and returns `de::Error::custom` of its English from its `Deserialize`;
/// given serde's text of that error, this takes the stashed error back ([`spec::take_typed`],
/// which checks the text is the stashed error's): `Some((keys below the value, message,
/// limit))`, `None` for serde's own words. The locating pass's stop is stashed too.
fn typed_leaf_error(serde_text: &str) -> Option<Leaf> {
    let t = spec::take_typed(serde_text)?;
    let below = if t.below.is_empty() {
        Vec::new()
    } else {
        vec![t.below]
    };
    Some((below, t.message, t.limit))
}

/// What serde said, read once.
enum Said {
    /// The key missing.
    Missing(String),
    /// An unknown key, and the keys its object takes.
    UnknownField { key: String, valid: Vec<String> },
    /// The locating pass stopped at the first number of the root it looks for.
    Located,
    /// A sentence, typed, and the limit it names.
    Typed(crate::Message, Option<crate::Limit>),
    /// A leaf's sentence not yet typed (its English, with its limit tag).
    Untyped(String),
}

/// Serde's words about a value, typed: THE one reader of serde's own messages (with
/// [`serde_error`], which reads a whole error). `text` is serde_json's message without its
/// place; the keys returned are those below the value that raised it (from the typed error a
/// reader stashed: [`typed_leaf_error`]).
fn said_by_serde(text: &str) -> (Vec<String>, Said) {
    use crate::message::contract::Expected;
    use crate::message::found::Found;
    if let Some((below, m, limit)) = typed_leaf_error(text) {
        if matches!(&m, crate::Message::Read(r) if **r == Read::Located) {
            return (below, Said::Located);
        }
        return (below, Said::Typed(m, limit));
    }
    let below = Vec::new();
    let message = text;
    let typed = |c: Contract| Said::Typed(c.into(), None);
    if let Some(rest) = message.strip_prefix("missing field `") {
        let key = rest.trim_end_matches('`');
        return (below, Said::Missing(key.to_string()));
    }
    if message.starts_with("unknown field `") {
        let names = backticked(message);
        let (key, valid) = names.split_first().map_or(("", &[][..]), |(k, v)| (*k, v));
        let valid = valid.iter().map(|k| k.to_string()).collect();
        let key = key.to_string();
        return (below, Said::UnknownField { key, valid });
    }
    if message.starts_with("unknown variant `") {
        let names = backticked(message);
        if let Some((found, valid)) = names.split_first() {
            let valid = valid.iter().map(|k| k.to_string()).collect();
            let found = found.to_string();
            return (below, typed(Contract::UnknownWord { valid, found }));
        }
    }
    if let Some(rest) = message.strip_prefix("invalid type: ") {
        if let Some((found, expected)) = rest.split_once(", expected ") {
            let number = |s: &str| Found::Number(s.trim_matches('`').to_string());
            let found = match found {
                "sequence" => Found::List,
                "map" => Found::Object,
                "unit value" => Found::Null,
                "boolean `true`" => Found::Bool(true),
                "boolean `false`" => Found::Bool(false),
                f => match (
                    f.strip_prefix("integer "),
                    f.strip_prefix("floating point "),
                    f.strip_prefix("string "),
                ) {
                    (Some(n), _, _) | (_, Some(n), _) => number(n),
                    (_, _, Some(s)) => Found::Str(s.to_string()),
                    _ => Found::Other(f.replace('`', "")),
                },
            };
            let expected = Expected::from_words(expected);
            return (below, typed(Contract::InvalidType { found, expected }));
        }
    }
    if let Some(rest) = message.strip_prefix("invalid value: ") {
        if let Some((found, expected)) = rest.split_once(", expected ") {
            let (found, expected) = (found.to_string(), expected.to_string());
            return (below, typed(Contract::InvalidValue { found, expected }));
        }
    }
    if let Some(rest) = message.strip_prefix("invalid length ") {
        if let Some((len, expected)) = rest.split_once(", expected ") {
            if let Ok(len) = len.parse() {
                let expected = expected.to_string();
                return (below, typed(Contract::InvalidLength { len, expected }));
            }
        }
    }
    if let Some(rest) = message.strip_prefix("duplicate field `") {
        let key = rest.trim_end_matches('`').to_string();
        return (below, typed(Contract::DuplicateKey { key }));
    }
    (below, Said::Untyped(message.to_string()))
}

/// A whole error of serde_json, typed: a text that is not JSON (its place, line and column,
/// when it has one), or what serde said about a value ([`said_by_serde`]). The one function,
/// with [`said_by_serde`], that reads serde's words; a front end that reads a problem's text
/// itself (the CLI's stream of problems) words its errors through it.
pub fn serde_error(e: &serde_json::Error) -> Contract {
    use crate::message::contract::Syntax;
    use serde_json::error::Category;
    let text = e.to_string();
    let place = format!(" at line {} column {}", e.line(), e.column());
    let bare = match e.line() {
        0 => text.as_str(),
        _ => text.strip_suffix(&place).unwrap_or(&text),
    };
    match e.classify() {
        Category::Syntax | Category::Eof | Category::Io => {
            let what = Syntax::WORDS
                .iter()
                .find(|(w, _)| *w == bare)
                .map_or_else(|| Syntax::Other(bare.to_string()), |(_, s)| s.clone());
            Contract::Syntax {
                what,
                line: e.line(),
                column: e.column(),
            }
        }
        Category::Data => match said_by_serde(bare) {
            (below, Said::Typed(crate::Message::Contract(c), None))
                if below.is_empty() && e.line() == 0 =>
            {
                *c
            }
            _ => Contract::Serde { text },
        },
    }
}

/// A reading error as a [`ProblemError`]: the path of the value at fault, what serde said
/// typed ([`said_by_serde`]); `Err` with the path of the number found by the locating pass.
fn reading_error(path: &str, e: &serde_json::Error, op: &str) -> Result<ProblemError, String> {
    let text = e.to_string();
    let (below, said) = said_by_serde(&text);
    let path = below.iter().fold(path.to_string(), |p, k| join(&p, k));
    Ok(match said {
        Said::Located => return Err(path),
        Said::Missing(key) => ProblemError::at(join(&path, &key), Contract::Missing),
        Said::UnknownField { key, valid } => {
            // the tracked path already ends with the unknown key
            let parent = path
                .strip_suffix(key.as_str())
                .map(|p| p.trim_end_matches('.'))
                .unwrap_or(&path)
                .to_string();
            let mut candidates: Vec<&str> = valid.iter().map(String::as_str).collect();
            if parent.is_empty() {
                // the fixture's fields are valid everywhere at the top
                candidates.extend_from_slice(struct_fields::<Meta>());
            }
            let nearest = nearest(&key, &candidates).map(str::to_string);
            let owner = if parent.is_empty() {
                op.to_string()
            } else {
                parent.clone()
            };
            ProblemError::at(
                join(&parent, &key),
                Contract::UnknownKey {
                    nearest,
                    owner,
                    valid,
                },
            )
        }
        Said::Typed(m, limit) => ProblemError {
            limit,
            ..ProblemError::at(path, m)
        },
        Said::Untyped(text) => ProblemError::at(path, Contract::Serde { text }),
    })
}

/// Reads `T` from `value` under the reading context, with the path of an error.
fn read_at<'de, D, T>(
    value: D,
    read: impl for<'b> FnOnce(
        serde_path_to_error::Deserializer<'static, 'b, D>,
    ) -> Result<T, serde_json::Error>,
) -> Result<T, (String, serde_json::Error)>
where
    D: Deserializer<'de, Error = serde_json::Error>,
{
    let mut track = serde_path_to_error::Track::new();
    let result = read(serde_path_to_error::Deserializer::new(value, &mut track));
    result.map_err(|e| {
        let path = track.path().to_string();
        let path = if path == "." { String::new() } else { path };
        (path, e)
    })
}

/// A root the operation itself needs: circles of quarter arcs (1 or 4) need √2/2 for their
/// weights; of 3 or 6 arcs, √3 (their control points lie on equilateral triangles).
fn needed_root(op: &str, args: &[(&str, &Value)]) -> Option<u64> {
    let get = |key: &str| args.iter().find(|(k, _)| *k == key).map(|(_, v)| *v);
    let arcs = get("arcs").and_then(|v| v.as_u64());
    if matches!(op, "revolution" | "circle") {
        if let Some(sweep) = get("sweep").and_then(angle_of) {
            let start = match get("start") {
                Some(v) => angle_of(v)?,
                None => cagd_scalar::BigRational::from_integer(0.into()),
            };
            let arcs = match arcs {
                Some(n) => usize::try_from(n).ok()?,
                None => cagd_bspline::default_arcs(&sweep),
            };
            return Some(cagd_bspline::root_of_angles(&start, &sweep, arcs).unwrap_or(2));
        }
    }
    match (op, arcs) {
        ("revolution" | "circle", Some(3 | 6)) => Some(3),
        ("revolution" | "circle", _) => Some(2),
        _ => None,
    }
}

/// An angle written as a JSON integer or a string "p" or "p/q" (degrees), before the reading.
fn angle_of(v: &Value) -> Option<cagd_scalar::BigRational> {
    use cagd_scalar::BigRational;
    if let Some(n) = v.as_i64() {
        return Some(BigRational::from_integer(n.into()));
    }
    let s = v.as_str()?.trim();
    let (p, q) = s.split_once('/').unwrap_or((s, "1"));
    let (p, q): (i64, i64) = (p.trim().parse().ok()?, q.trim().parse().ok()?);
    (q != 0).then(|| BigRational::new(p.into(), q.into()))
}

/// The top-level keys of a problem read from its text, each with the text of its value (not
/// yet read); `None` when the text is no object, or writes a key twice (the JSON value keeps
/// the last, where it first stood: that reading is [`Problem::read`]'s).
fn top_level(text: &str) -> Option<Vec<(std::borrow::Cow<'_, str>, &RawValue)>> {
    struct Entries<'a>(Vec<(std::borrow::Cow<'a, str>, &'a RawValue)>);
    impl<'de> Deserialize<'de> for Entries<'de> {
        fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
            struct V;
            impl<'de> Visitor<'de> for V {
                type Value = Entries<'de>;
                fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                    f.write_str("a problem object")
                }
                fn visit_map<A: de::MapAccess<'de>>(
                    self,
                    mut map: A,
                ) -> Result<Self::Value, A::Error> {
                    let mut out: Vec<(std::borrow::Cow<'de, str>, &'de RawValue)> = Vec::new();
                    while let Some(key) = map.next_key::<std::borrow::Cow<'de, str>>()? {
                        if out.iter().any(|(k, _)| *k == key) {
                            return Err(de::Error::custom("a key written twice"));
                        }
                        out.push((key, map.next_value()?));
                    }
                    Ok(Entries(out))
                }
            }
            d.deserialize_map(V)
        }
    }
    serde_json::from_str::<Entries<'_>>(text).ok().map(|e| e.0)
}

/// The reading of [`Problem::read_text_one_pass`]: the operation's name, then its arguments
/// read as they come, the fixture's keys kept as text and read at the end.
struct OnePass<'l> {
    limits: &'l Limits,
}

/// What [`OnePass`] reads: the operation, the fixture's block, the root met, the parameters
/// declared and the keys of the arguments in the order written.
type OnePassRead = (Op, Meta, Option<u64>, Vec<Name>, Vec<String>);

/// The error that gives a problem up to the two-pass reading (never shown).
const GIVE_UP: &str = "read in two passes";

impl<'de> Visitor<'de> for OnePass<'_> {
    type Value = OnePassRead;
    fn expecting(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("a problem object")
    }
    fn visit_map<A: de::MapAccess<'de>>(self, mut map: A) -> Result<OnePassRead, A::Error> {
        let give_up = || de::Error::custom(GIVE_UP);
        match map.next_key::<std::borrow::Cow<'de, str>>()? {
            Some(k) if k == "op" => {}
            _ => return Err(give_up()),
        }
        let name = map.next_value::<std::borrow::Cow<'de, str>>()?;
        let op = *NAMES.iter().find(|n| **n == name).ok_or_else(give_up)?;
        if matches!(op, "revolution" | "circle") {
            return Err(give_up());
        }
        let meta_keys = struct_fields::<Meta>();
        let mut meta_args: Vec<(std::borrow::Cow<'de, str>, &'de RawValue)> = Vec::new();
        let mut order: Vec<String> = Vec::new();
        let (result, root, declared) = spec::read_with(self.limits, &[], None, None, || {
            spec::from_text(|| {
                let rest = Arguments {
                    map: &mut map,
                    meta_keys,
                    meta: &mut meta_args,
                    order: &mut order,
                };
                Op::read(op, rest).unwrap_or_else(|| Err(give_up()))
            })
        });
        let op_value = result?;
        for (k, v) in &meta_args {
            // a value of any depth, which the whole problem's reading bounds
            if matches!(k.as_ref(), "expected" | "values")
                && nesting(v.get()) + 1 >= crate::field::MAX_NESTING
            {
                return Err(give_up());
            }
        }
        let meta_args: Vec<(&str, &RawValue)> =
            meta_args.iter().map(|(k, v)| (k.as_ref(), *v)).collect();
        let meta = Meta::deserialize(pairs(&meta_args)).map_err(|_| give_up())?;
        Ok((op_value, meta, root, declared, order))
    }
}

/// The keys of a problem after `op`, as the map of the operation's arguments: the fixture's
/// keys are set aside as text, the others handed to the operation's struct as they come.
struct Arguments<'a, 'de, A> {
    map: &'a mut A,
    meta_keys: &'static [&'static str],
    meta: &'a mut Vec<(std::borrow::Cow<'de, str>, &'de RawValue)>,
    order: &'a mut Vec<String>,
}

impl<'de, A: de::MapAccess<'de>> de::MapAccess<'de> for Arguments<'_, 'de, A> {
    type Error = A::Error;
    fn next_key_seed<K: de::DeserializeSeed<'de>>(
        &mut self,
        seed: K,
    ) -> Result<Option<K::Value>, A::Error> {
        loop {
            let Some(key) = self.map.next_key::<std::borrow::Cow<'de, str>>()? else {
                return Ok(None);
            };
            let k = key.as_ref();
            if matches!(k, "op" | "formula" | "parameters" | "functions")
                || self.meta.iter().any(|(m, _)| m == k)
            {
                // a key written twice, or one the arguments' reading depends on
                return Err(de::Error::custom(GIVE_UP));
            }
            if self.meta_keys.contains(&k) {
                let v: &'de RawValue = self.map.next_value()?;
                self.meta.push((key, v));
                continue;
            }
            self.order.push(k.to_string());
            return seed
                .deserialize(de::value::StrDeserializer::<A::Error>::new(k))
                .map(Some);
        }
    }
    fn next_value_seed<V: de::DeserializeSeed<'de>>(
        &mut self,
        seed: V,
    ) -> Result<V::Value, A::Error> {
        self.map.next_value_seed(seed)
    }
}

impl<'de, A: de::MapAccess<'de>> Deserializer<'de> for Arguments<'_, 'de, A> {
    type Error = A::Error;
    fn deserialize_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, A::Error> {
        visitor.visit_map(self)
    }
    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string
        bytes byte_buf option unit unit_struct newtype_struct seq tuple
        tuple_struct map struct enum identifier ignored_any
    }
}

/// The deepest nesting of lists and objects in a JSON text (brackets outside strings).
fn nesting(text: &str) -> usize {
    let (mut depth, mut deepest, mut in_string, mut escaped) = (0usize, 0usize, false, false);
    for b in text.bytes() {
        if in_string {
            match b {
                _ if escaped => escaped = false,
                b'\\' => escaped = true,
                b'"' => in_string = false,
                _ => {}
            }
            continue;
        }
        match b {
            b'"' => in_string = true,
            b'[' | b'{' => {
                depth += 1;
                deepest = deepest.max(depth);
            }
            b']' | b'}' => depth = depth.saturating_sub(1),
            _ => {}
        }
    }
    deepest
}

impl Problem {
    /// Reads a problem from its JSON text under `limits`, as [`Problem::read`] reads its JSON
    /// value, with the same answer and the same errors: `invalid` says what is wrong with a
    /// text that is not JSON.
    ///
    /// The text is read straight into the typed problem, without a JSON value in between and
    /// without tracking field paths; should that reading fail (a bad problem, or one of the
    /// rare texts it leaves to the value's reading: a key written twice, a `formula`, values
    /// nested near the limit), the problem is read again as a JSON value by
    /// [`Problem::read`], whose error names the field at fault.
    pub fn read_text(
        text: &str,
        limits: &Limits,
        invalid: impl FnOnce(serde_json::Error) -> ProblemError,
    ) -> Result<Problem, ProblemError> {
        if let Some(problem) = Problem::read_text_fast(text, limits) {
            return Ok(problem);
        }
        let value: Value = serde_json::from_str(text).map_err(invalid)?;
        Problem::read(&value, limits)
    }

    /// The reading of [`Problem::read_text`] without a JSON value; `None` where it leaves the
    /// problem to [`Problem::read`] (every error among them).
    fn read_text_fast(text: &str, limits: &Limits) -> Option<Problem> {
        spec::take_hints();
        spec::take_homogeneous();
        if let Some(problem) = Problem::read_text_one_pass(text, limits) {
            return Some(problem);
        }
        // the remarks of the pass given up are made again below
        spec::take_hints();
        spec::take_homogeneous();
        let entries = top_level(text)?;
        let (_, op) = entries.iter().find(|(k, _)| k == "op")?;
        let op: std::borrow::Cow<'_, str> = serde_json::from_str(op.get()).ok()?;
        let op = *NAMES.iter().find(|n| **n == op)?;
        let meta_keys = struct_fields::<Meta>();
        let mut meta_args: Vec<(&str, &RawValue)> = Vec::new();
        let mut args: Vec<(&str, &RawValue)> = Vec::new();
        for (k, v) in &entries {
            match k.as_ref() {
                "op" => {}
                // formulas are read through serde's untagged enums, which buffer numbers
                // differently from a value: left to the value's reading
                "formula" => return None,
                // a value of any depth, which the whole problem's reading bounds
                "expected" | "values" if nesting(v.get()) + 1 >= crate::field::MAX_NESTING => {
                    return None
                }
                k if meta_keys.contains(&k) => meta_args.push((k, v)),
                k => args.push((k, v)),
            }
        }
        let meta = Meta::deserialize(pairs(&meta_args)).ok()?;
        let mut parameters = read_parameters(&meta.parameters, "parameters").ok()?;
        if !meta.functions.is_empty() {
            if op != "revolution" {
                return None;
            }
            for f in read_parameters(&meta.functions, "functions").ok()? {
                if parameters.contains(&f) {
                    return None;
                }
                parameters.push(Name::function(f.as_str(), "u"));
            }
        }
        let needed = if matches!(op, "revolution" | "circle") {
            let angles: Vec<(&str, Value)> = args
                .iter()
                .filter(|(k, _)| matches!(*k, "arcs" | "sweep" | "start"))
                .map(|(k, v)| Some((*k, serde_json::from_str(v.get()).ok()?)))
                .collect::<Option<_>>()?;
            let angles: Vec<(&str, &Value)> = angles.iter().map(|(k, v)| (*k, v)).collect();
            needed_root(op, &angles)
        } else {
            None
        };
        let (result, root, declared) = spec::read_with(limits, &parameters, needed, None, || {
            spec::from_text(|| Op::read(op, pairs(&args)))
        });
        let op_value = result?.ok()?;
        let order = args.iter().map(|(k, _)| k.to_string()).collect();
        Problem::assemble(op_value, meta, root, declared, order).ok()
    }

    /// The reading of [`Problem::read_text_fast`] in one pass over the text, for a problem that
    /// names its operation first (`{"op": "closed_form", ...}`): each argument is read into the
    /// operation's struct where it stands, with no text kept for a second reading. `None`
    /// for every other problem (the key `op` later, `parameters`, `functions` or `formula`
    /// given, a circle or revolution, whose root is found from its arguments before they are
    /// read) and at any error: [`Problem::read_text_fast`] then reads it in two passes.
    fn read_text_one_pass(text: &str, limits: &Limits) -> Option<Problem> {
        let mut de = serde_json::Deserializer::from_str(text);
        let (op_value, meta, root, declared, order) =
            de.deserialize_map(OnePass { limits }).ok()?;
        de.end().ok()?;
        Problem::assemble(op_value, meta, root, declared, order).ok()
    }

    /// The problem of an operation read: its field from the root its numbers need and the
    /// letters declared, the values of `meta`, the remarks of the reading.
    fn assemble(
        op: Op,
        meta: Meta,
        root: Option<u64>,
        declared: Vec<Name>,
        order: Vec<String>,
    ) -> Result<Problem, ProblemError> {
        let values = read_values(&meta.values, &declared)?;
        Ok(Problem {
            op,
            meta,
            field: match (root, declared.is_empty()) {
                (None, true) => NumberField::Rational,
                (Some(d), true) => NumberField::Quadratic(d),
                (d, false) => NumberField::Letters(d.unwrap_or(0)),
            },
            order,
            parameters: declared,
            values,
            hints: spec::take_hints(),
            homogeneous: spec::take_homogeneous(),
        })
    }

    /// Reads a problem under `limits`: every number once, every key known.
    pub fn read(problem: &Value, limits: &Limits) -> Result<Problem, ProblemError> {
        // the remarks of an earlier reading on this thread are not this problem's
        spec::take_hints();
        spec::take_homogeneous();
        let Value::Object(map) = problem else {
            return Err(ProblemError::at(
                "",
                Contract::NotAProblem {
                    found: Found::of(problem),
                },
            ));
        };
        let op = match map.get("op") {
            None | Some(Value::Null) => {
                return Err(ProblemError::at("op", Contract::MissingOperation))
            }
            Some(Value::String(s)) => s.as_str(),
            Some(other) => {
                return Err(ProblemError::at(
                    "op",
                    Contract::OperationNotAString {
                        found: Found::of(other),
                    },
                ))
            }
        };
        if !NAMES.contains(&op) {
            return Err(ProblemError::at(
                "op",
                Contract::UnknownOperation {
                    found: op.to_string(),
                    nearest: nearest(op, NAMES).map(str::to_string),
                },
            ));
        }
        let meta_keys = struct_fields::<Meta>();
        let mut meta_args: Vec<(&str, &Value)> = Vec::new();
        let mut args: Vec<(&str, &Value)> = Vec::new();
        for (k, v) in map {
            if k == "op" {
                continue;
            }
            if meta_keys.contains(&k.as_str()) {
                meta_args.push((k.as_str(), v));
            } else {
                args.push((k.as_str(), v));
            }
        }
        let meta = read_at(pairs(&meta_args), |d| Meta::deserialize(d))
            .map_err(|(path, e)| reading_error(&path, &e, op).unwrap_or_else(located))?;
        let mut parameters = read_parameters(&meta.parameters, "parameters")?;
        if !meta.functions.is_empty() {
            if op != "revolution" {
                return Err(ProblemError::at(
                    "functions",
                    Contract::FunctionsOnlyInRevolution { op: op.to_string() },
                ));
            }
            for f in read_parameters(&meta.functions, "functions")? {
                if parameters.contains(&f) {
                    return Err(ProblemError::at(
                        "functions",
                        Contract::DeclaredBoth {
                            name: f.as_str().to_string(),
                        },
                    ));
                }
                parameters.push(Name::function(f.as_str(), "u"));
            }
        }
        let needed = needed_root(op, &args);
        let read_args = |locate: Option<u64>| {
            spec::read_with(limits, &parameters, needed, locate, || {
                read_at(pairs(&args), |d| {
                    Op::read(op, d).unwrap_or_else(|| Err(de::Error::custom("unknown operation")))
                })
            })
        };
        let (result, root, declared) = read_args(None);
        let op_value = match result {
            Ok(v) => v,
            Err((path, e)) => {
                let mut error = reading_error(&path, &e, op).unwrap_or_else(located);
                if let crate::Message::Read(r) = &mut error.message
                    && let Read::RootAgainstEarlier { needs, first } = **r
                {
                    // find where the first number of the other root is, to name it
                    if let (Err((at, e)), _, _) = read_args(Some(first)) {
                        if let Err(at) = reading_error(&at, &e, op) {
                            **r = Read::RootAgainstAt { needs, at, first };
                        }
                    }
                }
                return Err(error);
            }
        };
        let order = args.iter().map(|(k, _)| k.to_string()).collect();
        Problem::assemble(op_value, meta, root, declared, order)
    }

    /// The operation's name.
    pub fn op_name(&self) -> &'static str {
        self.op.name()
    }
}

/// The declared parameters: each one letter (the grammar reads a run of letters as a
/// product), possibly with a subscript as a generic mesh names its points (`c_{1,0}`), none
/// twice.
fn read_parameters(names: &[String], key: &str) -> Result<Vec<Name>, ProblemError> {
    let mut out: Vec<Name> = Vec::with_capacity(names.len());
    for (i, n) in names.iter().enumerate() {
        let mut chars = n.chars();
        let first = chars.next();
        let rest: String = chars.collect();
        let subscript = rest
            .strip_prefix("_{")
            .and_then(|r| r.strip_suffix('}'))
            .is_some_and(|r| !r.is_empty() && r.chars().all(|c| c.is_ascii_digit() || c == ','));
        let one_letter = first.is_some_and(char::is_alphabetic)
            && (rest.is_empty() || (subscript && key == "parameters"));
        if !one_letter {
            return Err(ProblemError::at(
                format!("{key}[{i}]"),
                Contract::NotOneLetter { found: n.clone() },
            ));
        }
        if out.iter().any(|m| m.as_str() == n) {
            return Err(ProblemError::at(
                format!("{key}[{i}]"),
                Contract::DeclaredTwice { name: n.clone() },
            ));
        }
        out.push(Name::new(n));
    }
    Ok(out)
}

/// The values of `values`: each key a declared parameter, each value an exact number (which
/// may itself use the parameters).
fn read_values(
    values: &serde_json::Map<String, Value>,
    parameters: &[Name],
) -> Result<Vec<(Name, Number)>, ProblemError> {
    values
        .iter()
        .map(|(k, v)| {
            let path = format!("values.{k}");
            let Some(name) = parameters.iter().find(|n| n.as_str() == k) else {
                return Err(ProblemError::at(
                    &path,
                    Contract::NotDeclared { name: k.clone() },
                ));
            };
            let spec::Num(x) = spec::read_value_typed(v, parameters).map_err(|t| ProblemError {
                limit: t.limit,
                ..ProblemError::at(&path, t.message)
            })?;
            Ok((name.clone(), x))
        })
        .collect()
}

/// The error of a reading stopped by the locating pass, outside it (never: only the locating
/// pass looks for a root's first number).
fn located(path: String) -> ProblemError {
    ProblemError::at(
        path,
        Contract::InternalError {
            what: "a number located outside the locating pass".into(),
        },
    )
}

/// A map deserializer over borrowed key-value pairs of the problem object: its values as JSON
/// values (`&Value`) or as their texts (`&RawValue`).
fn pairs<'a, V>(
    items: &'a [(&'a str, V)],
) -> de::value::MapDeserializer<'a, impl Iterator<Item = (&'a str, V)> + 'a, serde_json::Error>
where
    V: Copy + de::IntoDeserializer<'a, serde_json::Error> + 'a,
{
    de::value::MapDeserializer::new(items.iter().copied())
}
