//! Operations on one tensor-product patch (chapter 5): evaluation, restriction, elevation,
//! derivatives, normals and knot insertion.

use crate::explain;
use crate::message::inner::Inner;
use crate::message::surface::Surface;
use crate::out::{at, num, pair, req, Out, Run};
use crate::problem::{Derivative, Elevate, Evaluate, InsertKnot, Normal, Param, Restrict, UorV};
use crate::spec::Orders;
use crate::steps::{Fact, Formula, Line};
use crate::value::quantity::{Corner, Quantity};
use crate::value::Number;
use crate::value::{exact_map, exact_point, exact_points, exact_rational, Exact, ExactScalar};
use crate::ProblemError;
use cagd_linalg::Point;
use cagd_poly::{Poly, RationalMap, Var, VecPoly};
use cagd_spline_surface::{BSplineSurface, Direction};
use cagd_surface::{CornerNormal, RationalBezierSurface};

/// A validated surface.
use crate::any::AnySurface as Patch;

/// The error for a restriction of a surface that is not a Bézier patch.
fn not_bezier<T>(path: &str) -> Result<T, ProblemError> {
    Err(ProblemError::at(path, Surface::RestrictionNeedsBezier))
}

/// `evaluate` a surface at `params` = [[u, v], ...].
pub(crate) fn evaluate<S: ExactScalar>(a: &Evaluate, run: Run<'_>) -> Result<Out, ProblemError> {
    let s = Patch::<S>::read(req(&a.surface, "surface")?, "surface")?;
    let params = req(&a.params, "params")?;
    let mut points = Vec::with_capacity(params.0.len());
    let mut out = run.out();
    if out.steps_on() {
        out.formula(match &s {
            Patch::Bezier(_) => Formula::DeCasteljauSurface,
            Patch::RationalBezier(_) => Formula::RationalSurface,
            Patch::BSpline(_) => Formula::BSplineSurface,
            Patch::Nurbs(_) => Formula::NurbsSurface,
            Patch::Map(_) => Formula::Substitution,
        });
        if let Patch::Map(e) = &s {
            out.value("c(u, v)", Exact::Map(exact_map(e)));
        }
        if matches!(s, Patch::RationalBezier(_)) {
            out.formula(Formula::DeCasteljauSurface);
        }
    }
    let shown = explain::worked_points(s.mesh_size().map_or(0, |(_, cols)| cols));
    for (i, uv) in params.0.iter().enumerate() {
        let path = format!("params[{i}]");
        let (u, v) = match uv {
            Param::Many(xs) => match xs.as_slice() {
                [u, v] => (num::<S>(u, &path)?, num::<S>(v, &path)?),
                _ => {
                    return Err(ProblemError::at(
                        path,
                        crate::message::read::Read::TwoNumbers { found: xs.len() },
                    ))
                }
            },
            Param::One(_) => return Err(ProblemError::at(path, Surface::TwoParametersFoundNumber)),
        };
        let p = s.eval(&path, &u, &v)?;
        if explain::worked(&out, i, shown) {
            explain_point(&mut out, &s, &u, &v, &p);
        }
        points.push(p);
    }
    explain::same_for_the_others(&mut out, points.len(), shown);
    Ok(out.result(Quantity::Points, Exact::Points(exact_points(&points))))
}

/// The two passes of c(u, v): along u in each column (a scheme per column), then along v on
/// the points found; for rational patches on the homogeneous mesh.
fn explain_point<S: ExactScalar>(out: &mut Out, s: &Patch<S>, u: &S, v: &S, p: &Point<S>) {
    out.fact(Fact::At {
        params: vec![explain::number(u), explain::number(v)],
    });
    let casteljau = |out: &mut Out, mesh: &cagd_surface::Mesh<S>| {
        let (m, n) = (mesh.rows() - 1, mesh.cols() - 1);
        out.explain(explain::bernstein_table(m, u, "u"));
        out.explain(explain::bernstein_table(n, v, "v"));
        out.fact(Fact::AlongU);
        let columns = mesh.to_columns();
        let mut firsts = Vec::with_capacity(columns.len());
        for (j, col) in columns.iter().enumerate() {
            let q = if explain::worked_line(j, columns.len()) {
                let Ok(levels) = cagd_bezier::de_casteljau_triangle(col, u) else {
                    return;
                };
                out.explain(explain::casteljau_table(&levels));
                levels.last().and_then(|l| l.first()).cloned()
            } else {
                if j == 1 {
                    explain::same_in_the_other_lines(out, Line::Column, columns.len());
                }
                cagd_linalg::exact::bernstein_combination(col, u)
                    .or_else(|| cagd_bezier::de_casteljau(col, u).ok())
            };
            if let Some(q) = q {
                out.value(format!("c_{{0,{j}}}^{{{m},0}}"), explain::point(&q));
                firsts.push(q);
            }
        }
        out.fact(Fact::AlongV);
        if let Ok(levels) = cagd_bezier::de_casteljau_triangle(&firsts, v) {
            out.explain(explain::casteljau_table(&levels));
        }
    };
    let de_boor = |out: &mut Out,
                   ku: &cagd_bspline::KnotVector<S>,
                   kv: &cagd_bspline::KnotVector<S>,
                   mesh: &cagd_surface::Mesh<S>| {
        if let Some(b) = explain::bspline_basis(ku, u, "u") {
            out.explain(b);
        }
        if let Some(b) = explain::bspline_basis(kv, v, "v") {
            out.explain(b);
        }
        out.fact(Fact::AlongU);
        let columns = mesh.to_columns();
        let mut firsts = Vec::with_capacity(columns.len());
        for (j, col) in columns.iter().enumerate() {
            let Ok(tri) = cagd_bspline::de_boor_triangle(ku, col, u) else {
                return;
            };
            if explain::worked_line(j, columns.len()) {
                explain::de_boor(out, ku, &tri, "u");
            } else if j == 1 {
                explain::same_in_the_other_lines(out, Line::Column, columns.len());
            }
            if let Some(q) = tri.point() {
                out.value(format!("c(u, \\cdot)_{{{j}}}"), explain::point(q));
                firsts.push(q.clone());
            }
        }
        out.value("c(u, \\cdot)", Exact::Points(exact_points(&firsts)));
        out.fact(Fact::AlongV);
        if let Ok(tri) = cagd_bspline::de_boor_triangle(kv, &firsts, v) {
            explain::de_boor(out, kv, &tri, "v");
        }
    };
    match s {
        Patch::Bezier(b) => casteljau(out, b.mesh()),
        Patch::RationalBezier(b) => {
            out.fact(Fact::Homogeneous);
            casteljau(out, &b.homogeneous());
        }
        Patch::BSpline(b) => de_boor(out, b.knots_u(), b.knots_v(), b.mesh()),
        Patch::Nurbs(b) => {
            out.fact(Fact::Homogeneous);
            let h = homogeneous_mesh(b.mesh(), b.weights());
            de_boor(out, b.knots_u(), b.knots_v(), &h);
        }
        Patch::Map(_) => {}
    }
    out.value("c(u, v)", explain::point(p));
}

/// The mesh of the homogeneous points (w c, w).
fn homogeneous_mesh<S: ExactScalar>(
    mesh: &cagd_surface::Mesh<S>,
    weights: &cagd_surface::Grid<S>,
) -> cagd_surface::Mesh<S> {
    cagd_surface::Grid::from_fn(mesh.rows(), mesh.cols(), |i, j| {
        match (mesh.get(i, j), weights.get(i, j)) {
            (Some(p), Some(w)) => p.to_homogeneous(w),
            (Some(p), None) => p.clone(),
            _ => Point::zero(mesh.dim() + 1),
        }
    })
}

/// `restrict` a patch to `u` = [a, b] × `v` = [c, d], eq. (13), with the row step ĉ.
pub(crate) fn restrict<S: ExactScalar>(a: &Restrict, run: Run<'_>) -> Result<Out, ProblemError> {
    let sf = "surface";
    let patch = Patch::<S>::read(req(&a.surface, sf)?, sf)?;
    let (u0, u1) = pair::<S>(req(&a.u, "u")?, "u")?;
    let (v0, v1) = pair::<S>(req(&a.v, "v")?, "v")?;
    let mut out = run.out();
    if out.steps_on() {
        out.formula(Formula::RestrictSurface);
        for (name, x) in [("a", &u0), ("b", &u1), ("c", &v0), ("d", &v1)] {
            out.value(name, explain::number(x));
        }
        if matches!(patch, Patch::RationalBezier(_)) {
            out.fact(Fact::Homogeneous);
        }
    }
    let (rows_step, result) = match patch {
        Patch::Bezier(s) => {
            let r = s.restrict(&u0, &u1, &v0, &v1).map_err(at(sf))?;
            (Patch::Bezier(r.rows_step), Patch::Bezier(r.result))
        }
        Patch::RationalBezier(s) => {
            let r = s.restrict(&u0, &u1, &v0, &v1).map_err(|e| match e {
                // the input's weights were checked when it was read: a zero weight now is one
                // of the restricted patch, where the weight function vanishes at a corner
                cagd_surface::SurfaceError::ZeroWeight { row, col } => ProblemError::at(
                    sf,
                    Surface::RestrictedZeroWeight {
                        row,
                        col,
                        u0: u0.to_text(),
                        u1: u1.to_text(),
                        v0: v0.to_text(),
                        v1: v1.to_text(),
                    },
                ),
                e => ProblemError::at(sf, e),
            })?;
            (
                Patch::RationalBezier(r.rows_step),
                Patch::RationalBezier(r.result),
            )
        }
        _ => return not_bezier(sf),
    };
    if out.steps_on() {
        let args = |x: &S, y: &S, k: usize, of: usize| {
            std::iter::repeat_n(x.to_text(), of - k)
                .chain(std::iter::repeat_n(y.to_text(), k))
                .collect::<Vec<_>>()
                .join(", ")
        };
        // the notes' order: the rows in v first (the mesh ĉ, ĉ_{i,j} = c_i[c^<n-j>, d^<j>]
        // with c_i the polygon of row i), then the columns of ĉ in u
        out.fact(Fact::RestrictRows);
        if let Patch::Bezier(h) = &rows_step {
            let n = h.bidegree().1;
            for ((i, j), p) in h.mesh().indexed() {
                out.value(
                    format!(
                        "\\hat{{c}}_{{{i},{j}}} = c_{{{i}}}[{}]",
                        args(&v0, &v1, j, n)
                    ),
                    explain::point(p),
                );
            }
        }
        out.fact(Fact::RestrictColumns);
        if let Patch::Bezier(r) = &result {
            let (m, n) = r.bidegree();
            for ((i, j), p) in r.mesh().indexed() {
                out.value(
                    format!(
                        "\\tilde{{c}}_{{{i},{j}}} = c[{}; {}]",
                        args(&u0, &u1, i, m),
                        args(&v0, &v1, j, n)
                    ),
                    explain::point(p),
                );
            }
        }
    }
    Ok(out
        .result(Quantity::Surface, result.to_exact())
        .step(Quantity::CHat, rows_step.to_exact()))
}

/// `elevate` a patch by `by` = [r, s], eq. (14)-(15).
pub(crate) fn elevate<S: ExactScalar>(a: &Elevate, run: Run<'_>) -> Result<Out, ProblemError> {
    let sf = "surface";
    let patch = Patch::<S>::read(req(&a.surface, sf)?, sf)?;
    let (r, s_) = match req(&a.by, "by")? {
        Orders::Two(r, s) => (r.get(), s.get()),
        Orders::One(n) => {
            return Err(ProblemError::at(
                "by",
                Surface::ListRsFoundNumber {
                    found: n.0.to_string(),
                },
            ))
        }
    };
    if let Some((m, n)) = patch.bidegree() {
        let (m2, n2) = (m.saturating_add(r), n.saturating_add(s_));
        run.check_degree(
            "by",
            m2.max(n2),
            crate::message::limited::Limited::ElevatingBidegree { m, n, r, s: s_ },
        )?;
        let (rows, cols) = patch.elevated_size(r, s_).unwrap_or((m2 + 1, n2 + 1));
        run.check_points(
            "by",
            rows.saturating_mul(cols),
            crate::message::limited::Limited::ElevatedPatch { m: m2, n: n2 },
        )?;
    }
    let mut steps = run.out();
    if steps.steps_on() {
        explain_elevation(&mut steps, &patch, r, s_);
    }
    let out = match patch {
        Patch::Bezier(s) => Patch::Bezier(s.elevate(r, s_).map_err(at(sf))?),
        Patch::RationalBezier(s) => Patch::RationalBezier(s.elevate(r, s_).map_err(at(sf))?),
        Patch::BSpline(s) => Patch::BSpline(s.elevate_degree(r, s_).map_err(at(sf))?),
        Patch::Nurbs(s) => Patch::Nurbs(s.elevate_degree(r, s_).map_err(at(sf))?),
        Patch::Map(_) => return Err(ProblemError::at(sf, Surface::ElevationNeedsMesh)),
    };
    Ok(steps.result(Quantity::Surface, out.to_exact()))
}

/// (14) on each column r times, then (15) on each row s times, every new point as its
/// combination; rational patches on the homogeneous mesh; B-splines: the rule. A pass that
/// would write more than [`explain::WORKED_COMBINATIONS`] combinations works its first column
/// (row) only and says the others are elevated in the same way: the elevated mesh is the
/// answer, computed once by the elevation itself.
fn explain_elevation<S: ExactScalar>(out: &mut Out, patch: &Patch<S>, r: usize, s: usize) {
    let mesh = match patch {
        Patch::Bezier(b) => b.mesh().clone(),
        Patch::RationalBezier(b) => {
            out.fact(Fact::Homogeneous);
            b.homogeneous()
        }
        Patch::BSpline(b) => {
            explain_spline_elevation(out, b, r, s);
            return;
        }
        Patch::Nurbs(b) => {
            out.fact(Fact::Homogeneous);
            let h = homogeneous_mesh(b.mesh(), b.weights());
            if let Ok(h) = BSplineSurface::try_new(b.knots_u().clone(), b.knots_v().clone(), h) {
                explain_spline_elevation(out, &h, r, s);
            }
            return;
        }
        Patch::Map(_) => return,
    };
    // the combinations of a pass: `lines` lines of `points` points, elevated `times` times
    let pass = |lines: usize, points: usize, times: usize| {
        lines.saturating_mul((1..=times).map(|k| points + k).sum::<usize>())
    };
    let whole_u = pass(mesh.cols(), mesh.rows(), r) <= explain::WORKED_COMBINATIONS;
    let whole_v = pass(mesh.rows() + r, mesh.cols(), s) <= explain::WORKED_COMBINATIONS;
    let mut columns = mesh.to_columns();
    let sup_u = |k: usize| {
        if k == 0 {
            String::new()
        } else {
            format!("^{{{k},0}}")
        }
    };
    if r > 0 && whole_u {
        out.formula(Formula::ElevateU);
        for step in 0..r {
            let m = columns.first().map_or(0, Vec::len).saturating_sub(1);
            out.fact(Fact::Degree { from: m, to: m + 1 });
            let (before, after) = (sup_u(step), sup_u(step + 1));
            for (j, col) in columns.iter_mut().enumerate() {
                *col =
                    explain::elevate_once(out, col, &|i| format!("c_{{{i},{j}}}{before}"), &|i| {
                        format!("c_{{{i},{j}}}{after}")
                    });
            }
        }
    } else if r > 0 {
        // the first column, elevated by r at once; the others in the same way
        out.formula(if r == 1 {
            Formula::ElevateU
        } else {
            Formula::ElevateUAtOnce
        });
        let m = mesh.rows().saturating_sub(1);
        out.fact(Fact::Degree { from: m, to: m + r });
        let after = sup_u(r);
        if let Some(first) = columns.first_mut() {
            *first = explain::elevate_at_once(out, first, r, &|i| format!("c_{{{i},0}}"), &|i| {
                format!("c_{{{i},0}}{after}")
            });
        }
        explain::same_in_the_other_lines(out, Line::Column, columns.len());
    }
    if s == 0 {
        return;
    }
    let sup_v = |k: usize| {
        if k == 0 && r == 0 {
            String::new()
        } else {
            format!("^{{{r},{k}}}")
        }
    };
    if !whole_v {
        // the first row, elevated by s at once: (14) keeps it (c_{0,j}^{r,0} = c_{0,j})
        out.formula(if s == 1 {
            Formula::ElevateV
        } else {
            Formula::ElevateVAtOnce
        });
        let n = mesh.cols().saturating_sub(1);
        out.fact(Fact::Degree { from: n, to: n + s });
        let (before, after) = (sup_v(0), sup_v(s));
        if let Some(row) = mesh.row(0) {
            explain::elevate_at_once(out, row, s, &|j| format!("c_{{0,{j}}}{before}"), &|j| {
                format!("c_{{0,{j}}}{after}")
            });
        }
        explain::same_in_the_other_lines(out, Line::Row, mesh.rows() + r);
        return;
    }
    if !whole_u {
        for col in columns.iter_mut().skip(1) {
            if let Ok(e) = cagd_bezier::elevate_degree(col, r) {
                *col = e;
            }
        }
    }
    let Ok(mut rows) = cagd_surface::Grid::from_columns(columns).map(|g| g.to_rows()) else {
        return;
    };
    out.formula(Formula::ElevateV);
    for step in 0..s {
        let n = rows.first().map_or(0, Vec::len).saturating_sub(1);
        out.fact(Fact::Degree { from: n, to: n + 1 });
        let (before, after) = (sup_v(step), sup_v(step + 1));
        for (i, row) in rows.iter_mut().enumerate() {
            *row = explain::elevate_once(out, row, &|j| format!("c_{{{i},{j}}}{before}"), &|j| {
                format!("c_{{{i},{j}}}{after}")
            });
        }
    }
}

/// `derivative` of order `order` = [r, s] of a patch: the derivative patch (18) and its closed
/// form, optionally on a border `at` = {"u": 1}.
pub(crate) fn derivative<S: ExactScalar>(
    a: &Derivative,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let sf = "surface";
    let patch = Patch::<S>::read(req(&a.surface, sf)?, sf)?;
    let (r, s_) = match req(&a.order, "order")? {
        Orders::Two(r, s) => (run.degree("order[0]", *r)?, run.degree("order[1]", *s)?),
        Orders::One(n) => {
            return Err(ProblemError::at(
                "order",
                Surface::ListRsFoundNumber {
                    found: n.0.to_string(),
                },
            ))
        }
    };
    let restrict_to = |mut d: VecPoly<S>| -> Result<VecPoly<S>, ProblemError> {
        if let Some(border) = &a.at {
            for (name, var, x) in [("at.u", Var::U, &border.u), ("at.v", Var::V, &border.v)] {
                if let Some(x) = x {
                    d = d.substitute_value(var, &num::<S>(x, name)?);
                }
            }
        }
        Ok(d)
    };
    let mut out = run.out();
    if out.steps_on() {
        explain_derivative(&mut out, &patch, r, s_, a);
    }
    match patch {
        Patch::Bezier(s) => {
            let d = s.partial_derivative(r, s_).map_err(at(sf))?;
            let closed = restrict_to(d.closed_form().map_err(at(sf))?)?;
            out = out
                .result(Quantity::Surface, Patch::Bezier(d).to_exact())
                .closed_form(Exact::Map(exact_map(&closed)));
        }
        Patch::RationalBezier(s) => {
            let d = s.partial_derivative(r, s_).map_err(at(sf))?;
            let (numer, denom) = (restrict_to(d.numerator().clone())?, d.denominator());
            let denom = restrict_to(VecPoly::new(vec![denom.clone()]))?;
            let denom = denom
                .components()
                .first()
                .cloned()
                .unwrap_or_else(Poly::one);
            let d = RationalMap::new(numer, denom).map_err(|e| {
                ProblemError::at(
                    "at",
                    Surface::DerivativeUndefined {
                        because: Inner::new(e),
                    },
                )
            })?;
            out = out.closed_form(Exact::Rational(exact_rational(&d)));
        }
        Patch::Map(e) => {
            let mut d = e;
            for var in std::iter::repeat_n(Var::U, r).chain(std::iter::repeat_n(Var::V, s_)) {
                if d.is_zero() {
                    break;
                }
                d = d.partial(var);
            }
            out = out.closed_form(Exact::Map(exact_map(&restrict_to(d)?)));
        }
        Patch::BSpline(_) | Patch::Nurbs(_) => {
            return crate::pieces::derivative(&patch, (r, s_), a.at.as_ref(), sf, out)
        }
    }
    Ok(out)
}

/// Degree elevation of a B-spline patch: the curve rule on each column (r times), then on
/// each row of the result (s times), Bézier piece by piece.
fn explain_spline_elevation<S: ExactScalar>(
    out: &mut Out,
    b: &BSplineSurface<S>,
    r: usize,
    s: usize,
) {
    use crate::curves::curve::{elevate_pieces_named, pieces_of};
    out.formula(Formula::ElevateBSpline);
    out.formula(Formula::ElevateCurve);
    if r > 0 {
        out.fact(Fact::EachColumn);
        for (j, col) in b.mesh().to_columns().iter().enumerate() {
            let pieces = pieces_of(b.knots_u(), col);
            elevate_pieces_named(out, &pieces, r, &|i| format!("b_{{{i},{j}}}"));
        }
    }
    if s > 0 {
        let Ok(mid) = b.elevate_degree(r, 0) else {
            return;
        };
        out.fact(Fact::EachRow);
        for (i, row) in mid.mesh().to_rows().iter().enumerate() {
            let pieces = pieces_of(mid.knots_v(), row);
            elevate_pieces_named(out, &pieces, s, &|j| format!("b_{{{i},{j}}}"));
        }
    }
}

/// (18): the differences Δ^{r,s} c_{i,j} and the factor; (19)/(20) on a border u = 0, 1.
fn explain_derivative<S: ExactScalar>(
    out: &mut Out,
    patch: &Patch<S>,
    r: usize,
    s: usize,
    a: &Derivative,
) {
    let border_u =
        a.at.as_ref()
            .and_then(|b| b.u.as_ref())
            .map(|x| x.0.clone());
    match patch {
        Patch::Bezier(b) => {
            let (m, n) = b.bidegree();
            out.formula(Formula::DerivativeSurface);
            if s == 0 && r > 0 {
                if let Some(x) = &border_u {
                    if x == &<Number as cagd_scalar::FieldOps>::from_i64(0) {
                        out.formula(Formula::DerivativeBorder0);
                    } else if x == &<Number as cagd_scalar::FieldOps>::from_i64(1) {
                        out.formula(Formula::DerivativeBorder1);
                    }
                }
            }
            out.value(
                format!("{m}!\\,{n}!/(({m}-{r})!\\,({n}-{s})!)"),
                explain::number(&(explain::falling::<S>(m, r) * explain::falling::<S>(n, s))),
            );
            let diffs = b
                .mesh()
                .map_columns(|c| {
                    cagd_bezier::forward_differences(c, r).map_err(cagd_surface::SurfaceError::from)
                })
                .and_then(|g| {
                    g.map_rows(|row| {
                        cagd_bezier::forward_differences(row, s)
                            .map_err(cagd_surface::SurfaceError::from)
                    })
                });
            if let Ok(d) = diffs {
                if d.rows() > 0 && d.cols() > 0 {
                    out.value(
                        format!("\\Delta^{{{r},{s}}} c_{{i,j}}"),
                        Exact::bezier_surface(&d, None),
                    );
                }
            }
        }
        Patch::RationalBezier(b) => {
            out.formula(Formula::RationalSurface);
            out.formula(Formula::DerivativeRational);
            rational_parts(out, b);
        }
        Patch::Map(e) => {
            out.formula(Formula::DerivativeMap);
            // the derivative on the whole domain first, then its value on the border
            if border_u.is_some() || a.at.as_ref().is_some_and(|b| b.v.is_some()) {
                let mut d = e.clone();
                for var in std::iter::repeat_n(Var::U, r).chain(std::iter::repeat_n(Var::V, s)) {
                    d = d.partial(var);
                }
                out.value(
                    format!("{}(u, v)", partial_symbol(r, s)),
                    Exact::Map(exact_map(&d)),
                );
            }
        }
        _ => {}
    }
    if let Some(x) = &border_u {
        out.value("u", Exact::Number(x.clone()));
    }
    if let Some(x) = a.at.as_ref().and_then(|b| b.v.as_ref()) {
        out.value("v", Exact::Number(x.0.clone()));
    }
}

/// The symbol of the partial derivative of order (r, s): c_u, c_{uv}, c_{uuv}; the
/// fraction ∂^{r+s} c/∂u^r ∂v^s beyond order 3.
fn partial_symbol(r: usize, s: usize) -> String {
    if r + s == 0 {
        return "c".to_string();
    }
    if r + s <= 3 {
        let letters = "u".repeat(r) + &"v".repeat(s);
        return if letters.len() == 1 {
            format!("c_{letters}")
        } else {
            format!("c_{{{letters}}}")
        };
    }
    format!(
        "\\partial^{{{}}} c/\\partial u^{{{r}}} \\partial v^{{{s}}}",
        r + s
    )
}

/// The numerator p(u, v) and the weight w(u, v) of a rational patch, c = p/w.
fn rational_parts<S: ExactScalar>(out: &mut Out, b: &RationalBezierSurface<S>) {
    if let Ok(c) = b.closed_form() {
        out.value("p(u, v)", Exact::Map(exact_map(c.numerator())));
        out.value(
            "w(u, v)",
            Exact::Poly(crate::value::exact_poly(c.denominator())),
        );
    }
}

/// Whether a mesh is generic (a formula fixture's `{"generic": "c"}`): each coordinate of
/// each point its own letter, x_{i,j}, y_{i,j}, z_{i,j}.
fn generic_mesh<S: ExactScalar>(mesh: &cagd_surface::Mesh<S>) -> bool {
    let mut letters = Vec::new();
    for (_, p) in mesh.indexed() {
        for x in p.coords() {
            let x = x.exact();
            match x.names().as_slice() {
                [name] if x == Number::named(name.clone()) && !letters.contains(name) => {
                    letters.push(name.clone());
                }
                _ => return false,
            }
        }
    }
    !letters.is_empty()
}

/// The normal at the corners of a generic mesh of bidegree (m, n) in the notes' factored
/// form, (18) and (25): n(0, 0) = mn Δ^{1,0}c_{0,0} × Δ^{0,1}c_{0,0} = mn (c_{1,0} - c_{0,0}) ×
/// (c_{0,1} - c_{0,0}), and likewise at the other corners (never expanded in the letters).
fn generic_corner_normals(out: &mut Out, (m, n): (usize, usize)) {
    out.formula(Formula::DerivativeSurface);
    out.formula(Formula::CornerNormal);
    out.value(
        "mn",
        Exact::Number(<Number as cagd_scalar::FieldOps>::from_i64(
            i64::try_from(m * n).unwrap_or(i64::MAX),
        )),
    );
    let (m1, n1) = (m.saturating_sub(1), n.saturating_sub(1));
    for ((u, v), (i0, i1), (j0, j1)) in [
        ((0, 0), (0, 1), (0, 1)),
        ((1, 0), (m1, m), (0, 1)),
        ((0, 1), (0, 1), (n1, n)),
        ((1, 1), (m1, m), (n1, n)),
    ] {
        let (ic, jc) = (if u == 0 { i0 } else { i1 }, if v == 0 { j0 } else { j1 });
        out.explain(crate::steps::Step::Identity {
            symbol: format!("n({u}, {v})"),
            equals: format!(
                "mn\\, \\Delta^{{1,0}} c_{{{i0},{jc}}} \\times \\Delta^{{0,1}} c_{{{ic},{j0}}} = {}\\, (c_{{{i1},{jc}}} - c_{{{i0},{jc}}}) \\times (c_{{{ic},{j1}}} - c_{{{ic},{j0}}})",
                m * n
            ),
        });
    }
}

fn corner_value<S: ExactScalar>(n: &CornerNormal<S>) -> Exact {
    match n {
        CornerNormal::Normal(p) => Exact::Point(exact_point(p)),
        _ => n.degenerate().map_or_else(
            || Exact::Text(n.to_text()),
            |words| Exact::Sentence(words.into()),
        ),
    }
}

/// `normal`: c_u × c_v as a closed form, and at the four corners (`m n` times (25) on the unit
/// square); where it vanishes, the limit of its direction along a border (the pole of the
/// sphere octant), as `corner_XY` (the reason and the direction, in words) and
/// `corner_XY_limit` (the direction).
pub(crate) fn normal<S: ExactScalar>(a: &Normal, run: Run<'_>) -> Result<Out, ProblemError> {
    let sf = "surface";
    let patch = Patch::<S>::read(req(&a.surface, sf)?, sf)?;
    let mut out = run.out();
    let generic = matches!(&patch, Patch::Bezier(b) if generic_mesh(b.mesh()));
    if out.steps_on() {
        out.formula(Formula::Normal);
        match &patch {
            Patch::Bezier(b) if generic => generic_corner_normals(&mut out, b.bidegree()),
            Patch::Bezier(b) => {
                for (name, (r, s)) in [("c_u", (1, 0)), ("c_v", (0, 1))] {
                    if let Ok(c) = b.partial_derivative(r, s).and_then(|d| d.closed_form()) {
                        out.value(name, Exact::Map(exact_map(&c)));
                    }
                }
                let (m, n) = b.bidegree();
                out.formula(Formula::CornerNormal);
                let mesh = b.mesh();
                let mn = S::from_i64(i64::try_from(m * n).unwrap_or(i64::MAX));
                out.value("mn", explain::number(&mn));
                // each corner (u, v): the differences along its two borders, from the corner
                // point of the mesh (i0, j0), towards (i1, j0) and (i0, j1)
                for ((u, v), (i0, i1), (j0, j1)) in [
                    ((0, 0), (0, 1), (0, 1)),
                    ((1, 0), (m.saturating_sub(1), m), (0, 1)),
                    ((0, 1), (0, 1), (n.saturating_sub(1), n)),
                    ((1, 1), (m.saturating_sub(1), m), (n.saturating_sub(1), n)),
                ] {
                    let (ic, jc) = (if u == 0 { i0 } else { i1 }, if v == 0 { j0 } else { j1 });
                    let (Some(a0), Some(a1), Some(b0), Some(b1)) = (
                        mesh.get(i0, jc),
                        mesh.get(i1, jc),
                        mesh.get(ic, j0),
                        mesh.get(ic, j1),
                    ) else {
                        continue;
                    };
                    let du = a1.clone() - a0.clone();
                    let dv = b1.clone() - b0.clone();
                    out.value(
                        format!("\\Delta^{{1,0}} c_{{{i0},{jc}}}"),
                        explain::point(&du),
                    );
                    out.value(
                        format!("\\Delta^{{0,1}} c_{{{ic},{j0}}}"),
                        explain::point(&dv),
                    );
                    if let Ok(x) = du.cross(&dv) {
                        out.value(
                            format!(
                                "n({u}, {v}) = mn\\, \\Delta^{{1,0}} c_{{{i0},{jc}}} \\times \\Delta^{{0,1}} c_{{{ic},{j0}}}"
                            ),
                            explain::point(&x.scale(&mn)),
                        );
                    }
                }
            }
            Patch::RationalBezier(b) => {
                out.formula(Formula::RationalSurface);
                out.formula(Formula::DerivativeRational);
                rational_parts(&mut out, b);
            }
            Patch::Map(e) => {
                out.value("c_u", Exact::Map(exact_map(&e.partial(Var::U))));
                out.value("c_v", Exact::Map(exact_map(&e.partial(Var::V))));
            }
            _ => {}
        }
    }
    let corners = match patch {
        Patch::Bezier(s) => {
            let field = s.normal().map_err(at(sf))?;
            // on a generic mesh the closed form is an expansion in its letters that the notes
            // never print (pages of x_{i,j} y_{k,l} terms): the corners (25) are the answer
            if !generic {
                out = out.closed_form(Exact::Map(exact_map(&field)));
            }
            s.corner_normals(&field).map_err(at(sf))?
        }
        Patch::RationalBezier(s) => {
            let field = s.normal().map_err(at(sf))?;
            out = out.closed_form(Exact::Rational(exact_rational(&field)));
            s.corner_normals(&field).map_err(at(sf))?
        }
        Patch::Map(e) => {
            let n = e
                .partial(Var::U)
                .cross(&e.partial(Var::V))
                .map_err(at(sf))?;
            return Ok(out.closed_form(Exact::Map(exact_map(&n))));
        }
        Patch::BSpline(_) | Patch::Nurbs(_) => return crate::pieces::normal(&patch, sf, out),
    };
    for (corner, c) in Corner::ALL.into_iter().zip(corners.iter()) {
        out = out.result(
            Quantity::CornerNormal {
                corner,
                limit: false,
            },
            corner_value(c),
        );
        if let CornerNormal::Limit { direction, .. } = c {
            out = out.result(
                Quantity::CornerNormal {
                    corner,
                    limit: true,
                },
                Exact::Point(exact_point(direction)),
            );
        }
    }
    Ok(out)
}

/// `insert_knot` into a B-spline or NURBS surface in `direction` `u` or `v`.
pub(crate) fn insert_knot<S: ExactScalar>(
    a: &InsertKnot,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let sf = "surface";
    let patch = Patch::<S>::read(req(&a.surface, sf)?, sf)?;
    let knot = num::<S>(req(&a.knot, "knot")?, "knot")?;
    let times = run.times(a.times)?;
    let dir = match req(&a.direction, "direction")? {
        UorV::U => Direction::U,
        UorV::V => Direction::V,
    };
    if let Some((rows, cols)) = patch.mesh_size() {
        let (rows, cols) = match dir {
            Direction::U => (rows.saturating_add(times), cols),
            Direction::V => (rows, cols.saturating_add(times)),
        };
        run.check_points(
            sf,
            rows.saturating_mul(cols),
            crate::message::limited::Limited::SurfaceKnotInserted,
        )?;
    }
    let mut steps = run.out();
    if steps.steps_on() {
        let (knots, mesh) = match &patch {
            Patch::BSpline(s) => (
                if dir == Direction::U {
                    s.knots_u()
                } else {
                    s.knots_v()
                },
                s.mesh().clone(),
            ),
            Patch::Nurbs(s) => {
                steps.fact(Fact::Homogeneous);
                (
                    if dir == Direction::U {
                        s.knots_u()
                    } else {
                        s.knots_v()
                    },
                    homogeneous_mesh(s.mesh(), s.weights()),
                )
            }
            _ => return Err(ProblemError::at(sf, Surface::KnotInsertionNeedsBSpline)),
        };
        let knots = knots.clone();
        let lines = match dir {
            Direction::U => {
                steps.fact(Fact::EachColumn);
                mesh.to_columns()
            }
            Direction::V => {
                steps.fact(Fact::EachRow);
                mesh.to_rows()
            }
        };
        // the same span and α_i for every column (row): shown on each
        let name = if dir == Direction::U { "u" } else { "v" };
        steps.formula(Formula::Boehm);
        let symbol = |i: usize, line: usize| match dir {
            Direction::U => format!("d_{{{i},{line}}}"),
            Direction::V => format!("d_{{{line},{i}}}"),
        };
        crate::curves::curve::explain_boehm_lines(
            &mut steps, &knots, &lines, &knot, times, name, &symbol,
        );
    }
    let out = match patch {
        Patch::BSpline(s) => Patch::BSpline(s.insert_knot(dir, &knot, times).map_err(at(sf))?),
        Patch::Nurbs(s) => Patch::Nurbs(s.insert_knot(dir, &knot, times).map_err(at(sf))?),
        _ => return Err(ProblemError::at(sf, Surface::KnotInsertionNeedsBSpline)),
    };
    Ok(steps.result(Quantity::Surface, out.to_exact()))
}
