//! Knot vectors as objects: the multiplicity of each knot and the span of a parameter
//! (`knot_vector`), uniform and open uniform vectors built from a degree and a number of
//! control points, and knots (of a curve, or alone) normalized onto [0, 1] (`normalize`).
//! The mathematics is cagd-bspline's ([`KnotVector::span_in`], [`knots_spaced`],
//! [`multiplicities`], [`KnotVector::normalized`]); here the problem read and the answer
//! written.

use crate::any::AnyCurve as Curve;
use crate::any::AnySurface as Surface;
use crate::convert::convert;
use crate::input::CurveIn;
use crate::message::curve::Curve as Say;
use crate::out::{at, num, req, Out, Run};
use crate::problem::{Convention, KnotVector as KnotVectorArgs, Normalize, Spacing};
use crate::spec::{Int, List, Num};
use crate::steps::Formula;
use crate::value::Number;
use crate::value::{exact, Exact, ExactScalar, Quantity};
use crate::ProblemError;
use cagd_bspline::{knots_spaced, multiplicities, normalize_list, KnotConvention, KnotVector};
use cagd_poly::Var;

/// The convention a problem names (default the notes').
fn convention(c: Option<Convention>) -> KnotConvention {
    match c {
        None | Some(Convention::Notes) => KnotConvention::Notes,
        Some(Convention::NurbsBook) => KnotConvention::Full,
    }
}

/// A count as an answer's integer.
fn int(n: usize) -> Exact {
    Exact::Int(i64::try_from(n).unwrap_or(i64::MAX))
}

/// A list of knots as an answer's value.
fn knots_value<S: ExactScalar>(knots: &[S]) -> Exact {
    Exact::List(knots.iter().map(|u| Exact::Number(exact(u))).collect())
}

/// A vector read: the validated vector, the knots as written and their convention.
struct Read<S: ExactScalar> {
    vector: KnotVector<S>,
    written: Vec<S>,
    convention: KnotConvention,
}

/// `knots` with `degree` in `convention`.
fn read_knots<S: ExactScalar>(
    knots: &List<Num>,
    degree: Option<Int>,
    written_in: Option<Convention>,
    run: Run<'_>,
) -> Result<Read<S>, ProblemError> {
    let written = knots
        .0
        .iter()
        .enumerate()
        .map(|(k, x)| num::<S>(x, &format!("knots[{k}]")))
        .collect::<Result<Vec<S>, _>>()?;
    let p = run.degree("degree", *req(&degree, "degree")?)?;
    let convention = convention(written_in);
    let vector = match convention {
        KnotConvention::Notes => KnotVector::from_notes(written.clone(), p),
        KnotConvention::Full => KnotVector::from_full(written.clone(), p),
    }
    .map_err(at("knots"))?;
    Ok(Read {
        vector,
        written,
        convention,
    })
}

/// The knots of a B-spline or NURBS `curve`, their convention told by their length.
fn read_curve_knots<S: ExactScalar>(c: &CurveIn<Number>) -> Result<Read<S>, ProblemError> {
    let (vector, written) = match (Curve::<S>::read(c, "curve")?, c) {
        (Curve::BSpline(b), CurveIn::BSpline { knots, .. }) => (b.knots().clone(), knots),
        (Curve::Nurbs(b), CurveIn::BSpline { knots, .. }) => (b.knots().clone(), knots),
        _ => return Err(ProblemError::at("curve", Say::KnotsNeedBSpline)),
    };
    let written = written
        .iter()
        .enumerate()
        .map(|(k, x)| convert::<S>(x, &format!("curve.knots[{k}]")))
        .collect::<Result<Vec<S>, _>>()?;
    let convention = if written.len() == vector.full().len() {
        KnotConvention::Full
    } else {
        KnotConvention::Notes
    };
    Ok(Read {
        vector,
        written,
        convention,
    })
}

/// `spacing` with `degree`, `control_points` and `interval`: the vector built, written in
/// `convention`.
fn build<S: ExactScalar>(
    a: &KnotVectorArgs,
    spacing: Spacing,
    run: Run<'_>,
    out: &mut Out,
) -> Result<Read<S>, ProblemError> {
    let p = run.degree("degree", *req(&a.degree, "degree")?)?;
    let n = run.count("control_points", *req(&a.control_points, "control_points")?)?;
    let (spacing, formula) = match spacing {
        Spacing::Uniform => (cagd_bspline::Spacing::Uniform, Formula::UniformKnots),
        Spacing::OpenUniform => (
            cagd_bspline::Spacing::OpenUniform,
            Formula::OpenUniformKnots,
        ),
    };
    let (lo, hi) = match (&a.interval, spacing) {
        (Some(pair), _) => (
            num::<S>(&pair.0, "interval[0]")?,
            num::<S>(&pair.1, "interval[1]")?,
        ),
        (None, cagd_bspline::Spacing::Uniform) => {
            let last = i64::try_from(n.saturating_add(p)).unwrap_or(i64::MAX);
            (S::from_i64(0), S::from_i64(last))
        }
        (None, cagd_bspline::Spacing::OpenUniform) => (S::from_i64(0), S::from_i64(1)),
    };
    out.formula(formula);
    if out.steps_on() {
        out.value("a", Exact::Number(exact(&lo)));
        out.value("b", Exact::Number(exact(&hi)));
    }
    let full = knots_spaced(spacing, p, n, &lo, &hi).map_err(at("control_points"))?;
    let vector = KnotVector::from_full(full, p).map_err(at("control_points"))?;
    let convention = convention(a.convention);
    let written = match (spacing, convention) {
        // the uniform vector's outer knots are its own (the canonical form sets them to their
        // neighbours): built again, the notes' are the full ones without the first and last
        (cagd_bspline::Spacing::Uniform, KnotConvention::Full) => {
            knots_spaced(spacing, p, n, &lo, &hi).map_err(at("control_points"))?
        }
        (cagd_bspline::Spacing::Uniform, KnotConvention::Notes) => {
            let full = knots_spaced(spacing, p, n, &lo, &hi).map_err(at("control_points"))?;
            full.get(1..full.len().saturating_sub(1))
                .map(<[S]>::to_vec)
                .unwrap_or_default()
        }
        (_, c) => vector.to_convention(c),
    };
    Ok(Read {
        vector,
        written,
        convention,
    })
}

/// `knot_vector`: a vector read (`knots` with `degree` and `convention`, or a `curve`'s) or
/// built (`spacing`); the multiplicity of each distinct knot as written and, for `params`,
/// the span of each (The NURBS Book's FindSpan, A2.1), indexed in the vector as written.
pub(crate) fn knot_vector<S: ExactScalar>(
    a: &KnotVectorArgs,
    run: Run<'_>,
) -> Result<Out, ProblemError> {
    let mut out = run.out();
    let built = a.spacing.is_some();
    let read = match (&a.spacing, &a.knots, &a.curve) {
        (Some(spacing), _, _) => build::<S>(a, *spacing, run, &mut out)?,
        (None, Some(knots), _) => read_knots::<S>(knots, a.degree, a.convention, run)?,
        (None, None, Some(c)) => {
            if a.convention.is_some() {
                return Err(ProblemError::at("convention", Say::ConventionWithCurve));
            }
            read_curve_knots::<S>(c)?
        }
        (None, None, None) => return Err(ProblemError::at("", Say::KnotVectorNeeds)),
    };
    let Read {
        vector,
        written,
        convention,
    } = read;
    let table = multiplicities(&written)
        .into_iter()
        .map(|(u, m)| {
            Exact::Object(vec![
                (Quantity::Knot, Exact::Number(exact(&u))),
                (Quantity::Multiplicity, int(m)),
            ])
        })
        .collect();
    if built {
        out = out.result(Quantity::Knots, knots_value(&written));
    }
    out = out.result(Quantity::Multiplicities, Exact::List(table));
    let (start, end) = vector.domain();
    out = out.result(
        Quantity::Domain,
        Exact::Point(cagd_linalg::Point::new(vec![exact(&start), exact(&end)])),
    );
    if let Some(params) = &a.params {
        out.formula(Formula::FindSpan);
        let mut spans = Vec::with_capacity(params.0.len());
        for (k, t) in params.0.iter().enumerate() {
            let path = format!("params[{k}]");
            let t = num::<S>(t, &path)?;
            let i = vector.span_in(&t, convention).map_err(at(&path))?;
            if out.steps_on() {
                out.value("t", Exact::Number(exact(&t)));
                for j in [i, i + 1] {
                    if let Some(u) = written.get(j) {
                        out.value(format!("u_{j}"), Exact::Number(exact(u)));
                    }
                }
            }
            spans.push(Exact::Object(vec![
                (Quantity::Variable(Var::T), Exact::Number(exact(&t))),
                (Quantity::Span, int(i)),
            ]));
        }
        out = out.result(Quantity::Spans, Exact::List(spans));
    }
    Ok(out)
}

/// `normalize`: a B-spline or NURBS curve on the knots (u - a)/(b - a), [a, b] its domain, the
/// same control points and weights (the same point set: the new curve at s is the old at
/// a + s (b - a)); a B-spline or NURBS surface so in u and in v ([a, b] x [c, d] onto
/// [0, 1] x [0, 1]); or `knots` alone so mapped, written in their `convention`.
pub(crate) fn normalize<S: ExactScalar>(a: &Normalize, run: Run<'_>) -> Result<Out, ProblemError> {
    let mut out = run.out();
    out.formula(Formula::NormalizeKnots);
    if let Some(c) = &a.curve {
        if a.convention.is_some() {
            return Err(ProblemError::at("convention", Say::ConventionWithCurve));
        }
        let c = Curve::<S>::read(c, "curve")?;
        let (lo, hi) = match &c {
            Curve::BSpline(b) => b.knots().domain(),
            Curve::Nurbs(b) => b.knots().domain(),
            _ => return Err(ProblemError::at("curve", Say::KnotsNeedBSpline)),
        };
        if out.steps_on() {
            out.value("a", Exact::Number(exact(&lo)));
            out.value("b", Exact::Number(exact(&hi)));
        }
        let c = match c {
            Curve::BSpline(b) => Curve::BSpline(b.normalized()),
            Curve::Nurbs(b) => Curve::Nurbs(b.normalized()),
            other => other,
        };
        return Ok(out.result(Quantity::Curve, c.to_exact()));
    }
    if let Some(sf) = &a.surface {
        if a.convention.is_some() {
            return Err(ProblemError::at("convention", Say::ConventionWithCurve));
        }
        let sf = Surface::<S>::read(sf, "surface")?;
        let (ku, kv) = match &sf {
            Surface::BSpline(b) => (b.knots_u().domain(), b.knots_v().domain()),
            Surface::Nurbs(b) => (b.knots_u().domain(), b.knots_v().domain()),
            _ => return Err(ProblemError::at("surface", Say::KnotsNeedBSpline)),
        };
        if out.steps_on() {
            for (name, x) in [("a", &ku.0), ("b", &ku.1), ("c", &kv.0), ("d", &kv.1)] {
                out.value(name, Exact::Number(exact(x)));
            }
        }
        let sf = match sf {
            Surface::BSpline(b) => Surface::BSpline(b.normalized()),
            Surface::Nurbs(b) => Surface::Nurbs(b.normalized()),
            other => other,
        };
        return Ok(out.result(Quantity::Surface, sf.to_exact()));
    }
    let Some(knots) = &a.knots else {
        return Err(ProblemError::at("", Say::NormalizeNeeds));
    };
    let Read {
        vector, written, ..
    } = read_knots::<S>(knots, a.degree, a.convention, run)?;
    let (lo, hi) = vector.domain();
    if out.steps_on() {
        out.value("a", Exact::Number(exact(&lo)));
        out.value("b", Exact::Number(exact(&hi)));
    }
    Ok(out.result(
        Quantity::Knots,
        knots_value(&normalize_list(&written, &lo, &hi)),
    ))
}
