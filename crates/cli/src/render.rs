//! `cagd render FILE|- --svg OUT.svg [--obj ...] [--stl ...] [--iges ...] [--html ...]`: figures.

use crate::cli::{path, PathKind};
use crate::said::{CliMessage, Said};
use crate::solve::{problems, read_json};
use crate::{CliError, Report};
use cagd_poly::Var;
use cagd_problem::Number;
use cagd_problem::{Exact, Quantity};
use cagd_render::{
    plot_gaussian_sign, plot_polynomial, plot_weights, render_svg, to_html, to_iges, to_obj,
    to_stl_binary, AnySurface, HtmlOptions, Layers, PlotOptions, Scene, SvgOptions,
};
use cagd_scalar::FieldOps;
use clap::Args;

/// The usage line of `cagd render`.
pub const USAGE: &str =
    "cagd render FILE|- [--svg|--html|--obj|--stl|--iges|--plot OUT]... [--steps]
                   [--azimuth DEG] [--elevation DEG] [--density N] [--layers LIST] [--lang LANG]";

/// Figures: SVG, an interactive HTML page, OBJ/STL, IGES
///
/// Draws a problem (it is solved first), an answer of `cagd solve --format json`, or a bare
/// surface/curve object, read from FILE or standard input (-). For a batch, the first problem
/// is drawn. The geometry is evaluated exactly and converted to floating point only to draw.
/// Give at least one output; the files are written in the order given.
///
/// --plot draws a chart of a scalar quantity that teaches something: for a developability
/// problem, the polynomial c_uv · (c_u × c_v) over u in [0, 1]; for a rational patch, the
/// weights of its rows; otherwise the sign of the Gaussian curvature across the patch
/// (computed exactly at the grid points).
#[derive(Debug, Clone, Args)]
#[command(verbatim_doc_comment, override_usage = USAGE)]
pub struct RenderArgs {
    /// The problem, answer or object to draw (a JSON file), or - for standard input
    #[arg(value_name = "FILE|-", value_parser = path("FILE", PathKind::File))]
    pub input: String,
    /// A figure: isoparametric net, control mesh, axes; the same input gives the same bytes
    #[arg(long, value_name = "OUT.svg", value_parser = path("--svg", PathKind::File))]
    pub svg: Vec<String>,
    /// An interactive 3D view in one self-contained page (drag, zoom, hover a control point)
    #[arg(long, value_name = "OUT.html", value_parser = path("--html", PathKind::File))]
    pub html: Vec<String>,
    /// A tessellation with normals, as OBJ (see --density)
    #[arg(long, value_name = "OUT.obj", value_parser = path("--obj", PathKind::File))]
    pub obj: Vec<String>,
    /// A tessellation with normals, as binary STL (see --density)
    #[arg(long, value_name = "OUT.stl", value_parser = path("--stl", PathKind::File))]
    pub stl: Vec<String>,
    /// The exact NURBS surface as an IGES rational B-spline surface (entity 128)
    #[arg(long, value_name = "OUT.igs", value_parser = path("--iges", PathKind::File))]
    pub iges: Vec<String>,
    /// A chart of a scalar quantity that teaches something (see above)
    #[arg(long, value_name = "OUT.svg", value_parser = path("--plot", PathKind::File))]
    pub plot: Vec<String>,
    /// Also draw the intermediate surfaces (c_c, c_d, c_cd of a Coons patch...), each in a
    /// panel of its own in the SVG
    #[arg(long)]
    pub steps: bool,
    /// The azimuth of the view, in degrees (SVG and HTML)
    #[arg(long, value_name = "DEG", allow_negative_numbers = true, value_parser = degrees("--azimuth"))]
    pub azimuth: Option<f64>,
    /// The elevation of the view, in degrees (SVG and HTML)
    #[arg(long, value_name = "DEG", allow_negative_numbers = true, value_parser = degrees("--elevation"))]
    pub elevation: Option<f64>,
    /// Subdivisions of each direction of a patch in OBJ and STL, 1 to 256
    #[arg(long, value_name = "N", default_value_t = 16, allow_negative_numbers = true, value_parser = density)]
    pub density: usize,
    /// The layers of the SVG figure: surface, mesh, boundary, normals, curves, axes (a list)
    #[arg(long, value_name = "LIST", value_parser = layers)]
    pub layers: Option<Layers>,
    /// The limits the problem is read and solved under; --max-seconds also bounds the time
    /// each figure takes
    #[command(flatten)]
    pub limits: crate::cli::LimitArgs,
    /// The language of the figures: the title and legend of a problem's figure, the HTML
    /// page's words
    #[command(flatten)]
    pub lang: crate::cli::LangArgs,
    /// The outputs in the order they were given (filled by `cli::parse`); when empty, those
    /// of the fields above, kind by kind.
    #[arg(skip)]
    pub given: Vec<(OutputKind, String)>,
}

/// A kind of output file.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OutputKind {
    Svg,
    Html,
    Obj,
    Stl,
    Iges,
    Plot,
}

impl OutputKind {
    /// Its flag (`--svg`).
    fn flag(self) -> String {
        let id = Self::ALL
            .iter()
            .find(|(k, _)| *k == self)
            .map_or("", |(_, id)| id);
        format!("--{id}")
    }

    /// Every kind, with the id of its argument.
    const ALL: [(OutputKind, &'static str); 6] = [
        (OutputKind::Svg, "svg"),
        (OutputKind::Html, "html"),
        (OutputKind::Obj, "obj"),
        (OutputKind::Stl, "stl"),
        (OutputKind::Iges, "iges"),
        (OutputKind::Plot, "plot"),
    ];
}

impl RenderArgs {
    /// The paths given for `kind`.
    fn paths(&self, kind: OutputKind) -> &[String] {
        match kind {
            OutputKind::Svg => &self.svg,
            OutputKind::Html => &self.html,
            OutputKind::Obj => &self.obj,
            OutputKind::Stl => &self.stl,
            OutputKind::Iges => &self.iges,
            OutputKind::Plot => &self.plot,
        }
    }

    /// Records the outputs in the order they were given on the command line.
    pub fn order_outputs(&mut self, matches: &clap::ArgMatches) {
        let mut given: Vec<(usize, OutputKind, String)> = Vec::new();
        for (kind, id) in OutputKind::ALL {
            let indices = matches.indices_of(id).into_iter().flatten();
            given.extend(
                indices
                    .zip(self.paths(kind))
                    .map(|(i, path)| (i, kind, path.clone())),
            );
        }
        given.sort_by_key(|(i, _, _)| *i);
        self.given = given.into_iter().map(|(_, k, p)| (k, p)).collect();
    }

    /// The outputs to write, in order.
    fn outputs(&self) -> Vec<(OutputKind, String)> {
        if !self.given.is_empty() {
            return self.given.clone();
        }
        OutputKind::ALL
            .iter()
            .flat_map(|&(kind, _)| self.paths(kind).iter().map(move |p| (kind, p.clone())))
            .collect()
    }
}

/// The file a path names, to compare two paths: the canonical path of the file, or of its
/// folder joined with its name when the file does not exist yet (`F`, `./F` and `d/../F` are
/// one file; so are two paths through a symbolic link); the path as given, made absolute,
/// when its folder does not exist either (writing it fails then).
fn the_file(path: &str) -> std::path::PathBuf {
    let p = std::path::Path::new(path);
    if let Ok(c) = std::fs::canonicalize(p) {
        return c;
    }
    let folder = p
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(std::path::Path::new("."));
    match (std::fs::canonicalize(folder), p.file_name()) {
        (Ok(d), Some(name)) => d.join(name),
        _ => std::path::absolute(p).unwrap_or_else(|_| p.to_path_buf()),
    }
}

/// Refuses two outputs to one file (the second would overwrite the first) and an output to
/// the input file (read before, then overwritten), naming both paths as given.
fn distinct_outputs(input: &str, outputs: &[(OutputKind, String)]) -> Result<(), CliError> {
    let input = (input != "-").then(|| the_file(input));
    let mut seen: Vec<(std::path::PathBuf, OutputKind, &str)> = Vec::new();
    for (kind, path) in outputs {
        let file = the_file(path);
        if input.as_ref() == Some(&file) {
            return Err(CliError::usage(CliMessage::IsInput {
                flag: kind.flag(),
                path: path.clone(),
            }));
        }
        if let Some((_, k, first)) = seen.iter().find(|(f, _, _)| *f == file) {
            return Err(CliError::usage(CliMessage::SameFile {
                first_flag: k.flag(),
                first: first.to_string(),
                flag: kind.flag(),
                path: path.clone(),
            }));
        }
        seen.push((file, *kind, path));
    }
    Ok(())
}

/// A parser of the number of degrees of `flag`.
fn degrees(flag: &'static str) -> impl Fn(&str) -> Result<f64, CliMessage> + Clone {
    move |v: &str| {
        v.parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| CliMessage::Degrees {
                flag: flag.into(),
                found: v.into(),
            })
    }
}

/// `--density`: 1 to 256.
fn density(v: &str) -> Result<usize, CliMessage> {
    v.parse()
        .ok()
        .filter(|d| (1..=256).contains(d))
        .ok_or_else(|| CliMessage::Density { found: v.into() })
}

/// Runs `cagd render`; its errors in the language asked.
pub fn run(args: &RenderArgs) -> Result<Report, CliError> {
    run_in(args).map_err(|e| e.in_lang(args.lang.lang()))
}

fn run_in(args: &RenderArgs) -> Result<Report, CliError> {
    let mut svg = SvgOptions::default();
    let mut html = HtmlOptions::default();
    if let Some(azimuth) = args.azimuth {
        svg.view.azimuth = azimuth;
        html.view.azimuth = azimuth;
    }
    if let Some(elevation) = args.elevation {
        svg.view.elevation = elevation;
        html.view.elevation = elevation;
    }
    if let Some(layers) = args.layers {
        svg.layers = layers;
    }
    let lang = args.lang.lang();
    html.lang = lang;
    svg.panels = args.steps;
    let (input, density, steps) = (&args.input, args.density, args.steps);
    let outputs = args.outputs();
    if outputs.is_empty() {
        return Err(CliError::usage(CliMessage::NoOutput));
    }
    distinct_outputs(input, &outputs)?;
    let doc = read_json(input)?;
    let first = problems(&doc).into_iter().next().unwrap_or_default();
    // a problem is read and solved once, here; its figure and plot come from the answer
    let answer = if first.get("op").is_some() && first.get("result").is_none() {
        let settings = cagd_problem::Settings {
            limits: args.limits.limits(),
            steps,
        };
        let refused = |e| CliError::Input(Said::Problem(Box::new(e)));
        let problem = cagd_problem::Problem::read(&first, &settings.limits).map_err(refused)?;
        Some(
            cagd_problem::solve_problem(&std::sync::Arc::new(problem), &settings)
                .map_err(refused)?,
        )
    } else {
        None
    };
    let mut scene = match &answer {
        Some(a) => Scene::from_answer(a, steps),
        None => Scene::from_json(&first, steps),
    }
    .map_err(|e| CliError::Input(Said::from(e)))?;
    if let Some(a) = &answer {
        crate::figures::localize(&mut scene, &a.problem, &a.op, lang);
    }
    let bad = |e: cagd_render::RenderError| CliError::Input(Said::from(e));
    let mut text = String::new();
    let deadline = args.limits.limits().max_seconds;
    for (kind, path) in outputs {
        let draw = || -> Result<Vec<u8>, CliError> {
            Ok(match kind {
                OutputKind::Svg => render_svg(&scene, &svg).map_err(bad)?.into_bytes(),
                OutputKind::Html => to_html(&scene, &html).map_err(bad)?.into_bytes(),
                OutputKind::Obj => to_obj(&scene, density).map_err(bad)?.into_bytes(),
                OutputKind::Stl => to_stl_binary(&scene, density).map_err(bad)?,
                OutputKind::Plot => plot(answer.as_ref(), &scene)?.into_bytes(),
                OutputKind::Iges => to_iges(&scene).map_err(bad)?.into_bytes(),
            })
        };
        // each figure is evaluated exactly point by point: under the problem's deadline
        let bytes = cagd_scalar::cancel::with_deadline(deadline, draw).map_err(|_| {
            let seconds = deadline.unwrap_or_default().as_secs_f64().to_string();
            let path = path.clone();
            CliError::input(if matches!(kind, OutputKind::Obj | OutputKind::Stl) {
                CliMessage::NotDrawnDense { path, seconds }
            } else {
                CliMessage::NotDrawn { path, seconds }
            })
        })??;
        std::fs::write(&path, bytes).map_err(|e| {
            CliError::input(CliMessage::CannotWrite {
                path: path.clone(),
                why: e.to_string(),
            })
        })?;
        text += &crate::generate::wrote(std::path::Path::new(&path), args.lang.lang());
    }
    Ok(text.into())
}

/// The chart of `--plot` (see the help).
fn plot(answer: Option<&cagd_problem::Answer>, scene: &Scene<Number>) -> Result<String, CliError> {
    let bad = |e: cagd_render::RenderError| CliError::Input(Said::from(e));
    if let Some(answer) = answer.filter(|a| a.op == "developable") {
        {
            if let Some(Exact::Poly(p)) = answer.result_of(&Quantity::DevelopablePolynomial) {
                let options = PlotOptions {
                    title: Some(format!("c_uv · (c_u × c_v) = {}", p.to_text())),
                    ..PlotOptions::default()
                };
                let unit = (Number::from_i64(0), Number::from_i64(1));
                return plot_polynomial(p, Var::U, unit, &options).map_err(bad);
            }
        }
    }
    let surface = scene
        .surfaces
        .first()
        .ok_or_else(|| CliError::input(CliMessage::NoSurface))?;
    match &surface.geometry {
        AnySurface::RationalBezier(r) => {
            let weights: Vec<Number> = r.weights().iter().cloned().collect();
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
fn layers(list: &str) -> Result<Layers, CliMessage> {
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
                return Err(CliMessage::UnknownLayer {
                    layer: other.into(),
                })
            }
        }
    }
    Ok(l)
}
