//! The visitors' refusals: every JSON kind a reader does not take, said with what it expected.

use crate::message::found::Found;
use serde::de::SeqAccess;

/// The kind of a list whose length is known (`a list of 3`).
pub(super) fn list_of<'de, A: SeqAccess<'de>>(seq: &A) -> Found {
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
