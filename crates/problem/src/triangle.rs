//! The shape of a triangular Bézier patch: `{"triangle": [[b_{n,0,0}], [b_{n-1,1,0},
//! b_{n-1,0,1}], ..., [b_{0,n,0}, ..., b_{0,0,n}]]}`, row m holding the m + 1 points
//! b_{n-m, m-k, k}, k = 0, ..., m (the order of `cagd_triangle::multi_indices`); the degree n is
//! the number of rows less one. The same shape in problems and in answers, so an answer feeds
//! back.

use crate::limits::{tagged, Limit};
use crate::spec::{below, limits, member, List, Points};
use crate::value::{exact_points, Exact, ExactScalar, Number};
use crate::ProblemError;
use cagd_linalg::Point;
use cagd_poly::{Poly, Var, VecPoly};
use cagd_triangle::TriangularPatch;
use serde::de::{self, Deserializer};
use serde::Deserialize;

/// A triangular Bézier patch as written: its rows of control points (row m has m + 1).
#[derive(Debug, Clone, PartialEq)]
pub struct TriangleIn(pub Vec<Vec<Point<Number>>>);

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawTriangle {
    triangle: serde_json::Value,
}

impl<'de> Deserialize<'de> for TriangleIn {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let raw = RawTriangle::deserialize(d)?;
        read(&raw.triangle).map_err(de::Error::custom)
    }
}

/// The rows of a triangular net, checked: row m of m + 1 points, one dimension, the degree and
/// the points within the limits.
fn read(v: &serde_json::Value) -> Result<TriangleIn, String> {
    let List(rows) = member::<List<Points>>("triangle", v)?;
    let limits = limits();
    let degree = rows.len().saturating_sub(1);
    if degree > limits.max_degree {
        return Err(below(
            "triangle",
            tagged(
                format!(
                    "{} rows make a triangular patch of degree {degree}, above the limit of {} for degrees",
                    rows.len(),
                    limits.max_degree
                ),
                Limit::Degree,
            ),
        ));
    }
    let total: usize = rows.iter().map(|r| r.0.len()).sum();
    if total > limits.max_points {
        return Err(below(
            "triangle",
            tagged(
                format!(
                    "a triangular net of {total} points is larger than the limit of {}",
                    limits.max_points
                ),
                Limit::Points,
            ),
        ));
    }
    let dim = rows.first().and_then(|r| r.0.first()).map_or(0, Point::dim);
    let mut out = Vec::with_capacity(rows.len());
    for (m, Points(row)) in rows.into_iter().enumerate() {
        if row.len() != m + 1 {
            return Err(below(
                &format!("triangle[{m}]"),
                format!(
                    "row {m} of a triangular net holds {} points (b_{{n-{m},{m}-k,k}}, k = 0, ..., {m}), found {}",
                    m + 1,
                    row.len()
                ),
            ));
        }
        if let Some(p) = row.iter().find(|p| p.dim() != dim) {
            return Err(below(
                &format!("triangle[{m}]"),
                format!(
                    "points of dimension {} here, but row 0 has dimension {dim}",
                    p.dim()
                ),
            ));
        }
        out.push(row);
    }
    Ok(TriangleIn(out))
}

impl TriangleIn {
    /// The degree n: the rows less one.
    pub fn degree(&self) -> usize {
        self.0.len().saturating_sub(1)
    }

    /// The patch in the scalar `S`.
    pub(crate) fn patch<S: ExactScalar>(
        &self,
        path: &str,
    ) -> Result<TriangularPatch<S>, ProblemError> {
        let mut points = Vec::new();
        for row in &self.0 {
            points.extend(crate::ops::convert_points::<S>(row, path)?);
        }
        TriangularPatch::try_new(self.degree(), points)
            .map_err(|e| ProblemError::at(path, e.to_string()))
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

/// The value of a net as written, for the answer key's inputs: its rows.
pub(crate) fn exact_input(t: &TriangleIn) -> Exact {
    Exact::List(t.0.iter().map(|r| Exact::Points(r.clone())).collect())
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
