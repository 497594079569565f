//! The figure of a problem and its answer (the JSON of `docs/format.md`).
//!
//! A figure shows the surfaces of the answer (the result `surface`); when the answer has no
//! mesh of its own (a continuity check, a developability test) the problem's surfaces; when
//! there is none either (a parametric construction) the answer's closed forms in u and v.
//! Optionally it adds the surfaces among the steps (`c_c`, `c_d`, `c_cd` of a Coons patch),
//! and it always shows the problem's curves (the `c1`, `c2`, `d1`, `d2` of a Coons patch, the
//! profile of a revolution).
//! Everything is over [`Quadratic`], which holds every exact number of an answer.

use crate::{CurveGeometry, RenderError, Scene, SurfaceGeometry};
use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_bspline::{BSplineCurve, NurbsCurve};
use cagd_poly::{Var, VecPoly};
use cagd_problem::input::{CurveIn, Field, SurfaceIn};
use cagd_problem::{solve, Answer, Exact};
use cagd_scalar::Quadratic;
use cagd_spline_surface::{BSplineSurface, NurbsSurface};
use cagd_surface::{BezierSurface, RationalBezierSurface};
use serde_json::Value;

/// A surface of the problem format as a surface of a figure.
pub fn surface_geometry(
    s: &SurfaceIn<Quadratic>,
) -> Result<SurfaceGeometry<Quadratic>, RenderError> {
    Ok(match s {
        SurfaceIn::Bezier {
            mesh,
            weights: None,
        } => SurfaceGeometry::Bezier(BezierSurface::try_new(mesh.clone())?),
        SurfaceIn::Bezier {
            mesh,
            weights: Some(w),
        } => SurfaceGeometry::RationalBezier(RationalBezierSurface::try_new(
            mesh.clone(),
            w.clone(),
        )?),
        SurfaceIn::BSpline {
            mesh,
            degree,
            knots,
            weights: None,
        } => {
            SurfaceGeometry::BSpline(BSplineSurface::read(*degree, knots.clone(), mesh.clone())?.0)
        }
        SurfaceIn::BSpline {
            mesh,
            degree,
            knots,
            weights: Some(w),
        } => SurfaceGeometry::Nurbs(
            NurbsSurface::read(*degree, knots.clone(), mesh.clone(), w.clone())?.0,
        ),
        SurfaceIn::Expr(c) => SurfaceGeometry::Map(c.clone()),
    })
}

/// A curve of the problem format as a curve of a figure.
pub fn curve_geometry(c: &CurveIn<Quadratic>) -> Result<CurveGeometry<Quadratic>, RenderError> {
    Ok(match c {
        CurveIn::Bezier {
            points,
            weights: None,
        } => CurveGeometry::Bezier(BezierCurve::try_new(points.clone())?),
        CurveIn::Bezier {
            points,
            weights: Some(w),
        } => {
            CurveGeometry::RationalBezier(RationalBezierCurve::try_new(points.clone(), w.clone())?)
        }
        CurveIn::BSpline {
            points,
            degree,
            knots,
            weights: None,
        } => CurveGeometry::BSpline(BSplineCurve::read(*degree, knots.clone(), points.clone())?.0),
        CurveIn::BSpline {
            points,
            degree,
            knots,
            weights: Some(w),
        } => CurveGeometry::Nurbs(
            NurbsCurve::read(*degree, knots.clone(), points.clone(), w.clone())?.0,
        ),
        CurveIn::Expr(c) => CurveGeometry::Map(c.clone()),
    })
}

/// A polynomial map in u and v into the plane or space: a surface to draw.
fn is_surface_map(m: &VecPoly<Quadratic>) -> bool {
    let vars = m.vars();
    (2..=3).contains(&m.dim())
        && vars.contains(&Var::U)
        && vars.contains(&Var::V)
        && vars.len() == 2
}

/// The surfaces among named exact values; with `maps`, the polynomial maps in u and v (closed
/// forms) too.
fn surfaces_of(
    values: &[(String, Exact)],
    maps: bool,
) -> Result<Vec<(String, SurfaceGeometry<Quadratic>)>, RenderError> {
    let mut out = Vec::new();
    for (name, v) in values {
        match v {
            Exact::Surface(s) => out.push((name.clone(), surface_geometry(s)?)),
            Exact::Map(m) if maps && is_surface_map(m) => {
                out.push((name.clone(), SurfaceGeometry::Map(m.clone())))
            }
            _ => {}
        }
    }
    Ok(out)
}

/// Values with their names, in order.
type Named<T> = Vec<(String, T)>;

/// Keys of a problem that are not geometry.
const NOT_GEOMETRY: &[&str] = &[
    "op", "name", "title", "source", "equation", "expected", "errata", "field",
];

/// The surfaces and curves of a problem.
type Inputs = (
    Named<SurfaceGeometry<Quadratic>>,
    Named<CurveGeometry<Quadratic>>,
);

/// The input of a problem: its surfaces and its curves, by key (in the JSON's key order).
fn inputs(problem: &Value) -> Result<Inputs, RenderError> {
    let mut surfaces = Vec::new();
    let mut curves = Vec::new();
    let Some(obj) = problem.as_object() else {
        return Ok((surfaces, curves));
    };
    let root = Field::root(problem);
    for (key, value) in obj {
        if NOT_GEOMETRY.contains(&key.as_str()) || !value.is_object() {
            continue;
        }
        let Some(field) = root.get(key) else { continue };
        let shape = ["bezier", "bspline", "expr"]
            .iter()
            .any(|k| value.get(k).is_some());
        if !shape {
            continue;
        }
        // a surface's mesh is a list of rows of points; a curve's polygon a list of points
        let nested = |k: &str| {
            value
                .get(k)
                .and_then(Value::as_array)
                .and_then(|rows| rows.first())
                .and_then(Value::as_array)
                .and_then(|row| row.first())
                .is_some_and(Value::is_array)
        };
        if nested("bezier") || nested("bspline") {
            surfaces.push((
                key.clone(),
                surface_geometry(&field.surface::<Quadratic>()?)?,
            ));
        } else if value.get("expr").is_some() {
            let s = field.surface::<Quadratic>()?;
            match s {
                SurfaceIn::Expr(m) if is_surface_map(&m) => {
                    surfaces.push((key.clone(), SurfaceGeometry::Map(m)))
                }
                _ => curves.push((key.clone(), curve_geometry(&field.curve::<Quadratic>()?)?)),
            }
        } else {
            curves.push((key.clone(), curve_geometry(&field.curve::<Quadratic>()?)?));
        }
    }
    Ok((surfaces, curves))
}

impl Scene<Quadratic> {
    /// The figure of a problem and its answer: the answer's surfaces, or the problem's when the
    /// answer has none, or else the answer's closed forms in u and v; with `steps`, the
    /// surfaces among the steps; and the problem's curves. The title is the problem's `title` (or `name`, or the operation).
    pub fn from_answer(problem: &Value, answer: &Answer, steps: bool) -> Result<Self, RenderError> {
        let mut scene = Scene::new();
        let title = ["title", "name"]
            .iter()
            .find_map(|k| problem.get(k).and_then(Value::as_str))
            .map_or_else(|| answer.op.clone(), str::to_string);
        scene.title = Some(title);
        let (in_surfaces, in_curves) = inputs(problem)?;
        // the answer's meshes; else the problem's; else the answer's closed forms
        let mut results = surfaces_of(&answer.result, false)?;
        if results.is_empty() {
            results = in_surfaces;
        }
        if results.is_empty() {
            results = surfaces_of(&answer.result, true)?;
        }
        for (name, s) in results {
            scene.add_surface(name, s);
        }
        if steps {
            for (name, s) in surfaces_of(&answer.steps, true)? {
                scene.add_surface(name, s);
            }
        }
        for (name, c) in in_curves {
            scene.add_curve(name, c);
        }
        if scene.is_empty() {
            return Err(RenderError::EmptyScene);
        }
        Ok(scene)
    }

    /// The figure of a JSON document: a problem (solved first, then as
    /// [`Scene::from_answer`]), an answer `{"ok": true, "op": ..., "result": {...}}` as
    /// `cagd solve` prints it, or a bare surface or curve (`{"bezier": [[...]]}`).
    pub fn from_json(value: &Value, steps: bool) -> Result<Self, RenderError> {
        if value.get("op").is_some() && value.get("result").is_none() {
            let answer = solve(value)?;
            return Self::from_answer(value, &answer, steps);
        }
        if let Some(result) = value.get("result") {
            return answer_json(value, result, steps);
        }
        // a bare surface or curve
        let (surfaces, curves) = inputs(&serde_json::json!({ "figure": value }))?;
        let mut scene = Scene::new();
        for (name, s) in surfaces {
            scene.add_surface(name, s);
        }
        for (name, c) in curves {
            scene.add_curve(name, c);
        }
        if scene.is_empty() {
            return Err(RenderError::EmptyScene);
        }
        Ok(scene)
    }
}

/// The figure of an answer as JSON: the surfaces among its results (and steps).
fn answer_json(doc: &Value, result: &Value, steps: bool) -> Result<Scene<Quadratic>, RenderError> {
    let mut scene = Scene::new();
    scene.title = doc.get("op").and_then(Value::as_str).map(str::to_string);
    let (surfaces, curves) = inputs(result)?;
    for (name, s) in surfaces {
        scene.add_surface(name, s);
    }
    if steps {
        if let Some(list) = result.get("steps").and_then(Value::as_array) {
            let mut named = serde_json::Map::new();
            for item in list {
                if let (Some(name), Some(v)) =
                    (item.get("name").and_then(Value::as_str), item.get("value"))
                {
                    named.insert(name.to_string(), v.clone());
                }
            }
            let (step_surfaces, _) = inputs(&Value::Object(named))?;
            for (name, s) in step_surfaces {
                scene.add_surface(name, s);
            }
        }
    }
    for (name, c) in curves {
        scene.add_curve(name, c);
    }
    if scene.is_empty() {
        return Err(RenderError::EmptyScene);
    }
    Ok(scene)
}
