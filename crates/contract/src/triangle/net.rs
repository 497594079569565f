//! The shape of a triangular Bézier patch: `{"triangle": [[b_{n,0,0}], [b_{n-1,1,0},
//! b_{n-1,0,1}], ..., [b_{0,n,0}, ..., b_{0,0,n}]]}`, row m holding the m + 1 points
//! b_{n-m, m-k, k}, k = 0, ..., m (the order of `cagd_triangle::multi_indices`); the degree n is
//! the number of rows less one. The same shape in problems and in answers, so an answer feeds
//! back.

use crate::message::read::Read;
use crate::spec::{limits, member_value, List, Points, Typed};
use crate::value::exact::Number;
use cagd_linalg::Point;
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
}
