//! The entries of a value (each control point, weight, knot vector, coordinate function...),
//! a student's answer read in the shape of the key's, and the two compared entry by entry.

use crate::input::{CurveIn, SurfaceIn};
use crate::message::check::Check;
use crate::spec::{self, List, Num, PointIn, Points};
use crate::value::expected::{parse_expected, same_knots};
use crate::value::json::rational_json;
use crate::{Exact, Number};
use cagd_param::Name;
use cagd_words::{said, Lang, Message, Phrase};
use serde_json::Value;
use std::collections::HashMap;

/// One entry of a result: what a student writes as one number, point or list, in the notes'
/// notation (control points `b_i` of a polygon and `c_i,j` of a mesh, weights `w_i` and
/// `w_i,j`, counted from 0 as in the notes).
#[derive(Debug, Clone, PartialEq, Eq, Hash)]
pub enum Entry {
    /// The value as a whole (a number, a point, a closed form, a yes or no).
    Whole,
    /// Point i of a control polygon or of a list of points.
    Point(usize),
    /// Weight i of a rational curve.
    Weight(usize),
    /// Control point (i, j) of a mesh.
    MeshPoint(usize, usize),
    /// Weight (i, j) of a rational surface.
    MeshWeight(usize, usize),
    /// The knot vector of a B-spline curve (either convention: the notes' or The NURBS
    /// Book's, with the end knots).
    Knots,
    /// The knot vector in u of a B-spline surface.
    KnotsU,
    /// The knot vector in v of a B-spline surface.
    KnotsV,
    /// The degree (or bidegree) of a B-spline curve or surface.
    Degree,
    /// Coordinate function k of a parametrization (x, y, z for k = 0, 1, 2).
    Component(usize),
    /// Entry (i, j) of a matrix.
    Cell(usize, usize),
    /// An entry the student wrote beyond the key's (more points, a larger mesh).
    Extra,
    /// Item k of a list (counted from 1: the first piece, the second...), and the entry in
    /// it.
    Item(usize, Box<Entry>),
    /// A field of an object value (a piece's `u` interval), by its name, and the entry in it.
    Field(String, Box<Entry>),
}

/// One entry of a result: the key's value, the student's, and whether they are equal.
#[derive(Debug, Clone, PartialEq)]
pub struct Mark {
    /// Which entry.
    pub entry: Entry,
    /// The key's value (none for [`Entry::Extra`]).
    pub key: Option<Exact>,
    /// The student's value (none when the student did not write this entry).
    pub written: Option<Exact>,
    /// Whether the student's value is the key's, exactly.
    pub right: bool,
}

impl Message for Entry {
    fn phrase(&self, lang: Lang) -> Phrase {
        let coordinate = |k: &usize| match k {
            0 => "x".to_string(),
            1 => "y".to_string(),
            2 => "z".to_string(),
            k => format!("x_{}", k + 1),
        };
        match self {
            Entry::Whole => said(lang, "the value", "el valor", []),
            Entry::Point(i) => said(lang, "b_‹›", "b_‹›", [i.into()]),
            Entry::Weight(i) => said(lang, "w_‹›", "w_‹›", [i.into()]),
            Entry::MeshPoint(i, j) => said(lang, "c_‹›,‹›", "c_‹›,‹›", [i.into(), j.into()]),
            Entry::MeshWeight(i, j) => said(lang, "w_‹›,‹›", "w_‹›,‹›", [i.into(), j.into()]),
            Entry::Knots => said(lang, "the knots", "los nudos", []),
            Entry::KnotsU => said(lang, "the knots in u", "los nudos en u", []),
            Entry::KnotsV => said(lang, "the knots in v", "los nudos en v", []),
            Entry::Degree => said(lang, "the degree", "el grado", []),
            Entry::Component(k) => said(
                lang,
                "the function ‹›",
                "la función ‹›",
                [(&coordinate(k)).into()],
            ),
            Entry::Cell(i, j) => said(
                lang,
                "entry (‹›, ‹›)",
                "elemento (‹›, ‹›)",
                [i.into(), j.into()],
            ),
            Entry::Extra => said(lang, "entries beyond the key's", "elementos de más", []),
            Entry::Item(k, inner) => said(
                lang,
                "[‹›] ‹›",
                "[‹›] ‹›",
                [(&(k + 1)).into(), inner.phrase(lang).into()],
            ),
            Entry::Field(name, inner) => said(
                lang,
                "‹›: ‹›",
                "‹›: ‹›",
                [name.as_str().into(), inner.phrase(lang).into()],
            ),
        }
    }
}

cagd_words::display_english!(Entry);

impl Exact {
    /// The value's entries, in order: a polygon's points and weights, a mesh's points and
    /// weights, a B-spline's degree and knots, a parametrization's coordinate functions, a
    /// matrix's cells, the entries of each item of a list and of each field of an object;
    /// any other value is one entry ([`Entry::Whole`]).
    pub fn entries(&self) -> Vec<(Entry, Exact)> {
        let components = |m: &cagd_poly::VecPoly<Number>| -> Vec<(Entry, Exact)> {
            m.components()
                .iter()
                .enumerate()
                .map(|(k, p)| (Entry::Component(k), Exact::Poly(p.clone())))
                .collect()
        };
        let numbers = |xs: &[Number]| Exact::List(xs.iter().cloned().map(Exact::Number).collect());
        match self {
            Exact::Points(ps) => ps
                .iter()
                .enumerate()
                .map(|(i, p)| (Entry::Point(i), Exact::Point(p.clone())))
                .collect(),
            Exact::Matrix(rows) => rows
                .iter()
                .enumerate()
                .flat_map(|(i, r)| {
                    r.iter()
                        .enumerate()
                        .map(move |(j, x)| (Entry::Cell(i, j), Exact::Number(x.clone())))
                })
                .collect(),
            Exact::Map(m) if m.components().len() > 1 => components(m),
            Exact::Curve(c) => {
                let mut out = Vec::new();
                let (points, weights) = match c {
                    CurveIn::Bezier { points, weights } => (points, weights),
                    CurveIn::BSpline {
                        points,
                        degree,
                        knots,
                        weights,
                    } => {
                        out.push((
                            Entry::Degree,
                            Exact::Int(i64::try_from(*degree).unwrap_or(i64::MAX)),
                        ));
                        out.push((Entry::Knots, numbers(knots)));
                        (points, weights)
                    }
                    CurveIn::Expr(m) => return components(m),
                };
                for (i, p) in points.iter().enumerate() {
                    out.push((Entry::Point(i), Exact::Point(p.clone())));
                }
                for (i, w) in weights.iter().flatten().enumerate() {
                    out.push((Entry::Weight(i), Exact::Number(w.clone())));
                }
                out
            }
            Exact::Surface(s) => {
                let mut out = Vec::new();
                let (mesh, weights) = match s {
                    SurfaceIn::Bezier { mesh, weights } => (mesh, weights),
                    SurfaceIn::BSpline {
                        mesh,
                        degree,
                        knots,
                        weights,
                    } => {
                        let (p, q) = *degree;
                        out.push((
                            Entry::Degree,
                            Exact::List(vec![
                                Exact::Int(i64::try_from(p).unwrap_or(i64::MAX)),
                                Exact::Int(i64::try_from(q).unwrap_or(i64::MAX)),
                            ]),
                        ));
                        out.push((Entry::KnotsU, numbers(&knots.0)));
                        out.push((Entry::KnotsV, numbers(&knots.1)));
                        (mesh, weights)
                    }
                    SurfaceIn::Expr(m) => return components(m),
                };
                for ((i, j), p) in mesh.indexed() {
                    out.push((Entry::MeshPoint(i, j), Exact::Point(p.clone())));
                }
                for ((i, j), w) in weights.iter().flat_map(|w| w.indexed()) {
                    out.push((Entry::MeshWeight(i, j), Exact::Number(w.clone())));
                }
                out
            }
            Exact::List(xs) => xs
                .iter()
                .enumerate()
                .flat_map(|(k, x)| {
                    x.entries()
                        .into_iter()
                        .map(move |(e, v)| (Entry::Item(k, Box::new(e)), v))
                })
                .collect(),
            Exact::Object(kv) => kv
                .iter()
                .flat_map(|(q, x)| {
                    let name = q.name().into_owned();
                    x.entries()
                        .into_iter()
                        .map(move |(e, v)| (Entry::Field(name.clone(), Box::new(e)), v))
                })
                .collect(),
            _ => vec![(Entry::Whole, self.clone())],
        }
    }

    /// A student's answer `written` (JSON, in the shapes of the problem format, numbers in
    /// any form the grammar reads: `5/6`, `0.5`, `√2/2`, `sqrt2/2`, letters of `parameters`)
    /// read as a value of this value's kind. A value of another kind (a string where a yes or
    /// no is asked) is read as text, which no entry equals; one that the readers refuse is
    /// the reader's mismatch.
    pub fn read_like(&self, written: &Value, parameters: &[Name]) -> Result<Exact, Check> {
        let text = || Exact::Text(written.to_string());
        Ok(match self {
            Exact::Bool(_) => written.as_bool().map_or_else(text, Exact::Bool),
            Exact::Int(_) => written.as_i64().map_or_else(text, Exact::Int),
            Exact::Text(t) => match written.as_str() {
                Some(w) if w == t => self.clone(),
                _ => text(),
            },
            Exact::Sentence(m) => match written.as_str() {
                Some(w) if *w == *m.to_string() => self.clone(),
                _ => text(),
            },
            Exact::Number(_) => {
                let Num(x) = spec::read_value(written, parameters).map_err(Check::unread)?;
                Exact::Number(x)
            }
            Exact::Point(_) => {
                let PointIn(p) = spec::read_value(written, parameters).map_err(Check::unread)?;
                Exact::Point(p)
            }
            Exact::Points(_) => {
                let Points(ps) = spec::read_value(written, parameters).map_err(Check::unread)?;
                Exact::Points(ps)
            }
            Exact::Matrix(_) => {
                let List(rows) = spec::read_value::<List<List<Num>>>(written, parameters)
                    .map_err(Check::unread)?;
                Exact::Matrix(
                    rows.into_iter()
                        .map(|List(r)| r.into_iter().map(|Num(x)| x).collect())
                        .collect(),
                )
            }
            Exact::Poly(_) => Exact::Poly(
                parse_expected(written)?
                    .scalar::<Number>()
                    .map_err(Check::unread)?,
            ),
            Exact::Map(_) => Exact::Map(
                parse_expected(written)?
                    .vector::<Number>()
                    .map_err(Check::unread)?,
            ),
            Exact::Rational(r) => match written.as_str() {
                Some(w) if w == rational_json(r) || w == r.to_text() => self.clone(),
                _ => text(),
            },
            Exact::Curve(_) => {
                Exact::Curve(spec::read_value(written, parameters).map_err(Check::unread)?)
            }
            Exact::Surface(_) => {
                Exact::Surface(spec::read_value(written, parameters).map_err(Check::unread)?)
            }
            Exact::List(xs) => {
                let items = written.as_array().ok_or_else(|| Check::ComputedList {
                    expected: written.to_string(),
                })?;
                let mut out = Vec::with_capacity(items.len());
                for (k, item) in items.iter().enumerate() {
                    match xs.get(k).or(xs.last()) {
                        Some(like) => out.push(like.read_like(item, parameters)?),
                        None => out.push(Exact::Text(item.to_string())),
                    }
                }
                Exact::List(out)
            }
            Exact::Object(kv) => {
                let obj = written.as_object().ok_or_else(|| Check::ComputedObject {
                    expected: written.to_string(),
                })?;
                let mut out = Vec::new();
                for (q, like) in kv {
                    if let Some(w) = obj.get(q.name().as_ref()) {
                        out.push((q.clone(), like.read_like(w, parameters)?));
                    }
                }
                Exact::Object(out)
            }
        })
    }
}

/// The key's value and the student's compared entry by entry: a [`Mark`] for each entry of
/// the key (right when the student wrote the same exact value there; knot vectors in either
/// convention), and one [`Entry::Extra`] mark, wrong, when the student wrote entries the key
/// does not have.
pub fn marks(key: &Exact, written: &Exact) -> Vec<Mark> {
    let mut written: HashMap<Entry, Exact> = written.entries().into_iter().collect();
    let mut out: Vec<Mark> = key
        .entries()
        .into_iter()
        .map(|(entry, k)| {
            let w = written.remove(&entry);
            let right = w.as_ref().is_some_and(|w| match entry {
                Entry::Knots | Entry::KnotsU | Entry::KnotsV => same_knots(&k, w),
                _ => &k == w,
            });
            Mark {
                entry,
                key: Some(k),
                written: w,
                right,
            }
        })
        .collect();
    if !written.is_empty() {
        out.push(Mark {
            entry: Entry::Extra,
            key: None,
            written: None,
            right: false,
        });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn surface(v: Value) -> Exact {
        Exact::Surface(spec::read_value(&v, &[]).unwrap())
    }

    #[test]
    fn a_mesh_is_marked_entry_by_entry() {
        let key = surface(json!({"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]}));
        let written = key
            .read_like(
                &json!({"bezier": [[["0", "0", "0"], [0, 1, 0]], [[1, 0, 0], [1, 1, "0.5"]]]}),
                &[],
            )
            .unwrap();
        let marks = marks(&key, &written);
        assert_eq!(marks.len(), 4);
        let wrong: Vec<String> = marks
            .iter()
            .filter(|m| !m.right)
            .map(|m| m.entry.to_string())
            .collect();
        assert_eq!(wrong, ["c_1,1"]);
    }

    #[test]
    fn forgotten_weights_are_wrong_entries() {
        let key = surface(json!({"bezier": [[[0, 0, 0], [0, 1, 0]]], "weights": [[1, 2]]}));
        let written = key
            .read_like(&json!({"bezier": [[[0, 0, 0], [0, 1, 0]]]}), &[])
            .unwrap();
        let wrong: Vec<String> = marks(&key, &written)
            .iter()
            .filter(|m| !m.right)
            .map(|m| m.entry.to_string())
            .collect();
        assert_eq!(wrong, ["w_0,0", "w_0,1"]);
    }

    #[test]
    fn knots_in_either_convention() {
        let n = |xs: &[i64]| {
            Exact::List(
                xs.iter()
                    .map(|x| Exact::Number(<Number as cagd_scalar::FieldOps>::from_i64(*x)))
                    .collect(),
            )
        };
        assert!(same_knots(&n(&[0, 0, 1, 2, 2]), &n(&[0, 0, 0, 1, 2, 2, 2])));
        assert!(!same_knots(&n(&[0, 0, 1, 2, 2]), &n(&[0, 1, 1, 2])));
    }
}
