//! The figures of the keys and problem sets: an example's or a problem's figure, drawn by
//! cagd-render, its title and its legend in the key's language.

use crate::CliError;
use cagd_keys::{names, Lang};
use cagd_problem::Number;
use cagd_problem::{Answer, Exact, Verdict};
use cagd_render::{curve_geometry, surface_geometry, Scene};
use cagd_scalar::FieldOps;

/// The file type of a figure.
#[derive(Clone, Copy)]
pub enum Figure {
    /// SVG, for Markdown.
    Svg,
    /// PNG, for LaTeX.
    Png,
}

/// The figure of a statement: the problem's data only (its curves and surfaces), never the
/// answer; `None` when the problem has no shape to draw.
fn statement_scene(v: &Verdict) -> Option<Scene<Number>> {
    let problem = v.problem.as_ref()?;
    let mut scene = Scene::new();
    for (name, shape) in problem.shapes() {
        match &shape {
            Exact::Surface(s) => {
                if let Ok(g) = surface_geometry(s) {
                    scene.add_surface(name, g);
                }
            }
            Exact::Curve(c) => {
                if let Ok(g) = curve_geometry(c) {
                    scene.add_curve(name, g);
                }
            }
            _ => {}
        }
    }
    (!scene.is_empty()).then_some(scene)
}

/// An answer that can be drawn: an answer in letters (a circle of radius R) with numbers put
/// in, 1, 2, 3... in the order the letters are declared (R = 1; a, b, c, d = 1, 2, 3, 4), its
/// steps left out; `None` when a value cannot be put in.
fn drawable(answer: &Answer) -> Option<Answer> {
    let letters = &answer.problem.parameters;
    if letters.is_empty() {
        return Some(answer.clone());
    }
    let values: Vec<_> = letters
        .iter()
        .zip(1i64..)
        .map(|(n, k)| (n.clone(), Number::from_i64(k)))
        .collect();
    let mut a = answer.clone();
    for (_, x) in &mut a.result {
        *x = x.substitute(&values).ok()?;
    }
    a.steps.clear();
    Some(a)
}

/// The scene's title and the names of its legend in `lang`: the problem's title (the Spanish
/// one of a fixture), `superficie` for `surface`.
fn localize(scene: &mut Scene<Number>, v: &Verdict, lang: Lang) {
    let Some(problem) = v.problem.as_deref() else {
        return;
    };
    if lang == Lang::Es {
        if let Some(t) = problem.meta.es.as_ref().and_then(|e| e.title.clone()) {
            scene.title = Some(t);
        }
    }
    let label = |name: &str| names::label(name, &Exact::Bool(false), Some(problem), lang).text;
    for s in &mut scene.surfaces {
        s.name = label(&s.name);
    }
    for c in &mut scene.curves {
        c.name = label(&c.name);
    }
}

/// Writes the figure of one example or problem to `dir` and returns its path, or `None` when
/// it has nothing to draw (a failed answer, a closed form without a surface...). With
/// `statement`, the figure of the data alone.
pub fn figure(
    dir: &str,
    name: &str,
    v: &Verdict,
    kind: Figure,
    lang: Lang,
    statement: bool,
) -> Result<Option<String>, CliError> {
    let scene = if statement {
        statement_scene(v)
    } else {
        v.answer
            .as_ref()
            .ok()
            .and_then(drawable)
            .and_then(|a| Scene::from_answer(&a, false).ok())
    };
    let Some(mut scene) = scene else {
        return Ok(None);
    };
    localize(&mut scene, v, lang);
    if let Some(p) = v
        .problem
        .as_deref()
        .filter(|p| !statement && !p.parameters.is_empty())
    {
        // the numbers put in for the letters, said in the title
        let values: Vec<String> = p
            .parameters
            .iter()
            .zip(1..)
            .map(|(n, k)| format!("{n} = {k}"))
            .collect();
        scene.title = Some(format!(
            "{} ({})",
            scene.title.clone().unwrap_or_default(),
            values.join(", ")
        ));
    }
    let Ok(svg) = cagd_render::render_svg(&scene, &cagd_render::SvgOptions::default()) else {
        return Ok(None);
    };
    std::fs::create_dir_all(dir)
        .map_err(|e| CliError::Input(format!("cannot create {dir}: {e}")))?;
    let (path, bytes) = match kind {
        Figure::Svg => (format!("{dir}/{name}.svg"), svg.into_bytes()),
        Figure::Png => match cagd_render::svg_to_png(&svg, 2.0) {
            Ok(png) => (format!("{dir}/{name}.png"), png),
            Err(_) => return Ok(None),
        },
    };
    std::fs::write(&path, bytes)
        .map_err(|e| CliError::Input(format!("cannot write {path}: {e}")))?;
    Ok(Some(path))
}
