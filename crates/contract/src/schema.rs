//! JSON Schemas of problems and answers, generated from the types that read them, and kept in
//! `docs/` ([`PROBLEM_SCHEMA`], [`ANSWER_SCHEMA`]).
//!
//! The operations' structs, [`Meta`] and the words (`UorV`, `Blend`...) derive [`JsonSchema`];
//! the values read by hand in [`crate::spec`] (numbers, points, meshes, expressions, curves
//! and surfaces) have their schemas written here. [`problem_schema`] puts them together: one
//! object per operation, with its `op`, its keys and the fixture's keys, and no other key.
//! The answers are not read by a type: [`answer_schema`] describes what
//! [`crate::Answer::to_json`] and [`crate::error_json`] write, with the same shapes.
//!
//! The schemas describe the format of `docs/format.md`: the keys, and the shape of every
//! value (a misspelled key, a JSON number with a fraction part, a curve with the keys of two
//! shapes are refused). What the reading checks beyond shapes is not in them: the limits of
//! the run, the keys an operation needs, a mesh's rows of equal length, the count of weights,
//! the one square root of a problem. Where the reading is lenient beyond the format (`null`
//! for an absent key, the words `bilinear`, `cubic`, `spline`, the keys of a second shape in
//! a curve or surface), the schemas keep to the format.

use crate::expected_schema::order;
use crate::input::{CurveIn, SurfaceIn};
use crate::problem::{self, Meta, Param, NAMES};
use crate::spec::{
    Degree, ExprIn, GridIn, Int, List, MeshIn, Num, Orders, Pair, PointData, PointIn, Points,
};
use crate::value::Number;
use schemars::generate::SchemaSettings;
use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};
use serde_json::{json, Map, Value};
use std::borrow::Cow;

/// Where the problem schema is kept, from the root of the workspace.
pub const PROBLEM_SCHEMA: &str = "docs/problem.schema.json";

/// Where the answer schema is kept, from the root of the workspace.
pub const ANSWER_SCHEMA: &str = "docs/answer.schema.json";

/// The JSON Schema dialect of both schemas.
const DIALECT: &str = "https://json-schema.org/draft/2020-12/schema";

/// The characters of the number grammar (`docs/format.md`, Numbers): digits, the decimal
/// point, signs and operators (with `−`, `·`, `×`), parentheses, `sqrt` and `√`, and the
/// letters of the parameters a problem declares (`"R"`, `"(2a + c)/3"`: the reading refuses an
/// undeclared one, which a schema cannot know).
const NUMBER_PATTERN: &str = r"^(?:[0-9.\s+*/^()√·×−A-Za-z_{},-]|sqrt)+$";

/// The characters of the expression grammar: those of numbers, the comma of tuples, and the
/// variables `u, v, w, t, s, x, y, z`, and the letters of declared parameters and functions.
const EXPRESSION_PATTERN: &str = r"^(?:[0-9.\s+*/^(),√·×−A-Za-z_{}-]|sqrt)+$";

/// Both schema files: the path from the root of the workspace, and the text (pretty JSON with
/// a final newline), as `cargo run -p cagd-problem --example schema` writes them.
pub fn schema_files() -> Vec<(&'static str, String)> {
    vec![
        (PROBLEM_SCHEMA, text(&problem_schema())),
        (ANSWER_SCHEMA, text(&answer_schema())),
    ]
}

fn text(schema: &Value) -> String {
    serde_json::to_string_pretty(schema).unwrap_or_default() + "\n"
}

/// The schema of a problem, or of a batch (a list of problems): one of the operations, each
/// an object with its `op`, its arguments and the fixture's keys (`name`, `title`, `source`,
/// `equation`, `note`, `expected`, `errata`), and no other key.
pub fn problem_schema() -> Value {
    let mut generator = SchemaSettings::draft2020_12().into_generator();
    let meta = Meta::json_schema(&mut generator);
    let mut defs = Map::new();
    let mut operations = Vec::new();
    for (name, args) in problem::argument_schemas(&mut generator) {
        let mut properties = Map::new();
        properties.insert(
            "op".into(),
            json!({"description": "The operation.", "const": name}),
        );
        properties.extend(members(&args, "properties"));
        properties.extend(members(&meta, "properties"));
        let mut required = vec![Value::from("op")];
        for schema in [&args, &meta] {
            if let Some(Value::Array(keys)) = schema.get("required") {
                required.extend(keys.iter().cloned());
            }
        }
        let mut op = Map::new();
        op.insert("title".into(), Value::from(name));
        if let Some(d) = args.get("description") {
            op.insert("description".into(), d.clone());
        }
        op.insert("type".into(), Value::from("object"));
        op.insert("properties".into(), Value::Object(properties));
        op.insert("required".into(), Value::Array(required));
        op.insert("additionalProperties".into(), Value::Bool(false));
        defs.insert(name.to_string(), Value::Object(op));
        operations.push(json!({"$ref": format!("#/$defs/{name}")}));
    }
    let mut all = Map::new();
    all.insert(
        "problem".into(),
        json!({
            "description": "A problem: {\"op\": NAME, ...arguments}, with the fixture's keys if it has them.",
            "oneOf": operations,
        }),
    );
    all.extend(defs);
    all.extend(generator.take_definitions(true));
    let mut schema = json!({
        "$schema": DIALECT,
        "title": "cagd-exact problems",
        "description": "A problem of cagd solve (docs/format.md, Problems), or a batch: a list of problems.",
        "oneOf": [
            {"$ref": "#/$defs/problem"},
            {"type": "array", "items": {"$ref": "#/$defs/problem"}},
        ],
        "$defs": all,
    });
    no_null(&mut schema);
    schema
}

/// The members of the object `key` of a schema (its `properties`).
fn members(schema: &Schema, key: &str) -> Map<String, Value> {
    schema
        .get(key)
        .and_then(Value::as_object)
        .cloned()
        .unwrap_or_default()
}

/// Removes `null` from the types a schema allows: schemars lets an `Option` be null, which the
/// format does not write (an absent key is absent).
fn no_null(schema: &mut Value) {
    fn is_null(s: &Value) -> bool {
        s.get("type").is_some_and(|t| t == "null")
    }
    match schema {
        Value::Object(map) => {
            if let Some(Value::Array(types)) = map.get_mut("type") {
                types.retain(|t| t != "null");
                if let [only] = types.as_slice() {
                    let only = only.clone();
                    map.insert("type".into(), only);
                }
            }
            let alternatives = match map.get("anyOf") {
                Some(Value::Array(xs)) if xs.iter().any(is_null) => Some(xs.clone()),
                _ => None,
            };
            if let Some(xs) = alternatives {
                map.remove("anyOf");
                let mut rest: Vec<Value> = xs.into_iter().filter(|x| !is_null(x)).collect();
                match (rest.pop(), rest.is_empty()) {
                    (Some(Value::Object(only)), true) => {
                        // the one alternative left, then what the schema said besides
                        let mut merged = only;
                        for (k, v) in std::mem::take(map) {
                            merged.entry(k).or_insert(v);
                        }
                        *map = merged;
                    }
                    (Some(last), _) => {
                        rest.push(last);
                        map.insert("anyOf".into(), Value::Array(rest));
                    }
                    (None, _) => {}
                }
            }
            for v in map.values_mut() {
                no_null(v);
            }
        }
        Value::Array(xs) => xs.iter_mut().for_each(no_null),
        _ => {}
    }
}

impl JsonSchema for Num {
    fn schema_name() -> Cow<'static, str> {
        "Number".into()
    }
    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        json_schema!({
            "description": "An exact number: a JSON integer, or a string of the number grammar (\"5/6\", \"0.25\", \"sqrt2/2\", \"1/2 + 3√2/4\"). A JSON number with a fraction part (0.5) is refused: write \"0.5\".",
            "type": ["integer", "string"],
            "pattern": NUMBER_PATTERN,
        })
    }
}

impl JsonSchema for Int {
    fn schema_name() -> Cow<'static, str> {
        "Integer".into()
    }
    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        json_schema!({
            "description": "A non-negative integer.",
            "type": "integer",
            "minimum": 0,
        })
    }
}

impl JsonSchema for Degree {
    fn schema_name() -> Cow<'static, str> {
        "Degree".into()
    }
    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        json_schema!({
            "description": "A degree: a non-negative integer (at most 50 unless --max-degree raises it).",
            "type": "integer",
            "minimum": 0,
        })
    }
}

impl<T: JsonSchema> JsonSchema for List<T> {
    fn inline_schema() -> bool {
        true
    }
    fn schema_name() -> Cow<'static, str> {
        format!("List_of_{}", T::schema_name()).into()
    }
    fn schema_id() -> Cow<'static, str> {
        format!("List<{}>", T::schema_id()).into()
    }
    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        json_schema!({
            "type": "array",
            "items": generator.subschema_for::<T>(),
        })
    }
}

impl JsonSchema for Pair {
    fn schema_name() -> Cow<'static, str> {
        "Pair".into()
    }
    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        json_schema!({
            "description": "Two numbers [a, b].",
            "type": "array",
            "items": generator.subschema_for::<Num>(),
            "minItems": 2,
            "maxItems": 2,
        })
    }
}

impl JsonSchema for Orders {
    fn schema_name() -> Cow<'static, str> {
        "Orders".into()
    }
    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        let int = generator.subschema_for::<Int>();
        json_schema!({
            "description": "r for a curve, [r, s] for a surface.",
            "oneOf": [
                int.clone(),
                {"type": "array", "items": int, "minItems": 2, "maxItems": 2},
            ],
        })
    }
}

impl JsonSchema for Param {
    fn schema_name() -> Cow<'static, str> {
        "Param".into()
    }
    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        let num = generator.subschema_for::<Num>();
        json_schema!({
            "description": "A parameter: t for a curve, [u, v] for a surface; for a triangular patch [u, v] or barycentric [r, s, t].",
            "oneOf": [
                num.clone(),
                {"type": "array", "items": num, "minItems": 2, "maxItems": 3},
            ],
        })
    }
}

impl JsonSchema for PointIn {
    fn schema_name() -> Cow<'static, str> {
        "Point".into()
    }
    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        point(generator.subschema_for::<Num>().to_value()).into_schema()
    }
}

impl JsonSchema for Points {
    fn schema_name() -> Cow<'static, str> {
        "Points".into()
    }
    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        points(generator.subschema_for::<PointIn>().to_value()).into_schema()
    }
}

impl JsonSchema for MeshIn {
    fn schema_name() -> Cow<'static, str> {
        "Mesh".into()
    }
    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        mesh(generator.subschema_for::<Points>().to_value()).into_schema()
    }
}

impl JsonSchema for GridIn {
    fn schema_name() -> Cow<'static, str> {
        "Grid".into()
    }
    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        grid(generator.subschema_for::<Num>().to_value()).into_schema()
    }
}

impl JsonSchema for ExprIn {
    fn schema_name() -> Cow<'static, str> {
        "Expression".into()
    }
    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        expression().into_schema()
    }
}

impl JsonSchema for PointData {
    fn schema_name() -> Cow<'static, str> {
        "PointData".into()
    }
    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        json_schema!({
            "description": "Data points: a grid (rows of points, for a surface) or a list of points (for a curve).",
            "oneOf": [
                generator.subschema_for::<MeshIn>(),
                generator.subschema_for::<Points>(),
            ],
        })
    }
}

impl JsonSchema for crate::triangle::TriangleIn {
    fn schema_name() -> Cow<'static, str> {
        "Triangle".into()
    }
    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        let points = generator.subschema_for::<Points>().to_value();
        let number = generator.subschema_for::<Num>().to_value();
        triangle(points, number).into_schema()
    }
}

/// A triangular Bézier patch: its rows of control points (and of weights, for a rational one).
fn triangle(points: Value, number: Value) -> Value {
    json!({
        "description": "A triangular Bézier patch of degree n: {\"triangle\": [[b_{n,0,0}], [b_{n-1,1,0}, b_{n-1,0,1}], ..., [b_{0,n,0}, ..., b_{0,0,n}]]}, row m holding the m + 1 points b_{n-m,m-k,k}, k = 0, ..., m.",
        "type": "object",
        "properties": {
            "triangle": {"type": "array", "items": points, "minItems": 1},
            "weights": {
                "description": "The weights w_{ijk} of a rational triangular patch, in the rows of the net.",
                "type": "array",
                "items": {"type": "array", "items": number, "minItems": 1},
                "minItems": 1,
            },
        },
        "required": ["triangle"],
        "additionalProperties": false,
    })
}

impl JsonSchema for CurveIn<Number> {
    fn schema_name() -> Cow<'static, str> {
        "Curve".into()
    }
    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        curve(&Shapes::of(generator)).into_schema()
    }
}

impl JsonSchema for SurfaceIn<Number> {
    fn schema_name() -> Cow<'static, str> {
        "Surface".into()
    }
    fn json_schema(generator: &mut SchemaGenerator) -> Schema {
        surface(&Shapes::of(generator)).into_schema()
    }
}

/// The schemas the shapes of curves and surfaces are made of: references to definitions.
struct Shapes {
    number: Value,
    points: Value,
    mesh: Value,
    grid: Value,
    degree: Value,
    expression: Value,
}

impl Shapes {
    /// In a problem: the definitions of the types that read them.
    fn of(generator: &mut SchemaGenerator) -> Shapes {
        Shapes {
            number: generator.subschema_for::<Num>().to_value(),
            points: generator.subschema_for::<Points>().to_value(),
            mesh: generator.subschema_for::<MeshIn>().to_value(),
            grid: generator.subschema_for::<GridIn>().to_value(),
            degree: generator.subschema_for::<Degree>().to_value(),
            expression: generator.subschema_for::<ExprIn>().to_value(),
        }
    }

    /// In an answer: the definitions of [`answer_schema`].
    fn answer() -> Shapes {
        let def = |name: &str| json!({"$ref": format!("#/$defs/{name}")});
        Shapes {
            number: def("Number"),
            points: def("Points"),
            mesh: def("Mesh"),
            grid: def("Grid"),
            degree: def("Degree"),
            expression: def("Expression"),
        }
    }
}

/// A value as a schema (every value built here is an object).
trait IntoSchema {
    fn into_schema(self) -> Schema;
}

impl IntoSchema for Value {
    fn into_schema(self) -> Schema {
        Schema::try_from(self).unwrap_or_default()
    }
}

fn point(number: Value) -> Value {
    json!({
        "description": "A point [x, y, z] (any dimension, the same within a curve or mesh).",
        "type": "array",
        "items": number,
        "minItems": 1,
    })
}

fn points(point: Value) -> Value {
    json!({
        "description": "A non-empty list of points of one dimension.",
        "type": "array",
        "items": point,
        "minItems": 1,
    })
}

fn mesh(points: Value) -> Value {
    json!({
        "description": "A mesh: a non-empty list of rows of points (outer index i along u, inner j along v, as the notes' c_ij), the rows of equal length.",
        "type": "array",
        "items": points,
        "minItems": 1,
    })
}

fn grid(number: Value) -> Value {
    json!({
        "description": "Rows of numbers (the weights of a surface), in the shape of its mesh.",
        "type": "array",
        "items": {"type": "array", "items": number, "minItems": 1},
        "minItems": 1,
    })
}

fn expression() -> Value {
    json!({
        "description": "An expression of the grammar (docs/format.md, Expressions) in the variables u, v, w, t, s, x, y, z: \"(u, 0, u^2)\", \"x*y\".",
        "type": "string",
        "pattern": EXPRESSION_PATTERN,
    })
}

/// The flag of control points written homogeneous, `(w x, w y, w z, w)`.
fn homogeneous() -> Value {
    json!({"description": "The control points are homogeneous, (w x, w y, w z, w): the weights are their last coordinates (0: the control vector of the others); no \"weights\" beside.", "type": "boolean"})
}

/// The letter of a generic polygon or mesh.
fn generic_letter() -> Value {
    json!({"type": "string", "pattern": "^[A-Za-z]$"})
}

/// The dimension of a generic polygon or mesh.
fn generic_dim() -> Value {
    json!({"description": "1 (the points are letters c_{i,j}), 2 or 3 (coordinates x_{i,j}, y_{i,j}, z_{i,j}), or \"xz\" (a profile (x_{i}, 0, z_{i}) of the XZ plane).", "oneOf": [{"type": "integer", "minimum": 1, "maximum": 3}, {"const": "xz"}]})
}

/// The three shapes of a curve.
fn curve(s: &Shapes) -> Value {
    let numbers = json!({"type": "array", "items": s.number});
    json!({
        "description": "A curve: {\"bezier\": [point, ...]} (with \"weights\": a rational curve), {\"bspline\": [point, ...], \"degree\": p, \"knots\": [...]} (with \"weights\": a NURBS), or {\"expr\": \"(u, 0, u^2)\"}.",
        "oneOf": [
            {
                "title": "Bézier curve",
                "type": "object",
                "properties": {
                    "bezier": s.points,
                    "weights": numbers,
                    "homogeneous": homogeneous(),
                },
                "required": ["bezier"],
                "additionalProperties": false,
            },
            {
                "title": "B-spline curve",
                "type": "object",
                "properties": {
                    "bspline": s.points,
                    "degree": s.degree,
                    "knots": {
                        "description": "The knots, in the notes' convention (n + p - 1 for n control points) or The NURBS Book's (n + p + 1).",
                        "type": "array",
                        "items": s.number,
                    },
                    "weights": numbers,
                    "homogeneous": homogeneous(),
                },
                "required": ["bspline", "degree", "knots"],
                "additionalProperties": false,
            },
            {
                "title": "Polynomial curve",
                "type": "object",
                "properties": {"expr": s.expression},
                "required": ["expr"],
                "additionalProperties": false,
            },
            {
                "title": "Generic Bézier curve",
                "description": "The polygon c_{0}, ..., c_{n} of one-dimensional points in letters (the answer is the general formula), with weights w_{i} when \"weights\" is a letter.",
                "type": "object",
                "properties": {
                    "generic": generic_letter(),
                    "dim": generic_dim(),
                    "degree": s.degree,
                    "weights": {"oneOf": [generic_letter(), numbers]},
                },
                "required": ["generic", "degree"],
                "additionalProperties": false,
            },
        ],
    })
}

/// The three shapes of a surface.
fn surface(s: &Shapes) -> Value {
    let knots = json!({"type": "array", "items": s.number});
    json!({
        "description": "A surface: {\"bezier\": [[point, ...], ...]} (with \"weights\" of the same shape: rational), {\"bspline\": [[point, ...], ...], \"degree\": [p, q], \"knots\": [[u knots], [v knots]]} (with \"weights\": NURBS), or {\"expr\": \"(u, v, u v)\"}.",
        "oneOf": [
            {
                "title": "Bézier surface",
                "type": "object",
                "properties": {
                    "bezier": s.mesh,
                    "weights": s.grid,
                    "homogeneous": homogeneous(),
                },
                "required": ["bezier"],
                "additionalProperties": false,
            },
            {
                "title": "B-spline surface",
                "type": "object",
                "properties": {
                    "bspline": s.mesh,
                    "degree": {
                        "description": "The degrees [p, q] in u and v.",
                        "type": "array",
                        "items": s.degree,
                        "minItems": 2,
                        "maxItems": 2,
                    },
                    "knots": {
                        "description": "The knots in u and in v: [[u knots], [v knots]].",
                        "type": "array",
                        "items": knots,
                        "minItems": 2,
                        "maxItems": 2,
                    },
                    "weights": s.grid,
                    "homogeneous": homogeneous(),
                },
                "required": ["bspline", "degree", "knots"],
                "additionalProperties": false,
            },
            {
                "title": "Polynomial surface",
                "type": "object",
                "properties": {"expr": s.expression},
                "required": ["expr"],
                "additionalProperties": false,
            },
            {
                "title": "Generic Bézier surface",
                "description": "The mesh c_{i,j} of one-dimensional points in letters (the answer is the general formula), with weights w_{i,j} when \"weights\" is a letter.",
                "type": "object",
                "properties": {
                    "generic": generic_letter(),
                    "dim": generic_dim(),
                    "degree": {
                        "description": "The bidegree [m, n].",
                        "type": "array",
                        "items": s.degree,
                        "minItems": 2,
                        "maxItems": 2,
                    },
                    "weights": {"oneOf": [generic_letter(), s.grid]},
                },
                "required": ["generic", "degree"],
                "additionalProperties": false,
            },
        ],
    })
}

/// The schema of an answer, or of a list of answers: `{"ok": true, "op", "result"}` (with
/// `passed` and `mismatches` when `cagd solve` checked an `expected`; with `name` in a key
/// of `cagd generate`; with the `assessment` of the answer written, and its `student`, `file`
/// and `problem`, from `cagd check`) or `{"ok": false, "error"}`. In answers every number is a string.
pub fn answer_schema() -> Value {
    let def = |name: &str| json!({"$ref": format!("#/$defs/{name}")});
    let shapes = Shapes::answer();
    json!({
        "$schema": DIALECT,
        "title": "cagd-exact answers",
        "description": "The answer to a problem of cagd solve --format json (docs/format.md, Answers), or a list of answers.",
        "oneOf": [
            def("answer"),
            {"type": "array", "items": def("answer")},
        ],
        "$defs": {
            "answer": {
                "description": "An answer: solved, or an error.",
                "oneOf": [def("solved"), def("failed")],
            },
            "solved": {
                "title": "solved",
                "type": "object",
                "properties": {
                    "ok": {"const": true},
                    "op": {"description": "The operation.", "enum": NAMES},
                    "result": def("result"),
                    "passed": {
                        "description": "Whether the result equals the problem's `expected` (cagd solve, when the problem has one).",
                        "type": "boolean",
                    },
                    "mismatches": {
                        "description": "Where the result differs from `expected`.",
                        "type": "array",
                        "items": {"type": "string"},
                    },
                    "name": {
                        "description": "The problem's name (in key.json of cagd generate).",
                        "type": "string",
                    },
                    "parameters": {
                        "description": "The letters of an answer in letters (so that it feeds back as a problem).",
                        "type": "array",
                        "items": {"type": "string"},
                    },
                    "assessment": def("assessment"),
                    "student": def("student"),
                    "file": def("file"),
                    "problem": def("problem"),
                },
                "required": ["ok", "op", "result"],
                "additionalProperties": false,
            },
            "failed": {
                "title": "failed",
                "type": "object",
                "properties": {
                    "ok": {"const": false},
                    "error": {
                        "description": "What is wrong, with the problem's index and the field: \"problem 3: field `c1.bezier[2]`: ...\".",
                        "type": "string",
                    },
                    "name": {
                        "description": "The problem's name (in key.json of cagd generate).",
                        "type": "string",
                    },
                    "student": def("student"),
                    "file": def("file"),
                    "problem": def("problem"),
                },
                "required": ["ok", "error"],
                "additionalProperties": false,
            },
            "result": {
                "description": "The results by name; numbers are strings of the number grammar.",
                "type": "object",
                "properties": {
                    "surface": def("Surface"),
                    "curve": def("Curve"),
                    "triangle": def("Triangle"),
                    "points": def("Points"),
                    "closed_form": {
                        "description": "The parametrization in the printer form; a rational one as \"(numerator)/(denominator)\".",
                        "type": "string",
                    },
                    "developable": {"type": "boolean"},
                    "polynomial": {"type": "string"},
                    "order": order(),
                    "remarks": {
                        "description": "Words about what was done.",
                        "type": "array",
                        "items": {"type": "string"},
                    },
                    "steps": {
                        "description": "With --steps: the intermediate values the notes show.",
                        "type": "array",
                        "items": {
                            "type": "object",
                            "properties": {
                                "name": {"type": "string"},
                                "value": def("Value"),
                            },
                            "required": ["name", "value"],
                            "additionalProperties": false,
                        },
                    },
                    "derivation": {
                        "description": "With --steps: the worked solution, step by step, as the answer keys write it: a `formula` (its name and the notes' `equation` {chapter, number}), a `value` (`symbol`, `value`), a `combination` (`symbol`, `terms` as [coefficient, symbol, value], `value`), a `table` (`title`, `table`: `columns` and `rows` of [label, cells], an empty cell null) a `fact` (its name in `fact`, and its values), a `matrix` too big to print whole (`symbol`, its size `rows` x `cols`, what its `entries` are, and its `first_rows`), a `product` (`symbol`, `factors` as [symbol, value], `value`) or an `identity` (`symbol` = `equals`, a general formula in the notes' factored form). Symbols are in a LaTeX-like notation (`c_{1,2}^{1,0}`, `\\alpha_{3}`).",
                        "type": "array",
                        "items": {
                            "type": "object",
                            "properties": {
                                "kind": {"enum": ["formula", "value", "combination", "table", "fact", "matrix", "product", "identity"]},
                            },
                            "required": ["kind"],
                        },
                    },
                },
                "additionalProperties": def("Value"),
            },
            "assessment": {
                "description": "The diagnosis of the answer written under `expected` (cagd check; docs/format.md, Checking a student's answer): each result and step written, marked entry by entry, scored, and the common mistakes that explain it.",
                "type": "object",
                "properties": {
                    "correct": {"description": "Whether every result and step written is right.", "type": "boolean"},
                    "right": {"description": "How many entries of the results are right.", "type": "integer", "minimum": 0},
                    "entries": {"description": "How many entries the results have.", "type": "integer", "minimum": 0},
                    "score": def("Score"),
                    "results": {"type": "array", "items": def("assessed")},
                    "steps": {"description": "The steps written (c_c, c_d, c_cd; the De Casteljau levels...), in the key's order.", "type": "array", "items": def("assessed")},
                    "first_departure": {"description": "The first step, in the key's order, where the written values leave the key's.", "type": "string"},
                    "student": {"description": "The problem's `student`.", "type": "string"},
                },
                "required": ["correct", "right", "entries", "score", "results"],
                "additionalProperties": false,
            },
            "assessed": {
                "description": "A result (or step) written, assessed: `wrong`, `diagnoses` and `known_mistake` when it is not correct.",
                "type": "object",
                "properties": {
                    "result": {"description": "The result's (or step's) name.", "type": "string"},
                    "correct": {"type": "boolean"},
                    "right": {"type": "integer", "minimum": 0},
                    "entries": {"type": "integer", "minimum": 0},
                    "score": def("Score"),
                    "wrong": {
                        "description": "The wrong entries: the key's value and the one written.",
                        "type": "array",
                        "items": {
                            "type": "object",
                            "properties": {
                                "entry": {"description": "Which entry (`c_1,1`, `w_2`, `knots`).", "type": "string"},
                                "expected": {"description": "The key's value of the entry (a value of an answer; none, written as JSON null, for an entry the key does not have)."},
                                "written": {"description": "The value written (a value of an answer; none, written as JSON null, where the answer has no such entry)."},
                            },
                            "required": ["entry", "expected", "written"],
                            "additionalProperties": false,
                        },
                    },
                    "diagnoses": {
                        "description": "The common mistakes whose exact answer equals the one written on the entries they explain (docs/mistakes.md); empty when no known mistake does.",
                        "type": "array",
                        "items": {
                            "type": "object",
                            "properties": {
                                "id": def("MistakeId"),
                                "result": {"type": "string"},
                                "entries": {"type": "array", "items": {"type": "string"}},
                                "whole": {"description": "Whether the mistake explains the whole result.", "type": "boolean"},
                                "ambiguous_with": {"description": "The other mistakes that give the same values.", "type": "array", "items": def("MistakeId")},
                            },
                            "required": ["id", "result", "entries", "whole", "ambiguous_with"],
                            "additionalProperties": false,
                        },
                    },
                    "known_mistake": {"description": "Whether a known mistake explains the wrong result.", "type": "boolean"},
                    "unread": {"description": "Why the value written could not be read (every entry then counts as wrong).", "type": "string"},
                    "unknown": {"description": "The key written is not a result of the operation.", "const": true},
                },
                "required": ["result", "correct", "right", "entries", "score"],
                "additionalProperties": false,
            },
            "student": {
                "description": "Whose answer this is (cagd check): the problem's `student`, else the file's name without its extension.",
                "type": "string",
            },
            "file": {
                "description": "The file the answer was read from (cagd check).",
                "type": "string",
            },
            "problem": {
                "description": "The answer's place in its file, from 1 (cagd check).",
                "type": "integer",
                "minimum": 1,
            },
            "Score": {
                "description": "The share of entries right, an exact fraction (\"7/9\", \"1\", \"0\").",
                "type": "string",
                "pattern": "^[0-9]+(/[0-9]+)?$",
            },
            "MistakeId": {
                "description": "A mistake of the catalogue, `family.what` (`coons.cd_added`).",
                "type": "string",
                "pattern": "^[a-z_]+\\.[a-z0-9_]+$",
            },
            "Value": {
                "description": "A value of an answer: true or false, an integer, a string (a number, a closed form, words), or a list or an object of values.",
                "anyOf": [
                    {"type": "boolean"},
                    {"type": "integer"},
                    {"type": "string"},
                    {"type": "array", "items": def("Value")},
                    {"type": "object", "additionalProperties": def("Value")},
                ],
            },
            "Number": {
                "description": "An exact number, as a string of the number grammar (\"5/6\", \"sqrt2/2\", \"1/2 + 3*sqrt2/4\").",
                "type": "string",
                "pattern": NUMBER_PATTERN,
            },
            "Point": point(def("Number")),
            "Points": points(def("Point")),
            "Mesh": mesh(def("Points")),
            "Grid": grid(def("Number")),
            "Degree": {"type": "integer", "minimum": 0},
            "Expression": expression(),
            "Curve": curve(&shapes),
            "Surface": surface(&shapes),
            "Triangle": triangle(def("Points"), def("Number")),
        },
    })
}
