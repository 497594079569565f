//! Figures: an SVG drawing inline in Jupyter, and the interactive HTML page.
//!
//! The geometry is evaluated exactly by cagd-render and converted to floating point only to
//! draw, as `cagd render` does.

use crate::error::cagd_error;
use crate::said::PyMessage;
use cagd_problem::Answer;
use cagd_problem::Number;
use cagd_render::{render_svg, to_html, HtmlOptions, RenderError, Scene, SvgOptions, View};
use pyo3::prelude::*;
use serde_json::Value;

fn render_error(e: &RenderError) -> PyErr {
    cagd_error(PyMessage::CannotDraw(e.clone()))
}

/// The figure of a problem's answer, or of an answer or surface given as JSON: the
/// isoparametric net, the control mesh and the input curves. Shows inline in Jupyter as SVG;
/// `figure.interactive()` shows the page where students turn the surface around and hover a
/// control point to read its exact coordinates.
#[pyclass(module = "cagd_exact", name = "Figure", frozen)]
pub struct Figure {
    scene: Scene<Number>,
}

impl Figure {
    /// The figure of an answer (`Scene::from_answer`).
    pub fn of_answer(answer: &Answer, steps: bool) -> PyResult<Self> {
        Scene::from_answer(answer, steps)
            .map(|scene| Figure { scene })
            .map_err(|e| render_error(&e))
    }

    /// The figure of an answer as JSON, or of a bare surface or curve (`Scene::from_json`).
    pub fn of_json(value: &Value, steps: bool) -> PyResult<Self> {
        Scene::from_json(value, steps)
            .map(|scene| Figure { scene })
            .map_err(|e| render_error(&e))
    }
}

fn view(azimuth: Option<f64>, elevation: Option<f64>) -> View {
    let default = View::default();
    View {
        azimuth: azimuth.unwrap_or(default.azimuth),
        elevation: elevation.unwrap_or(default.elevation),
    }
}

#[pymethods]
impl Figure {
    /// The SVG drawing (deterministic bytes); angles in degrees.
    #[pyo3(signature = (*, width=None, height=None, azimuth=None, elevation=None))]
    fn svg(
        &self,
        width: Option<u32>,
        height: Option<u32>,
        azimuth: Option<f64>,
        elevation: Option<f64>,
    ) -> PyResult<String> {
        let default = SvgOptions::default();
        let options = SvgOptions {
            width: width.unwrap_or(default.width),
            height: height.unwrap_or(default.height),
            view: view(azimuth, elevation),
            ..default
        };
        render_svg(&self.scene, &options).map_err(|e| render_error(&e))
    }

    /// The self-contained interactive HTML page (as `cagd render --html`).
    #[pyo3(signature = (*, azimuth=None, elevation=None))]
    fn html(&self, azimuth: Option<f64>, elevation: Option<f64>) -> PyResult<String> {
        let options = HtmlOptions {
            view: view(azimuth, elevation),
            ..HtmlOptions::default()
        };
        to_html(&self.scene, &options).map_err(|e| render_error(&e))
    }

    /// The interactive page, shown inline in Jupyter (in an iframe) `height` pixels high.
    #[pyo3(signature = (*, height=560))]
    fn interactive(&self, height: u32) -> PyResult<Page> {
        Ok(Page {
            html: self.html(None, None)?,
            height,
        })
    }

    /// Writes the figure to `path`: `.svg` the drawing, `.html` the interactive page.
    fn save(&self, path: &str) -> PyResult<()> {
        let text = if path.ends_with(".html") || path.ends_with(".htm") {
            self.html(None, None)?
        } else if path.ends_with(".svg") {
            self.svg(None, None, None, None)?
        } else {
            return Err(cagd_error(PyMessage::FigureFormat {
                path: path.to_string(),
            }));
        };
        std::fs::write(path, text).map_err(|e| {
            cagd_error(PyMessage::CannotWrite {
                path: path.to_string(),
                why: e.to_string(),
            })
        })
    }

    fn _repr_svg_(&self) -> PyResult<String> {
        self.svg(None, None, None, None)
    }

    fn __repr__(&self) -> String {
        format!(
            "<cagd_exact.Figure {}>",
            self.scene.title.clone().unwrap_or_default()
        )
    }
}

/// The interactive HTML page of a figure, shown in Jupyter inside an iframe.
#[pyclass(module = "cagd_exact", name = "Page", frozen)]
pub struct Page {
    /// The page.
    #[pyo3(get)]
    html: String,
    height: u32,
}

#[pymethods]
impl Page {
    fn _repr_html_(&self) -> String {
        let escaped = self
            .html
            .replace('&', "&amp;")
            .replace('"', "&quot;")
            .replace('<', "&lt;")
            .replace('>', "&gt;");
        format!(
            "<iframe srcdoc=\"{escaped}\" style=\"width: 100%; height: {}px; border: 0\"></iframe>",
            self.height
        )
    }

    fn __repr__(&self) -> String {
        format!("<cagd_exact.Page {} bytes>", self.html.len())
    }
}
