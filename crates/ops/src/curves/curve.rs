//! Operations on curves: evaluation, elevation, restriction, derivatives, knot insertion, and
//! circles.

use crate::any_curve::curve_var;
use crate::convert::convert_points;
use crate::curves::split::split_bspline;
use crate::explain;
use crate::message::curve::Curve as Say;
use crate::out::{at, num, pair, req, Out, Run};
use crate::problem::{Circle, Derivative, Elevate, Evaluate, InsertKnot, Param, Restrict};
use crate::steps::{Fact, Formula};
use crate::value::Quantity;
use crate::value::{exact_map, exact_points, Exact, ExactScalar};
use crate::ProblemError;
use cagd_bspline::{circle_of_arcs, BSplineCurve, KnotConvention, KnotVector, NurbsCurve};
use cagd_linalg::Point;
use cagd_poly::Var;

/// A validated curve of any kind.
use crate::any::AnyCurve as Curve;

/// `evaluate` on a curve: the points c(t) for `params`.
pub(crate) fn evaluate<S: ExactScalar>(a: &Evaluate, run: Run<'_>) -> Result<Out, ProblemError> {
    let c = Curve::<S>::read_with_vectors(req(&a.curve, "curve")?, "curve")?;
    let params = req(&a.params, "params")?;
    let mut points = Vec::with_capacity(params.0.len());
    let mut out = run.out();
    if out.steps_on() {
        out.formula(match &c {
            Curve::Bezier(_) => Formula::DeCasteljau,
            Curve::RationalBezier(_) => Formula::DeCasteljauRational,
            Curve::BSpline(_) | Curve::Nurbs(_) => Formula::DeBoor,
            Curve::Map(_) => Formula::SubstitutionCurve,
        });
        if let Curve::Map(e) = &c {
            out.value("c(t)", Exact::Map(exact_map(e)));
        }
    }
    for (i, t) in params.0.iter().enumerate() {
        let path = format!("params[{i}]");
        let t = match t {
            Param::One(t) => num::<S>(t, &path)?,
            Param::Many(_) => return Err(ProblemError::at(path, Say::ParamIsAList)),
        };
        let p = c.eval(&path, &t)?;
        if explain::worked(&out, i, explain::WORKED_POINTS) {
            explain_point(&mut out, &c, &t, &p);
        }
        points.push(p);
    }
    explain::same_for_the_others(&mut out, points.len(), explain::WORKED_POINTS);
    Ok(out.result(Quantity::Points, Exact::Points(exact_points(&points))))
}

/// The steps of c(t): the scheme of the curve's algorithm and its basis values.
fn explain_point<S: ExactScalar>(out: &mut Out, c: &Curve<S>, t: &S, p: &Point<S>) {
    out.fact(Fact::At {
        params: vec![explain::number(t)],
    });
    match c {
        Curve::Bezier(b) => {
            if let Ok(levels) = b.triangle(t) {
                out.explain(explain::casteljau_table(&levels));
            }
            out.explain(explain::bernstein_table(
                b.degree(),
                &b.local_parameter(t),
                "t",
            ));
        }
        Curve::RationalBezier(b) => {
            out.fact(Fact::Homogeneous);
            if let Ok(levels) = b.triangle_homogeneous(t) {
                out.explain(explain::casteljau_table(&levels));
            }
            out.explain(explain::bernstein_table(
                b.degree(),
                &b.local_parameter(t),
                "t",
            ));
        }
        Curve::BSpline(b) => {
            if let Ok(tri) = b.de_boor_triangle(t) {
                explain::de_boor(out, b.knots(), &tri, "u");
            }
            if let Some(s) = explain::bspline_basis(b.knots(), t, "t") {
                out.explain(s);
            }
        }
        Curve::Nurbs(b) => {
            out.fact(Fact::Homogeneous);
            if let Ok(tri) = b.de_boor_triangle(t) {
                explain::de_boor(out, b.knots(), &tri, "u");
            }
            if let Some(s) = explain::bspline_basis(b.knots(), t, "t") {
                out.explain(s);
            }
        }
        Curve::Map(_) => {}
    }
    out.value("c(t)", explain::point(p));
}

/// `elevate` on a curve by `by` = r.
pub(crate) fn elevate<S: ExactScalar>(a: &Elevate, run: Run<'_>) -> Result<Out, ProblemError> {
    let c = Curve::<S>::read_with_vectors(req(&a.curve, "curve")?, "curve")?;
    let r = match req(&a.by, "by")? {
        crate::spec::Orders::One(r) => r.get(),
        crate::spec::Orders::Two(..) => {
            return Err(ProblemError::at("by", Say::OrderIsAList { found: 2 }))
        }
    };
    if !matches!(c, Curve::Map(_)) {
        let p0 = c.degree();
        run.check_degree(
            "by",
            p0.saturating_add(r),
            crate::message::limited::Limited::ElevatingDegree { from: p0, by: r },
        )?;
        run.check_points(
            "curve",
            c.elevated_len(r),
            crate::message::limited::Limited::ElevatedCurve,
        )?;
    }
    let cf = "curve";
    let mut out = run.out();
    if out.steps_on() {
        explain_elevation(&mut out, &c, r);
    }
    let c = match c {
        Curve::Bezier(c) => Curve::Bezier(c.elevate_degree(r)),
        Curve::RationalBezier(c) => Curve::RationalBezier(c.elevate_degree(r).map_err(at(cf))?),
        Curve::BSpline(c) => Curve::BSpline(c.elevate_degree(r).map_err(at(cf))?),
        Curve::Nurbs(c) => Curve::Nurbs(c.elevate_degree(r).map_err(at(cf))?),
        Curve::Map(_) => return Err(ProblemError::at(cf, Say::ElevateExpression)),
    };
    run.check_points(
        cf,
        c.point_count(),
        crate::message::limited::Limited::ElevatedCurve,
    )?;
    if out.steps_on() {
        if let Curve::BSpline(b) = &c {
            out.value("\\hat{u}", knots_exact(b.knots()));
        }
        if let Curve::Nurbs(b) = &c {
            out.value("\\hat{u}", knots_exact(b.knots()));
        }
    }
    Ok(out.result(Quantity::Curve, c.to_exact()))
}

/// A knot vector in the notes' convention.
pub(crate) fn knots_exact<S: ExactScalar>(k: &KnotVector<S>) -> Exact {
    Exact::List(
        k.to_convention(KnotConvention::Notes)
            .iter()
            .map(explain::number)
            .collect(),
    )
}

/// A Bézier piece of a B-spline: its interval and its control points.
pub(crate) type Piece<S> = ((S, S), Vec<Point<S>>);

/// The Bézier pieces of a B-spline, each elevated r times (the rule of
/// [`Formula::ElevateCurve`] on each), as combinations.
fn elevate_pieces<S: ExactScalar>(out: &mut Out, pieces: &[Piece<S>], r: usize) {
    out.formula(Formula::ElevateCurve);
    elevate_pieces_named(out, pieces, r, &|i| format!("b_{{{i}}}"));
}

/// The pieces of [`elevate_pieces`], with `name(i)` the symbol of the piece's point i.
pub(crate) fn elevate_pieces_named<S: ExactScalar>(
    out: &mut Out,
    pieces: &[Piece<S>],
    r: usize,
    name: &dyn Fn(usize) -> String,
) {
    for (k, ((a, b), points)) in pieces.iter().enumerate() {
        out.fact(Fact::Piece {
            index: k,
            interval: vec![explain::number(a), explain::number(b)],
        });
        let mut points = points.clone();
        for step in 0..r {
            let prime = |s: usize| {
                if s == 0 {
                    String::new()
                } else {
                    format!("^{{({s})}}")
                }
            };
            let (before, after) = (prime(step), prime(step + 1));
            points =
                explain::elevate_once(out, &points, &|i| format!("{}{before}", name(i)), &|i| {
                    format!("{}{after}", name(i))
                });
        }
    }
}

/// The Bézier pieces of the B-spline curve of `knots` and `points`.
pub(crate) fn pieces_of<S: ExactScalar>(
    knots: &KnotVector<S>,
    points: &[Point<S>],
) -> Vec<Piece<S>> {
    BSplineCurve::try_new(knots.clone(), points.to_vec())
        .and_then(|c| c.bezier_pieces())
        .map(|ps| ps.into_iter().map(|p| (p.interval, p.points)).collect())
        .unwrap_or_default()
}

/// The combinations of each elevation by one, r times (on the homogeneous points of a
/// rational curve); for a B-spline, the rule and the knots before.
fn explain_elevation<S: ExactScalar>(out: &mut Out, c: &Curve<S>, r: usize) {
    let polygon = match c {
        Curve::Bezier(b) => b.points().to_vec(),
        Curve::RationalBezier(b) => b.homogeneous(),
        Curve::BSpline(b) => {
            out.formula(Formula::ElevateBSpline);
            out.value("u", knots_exact(b.knots()));
            if let Ok(pieces) = b.bezier_pieces() {
                let pieces: Vec<_> = pieces.into_iter().map(|p| (p.interval, p.points)).collect();
                elevate_pieces(out, &pieces, r);
            }
            return;
        }
        Curve::Nurbs(b) => {
            out.formula(Formula::ElevateBSpline);
            out.fact(Fact::Homogeneous);
            out.value("u", knots_exact(b.knots()));
            if let Ok(pieces) = b.homogeneous().bezier_pieces() {
                let pieces: Vec<_> = pieces.into_iter().map(|p| (p.interval, p.points)).collect();
                elevate_pieces(out, &pieces, r);
            }
            return;
        }
        Curve::Map(_) => return,
    };
    out.formula(Formula::ElevateCurve);
    if matches!(c, Curve::RationalBezier(_)) {
        out.fact(Fact::Homogeneous);
    }
    let mut points = polygon;
    for step in 0..r {
        let n = points.len().saturating_sub(1);
        out.fact(Fact::Degree { from: n, to: n + 1 });
        let prime = |k: usize| {
            if k == 0 {
                String::new()
            } else {
                format!("^{{({k})}}")
            }
        };
        let (before, after) = (prime(step), prime(step + 1));
        points = explain::elevate_once(out, &points, &|i| format!("c_{{{i}}}{before}"), &|i| {
            format!("c_{{{i}}}{after}")
        });
    }
}

/// `restrict` a Bézier curve to `t` = [a, b] (the control polygon of c on [a, b], read on [0, 1]).
pub(crate) fn restrict<S: ExactScalar>(a: &Restrict, run: Run<'_>) -> Result<Out, ProblemError> {
    let cf = "curve";
    let c = Curve::<S>::read_with_vectors(req(&a.curve, cf)?, cf)?;
    let (t0, t1) = pair::<S>(req(&a.t, "t")?, "t")?;
    let mut out = run.out();
    if out.steps_on() {
        explain_restriction(&mut out, &c, &t0, &t1);
    }
    let c = match c {
        Curve::Bezier(c) => Curve::Bezier(
            c.restrict(&t0, &t1)
                .and_then(|r| r.with_domain(S::zero(), S::one()))
                .map_err(at(cf))?,
        ),
        Curve::RationalBezier(c) => Curve::RationalBezier(
            c.restrict(&t0, &t1)
                .and_then(|r| r.with_domain(S::zero(), S::one()))
                .map_err(at(cf))?,
        ),
        _ => return Err(ProblemError::at(cf, Say::RestrictBezierOnly)),
    };
    Ok(out.result(Quantity::Curve, c.to_exact()))
}

/// c̃_i = c[a^<n-i>, b^<i>], each blossom evaluated (on the homogeneous points of a rational
/// curve).
fn explain_restriction<S: ExactScalar>(out: &mut Out, c: &Curve<S>, a: &S, b: &S) {
    let n = c.degree();
    out.formula(Formula::RestrictCurve);
    out.value("a", explain::number(a));
    out.value("b", explain::number(b));
    if matches!(c, Curve::RationalBezier(_)) {
        out.fact(Fact::Homogeneous);
    }
    for i in 0..=n {
        let args: Vec<S> = std::iter::repeat_n(a.clone(), n - i)
            .chain(std::iter::repeat_n(b.clone(), i))
            .collect();
        let value = match c {
            Curve::Bezier(b) => b.blossom(&args).ok(),
            Curve::RationalBezier(b) => b.blossom_homogeneous(&args).ok(),
            _ => None,
        };
        let Some(value) = value else { return };
        let shown: Vec<String> = args.iter().map(|x| x.to_text()).collect();
        out.value(
            format!("\\tilde{{c}}_{{{i}}} = c[{}]", shown.join(", ")),
            explain::point(&value),
        );
    }
}

/// `derivative` of order r of a curve: the derivative curve's control polygon (Bézier), or
/// its closed form.
pub(crate) fn derivative<S: ExactScalar>(
    a: &Derivative,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let cf = "curve";
    let c = Curve::<S>::read_with_vectors(req(&a.curve, cf)?, cf)?;
    let r = match req(&a.order, "order")? {
        crate::spec::Orders::One(r) => run.degree("order", *r)?,
        crate::spec::Orders::Two(..) => {
            return Err(ProblemError::at("order", Say::OrderIsAList { found: 2 }))
        }
    };
    let mut out = run.out();
    match c {
        Curve::Bezier(c) => {
            if out.steps_on() {
                let n = c.degree();
                out.formula(Formula::DerivativeCurve);
                let levels: Vec<Vec<Point<S>>> =
                    (0..=r.min(n)).map(|k| c.forward_differences(k)).collect();
                out.explain(explain::titled_differences(explain::casteljau_table(
                    &levels,
                )));
                out.value(
                    format!("{n}!/({n}-{r})!"),
                    explain::number(&explain::falling::<S>(n, r)),
                );
            }
            let d = c.derivative(r);
            let closed = d.closed_form(Var::T);
            Ok(out
                .result(Quantity::Curve, Curve::Bezier(d).to_exact())
                .closed_form(Exact::Map(exact_map(&closed))))
        }
        Curve::Map(e) => {
            let var = curve_var(&e);
            let mut d = e;
            for _ in 0..r {
                if d.is_zero() {
                    break;
                }
                d = d.partial(var);
            }
            out.formula(Formula::DerivativeMap);
            Ok(out.closed_form(Exact::Map(exact_map(&d))))
        }
        Curve::RationalBezier(_) | Curve::BSpline(_) | Curve::Nurbs(_) => {
            crate::pieces::curve_derivative(&c, r, cf, out)
        }
    }
}

/// `insert_knot` into a B-spline or NURBS curve.
pub(crate) fn insert_knot<S: ExactScalar>(
    a: &InsertKnot,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let cf = "curve";
    let c = Curve::<S>::read(req(&a.curve, cf)?, cf)?;
    let knot = num::<S>(req(&a.knot, "knot")?, "knot")?;
    let times = run.times(a.times)?;
    run.check_points(
        cf,
        c.point_count().saturating_add(times),
        crate::message::limited::Limited::CurveKnotInserted,
    )?;
    if let Some(s) = splits(&c, &knot, times)? {
        return split_by_insertion(&c, &knot, s, run.out());
    }
    let mut out = run.out();
    if out.steps_on() {
        match &c {
            Curve::BSpline(b) => explain_boehm(&mut out, b.knots(), b.points(), &knot, times, "u"),
            Curve::Nurbs(b) => {
                out.fact(Fact::Homogeneous);
                let h = b.homogeneous();
                explain_boehm(&mut out, h.knots(), h.points(), &knot, times, "u");
            }
            _ => {}
        }
    }
    let c = match c {
        Curve::BSpline(c) => Curve::BSpline(c.insert_knot(&knot, times).map_err(at(cf))?),
        Curve::Nurbs(c) => Curve::Nurbs(c.insert_knot(&knot, times).map_err(at(cf))?),
        _ => return Err(ProblemError::at(cf, Say::InsertNeedsBSpline)),
    };
    Ok(out.result(Quantity::Curve, c.to_exact()))
}

/// Whether inserting `knot` `times` times splits the curve: an interior knot reaching
/// multiplicity p + 1 (the same count in the notes' convention and in The NURBS Book's, which
/// differ only at the ends) does, and its multiplicity before is returned; past p + 1 the
/// insertion is refused with the reason; `None` when it stays at or below p, or the knot is an
/// end of the domain (then the insertion itself refuses it).
fn splits<S: ExactScalar>(
    c: &Curve<S>,
    knot: &S,
    times: usize,
) -> Result<Option<usize>, ProblemError> {
    let knots = match c {
        Curve::BSpline(b) => b.knots(),
        Curve::Nurbs(b) => b.knots(),
        _ => return Ok(None),
    };
    let (a, b) = knots.domain();
    let (p, s) = (knots.degree(), knots.multiplicity(knot));
    if !(a < *knot && *knot < b) || s.saturating_add(times) <= p {
        return Ok(None);
    }
    if s.saturating_add(times) > p + 1 {
        return Err(ProblemError::at(
            "times",
            Say::InsertBeyondSplit {
                knot: knot.to_text(),
                multiplicity: s,
                times,
                degree: p,
            },
        ));
    }
    Ok(Some(s))
}

/// The curve split by `knot` inserted up to multiplicity p + 1 from `s`
/// ([`BSplineCurve::split_at`]: Boehm up to multiplicity p, where the curve passes through a
/// control point, then the knots and points cut there): the two curves, each on its own knots.
fn split_by_insertion<S: ExactScalar>(
    c: &Curve<S>,
    knot: &S,
    s: usize,
    mut out: Out,
) -> Result<Out, ProblemError> {
    let (left, right) = match c {
        Curve::BSpline(b) => {
            let p = b.degree();
            out.remark(Say::SplitByInsertion {
                knot: knot.to_text(),
                degree: p,
            });
            if out.steps_on() && s < p {
                explain_boehm(&mut out, b.knots(), b.points(), knot, p - s, "u");
            }
            let (l, r) = split_bspline(b, knot, "knot")?;
            (Curve::BSpline(l), Curve::BSpline(r))
        }
        Curve::Nurbs(b) => {
            let (p, h) = (b.degree(), b.homogeneous());
            out.remark(Say::SplitByInsertion {
                knot: knot.to_text(),
                degree: p,
            });
            if out.steps_on() {
                out.fact(Fact::Homogeneous);
                if s < p {
                    explain_boehm(&mut out, h.knots(), h.points(), knot, p - s, "u");
                }
            }
            let (l, r) = split_bspline(&h, knot, "knot")?;
            let project = |c| NurbsCurve::from_homogeneous(c).map_err(at("knot"));
            (Curve::Nurbs(project(l)?), Curve::Nurbs(project(r)?))
        }
        _ => return Err(ProblemError::at("curve", Say::InsertNeedsBSpline)),
    };
    Ok(out.result(
        Quantity::Curves,
        Exact::List(vec![left.to_exact(), right.to_exact()]),
    ))
}

/// Boehm's insertion of t, `times` times: the span, the α_i, the new points as combinations
/// and which points changed.
pub(crate) fn explain_boehm<S: ExactScalar>(
    out: &mut Out,
    knots: &KnotVector<S>,
    points: &[Point<S>],
    t: &S,
    times: usize,
    knot_name: &str,
) {
    out.formula(Formula::Boehm);
    explain_boehm_lines(
        out,
        knots,
        &[points.to_vec()],
        t,
        times,
        knot_name,
        &|i, _| format!("d_{{{i}}}"),
    );
}

/// Boehm's insertion into several polygons on the same knots (the columns or rows of a
/// mesh): the span and the α_i once per insertion, then the new points of each polygon,
/// `name(i, line)` the symbol of point i of a polygon.
pub(crate) fn explain_boehm_lines<S: ExactScalar>(
    out: &mut Out,
    knots: &KnotVector<S>,
    lines: &[Vec<Point<S>>],
    t: &S,
    times: usize,
    knot_name: &str,
    name: &dyn Fn(usize, usize) -> String,
) {
    let Ok(all) = lines
        .iter()
        .map(|l| {
            let mut steps = Vec::with_capacity(times);
            cagd_bspline::insert_knot_recorded(knots, l, t, times, &mut steps).map(|_| steps)
        })
        .collect::<Result<Vec<_>, _>>()
    else {
        return;
    };
    let p = knots.degree();
    let mut before: Vec<Vec<Point<S>>> = lines.to_vec();
    let mut knots_before = knots.clone();
    for n in 0..times {
        let Some(step) = all.first().and_then(|s| s.get(n)) else {
            return;
        };
        if times > 1 {
            out.fact(Fact::Insertion {
                step: n + 1,
                of: times,
            });
        }
        let k = step.first + p - 1;
        out.explain(explain::span(&knots_before, k, t, knot_name));
        for (i, alpha) in (step.first..).zip(&step.alphas) {
            out.value(format!("\\alpha_{{{i}}}"), explain::number(alpha));
        }
        for (line, steps) in all.iter().enumerate() {
            let (Some(step), Some(old)) = (steps.get(n), before.get(line)) else {
                continue;
            };
            for (i, alpha) in (step.first..).zip(&step.alphas) {
                let (Some(new), Some(left), Some(right)) =
                    (step.points.get(i), old.get(i - 1), old.get(i))
                else {
                    continue;
                };
                let hat = name(i, line).replacen('d', "\\hat{d}", 1);
                out.explain(explain::combination(
                    hat,
                    vec![
                        (
                            S::one() - alpha.clone(),
                            name(i - 1, line),
                            explain::point(left),
                        ),
                        (alpha.clone(), name(i, line), explain::point(right)),
                    ],
                    explain::point(new),
                ));
            }
        }
        out.fact(Fact::Changed {
            first: step.first,
            last: k,
        });
        knots_before = step.knots.clone();
        before = all
            .iter()
            .filter_map(|s| s.get(n).map(|x| x.points.clone()))
            .collect();
    }
}

/// `circle`: the circle of `radius` (default 1) about `center` (default the origin of R^3, the
/// circle in the plane z = c_z) as a quadratic NURBS of `arcs` arcs (default 4) on `interval`
/// (default [0, 1]; the slides use [0, 4]).
pub(crate) fn circle<S: ExactScalar>(a: &Circle, run: Run<'_>) -> Result<Out, ProblemError> {
    let radius = a
        .radius
        .as_ref()
        .map(|r| num::<S>(r, "radius"))
        .transpose()?
        .unwrap_or_else(S::one);
    let arcs = a
        .arcs
        .map(|n| run.count("arcs", n))
        .transpose()?
        .unwrap_or(4);
    if a.arcs.is_some() {
        run.check_points(
            "arcs",
            arcs.saturating_mul(2).saturating_add(1),
            crate::message::limited::Limited::Circle,
        )?;
    }
    let center = match &a.center {
        Some(c) => convert_points::<S>(std::slice::from_ref(&c.0), "center")?
            .pop()
            .unwrap_or_else(|| Point::zero(3)),
        None => Point::zero(3),
    };
    if center.dim() < 2 {
        return Err(ProblemError::at("", Say::CircleCenter));
    }
    let domain = match &a.interval {
        Some(i) => pair::<S>(i, "interval")?,
        None => (S::zero(), S::one()),
    };
    let c = match &a.sweep {
        Some(sweep) => {
            let sweep = crate::curves::arc::degrees::<S>(sweep, "sweep")?;
            let start = match &a.start {
                Some(x) => crate::curves::arc::degrees::<S>(x, "start")?,
                None => cagd_scalar::BigRational::from_integer(0.into()),
            };
            let arcs = match a.arcs {
                Some(n) => run.count("arcs", n)?,
                None => cagd_bspline::default_arcs(&sweep),
            };
            run.check_points(
                "arcs",
                arcs.saturating_mul(2).saturating_add(1),
                crate::message::limited::Limited::Arc,
            )?;
            crate::curves::arc::arc(&radius, &start, &sweep, arcs, domain, "sweep")?
        }
        None => {
            if a.start.is_some() {
                return Err(ProblemError::at("start", Say::StartWithoutSweep));
            }
            circle_of_arcs(arcs, &radius, None, domain).map_err(at(""))?
        }
    };
    let moved: Vec<Point<S>> = c
        .points()
        .iter()
        .map(|q| {
            let mut coords = center.coords().to_vec();
            for (c, x) in coords.iter_mut().zip(q.coords()).take(2) {
                *c = c.add_ref(x);
            }
            Point::new(coords)
        })
        .collect();
    let moved =
        NurbsCurve::try_new(c.knots().clone(), moved, c.weights().to_vec()).map_err(at(""))?;
    let mut out = run.out();
    if out.steps_on() {
        out.formula(Formula::Circle);
        out.value(
            "N",
            explain::number(&S::from_i64(i64::try_from(arcs).unwrap_or(i64::MAX))),
        );
        if let Some(w) = moved.weights().get(1) {
            out.value("w", explain::number(w));
        }
        out.value("u", knots_exact(moved.knots()));
    }
    Ok(out.result(Quantity::Curve, Curve::Nurbs(moved).to_exact()))
}
