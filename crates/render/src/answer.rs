//! The figure of a problem and its answer (the JSON of `docs/format.md`).
//!
//! A figure shows the surfaces of the answer (the result `surface`); when the answer has no
//! mesh of its own (a continuity check, a developability test) the problem's surfaces; when
//! there is none either (a parametric construction) the answer's closed forms in u and v.
//! Optionally it adds the surfaces among the steps (`c_c`, `c_d`, `c_cd` of a Coons patch),
//! and it always shows the problem's curves (the `c1`, `c2`, `d1`, `d2` of a Coons patch, the
//! profile of a revolution) and the answer's (a circle, an elevated curve).
//! Everything is over [`Number`], which holds every exact number of an answer. A problem is
//! drawn from its typed answer ([`Scene::from_answer`]): this crate never solves.

use crate::{AnyCurve, AnySurface, CurvePolygon, Legend, RenderError, Scene, SurfaceNet};
use cagd_contract::input::{CurveIn, SurfaceIn};
use cagd_contract::Number;
use cagd_contract::{Answer, Argument, Exact, Problem, Quantity};
use cagd_poly::{Var, VecPoly};
use serde::Deserialize;
use serde_json::Value;

/// A surface of the problem format as a surface of a figure: validated by the problem
/// layer's one reading ([`AnySurface::read`]).
pub fn surface_geometry(s: &SurfaceIn<Number>) -> Result<AnySurface<Number>, RenderError> {
    Ok(AnySurface::read(s, "")?)
}

/// A curve of the problem format as a curve of a figure ([`AnyCurve::read_with_vectors`]: a
/// rational Bézier curve may have control vectors, zero weights; the curve is drawn from its
/// homogeneous closed form, and its polygon, which is no polygon of points, is not drawn).
pub fn curve_geometry(c: &CurveIn<Number>) -> Result<AnyCurve<Number>, RenderError> {
    Ok(AnyCurve::read_with_vectors(c, "")?)
}

/// A polynomial map in u and v into the plane or space: a surface to draw.
fn is_surface_map(m: &VecPoly<Number>) -> bool {
    let vars = m.vars();
    (2..=3).contains(&m.dim())
        && vars.contains(&Var::U)
        && vars.contains(&Var::V)
        && vars.len() == 2
}

/// The surfaces among named exact values; with `maps`, the polynomial maps in u and v (closed
/// forms) too.
fn surfaces_of(values: &[(Quantity, Exact)], maps: bool) -> Result<Vec<Named>, RenderError> {
    let mut out = Vec::new();
    for (quantity, v) in values {
        let name = quantity.name().into_owned();
        let whole = |s| (name.clone(), Legend::Quantity(quantity.clone()), s);
        match v {
            Exact::Surface(s) => out.push(whole(surface_geometry(s)?)),
            Exact::Map(m) if maps && is_surface_map(m) => {
                out.push(whole(AnySurface::Map(m.clone())))
            }
            // the pieces of `subdivide` and `extract` (a grid of patches: its rows)
            Exact::List(xs) => {
                let mut items: Vec<(String, &Exact)> = Vec::new();
                for (i, x) in xs.iter().enumerate() {
                    match x {
                        Exact::List(row) => items.extend(
                            row.iter()
                                .enumerate()
                                .map(|(j, y)| (format!("{name}[{i}][{j}]"), y)),
                        ),
                        _ => items.push((format!("{name}[{i}]"), x)),
                    }
                }
                for (n, x) in items {
                    match x {
                        Exact::Surface(s) => out.push((n, Legend::Name, surface_geometry(s)?)),
                        other => {
                            if let Some(m) = cagd_contract::triangle::square_surface(other) {
                                out.push((n, Legend::Name, m));
                            }
                        }
                    }
                }
            }
            other => {
                if let Some(m) = cagd_contract::triangle::square_surface(other) {
                    out.push(whole(m));
                }
            }
        }
    }
    Ok(out)
}

/// A surface of a figure with its name and what it is.
type Named = (String, Legend, AnySurface<Number>);

/// The figure of a document that is not a problem: a surface or a curve (a bare shape, or a
/// value of an answer) read with the problem format's typed readers; `None` when the value is
/// neither.
fn shape(value: &Value) -> Result<Option<Shape>, RenderError> {
    if !value.is_object() {
        return Ok(None);
    }
    if let Ok(s) = SurfaceIn::<Number>::deserialize(value) {
        return Ok(Some(match s {
            SurfaceIn::Expr(m) if !is_surface_map(&m) => {
                Shape::Curve(curve_geometry(&CurveIn::Expr(m))?)
            }
            s => Shape::Surface(surface_geometry(&s)?),
        }));
    }
    if let Ok(c) = CurveIn::<Number>::deserialize(value) {
        return Ok(Some(Shape::Curve(curve_geometry(&c)?)));
    }
    Ok(None)
}

/// A surface or a curve to draw (one at a time: no box needed).
#[allow(clippy::large_enum_variant)]
enum Shape {
    Surface(AnySurface<Number>),
    Curve(AnyCurve<Number>),
}

/// The curves of a figure with the argument each one is.
type ArgumentCurves = Vec<(Argument, AnyCurve<Number>)>;

/// The problem's data as a figure draws it: its surfaces (named by their argument) and its
/// curves, at its `values` when it is in letters; refused without them
/// ([`RenderError::Letters`]).
fn problem_shapes(problem: &Problem) -> Result<(Vec<Named>, ArgumentCurves), RenderError> {
    let mut in_surfaces = Vec::new();
    let mut in_curves = Vec::new();
    // a problem in letters (a circle of radius R) is drawn at its `values`, data and
    // answer alike; without values it cannot be drawn
    if !problem.parameters.is_empty() && problem.values.is_empty() {
        let letters: Vec<&str> = problem.parameters.iter().map(|n| n.as_str()).collect();
        let values: Vec<String> = letters.iter().map(|l| format!("{l:?}: 1")).collect();
        return Err(RenderError::Letters {
            letters: letters.join(", "),
            values: format!("\"values\": {{{}}}", values.join(", ")),
        });
    }
    let shapes = problem
        .shapes()
        .into_iter()
        .filter_map(|(argument, shape)| {
            if problem.values.is_empty() {
                Some((argument, shape))
            } else {
                shape
                    .substitute(&problem.values)
                    .ok()
                    .map(|shape| (argument, shape))
            }
        })
        .collect::<Vec<_>>();
    for (argument, shape) in shapes {
        let (name, legend) = (argument.name().to_string(), Legend::Argument(argument));
        match &shape {
            Exact::Surface(SurfaceIn::Expr(m)) if !is_surface_map(m) => {
                in_curves.push((argument, curve_geometry(&CurveIn::Expr(m.clone()))?))
            }
            Exact::Surface(s) => in_surfaces.push((name, legend, surface_geometry(s)?)),
            Exact::Curve(c) => in_curves.push((argument, curve_geometry(c)?)),
            other => {
                if let Some(m) = cagd_contract::triangle::square_surface(other) {
                    in_surfaces.push((name, legend, m));
                }
            }
        }
    }
    if !problem.values.is_empty() {
        // a generic mesh in letters (scalar points c_{i,j}) is drawn through its answer's
        // graph alone: its data, put in, is not in the plane or in space
        in_surfaces.retain(|(_, _, s)| {
            s.control_net()
                .map_or(true, |n| (2..=3).contains(&n.points.dim()))
        });
        in_curves.retain(|(_, c)| {
            c.control_polygon().map_or(true, |p| {
                p.points.first().is_none_or(|q| (2..=3).contains(&q.dim()))
            })
        });
    }
    Ok((in_surfaces, in_curves))
}

impl Scene<Number> {
    /// The figure of a problem's data alone (its curves and surfaces given, never its
    /// answer: a student's page shows it beside the question), titled as
    /// [`Scene::from_answer`]. A problem in letters is drawn at its `values` and refused
    /// without them ([`RenderError::Letters`]); a problem with nothing to draw (a number, a
    /// point) is [`RenderError::EmptyScene`]. It never solves.
    pub fn from_problem(problem: &Problem) -> Result<Self, RenderError> {
        let mut scene = Scene::new();
        let meta = &problem.meta;
        scene.title = Some(
            meta.title
                .clone()
                .or_else(|| meta.name.clone())
                .unwrap_or_else(|| problem.op.name().to_string()),
        );
        let (surfaces, curves) = problem_shapes(problem)?;
        for (name, legend, s) in surfaces {
            scene.add_surface_with(name, legend, s);
        }
        for (argument, c) in curves {
            scene.add_curve_as(Legend::Argument(argument), c);
        }
        if scene.is_empty() {
            return Err(RenderError::EmptyScene);
        }
        Ok(scene)
    }

    /// The figure of a problem and its answer: the answer's surfaces, or the problem's when the
    /// answer has none, or else the answer's closed forms in u and v; with `steps`, the
    /// surfaces among the steps; and the problem's curves. A restriction is drawn inside its
    /// original (the problem's surface, faint: [`Scene::add_faint_surface_as`]). A problem in
    /// letters is drawn at its `values`, data and answer alike, and refused without them
    /// ([`RenderError::Letters`], which says how to write them). The title is the problem's
    /// `title` (or `name`, or the operation). Everything comes from the typed answer: nothing
    /// is read or solved again.
    pub fn from_answer(answer: &Answer, steps: bool) -> Result<Self, RenderError> {
        let mut scene = Scene::new();
        let meta = &answer.problem.meta;
        let title = meta
            .title
            .clone()
            .or_else(|| meta.name.clone())
            .unwrap_or_else(|| answer.op.clone());
        scene.title = Some(title);
        let (mut in_surfaces, in_curves) = problem_shapes(&answer.problem)?;
        // the answer's meshes; else the problem's; else the answer's closed forms
        let mut results = surfaces_of(&answer.result, false)?;
        // a restriction is drawn inside its original, faint behind it
        let originals = if answer.op == "restrict" && !results.is_empty() {
            std::mem::take(&mut in_surfaces)
        } else {
            Vec::new()
        };
        if results.is_empty() {
            results = in_surfaces;
        }
        if results.is_empty() {
            results = surfaces_of(&answer.result, true)?;
        }
        for (name, legend, s) in results {
            scene.add_surface_with(name, legend, s);
        }
        for (_, legend, s) in originals {
            if let Legend::Argument(a) = legend {
                scene.add_faint_surface_as(Legend::Original(a), s);
            }
        }
        if steps {
            for (name, legend, s) in surfaces_of(&answer.steps, true)? {
                scene.add_surface_with(name, legend, s);
            }
        }
        for (argument, c) in in_curves {
            scene.add_curve_as(Legend::Argument(argument), c);
        }
        // the answer's curves: a circle, an elevated curve, a curve with a knot inserted
        for (quantity, v) in &answer.result {
            if let Exact::Curve(c) = v {
                scene.add_curve_as(Legend::Quantity(quantity.clone()), curve_geometry(c)?);
            }
        }
        if scene.is_empty() {
            return Err(RenderError::EmptyScene);
        }
        Ok(scene)
    }

    /// The figure of a JSON document that is not a problem: an answer `{"ok": true, "op":
    /// ..., "result": {...}}` as `cagd solve --format json` prints it (its surfaces and curves,
    /// with `steps` the surfaces among its steps), or a bare surface or curve
    /// (`{"bezier": [[...]]}`). A problem is solved by the caller and drawn with
    /// [`Scene::from_answer`].
    pub fn from_json(value: &Value, steps: bool) -> Result<Self, RenderError> {
        let mut scene = Scene::new();
        let add = |scene: &mut Scene<Number>, name: &str, v: &Value, curves: bool| {
            match shape(v)? {
                Some(Shape::Surface(s)) => {
                    scene.add_surface(name.to_string(), s);
                }
                Some(Shape::Curve(c)) if curves => {
                    scene.add_curve(name.to_string(), c);
                }
                _ => {}
            }
            Ok::<_, RenderError>(())
        };
        if let Some(result) = value.get("result").and_then(Value::as_object) {
            scene.title = value.get("op").and_then(Value::as_str).map(str::to_string);
            let mut curves = Vec::new();
            for (name, v) in result {
                match shape(v)? {
                    Some(Shape::Surface(s)) => {
                        scene.add_surface(name.clone(), s);
                    }
                    Some(Shape::Curve(c)) => curves.push((name.clone(), c)),
                    None => {}
                }
            }
            if steps {
                for item in result
                    .get("steps")
                    .and_then(Value::as_array)
                    .into_iter()
                    .flatten()
                {
                    if let (Some(name), Some(v)) =
                        (item.get("name").and_then(Value::as_str), item.get("value"))
                    {
                        add(&mut scene, name, v, false)?;
                    }
                }
            }
            for (name, c) in curves {
                scene.add_curve(name, c);
            }
        } else {
            add(&mut scene, "figure", value, true)?;
        }
        if scene.is_empty() {
            return Err(RenderError::EmptyScene);
        }
        Ok(scene)
    }
}
