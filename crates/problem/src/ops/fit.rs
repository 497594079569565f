//! Interpolation and least-squares approximation (chapter 5 §7, and curves).

use super::curve::Curve;
use super::patch::Patch;
use super::Out;
use crate::input::Field;
use crate::value::{exact_map, exact_mesh, Exact, ExactScalar};
use crate::ProblemError;
use cagd_fit::{
    approximate_bezier, approximate_bezier_surface_steps, coordinate_matrices, interpolate_bezier,
    interpolate_bezier_surface_steps, interpolate_bicubic_spline_steps, interpolate_cubic_spline,
    EndConditions, PassOrder, SurfaceEndConditions,
};
use cagd_linalg::{Matrix, Point};

fn at<'f, E: std::fmt::Display>(f: &'f Field<'_>) -> impl Fn(E) -> ProblemError + 'f {
    move |e| f.error(e.to_string())
}

fn matrix<S: ExactScalar>(m: &Matrix<S>) -> Exact {
    Exact::matrix(&m.to_rows())
}

/// Points as the rows of a matrix of coordinates (B^t A in the notes).
fn rows_of<S: ExactScalar>(ps: &[Point<S>]) -> Exact {
    Exact::matrix(&ps.iter().map(|p| p.coords().to_vec()).collect::<Vec<_>>())
}

/// The end conditions named by `end` (default natural).
fn end<S: ExactScalar>(p: &Field<'_>) -> Result<(EndConditions<S>, &'static str), ProblemError> {
    match p.get("end") {
        None => Ok((EndConditions::natural(), "natural")),
        Some(e) => match e.str()? {
            "natural" => Ok((EndConditions::natural(), "natural")),
            "bessel" => Ok((EndConditions::bessel(), "bessel")),
            other => Err(e.error(format!(
                "expected \"natural\" or \"bessel\", found {other:?}"
            ))),
        },
    }
}

/// The basis named by `basis` (default bezier).
fn basis<'f>(p: &'f Field<'_>) -> Result<&'f str, ProblemError> {
    match p.get("basis") {
        None => Ok("bezier"),
        Some(b) => match b.str()? {
            "bezier" => Ok("bezier"),
            "bicubic" | "cubic" | "spline" => Ok("bicubic"),
            other => Err(b.error(format!(
                "expected \"bezier\" or \"bicubic\", found {other:?}"
            ))),
        },
    }
}

/// The parameters of an interpolation, read from `f`: they must be distinct, or the
/// interpolation system is singular (two equal rows of the Bernstein or spline matrix).
fn distinct_parameters<S: ExactScalar>(f: &Field<'_>) -> Result<Vec<S>, ProblemError> {
    let items = f.items()?;
    let mut values: Vec<S> = Vec::with_capacity(items.len());
    for item in &items {
        let x = item.scalar::<S>()?;
        if let Some(i) = values.iter().position(|y| *y == x) {
            return Err(item.error(format!(
                "the parameter {} repeats entry {i}: the interpolation system is singular (the parameters must be distinct)",
                x.to_text()
            )));
        }
        values.push(x);
    }
    Ok(values)
}

/// `interpolate`: a grid of `points` at parameters `u`, `v` (surface), or `points` at
/// `params` (curve).
pub(crate) fn interpolate<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let pts = p.req("points")?;
    let basis = basis(p)?;
    if p.get("u").is_some() || p.get("v").is_some() {
        let u = distinct_parameters::<S>(&p.req("u")?)?;
        let v = distinct_parameters::<S>(&p.req("v")?)?;
        let data = pts.mesh::<S>()?;
        if basis == "bezier" {
            let g = interpolate_bezier_surface_steps(&u, &v, &data, PassOrder::RowsFirst)
                .map_err(at(&pts))?;
            let closed = g.surface.closed_form().map_err(at(p))?;
            let mut out = Out::default()
                .result("surface", Patch::Bezier(g.surface.clone()).exact())
                .result("closed_form", Exact::Map(exact_map(&closed)))
                .step("B_U", matrix(&g.b_u))
                .step("B_V", matrix(&g.b_v))
                .step(
                    "C_tilde",
                    Exact::Surface(crate::input::SurfaceIn::Bezier {
                        mesh: exact_mesh(&g.intermediate),
                        weights: None,
                    }),
                );
            let coords = coordinate_matrices(g.surface.mesh()).map_err(at(p))?;
            for (name, c) in ["C_x", "C_y", "C_z", "C_w"].iter().zip(&coords) {
                out = out.step(name, matrix(c));
            }
            return Ok(out);
        }
        let ends = match end::<S>(p)?.1 {
            "bessel" => SurfaceEndConditions::bessel(),
            _ => SurfaceEndConditions::natural(),
        };
        let g = interpolate_bicubic_spline_steps(&u, &v, &data, &ends, PassOrder::RowsFirst)
            .map_err(at(&pts))?;
        return Ok(Out::default()
            .result("surface", Patch::BSpline(g.surface).exact())
            .step(
                "d_tilde",
                Exact::Surface(crate::input::SurfaceIn::Bezier {
                    mesh: exact_mesh(&g.intermediate),
                    weights: None,
                }),
            ));
    }
    let params = distinct_parameters::<S>(&p.req("params")?)?;
    let points = pts.points::<S>()?;
    let curve = if basis == "bezier" {
        Curve::Bezier(interpolate_bezier(&params, &points).map_err(at(&pts))?)
    } else {
        let (ends, _) = end::<S>(p)?;
        Curve::BSpline(interpolate_cubic_spline(&params, &points, &ends).map_err(at(&pts))?)
    };
    Ok(Out::default().result("curve", curve.exact()))
}

/// `approximate`: least squares, eq. (28)-(29), of `points` at `params` — pairs [u, v] for a
/// patch of bidegree `degree` = [m, n], numbers t for a Bézier curve of degree `degree` = p.
pub(crate) fn approximate<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let pf = p.req("params")?;
    let points = p.req("points")?.points::<S>()?;
    let surface_params = pf.items()?.first().is_some_and(|f| f.value.is_array());
    if surface_params {
        let params = pf
            .items()?
            .iter()
            .map(|f| f.pair::<S>())
            .collect::<Result<Vec<_>, _>>()?;
        let df = p.req("degree")?;
        let (m, n) = df.degree_pair()?;
        df.check_points(
            m.saturating_add(1).saturating_mul(n.saturating_add(1)),
            &format!("a patch of bidegree ({m}, {n})"),
        )?;
        let ls = approximate_bezier_surface_steps(m, n, &params, &points).map_err(at(&pf))?;
        let closed = ls.surface.closed_form().map_err(at(p))?;
        return Ok(Out::default()
            .result("surface", Patch::Bezier(ls.surface.clone()).exact())
            .result("closed_form", Exact::Map(exact_map(&closed)))
            .step("B", matrix(&ls.collocation))
            .step("BtB", matrix(&ls.normal_matrix))
            .step("BtA", rows_of(&ls.rhs)));
    }
    let params = pf.scalars::<S>()?;
    let degree = p.req("degree")?.degree()?;
    let c = approximate_bezier(degree, &params, &points).map_err(at(&pf))?;
    Ok(Out::default().result("curve", Curve::Bezier(c).exact()))
}
