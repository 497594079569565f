//! Reading problems: a cursor over the JSON that knows its path, and exact readers for numbers,
//! points, meshes, curves and surfaces (the shapes of `docs/format.md`).

use crate::limits::{read_number, with_flag, Limits, DEFAULT_LIMITS};
use crate::ProblemError;
use cagd_linalg::Point;
use cagd_poly::{parse_expr_with, Expr, VecPoly};
use cagd_scalar::{Quadratic, Scalar};
use cagd_surface::{Grid, Mesh};
use serde_json::Value;

/// A JSON value and its path in the problem, for error messages, read under the [`Limits`]
/// of the run.
#[derive(Clone, Debug)]
pub struct Field<'a> {
    /// The value.
    pub value: &'a Value,
    path: String,
    limits: &'a Limits,
}

impl<'a> Field<'a> {
    /// The root of a problem, read under the default limits.
    pub fn root(value: &'a Value) -> Self {
        Field::root_with(value, &DEFAULT_LIMITS)
    }

    /// The root of a problem, read under `limits`.
    pub fn root_with(value: &'a Value, limits: &'a Limits) -> Self {
        Field {
            value,
            path: String::new(),
            limits,
        }
    }

    /// The limits this field is read under.
    pub fn limits(&self) -> &'a Limits {
        self.limits
    }

    /// This field's path.
    pub fn path(&self) -> &str {
        &self.path
    }

    /// An error at this field.
    pub fn error(&self, message: impl Into<String>) -> ProblemError {
        ProblemError::at(self.path.clone(), message)
    }

    fn child_path(&self, key: &str) -> String {
        if self.path.is_empty() {
            key.to_string()
        } else {
            format!("{}.{key}", self.path)
        }
    }

    /// The member `key` of an object, or `None` when absent (or null).
    pub fn get(&self, key: &str) -> Option<Field<'a>> {
        match self.value.get(key) {
            None | Some(Value::Null) => None,
            Some(v) => Some(Field {
                value: v,
                path: self.child_path(key),
                limits: self.limits,
            }),
        }
    }

    /// The member `key`, required.
    pub fn req(&self, key: &str) -> Result<Field<'a>, ProblemError> {
        if !self.value.is_object() {
            return Err(self.error(format!("expected an object, found {}", kind(self.value))));
        }
        self.get(key).ok_or_else(|| {
            ProblemError::at(self.child_path(key), "missing (this operation needs it)")
        })
    }

    /// The items of an array (at most [`Limits::max_points`] of them).
    pub fn items(&self) -> Result<Vec<Field<'a>>, ProblemError> {
        let arr = self
            .value
            .as_array()
            .ok_or_else(|| self.error(format!("expected a list, found {}", kind(self.value))))?;
        let max = self.limits.max_points;
        if arr.len() > max {
            return Err(self.error(format!(
                "a list of {} items is longer than the limit of {max} (raise it with --max-points)",
                arr.len()
            )));
        }
        Ok(arr
            .iter()
            .enumerate()
            .map(|(i, v)| Field {
                value: v,
                path: format!("{}[{i}]", self.path),
                limits: self.limits,
            })
            .collect())
    }

    /// A string.
    pub fn str(&self) -> Result<&'a str, ProblemError> {
        self.value
            .as_str()
            .ok_or_else(|| self.error(format!("expected a string, found {}", kind(self.value))))
    }

    /// A non-negative integer (degrees, counts).
    pub fn usize(&self) -> Result<usize, ProblemError> {
        self.value
            .as_u64()
            .and_then(|n| usize::try_from(n).ok())
            .ok_or_else(|| {
                self.error(format!(
                    "expected a non-negative integer, found {}",
                    kind(self.value)
                ))
            })
    }

    /// A degree (or a derivative order, a multiplicity): a non-negative integer of at most
    /// [`Limits::max_degree`].
    pub fn degree(&self) -> Result<usize, ProblemError> {
        let n = self.usize()?;
        let max = self.limits.max_degree;
        if n > max {
            return Err(self.error(format!(
                "{n} is above the limit of {max} for degrees (raise it with --max-degree)"
            )));
        }
        Ok(n)
    }

    /// A pair of degrees `[p, q]`, each at most [`Limits::max_degree`].
    pub fn degree_pair(&self) -> Result<(usize, usize), ProblemError> {
        let items = self.items()?;
        match items.as_slice() {
            [a, b] => Ok((a.degree()?, b.degree()?)),
            _ => Err(self.error(format!(
                "expected two integers [r, s], found a list of {}",
                items.len()
            ))),
        }
    }

    /// A count of pieces (arcs) or points: a non-negative integer of at most
    /// [`Limits::max_points`].
    pub fn count(&self) -> Result<usize, ProblemError> {
        let n = self.usize()?;
        let max = self.limits.max_points;
        if n > max {
            return Err(self.error(format!(
                "{n} is above the limit of {max} (raise it with --max-points)"
            )));
        }
        Ok(n)
    }

    /// `Err` at this field when a result of `points` points (a mesh `rows` × `cols`, a
    /// curve) would exceed [`Limits::max_points`].
    pub fn check_points(&self, points: usize, what: &str) -> Result<(), ProblemError> {
        let max = self.limits.max_points;
        if points > max {
            return Err(self.error(format!(
                "{what} would have {points} control points, more than the limit of {max} (raise it with --max-points)"
            )));
        }
        Ok(())
    }

    /// `Err` at this field when a computed degree would exceed [`Limits::max_degree`];
    /// `what` says how it is computed ("elevating degree 2 by 1").
    pub fn check_degree(&self, degree: usize, what: &str) -> Result<(), ProblemError> {
        let max = self.limits.max_degree;
        if degree > max {
            return Err(self.error(format!(
                "{what} gives degree {degree}, above the limit of {max} (raise it with --max-degree)"
            )));
        }
        Ok(())
    }

    /// A boolean.
    pub fn bool(&self) -> Result<bool, ProblemError> {
        self.value.as_bool().ok_or_else(|| {
            self.error(format!(
                "expected true or false, found {}",
                kind(self.value)
            ))
        })
    }

    /// An exact number: a JSON integer, or a string of the grammar (`"5/6"`, `"sqrt2/2"`).
    /// JSON numbers with a fraction part are refused: write them as strings (`"0.1"`), since
    /// a JSON reader may already have rounded them.
    pub fn number(&self) -> Result<Quadratic, ProblemError> {
        match self.value {
            Value::Number(n) => {
                if let Some(i) = n.as_i64() {
                    let x = Quadratic::from_i64(i);
                    self.limits.check_digits(&x).map_err(|e| self.error(e))?;
                    Ok(x)
                } else if n.is_u64() {
                    read_number(&n.to_string(), self.limits)
                        .map_err(|e| self.error(with_flag(e.to_string())))
                } else {
                    Err(self.error(format!(
                        "the number {n} has a fraction part; write it as a string (\"{n}\") so it is read exactly"
                    )))
                }
            }
            Value::String(s) => read_number(s, self.limits)
                .map_err(|e| self.error(with_flag(format!("{}: {e}", quoted(s))))),
            other => Err(self.error(format!("expected a number, found {}", kind(other)))),
        }
    }

    /// An exact number in the scalar `S` of the problem.
    pub fn scalar<S: Scalar>(&self) -> Result<S, ProblemError> {
        let x = self.number()?;
        S::try_from_number(&x).map_err(|e| self.error(e.to_string()))
    }

    /// A list of numbers.
    pub fn scalars<S: Scalar>(&self) -> Result<Vec<S>, ProblemError> {
        self.items()?.iter().map(Field::scalar).collect()
    }

    /// A point `[x, y, z]` (any dimension ≥ 1).
    pub fn point<S: Scalar>(&self) -> Result<Point<S>, ProblemError> {
        let coords = self.items().map_err(|_| {
            self.error(format!(
                "expected a point [x, y, z], found {}",
                kind(self.value)
            ))
        })?;
        if coords.is_empty() {
            return Err(self.error("a point needs at least one coordinate"));
        }
        Ok(Point::new(
            coords.iter().map(Field::scalar).collect::<Result<_, _>>()?,
        ))
    }

    /// A list of points of one dimension.
    pub fn points<S: Scalar>(&self) -> Result<Vec<Point<S>>, ProblemError> {
        let items = self.items()?;
        if items.is_empty() {
            return Err(self.error("expected at least one point"));
        }
        let pts: Vec<Point<S>> = items.iter().map(Field::point).collect::<Result<_, _>>()?;
        same_dimension(&items, &pts)?;
        Ok(pts)
    }

    /// A mesh: a list of rows of points (outer index i along u), at most
    /// [`Limits::max_points`] points in all.
    pub fn mesh<S: Scalar>(&self) -> Result<Mesh<S>, ProblemError> {
        let rows = self.items()?;
        if rows.is_empty() {
            return Err(self.error("expected a mesh: a non-empty list of rows of points"));
        }
        let total: usize = rows
            .iter()
            .map(|r| r.value.as_array().map_or(0, Vec::len))
            .fold(0, usize::saturating_add);
        if total > self.limits.max_points {
            return Err(self.error(format!(
                "a mesh of {total} points is larger than the limit of {} (raise it with --max-points)",
                self.limits.max_points
            )));
        }
        let mut out = Vec::with_capacity(rows.len());
        let mut dim = None;
        for (i, r) in rows.iter().enumerate() {
            let pts = r.points::<S>()?;
            if let Some(first) = out.first().map(Vec::len) {
                if pts.len() != first {
                    return Err(r.error(format!(
                        "row {i} has {} points but row 0 has {first}: a mesh needs rows of equal length",
                        pts.len()
                    )));
                }
            }
            let d = pts.first().map_or(0, Point::dim);
            if let Some(d0) = dim {
                if d != d0 {
                    return Err(r.error(format!(
                        "points of dimension {d} here, but row 0 has dimension {d0}"
                    )));
                }
            }
            dim = Some(d);
            out.push(pts);
        }
        Mesh::mesh(out).map_err(|e| self.error(e.to_string()))
    }

    /// A grid of numbers (weights), rows like a mesh.
    pub fn number_grid<S: Scalar>(&self) -> Result<Grid<S>, ProblemError> {
        let rows = self.items()?;
        let rows: Vec<Vec<S>> = rows.iter().map(Field::scalars).collect::<Result<_, _>>()?;
        Grid::from_rows(rows).map_err(|e| self.error(e.to_string()))
    }

    /// A pair `[a, b]`.
    pub fn pair<S: Scalar>(&self) -> Result<(S, S), ProblemError> {
        let v = self.scalars::<S>()?;
        match <[S; 2]>::try_from(v) {
            Ok([a, b]) => Ok((a, b)),
            Err(v) => Err(self.error(format!("expected two numbers [a, b], found {}", v.len()))),
        }
    }

    /// A pair of non-negative integers `[r, s]` (bidegrees, orders).
    pub fn usize_pair(&self) -> Result<(usize, usize), ProblemError> {
        let items = self.items()?;
        match items.as_slice() {
            [a, b] => Ok((a.usize()?, b.usize()?)),
            _ => Err(self.error(format!(
                "expected two integers [r, s], found a list of {}",
                items.len()
            ))),
        }
    }

    /// An expression string, read under the limits: its degree is at most
    /// [`Limits::max_degree`] and its coefficients have at most [`Limits::max_digits`] digits.
    pub fn expr(&self) -> Result<Expr, ProblemError> {
        let text = self.str()?;
        let q = quoted(text);
        let e = parse_expr_with(text, &self.limits.grammar())
            .map_err(|e| self.error(with_flag(format!("{q}: {e}"))))?;
        let polys = match &e {
            Expr::Scalar(p) => std::slice::from_ref(p),
            Expr::Vector(m) => m.components(),
        };
        for p in polys {
            let degree = usize::try_from(p.degree()).unwrap_or(usize::MAX);
            if degree > self.limits.max_degree {
                return Err(self.error(format!(
                    "{q}: degree {degree} is above the limit of {} (raise it with --max-degree)",
                    self.limits.max_degree
                )));
            }
            for (_, c) in p.terms() {
                self.limits
                    .check_digits(c)
                    .map_err(|m| self.error(format!("{q}: {m}")))?;
            }
        }
        Ok(e)
    }

    /// A polynomial map given as an expression string, e.g. `"(u, 0, u^2)"`.
    pub fn vec_poly<S: Scalar>(&self) -> Result<VecPoly<S>, ProblemError> {
        let e = self.expr()?;
        e.vector::<S>()
            .map_err(|e| self.error(format!("{}: {e}", quoted(self.str().unwrap_or_default()))))
    }
}

/// Points of a list must share one dimension.
fn same_dimension<S: Scalar>(items: &[Field<'_>], pts: &[Point<S>]) -> Result<(), ProblemError> {
    let d0 = pts.first().map_or(0, Point::dim);
    for (f, p) in items.iter().zip(pts) {
        if p.dim() != d0 {
            return Err(f.error(format!(
                "this point has {} coordinates but the first has {d0}",
                p.dim()
            )));
        }
    }
    Ok(())
}

/// A string quoted for an error message, cut to its first 40 characters so that the
/// message stays one short line whatever the input holds.
pub fn quoted(s: &str) -> String {
    const SHOWN: usize = 40;
    let mut chars = s.chars();
    let head: String = chars.by_ref().take(SHOWN).collect();
    if chars.next().is_some() {
        format!("{:?}", head + "...")
    } else {
        format!("{s:?}")
    }
}

/// The JSON kind of a value, in words.
pub fn kind(v: &Value) -> String {
    match v {
        Value::Null => "null".into(),
        Value::Bool(b) => format!("{b}"),
        Value::Number(n) => format!("the number {n}"),
        Value::String(s) => format!("the string {}", quoted(s)),
        Value::Array(a) => format!("a list of {}", a.len()),
        Value::Object(_) => "an object".into(),
    }
}

/// A curve as the problem gives it.
#[derive(Debug, Clone, PartialEq)]
pub enum CurveIn<S: Scalar> {
    /// `{"bezier": [...], "weights": [...]}`.
    Bezier {
        /// Control polygon.
        points: Vec<Point<S>>,
        /// Weights (rational curve) or `None`.
        weights: Option<Vec<S>>,
    },
    /// `{"bspline": [...], "degree": p, "knots": [...], "weights": [...]}`.
    BSpline {
        /// Control polygon.
        points: Vec<Point<S>>,
        /// Degree.
        degree: usize,
        /// Knots, in either convention (told apart by length).
        knots: Vec<S>,
        /// Weights (NURBS) or `None`.
        weights: Option<Vec<S>>,
    },
    /// `{"expr": "(u, 0, u^2)"}`: a polynomial map in one variable.
    Expr(VecPoly<S>),
}

/// A surface as the problem gives it.
#[derive(Debug, Clone, PartialEq)]
pub enum SurfaceIn<S: Scalar> {
    /// `{"bezier": [[...]], "weights": [[...]]}`.
    Bezier {
        /// Control mesh.
        mesh: Mesh<S>,
        /// Weights or `None`.
        weights: Option<Grid<S>>,
    },
    /// `{"bspline": [[...]], "degree": [p, q], "knots": [[...], [...]], "weights": [[...]]}`.
    BSpline {
        /// Control mesh.
        mesh: Mesh<S>,
        /// Degrees (p, q).
        degree: (usize, usize),
        /// Knots in u and in v.
        knots: (Vec<S>, Vec<S>),
        /// Weights or `None`.
        weights: Option<Grid<S>>,
    },
    /// `{"expr": "(u, v, u v)"}`: a polynomial map in u and v.
    Expr(VecPoly<S>),
}

impl<'a> Field<'a> {
    /// A curve in one of its three shapes.
    pub fn curve<S: Scalar>(&self) -> Result<CurveIn<S>, ProblemError> {
        if let Some(pts) = self.get("bezier") {
            let points = pts.points()?;
            let weights = self.get("weights").map(|w| w.scalars()).transpose()?;
            check_weight_count(self, weights.as_deref(), points.len())?;
            return Ok(CurveIn::Bezier { points, weights });
        }
        if let Some(pts) = self.get("bspline") {
            let points = pts.points()?;
            let degree = self.req("degree")?.degree()?;
            let knots = self.req("knots")?.scalars()?;
            let weights = self.get("weights").map(|w| w.scalars()).transpose()?;
            check_weight_count(self, weights.as_deref(), points.len())?;
            return Ok(CurveIn::BSpline {
                points,
                degree,
                knots,
                weights,
            });
        }
        if let Some(e) = self.get("expr") {
            return Ok(CurveIn::Expr(e.vec_poly()?));
        }
        Err(self.error(
            "expected a curve: {\"bezier\": [...]}, {\"bspline\": [...], \"degree\": p, \"knots\": [...]} or {\"expr\": \"(u, 0, u^2)\"}",
        ))
    }

    /// A surface in one of its three shapes.
    pub fn surface<S: Scalar>(&self) -> Result<SurfaceIn<S>, ProblemError> {
        if let Some(m) = self.get("bezier") {
            let mesh = m.mesh()?;
            let weights = self.get("weights").map(|w| w.number_grid()).transpose()?;
            check_weight_shape(self, weights.as_ref(), &mesh)?;
            return Ok(SurfaceIn::Bezier { mesh, weights });
        }
        if let Some(m) = self.get("bspline") {
            let mesh = m.mesh()?;
            let degree = self.req("degree")?.degree_pair()?;
            let knots_field = self.req("knots")?;
            let lists = knots_field.items()?;
            let (ku, kv) = match lists.as_slice() {
                [a, b] => (a.scalars()?, b.scalars()?),
                _ => {
                    return Err(knots_field.error(format!(
                        "expected two knot vectors [[u knots], [v knots]], found a list of {}",
                        lists.len()
                    )))
                }
            };
            let weights = self.get("weights").map(|w| w.number_grid()).transpose()?;
            check_weight_shape(self, weights.as_ref(), &mesh)?;
            return Ok(SurfaceIn::BSpline {
                mesh,
                degree,
                knots: (ku, kv),
                weights,
            });
        }
        if let Some(e) = self.get("expr") {
            return Ok(SurfaceIn::Expr(e.vec_poly()?));
        }
        Err(self.error(
            "expected a surface: {\"bezier\": [[...]]}, {\"bspline\": [[...]], \"degree\": [p, q], \"knots\": [[...], [...]]} or {\"expr\": \"(u, v, u v)\"}",
        ))
    }
}

fn check_weight_count<S>(
    f: &Field<'_>,
    weights: Option<&[S]>,
    n: usize,
) -> Result<(), ProblemError> {
    match weights {
        Some(w) if w.len() != n => Err(ProblemError::at(
            f.child_path("weights"),
            format!("{} weights for {n} control points", w.len()),
        )),
        _ => Ok(()),
    }
}

fn check_weight_shape<S: Scalar>(
    f: &Field<'_>,
    weights: Option<&Grid<S>>,
    mesh: &Mesh<S>,
) -> Result<(), ProblemError> {
    match weights {
        Some(w) if (w.rows(), w.cols()) != (mesh.rows(), mesh.cols()) => Err(ProblemError::at(
            f.child_path("weights"),
            format!(
                "the weights form a {}x{} grid but the mesh is {}x{}",
                w.rows(),
                w.cols(),
                mesh.rows(),
                mesh.cols()
            ),
        )),
        _ => Ok(()),
    }
}
