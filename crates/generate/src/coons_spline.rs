//! B-spline Coons surfaces (notes, chapter 6, §5): "usando el algoritmo de inserción para que
//! las tres superficies auxiliares tengan los mismos nudos. Primero elevaríamos el grado de las
//! tres parametrizaciones hasta que todas alcancen el bigrado (m, n) y luego insertaríamos los
//! nudos no comunes".

use crate::common::OneField;
use crate::coons::quadrilateral;
use crate::{make_compatible, GenerateError, Note, Step};
use cagd_bspline::{BSplineCurve, KnotVector};
use cagd_linalg::Point;
use cagd_record::Record;
use cagd_scalar::Scalar;
use cagd_spline_surface::{BSplineSurface, Direction};
use cagd_surface::Mesh;

/// A B-spline Coons surface, with the three auxiliary surfaces on its knots.
#[derive(Clone, PartialEq, Debug)]
pub struct CoonsBSpline<S: Scalar> {
    /// The corner a.
    pub a: Point<S>,
    /// The corner b.
    pub b: Point<S>,
    /// The corner c.
    pub c: Point<S>,
    /// The corner d.
    pub d: Point<S>,
    /// The boundary curves with common degrees and knots: c1, c2 in u, d1, d2 in v.
    pub curves: [BSplineCurve<S>; 4],
    /// The ruled surface between c1 and c2, raised to degree n in v with the knots of d1, d2.
    pub c_c: BSplineSurface<S>,
    /// The ruled surface between d1 and d2, raised to degree m in u with the knots of c1, c2.
    pub c_d: BSplineSurface<S>,
    /// The bilinear surface of the corners, raised to (m, n) with both knot vectors.
    pub c_cd: BSplineSurface<S>,
    /// The Coons surface, mesh `c_ij = c_c,ij + c_d,ij - c_cd,ij` (18).
    pub surface: BSplineSurface<S>,
    /// Degree elevations and knot insertions of the curves.
    pub notes: Vec<Note>,
}

/// The knots of `target` missing from `have` (each as often as it is missing).
fn missing<S: Scalar>(have: &KnotVector<S>, target: &KnotVector<S>) -> Vec<S> {
    let mut out = Vec::new();
    for (t, m) in target.distinct() {
        for _ in have.multiplicity(&t)..m {
            out.push(t.clone());
        }
    }
    out
}

/// Raises a surface to bidegree (p, q) and inserts the knots it lacks of `knots_u`, `knots_v`.
fn conform<S: Scalar>(
    s: BSplineSurface<S>,
    knots_u: &KnotVector<S>,
    knots_v: &KnotVector<S>,
) -> Result<BSplineSurface<S>, GenerateError> {
    let (p, q) = s.bidegree();
    let s = s.elevate_degree(knots_u.degree() - p, knots_v.degree() - q)?;
    let s = s.refine_knots(Direction::U, &missing(s.knots_u(), knots_u))?;
    Ok(s.refine_knots(Direction::V, &missing(s.knots_v(), knots_v))?)
}

/// The B-spline Coons surface of four clamped B-spline curves forming a closed quadrilateral
/// (13): c1, c2 on a common domain [u0, u1], d1, d2 on [v0, v1]. Opposite curves are given a
/// common degree and knots ([`crate::make_compatible`]); the ruled surfaces c_c (degree 1 in
/// v), c_d (degree 1 in u) and the bilinear c_cd are raised to the bidegree (m, n) and given
/// the same knots by insertion; then `c_ij = c_c,ij + c_d,ij - c_cd,ij` (18). Records the
/// corners and the meshes `c_c`, `c_d`, `c_cd`, `c`.
pub fn coons_bspline<S: Scalar>(
    c1: &BSplineCurve<S>,
    c2: &BSplineCurve<S>,
    d1: &BSplineCurve<S>,
    d2: &BSplineCurve<S>,
    rec: &mut impl Record<Step<S>>,
) -> Result<CoonsBSpline<S>, GenerateError> {
    OneField::default()
        .bspline(c1)?
        .bspline(c2)?
        .bspline(d1)?
        .bspline(d2)?;
    crate::common::same_dim("c1", c1.dim(), "d1", d1.dim())?;
    let cs = make_compatible(c1, c2, ("c1", "c2"))?;
    let ds = make_compatible(d1, d2, ("d1", "d2"))?;
    let ends = |c: &BSplineCurve<S>| -> Result<(Point<S>, Point<S>), GenerateError> {
        let (s, e) = c.domain();
        Ok((c.eval(&s)?, c.eval(&e)?))
    };
    let e = [
        ends(&cs.first)?,
        ends(&cs.second)?,
        ends(&ds.first)?,
        ends(&ds.second)?,
    ];
    let [a, b, c, d] = quadrilateral([&e[0], &e[1], &e[2], &e[3]])?;
    let mut notes = cs.notes;
    notes.extend(ds.notes);
    for (name, p) in [("a", &a), ("b", &b), ("c", &c), ("d", &d)] {
        rec.record(|| Step::point(name, p));
    }
    let knots_u = cs.first.knots().clone();
    let knots_v = ds.first.knots().clone();
    let linear = |k: &KnotVector<S>| -> Result<KnotVector<S>, GenerateError> {
        let (s, e) = k.domain();
        Ok(KnotVector::clamped(1, &[s, e])?)
    };
    let (lin_u, lin_v) = (linear(&knots_u)?, linear(&knots_v)?);
    let pair_rows = |p: &[Point<S>], q: &[Point<S>]| -> Vec<Vec<Point<S>>> {
        p.iter()
            .zip(q)
            .map(|(x, y)| vec![x.clone(), y.clone()])
            .collect()
    };
    let ruled_c = BSplineSurface::try_new(
        knots_u.clone(),
        lin_v.clone(),
        Mesh::mesh(pair_rows(cs.first.points(), cs.second.points()))?,
    )?;
    let ruled_d = BSplineSurface::try_new(
        lin_u.clone(),
        knots_v.clone(),
        Mesh::mesh(vec![
            ds.first.points().to_vec(),
            ds.second.points().to_vec(),
        ])?,
    )?;
    let bilinear = BSplineSurface::try_new(
        lin_u,
        lin_v,
        Mesh::mesh(vec![vec![a.clone(), c.clone()], vec![b.clone(), d.clone()]])?,
    )?;
    let c_c = conform(ruled_c, &knots_u, &knots_v)?;
    let c_d = conform(ruled_d, &knots_u, &knots_v)?;
    let c_cd = conform(bilinear, &knots_u, &knots_v)?;
    let (rows, cols) = (c_c.mesh().rows(), c_c.mesh().cols());
    let mut mesh = Vec::with_capacity(rows);
    for i in 0..rows {
        let mut row = Vec::with_capacity(cols);
        for j in 0..cols {
            match (
                c_c.mesh().get(i, j),
                c_d.mesh().get(i, j),
                c_cd.mesh().get(i, j),
            ) {
                (Some(p), Some(q), Some(r)) => row.push(&(p + q) - r),
                _ => {
                    return Err(GenerateError::Surface(
                        cagd_surface::SurfaceError::EmptyMesh,
                    ))
                }
            }
        }
        mesh.push(row);
    }
    let surface = BSplineSurface::try_new(knots_u, knots_v, Mesh::mesh(mesh)?)?;
    rec.record(|| Step::mesh("c_c", c_c.mesh()));
    rec.record(|| Step::mesh("c_d", c_d.mesh()));
    rec.record(|| Step::mesh("c_cd", c_cd.mesh()));
    rec.record(|| Step::mesh("c", surface.mesh()));
    Ok(CoonsBSpline {
        a,
        b,
        c,
        d,
        curves: [cs.first, cs.second, ds.first, ds.second],
        c_c,
        c_d,
        c_cd,
        surface,
        notes,
    })
}
