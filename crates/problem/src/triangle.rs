//! The shape of a triangular Bézier patch: `{"triangle": [[b_{n,0,0}], [b_{n-1,1,0},
//! b_{n-1,0,1}], ..., [b_{0,n,0}, ..., b_{0,0,n}]]}`, row m holding the m + 1 points
//! b_{n-m, m-k, k}, k = 0, ..., m (the order of `cagd_triangle::multi_indices`); the degree n is
//! the number of rows less one. The same shape in problems and in answers, so an answer feeds
//! back.

use crate::message::read::Read;
use crate::spec::{limits, member_value, List, Points, Typed};
use crate::value::{exact_points, Exact, ExactScalar, Number};
use crate::ProblemError;
use cagd_linalg::Point;
use cagd_poly::{Poly, Var, VecPoly};
use cagd_triangle::TriangularPatch;
use serde::de::Deserializer;
use serde::Deserialize;

/// A triangular Bézier patch as written: its rows of control points (row m has m + 1), and
/// for a rational patch the rows of its weights w_{ijk} (the same shape).
#[derive(Debug, Clone, PartialEq)]
pub struct TriangleIn(pub Vec<Vec<Point<Number>>>, pub Option<Vec<Vec<Number>>>);

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawTriangle {
    triangle: serde_json::Value,
    #[serde(default)]
    weights: Option<serde_json::Value>,
}

impl<'de> Deserialize<'de> for TriangleIn {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let raw = RawTriangle::deserialize(d)?;
        let mut t = read(&raw.triangle).map_err(Typed::serde)?;
        if let Some(w) = &raw.weights {
            t.1 = Some(read_weights(w, t.0.len()).map_err(Typed::serde)?);
        }
        Ok(t)
    }
}

/// The rows of the weights of a rational triangular net of `rows` rows: row m of m + 1
/// numbers.
fn read_weights(v: &serde_json::Value, rows: usize) -> Result<Vec<Vec<Number>>, Typed> {
    let List(ws) = member_value::<List<List<crate::spec::Num>>>("weights", v)?;
    if ws.len() != rows {
        return Err(Typed::from(Read::TriangleWeightRows {
            found: ws.len(),
            rows,
        })
        .below("weights"));
    }
    let mut out = Vec::with_capacity(rows);
    for (m, List(row)) in ws.into_iter().enumerate() {
        if row.len() != m + 1 {
            return Err(Typed::from(Read::TriangleWeightRow {
                row: m,
                holds: m + 1,
                found: row.len(),
            })
            .below(&format!("weights[{m}]")));
        }
        out.push(row.into_iter().map(|x| x.0).collect());
    }
    Ok(out)
}

/// The rows of a triangular net, checked: row m of m + 1 points, one dimension, the degree and
/// the points within the limits.
fn read(v: &serde_json::Value) -> Result<TriangleIn, Typed> {
    let List(rows) = member_value::<List<Points>>("triangle", v)?;
    let limits = limits();
    let degree = rows.len().saturating_sub(1);
    if degree > limits.max_degree {
        return Err(Typed::from(Read::TriangleDegree {
            rows: rows.len(),
            degree,
            max: limits.max_degree,
        })
        .below("triangle"));
    }
    let total: usize = rows.iter().map(|r| r.0.len()).sum();
    if total > limits.max_points {
        return Err(Typed::from(Read::TriangleLarger {
            points: total,
            max: limits.max_points,
        })
        .below("triangle"));
    }
    let dim = rows.first().and_then(|r| r.0.first()).map_or(0, Point::dim);
    let mut out = Vec::with_capacity(rows.len());
    for (m, Points(row)) in rows.into_iter().enumerate() {
        if row.len() != m + 1 {
            return Err(Typed::from(Read::TriangleRow {
                row: m,
                holds: m + 1,
                found: row.len(),
            })
            .below(&format!("triangle[{m}]")));
        }
        if let Some(p) = row.iter().find(|p| p.dim() != dim) {
            return Err(Typed::from(Read::RowDim {
                found: p.dim(),
                first: dim,
            })
            .below(&format!("triangle[{m}]")));
        }
        out.push(row);
    }
    Ok(TriangleIn(out, None))
}

impl TriangleIn {
    /// The degree n: the rows less one.
    pub fn degree(&self) -> usize {
        self.0.len().saturating_sub(1)
    }

    /// The patch in the scalar `S`; a rational patch as its homogeneous net (w b, w), points
    /// of one more coordinate, and `true`.
    pub(crate) fn patch<S: ExactScalar>(
        &self,
        path: &str,
    ) -> Result<(TriangularPatch<S>, bool), ProblemError> {
        let mut points = Vec::new();
        for row in &self.0 {
            points.extend(crate::convert::convert_points::<S>(row, path)?);
        }
        if let Some(weights) = &self.1 {
            let mut homogeneous = Vec::with_capacity(points.len());
            let indices = cagd_triangle::multi_indices(self.degree());
            for ((p, w), (i, j, k)) in points.iter().zip(weights.iter().flatten()).zip(indices) {
                let w = crate::convert::convert::<S>(w, path)?;
                if w.is_zero() {
                    return Err(ProblemError::at(
                        format!("{path}.weights"),
                        Read::TriangleWeightZero { i, j, k },
                    ));
                }
                let mut c: Vec<S> = p.coords().iter().map(|x| x.mul_ref(&w)).collect();
                c.push(w);
                homogeneous.push(Point::new(c));
            }
            points = homogeneous;
        }
        TriangularPatch::try_new(self.degree(), points)
            .map(|p| (p, self.1.is_some()))
            .map_err(|e| ProblemError::at(path, e))
    }
}

/// A patch as the value of an answer: `{"triangle": [[...], ...]}`, the shape a problem reads.
pub(crate) fn exact_triangle<S: ExactScalar>(patch: &TriangularPatch<S>) -> Exact {
    let n = patch.degree();
    let mut rows = Vec::with_capacity(n + 1);
    let mut start = 0;
    for m in 0..=n {
        let row = patch.points().get(start..start + m + 1).unwrap_or_default();
        rows.push(Exact::Points(exact_points(row)));
        start += m + 1;
    }
    Exact::Object(vec![("triangle".to_string(), Exact::List(rows))])
}

/// The value of a net as written, for the answer key's inputs: its rows (and, for a rational
/// patch, `{"triangle": rows, "weights": rows}`).
pub(crate) fn exact_input(t: &TriangleIn) -> Exact {
    let rows = Exact::List(t.0.iter().map(|r| Exact::Points(r.clone())).collect());
    match &t.1 {
        None => rows,
        Some(w) => Exact::Object(vec![
            ("triangle".to_string(), rows),
            ("weights".to_string(), weight_rows(w)),
        ]),
    }
}

/// Rows of weights as a value: a list of rows, each a list of its numbers (`[[1], [2, 2],
/// [1, 3, 1]]`; as tuples they read like points).
pub(crate) fn weight_rows(w: &[Vec<Number>]) -> Exact {
    Exact::List(
        w.iter()
            .map(|r| Exact::List(r.iter().cloned().map(Exact::Number).collect()))
            .collect(),
    )
}

/// A triangular patch among the values of an answer or the inputs of a problem
/// (`{"triangle": rows}`, or its rows) as a polynomial map on the unit square, for figures:
/// b(u (1 - v), v), which maps the square onto the domain triangle (the edge v = 1 collapsed
/// to the corner (0, 1)) and so draws the same patch; `None` for any other value.
pub fn square_map(value: &Exact) -> Option<VecPoly<Number>> {
    let rows = match value {
        Exact::Object(kv) => match kv.as_slice() {
            [(k, Exact::List(rows))] if k == "triangle" => rows,
            _ => return None,
        },
        Exact::List(rows) => rows,
        _ => return None,
    };
    let mut points = Vec::new();
    for (m, row) in rows.iter().enumerate() {
        match row {
            Exact::Points(ps) if ps.len() == m + 1 => points.extend(ps.iter().cloned()),
            _ => return None,
        }
    }
    let patch = TriangularPatch::try_new(rows.len().checked_sub(1)?, points).ok()?;
    let f = patch.closed_form();
    let squeezed = Poly::var(Var::U)
        * (Poly::constant(<Number as num_traits::One>::one()) - Poly::var(Var::V));
    Some(VecPoly::new(
        f.components()
            .iter()
            .map(|p| p.substitute(Var::U, &squeezed))
            .collect(),
    ))
}

/// A triangular patch among the values of an answer or the inputs of a problem, polynomial
/// ([`square_map`]) or rational (`{"triangle": rows, "weights": rows}`), as a surface on the
/// unit square for figures: b(u (1 - v), v). For a rational patch the homogeneous closed form
/// H(u (1 - v), v) has degree ≤ n in u and in v, so it is a rational Bézier patch of bidegree
/// (n, n) whose homogeneous mesh is the Bernstein coefficients of each component
/// (`BezierSurface::graph`); `None` for any other value.
pub fn square_surface(value: &Exact) -> Option<crate::any::AnySurface<Number>> {
    if let Some(m) = square_map(value) {
        return Some(crate::any::AnySurface::Map(m));
    }
    let Exact::Object(kv) = value else {
        return None;
    };
    let (rows, weights) = match kv.as_slice() {
        [(k, Exact::List(rows)), (w, Exact::List(weights))]
            if k == "triangle" && w == "weights" =>
        {
            (rows, weights)
        }
        _ => return None,
    };
    let points = rows
        .iter()
        .map(|r| match r {
            Exact::Points(ps) => Some(ps.clone()),
            _ => None,
        })
        .collect::<Option<Vec<_>>>()?;
    let weights = weights
        .iter()
        .map(|r| match r {
            Exact::List(ws) => ws
                .iter()
                .map(|w| match w {
                    Exact::Number(x) => Some(x.clone()),
                    _ => None,
                })
                .collect(),
            _ => None,
        })
        .collect::<Option<Vec<_>>>()?;
    let (h, _) = TriangleIn(points, Some(weights)).patch::<Number>("").ok()?;
    let n = h.degree();
    let squeezed = Poly::var(Var::U)
        * (Poly::constant(<Number as num_traits::One>::one()) - Poly::var(Var::V));
    let meshes = h
        .closed_form()
        .components()
        .iter()
        .map(|p| cagd_surface::BezierSurface::graph(&p.substitute(Var::U, &squeezed), n, n).ok())
        .collect::<Option<Vec<_>>>()?;
    let rows = (0..=n)
        .map(|i| {
            (0..=n)
                .map(|j| {
                    meshes
                        .iter()
                        .map(|m| m.mesh().get(i, j).and_then(|p| p.coords().last().cloned()))
                        .collect::<Option<Vec<_>>>()
                        .map(Point::new)
                })
                .collect::<Option<Vec<_>>>()
        })
        .collect::<Option<Vec<_>>>()?;
    let mesh = cagd_surface::Mesh::mesh(rows).ok()?;
    cagd_surface::RationalBezierSurface::from_homogeneous(&mesh)
        .ok()
        .map(crate::any::AnySurface::RationalBezier)
}
