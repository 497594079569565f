//! Operations on the control points of a curve or patch: the blossom of curves and patches,
//! subdivision at a point, boundary and iso-parametric curves, Bézier extraction, knot removal
//! and degree reduction.

use crate::any::AnyCurve as Curve;
use crate::any::AnySurface as Patch;
use crate::curves::curve::knots_exact;
use crate::curves::split::split_bspline;
use crate::explain;
use crate::message::fitting::Fitting;
use crate::out::{at, num, req, Out, Run};
use crate::problem::{
    Blossom, Boundary, Extract, Isocurve, Param, ReduceDegree, RemoveKnot, Subdivide,
};
use crate::steps::{Fact, Formula};
use crate::value::{exact_point, Exact, ExactScalar};
use crate::value::{quantity, Quantity};
use crate::ProblemError;
use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_bspline::{BSplineCurve, KnotVector, NurbsCurve};
use cagd_linalg::Point;
use cagd_poly::{Poly, VecPoly};
use cagd_scalar::Scalar;
use cagd_surface::{Border, Mesh};

/// The intervals of the pieces in one direction.
type Intervals<S> = Vec<(S, S)>;

/// The numbers of a list of parameters, each one number.
fn numbers<S: ExactScalar>(params: &[Param], key: &str) -> Result<Vec<S>, ProblemError> {
    params
        .iter()
        .enumerate()
        .map(|(i, p)| match p {
            Param::One(x) => num::<S>(x, &format!("{key}[{i}]")),
            Param::Many(_) => Err(ProblemError::at(
                format!("{key}[{i}]"),
                Fitting::NumberNotList,
            )),
        })
        .collect()
}

/// The levels of De Casteljau run with t_r at level r: c_i^r = (1 - t_r) c_i^{r-1} + t_r
/// c_{i+1}^{r-1} (the blossom's scheme; every t_r = t gives the curve's).
fn blossom_levels<S: Scalar>(points: &[Point<S>], ts: &[S]) -> Vec<Vec<Point<S>>> {
    let mut levels = vec![points.to_vec()];
    for t in ts {
        let Some(last) = levels.last() else { break };
        let next: Vec<Point<S>> = last
            .windows(2)
            .filter_map(|w| match w {
                [a, b] => Some(a.lerp(b, t)),
                _ => None,
            })
            .collect();
        levels.push(next);
    }
    levels
}

/// `blossom`: the polar form of a Bézier curve at `params` = [t_1, ..., t_n] (De Casteljau with
/// t_r at level r; symmetric, affine in each argument, c[t, ..., t] = c(t)); of a Bézier patch
/// at `u` = [u_1, ..., u_m], `v` = [v_1, ..., v_n] (eq. (12): rows in v, then the column in u);
/// of a rational curve or patch on the homogeneous points, projected.
pub(crate) fn blossom<S: ExactScalar>(a: &Blossom, run: Run<'_>) -> Result<Out, ProblemError> {
    let mut out = run.out();
    if let Some(c) = &a.curve {
        let c = Curve::<S>::read_with_vectors(c, "curve")?;
        let ts = numbers::<S>(&req(&a.params, "params")?.0, "params")?;
        out.formula(Formula::BlossomCurve);
        let value = match &c {
            Curve::Bezier(b) => {
                if out.steps_on() && ts.len() == b.degree() {
                    let local: Vec<S> = ts.iter().map(|t| b.local_parameter(t)).collect();
                    out.explain(explain::casteljau_table(&blossom_levels(
                        b.points(),
                        &local,
                    )));
                }
                b.blossom(&ts).map_err(at("params"))?
            }
            Curve::RationalBezier(b) => {
                if out.steps_on() && ts.len() == b.degree() {
                    out.fact(Fact::Homogeneous);
                    let local: Vec<S> = ts.iter().map(|t| b.local_parameter(t)).collect();
                    out.explain(explain::casteljau_table(&blossom_levels(
                        &b.homogeneous(),
                        &local,
                    )));
                }
                b.blossom(&ts).map_err(at("params"))?
            }
            _ => return Err(ProblemError::at("curve", Fitting::BlossomCurve)),
        };
        return Ok(out.result(Quantity::Point, Exact::Point(exact_point(&value))));
    }
    if let Some(s) = &a.surface {
        let s = Patch::<S>::read(s, "surface")?;
        let us: Vec<S> = list(&a.u, "u")?;
        let vs: Vec<S> = list(&a.v, "v")?;
        out.formula(Formula::BlossomSurface);
        let value = match &s {
            Patch::Bezier(p) => p.blossom(&us, &vs).map_err(at("surface"))?,
            Patch::RationalBezier(p) => p.blossom(&us, &vs).map_err(at("surface"))?,
            _ => return Err(ProblemError::at("surface", Fitting::BlossomSurface)),
        };
        return Ok(out.result(Quantity::Point, Exact::Point(exact_point(&value))));
    }
    Err(ProblemError::at("", Fitting::BlossomNeeds))
}

/// A list of numbers given by the problem.
fn list<S: ExactScalar>(
    x: &Option<crate::spec::List<crate::spec::Num>>,
    key: &str,
) -> Result<Vec<S>, ProblemError> {
    req(x, key)?
        .0
        .iter()
        .enumerate()
        .map(|(i, x)| num::<S>(x, &format!("{key}[{i}]")))
        .collect()
}

/// `subdivide`: a Bézier curve at `t` into the two curves on [a, t] and [t, b], each read on
/// [0, 1] (left c_0^0, c_0^1, ..., c_0^n; right c_0^n, c_1^{n-1}, ..., c_n^0 of De Casteljau at
/// t); a B-spline (NURBS) curve by inserting t until its multiplicity is p (Boehm), into the
/// two curves on [a, t] and [t, b] (their knots keep the parameter: [`split_bspline`]); a Bézier patch at (`u`, `v`) into four patches (eq. (13) on each quadrant: rows
/// [0, u] × [0, v], [0, u] × [v, 1], [u, 1] × [0, v], [u, 1] × [v, 1]), or at `u` alone (`v`
/// alone) into two.
pub(crate) fn subdivide<S: ExactScalar>(a: &Subdivide, run: Run<'_>) -> Result<Out, ProblemError> {
    let mut out = run.out();
    if let Some(c) = &a.curve {
        let c = Curve::<S>::read_with_vectors(c, "curve")?;
        let t = num::<S>(req(&a.t, "t")?, "t")?;
        if matches!(c, Curve::Bezier(_) | Curve::RationalBezier(_)) {
            out.formula(Formula::SubdivideCurve);
        }
        let (left, right) = match &c {
            Curve::Bezier(b) => {
                if out.steps_on() {
                    if let Ok(levels) = b.triangle(&t) {
                        out.explain(explain::casteljau_table(&levels));
                    }
                }
                let (l, r) = b.subdivide(&t).map_err(at("t"))?;
                (Curve::Bezier(l), Curve::Bezier(r))
            }
            Curve::RationalBezier(b) => {
                if out.steps_on() {
                    out.fact(Fact::Homogeneous);
                    if let Ok(levels) = b.triangle_homogeneous(&t) {
                        out.explain(explain::casteljau_table(&levels));
                    }
                }
                let (l, r) = b.subdivide(&t).map_err(at("t"))?;
                (Curve::RationalBezier(l), Curve::RationalBezier(r))
            }
            Curve::BSpline(b) => {
                if out.steps_on() {
                    let times = b.degree().saturating_sub(b.knots().multiplicity(&t));
                    crate::curves::curve::explain_boehm(
                        &mut out,
                        b.knots(),
                        b.points(),
                        &t,
                        times,
                        "u",
                    );
                }
                let (l, r) = split_bspline(b, &t, "t")?;
                (Curve::BSpline(l), Curve::BSpline(r))
            }
            Curve::Nurbs(b) => {
                let h = b.homogeneous();
                if out.steps_on() {
                    out.fact(Fact::Homogeneous);
                    let times = h.degree().saturating_sub(h.knots().multiplicity(&t));
                    crate::curves::curve::explain_boehm(
                        &mut out,
                        h.knots(),
                        h.points(),
                        &t,
                        times,
                        "u",
                    );
                }
                let (l, r) = split_bspline(&h, &t, "t")?;
                let project = |c| NurbsCurve::from_homogeneous(c).map_err(at("t"));
                (Curve::Nurbs(project(l)?), Curve::Nurbs(project(r)?))
            }
            Curve::Map(_) => return Err(ProblemError::at("curve", Fitting::SubdivisionMap)),
        };
        return Ok(out.result(
            Quantity::Curves,
            Exact::List(vec![left.to_exact(), right.to_exact()]),
        ));
    }
    if let Some(s) = &a.surface {
        let s = Patch::<S>::read(s, "surface")?;
        let u = a.u.as_ref().map(|x| num::<S>(x, "u")).transpose()?;
        let v = a.v.as_ref().map(|x| num::<S>(x, "v")).transpose()?;
        if matches!(s, Patch::BSpline(_) | Patch::Nurbs(_)) {
            if u.is_none() && v.is_none() {
                return Err(ProblemError::at("u", Fitting::SplitSurfaceWhere));
            }
            // the size of the answer, known before the work: at most p (q) rows (columns) more,
            // one shared row (column) written twice
            let ((rows, cols), (p, q)) = match &s {
                Patch::BSpline(b) => ((b.mesh().rows(), b.mesh().cols()), b.bidegree()),
                Patch::Nurbs(b) => ((b.mesh().rows(), b.mesh().cols()), b.bidegree()),
                _ => ((0, 0), (0, 0)),
            };
            let grow = |n: usize, d: usize, split: bool| {
                if split {
                    n.saturating_add(d).saturating_add(1)
                } else {
                    n
                }
            };
            run.check_points(
                "surface",
                grow(rows, p, u.is_some()).saturating_mul(grow(cols, q, v.is_some())),
                Fitting::SurfacesOfSubdivision,
            )?;
            // Boehm's insertion on every column (row) of the mesh, to multiplicity p (q)
            out.formula(Formula::Boehm);
            return crate::surfaces::surface_knots::subdivide(&s, u.as_ref(), v.as_ref(), out);
        }
        out.formula(Formula::SubdivideSurface);
        let (zero, one) = (S::zero(), S::one());
        // the rectangles, in the order of the answer
        let rects: Vec<(S, S, S, S)> = match (&u, &v) {
            (Some(u), Some(v)) => vec![
                (zero.clone(), u.clone(), zero.clone(), v.clone()),
                (zero.clone(), u.clone(), v.clone(), one.clone()),
                (u.clone(), one.clone(), zero.clone(), v.clone()),
                (u.clone(), one.clone(), v.clone(), one.clone()),
            ],
            (Some(u), None) => vec![
                (zero.clone(), u.clone(), zero.clone(), one.clone()),
                (u.clone(), one.clone(), zero.clone(), one.clone()),
            ],
            (None, Some(v)) => vec![
                (zero.clone(), one.clone(), zero.clone(), v.clone()),
                (zero.clone(), one.clone(), v.clone(), one.clone()),
            ],
            (None, None) => return Err(ProblemError::at("u", Fitting::SplitPatchWhere)),
        };
        for (key, x) in [("u", &u), ("v", &v)] {
            if let Some(x) = x {
                // a value in letters has no sign: taken inside, as the notes take it
                let outside = matches!(
                    x.compare(&zero),
                    Some(std::cmp::Ordering::Less | std::cmp::Ordering::Equal)
                ) || matches!(
                    x.compare(&one),
                    Some(std::cmp::Ordering::Greater | std::cmp::Ordering::Equal)
                );
                if outside {
                    return Err(ProblemError::at(
                        key,
                        Fitting::NotInsideUnit { x: x.to_text() },
                    ));
                }
            }
        }
        let mut parts = Vec::with_capacity(rects.len());
        for (a0, b0, c0, d0) in &rects {
            if out.steps_on() {
                out.value(
                    "[a, b] \\times [c, d]",
                    Exact::Point(exact_point(&Point::new(vec![
                        a0.clone(),
                        b0.clone(),
                        c0.clone(),
                        d0.clone(),
                    ]))),
                );
            }
            let piece = match &s {
                Patch::Bezier(p) => {
                    Patch::Bezier(p.restrict(a0, b0, c0, d0).map_err(at("surface"))?.result)
                }
                Patch::RationalBezier(p) => {
                    Patch::RationalBezier(p.restrict(a0, b0, c0, d0).map_err(at("surface"))?.result)
                }
                _ => return Err(ProblemError::at("surface", Fitting::SubdivisionPatches)),
            };
            parts.push(piece.to_exact());
        }
        return Ok(out.result(Quantity::Surfaces, Exact::List(parts)));
    }
    Err(ProblemError::at("", Fitting::SubdivideNeeds))
}

/// `boundary`: the four boundary curves of a Bézier (or rational) patch, `curve_u0` = c(0, v),
/// `curve_u1` = c(1, v), `curve_v0` = c(u, 0), `curve_v1` = c(u, 1), whose control polygons
/// are the first and last rows and columns of the mesh (notes ch. 5 §3).
pub(crate) fn boundary<S: ExactScalar>(a: &Boundary, run: Run<'_>) -> Result<Out, ProblemError> {
    let sf = "surface";
    let s = Patch::<S>::read(req(&a.surface, sf)?, sf)?;
    let mut out = run.out();
    out.formula(Formula::BoundarySurface);
    let borders = [
        (Border::U0, quantity::Border::U0),
        (Border::U1, quantity::Border::U1),
        (Border::V0, quantity::Border::V0),
        (Border::V1, quantity::Border::V1),
    ];
    for (border, name) in borders {
        let c = match &s {
            Patch::Bezier(p) => Curve::Bezier(p.boundary(border).map_err(at(sf))?),
            Patch::RationalBezier(p) => {
                let c = p.boundary(border).map_err(at(sf))?;
                Curve::RationalBezier(
                    RationalBezierCurve::try_new(c.points().to_vec(), c.weights().to_vec())
                        .map_err(at(sf))?,
                )
            }
            Patch::BSpline(_) | Patch::Nurbs(_) => {
                // c(u0, v) for u0 = a, b and c(u, v0) for v0 = c, d: iso-parametric curves
                let ((a0, b0), (c0, d0)) = s.domain();
                let (dir_u, x) = match border {
                    Border::U0 => (true, a0),
                    Border::U1 => (true, b0),
                    Border::V0 => (false, c0),
                    Border::V1 => (false, d0),
                };
                iso(&s, dir_u, &x, if dir_u { "u" } else { "v" })?
            }
            Patch::Map(e) => {
                let (var, x) = match border {
                    Border::U0 => (cagd_poly::Var::U, S::zero()),
                    Border::U1 => (cagd_poly::Var::U, S::one()),
                    Border::V0 => (cagd_poly::Var::V, S::zero()),
                    Border::V1 => (cagd_poly::Var::V, S::one()),
                };
                Curve::Map(substitute(e, var, &x))
            }
        };
        out = out.result(Quantity::BoundaryCurve(name), c.to_exact());
    }
    Ok(out)
}

/// A polynomial map with `var` put to `x`.
fn substitute<S: ExactScalar>(e: &VecPoly<S>, var: cagd_poly::Var, x: &S) -> VecPoly<S> {
    VecPoly::new(
        e.components()
            .iter()
            .map(|p| p.substitute(var, &Poly::constant(x.clone())))
            .collect(),
    )
}

/// The iso-parametric curve of a patch at u = x (`along_v`: the curve runs in v) or v = x:
/// De Casteljau (De Boor for a B-spline surface) on every column at u = x, or every row at
/// v = x; a rational patch on its homogeneous mesh, projected.
fn iso<S: ExactScalar>(
    s: &Patch<S>,
    fix_u: bool,
    x: &S,
    key: &str,
) -> Result<Curve<S>, ProblemError> {
    let lines = |m: &Mesh<S>| if fix_u { m.to_columns() } else { m.to_rows() };
    let sf = "surface";
    Ok(match s {
        Patch::Bezier(p) => {
            let dom = p.domain();
            let t = if fix_u {
                dom.local_u(x)
            } else {
                dom.local_v(x)
            };
            let pts = lines(p.mesh())
                .iter()
                .map(|l| cagd_bezier::de_casteljau(l, &t))
                .collect::<Result<Vec<_>, _>>()
                .map_err(at(key))?;
            Curve::Bezier(BezierCurve::try_new(pts).map_err(at(sf))?)
        }
        Patch::RationalBezier(p) => {
            let h = p.homogeneous_patch();
            let dom = p.domain();
            let t = if fix_u {
                dom.local_u(x)
            } else {
                dom.local_v(x)
            };
            let pts = lines(h.mesh())
                .iter()
                .map(|l| cagd_bezier::de_casteljau(l, &t))
                .collect::<Result<Vec<_>, _>>()
                .map_err(at(key))?;
            Curve::RationalBezier(RationalBezierCurve::from_homogeneous(&pts).map_err(at(key))?)
        }
        Patch::BSpline(p) => {
            let (across, along) = if fix_u {
                (p.knots_u(), p.knots_v())
            } else {
                (p.knots_v(), p.knots_u())
            };
            let pts = spline_line_values(&lines(p.mesh()), across, x, key)?;
            Curve::BSpline(BSplineCurve::try_new(along.clone(), pts).map_err(at(sf))?)
        }
        Patch::Nurbs(p) => {
            let h = p.homogeneous();
            let (across, along) = if fix_u {
                (h.knots_u(), h.knots_v())
            } else {
                (h.knots_v(), h.knots_u())
            };
            let pts = spline_line_values(&lines(h.mesh()), across, x, key)?;
            let hc = BSplineCurve::try_new(along.clone(), pts).map_err(at(sf))?;
            Curve::Nurbs(NurbsCurve::from_homogeneous(hc).map_err(at(key))?)
        }
        Patch::Map(e) => Curve::Map(substitute(
            e,
            if fix_u {
                cagd_poly::Var::U
            } else {
                cagd_poly::Var::V
            },
            x,
        )),
    })
}

/// Each polygon of `lines` as a B-spline on `knots`, evaluated at x (De Boor).
fn spline_line_values<S: ExactScalar>(
    lines: &[Vec<Point<S>>],
    knots: &KnotVector<S>,
    x: &S,
    key: &str,
) -> Result<Vec<Point<S>>, ProblemError> {
    lines
        .iter()
        .map(|l| {
            BSplineCurve::try_new(knots.clone(), l.clone())
                .and_then(|c| c.eval(x))
                .map_err(at(key))
        })
        .collect()
}

/// `isocurve`: the curve u = `u` (running in v) or v = `v` (running in u) of a surface of any
/// kind: d_j = Σ_i c_{ij} B_i^m(u0) (De Casteljau on every column at u0; De Boor for a
/// B-spline surface, on the homogeneous mesh for a rational one), a curve of the same kind with
/// the knots and weights of the other direction.
pub(crate) fn isocurve<S: ExactScalar>(a: &Isocurve, run: Run<'_>) -> Result<Out, ProblemError> {
    let s = Patch::<S>::read(req(&a.surface, "surface")?, "surface")?;
    let (fix_u, x, key) = match (&a.u, &a.v) {
        (Some(u), None) => (true, num::<S>(u, "u")?, "u"),
        (None, Some(v)) => (false, num::<S>(v, "v")?, "v"),
        (Some(_), Some(_)) => return Err(ProblemError::at("v", Fitting::IsoBoth)),
        (None, None) => return Err(ProblemError::at("u", Fitting::IsoNeither)),
    };
    let mut out = run.out();
    out.formula(Formula::Isocurve);
    let c = iso(&s, fix_u, &x, key)?;
    if out.steps_on() {
        out.value(if fix_u { "u_0" } else { "v_0" }, explain::number(&x));
        // each point: a column (row) of the mesh evaluated at u0 (v0)
        let points = match &c {
            Curve::Bezier(b) => b.points().to_vec(),
            Curve::RationalBezier(b) => b.points().to_vec(),
            Curve::BSpline(b) => b.points().to_vec(),
            Curve::Nurbs(b) => b.points().to_vec(),
            Curve::Map(_) => Vec::new(),
        };
        for (j, p) in points.iter().enumerate() {
            out.value(format!("d_{{{j}}}"), explain::point(p));
        }
    }
    Ok(out.result(Quantity::Curve, c.to_exact()))
}

/// `extract`: the Bézier pieces of a B-spline (NURBS) curve, `curves` with their `intervals`
/// (every breakpoint inserted up to multiplicity p; each piece read on [0, 1]); of a B-spline
/// (NURBS) surface, the grid of Bézier patches `surfaces` (row a with `u_intervals[a]`, column b
/// with `v_intervals[b]`).
pub(crate) fn extract<S: ExactScalar>(a: &Extract, run: Run<'_>) -> Result<Out, ProblemError> {
    let mut out = run.out();
    out.formula(Formula::Extract);
    let interval =
        |(x, y): &(S, S)| Exact::Point(exact_point(&Point::new(vec![x.clone(), y.clone()])));
    if let Some(c) = &a.curve {
        let cf = "curve";
        let c = Curve::<S>::read(c, cf)?;
        // the size of the answer, known before the work: p + 1 points per span
        let pieces = match &c {
            Curve::BSpline(b) => b.knots().spans().len().saturating_mul(b.degree() + 1),
            Curve::Nurbs(b) => b.knots().spans().len().saturating_mul(b.degree() + 1),
            _ => 0,
        };
        run.check_points(cf, pieces, Fitting::BezierPieces)?;
        let (curves, intervals): (Vec<Exact>, Vec<Exact>) = match &c {
            Curve::BSpline(b) => {
                if out.steps_on() {
                    out.value("u", knots_exact(b.knots()));
                }
                b.bezier_pieces()
                    .map_err(at(cf))?
                    .into_iter()
                    .map(|p| {
                        Ok((
                            Curve::Bezier(BezierCurve::try_new(p.points).map_err(at(cf))?)
                                .to_exact(),
                            interval(&p.interval),
                        ))
                    })
                    .collect::<Result<Vec<_>, ProblemError>>()?
                    .into_iter()
                    .unzip()
            }
            Curve::Nurbs(b) => {
                if out.steps_on() {
                    out.value("u", knots_exact(b.knots()));
                }
                b.bezier_pieces()
                    .map_err(at(cf))?
                    .into_iter()
                    .map(|p| {
                        Ok((
                            Curve::RationalBezier(
                                RationalBezierCurve::try_new(p.points, p.weights)
                                    .map_err(at(cf))?,
                            )
                            .to_exact(),
                            interval(&p.interval),
                        ))
                    })
                    .collect::<Result<Vec<_>, ProblemError>>()?
                    .into_iter()
                    .unzip()
            }
            _ => return Err(ProblemError::at(cf, Fitting::ExtractCurve)),
        };
        return Ok(out
            .result(Quantity::Curves, Exact::List(curves))
            .result(Quantity::Intervals, Exact::List(intervals)));
    }
    if let Some(s) = &a.surface {
        let sf = "surface";
        let s = Patch::<S>::read(s, sf)?;
        let size = |ku: &KnotVector<S>, kv: &KnotVector<S>| {
            let one = |k: &KnotVector<S>| k.spans().len().saturating_mul(k.degree() + 1);
            one(ku).saturating_mul(one(kv))
        };
        let pieces = match &s {
            Patch::BSpline(p) => size(p.knots_u(), p.knots_v()),
            Patch::Nurbs(p) => size(p.knots_u(), p.knots_v()),
            _ => 0,
        };
        run.check_points(sf, pieces, Fitting::BezierPatches)?;
        let (grid, us, vs): (Vec<Exact>, Intervals<S>, Intervals<S>) = match &s {
            Patch::BSpline(p) => {
                let b = p.bezier_patches().map_err(at(sf))?;
                let grid = b
                    .patches
                    .iter()
                    .map(|row| {
                        Exact::List(
                            row.iter()
                                .map(|q| Patch::Bezier(q.clone()).to_exact())
                                .collect(),
                        )
                    })
                    .collect();
                (grid, b.u_intervals, b.v_intervals)
            }
            Patch::Nurbs(p) => {
                let b = p.bezier_patches().map_err(at(sf))?;
                let grid = b
                    .patches
                    .iter()
                    .map(|row| {
                        Exact::List(
                            row.iter()
                                .map(|q| Patch::RationalBezier(q.clone()).to_exact())
                                .collect(),
                        )
                    })
                    .collect();
                (grid, b.u_intervals, b.v_intervals)
            }
            _ => return Err(ProblemError::at(sf, Fitting::ExtractSurface)),
        };
        return Ok(out
            .result(Quantity::Surfaces, Exact::List(grid))
            .result(
                Quantity::IntervalsU,
                Exact::List(us.iter().map(interval).collect()),
            )
            .result(
                Quantity::IntervalsV,
                Exact::List(vs.iter().map(interval).collect()),
            ));
    }
    Err(ProblemError::at("", Fitting::ExtractNeeds))
}

/// `remove_knot`: the knot `knot` removed `times` times (default 1) from a B-spline (NURBS)
/// curve, exactly: the points of the curve without it solve Boehm's relations
/// d_i = (1 - α_i) d̃_{i-1} + α_i d̃_i; when the curve is not the same without the knot (the
/// relations do not all hold), the removal is refused with the reason.
pub(crate) fn remove_knot<S: ExactScalar>(
    a: &RemoveKnot,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let cf = "curve";
    if let Some(sf) = &a.surface {
        let patch = Patch::<S>::read(sf, "surface")?;
        let knot = num::<S>(req(&a.knot, "knot")?, "knot")?;
        let times = run.times(a.times)?;
        let mut out = run.out();
        out.formula(Formula::RemoveKnot);
        let dir = a.direction.unwrap_or(crate::problem::UorV::U);
        return crate::surfaces::surface_knots::remove_knot(&patch, dir, &knot, times, out);
    }
    let c = Curve::<S>::read(req(&a.curve, cf)?, cf)?;
    let knot = num::<S>(req(&a.knot, "knot")?, "knot")?;
    let times = run.times(a.times)?;
    let mut out = run.out();
    out.formula(Formula::RemoveKnot);
    let c = match c {
        Curve::BSpline(b) => {
            if out.steps_on() {
                out.value("u", knots_exact(b.knots()));
            }
            Curve::BSpline(b.remove_knot(&knot, times).map_err(at("knot"))?)
        }
        Curve::Nurbs(b) => {
            if out.steps_on() {
                out.fact(Fact::Homogeneous);
                out.value("u", knots_exact(b.knots()));
            }
            Curve::Nurbs(b.remove_knot(&knot, times).map_err(at("knot"))?)
        }
        _ => return Err(ProblemError::at(cf, Fitting::RemoveKnotCurve)),
    };
    Ok(out.result(Quantity::Curve, c.to_exact()))
}

/// `reduce_degree` of a Bézier curve of degree n by `by` = r (default 1): the polygon c̃ of
/// degree n - r whose elevation E c̃ is nearest the polygon c in the least-squares sense,
/// E^t E c̃ = E^t c (E the (n + 1) × (n - r + 1) matrix of elevating by r, of full rank). When
/// E c̃ = c the curve was of degree n - r and the reduction is exact (`exact`: true, the same
/// curve); otherwise it is the least-squares approximation of the control polygon (`exact`:
/// false, with the `residual` c - E c̃, the curve changes).
pub(crate) fn reduce_degree<S: ExactScalar>(
    a: &ReduceDegree,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let cf = "curve";
    let c = Curve::<S>::read(req(&a.curve, cf)?, cf)?;
    let r = a.by.map(|n| run.degree("by", n)).transpose()?.unwrap_or(1);
    let b = match c {
        Curve::Bezier(b) => b,
        Curve::Map(_) => {
            return Err(ProblemError::at(
                cf,
                crate::message::curve::Curve::ReductionKinds,
            ))
        }
        // rational, B-spline, NURBS: exact, or refused with the reason
        other => return crate::curves::reduce::reduce_exactly(&other, r, run),
    };
    let n = b.degree();
    if r > n {
        let too_far = cagd_bezier::ReductionError::CannotReduce { degree: n, by: r };
        return Err(ProblemError::at("by", too_far));
    }
    let m = n - r;
    let crate::curves::reduce::Reduced {
        reduced,
        back,
        residual,
    } = crate::curves::reduce::reduce_polygon(b.points(), r, cf)?;
    let exact = residual.iter().all(Point::is_zero);
    let mut out = run.out();
    out.formula(if exact {
        Formula::ReduceExact
    } else {
        Formula::ReduceLeastSquares
    });
    out.fact(Fact::Degree { from: n, to: m });
    if out.steps_on() {
        out.value(
            "E \\tilde{c}",
            Exact::Points(crate::value::exact_points(&back)),
        );
    }
    if exact {
        out.remark(crate::message::curve::Curve::ReducedExactly {
            degree: m,
            points: m + 1,
        });
    } else {
        out.remark(Fitting::ReducedLeastSquares { m });
    }
    let (lo, hi) = (b.domain().0.clone(), b.domain().1.clone());
    let curve = Curve::Bezier(
        BezierCurve::try_new(reduced)
            .and_then(|c| c.with_domain(lo, hi))
            .map_err(at(cf))?,
    );
    Ok(out
        .result(Quantity::Curve, curve.to_exact())
        .result(Quantity::IsExact, Exact::Bool(exact))
        .result(
            Quantity::Residual,
            Exact::Points(crate::value::exact_points(&residual)),
        ))
}
