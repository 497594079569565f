//! Operations on one surface (or curve): closed forms, graphs, derivatives.

use super::Out;
use crate::input::{CurveIn, Field, SurfaceIn};
use crate::value::{exact_map, exact_mesh, exact_rational, Exact, ExactScalar};
use crate::ProblemError;
use cagd_poly::{
    control_mesh, from_bernstein_1d, from_bernstein_2d, parse_expr, Poly, RationalMap, Var, VecPoly,
};
use cagd_surface::{Mesh, RationalBezierSurface};

/// The closed form of a surface (`surface`) or a curve (`curve`).
pub(crate) fn closed_form<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    if let Some(s) = p.get("surface") {
        let e = surface_closed_form::<S>(&s, &s.surface::<S>()?)?;
        return Ok(Out::default().result("closed_form", e));
    }
    if let Some(c) = p.get("curve") {
        let e = curve_closed_form::<S>(&c, &c.curve::<S>()?)?;
        return Ok(Out::default().result("closed_form", e));
    }
    Err(p.error("closed_form needs a `surface` or a `curve`"))
}

/// The closed form of a Bézier or rational Bézier surface, or of a parametric one.
pub(crate) fn surface_closed_form<S: ExactScalar>(
    f: &Field<'_>,
    s: &SurfaceIn<S>,
) -> Result<Exact, ProblemError> {
    match s {
        SurfaceIn::Bezier {
            mesh,
            weights: None,
        } => Ok(Exact::Map(exact_map(&mesh_map(f, mesh)?))),
        SurfaceIn::Bezier {
            mesh,
            weights: Some(w),
        } => {
            let patch = RationalBezierSurface::try_new(mesh.clone(), w.clone())
                .map_err(|e| f.error(e.to_string()))?;
            let h = patch.homogeneous().to_rows();
            let hm = from_bernstein_2d(&h, Var::U, Var::V).map_err(|e| f.error(e.to_string()))?;
            let r = RationalMap::from_homogeneous(&hm).map_err(|e| f.error(e.to_string()))?;
            Ok(Exact::Rational(exact_rational(&r)))
        }
        SurfaceIn::Expr(e) => Ok(Exact::Map(exact_map(e))),
        SurfaceIn::BSpline { .. } => Err(f.error(
            "a B-spline surface has one closed form per span: split it into Bézier patches first",
        )),
    }
}

/// The closed form c(u, v) of a Bézier mesh.
pub(crate) fn mesh_map<S: ExactScalar>(
    f: &Field<'_>,
    mesh: &Mesh<S>,
) -> Result<VecPoly<S>, ProblemError> {
    from_bernstein_2d(&mesh.to_rows(), Var::U, Var::V).map_err(|e| f.error(e.to_string()))
}

/// The closed form of a curve, in the variable t (or the curve's own variable).
pub(crate) fn curve_closed_form<S: ExactScalar>(
    f: &Field<'_>,
    c: &CurveIn<S>,
) -> Result<Exact, ProblemError> {
    match c {
        CurveIn::Bezier {
            points,
            weights: None,
        } => Ok(Exact::Map(exact_map(
            &from_bernstein_1d(points, Var::T).map_err(|e| f.error(e.to_string()))?,
        ))),
        CurveIn::Bezier {
            points,
            weights: Some(w),
        } => {
            let h: Vec<_> = points
                .iter()
                .zip(w)
                .map(|(p, w)| p.to_homogeneous(w))
                .collect();
            let hm = from_bernstein_1d(&h, Var::T).map_err(|e| f.error(e.to_string()))?;
            let r = RationalMap::from_homogeneous(&hm).map_err(|e| f.error(e.to_string()))?;
            Ok(Exact::Rational(exact_rational(&r)))
        }
        CurveIn::Expr(e) => Ok(Exact::Map(exact_map(e))),
        CurveIn::BSpline { .. } => Err(f.error(
            "a B-spline curve has one closed form per span: split it into Bézier pieces first",
        )),
    }
}

/// The graph of f(x, y) as a Bézier patch of bidegree (m, n), notes chapter 5 eq. (3):
/// c_ij = (i/m, j/n, ĉ_ij) where ĉ_ij are the Bernstein coefficients of f.
pub(crate) fn graph<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let ff = p.req("f")?;
    let text = ff.str()?;
    let parsed = parse_expr(text).map_err(|e| ff.error(format!("{text:?}: {e}")))?;
    let poly: Poly<S> = parsed
        .scalar()
        .map_err(|e| ff.error(format!("{text:?}: {e}")))?;
    // The notes write f(x, y); u and v are accepted too.
    let poly = poly
        .substitute(Var::X, &Poly::var(Var::U))
        .substitute(Var::Y, &Poly::var(Var::V));
    let (m, n) = match p.get("degree") {
        Some(d) => d.usize_pair()?,
        None => (
            poly.degree_in(Var::U).max(1) as usize,
            poly.degree_in(Var::V).max(1) as usize,
        ),
    };
    let map = VecPoly::new(vec![Poly::var(Var::U), Poly::var(Var::V), poly]);
    let rows = control_mesh(&map, Var::U, Var::V, m, n).map_err(|e| ff.error(e.to_string()))?;
    let mesh = Mesh::mesh(rows).map_err(|e| ff.error(e.to_string()))?;
    Ok(Out::default()
        .result(
            "surface",
            Exact::Surface(SurfaceIn::Bezier {
                mesh: exact_mesh(&mesh),
                weights: None,
            }),
        )
        .result("closed_form", Exact::Map(exact_map(&map))))
}
