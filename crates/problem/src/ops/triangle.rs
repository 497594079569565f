//! Triangular Bézier patches (crate cagd-triangle) through the problem format: evaluation by
//! De Casteljau, closed form, degree elevation, directional derivatives, blossom, subdivision
//! at a point and the boundary curves. A patch is `{"triangle": [[b_{n,0,0}], ...]}`
//! (`crate::triangle`); a point of its domain is [u, v] in the triangle (0, 0), (1, 0), (0, 1)
//! (r = 1 - u - v, s = u, t = v) or barycentric [r, s, t].

use super::{at, explain, num, pair, req, Out, Run};
use crate::problem::{
    Blossom, Boundary, ClosedForm, Derivative, Elevate, Evaluate, Normal, Param, Subdivide,
};
use crate::spec::Orders;
use crate::steps::{Fact, Formula};
use crate::triangle::{exact_triangle, TriangleIn};
use crate::value::{exact_map, exact_points, Exact, ExactScalar};
use crate::ProblemError;
use cagd_bezier::BezierCurve;
use cagd_linalg::Point;
use cagd_triangle::{multi_indices, Barycentric, Direction, Edge, TriangularPatch};

const TF: &str = "triangle";

fn read<S: ExactScalar>(t: &Option<TriangleIn>) -> Result<TriangularPatch<S>, ProblemError> {
    req(t, TF)?.patch::<S>(TF)
}

/// A point of the domain triangle: [u, v], or barycentric [r, s, t] (r + s + t = 1).
fn point_of<S: ExactScalar>(p: &Param, path: &str) -> Result<Barycentric<S>, ProblemError> {
    match p {
        Param::Many(xs) => match xs.as_slice() {
            [u, v] => Ok(Barycentric::from_uv(num::<S>(u, path)?, num::<S>(v, path)?)),
            [r, s, t] => Barycentric::try_new(num::<S>(r, path)?, num::<S>(s, path)?, num::<S>(t, path)?)
                .map_err(at(path)),
            _ => Err(ProblemError::at(
                path,
                format!("expected [u, v] or barycentric [r, s, t], found a list of {}", xs.len()),
            )),
        },
        Param::One(_) => Err(ProblemError::at(
            path,
            "expected a point [u, v] of the domain triangle (or barycentric [r, s, t]), found a number",
        )),
    }
}

/// The De Casteljau levels 1, ..., n as values b_{i,j,k}^l.
fn explain_levels<S: ExactScalar>(out: &mut Out, n: usize, levels: &[Vec<Point<S>>]) {
    for (l, level) in levels.iter().enumerate().skip(1) {
        for ((i, j, k), p) in multi_indices(n - l).zip(level) {
            out.value(format!("b_{{{i},{j},{k}}}^{{{l}}}"), explain::point(p));
        }
    }
}

/// `evaluate` a triangular patch at `params`: De Casteljau on the net (with its levels as
/// steps), b(x) = b^n_{0,0,0}(x).
pub(crate) fn evaluate<S: ExactScalar>(a: &Evaluate, run: Run<'_>) -> Result<Out, ProblemError> {
    let patch = read::<S>(&a.triangle)?;
    let params = req(&a.params, "params")?;
    let mut out = run.out();
    out.formula(Formula::DeCasteljauTriangle);
    let mut points = Vec::with_capacity(params.0.len());
    for (i, p) in params.0.iter().enumerate() {
        let path = format!("params[{i}]");
        let x = point_of::<S>(p, &path)?;
        let value = if out.steps_on() {
            out.fact(Fact::At {
                params: x.coords().iter().map(explain::number).collect(),
            });
            let dc = patch.de_casteljau(&x);
            explain_levels(&mut out, patch.degree(), dc.levels());
            dc.into_value()
        } else {
            patch.evaluate(&x)
        };
        if out.steps_on() {
            out.value("b(r, s, t)", explain::point(&value));
        }
        points.push(value);
    }
    Ok(out.result("points", Exact::Points(exact_points(&points))))
}

/// `closed_form` of a triangular patch: b(u, v) = Σ b_{ijk} n!/(i! j! k!) (1 - u - v)^i u^j v^k.
pub(crate) fn closed_form<S: ExactScalar>(
    a: &ClosedForm,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let patch = read::<S>(&a.triangle)?;
    let mut out = run.out();
    out.formula(Formula::BernsteinTriangle);
    Ok(out.result("closed_form", Exact::Map(exact_map(&patch.closed_form()))))
}

/// `elevate` a triangular patch by `by` = r: r elevations by one,
/// b^{(1)}_{ijk} = (i b_{i-1,j,k} + j b_{i,j-1,k} + k b_{i,j,k-1})/(n + 1).
pub(crate) fn elevate<S: ExactScalar>(a: &Elevate, run: Run<'_>) -> Result<Out, ProblemError> {
    let patch = read::<S>(&a.triangle)?;
    let r = match req(&a.by, "by")? {
        Orders::One(r) => r.get(),
        Orders::Two(..) => {
            return Err(ProblemError::at(
                "by",
                "expected a non-negative integer (a triangular patch has one degree), found a list of 2",
            ))
        }
    };
    let n = patch.degree();
    let to = n.saturating_add(r);
    run.check_degree("by", to, &format!("elevating degree {n} by {r}"))?;
    run.check_points(
        "by",
        cagd_triangle::control_point_count(to).unwrap_or(usize::MAX),
        "the elevated patch",
    )?;
    let mut out = run.out();
    out.formula(Formula::ElevateTriangle);
    let mut p = patch;
    for _ in 0..r {
        let next = p.elevate_degree();
        out.fact(Fact::Degree {
            from: p.degree(),
            to: next.degree(),
        });
        p = next;
    }
    Ok(out.result("triangle", exact_triangle(&p)))
}

/// `derivative` of a triangular patch along `direction` = [du, dv] (default [1, 0], ∂/∂u),
/// `order` times (default 1): D_d b = n Σ (d_1 b_{i+1,j,k} + d_2 b_{i,j+1,k} + d_3 b_{i,j,k+1})
/// B^{n-1}_{ijk}, d = (-du - dv, du, dv); a patch of degree n - r, and its closed form.
pub(crate) fn derivative<S: ExactScalar>(
    a: &Derivative,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let patch = read::<S>(&a.triangle)?;
    if a.at.is_some() {
        return Err(ProblemError::at(
            "at",
            "`at` restricts a tensor-product patch to a border; for a triangular patch, `evaluate` the derivative's closed form or `boundary` its net",
        ));
    }
    let r = match &a.order {
        None => 1,
        Some(Orders::One(r)) => run.degree("order", *r)?,
        Some(Orders::Two(..)) => return Err(ProblemError::at(
            "order",
            "expected a non-negative integer (derivatives along one direction), found a list of 2",
        )),
    };
    let (du, dv) = match &a.direction {
        Some(d) => pair::<S>(d, "direction")?,
        None => (S::one(), S::zero()),
    };
    let d = Direction::from_uv(du, dv);
    let mut out = run.out();
    out.formula(Formula::DerivativeTriangle);
    if out.steps_on() {
        out.value(
            "d",
            Exact::Point(crate::value::exact_point(&Point::new(d.coords().to_vec()))),
        );
    }
    let mut p = patch;
    for _ in 0..r {
        p = p.derivative(&d);
    }
    Ok(out
        .result("triangle", exact_triangle(&p))
        .result("closed_form", Exact::Map(exact_map(&p.closed_form()))))
}

/// `blossom` of a triangular patch at the n points `params`: De Casteljau with x_l at level l
/// (symmetric, affine in each argument, b[x, ..., x] = b(x)).
pub(crate) fn blossom<S: ExactScalar>(a: &Blossom, run: Run<'_>) -> Result<Out, ProblemError> {
    let patch = read::<S>(&a.triangle)?;
    let params = req(&a.params, "params")?;
    let args = params
        .0
        .iter()
        .enumerate()
        .map(|(i, p)| point_of::<S>(p, &format!("params[{i}]")))
        .collect::<Result<Vec<_>, _>>()?;
    let mut out = run.out();
    out.formula(Formula::BlossomTriangle);
    let value = if out.steps_on() {
        let dc = patch.blossom_steps(&args).map_err(at("params"))?;
        explain_levels(&mut out, patch.degree(), dc.levels());
        dc.into_value()
    } else {
        patch.blossom(&args).map_err(at("params"))?
    };
    Ok(out.result("point", Exact::Point(crate::value::exact_point(&value))))
}

/// `subdivide` a triangular patch at the point (`u`, `v`) of its domain into the three patches
/// over (x, e2, e3), (e1, x, e3), (e1, e2, x): c_{ijk} = b^i_{0,j,k}(x), b^j_{i,0,k}(x),
/// b^k_{i,j,0}(x), the levels of De Casteljau at x.
pub(crate) fn subdivide<S: ExactScalar>(a: &Subdivide, run: Run<'_>) -> Result<Out, ProblemError> {
    let patch = read::<S>(&a.triangle)?;
    if a.t.is_some() {
        return Err(ProblemError::at(
            "t",
            "a triangular patch is split at a point (u, v) of its domain: give `u` and `v`",
        ));
    }
    let u = num::<S>(req(&a.u, "u")?, "u")?;
    let v = num::<S>(req(&a.v, "v")?, "v")?;
    let x = Barycentric::from_uv(u, v);
    let mut out = run.out();
    out.formula(Formula::SubdivideTriangle);
    if out.steps_on() {
        let dc = patch.de_casteljau(&x);
        explain_levels(&mut out, patch.degree(), dc.levels());
    }
    let parts = patch.split(&x);
    Ok(out.result(
        "triangles",
        Exact::List(parts.iter().map(exact_triangle).collect()),
    ))
}

/// `boundary` of a triangular patch: the Bézier curves over the edges t = 0 (v = 0, from
/// (0, 0) to (1, 0)), r = 0 (u + v = 1, from (1, 0) to (0, 1)) and s = 0 (u = 0, from (0, 1) to
/// (0, 0)), whose control points are the net's points on that edge.
pub(crate) fn boundary<S: ExactScalar>(a: &Boundary, run: Run<'_>) -> Result<Out, ProblemError> {
    let patch = read::<S>(&a.triangle)?;
    let mut out = run.out();
    out.formula(Formula::BoundaryTriangle);
    for (edge, name) in Edge::ALL.iter().zip(["v0", "uv1", "u0"]) {
        let curve = BezierCurve::try_new(patch.boundary_curve(*edge)).map_err(at(TF))?;
        out = out.result(
            &format!("curve_{name}"),
            super::curve::Curve::Bezier(curve).to_exact(),
        );
    }
    Ok(out)
}

/// `normal` of a triangular patch in R³: n = b_u × b_v (not normalized, so it stays exact), as a
/// closed form in (u, v) (the cross product of the derivative patches' closed forms, ∂/∂u along
/// d = (-1, 1, 0) and ∂/∂v along (-1, 0, 1)), and at the points `params` when given.
pub(crate) fn normal<S: ExactScalar>(a: &Normal, run: Run<'_>) -> Result<Out, ProblemError> {
    let patch = read::<S>(&a.triangle)?;
    if patch.dim() != 3 {
        return Err(ProblemError::at(
            TF,
            format!(
                "the normal b_u × b_v needs points in R³, found dimension {}",
                patch.dim()
            ),
        ));
    }
    let mut out = run.out();
    out.formula(Formula::DerivativeTriangle);
    out.formula(Formula::Normal);
    let bu = patch.derivative(&Direction::du()).closed_form();
    let bv = patch.derivative(&Direction::dv()).closed_form();
    if out.steps_on() {
        out.value("b_u", Exact::Map(exact_map(&bu)));
        out.value("b_v", Exact::Map(exact_map(&bv)));
    }
    let n = bu.cross(&bv).map_err(at(TF))?;
    out = out.result("closed_form", Exact::Map(exact_map(&n)));
    if let Some(params) = &a.params {
        let mut points = Vec::with_capacity(params.0.len());
        for (i, p) in params.0.iter().enumerate() {
            let path = format!("params[{i}]");
            let x = point_of::<S>(p, &path)?;
            points.push(patch.normal(&x).map_err(at(&path))?);
        }
        out = out.result("normals", Exact::Points(exact_points(&points)));
    }
    Ok(out)
}
