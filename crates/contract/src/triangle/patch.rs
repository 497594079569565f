//! A triangular net as a patch in the scalar of the solve (a rational one on its homogeneous
//! net), as the value of an answer, and as a surface on the unit square for figures.

use super::net::TriangleIn;
use crate::message::read::Read;
use crate::value::{exact_points, Exact, ExactScalar, Number, Quantity};
use crate::ProblemError;
use cagd_linalg::Point;
use cagd_poly::{Poly, Var, VecPoly};
use cagd_triangle::TriangularPatch;

impl TriangleIn {
    /// The patch in the scalar `S`; a rational patch as its homogeneous net (w b, w), points
    /// of one more coordinate, and `true`.
    pub fn patch<S: ExactScalar>(
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
pub fn exact_triangle<S: ExactScalar>(patch: &TriangularPatch<S>) -> Exact {
    let n = patch.degree();
    let mut rows = Vec::with_capacity(n + 1);
    let mut start = 0;
    for m in 0..=n {
        let row = patch.points().get(start..start + m + 1).unwrap_or_default();
        rows.push(Exact::Points(exact_points(row)));
        start += m + 1;
    }
    Exact::Object(vec![(Quantity::Triangle, Exact::List(rows))])
}

/// The value of a net as written, for the answer key's inputs: its rows (and, for a rational
/// patch, `{"triangle": rows, "weights": rows}`).
pub fn exact_input(t: &TriangleIn) -> Exact {
    let rows = Exact::List(t.0.iter().map(|r| Exact::Points(r.clone())).collect());
    match &t.1 {
        None => rows,
        Some(w) => Exact::Object(vec![
            (Quantity::Triangle, rows),
            (Quantity::Weights, weight_rows(w)),
        ]),
    }
}

/// Rows of weights as a value: a list of rows, each a list of its numbers (`[[1], [2, 2],
/// [1, 3, 1]]`; as tuples they read like points).
pub fn weight_rows(w: &[Vec<Number>]) -> Exact {
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
            [(Quantity::Triangle, Exact::List(rows))] => rows,
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
        [(Quantity::Triangle, Exact::List(rows)), (Quantity::Weights, Exact::List(weights))] => {
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
