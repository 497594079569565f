//! Answer values in JSON: numbers as exact strings, closed forms as parseable strings, curves
//! and surfaces in the input shape (so an answer feeds back as a problem).

use super::exact::{Exact, Number};
use crate::input::{CurveIn, SurfaceIn};
use cagd_linalg::Point;
use cagd_poly::RationalMap;
use cagd_scalar::{Print, Quadratic};
use cagd_surface::{Grid, Mesh};
use serde::ser::{Serialize, SerializeMap, Serializer};
use serde_json::Value;

impl Exact {
    /// The JSON form (numbers as exact strings; closed forms as parseable strings). A surface or
    /// curve has the input shape, so an answer can be fed back as a problem. The same JSON is
    /// written without this tree by the [`Serialize`] impl (`serde_json::to_writer`).
    pub fn to_json(&self) -> Value {
        serde_json::to_value(self).unwrap_or(Value::Null)
    }
}

thread_local! {
    /// Whether the answer being written writes rational control points homogeneous.
    static HOMOGENEOUS: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

/// Runs `f` (a writing of answer values) with the rational curves and surfaces written with
/// homogeneous control points when `on` (`{"bezier": [[w x, w y, w], ...], "homogeneous":
/// true}`: the form a problem with `"homogeneous": true` used), else as points and weights.
pub fn with_homogeneous<R>(on: bool, f: impl FnOnce() -> R) -> R {
    let before = HOMOGENEOUS.with(|h| h.replace(on));
    let out = f();
    HOMOGENEOUS.with(|h| h.set(before));
    out
}

/// The homogeneous points `(w p, w)` of points and weights, `(v, 0)` for a control vector,
/// when the answer is written homogeneous ([`with_homogeneous`]) and there are weights.
fn homogeneous_points(
    points: &[Point<Number>],
    weights: Option<&[Number]>,
) -> Option<Vec<Point<Number>>> {
    let w = weights.filter(|_| HOMOGENEOUS.with(std::cell::Cell::get))?;
    Some(
        points
            .iter()
            .zip(w)
            .map(|(p, w)| cagd_bezier::lift(p, w))
            .collect(),
    )
}

/// The homogeneous mesh of a mesh and its weights, as [`homogeneous_points`].
fn homogeneous_mesh(mesh: &Mesh<Number>, weights: Option<&Grid<Number>>) -> Option<Mesh<Number>> {
    let w = weights.filter(|_| HOMOGENEOUS.with(std::cell::Cell::get))?;
    let rows = (0..mesh.rows())
        .map(|i| {
            let (p, w) = (mesh.row(i).unwrap_or(&[]), w.row(i).unwrap_or(&[]));
            p.iter()
                .zip(w)
                .map(|(p, w)| cagd_bezier::lift(p, w))
                .collect()
        })
        .collect();
    Grid::from_rows(rows).ok()
}

/// A rational map as one string: `(numerator)/(denominator)` with both in the JSON form of
/// the expression grammar.
pub fn rational_json(r: &RationalMap<Number>) -> String {
    format!(
        "{}/({})",
        r.numerator().to_json_string(),
        r.denominator().to_json_string()
    )
}

/// `{a, b, c}` in plain text.
pub fn numbers_text(xs: &[Number]) -> String {
    format!(
        "{{{}}}",
        xs.iter().map(Print::to_text).collect::<Vec<_>>().join(", ")
    )
}

/// Rows of numbers in plain text: `[1, 0; 1/4, 1/2]`.
pub fn matrix_text(rows: &[Vec<Number>]) -> String {
    let rs: Vec<String> = rows
        .iter()
        .map(|r| r.iter().map(Print::to_text).collect::<Vec<_>>().join(", "))
        .collect();
    format!("[{}]", rs.join("; "))
}

/// One exact number, as the JSON string that reads back to it.
struct NumberJson<'a>(&'a Number);

impl Serialize for NumberJson<'_> {
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        // a rational, the common case, is written from the stack
        match self.0.as_const().and_then(Quadratic::as_rat) {
            Some(r) => r.with_text(|text| s.serialize_str(text)),
            None => s.serialize_str(&self.0.to_json_string()),
        }
    }
}

/// A list of numbers (a point, a row, knots, weights).
struct Numbers<'a>(&'a [Number]);

impl Serialize for Numbers<'_> {
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        s.collect_seq(self.0.iter().map(NumberJson))
    }
}

/// A list of points.
struct PointsJson<'a>(&'a [Point<Number>]);

impl Serialize for PointsJson<'_> {
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        s.collect_seq(self.0.iter().map(|p| Numbers(p.coords())))
    }
}

/// A grid of numbers, by rows.
struct GridJson<'a>(&'a Grid<Number>);

impl Serialize for GridJson<'_> {
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        s.collect_seq((0..self.0.rows()).map(|i| Numbers(self.0.row(i).unwrap_or(&[]))))
    }
}

/// A mesh of points, by rows.
struct MeshJson<'a>(&'a Mesh<Number>);

impl Serialize for MeshJson<'_> {
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        s.collect_seq((0..self.0.rows()).map(|i| PointsJson(self.0.row(i).unwrap_or(&[]))))
    }
}

impl Serialize for CurveIn<Number> {
    /// The input shape: `{"bezier": [...], "weights": [...]}`, `{"bspline": [...], "degree",
    /// "knots", "weights"}` or `{"expr": "..."}`.
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        let mut m = s.serialize_map(None)?;
        match self {
            CurveIn::Bezier { points, weights } => {
                if let Some(h) = homogeneous_points(points, weights.as_deref()) {
                    m.serialize_entry("bezier", &PointsJson(&h))?;
                    m.serialize_entry("homogeneous", &true)?;
                } else {
                    m.serialize_entry("bezier", &PointsJson(points))?;
                    if let Some(w) = weights {
                        m.serialize_entry("weights", &Numbers(w))?;
                    }
                }
            }
            CurveIn::BSpline {
                points,
                degree,
                knots,
                weights,
            } => {
                let h = homogeneous_points(points, weights.as_deref());
                m.serialize_entry("bspline", &PointsJson(h.as_deref().unwrap_or(points)))?;
                m.serialize_entry("degree", degree)?;
                m.serialize_entry("knots", &Numbers(knots))?;
                match (&h, weights) {
                    (Some(_), _) => m.serialize_entry("homogeneous", &true)?,
                    (None, Some(w)) => m.serialize_entry("weights", &Numbers(w))?,
                    (None, None) => {}
                }
            }
            CurveIn::Expr(e) => m.serialize_entry("expr", &e.to_json_string())?,
        }
        m.end()
    }
}

impl Serialize for SurfaceIn<Number> {
    /// The input shape: `{"bezier": mesh, "weights": grid}`, `{"bspline": mesh, "degree":
    /// [p, q], "knots": [[...], [...]], "weights"}` or `{"expr": "..."}`.
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        let mut m = s.serialize_map(None)?;
        match self {
            SurfaceIn::Bezier { mesh, weights } => {
                if let Some(h) = homogeneous_mesh(mesh, weights.as_ref()) {
                    m.serialize_entry("bezier", &MeshJson(&h))?;
                    m.serialize_entry("homogeneous", &true)?;
                } else {
                    m.serialize_entry("bezier", &MeshJson(mesh))?;
                    if let Some(w) = weights {
                        m.serialize_entry("weights", &GridJson(w))?;
                    }
                }
            }
            SurfaceIn::BSpline {
                mesh,
                degree,
                knots,
                weights,
            } => {
                let h = homogeneous_mesh(mesh, weights.as_ref());
                m.serialize_entry("bspline", &MeshJson(h.as_ref().unwrap_or(mesh)))?;
                m.serialize_entry("degree", &[degree.0, degree.1])?;
                m.serialize_entry("knots", &[Numbers(&knots.0), Numbers(&knots.1)])?;
                match (&h, weights) {
                    (Some(_), _) => m.serialize_entry("homogeneous", &true)?,
                    (None, Some(w)) => m.serialize_entry("weights", &GridJson(w))?,
                    (None, None) => {}
                }
            }
            SurfaceIn::Expr(e) => m.serialize_entry("expr", &e.to_json_string())?,
        }
        m.end()
    }
}

impl Serialize for Exact {
    /// The JSON form of [`Exact::to_json`], written straight to a serializer.
    fn serialize<Se: Serializer>(&self, s: Se) -> Result<Se::Ok, Se::Error> {
        match self {
            Exact::Bool(b) => s.serialize_bool(*b),
            Exact::Int(i) => s.serialize_i64(*i),
            Exact::Text(t) => s.serialize_str(t),
            Exact::Sentence(m) => s.collect_str(m),
            Exact::Number(x) => NumberJson(x).serialize(s),
            Exact::Point(p) => Numbers(p.coords()).serialize(s),
            Exact::Points(ps) => PointsJson(ps).serialize(s),
            Exact::Matrix(rows) => s.collect_seq(rows.iter().map(|r| Numbers(r))),
            Exact::Poly(p) => s.serialize_str(&p.to_json_string()),
            Exact::Map(m) => s.serialize_str(&m.to_json_string()),
            Exact::Rational(r) => s.serialize_str(&rational_json(r)),
            Exact::Curve(c) => c.serialize(s),
            Exact::Surface(surface) => surface.serialize(s),
            Exact::List(xs) => s.collect_seq(xs),
            Exact::Object(kv) => s.collect_map(kv.iter().map(|(k, v)| (k.name(), v))),
        }
    }
}

use crate::pretty::JsonWriter;

impl JsonWriter<'_> {
    /// One exact number, as [`NumberJson`] writes it: a rational's digits straight into the
    /// buffer.
    pub(crate) fn number(&mut self, x: &Number) {
        match x.as_const().and_then(Quadratic::as_rat) {
            Some(r) => self.plain_string(|out| r.push_text(out)),
            None => self.string(&x.to_json_string()),
        }
    }

    /// A list of numbers, as [`Numbers`] writes it.
    fn numbers(&mut self, xs: &[Number]) {
        self.seq(xs, |w, x| w.number(x));
    }

    /// A list of points, as [`PointsJson`] writes it.
    fn points(&mut self, ps: &[Point<Number>]) {
        self.seq(ps, |w, p| w.numbers(p.coords()));
    }

    /// A mesh by rows, as [`MeshJson`] writes it.
    fn mesh(&mut self, m: &Mesh<Number>) {
        self.seq(0..m.rows(), |w, i| w.points(m.row(i).unwrap_or(&[])));
    }

    /// A grid of numbers by rows, as [`GridJson`] writes it.
    fn grid(&mut self, g: &Grid<Number>) {
        self.seq(0..g.rows(), |w, i| w.numbers(g.row(i).unwrap_or(&[])));
    }

    /// An exact value: the bytes its [`Serialize`] impl writes through serde_json with
    /// [`crate::pretty::Pretty`].
    pub(crate) fn exact(&mut self, x: &Exact) {
        match x {
            Exact::Bool(b) => self.bool(*b),
            Exact::Int(i) => self.int(*i),
            Exact::Text(t) => self.string(t),
            Exact::Sentence(m) => self.string(&m.to_string()),
            Exact::Number(x) => self.number(x),
            Exact::Point(p) => self.numbers(p.coords()),
            Exact::Points(ps) => self.points(ps),
            Exact::Matrix(rows) => self.seq(rows, |w, r| w.numbers(r)),
            Exact::Poly(p) => self.string(&p.to_json_string()),
            Exact::Map(m) => self.string(&m.to_json_string()),
            Exact::Rational(r) => self.string(&rational_json(r)),
            Exact::Curve(c) => self.object(|o| match c {
                CurveIn::Bezier { points, weights } => {
                    if let Some(h) = homogeneous_points(points, weights.as_deref()) {
                        o.key("bezier").points(&h);
                        o.key("homogeneous").bool(true);
                    } else {
                        o.key("bezier").points(points);
                        if let Some(w) = weights {
                            o.key("weights").numbers(w);
                        }
                    }
                }
                CurveIn::BSpline {
                    points,
                    degree,
                    knots,
                    weights,
                } => {
                    let h = homogeneous_points(points, weights.as_deref());
                    o.key("bspline").points(h.as_deref().unwrap_or(points));
                    o.key("degree").int(*degree);
                    o.key("knots").numbers(knots);
                    match (&h, weights) {
                        (Some(_), _) => o.key("homogeneous").bool(true),
                        (None, Some(w)) => o.key("weights").numbers(w),
                        (None, None) => {}
                    }
                }
                CurveIn::Expr(e) => o.key("expr").string(&e.to_json_string()),
            }),
            Exact::Surface(sf) => self.object(|o| match sf {
                SurfaceIn::Bezier { mesh, weights } => {
                    if let Some(h) = homogeneous_mesh(mesh, weights.as_ref()) {
                        o.key("bezier").mesh(&h);
                        o.key("homogeneous").bool(true);
                    } else {
                        o.key("bezier").mesh(mesh);
                        if let Some(w) = weights {
                            o.key("weights").grid(w);
                        }
                    }
                }
                SurfaceIn::BSpline {
                    mesh,
                    degree,
                    knots,
                    weights,
                } => {
                    let h = homogeneous_mesh(mesh, weights.as_ref());
                    o.key("bspline").mesh(h.as_ref().unwrap_or(mesh));
                    o.key("degree").seq([degree.0, degree.1], |w, d| w.int(d));
                    o.key("knots")
                        .seq([&knots.0, &knots.1], |w, k| w.numbers(k));
                    match (&h, weights) {
                        (Some(_), _) => o.key("homogeneous").bool(true),
                        (None, Some(w)) => o.key("weights").grid(w),
                        (None, None) => {}
                    }
                }
                SurfaceIn::Expr(e) => o.key("expr").string(&e.to_json_string()),
            }),
            Exact::List(xs) => self.seq(xs, |w, x| w.exact(x)),
            Exact::Object(kv) => self.object(|o| {
                for (k, v) in kv {
                    o.key(&k.name()).exact(v);
                }
            }),
        }
    }
}
