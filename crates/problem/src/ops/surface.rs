//! Operations on one surface (or curve): closed forms, graphs, derivatives.

use super::curve::Curve;
use super::patch::Patch;
use super::Out;
use crate::input::{quoted, Field, SurfaceIn};
use crate::value::{exact_map, exact_mesh, exact_rational, Exact, ExactScalar};
use crate::ProblemError;
use cagd_poly::{control_mesh, from_bernstein_2d, Poly, Var, VecPoly};
use cagd_surface::Mesh;

/// The closed form of a surface (`surface`) or a curve (`curve`), from the validated patch or
/// curve (a zero weight is refused, not printed).
pub(crate) fn closed_form<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    if let Some(sf) = p.get("surface") {
        let e = match Patch::<S>::read(&sf)? {
            Patch::Bezier(s) => Exact::Map(exact_map(
                &s.closed_form().map_err(|e| sf.error(e.to_string()))?,
            )),
            Patch::Rational(s) => Exact::Rational(exact_rational(
                &s.closed_form().map_err(|e| sf.error(e.to_string()))?,
            )),
            Patch::Expr(e) => Exact::Map(exact_map(&e)),
            Patch::BSpline(_) | Patch::Nurbs(_) => {
                return Err(sf.error(
                    "a B-spline surface has one closed form per patch: split it into Bézier patches first",
                ))
            }
        };
        return Ok(Out::default().result("closed_form", e));
    }
    if let Some(cf) = p.get("curve") {
        let e = match Curve::<S>::read(&cf)? {
            Curve::Bezier(c) => Exact::Map(exact_map(&c.closed_form(Var::T))),
            Curve::Rational(c) => Exact::Rational(exact_rational(&c.closed_form(Var::T))),
            Curve::Expr(e) => Exact::Map(exact_map(&e)),
            Curve::BSpline(_) | Curve::Nurbs(_) => return Err(cf.error(
                "a B-spline curve has one closed form per span: split it into Bézier pieces first",
            )),
        };
        return Ok(Out::default().result("closed_form", e));
    }
    Err(p.error("closed_form needs a `surface` or a `curve`"))
}

/// The closed form c(u, v) of a Bézier mesh.
pub(crate) fn mesh_map<S: ExactScalar>(
    f: &Field<'_>,
    mesh: &Mesh<S>,
) -> Result<VecPoly<S>, ProblemError> {
    from_bernstein_2d(&mesh.to_rows(), Var::U, Var::V).map_err(|e| f.error(e.to_string()))
}

/// The graph of f(x, y) as a Bézier patch of bidegree (m, n), notes chapter 5 eq. (3):
/// c_ij = (i/m, j/n, ĉ_ij) where ĉ_ij are the Bernstein coefficients of f.
pub(crate) fn graph<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let ff = p.req("f")?;
    let parsed = ff.expr()?;
    let poly: Poly<S> = parsed
        .scalar()
        .map_err(|e| ff.error(format!("{}: {e}", quoted(ff.str().unwrap_or_default()))))?;
    // The notes write f(x, y); u and v are accepted too.
    let poly = poly
        .substitute(Var::X, &Poly::var(Var::U))
        .substitute(Var::Y, &Poly::var(Var::V));
    let (m, n) = match p.get("degree") {
        Some(d) => {
            let (m, n) = d.degree_pair()?;
            d.check_points(
                m.saturating_add(1).saturating_mul(n.saturating_add(1)),
                &format!("the graph of bidegree ({m}, {n})"),
            )?;
            (m, n)
        }
        None => {
            let degree = |var| usize::try_from(poly.degree_in(var).max(1)).unwrap_or(usize::MAX);
            let (m, n) = (degree(Var::U), degree(Var::V));
            ff.check_points(
                m.saturating_add(1).saturating_mul(n.saturating_add(1)),
                &format!("the graph of bidegree ({m}, {n})"),
            )?;
            (m, n)
        }
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
