//! One self-contained HTML page with an interactive 3D view of the scene: the data and the
//! viewer are inline (no network, no library), drawn on a `<canvas>`.
//!
//! Drag to rotate, wheel to zoom, check boxes to show the surface, the mesh, the boundaries,
//! the curves and the axes; hovering a control point shows its exact coordinates and weight
//! (`c1,1 = (1/2, 5/6, 31/6)`, `w = √2/2`). The URL hash sets the view:
//! `page.html#azimuth=60&elevation=20&zoom=1.5`.

use crate::sample::{sample, Density, Sampled};
use crate::view::escape;
use crate::{Colour, RenderError, Sampling, Scene, View};
use cagd_scalar::Scalar;
use cagd_words::{said, Lang, Message, Phrase};
use std::fmt::Write;

/// Options of [`to_html`].
#[derive(Clone, Debug, PartialEq)]
pub struct HtmlOptions {
    /// Canvas width in pixels.
    pub width: u32,
    /// Canvas height in pixels.
    pub height: u32,
    /// The initial view (the URL hash can change it).
    pub view: View,
    /// Isoparametric cells in each direction (2 to 64).
    pub isolines: usize,
    /// Exact sample points per cell edge (1 to 16).
    pub samples: usize,
    /// The language of the page: its `lang`, instructions, check boxes and key.
    pub lang: Lang,
}

impl Default for HtmlOptions {
    fn default() -> Self {
        HtmlOptions {
            width: 800,
            height: 600,
            view: View::default(),
            isolines: 12,
            samples: 3,
            lang: Lang::En,
        }
    }
}

/// The words of the page, in each language.
#[derive(Debug, Clone, Copy, PartialEq, Eq, strum::EnumIter)]
enum PageWord {
    /// The title of a scene without one.
    Figure,
    /// The check box of the surfaces.
    Surface,
    /// The check box of the control meshes.
    Mesh,
    /// The check box of the boundary curves.
    Boundary,
    /// The check box of the curves.
    Curves,
    /// The check box of the axes.
    Axes,
    /// How to use the view.
    Instructions,
    /// The weights of a row of the key.
    Weights,
}

impl Message for PageWord {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            PageWord::Figure => said(lang, "cagd-exact figure", "figura de cagd-exact", []),
            PageWord::Surface => said(lang, "surface", "superficie", []),
            PageWord::Mesh => said(lang, "control mesh", "malla de control", []),
            PageWord::Boundary => said(lang, "boundary", "borde", []),
            PageWord::Curves => said(lang, "curves", "curvas", []),
            PageWord::Axes => said(lang, "axes", "ejes", []),
            PageWord::Instructions => said(
                lang,
                "Drag to rotate, wheel to zoom, hover a control point to read it exactly.",
                "Arrastre para girar, use la rueda para acercar o alejar y pase el ratón por un punto de control para leerlo exacto.",
                [],
            ),
            PageWord::Weights => said(lang, "weights", "pesos", []),
        }
    }
}

fn word(w: PageWord, lang: Lang) -> String {
    w.phrase(lang).text()
}

const VIEWER: &str = include_str!("viewer.js");

/// A JSON string literal (quotes, backslashes, control characters escaped; `<` as `\u003c`
/// so the data cannot close its `<script>` element).
fn json_string(s: &str) -> String {
    serde_json::Value::String(s.to_string())
        .to_string()
        .replace('<', "\\u003c")
}

/// Fixed-decimal numbers for the page: 6 significant digits at the scale of the scene.
struct Numbers {
    decimals: usize,
}

impl Numbers {
    fn new(size: f64) -> Self {
        let magnitude = if size > 0.0 && size.is_finite() {
            size.log10().floor() as i64
        } else {
            0
        };
        Numbers {
            decimals: (5 - magnitude).clamp(0, 15) as usize,
        }
    }

    fn num(&self, x: f64) -> String {
        let d = self.decimals;
        let s = format!("{:.d$}", if x.is_finite() { x } else { 0.0 });
        if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
            s[1..].to_string()
        } else {
            s
        }
    }

    fn point(&self, p: &[f64; 3]) -> String {
        format!("[{},{},{}]", self.num(p[0]), self.num(p[1]), self.num(p[2]))
    }

    fn points(&self, ps: &[[f64; 3]]) -> String {
        format!(
            "[{}]",
            ps.iter()
                .map(|p| self.point(p))
                .collect::<Vec<_>>()
                .join(",")
        )
    }

    fn grid(&self, g: &[Vec<[f64; 3]>]) -> String {
        format!(
            "[{}]",
            g.iter()
                .map(|r| self.points(r))
                .collect::<Vec<_>>()
                .join(",\n")
        )
    }
}

fn strings(xs: &[String]) -> String {
    format!(
        "[{}]",
        xs.iter()
            .map(|s| json_string(s))
            .collect::<Vec<_>>()
            .join(",")
    )
}

fn string_grid(g: &[Vec<String>]) -> String {
    format!(
        "[{}]",
        g.iter().map(|r| strings(r)).collect::<Vec<_>>().join(",")
    )
}

/// The scene's data as JSON for the viewer.
fn scene_json(s: &Sampled, view: View) -> String {
    let n = Numbers::new(s.size());
    let mut out = String::from("{\n");
    let angle = |x: f64, default: f64| if x.is_finite() { x } else { default };
    let _ = writeln!(
        out,
        "\"view\": {{\"azimuth\": {}, \"elevation\": {}}},",
        angle(view.azimuth, View::default().azimuth),
        angle(view.elevation, View::default().elevation)
    );
    out.push_str("\"surfaces\": [");
    for (k, surf) in s.surfaces.iter().enumerate() {
        if k > 0 {
            out.push(',');
        }
        let back = surf.colour.mix(Colour::rgb(0xb0, 0xb0, 0xb0), 0.5);
        let _ = write!(
            out,
            "\n{{\"name\": {}, \"colour\": \"{}\", \"back_colour\": \"{}\", \"mesh_colour\": \"{}\", \
             \"cells\": [{}, {}], \"sub\": {},\n\"net\": {},\n\"net_text\": {},\n\"weights_text\": {},\n\"grid\": {}}}",
            json_string(&surf.name),
            surf.colour.hex(),
            back.hex(),
            surf.mesh_colour.hex(),
            surf.cells.0,
            surf.cells.1,
            surf.sub,
            n.grid(&surf.net),
            string_grid(&surf.net_text),
            surf.weights_text
                .as_ref()
                .map_or("null".to_string(), |w| string_grid(w)),
            n.grid(&surf.grid),
        );
    }
    out.push_str("],\n\"curves\": [");
    for (k, c) in s.curves.iter().enumerate() {
        if k > 0 {
            out.push(',');
        }
        let _ = write!(
            out,
            "\n{{\"name\": {}, \"colour\": \"{}\", \"polygon\": {}, \"polygon_text\": {}, \
             \"weights_text\": {},\n\"points\": {}}}",
            json_string(&c.name),
            c.colour.hex(),
            n.points(&c.polygon),
            strings(&c.polygon_text),
            c.weights_text
                .as_ref()
                .map_or("null".to_string(), |w| strings(w)),
            n.points(&c.points),
        );
    }
    out.push_str("]\n}");
    out
}

/// The exact control points of each surface and curve, as text, for the page's key.
fn key_html(s: &Sampled, lang: Lang) -> String {
    let weights = word(PageWord::Weights, lang);
    let mut out = String::new();
    for surf in &s.surfaces {
        let _ = writeln!(
            out,
            "<details><summary><span class=\"sw\" style=\"background:{}\"></span>{}</summary><pre>",
            surf.colour.hex(),
            escape(&surf.name)
        );
        for (i, row) in surf.net_text.iter().enumerate() {
            let _ = writeln!(out, "{}", escape(&row.join("  ")));
            if let Some(w) = surf.weights_text.as_ref().and_then(|w| w.get(i)) {
                let _ = writeln!(out, "  {weights} {}", escape(&w.join(", ")));
            }
        }
        out.push_str("</pre></details>\n");
    }
    for c in &s.curves {
        let _ = writeln!(
            out,
            "<details><summary><span class=\"sw\" style=\"background:{}\"></span>{}</summary><pre>{}",
            c.colour.hex(),
            escape(&c.name),
            escape(&c.polygon_text.join("  "))
        );
        if let Some(w) = &c.weights_text {
            let _ = write!(out, "\n  {weights} {}", escape(&w.join(", ")));
        }
        out.push_str("</pre></details>\n");
    }
    out
}

/// The text of the one inline script of the page [`to_html`] writes (its viewer), as it stands
/// between `<script>` and `</script>`: a server that sends the page allows exactly this script
/// by its hash in a Content-Security-Policy. (The scene's data is a `<script
/// type="application/json">`, which no browser runs.)
pub fn inline_script() -> String {
    format!("\n{VIEWER}")
}

/// The scene as one self-contained HTML page with an interactive view (see the module
/// documentation). Like the SVG, every point is evaluated exactly and converted to f64 only to
/// be drawn; the page also lists the exact control points.
pub fn to_html<S: Scalar>(scene: &Scene<S>, options: &HtmlOptions) -> Result<String, RenderError> {
    crate::error::check_density(Sampling::Isolines, options.isolines, 2, 64)?;
    crate::error::check_density(Sampling::SamplesPerCell, options.samples, 1, 16)?;
    let sampled = sample(
        scene,
        Density {
            cells: (options.isolines, options.isolines),
            sub: options.samples,
            normals: 0,
            curve_segments: 64,
        },
    )?;
    let lang = options.lang;
    let title = escape(
        &scene
            .title
            .clone()
            .unwrap_or_else(|| word(PageWord::Figure, lang)),
    );
    let toggles = [
        ("surface", PageWord::Surface),
        ("mesh", PageWord::Mesh),
        ("boundary", PageWord::Boundary),
        ("curves", PageWord::Curves),
        ("axes", PageWord::Axes),
    ]
    .iter()
    .map(|(k, w)| {
        format!(
            "<label><input type=\"checkbox\" id=\"show-{k}\" checked> {}</label>",
            escape(&word(*w, lang))
        )
    })
    .collect::<Vec<_>>()
    .join("\n");
    let instructions = escape(&word(PageWord::Instructions, lang));
    let code = match lang {
        Lang::En => "en",
        Lang::Es => "es",
    };
    let mut page = String::new();
    let _ = write!(
        page,
        "<!DOCTYPE html>\n<html lang=\"{code}\">\n<head>\n<meta charset=\"utf-8\">\n<title>{title}</title>\n\
<style>\nbody {{ font-family: sans-serif; margin: 12px; color: #222; }}\n\
canvas {{ border: 1px solid #ccc; cursor: grab; display: block; }}\n\
#controls label {{ margin-right: 14px; }}\n\
#tip {{ position: absolute; display: none; background: #fffbe6; border: 1px solid #caa; padding: 3px 6px; font: 13px monospace; pointer-events: none; white-space: nowrap; }}\n\
.sw {{ display: inline-block; width: 12px; height: 12px; margin-right: 6px; border: 1px solid #444; }}\n\
pre {{ margin: 4px 0 8px 18px; }}\n</style>\n</head>\n<body>\n<h1 style=\"font-size: 18px\">{title}</h1>\n\
<div id=\"controls\">\n{toggles}\n</div>\n\
<canvas id=\"view\" width=\"{w}\" height=\"{h}\"></canvas>\n\
<div id=\"tip\"></div>\n\
<p style=\"font-size: 13px; color: #555\">{instructions}</p>\n\
{key}\
<script type=\"application/json\" id=\"scene-data\">\n{data}\n</script>\n\
<script>{script}</script>\n</body>\n</html>\n",
        w = options.width,
        h = options.height,
        key = key_html(&sampled, lang),
        data = scene_json(&sampled, options.view),
        script = inline_script(),
    );
    Ok(page)
}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_word_of_the_page_in_both_languages() {
        for w in PageWord::iter() {
            assert_eq!(cagd_words::check_both(&w), Ok(()), "{w:?}");
        }
    }
}
