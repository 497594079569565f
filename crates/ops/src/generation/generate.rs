//! Surface generation (chapter 6): translational, ruled, developable, Coons, revolution.

use crate::any::AnyCurve as Curve;
use crate::any::AnySurface as Patch;
use crate::any_curve::curve_var;
use crate::explain;
use crate::input::CurveIn;
use crate::message::surface::Surface;
use crate::out::{at, pair as num_pair, req, Out, Run};
use crate::problem::{Blend, Coons, Developable, Revolution, Ruled, Translational};
use crate::steps::{Fact, Formula};
use crate::value::Number;
use crate::value::Quantity;
use crate::value::{
    exact, exact_grid, exact_map, exact_mesh, exact_point, exact_poly, exact_rational, Exact,
    ExactScalar,
};
use crate::ProblemError;
use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_bspline::{BSplineCurve, NurbsCurve};
use cagd_generate::{
    coons_bezier, coons_bspline, coons_surface_blended, developability, developability_bezier,
    nurbs_from_bezier, revolution_bezier_quadrant, revolution_nurbs, revolution_nurbs_arcs,
    revolution_surface, ruled_bezier, ruled_bspline, ruled_nurbs, ruled_rational, ruled_surface,
    translational_bezier, translational_bspline, translational_nurbs, translational_rational,
    translational_surface, Blending, GenerateError, Note, Step, StepValue,
};
use cagd_poly::{Poly, Var, VecPoly};
use cagd_record::NoSteps;
use cagd_surface::{BezierSurface, RationalBezierSurface};

/// The curves of a construction, brought to one kind.
enum Curves<S: ExactScalar> {
    Poly(Vec<VecPoly<S>>),
    Bezier(Vec<BezierCurve<S>>),
    Rational(Vec<RationalBezierCurve<S>>),
    BSpline(Vec<BSplineCurve<S>>),
    Nurbs(Vec<NurbsCurve<S>>),
}

/// The error of a construction, at the field of the curve it blames when it names one
/// (`d1` for "curves c1 and d1 do not meet at corner a").
fn blame<'k>(keys: &'k [(&'k str, Var)]) -> impl Fn(GenerateError) -> ProblemError + 'k {
    move |e| {
        let named = match &e {
            GenerateError::CornerMismatch { second_at, .. } => Some(second_at.as_str()),
            GenerateError::CurvesDoNotMeet { second, .. } => Some(second.as_str()),
            _ => None,
        };
        let key = named
            .and_then(|at| at.split('(').next())
            .map(str::trim)
            .filter(|k| ["c", "d", "c1", "c2", "d1", "d2"].contains(k));
        // translational names its curves c1, d1 where the problem says c, d
        let field = key.and_then(|k| {
            keys.iter()
                .map(|(name, _)| *name)
                .find(|name| *name == k || *name == k.trim_end_matches('1'))
        });
        ProblemError::at(field.unwrap_or(""), e)
    }
}

/// A polynomial curve written in the variable `var` (an expression in t is renamed).
fn in_var<S: ExactScalar>(e: &VecPoly<S>, var: Var) -> VecPoly<S> {
    let own = curve_var(e);
    if own == var {
        e.clone()
    } else {
        e.substitute(own, &Poly::var(var))
    }
}

/// Reads the curves at `keys`, each to be parametrized by the matching variable, and brings
/// them to one kind: expressions if any is an expression (Bézier curves are expanded),
/// rational if any is rational (polynomial ones get unit weights), B-spline likewise.
fn read_curves<S: ExactScalar>(
    given: &[&Option<CurveIn<Number>>],
    keys: &[(&str, Var)],
) -> Result<Curves<S>, ProblemError> {
    let mut fields: Vec<&str> = Vec::new();
    let mut curves = Vec::new();
    for (c, (k, _)) in given.iter().zip(keys) {
        curves.push(Curve::<S>::read(req(c, k)?, k)?);
        fields.push(k);
    }
    let any = |pred: fn(&Curve<S>) -> bool| curves.iter().any(pred);
    if any(|c| matches!(c, Curve::Map(_))) {
        let mut out = Vec::new();
        for ((c, f), (_, var)) in curves.into_iter().zip(&fields).zip(keys) {
            out.push(match c {
                Curve::Map(e) => in_var(&e, *var),
                Curve::Bezier(b) => b.closed_form(*var),
                _ => return Err(ProblemError::at(*f, Surface::CurvesAsExpressions)),
            });
        }
        return Ok(Curves::Poly(out));
    }
    if any(|c| matches!(c, Curve::BSpline(_) | Curve::Nurbs(_))) {
        if any(|c| matches!(c, Curve::Bezier(_) | Curve::RationalBezier(_))) {
            return Err(ProblemError::at("", Surface::MixingBezierBSpline));
        }
        if any(|c| matches!(c, Curve::Nurbs(_))) {
            let mut out = Vec::new();
            for (c, f) in curves.into_iter().zip(&fields) {
                out.push(match c {
                    Curve::Nurbs(n) => n,
                    Curve::BSpline(b) => {
                        let w = vec![S::one(); b.points().len()];
                        NurbsCurve::try_new(b.knots().clone(), b.points().to_vec(), w)
                            .map_err(at(f))?
                    }
                    _ => return Err(ProblemError::at(*f, Surface::ExpectedBSplineCurve)),
                });
            }
            return Ok(Curves::Nurbs(out));
        }
        let out = curves
            .into_iter()
            .filter_map(|c| match c {
                Curve::BSpline(b) => Some(b),
                _ => None,
            })
            .collect();
        return Ok(Curves::BSpline(out));
    }
    if any(|c| matches!(c, Curve::RationalBezier(_))) {
        let mut out = Vec::new();
        for (c, f) in curves.into_iter().zip(&fields) {
            out.push(match c {
                Curve::RationalBezier(r) => r,
                Curve::Bezier(b) => {
                    let w = vec![S::one(); b.points().len()];
                    RationalBezierCurve::try_new(b.points().to_vec(), w).map_err(at(f))?
                }
                _ => return Err(ProblemError::at(*f, Surface::ExpectedBezierCurve)),
            });
        }
        return Ok(Curves::Rational(out));
    }
    Ok(Curves::Bezier(
        curves
            .into_iter()
            .filter_map(|c| match c {
                Curve::Bezier(b) => Some(b),
                _ => None,
            })
            .collect(),
    ))
}

/// Names of steps that repeat the result itself.
const RESULT_STEPS: &[&str] = &["mesh", "weights", "c", "c(u, v)"];

/// The recorder of a construction's steps: a list when the steps are asked, else nothing.
fn recorder<S: ExactScalar>(out: &Out) -> Option<Vec<Step<S>>> {
    out.steps_on().then(Vec::new)
}

/// Adds a construction's remarks (its notes, kept with or without steps) and its recorded
/// steps as named exact values (those that repeat the result left out).
fn with_steps<S: ExactScalar>(mut out: Out, notes: &[Note], steps: Option<Vec<Step<S>>>) -> Out {
    // remarks are words about what was done: kept with or without steps
    for n in notes {
        out.remark(n.clone());
    }
    for s in steps.unwrap_or_default() {
        if RESULT_STEPS.contains(&s.name.as_str()) {
            continue;
        }
        let value = match &s.value {
            StepValue::Number(x) => Exact::Number(exact(x)),
            StepValue::Point(p) => Exact::Point(exact_point(p)),
            StepValue::Poly(p) => Exact::Poly(exact_poly(p)),
            StepValue::Map(m) => Exact::Map(exact_map(m)),
            StepValue::Rational(r) => Exact::Rational(exact_rational(r)),
            StepValue::Mesh(m) => Exact::Surface(crate::input::SurfaceIn::Bezier {
                mesh: exact_mesh(m),
                weights: None,
            }),
            StepValue::Weights(w) => Exact::Matrix(exact_grid(w).to_rows()),
            _ => Exact::Text(s.to_text()),
        };
        // the construction's name for its step, read into its kind once
        let quantity = Quantity::from_name(&s.name, || value.variables());
        out = out.step(quantity, value);
    }
    out
}

/// How the mesh of a construction is read in its steps.
#[derive(Clone, Copy)]
enum MeshSteps {
    /// Ruled: the columns j = 0, 1 are the polygons of c_1 and c_2, each raised the times
    /// given to the degree of the other.
    Ruled {
        /// How many degrees c_1 and c_2 were raised.
        raised: [usize; 2],
    },
    /// Revolution: row i is the circle C_i of the vertex c_i, its weights w_i ω_j.
    Revolution,
}

/// The rows or columns of the mesh of the construction's result (`surface`), as the notes
/// read them: recorded after the result (only with steps).
fn mesh_steps(mut out: Out, how: MeshSteps) -> Out {
    if !out.steps_on() {
        return out;
    }
    let surface = out
        .result
        .iter()
        .find(|(k, _)| *k == Quantity::Surface)
        .map(|(_, v)| v.clone());
    let (mesh, weights) = match surface {
        Some(Exact::Surface(
            crate::input::SurfaceIn::Bezier { mesh, weights }
            | crate::input::SurfaceIn::BSpline { mesh, weights, .. },
        )) => (mesh, weights),
        _ => return out,
    };
    match how {
        MeshSteps::Ruled { raised } => {
            for (j, curve) in [(0, 1), (1, 2)] {
                let power = match raised.get(j) {
                    Some(&r) if r > 0 => format!("^{{({r})}}"),
                    _ => String::new(),
                };
                if let Some(col) = mesh.column(j) {
                    out.value(
                        format!("c_{{i,{j}}} = c_{{{curve}i}}{power}"),
                        Exact::Points(col),
                    );
                }
            }
        }
        MeshSteps::Revolution => {
            for (i, row) in mesh.to_rows().into_iter().enumerate() {
                out.value(format!("c_{{{i},j}} = (C_{{{i}}})_j"), Exact::Points(row));
                if let Some(w) = weights.as_ref().and_then(|w| w.row(i)) {
                    out.value(
                        format!("w_{{{i},j}} = w_{{{i}}} \\omega_j"),
                        Exact::List(w.iter().cloned().map(Exact::Number).collect()),
                    );
                }
            }
        }
    }
    out
}

fn pair<T>(v: &[T]) -> Result<(&T, &T), ProblemError> {
    match v {
        [a, b] => Ok((a, b)),
        _ => Err(ProblemError::at("", Surface::ExpectedTwoCurves)),
    }
}

fn four<T>(v: &[T]) -> Result<[&T; 4], ProblemError> {
    match v {
        [a, b, c, d] => Ok([a, b, c, d]),
        _ => Err(ProblemError::at("", Surface::ExpectedFourCurves)),
    }
}

fn bezier<S: ExactScalar>(s: &BezierSurface<S>) -> Exact {
    Exact::bezier_surface(s.mesh(), None)
}

fn rational<S: ExactScalar>(s: &RationalBezierSurface<S>) -> Exact {
    Exact::bezier_surface(s.mesh(), Some(s.weights()))
}

fn closed<S: ExactScalar>(s: &BezierSurface<S>) -> Result<Exact, ProblemError> {
    Ok(Exact::Map(exact_map(&s.closed_form().map_err(at(""))?)))
}

/// (4): c_{i,j} = c_{1i} + d_{1j} - a for every point of the mesh, with a = c_{10} = d_{10}.
fn explain_translational<S: ExactScalar>(
    out: &mut Out,
    c: &[cagd_linalg::Point<S>],
    d: &[cagd_linalg::Point<S>],
    mesh: &cagd_surface::Mesh<S>,
) {
    let Some(a) = c.first() else { return };
    for ((i, j), p) in mesh.indexed() {
        let (Some(ci), Some(dj)) = (c.get(i), d.get(j)) else {
            continue;
        };
        out.explain(explain::combination(
            format!("c_{{{i},{j}}}"),
            vec![
                (S::one(), format!("c_{{1{i}}}"), explain::point(ci)),
                (S::one(), format!("d_{{1{j}}}"), explain::point(dj)),
                (-S::one(), "a".to_string(), explain::point(a)),
            ],
            explain::point(p),
        ));
    }
}

/// (5): w_{i,j} = w_{1i} ω_{1j} for every weight of the mesh, the weights of the two curves
/// multiplied.
fn explain_weights<S: ExactScalar>(
    out: &mut Out,
    w: &[S],
    omega: &[S],
    weights: &cagd_surface::Grid<S>,
) {
    for ((i, j), x) in weights.indexed() {
        let (Some(wi), Some(oj)) = (w.get(i), omega.get(j)) else {
            continue;
        };
        out.explain(crate::steps::Step::Product {
            symbol: format!("w_{{{i},{j}}}"),
            factors: vec![
                (format!("w_{{1{i}}}"), explain::number(wi)),
                (format!("\\omega_{{1{j}}}"), explain::number(oj)),
            ],
            value: explain::number(x),
        });
    }
}

/// `translational`: c(u) + d(v) - a, eq. (1), (4), (5).
pub(crate) fn translational<S: ExactScalar>(
    a: &Translational,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let keys = [("c", Var::U), ("d", Var::V)];
    let curves = read_curves::<S>(&[&a.c, &a.d], &keys)?;
    let p = &keys;
    let mut out = run.out();
    out.formula(Formula::Translational);
    if let (Curves::Poly(v), true) = (&curves, out.steps_on()) {
        for (name, c) in ["c_1(u)", "d_1(v)"].iter().zip(v) {
            out.value(*name, Exact::Map(exact_map(c)));
        }
    }
    if !matches!(curves, Curves::Poly(_)) {
        out.formula(Formula::TranslationalMesh);
        out.fact(Fact::Construction);
    }
    Ok(match curves {
        Curves::Poly(v) => {
            let (c, d) = pair(&v)?;
            let mut steps = recorder(&out);
            let t = translational_surface(c, d, &mut steps).map_err(blame(p))?;
            with_steps(
                out.closed_form(Exact::Map(exact_map(&t.surface))),
                &[],
                steps,
            )
        }
        Curves::Bezier(v) => {
            let (c, d) = pair(&v)?;
            let mut steps = recorder(&out);
            let t = translational_bezier(c, d, &mut steps).map_err(blame(p))?;
            let mut out = out
                .result(Quantity::Surface, bezier(&t.surface))
                .closed_form(closed(&t.surface)?);
            if out.steps_on() {
                explain_translational(&mut out, c.points(), d.points(), t.surface.mesh());
            }
            with_steps(out, &[], steps)
        }
        Curves::Rational(v) => {
            let (c, d) = pair(&v)?;
            let mut steps = recorder(&out);
            let t = translational_rational(c, d, &mut steps).map_err(blame(p))?;
            if out.steps_on() {
                explain_translational(&mut out, c.points(), d.points(), t.surface.mesh());
                explain_weights(&mut out, c.weights(), d.weights(), t.surface.weights());
            }
            with_steps(
                out.result(Quantity::Surface, rational(&t.surface)),
                &[],
                steps,
            )
        }
        Curves::BSpline(v) => {
            let (c, d) = pair(&v)?;
            let mut steps = recorder(&out);
            let t = translational_bspline(c, d, &mut steps).map_err(blame(p))?;
            if out.steps_on() {
                explain_translational(&mut out, c.points(), d.points(), t.surface.mesh());
            }
            with_steps(
                out.result(Quantity::Surface, Patch::BSpline(t.surface).to_exact()),
                &[],
                steps,
            )
        }
        Curves::Nurbs(v) => {
            let (c, d) = pair(&v)?;
            let mut steps = recorder(&out);
            let t = translational_nurbs(c, d, &mut steps).map_err(blame(p))?;
            if out.steps_on() {
                explain_translational(&mut out, c.points(), d.points(), t.surface.mesh());
                explain_weights(&mut out, c.weights(), d.weights(), t.surface.weights());
            }
            with_steps(
                out.result(Quantity::Surface, Patch::Nurbs(t.surface).to_exact()),
                &[],
                steps,
            )
        }
    })
}

/// A curve of a construction and its partner (ruled: c_1 and c_2; Coons: c_1, c_2 and d_1,
/// d_2): the curve's symbol (`c_1`), the letter and number of its points (`c`, 1: c_{1i}),
/// and its polygon, with its weights when rational.
struct Raised<'a, S: ExactScalar> {
    curve: &'a str,
    letter: char,
    number: usize,
    points: &'a [cagd_linalg::Point<S>],
    weights: Option<&'a [S]>,
}

/// The symbol of point i of a curve raised `r` times: c_{1i}, c_{1i}^{(r)}.
fn raised_symbol(letter: char, number: usize, i: usize, r: usize) -> String {
    match r {
        0 => format!("{letter}_{{{number}{i}}}"),
        r => format!("{letter}_{{{number}{i}}}^{{({r})}}"),
    }
}

/// Two curves of a construction of different degrees (ruled §3, Coons (18)): the one of
/// lower degree is raised to its partner's before the mesh is built, one degree at a time,
/// `c_i^{(1)} = i/(n+1) c_{i-1} + (1 - i/(n+1)) c_i`, point by point (a rational curve on its
/// homogeneous points (w c, w), then its points and weights). Returns how many degrees each
/// curve was raised.
fn explain_raised<S: ExactScalar>(out: &mut Out, pair: [&Raised<'_, S>; 2]) -> [usize; 2] {
    let [a, b] = pair;
    let (da, db) = (a.points.len(), b.points.len());
    let (low, high, raised) = match da.cmp(&db) {
        std::cmp::Ordering::Less => (a, b, [db - da, 0]),
        std::cmp::Ordering::Greater => (b, a, [0, da - db]),
        std::cmp::Ordering::Equal => return [0, 0],
    };
    if !out.steps_on() {
        return raised;
    }
    let (from, to) = (
        low.points.len().saturating_sub(1),
        high.points.len().saturating_sub(1),
    );
    out.formula(Formula::ElevateCurve);
    out.fact(Fact::CurveElevated {
        curve: low.curve.to_string(),
        from,
        to,
        partner: high.curve.to_string(),
    });
    let (letter, number) = (low.letter, low.number);
    match low.weights {
        None => {
            let mut points = low.points.to_vec();
            for r in 0..to - from {
                if to - from > 1 {
                    out.fact(Fact::Degree {
                        from: from + r,
                        to: from + r + 1,
                    });
                }
                points = explain::elevate_once(
                    out,
                    &points,
                    &|i| raised_symbol(letter, number, i, r),
                    &|i| raised_symbol(letter, number, i, r + 1),
                );
            }
        }
        Some(w) => {
            out.fact(Fact::Homogeneous);
            let Ok(curve) = RationalBezierCurve::try_new(low.points.to_vec(), w.to_vec()) else {
                return raised;
            };
            if let Ok(up) = curve.elevate_degree(to - from) {
                let r = to - from;
                out.value(
                    format!("{letter}_{{{number}i}}^{{({r})}}"),
                    Exact::Points(up.points().iter().map(exact_point).collect()),
                );
                out.value(
                    format!("w_{{{number}i}}^{{({r})}}"),
                    Exact::List(
                        up.weights()
                            .iter()
                            .map(|x| Exact::Number(exact(x)))
                            .collect(),
                    ),
                );
            }
        }
    }
    raised
}

/// `ruled`: (1 - v) c1(u) + v c2(u), eq. (7), and its mesh of bidegree (m, 1).
pub(crate) fn ruled<S: ExactScalar>(a: &Ruled, run: Run<'_>) -> Result<Out, ProblemError> {
    let keys = [("c1", Var::U), ("c2", Var::U)];
    let curves = read_curves::<S>(&[&a.c1, &a.c2], &keys)?;
    let mut out = run.out();
    out.formula(Formula::Ruled);
    if let (Curves::Poly(v), true) = (&curves, out.steps_on()) {
        for (k, c) in v.iter().enumerate() {
            out.value(format!("c_{{{}}}(u)", k + 1), Exact::Map(exact_map(c)));
        }
    }
    let mut raised = [0, 0];
    if !matches!(curves, Curves::Poly(_)) {
        let curve = |curve, number, points, weights| Raised {
            curve,
            letter: 'c',
            number,
            points,
            weights,
        };
        raised = match &curves {
            Curves::Bezier(v) => match v.as_slice() {
                [a, b] => explain_raised(
                    &mut out,
                    [
                        &curve("c_1", 1, a.points(), None),
                        &curve("c_2", 2, b.points(), None),
                    ],
                ),
                _ => raised,
            },
            Curves::Rational(v) => match v.as_slice() {
                [a, b] => explain_raised(
                    &mut out,
                    [
                        &curve("c_1", 1, a.points(), Some(a.weights())),
                        &curve("c_2", 2, b.points(), Some(b.weights())),
                    ],
                ),
                _ => raised,
            },
            _ => raised,
        };
        out.formula(Formula::RuledMesh);
        out.fact(Fact::Construction);
    }
    let out = match curves {
        Curves::Poly(v) => {
            let (a, b) = pair(&v)?;
            let mut steps = recorder(&out);
            let r = ruled_surface(a, b, &mut steps).map_err(at(""))?;
            with_steps(
                out.closed_form(Exact::Map(exact_map(&r.surface))),
                &[],
                steps,
            )
        }
        Curves::Bezier(v) => {
            let (a, b) = pair(&v)?;
            let mut steps = recorder(&out);
            let r = ruled_bezier(a, b, &mut steps).map_err(at(""))?;
            let out = out
                .result(Quantity::Surface, bezier(&r.surface))
                .closed_form(closed(&r.surface)?);
            with_steps(out, &r.notes, steps)
        }
        Curves::Rational(v) => {
            let (a, b) = pair(&v)?;
            let mut steps = recorder(&out);
            let r = ruled_rational(a, b, &mut steps).map_err(at(""))?;
            let out = out.result(Quantity::Surface, rational(&r.surface));
            with_steps(out, &r.notes, steps)
        }
        Curves::BSpline(v) => {
            let (a, b) = pair(&v)?;
            let mut steps = recorder(&out);
            let r = ruled_bspline(a, b, &mut steps).map_err(at(""))?;
            with_steps(
                out.result(Quantity::Surface, Patch::BSpline(r.surface).to_exact()),
                &r.notes,
                steps,
            )
        }
        Curves::Nurbs(v) => {
            let (a, b) = pair(&v)?;
            let mut steps = recorder(&out);
            let r = ruled_nurbs(a, b, &mut steps).map_err(at(""))?;
            with_steps(
                out.result(Quantity::Surface, Patch::Nurbs(r.surface).to_exact()),
                &r.notes,
                steps,
            )
        }
    };
    Ok(mesh_steps(out, MeshSteps::Ruled { raised }))
}

/// `developable`: the test c_uv · (c_u × c_v) ≡ 0 of eq. (9)/(10) for a ruled `surface`, or
/// the ruled surface of `c1` and `c2`.
pub(crate) fn developable<S: ExactScalar>(
    a: &Developable,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let ruled =
        a.surface.is_none() || matches!(&a.surface, Some(crate::input::SurfaceIn::Bezier { .. }));
    let test = |mut out: Out, d: &cagd_generate::Developability<S>, steps| {
        out.formula(Formula::Developable);
        if ruled {
            out.formula(Formula::DevelopableRuled);
        }
        let out = out
            .result(Quantity::Developable, Exact::Bool(d.developable))
            .result(
                Quantity::DevelopablePolynomial,
                Exact::Poly(exact_poly(&d.polynomial)),
            )
            .closed_form(Exact::Map(exact_map(&d.surface)));
        with_steps(out, &[], steps)
    };
    if let Some(surface) = &a.surface {
        let sf = "surface";
        return match Patch::<S>::read(surface, sf)? {
            Patch::Bezier(s) => {
                let out = run.out();
                let mut steps = recorder(&out);
                let d = developability_bezier(&s, &mut steps).map_err(at(sf))?;
                let out = out
                    .result(Quantity::FirstCellPlanar, Exact::Bool(d.first_cell_planar))
                    .result(Quantity::LastCellPlanar, Exact::Bool(d.last_cell_planar));
                Ok(test(out, &d.test, steps))
            }
            Patch::Map(e) => {
                let out = run.out();
                let mut steps = recorder(&out);
                let d = developability(&e, &mut steps).map_err(at(sf))?;
                Ok(test(out, &d, steps))
            }
            _ => Err(ProblemError::at(sf, Surface::DevelopableSurface)),
        };
    }
    let keys = [("c1", Var::U), ("c2", Var::U)];
    let curves = read_curves::<S>(&[&a.c1, &a.c2], &keys)?;
    let p = "";
    let surface = match curves {
        Curves::Poly(v) => {
            let (c1, c2) = pair(&v)?;
            ruled_surface(c1, c2, &mut NoSteps).map_err(at(""))?.surface
        }
        Curves::Bezier(v) => {
            let (c1, c2) = pair(&v)?;
            let r = ruled_bezier(c1, c2, &mut NoSteps).map_err(at(""))?;
            let out = run.out();
            let mut steps = recorder(&out);
            let d = developability_bezier(&r.surface, &mut steps).map_err(at(""))?;
            let out = out
                .result(Quantity::FirstCellPlanar, Exact::Bool(d.first_cell_planar))
                .result(Quantity::LastCellPlanar, Exact::Bool(d.last_cell_planar));
            return Ok(test(out, &d.test, steps));
        }
        _ => return Err(ProblemError::at(p, Surface::DevelopableCurves)),
    };
    let out = run.out();
    let mut steps = recorder(&out);
    let d = developability(&surface, &mut steps).map_err(at(""))?;
    Ok(test(out, &d, steps))
}

/// The surface of revolution of a NURBS profile (a B-spline or NURBS curve, or a Bézier
/// profile with a `sweep`): `c_ij = (x_i X_j, x_i Y_j, z_i)`, `w_ij = w_i ω_j` with the
/// profile's polygon (x_i, 0, z_i), weights w_i and knots in u, and the unit circle's arc
/// (X_j, Y_j), weights ω_j and knots in v (notes, chapter 6, after (21): "la construcción
/// anterior también es válida para curvas B-spline", Figure 13). The arc is a quadrant
/// (`arcs` 1, `quadrant`), the full turn of `arcs` arcs, or `sweep` degrees from `start`
/// in `arcs` arcs ([`crate::curves::arc::arc`]: exact for multiples of 30° or 45°).
fn revolution_spline<S: ExactScalar>(
    a: &Revolution,
    run: Run<'_>,
    out: Out,
    profile: &NurbsCurve<S>,
) -> Result<Out, ProblemError> {
    let domain = match &a.interval {
        Some(i) => num_pair::<S>(i, "interval")?,
        None => (S::zero(), S::one()),
    };
    let (start, sweep, arcs) = match &a.sweep {
        Some(sweep) => {
            if a.quadrant.is_some() {
                return Err(ProblemError::at("quadrant", Surface::QuadrantOrSweep));
            }
            let sweep = crate::curves::arc::degrees::<S>(sweep, "sweep")?;
            let start = match &a.start {
                Some(x) => crate::curves::arc::degrees::<S>(x, "start")?,
                None => cagd_scalar::BigRational::from_integer(0.into()),
            };
            let arcs = match a.arcs {
                Some(n) => run.count("arcs", n)?,
                None => cagd_bspline::default_arcs(&sweep),
            };
            (start, sweep, arcs)
        }
        None => {
            if a.start.is_some() {
                return Err(ProblemError::at("start", Surface::StartWithSweep));
            }
            let arcs = a
                .arcs
                .map(|n| run.count("arcs", n))
                .transpose()?
                .unwrap_or(1);
            if arcs == 1 {
                let q = a.quadrant.map_or(0, |q| q.get());
                if q > 3 {
                    return Err(ProblemError::at(
                        "quadrant",
                        Surface::NotAQuadrant {
                            quadrant: u64::try_from(q).unwrap_or(u64::MAX),
                        },
                    ));
                }
                let q = i64::try_from(q).unwrap_or(0);
                (
                    cagd_scalar::BigRational::from_integer((90 * q).into()),
                    cagd_scalar::BigRational::from_integer(90.into()),
                    1,
                )
            } else {
                if a.quadrant.is_some() {
                    return Err(ProblemError::at("quadrant", Surface::QuadrantArcs { arcs }));
                }
                (
                    cagd_scalar::BigRational::from_integer(0.into()),
                    cagd_scalar::BigRational::from_integer(360.into()),
                    arcs,
                )
            }
        }
    };
    run.check_points(
        "arcs",
        profile
            .points()
            .len()
            .saturating_mul(arcs.saturating_mul(2).saturating_add(1)),
        crate::message::limited::Limited::Revolution,
    )?;
    let circle = crate::curves::arc::arc(&S::one(), &start, &sweep, arcs, domain, "sweep")?;
    let mut steps = recorder(&out);
    let r = revolution_nurbs(profile, &circle, &mut steps).map_err(at(""))?;
    Ok(mesh_steps(
        with_steps(
            out.result(Quantity::Surface, Patch::Nurbs(r.surface).to_exact()),
            &r.notes,
            steps,
        ),
        MeshSteps::Revolution,
    ))
}

/// `coons`: the Coons patch of c1, c2 (along u) and d1, d2 (along v), eq. (15)-(19).
pub(crate) fn coons<S: ExactScalar>(a: &Coons, run: Run<'_>) -> Result<Out, ProblemError> {
    let blending = match a.blend {
        None | Some(Blend::Linear) => Blending::Bilinear,
        Some(Blend::Cubic) => Blending::Cubic,
    };
    let keys = [
        ("c1", Var::U),
        ("c2", Var::U),
        ("d1", Var::V),
        ("d2", Var::V),
    ];
    let curves = read_curves::<S>(&[&a.c1, &a.c2, &a.d1, &a.d2], &keys)?;
    let p = &keys;
    let corners = |a: &cagd_linalg::Point<S>,
                   b: &cagd_linalg::Point<S>,
                   c: &cagd_linalg::Point<S>,
                   d: &cagd_linalg::Point<S>| {
        Exact::Object(vec![
            (Quantity::Symbol("a".into()), Exact::Point(exact_point(a))),
            (Quantity::Symbol("b".into()), Exact::Point(exact_point(b))),
            (Quantity::Symbol("c".into()), Exact::Point(exact_point(c))),
            (Quantity::Symbol("d".into()), Exact::Point(exact_point(d))),
        ])
    };
    // The Bézier mesh (18)-(19) is for the bilinear blend; the cubic blend is a closed form.
    let curves = match (curves, blending) {
        (Curves::Bezier(v), Blending::Cubic) => Curves::Poly(
            v.iter()
                .zip(&keys)
                .map(|(c, (_, var))| c.closed_form(*var))
                .collect(),
        ),
        (c, _) => c,
    };
    let mut out = run.out();
    if out.steps_on() {
        if blending == Blending::Cubic {
            out.formula(Formula::CoonsCubic);
        } else {
            out.formula(Formula::Coons);
            out.formula(Formula::CoonsRuled);
            out.formula(Formula::CoonsBilinear);
        }
    }
    Ok(match curves {
        Curves::Poly(v) => {
            let [c1, c2, d1, d2] = four(&v)?;
            let s =
                coons_surface_blended(c1, c2, d1, d2, blending, &mut NoSteps).map_err(blame(p))?;
            out.closed_form(Exact::Map(exact_map(&s.surface)))
                .result(Quantity::Corners, corners(&s.a, &s.b, &s.c, &s.d))
                .step(Quantity::CoonsC, Exact::Map(exact_map(&s.c_c)))
                .step(Quantity::CoonsD, Exact::Map(exact_map(&s.c_d)))
                .step(Quantity::CoonsCd, Exact::Map(exact_map(&s.c_cd)))
        }
        Curves::Bezier(v) => {
            let [c1, c2, d1, d2] = four(&v)?;
            let s = coons_bezier(c1, c2, d1, d2, &mut NoSteps).map_err(blame(p))?;
            if out.steps_on() {
                let curve = |curve, letter, number, points| Raised {
                    curve,
                    letter,
                    number,
                    points,
                    weights: None,
                };
                explain_raised(
                    &mut out,
                    [
                        &curve("c_1", 'c', 1, c1.points()),
                        &curve("c_2", 'c', 2, c2.points()),
                    ],
                );
                explain_raised(
                    &mut out,
                    [
                        &curve("d_1", 'd', 1, d1.points()),
                        &curve("d_2", 'd', 2, d2.points()),
                    ],
                );
                out.formula(Formula::CoonsMesh);
                explain_coons_mesh(&mut out, &s);
            }
            out.result(Quantity::Surface, bezier(&s.surface))
                .closed_form(closed(&s.surface)?)
                .result(Quantity::Corners, corners(&s.a, &s.b, &s.c, &s.d))
                .step(Quantity::CoonsC, bezier(&s.c_c))
                .step(Quantity::CoonsD, bezier(&s.c_d))
                .step(Quantity::CoonsCd, bezier(&s.c_cd))
        }
        Curves::BSpline(v) => {
            let [c1, c2, d1, d2] = four(&v)?;
            let mut steps = recorder(&out);
            let s = coons_bspline(c1, c2, d1, d2, &mut steps).map_err(blame(p))?;
            with_steps(
                out.result(
                    Quantity::Surface,
                    Patch::BSpline(s.surface.clone()).to_exact(),
                ),
                &s.notes,
                steps,
            )
        }
        Curves::Rational(_) | Curves::Nurbs(_) => {
            return Err(ProblemError::at("", Surface::CoonsRational))
        }
    })
}

/// c_{i,j} = c_{c i,j} + c_{d i,j} - c_{cd i,j} for every point of the Bézier Coons mesh.
fn explain_coons_mesh<S: ExactScalar>(out: &mut Out, s: &cagd_generate::CoonsBezier<S>) {
    let (cc, cd, ccd) = (s.c_c.mesh(), s.c_d.mesh(), s.c_cd.mesh());
    for ((i, j), c) in s.surface.mesh().indexed() {
        let (Some(a), Some(b), Some(d)) = (cc.get(i, j), cd.get(i, j), ccd.get(i, j)) else {
            continue;
        };
        out.explain(explain::combination(
            format!("c_{{{i},{j}}}"),
            vec![
                (S::one(), format!("c_{{c\\,{i},{j}}}"), explain::point(a)),
                (S::one(), format!("c_{{d\\,{i},{j}}}"), explain::point(b)),
                (-S::one(), format!("c_{{cd\\,{i},{j}}}"), explain::point(d)),
            ],
            explain::point(c),
        ));
    }
}

/// `revolution`: the surface of a curve in the XZ plane turning about the Z axis, eq. (21):
/// `arcs` = 1 gives the first quadrant (rational Bézier), 4 (or another N) the full turn as
/// a NURBS with the circle of N arcs on `interval`.
pub(crate) fn revolution<S: ExactScalar>(
    a: &Revolution,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let cf = "curve";
    let curve = Curve::<S>::read(req(&a.curve, cf)?, cf)?;
    let arcs = a
        .arcs
        .map(|n| run.count("arcs", n))
        .transpose()?
        .unwrap_or(1);
    let mut out = run.out();
    out.formula(Formula::Revolution);
    if !matches!(curve, Curve::Map(_)) {
        out.formula(Formula::RevolutionMesh);
        out.fact(Fact::Construction);
    }
    let profile = match curve {
        Curve::Map(e) => {
            if a.sweep.is_some() || a.start.is_some() {
                return Err(ProblemError::at(
                    if a.sweep.is_some() { "sweep" } else { "start" },
                    Surface::ProfileSweep,
                ));
            }
            let r = revolution_surface(&e).map_err(at(cf))?;
            return Ok(out.result(Quantity::Parametrization, Exact::Text(r.to_text())));
        }
        Curve::Bezier(b) => {
            let w = vec![S::one(); b.points().len()];
            RationalBezierCurve::try_new(b.points().to_vec(), w).map_err(at(cf))?
        }
        Curve::RationalBezier(r) => r,
        Curve::BSpline(b) => {
            let w = vec![S::one(); b.points().len()];
            let n =
                NurbsCurve::try_new(b.knots().clone(), b.points().to_vec(), w).map_err(at(cf))?;
            return revolution_spline(a, run, out, &n);
        }
        Curve::Nurbs(n) => return revolution_spline(a, run, out, &n),
    };
    if a.sweep.is_some() || a.start.is_some() {
        return revolution_spline(a, run, out, &nurbs_from_bezier(&profile).map_err(at(cf))?);
    }
    if let Some(q) = a.quadrant {
        if q.get() > 3 {
            return Err(ProblemError::at(
                "quadrant",
                Surface::NotAQuadrant { quadrant: q.0 },
            ));
        }
        if arcs != 1 {
            return Err(ProblemError::at("quadrant", Surface::QuadrantArcs { arcs }));
        }
    }
    if arcs == 1 {
        let quadrant = a.quadrant.map_or(0, |q| q.get());
        let mut steps = recorder(&out);
        let r = revolution_bezier_quadrant(&profile, quadrant, &mut steps).map_err(at(""))?;
        return Ok(mesh_steps(
            with_steps(
                out.result(Quantity::Surface, rational(&r.surface)),
                &[],
                steps,
            ),
            MeshSteps::Revolution,
        ));
    }
    let domain = match &a.interval {
        Some(i) => num_pair::<S>(i, "interval")?,
        None => (S::zero(), S::one()),
    };
    if a.arcs.is_some() {
        run.check_points(
            "arcs",
            profile
                .points()
                .len()
                .saturating_mul(arcs.saturating_mul(2).saturating_add(1)),
            crate::message::limited::Limited::Revolution,
        )?;
    }
    let nurbs = nurbs_from_bezier(&profile).map_err(at(cf))?;
    let mut steps = recorder(&out);
    let r = revolution_nurbs_arcs(&nurbs, arcs, domain, &mut steps).map_err(at(""))?;
    Ok(mesh_steps(
        with_steps(
            out.result(Quantity::Surface, Patch::Nurbs(r.surface).to_exact()),
            &r.notes,
            steps,
        ),
        MeshSteps::Revolution,
    ))
}
