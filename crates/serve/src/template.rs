//! The answer form of a result: the key's value in the JSON shape `cagd solve --format json`
//! writes, each scalar leaf replaced by a cell `{"cell": ENTRY, "kind": KIND}` (API.md). The
//! cell's entry is the assessment's ([`Exact::entries`]), so that a check's marks name the
//! cells of the form: both are walked from the same typed value.

use cagd_problem::diagnosis::Entry;
use cagd_problem::input::{CurveIn, SurfaceIn};
use cagd_problem::Exact;
use cagd_surface::{Grid, Mesh};
use cagd_words::{Lang, Message};
use serde_json::{json, Map, Value};

/// What a cell holds, and so how the page draws it and the server reads it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CellKind {
    /// A number of the grammar (`5/6`, `√2/2`, letters of the problem's parameters).
    Number,
    /// A polynomial or a closed form (a wide cell).
    Expression,
    /// Yes or no.
    Bool,
    /// Words: an answer of the engine in words (a continuity verdict), compared as written.
    Text,
}

impl CellKind {
    /// Its name in the JSON (`"number"`...).
    pub fn name(self) -> &'static str {
        match self {
            CellKind::Number => "number",
            CellKind::Expression => "expression",
            CellKind::Bool => "bool",
            CellKind::Text => "text",
        }
    }

    /// The kind of a name.
    pub fn parse(name: &str) -> Option<CellKind> {
        match name {
            "number" => Some(CellKind::Number),
            "expression" => Some(CellKind::Expression),
            "bool" => Some(CellKind::Bool),
            "text" => Some(CellKind::Text),
            _ => None,
        }
    }
}

/// The cell an entry is written in: the coordinate functions of a closed form (`the
/// function x`) are one string of the answer, so their cell is the closed form's whole value;
/// every other entry is its own cell.
pub fn cell_of(entry: &Entry) -> Entry {
    match entry {
        Entry::Component(_) => Entry::Whole,
        Entry::Item(k, inner) => Entry::Item(*k, Box::new(cell_of(inner))),
        Entry::Field(name, inner) => Entry::Field(name.clone(), Box::new(cell_of(inner))),
        other => other.clone(),
    }
}

/// The answer form of a value: its JSON shape, every scalar leaf a cell.
pub fn template(value: &Exact) -> Value {
    walk(value, &|e| e)
}

/// One cell: its entry's id (the English phrase the marks name it by), its kind, and the
/// entry's name in each language for the page to show (`the value`, `el valor`).
fn cell(entry: Entry, kind: CellKind) -> Value {
    json!({
        "cell": entry.to_string(),
        "kind": kind.name(),
        "name": {"en": entry.phrase(Lang::En).text(), "es": entry.phrase(Lang::Es).text()},
    })
}

/// A point of `dim` coordinates, all of one entry.
fn point(dim: usize, entry: &Entry) -> Value {
    Value::Array(
        (0..dim)
            .map(|_| cell(entry.clone(), CellKind::Number))
            .collect(),
    )
}

/// `n` numbers of one entry (a knot vector).
fn same(n: usize, entry: Entry) -> Value {
    Value::Array(
        (0..n)
            .map(|_| cell(entry.clone(), CellKind::Number))
            .collect(),
    )
}

/// A mesh by rows, each point of entry `c_i,j`.
fn mesh<T: Clone>(
    m: &Mesh<T>,
    dim: impl Fn(usize, usize) -> usize,
    at: &dyn Fn(Entry) -> Entry,
) -> Value {
    Value::Array(
        (0..m.rows())
            .map(|i| {
                Value::Array(
                    (0..m.cols())
                        .map(|j| point(dim(i, j), &at(Entry::MeshPoint(i, j))))
                        .collect(),
                )
            })
            .collect(),
    )
}

/// A grid of weights by rows, each of entry `w_i,j`.
fn weights<T: Clone>(g: &Grid<T>, at: &dyn Fn(Entry) -> Entry) -> Value {
    Value::Array(
        (0..g.rows())
            .map(|i| {
                Value::Array(
                    (0..g.cols())
                        .map(|j| cell(at(Entry::MeshWeight(i, j)), CellKind::Number))
                        .collect(),
                )
            })
            .collect(),
    )
}

/// The form of `value`, its entries put where they are by `at` (inside an item of a list,
/// a field of an object).
fn walk(value: &Exact, at: &dyn Fn(Entry) -> Entry) -> Value {
    let whole = |kind| cell(at(Entry::Whole), kind);
    match value {
        Exact::Bool(_) => whole(CellKind::Bool),
        Exact::Int(_) | Exact::Number(_) => whole(CellKind::Number),
        Exact::Text(_) | Exact::Sentence(_) => whole(CellKind::Text),
        Exact::Poly(_) | Exact::Map(_) | Exact::Rational(_) => whole(CellKind::Expression),
        Exact::Point(p) => point(p.dim(), &at(Entry::Whole)),
        Exact::Points(ps) => Value::Array(
            ps.iter()
                .enumerate()
                .map(|(i, p)| point(p.dim(), &at(Entry::Point(i))))
                .collect(),
        ),
        Exact::Matrix(rows) => Value::Array(
            rows.iter()
                .enumerate()
                .map(|(i, r)| {
                    Value::Array(
                        (0..r.len())
                            .map(|j| cell(at(Entry::Cell(i, j)), CellKind::Number))
                            .collect(),
                    )
                })
                .collect(),
        ),
        Exact::Curve(c) => {
            let mut o = Map::new();
            let polygon = |points: &[cagd_linalg::Point<cagd_problem::Number>]| {
                Value::Array(
                    points
                        .iter()
                        .enumerate()
                        .map(|(i, p)| point(p.dim(), &at(Entry::Point(i))))
                        .collect(),
                )
            };
            let curve_weights = |w: &[cagd_problem::Number]| {
                Value::Array(
                    (0..w.len())
                        .map(|i| cell(at(Entry::Weight(i)), CellKind::Number))
                        .collect(),
                )
            };
            match c {
                CurveIn::Bezier { points, weights } => {
                    o.insert("bezier".into(), polygon(points));
                    if let Some(w) = weights {
                        o.insert("weights".into(), curve_weights(w));
                    }
                }
                CurveIn::BSpline {
                    points,
                    knots,
                    weights,
                    ..
                } => {
                    o.insert("bspline".into(), polygon(points));
                    o.insert("degree".into(), cell(at(Entry::Degree), CellKind::Number));
                    o.insert("knots".into(), same(knots.len(), at(Entry::Knots)));
                    if let Some(w) = weights {
                        o.insert("weights".into(), curve_weights(w));
                    }
                }
                CurveIn::Expr(_) => {
                    o.insert("expr".into(), whole(CellKind::Expression));
                }
            }
            Value::Object(o)
        }
        Exact::Surface(s) => {
            let mut o = Map::new();
            match s {
                SurfaceIn::Bezier {
                    mesh: m,
                    weights: w,
                } => {
                    o.insert("bezier".into(), mesh(m, |i, j| dim_at(m, i, j), at));
                    if let Some(w) = w {
                        o.insert("weights".into(), weights(w, at));
                    }
                }
                SurfaceIn::BSpline {
                    mesh: m,
                    knots,
                    weights: w,
                    ..
                } => {
                    o.insert("bspline".into(), mesh(m, |i, j| dim_at(m, i, j), at));
                    o.insert(
                        "degree".into(),
                        Value::Array(vec![
                            cell(at(Entry::Degree), CellKind::Number),
                            cell(at(Entry::Degree), CellKind::Number),
                        ]),
                    );
                    o.insert(
                        "knots".into(),
                        Value::Array(vec![
                            same(knots.0.len(), at(Entry::KnotsU)),
                            same(knots.1.len(), at(Entry::KnotsV)),
                        ]),
                    );
                    if let Some(w) = w {
                        o.insert("weights".into(), weights(w, at));
                    }
                }
                SurfaceIn::Expr(_) => {
                    o.insert("expr".into(), whole(CellKind::Expression));
                }
            }
            Value::Object(o)
        }
        Exact::List(xs) => Value::Array(
            xs.iter()
                .enumerate()
                .map(|(k, x)| walk(x, &|e| at(Entry::Item(k, Box::new(e)))))
                .collect(),
        ),
        Exact::Object(kv) => {
            let mut o = Map::new();
            for (q, x) in kv {
                let name = q.name().into_owned();
                let value = walk(x, &|e| at(Entry::Field(name.clone(), Box::new(e))));
                o.insert(name, value);
            }
            Value::Object(o)
        }
    }
}

/// The dimension of a mesh's point (i, j).
fn dim_at(m: &Mesh<cagd_problem::Number>, i: usize, j: usize) -> usize {
    m.get(i, j).map_or(0, cagd_linalg::Point::dim)
}

/// Every cell of a form, in order: its entry and kind.
pub fn cells(form: &Value) -> Vec<(String, CellKind)> {
    let mut out = Vec::new();
    each_cell(form, &mut |entry, kind| out.push((entry.to_string(), kind)));
    out
}

/// A cell of a form (`{"cell", "kind", "name"}`, as [`cell`] writes it): its entry and kind;
/// none for any other object (an answer's own objects never have a `cell`).
fn as_cell(o: &Map<String, Value>) -> Option<(&str, CellKind)> {
    let entry = o.get("cell").and_then(Value::as_str)?;
    let kind = o
        .get("kind")
        .and_then(Value::as_str)
        .and_then(CellKind::parse)?;
    o.keys()
        .all(|k| matches!(k.as_str(), "cell" | "kind" | "name"))
        .then_some((entry, kind))
}

/// The name in `lang` of the cell `id` of a form (`el valor` for `the value`), as the page
/// captions it; the id itself when the form has no such cell.
pub fn cell_name(form: &Value, id: &str, lang: Lang) -> String {
    fn find<'a>(form: &'a Value, id: &str) -> Option<&'a Map<String, Value>> {
        match form {
            Value::Array(xs) => xs.iter().find_map(|x| find(x, id)),
            Value::Object(o) => match as_cell(o) {
                Some((entry, _)) if entry == id => Some(o),
                Some(_) => None,
                None => o.values().find_map(|x| find(x, id)),
            },
            _ => None,
        }
    }
    let lang_key = match lang {
        Lang::En => "en",
        Lang::Es => "es",
    };
    find(form, id)
        .and_then(|o| o.get("name"))
        .and_then(|n| n.get(lang_key))
        .and_then(Value::as_str)
        .map_or_else(|| id.to_string(), str::to_string)
}

/// Calls `f` on each cell of a form.
fn each_cell(form: &Value, f: &mut dyn FnMut(&str, CellKind)) {
    match form {
        Value::Array(xs) => xs.iter().for_each(|x| each_cell(x, f)),
        Value::Object(o) => match as_cell(o) {
            Some((entry, kind)) => f(entry, kind),
            None => o.values().for_each(|x| each_cell(x, f)),
        },
        _ => {}
    }
}

/// The student's text of each cell, walking the form and the answer together: the cell's
/// entry, kind and what was written (`None` where the answer has no value there).
pub fn written_cells<'a>(
    form: &Value,
    answer: &'a Value,
) -> Vec<(String, CellKind, Option<&'a Value>)> {
    let mut out = Vec::new();
    pair(form, Some(answer), &mut out);
    out
}

fn pair<'a>(
    form: &Value,
    answer: Option<&'a Value>,
    out: &mut Vec<(String, CellKind, Option<&'a Value>)>,
) {
    match form {
        Value::Array(xs) => {
            for (k, x) in xs.iter().enumerate() {
                pair(x, answer.and_then(|a| a.get(k)), out);
            }
        }
        Value::Object(o) => match as_cell(o) {
            Some((entry, kind)) => {
                out.push((entry.to_string(), kind, answer));
            }
            None => {
                for (key, x) in o {
                    pair(x, answer.and_then(|a| a.get(key)), out);
                }
            }
        },
        _ => {}
    }
}

/// The student's answer with the text of each number cell that is an integer (`"2"`, `" -3 "`)
/// as a JSON integer: a degree or an order is read from an integer, and every number reader
/// takes one (exactly, as the text would be).
pub fn integers_as_numbers(form: &Value, answer: &Value) -> Value {
    match (form, answer) {
        (Value::Object(o), Value::String(t))
            if o.get("kind").and_then(Value::as_str) == Some(CellKind::Number.name()) =>
        {
            match t.trim().parse::<i64>() {
                Ok(n) => Value::from(n),
                Err(_) => answer.clone(),
            }
        }
        (Value::Array(fs), Value::Array(xs)) => Value::Array(
            xs.iter()
                .enumerate()
                .map(|(k, x)| match fs.get(k) {
                    Some(f) => integers_as_numbers(f, x),
                    None => x.clone(),
                })
                .collect(),
        ),
        (Value::Object(fo), Value::Object(xo)) => Value::Object(
            xo.iter()
                .map(|(key, x)| {
                    let x = match fo.get(key) {
                        Some(f) => integers_as_numbers(f, x),
                        None => x.clone(),
                    };
                    (key.clone(), x)
                })
                .collect(),
        ),
        _ => answer.clone(),
    }
}

/// Whether a student's value is wholly empty: every leaf `""` (or blank) or `null`.
pub fn is_empty(answer: &Value) -> bool {
    match answer {
        Value::Null => true,
        Value::String(s) => s.trim().is_empty(),
        Value::Array(xs) => xs.iter().all(is_empty),
        Value::Object(o) => o.values().all(is_empty),
        Value::Bool(_) | Value::Number(_) => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_problem::spec;
    use std::collections::BTreeSet;

    /// The cells of a value's form are its entries, each written once per cell
    /// ([`cell_of`]).
    fn same_entries(x: &Exact) -> Value {
        let form = template(x);
        let from_form: BTreeSet<String> = cells(&form).into_iter().map(|(e, _)| e).collect();
        let from_entries: BTreeSet<String> = x
            .entries()
            .iter()
            .map(|(e, _)| cell_of(e).to_string())
            .collect();
        assert_eq!(from_form, from_entries, "{form}");
        // the form's shape is the answer's JSON
        fn shape(v: &Value) -> Value {
            match v {
                Value::Array(xs) => Value::Array(xs.iter().map(shape).collect()),
                Value::Object(o) if o.contains_key("cell") => Value::Null,
                Value::Object(o) => {
                    Value::Object(o.iter().map(|(k, x)| (k.clone(), shape(x))).collect())
                }
                _ => Value::Null,
            }
        }
        assert_eq!(shape(&form), shape(&x.to_json()), "{form}");
        unnamed(&form)
    }

    /// The form without the cells' names (the tests compare ids and kinds).
    fn unnamed(v: &Value) -> Value {
        match v {
            Value::Array(xs) => Value::Array(xs.iter().map(unnamed).collect()),
            Value::Object(o) => Value::Object(
                o.iter()
                    .filter(|(k, _)| k.as_str() != "name")
                    .map(|(k, x)| (k.clone(), unnamed(x)))
                    .collect(),
            ),
            other => other.clone(),
        }
    }

    #[test]
    fn a_cell_is_named_in_both_languages() {
        let x = Exact::Poly(cagd_poly::Poly::zero());
        let form = template(&x);
        assert_eq!(form["name"]["es"], "el valor", "{form}");
        assert_eq!(form["name"]["en"], "the value", "{form}");
        assert_eq!(cell_name(&form, "the value", Lang::Es), "el valor");
        let knots = template(&curve(
            json!({"bspline": [[0, 0], [1, 1], [2, 0]], "degree": 2, "knots": [0, 0, 1, 1]}),
        ));
        assert_eq!(cell_name(&knots, "the knots", Lang::Es), "los nudos");
        assert_eq!(cell_name(&knots, "b_1", Lang::Es), "b_1");
        assert_eq!(cell_name(&knots, "nowhere", Lang::Es), "nowhere");
    }

    fn surface(v: Value) -> Exact {
        Exact::Surface(spec::read_value(&v, &[]).unwrap())
    }

    fn curve(v: Value) -> Exact {
        Exact::Curve(spec::read_value(&v, &[]).unwrap())
    }

    #[test]
    fn a_bezier_curve_with_weights() {
        let x = curve(json!({"bezier": [[0, 0], [1, 1], [2, 0]], "weights": [1, 2, 1]}));
        let form = same_entries(&x);
        assert_eq!(
            form["bezier"][1][0],
            json!({"cell": "b_1", "kind": "number"})
        );
        assert_eq!(form["weights"][2], json!({"cell": "w_2", "kind": "number"}));
    }

    #[test]
    fn a_mesh_with_weights() {
        let x = surface(json!({
            "bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]],
            "weights": [[1, 2], [1, 1]]
        }));
        let form = same_entries(&x);
        assert_eq!(
            form["bezier"][1][0][2],
            json!({"cell": "c_1,0", "kind": "number"})
        );
        assert_eq!(
            form["weights"][0][1],
            json!({"cell": "w_0,1", "kind": "number"})
        );
    }

    #[test]
    fn a_bspline_with_knots_and_degree() {
        let c = curve(
            json!({"bspline": [[0, 0], [1, 1], [2, 0], [3, 1]], "degree": 2, "knots": [0, 0, 1, 2, 2]}),
        );
        let form = same_entries(&c);
        assert_eq!(
            form["degree"],
            json!({"cell": "the degree", "kind": "number"})
        );
        assert_eq!(
            form["knots"][4],
            json!({"cell": "the knots", "kind": "number"})
        );
        let s = surface(json!({
            "bspline": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]],
            "degree": [1, 1],
            "knots": [[0, 1], [0, 1]]
        }));
        let form = same_entries(&s);
        assert_eq!(
            form["knots"][1][0],
            json!({"cell": "the knots in v", "kind": "number"})
        );
        assert_eq!(
            form["degree"][1],
            json!({"cell": "the degree", "kind": "number"})
        );
    }

    #[test]
    fn a_closed_form_is_one_cell() {
        let map = cagd_poly::parse_expr("(u, v, u*v)")
            .unwrap()
            .vector::<cagd_problem::Number>()
            .unwrap();
        let x = Exact::Map(map);
        let form = same_entries(&x);
        assert_eq!(form, json!({"cell": "the value", "kind": "expression"}));
        // its marks, one per coordinate function, are the one cell's
        assert!(x
            .entries()
            .iter()
            .all(|(e, _)| cell_of(e).to_string() == "the value"));
    }

    #[test]
    fn a_list_of_points() {
        let ps: spec::Points = spec::read_value(&json!([[0, 0, 1], ["1/2", 0, 1]]), &[]).unwrap();
        let x = Exact::Points(ps.0);
        let form = same_entries(&x);
        assert_eq!(form[1][0], json!({"cell": "b_1", "kind": "number"}));
        assert_eq!(form[1].as_array().map(Vec::len), Some(3));
    }

    #[test]
    fn pieces() {
        use cagd_problem::Quantity;
        let piece = |a: i64| {
            let map = cagd_poly::parse_expr(&format!("({a}*t, t^2)"))
                .unwrap()
                .vector::<cagd_problem::Number>()
                .unwrap();
            Exact::Object(vec![
                (
                    Quantity::Variable(cagd_poly::Var::T),
                    Exact::List(vec![
                        Exact::Number(<cagd_problem::Number as cagd_scalar::FieldOps>::from_i64(0)),
                        Exact::Number(<cagd_problem::Number as cagd_scalar::FieldOps>::from_i64(1)),
                    ]),
                ),
                (
                    Quantity::ClosedForm(Exact::Map(map.clone()).variables()),
                    Exact::Map(map),
                ),
            ])
        };
        let x = Exact::List(vec![piece(1), piece(2)]);
        let form = same_entries(&x);
        let cells: Vec<String> = cells(&form).into_iter().map(|(e, _)| e).collect();
        assert!(
            cells.contains(&"[2] closed_form: the value".to_string()),
            "{cells:?}"
        );
        assert!(
            cells.contains(&"[1] t: [2] the value".to_string()),
            "{cells:?}"
        );
    }

    #[test]
    fn written_cells_follow_the_form() {
        let x = curve(json!({"bezier": [[0, 0], [1, 1]]}));
        let form = template(&x);
        let answer = json!({"bezier": [["0", ""], ["1"]]});
        let got = written_cells(&form, &answer);
        assert_eq!(got.len(), 4);
        assert_eq!(got[1].2, Some(&json!("")));
        assert_eq!(got[3].2, None);
        assert!(is_empty(&json!({"bezier": [["", " "], [null]]})));
        assert!(!is_empty(&json!({"bezier": [["", "1"]]})));
    }
}
