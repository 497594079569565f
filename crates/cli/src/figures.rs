//! The figures of the keys and problem sets: an example's or a problem's figure, drawn by
//! cagd-render, its title and its legend in the key's language.

use crate::said::CliMessage;
use crate::CliError;
use cagd_keys::{names, Lang};
use cagd_problem::Number;
use cagd_problem::{Answer, Exact, Verdict};
use cagd_render::{curve_geometry, surface_geometry, Legend, Scene};
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
    for (argument, shape) in problem.shapes() {
        match &shape {
            Exact::Surface(s) => {
                if let Ok(g) = surface_geometry(s) {
                    scene.add_surface_as(Legend::Argument(argument), g);
                }
            }
            Exact::Curve(c) => {
                if let Ok(g) = curve_geometry(c) {
                    scene.add_curve_as(Legend::Argument(argument), g);
                }
            }
            _ => {}
        }
    }
    (!scene.is_empty()).then_some(scene)
}

/// The number put in for the `k`-th letter (from 1) of an answer in letters: `k` (R = 1; a, b,
/// c, d = 1, 2, 3, 4), or, for the points of a generic mesh (`c_{1,0}`, `x_{0,1}`), the values
/// k² mod 7 + 1, varied so that the sample mesh is not degenerate and its weights are
/// positive (2, 5, 3, 3, 5, 2, 1, 2...).
fn sample(name: &cagd_param::Name, k: i64) -> i64 {
    if name.as_str().contains('_') {
        (k * k) % 7 + 1
    } else {
        k
    }
}

/// The numbers put in for the letters of an answer drawn, as its title says them: each
/// value (`R = 1, a = 2`), or, for a generic mesh, the rule of [`sample`].
#[derive(Debug, Clone, PartialEq, Eq)]
enum PutIn {
    /// The letters and their values, as data.
    Values(String),
    /// The rule for the points of a generic mesh, k² mod 7 + 1.
    GenericRule,
}

impl cagd_words::Message for PutIn {
    fn phrase(&self, lang: Lang) -> cagd_words::Phrase {
        match self {
            PutIn::Values(values) => cagd_words::Phrase::data(values.clone()),
            PutIn::GenericRule => cagd_words::said(
                lang,
                "the generic points put in as k² mod 7 + 1",
                "los puntos genéricos sustituidos por k² mod 7 + 1",
                [],
            ),
        }
    }
}

/// An answer that can be drawn: an answer in letters (a circle of radius R) with numbers put
/// in by [`sample`], in the order the letters are declared, its steps left out; a mesh or
/// polygon of one-dimensional points (a generic mesh c_{i,j}) drawn as the graph of the
/// scalar patch, whose control points are (i/m, j/n, c_{i,j}) (the Bernstein polynomials
/// reproduce u and v); `None` when a value cannot be put in.
fn drawable(answer: &Answer) -> Option<Answer> {
    let letters = &answer.problem.parameters;
    let mut a = answer.clone();
    if !letters.is_empty() {
        let values: Vec<_> = letters
            .iter()
            .zip(1i64..)
            .map(|(n, k)| (n.clone(), Number::from_i64(sample(n, k))))
            .collect();
        for (_, x) in &mut a.result {
            *x = x.substitute(&values).ok()?;
        }
        // an answer with nothing to draw (the corner normals of a generic mesh, whose
        // closed form the keys do not expand): its data, with the same values put in
        let shape = |x: &Exact| {
            matches!(
                x,
                Exact::Surface(_) | Exact::Curve(_) | Exact::Map(_) | Exact::Rational(_)
            )
        };
        if !a.result.iter().any(|(_, x)| shape(x)) {
            for (_, x) in answer.problem.shapes() {
                if let Exact::Surface(_) = x {
                    let x = x.substitute(&values).ok()?;
                    a.result.push((cagd_problem::Quantity::Surface, x));
                }
            }
        }
    }
    for (_, x) in &mut a.result {
        if let Some(g) = graph_of(x) {
            *x = g;
        }
    }
    a.steps.clear();
    Some(a)
}

/// A Bézier patch or curve of one-dimensional points as its graph: (i/m, j/n, c_{i,j}) or
/// (i/n, c_i), with the same weights.
fn graph_of(x: &Exact) -> Option<Exact> {
    use cagd_linalg::Point;
    use cagd_problem::input::{CurveIn, SurfaceIn};
    let ratio = |i: usize, n: usize| {
        let (i, n) = (i64::try_from(i).ok()?, i64::try_from(n.max(1)).ok()?);
        Some(Number::from_ratio(i, n))
    };
    match x {
        Exact::Surface(SurfaceIn::Bezier { mesh, weights }) if mesh.dim() == 1 => {
            let (m, n) = (mesh.rows().saturating_sub(1), mesh.cols().saturating_sub(1));
            let mut rows = Vec::with_capacity(m + 1);
            for i in 0..=m {
                let mut row = Vec::with_capacity(n + 1);
                for j in 0..=n {
                    let z = mesh.get(i, j)?.coords().first()?.clone();
                    row.push(Point::new(vec![ratio(i, m)?, ratio(j, n)?, z]));
                }
                rows.push(row);
            }
            let mesh = cagd_surface::Grid::from_rows(rows).ok()?;
            Some(Exact::Surface(SurfaceIn::Bezier {
                mesh,
                weights: weights.clone(),
            }))
        }
        Exact::Curve(CurveIn::Bezier { points, weights })
            if points.first().is_some_and(|p| p.coords().len() == 1) =>
        {
            let n = points.len().saturating_sub(1);
            let points = points
                .iter()
                .enumerate()
                .map(|(i, p)| Some(Point::new(vec![ratio(i, n)?, p.coords().first()?.clone()])))
                .collect::<Option<Vec<_>>>()?;
            Some(Exact::Curve(CurveIn::Bezier {
                points,
                weights: weights.clone(),
            }))
        }
        _ => None,
    }
}

/// The scene's title and the names of its legend in `lang`: the problem's title (the Spanish
/// one of a fixture), `superficie` for an argument or a result `surface` (each labelled by
/// what it is); an item of a list keeps its name.
fn localize(scene: &mut Scene<Number>, v: &Verdict, lang: Lang) {
    let Some(problem) = v.problem.as_deref() else {
        return;
    };
    if lang == Lang::Es {
        if let Some(t) = problem.meta.es.as_ref().and_then(|e| e.title.clone()) {
            scene.title = Some(t);
        }
    }
    let label = |legend: &Legend| match legend {
        Legend::Argument(a) => Some(names::argument_label(a, Some(problem), lang).text),
        Legend::Quantity(q) => Some(names::label(q, Some(problem), lang).text),
        Legend::Name => None,
    };
    for s in &mut scene.surfaces {
        if let Some(name) = label(&s.legend) {
            s.name = name;
        }
    }
    for c in &mut scene.curves {
        if let Some(name) = label(&c.legend) {
            c.name = name;
        }
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
            .map(|(n, k)| format!("{n} = {}", sample(n, k)))
            .collect();
        let put_in = if values.len() > 6 {
            // a generic mesh: the rule, not 27 values
            PutIn::GenericRule
        } else {
            PutIn::Values(values.join(", "))
        };
        scene.title = Some(format!(
            "{} ({})",
            scene.title.clone().unwrap_or_default(),
            cagd_words::Message::phrase(&put_in, lang).text()
        ));
    }
    let Ok(svg) = cagd_render::render_svg(&scene, &cagd_render::SvgOptions::default()) else {
        return Ok(None);
    };
    std::fs::create_dir_all(dir).map_err(|e| {
        CliError::input(CliMessage::CannotCreate {
            path: dir.to_string(),
            why: e.to_string(),
        })
    })?;
    let (path, bytes) = match kind {
        Figure::Svg => (format!("{dir}/{name}.svg"), svg.into_bytes()),
        Figure::Png => match cagd_render::svg_to_png(&svg, 2.0) {
            Ok(png) => (format!("{dir}/{name}.png"), png),
            Err(_) => return Ok(None),
        },
    };
    std::fs::write(&path, bytes).map_err(|e| {
        CliError::input(CliMessage::CannotWrite {
            path: path.clone(),
            why: e.to_string(),
        })
    })?;
    Ok(Some(path))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_variant_in_both_languages() {
        for m in [PutIn::Values("R = 1".into()), PutIn::GenericRule] {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
}
