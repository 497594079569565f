//! A surface as written (`bezier`, `bspline`, `expr`), checked.

use super::context::{expected, fail, Typed};
use super::curve::{numbers, split_homogeneous};
use super::number::{json_number, Degree};
use super::points::{GridIn, List, MeshIn};
use super::shape::{
    bezier_degree, generic_degree, generic_dim, generic_letter, generic_number, generic_point,
    generic_weights, member, missing, Deferred, RawShape,
};
use crate::input::{quoted, SurfaceIn};
use crate::message::found::Found;
use crate::message::read::{Read, Wanted};
use crate::value::exact::Number;
use cagd_surface::{Grid, Mesh, SurfaceError};
use serde::de::{self, Deserializer, SeqAccess, Visitor};
use serde::Deserialize;
use std::fmt;

pub(super) fn weights_shape(w: &Grid<Number>, mesh: &Mesh<Number>) -> Result<(), Typed> {
    if (w.rows(), w.cols()) != (mesh.rows(), mesh.cols()) {
        return Err(Typed::from(SurfaceError::WeightShape {
            mesh: (mesh.rows(), mesh.cols()),
            weights: (w.rows(), w.cols()),
        })
        .below("weights"));
    }
    Ok(())
}

impl<'de> Deserialize<'de> for SurfaceIn<Number> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let raw = RawShape::deserialize(d)?;
        surface(raw).map_err(Typed::serde)
    }
}

/// Two degrees `[p, q]`, each within the degree limit.
pub(super) struct DegreePair(usize, usize);

impl<'de> Deserialize<'de> for DegreePair {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = DegreePair;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("two degrees")
            }
            fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<DegreePair, A::Error> {
                let n = seq.size_hint();
                let mut items = Vec::new();
                while let Some(Degree(x)) = seq.next_element()? {
                    items.push(x);
                    if items.len() > 2 {
                        break;
                    }
                }
                match items.as_slice() {
                    [a, b] => Ok(DegreePair(*a, *b)),
                    _ => Err(fail(Read::TwoIntegers {
                        found: n.unwrap_or(items.len()),
                    })),
                }
            }
            refuse_others!(Wanted::List);
            refuse_numbers!(Wanted::List);
        }
        d.deserialize_any(V)
    }
}

/// A mesh of homogeneous points written at `key`, row by row: its affine points (or control
/// vectors) and its weights (see [`split_homogeneous`]).
fn split_mesh(key: &str, mesh: &Mesh<Number>) -> Result<(Mesh<Number>, Grid<Number>), Typed> {
    let mut points = Vec::with_capacity(mesh.rows());
    let mut weights = Vec::with_capacity(mesh.rows());
    for i in 0..mesh.rows() {
        let row = mesh.row(i).unwrap_or_default().to_vec();
        let (p, w) = split_homogeneous(&format!("{key}[{i}]"), row)?;
        points.push(p);
        weights.push(w);
    }
    let fail = |e: SurfaceError| Typed::from(e).below(key);
    Ok((
        Grid::from_rows(points).map_err(fail)?,
        Grid::from_rows(weights).map_err(fail)?,
    ))
}

pub(super) fn surface(mut raw: RawShape<MeshIn>) -> Result<SurfaceIn<Number>, Typed> {
    raw.unused_points_read()?;
    if raw.homogeneous.is_some() && raw.bezier.is_none() && raw.bspline.is_none() {
        return Err(Typed::from(Read::HomogeneousWithoutPoints).below("homogeneous"));
    }
    if let Some(letter) = &raw.generic {
        let letter = generic_letter("generic", letter)?;
        let DegreePair(m, n) = member(
            "degree",
            raw.degree.as_ref().ok_or_else(|| missing("degree"))?,
        )?;
        let (m, n) = (
            generic_degree(m, "degree[0]")?,
            generic_degree(n, "degree[1]")?,
        );
        let dim = generic_dim(&raw)?;
        let mesh = Grid::from_fn(m + 1, n + 1, |i, j| generic_point(&letter, dim, &[i, j]));
        let weights = match (generic_weights(&raw)?, &raw.weights) {
            (Some(w), _) => Some(Grid::from_fn(m + 1, n + 1, |i, j| {
                generic_number(&w, &[i, j])
            })),
            (None, Some(w)) => {
                let GridIn(g) = member("weights", w)?;
                weights_shape(&g, &mesh)?;
                Some(g)
            }
            (None, None) => None,
        };
        return Ok(SurfaceIn::Bezier { mesh, weights });
    }
    let homogeneous = raw.homogeneous == Some(true);
    if homogeneous && raw.weights.is_some() {
        return Err(Typed::from(Read::HomogeneousWithWeights).below("weights"));
    }
    let weights = |mesh: &mut Mesh<Number>, key: &str| -> Result<Option<Grid<Number>>, Typed> {
        if homogeneous {
            super::context::note_homogeneous();
            let (m, w) = split_mesh(key, mesh)?;
            *mesh = m;
            return Ok(Some(w));
        }
        let w = raw
            .weights
            .as_ref()
            .map(|w| member::<GridIn>("weights", w).map(|g| g.0))
            .transpose()?;
        if let Some(w) = &w {
            weights_shape(w, mesh)?;
        }
        Ok(w)
    };
    if let Some(m) = raw.bezier.take() {
        let MeshIn(mut mesh) = m.points("bezier")?;
        bezier_degree(mesh.rows(), |points, degree, max| Read::PatchDegreeU {
            points,
            degree,
            max,
        })?;
        bezier_degree(mesh.cols(), |points, degree, max| Read::PatchDegreeV {
            points,
            degree,
            max,
        })?;
        let weights = weights(&mut mesh, "bezier")?;
        return Ok(SurfaceIn::Bezier { mesh, weights });
    }
    if let Some(m) = raw.bspline.take() {
        let MeshIn(mut mesh) = m.points("bspline")?;
        let DegreePair(p, q) = member(
            "degree",
            raw.degree.as_ref().ok_or_else(|| missing("degree"))?,
        )?;
        let knots = raw.knots.as_ref().ok_or_else(|| missing("knots"))?;
        let List(lists) = member::<List<Deferred>>("knots", knots)?;
        let (ku, kv) = match lists.as_slice() {
            [a, b] => (numbers("knots[0]", a)?, numbers("knots[1]", b)?),
            _ => {
                return Err(Typed::from(Read::TwoKnotVectors { found: lists.len() }).below("knots"))
            }
        };
        let weights = weights(&mut mesh, "bspline")?;
        return Ok(SurfaceIn::BSpline {
            mesh,
            degree: (p, q),
            knots: (ku, kv),
            weights,
        });
    }
    if let Some(e) = raw.expr {
        return e
            .vector::<Number>()
            .map(SurfaceIn::Expr)
            .map_err(Typed::from);
    }
    Err(Read::NotSurface.into())
}
