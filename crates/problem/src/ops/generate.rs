//! Surface generation (chapter 6): translational, ruled, developable, Coons, revolution.

use super::curve::{curve_var, Curve};
use super::patch::Patch;
use super::Out;
use crate::input::Field;
use crate::value::{
    exact, exact_grid, exact_map, exact_mesh, exact_point, exact_poly, exact_rational, Exact,
    ExactScalar,
};
use crate::ProblemError;
use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_bspline::{BSplineCurve, NurbsCurve};
use cagd_generate::{
    coons_bezier, coons_bspline, coons_surface_blended, developability, developability_bezier,
    nurbs_from_bezier, revolution_bezier_quadrant, revolution_nurbs_arcs, revolution_surface,
    ruled_bezier, ruled_bspline, ruled_nurbs, ruled_rational, ruled_surface, translational_bezier,
    translational_bspline, translational_nurbs, translational_rational, translational_surface,
    Blending, GenerateError, Step, StepValue,
};
use cagd_poly::{Poly, Var, VecPoly};
use cagd_surface::{BezierSurface, RationalBezierSurface};

/// The curves of a construction, brought to one kind.
enum Curves<S: ExactScalar> {
    Poly(Vec<VecPoly<S>>),
    Bezier(Vec<BezierCurve<S>>),
    Rational(Vec<RationalBezierCurve<S>>),
    BSpline(Vec<BSplineCurve<S>>),
    Nurbs(Vec<NurbsCurve<S>>),
}

fn at<'f, E: std::fmt::Display>(f: &'f Field<'_>) -> impl Fn(E) -> ProblemError + 'f {
    move |e| f.error(e.to_string())
}

/// The error of a construction, at the field of the curve it blames when it names one
/// (`d1` for "curves c1 and d1 do not meet at corner a").
fn blame<'f>(p: &'f Field<'_>) -> impl Fn(GenerateError) -> ProblemError + 'f {
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
        let field = key.and_then(|k| p.get(k).or_else(|| p.get(k.trim_end_matches('1'))));
        match field {
            Some(f) => f.error(e.to_string()),
            None => p.error(e.to_string()),
        }
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
    p: &Field<'_>,
    keys: &[(&str, Var)],
) -> Result<Curves<S>, ProblemError> {
    let mut fields = Vec::new();
    let mut curves = Vec::new();
    for (k, _) in keys {
        let f = p.req(k)?;
        curves.push(Curve::<S>::read(&f)?);
        fields.push(f);
    }
    let any = |pred: fn(&Curve<S>) -> bool| curves.iter().any(pred);
    if any(|c| matches!(c, Curve::Expr(_))) {
        let mut out = Vec::new();
        for ((c, f), (_, var)) in curves.into_iter().zip(&fields).zip(keys) {
            out.push(match c {
                Curve::Expr(e) => in_var(&e, *var),
                Curve::Bezier(b) => b.closed_form(*var),
                _ => {
                    return Err(f.error(
                        "give all the curves as expressions or polynomial Bézier curves when one is an expression",
                    ))
                }
            });
        }
        return Ok(Curves::Poly(out));
    }
    if any(|c| matches!(c, Curve::BSpline(_) | Curve::Nurbs(_))) {
        if any(|c| matches!(c, Curve::Bezier(_) | Curve::Rational(_))) {
            return Err(p.error(
                "mixing Bézier and B-spline curves: write the Bézier ones as B-splines (knots [0, ..., 0, 1, ..., 1])",
            ));
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
                    _ => return Err(f.error("expected a B-spline curve")),
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
    if any(|c| matches!(c, Curve::Rational(_))) {
        let mut out = Vec::new();
        for (c, f) in curves.into_iter().zip(&fields) {
            out.push(match c {
                Curve::Rational(r) => r,
                Curve::Bezier(b) => {
                    let w = vec![S::one(); b.points().len()];
                    RationalBezierCurve::try_new(b.points().to_vec(), w).map_err(at(f))?
                }
                _ => return Err(f.error("expected a Bézier curve")),
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

/// Adds a construction's steps: notes become remarks, the rest named exact values.
fn with_steps<S: ExactScalar>(mut out: Out, steps: &[Step<S>]) -> Out {
    for s in steps {
        if RESULT_STEPS.contains(&s.name.as_str()) {
            continue;
        }
        let value = match &s.value {
            StepValue::Text(t) => {
                out.remarks.push(t.clone());
                continue;
            }
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
        out = out.step(&s.name, value);
    }
    out
}

fn pair<'a, T>(v: &'a [T], f: &Field<'_>) -> Result<(&'a T, &'a T), ProblemError> {
    match v {
        [a, b] => Ok((a, b)),
        _ => Err(f.error("expected two curves")),
    }
}

fn four<'a, T>(v: &'a [T], f: &Field<'_>) -> Result<[&'a T; 4], ProblemError> {
    match v {
        [a, b, c, d] => Ok([a, b, c, d]),
        _ => Err(f.error("expected four curves")),
    }
}

fn bezier<S: ExactScalar>(s: &BezierSurface<S>) -> Exact {
    Exact::bezier_surface(s.mesh(), None)
}

fn rational<S: ExactScalar>(s: &RationalBezierSurface<S>) -> Exact {
    Exact::bezier_surface(s.mesh(), Some(s.weights()))
}

fn closed<S: ExactScalar>(f: &Field<'_>, s: &BezierSurface<S>) -> Result<Exact, ProblemError> {
    Ok(Exact::Map(exact_map(&s.closed_form().map_err(at(f))?)))
}

/// `translational`: c(u) + d(v) - a, eq. (1), (4), (5).
pub(crate) fn translational<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let curves = read_curves::<S>(p, &[("c", Var::U), ("d", Var::V)])?;
    let out = Out::default();
    Ok(match curves {
        Curves::Poly(v) => {
            let (c, d) = pair(&v, p)?;
            let t = translational_surface(c, d).map_err(blame(p))?;
            with_steps(
                out.result("closed_form", Exact::Map(exact_map(&t.surface))),
                &t.steps,
            )
        }
        Curves::Bezier(v) => {
            let (c, d) = pair(&v, p)?;
            let t = translational_bezier(c, d).map_err(blame(p))?;
            let out = out
                .result("surface", bezier(&t.surface))
                .result("closed_form", closed(p, &t.surface)?);
            with_steps(out, &t.steps)
        }
        Curves::Rational(v) => {
            let (c, d) = pair(&v, p)?;
            let t = translational_rational(c, d).map_err(blame(p))?;
            with_steps(out.result("surface", rational(&t.surface)), &t.steps)
        }
        Curves::BSpline(v) => {
            let (c, d) = pair(&v, p)?;
            let t = translational_bspline(c, d).map_err(blame(p))?;
            with_steps(
                out.result("surface", Patch::BSpline(t.surface).exact()),
                &t.steps,
            )
        }
        Curves::Nurbs(v) => {
            let (c, d) = pair(&v, p)?;
            let t = translational_nurbs(c, d).map_err(blame(p))?;
            with_steps(
                out.result("surface", Patch::Nurbs(t.surface).exact()),
                &t.steps,
            )
        }
    })
}

/// `ruled`: (1 - v) c1(u) + v c2(u), eq. (7), and its mesh of bidegree (m, 1).
pub(crate) fn ruled<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let curves = read_curves::<S>(p, &[("c1", Var::U), ("c2", Var::U)])?;
    let out = Out::default();
    Ok(match curves {
        Curves::Poly(v) => {
            let (a, b) = pair(&v, p)?;
            let r = ruled_surface(a, b).map_err(at(p))?;
            with_steps(
                out.result("closed_form", Exact::Map(exact_map(&r.surface))),
                &r.steps,
            )
        }
        Curves::Bezier(v) => {
            let (a, b) = pair(&v, p)?;
            let r = ruled_bezier(a, b).map_err(at(p))?;
            let out = out
                .result("surface", bezier(&r.surface))
                .result("closed_form", closed(p, &r.surface)?);
            with_steps(out, &r.steps)
        }
        Curves::Rational(v) => {
            let (a, b) = pair(&v, p)?;
            let r = ruled_rational(a, b).map_err(at(p))?;
            let out = out.result("surface", rational(&r.surface));
            with_steps(out, &r.steps)
        }
        Curves::BSpline(v) => {
            let (a, b) = pair(&v, p)?;
            let r = ruled_bspline(a, b).map_err(at(p))?;
            with_steps(
                out.result("surface", Patch::BSpline(r.surface).exact()),
                &r.steps,
            )
        }
        Curves::Nurbs(v) => {
            let (a, b) = pair(&v, p)?;
            let r = ruled_nurbs(a, b).map_err(at(p))?;
            with_steps(
                out.result("surface", Patch::Nurbs(r.surface).exact()),
                &r.steps,
            )
        }
    })
}

/// `developable`: the test c_uv · (c_u × c_v) ≡ 0 of eq. (9)/(10) for a ruled `surface`, or
/// the ruled surface of `c1` and `c2`.
pub(crate) fn developable<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let test = |out: Out, d: &cagd_generate::Developability<S>| {
        let out = out
            .result("developable", Exact::Bool(d.developable))
            .result("polynomial", Exact::Poly(exact_poly(&d.polynomial)))
            .result("closed_form", Exact::Map(exact_map(&d.surface)));
        with_steps(out, &d.steps)
    };
    if let Some(sf) = p.get("surface") {
        return match Patch::<S>::read(&sf)? {
            Patch::Bezier(s) => {
                let d = developability_bezier(&s).map_err(at(&sf))?;
                let out = Out::default()
                    .result("first_cell_planar", Exact::Bool(d.first_cell_planar))
                    .result("last_cell_planar", Exact::Bool(d.last_cell_planar));
                Ok(test(out, &d.test))
            }
            Patch::Expr(e) => Ok(test(Out::default(), &developability(&e).map_err(at(&sf))?)),
            _ => Err(sf.error(
                "the developability test takes a ruled Bézier patch of bidegree (m, 1) or a parametric surface",
            )),
        };
    }
    let curves = read_curves::<S>(p, &[("c1", Var::U), ("c2", Var::U)])?;
    let surface =
        match curves {
            Curves::Poly(v) => {
                let (a, b) = pair(&v, p)?;
                ruled_surface(a, b).map_err(at(p))?.surface
            }
            Curves::Bezier(v) => {
                let (a, b) = pair(&v, p)?;
                let r = ruled_bezier(a, b).map_err(at(p))?;
                let d = developability_bezier(&r.surface).map_err(at(p))?;
                let out = Out::default()
                    .result("first_cell_planar", Exact::Bool(d.first_cell_planar))
                    .result("last_cell_planar", Exact::Bool(d.last_cell_planar));
                return Ok(test(out, &d.test));
            }
            _ => return Err(p.error(
                "the developability test takes polynomial curves (expressions or Bézier curves)",
            )),
        };
    Ok(test(
        Out::default(),
        &developability(&surface).map_err(at(p))?,
    ))
}

/// `coons`: the Coons patch of c1, c2 (along u) and d1, d2 (along v), eq. (15)-(19).
pub(crate) fn coons<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let blending = match p.get("blend") {
        None => Blending::Bilinear,
        Some(b) => match b.str()? {
            "linear" | "bilinear" => Blending::Bilinear,
            "cubic" => Blending::Cubic,
            other => {
                return Err(b.error(format!("expected \"linear\" or \"cubic\", found {other:?}")))
            }
        },
    };
    let keys = [
        ("c1", Var::U),
        ("c2", Var::U),
        ("d1", Var::V),
        ("d2", Var::V),
    ];
    let curves = read_curves::<S>(p, &keys)?;
    let corners = |a: &cagd_linalg::Point<S>,
                   b: &cagd_linalg::Point<S>,
                   c: &cagd_linalg::Point<S>,
                   d: &cagd_linalg::Point<S>| {
        Exact::Object(vec![
            ("a".into(), Exact::Point(exact_point(a))),
            ("b".into(), Exact::Point(exact_point(b))),
            ("c".into(), Exact::Point(exact_point(c))),
            ("d".into(), Exact::Point(exact_point(d))),
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
    Ok(match curves {
        Curves::Poly(v) => {
            let [c1, c2, d1, d2] = four(&v, p)?;
            let s = coons_surface_blended(c1, c2, d1, d2, blending).map_err(blame(p))?;
            Out::default()
                .result("closed_form", Exact::Map(exact_map(&s.surface)))
                .result("corners", corners(&s.a, &s.b, &s.c, &s.d))
                .step("c_c", Exact::Map(exact_map(&s.c_c)))
                .step("c_d", Exact::Map(exact_map(&s.c_d)))
                .step("c_cd", Exact::Map(exact_map(&s.c_cd)))
        }
        Curves::Bezier(v) => {
            let [c1, c2, d1, d2] = four(&v, p)?;
            let s = coons_bezier(c1, c2, d1, d2).map_err(blame(p))?;
            Out::default()
                .result("surface", bezier(&s.surface))
                .result("closed_form", closed(p, &s.surface)?)
                .result("corners", corners(&s.a, &s.b, &s.c, &s.d))
                .step("c_c", bezier(&s.c_c))
                .step("c_d", bezier(&s.c_d))
                .step("c_cd", bezier(&s.c_cd))
        }
        Curves::BSpline(v) => {
            let [c1, c2, d1, d2] = four(&v, p)?;
            let s = coons_bspline(c1, c2, d1, d2).map_err(blame(p))?;
            with_steps(
                Out::default().result("surface", Patch::BSpline(s.surface.clone()).exact()),
                &s.steps,
            )
        }
        Curves::Rational(_) | Curves::Nurbs(_) => {
            return Err(p.error(
                "the Coons patch of rational curves has no mesh and weights of its own (notes §5: the projective construction can give zero or negative weights); give polynomial curves",
            ))
        }
    })
}

/// `revolution`: the surface of a curve in the XZ plane turning about the Z axis, eq. (21):
/// `arcs` = 1 gives the first quadrant (rational Bézier), 4 (or another N) the full turn as
/// a NURBS with the circle of N arcs on `interval`.
pub(crate) fn revolution<S: ExactScalar>(p: &Field<'_>) -> Result<Out, ProblemError> {
    let cf = p.req("curve")?;
    let arcs_field = p.get("arcs");
    let arcs = arcs_field
        .as_ref()
        .map(Field::count)
        .transpose()?
        .unwrap_or(1);
    let profile =
        match Curve::<S>::read(&cf)? {
            Curve::Expr(e) => {
                let r = revolution_surface(&e).map_err(at(&cf))?;
                return Ok(Out::default().result("parametrization", Exact::Text(r.to_text())));
            }
            Curve::Bezier(b) => {
                let w = vec![S::one(); b.points().len()];
                RationalBezierCurve::try_new(b.points().to_vec(), w).map_err(at(&cf))?
            }
            Curve::Rational(r) => r,
            _ => return Err(cf.error(
                "surfaces of revolution of B-spline profiles are not available yet in this build",
            )),
        };
    if arcs == 1 {
        let quadrant = p
            .get("quadrant")
            .map(|q| q.usize())
            .transpose()?
            .unwrap_or(0);
        let r = revolution_bezier_quadrant(&profile, quadrant).map_err(at(p))?;
        return Ok(with_steps(
            Out::default().result("surface", rational(&r.surface)),
            &r.steps,
        ));
    }
    let domain = match p.get("interval") {
        Some(i) => i.pair::<S>()?,
        None => (S::zero(), S::one()),
    };
    if let Some(a) = &arcs_field {
        a.check_points(
            profile
                .points()
                .len()
                .saturating_mul(arcs.saturating_mul(2).saturating_add(1)),
            "the surface of revolution",
        )?;
    }
    let nurbs = nurbs_from_bezier(&profile).map_err(at(&cf))?;
    let r = revolution_nurbs_arcs(&nurbs, arcs, domain).map_err(at(p))?;
    Ok(with_steps(
        Out::default().result("surface", Patch::Nurbs(r.surface).exact()),
        &r.steps,
    ))
}
