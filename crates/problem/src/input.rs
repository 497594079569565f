//! Reading problems: a cursor over the JSON that knows its path, and exact readers for numbers,
//! points, meshes, curves and surfaces (the shapes of `docs/format.md`).

use crate::ProblemError;
use cagd_linalg::Point;
use cagd_poly::{parse_expr, VecPoly};
use cagd_scalar::{parse_number, Quadratic, Scalar};
use cagd_surface::{Grid, Mesh};
use serde_json::Value;

/// A JSON value and its path in the problem, for error messages.
#[derive(Clone, Debug)]
pub struct Field<'a> {
    /// The value.
    pub value: &'a Value,
    path: String,
}

impl<'a> Field<'a> {
    /// The root of a problem.
    pub fn root(value: &'a Value) -> Self {
        Field {
            value,
            path: String::new(),
        }
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

    /// The items of an array.
    pub fn items(&self) -> Result<Vec<Field<'a>>, ProblemError> {
        let arr = self
            .value
            .as_array()
            .ok_or_else(|| self.error(format!("expected a list, found {}", kind(self.value))))?;
        Ok(arr
            .iter()
            .enumerate()
            .map(|(i, v)| Field {
                value: v,
                path: format!("{}[{i}]", self.path),
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
                    Ok(Quadratic::from_i64(i))
                } else if n.is_u64() {
                    parse_number(&n.to_string()).map_err(|e| self.error(e.to_string()))
                } else {
                    Err(self.error(format!(
                        "the number {n} has a fraction part; write it as a string (\"{n}\") so it is read exactly"
                    )))
                }
            }
            Value::String(s) => parse_number(s).map_err(|e| self.error(format!("{s:?}: {e}"))),
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

    /// A mesh: a list of rows of points (outer index i along u).
    pub fn mesh<S: Scalar>(&self) -> Result<Mesh<S>, ProblemError> {
        let rows = self.items()?;
        if rows.is_empty() {
            return Err(self.error("expected a mesh: a non-empty list of rows of points"));
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

    /// A polynomial map given as an expression string, e.g. `"(u, 0, u^2)"`.
    pub fn vec_poly<S: Scalar>(&self) -> Result<VecPoly<S>, ProblemError> {
        let text = self.str()?;
        let e = parse_expr(text).map_err(|e| self.error(format!("{text:?}: {e}")))?;
        e.vector::<S>()
            .map_err(|e| self.error(format!("{text:?}: {e}")))
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

/// The JSON kind of a value, in words.
pub fn kind(v: &Value) -> String {
    match v {
        Value::Null => "null".into(),
        Value::Bool(b) => format!("{b}"),
        Value::Number(n) => format!("the number {n}"),
        Value::String(s) => format!("the string {s:?}"),
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
            let degree = self.req("degree")?.usize()?;
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
            let degree = self.req("degree")?.usize_pair()?;
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
