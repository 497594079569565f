//! `cagd render FILE|- --svg OUT.svg [--obj ...] [--stl ...] [--iges ...] [--html ...]`: figures.

use crate::solve::{problems, read_json};
use crate::{CliError, Report};
use cagd_poly::Var;
use cagd_problem::Exact;
use cagd_render::{
    plot_gaussian_sign, plot_polynomial, plot_weights, render_svg, to_html, to_iges, to_obj,
    to_stl_binary, HtmlOptions, Layers, PlotOptions, Scene, SurfaceGeometry, SvgOptions,
};
use cagd_scalar::{Quadratic, Scalar};

/// The help of `cagd render`.
pub const HELP: &str = "\
Usage: cagd render FILE|- [--svg OUT.svg] [--html OUT.html] [--obj OUT.obj] [--stl OUT.stl]
                   [--iges OUT.igs] [--plot OUT.svg] [--azimuth DEG] [--elevation DEG] [--density N]
                   [--layers surface,mesh,boundary,normals,curves,axes] [--steps]

Draws a problem (it is solved first), an answer of `cagd solve --format json`, or a bare
surface/curve object, read from FILE or standard input (-). For a batch, the first problem
is drawn. The geometry is evaluated exactly and converted to floating point only to draw.
  --svg     a figure: isoparametric net, control mesh, axes; the same input gives the same bytes
  --html    one self-contained page with an interactive 3D view (drag, zoom, hover a control
            point for its exact coordinates)
  --obj, --stl   a tessellation with normals (--density N, default 16)
  --iges    the exact NURBS surface as an IGES rational B-spline surface (entity 128)
  --steps   also draw the intermediate surfaces (c_c, c_d, c_cd of a Coons patch...)
  --plot    a chart of a scalar quantity that teaches something: for a developability
            problem, the polynomial c_uv · (c_u × c_v) over u in [0, 1]; for a rational
            patch, the weights of its rows; otherwise the sign of the Gaussian curvature
            across the patch (computed exactly at the grid points)
";

/// Runs `cagd render`.
pub fn run(args: &[String]) -> Result<Report, CliError> {
    let mut input = None;
    let mut outputs: Vec<(&'static str, String)> = Vec::new();
    let mut svg = SvgOptions::default();
    let mut html = HtmlOptions::default();
    let mut density = 16usize;
    let mut steps = false;
    let mut it = args.iter();
    let number = |name: &str, v: Option<&String>| -> Result<f64, CliError> {
        let v = v.ok_or_else(|| CliError::Usage(format!("{name} needs a value")))?;
        v.parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| {
                CliError::Usage(format!("{name} takes a number of degrees, found '{v}'"))
            })
    };
    while let Some(arg) = it.next() {
        match arg.as_str() {
            "-h" | "--help" => return Ok(HELP.to_string().into()),
            kind @ ("--svg" | "--html" | "--obj" | "--stl" | "--iges" | "--plot") => {
                let path = it
                    .next()
                    .ok_or_else(|| CliError::Usage(format!("{kind} needs an output file")))?;
                let kind: &'static str = match kind {
                    "--svg" => "svg",
                    "--html" => "html",
                    "--obj" => "obj",
                    "--stl" => "stl",
                    "--plot" => "plot",
                    _ => "iges",
                };
                outputs.push((kind, path.clone()));
            }
            "--azimuth" => {
                svg.view.azimuth = number("--azimuth", it.next())?;
                html.view.azimuth = svg.view.azimuth;
            }
            "--elevation" => {
                svg.view.elevation = number("--elevation", it.next())?;
                html.view.elevation = svg.view.elevation;
            }
            "--density" => {
                let v = it
                    .next()
                    .ok_or_else(|| CliError::Usage("--density needs a value".into()))?;
                density = v
                    .parse()
                    .ok()
                    .filter(|d| (1..=256).contains(d))
                    .ok_or_else(|| {
                        CliError::Usage(format!("--density takes 1 to 256, found '{v}'"))
                    })?;
            }
            "--layers" => {
                let v = it
                    .next()
                    .ok_or_else(|| CliError::Usage("--layers needs a list".into()))?;
                svg.layers = layers(v)?;
            }
            "--steps" => steps = true,
            other if other.starts_with("--") => {
                return Err(CliError::Usage(format!("unknown option '{other}'")))
            }
            path => input = Some(path.to_string()),
        }
    }
    let input = input.ok_or_else(|| CliError::Usage("render needs a FILE (or -)".into()))?;
    if outputs.is_empty() {
        return Err(CliError::Usage(
            "render needs at least one output: --svg, --html, --obj, --stl, --iges or --plot"
                .into(),
        ));
    }
    let doc = read_json(&input)?;
    let first = problems(&doc).into_iter().next().unwrap_or_default();
    // a problem is read and solved once, here; its figure and plot come from the answer
    let answer = if first.get("op").is_some() && first.get("result").is_none() {
        let settings = cagd_problem::Settings {
            limits: cagd_problem::Limits::default(),
            steps,
        };
        let problem = cagd_problem::Problem::read(&first, &settings.limits)
            .map_err(|e| CliError::Input(e.to_string()))?;
        Some(
            cagd_problem::solve_problem(&std::sync::Arc::new(problem), &settings)
                .map_err(|e| CliError::Input(e.to_string()))?,
        )
    } else {
        None
    };
    let scene = match &answer {
        Some(a) => Scene::from_answer(a, steps),
        None => Scene::from_json(&first, steps),
    }
    .map_err(|e| CliError::Input(e.to_string()))?;
    let bad = |e: cagd_render::RenderError| CliError::Input(e.to_string());
    let mut text = String::new();
    for (kind, path) in outputs {
        let bytes: Vec<u8> = match kind {
            "svg" => render_svg(&scene, &svg).map_err(bad)?.into_bytes(),
            "html" => to_html(&scene, &html).map_err(bad)?.into_bytes(),
            "obj" => to_obj(&scene, density).map_err(bad)?.into_bytes(),
            "stl" => to_stl_binary(&scene, density).map_err(bad)?,
            "plot" => plot(answer.as_ref(), &scene)?.into_bytes(),
            _ => to_iges(&scene).map_err(bad)?.into_bytes(),
        };
        std::fs::write(&path, bytes)
            .map_err(|e| CliError::Input(format!("cannot write {path}: {e}")))?;
        text += &format!("wrote {path}\n");
    }
    Ok(text.into())
}

/// The chart of `--plot` (see the help).
fn plot(
    answer: Option<&cagd_problem::Answer>,
    scene: &Scene<Quadratic>,
) -> Result<String, CliError> {
    let bad = |e: cagd_render::RenderError| CliError::Input(e.to_string());
    if let Some(answer) = answer.filter(|a| a.op == "developable") {
        {
            if let Some(Exact::Poly(p)) = answer.get("polynomial") {
                let options = PlotOptions {
                    title: Some(format!("c_uv · (c_u × c_v) = {}", p.to_text())),
                    ..PlotOptions::default()
                };
                let unit = (Quadratic::from_i64(0), Quadratic::from_i64(1));
                return plot_polynomial(p, Var::U, unit, &options).map_err(bad);
            }
        }
    }
    let surface = scene
        .surfaces
        .first()
        .ok_or_else(|| CliError::Input("there is no surface to plot".into()))?;
    match &surface.geometry {
        SurfaceGeometry::RationalBezier(r) => {
            let weights: Vec<Quadratic> = r.weights().iter().cloned().collect();
            let names: Vec<String> = r
                .weights()
                .indexed()
                .map(|((i, j), _)| format!("w{i}{j}"))
                .collect();
            let options = PlotOptions {
                title: Some("weights w_ij, row by row".into()),
                ..PlotOptions::default()
            };
            plot_weights(&weights, Some(&names), &options).map_err(bad)
        }
        g => {
            let options = PlotOptions {
                title: Some("sign of the Gaussian curvature".into()),
                ..PlotOptions::default()
            };
            plot_gaussian_sign(g, 12, &options).map_err(bad)
        }
    }
}

/// `surface,mesh,...` → the layers to draw.
fn layers(list: &str) -> Result<Layers, CliError> {
    let mut l = Layers {
        surface: false,
        mesh: false,
        boundary: false,
        normals: false,
        curves: false,
        axes: false,
    };
    for name in list.split(',').map(str::trim).filter(|s| !s.is_empty()) {
        match name {
            "surface" => l.surface = true,
            "mesh" => l.mesh = true,
            "boundary" => l.boundary = true,
            "normals" => l.normals = true,
            "curves" => l.curves = true,
            "axes" => l.axes = true,
            other => {
                return Err(CliError::Usage(format!(
                    "unknown layer '{other}' (surface, mesh, boundary, normals, curves, axes)"
                )))
            }
        }
    }
    Ok(l)
}
