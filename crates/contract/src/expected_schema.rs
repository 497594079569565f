//! The JSON Schema of a fixture's `expected` (an answer, numbers as in problems) and of any
//! value of an answer.

use crate::input::{CurveIn, SurfaceIn};
use crate::spec::Points;
use crate::value::exact::Number;
use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};
use serde_json::{json, Value};
use std::borrow::Cow;

/// The schema of `expected` (a fixture's answer): an object of answer values by result name,
/// in the shapes of the answers but with numbers as in problems (JSON integers or strings);
/// `steps` by step name.
pub(crate) struct Expected;

impl JsonSchema for Expected {
    fn schema_name() -> Cow<'static, str> {
        "Expected".into()
    }
    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        let value = generator.subschema_for::<AnyValue>();
        json_schema!({
            "description": "The exact answer by result name, in the shapes of the answers (docs/format.md, Answers), numbers as in problems; `steps` holds intermediate values by step name, or the list of `{\"name\", \"value\"}` an answer writes (compared whole); `remarks` and `derivation`, as an answer writes them, are read and not compared, so that an answer's `result` feeds back whole.",
            "type": "object",
            "properties": {
                "surface": generator.subschema_for::<SurfaceIn<Number>>(),
                "curve": generator.subschema_for::<CurveIn<Number>>(),
                "points": generator.subschema_for::<Points>(),
                "closed_form": {"type": "string"},
                "developable": {"type": "boolean"},
                "order": order(),
                "steps": {"anyOf": [
                    {"type": "object", "minProperties": 1, "additionalProperties": value.clone()},
                    {"type": "array", "items": {
                        "type": "object",
                        "properties": {"name": {"type": "string"}, "value": value.clone()},
                        "required": ["name", "value"],
                        "additionalProperties": false,
                    }},
                ]},
                "remarks": {"type": "array", "items": {"type": "string"}},
                "derivation": {"type": "array", "items": {"type": "object"}},
            },
            "additionalProperties": value,
        })
    }
}

/// The continuity order of an answer: an integer (-1: not even continuous) or `"infinite"`.
pub(crate) fn order() -> Value {
    json!({
        "description": "The highest order of continuity: an integer (-1 when not continuous), or \"infinite\".",
        "anyOf": [{"type": "integer", "minimum": -1}, {"const": "infinite"}],
    })
}

/// Any value of an answer: true or false, an integer, a string (a number, a closed form,
/// words), a list or an object of values. Never a JSON number with a fraction part, never
/// null.
struct AnyValue;

impl JsonSchema for AnyValue {
    fn schema_name() -> Cow<'static, str> {
        "Value".into()
    }
    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        let value = generator.subschema_for::<AnyValue>();
        json_schema!({
            "description": "A value of an answer: true or false, an integer, a string (a number, a closed form, words), or a list or an object of values.",
            "anyOf": [
                {"type": "boolean"},
                {"type": "integer"},
                {"type": "string"},
                {"type": "array", "items": value.clone()},
                {"type": "object", "additionalProperties": value},
            ],
        })
    }
}
