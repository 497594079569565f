//! Small SVG charts of scalar quantities: a polynomial over an interval (the developability
//! polynomial), the sign of the Gaussian curvature across a patch, the weights along a row.
//!
//! Values are computed exactly at exact sample points and converted to f64 only to be drawn;
//! exact zeros at the sample points are marked and labelled exactly.

use crate::curvature::{gaussian_signs, CurvatureSign};
use crate::geometry::parameter;
use crate::view::{escape, n1};
use crate::{AnySurface, Drawn, RenderError, Sampling, Unplotted};
use cagd_poly::{Poly, Var};
use cagd_scalar::{ExactRational, Scalar};
use std::fmt::Write;

/// Options of the charts.
#[derive(Clone, Debug, PartialEq)]
pub struct PlotOptions {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The title; `None` for the chart's own (the polynomial, "Sign of the Gaussian
    /// curvature", "Weights").
    pub title: Option<String>,
    /// Exact sample points of a polynomial (2 to 2000).
    pub samples: usize,
}

impl Default for PlotOptions {
    fn default() -> Self {
        PlotOptions {
            width: 480,
            height: 300,
            title: None,
            samples: 200,
        }
    }
}

const FONT: &str = "font-family=\"DejaVu Sans, Arial, sans-serif\"";
const LINE: &str = "#2a5d9f";
const ZERO: &str = "#c0392b";
const POSITIVE: &str = "#d6604d";
const NEGATIVE: &str = "#4393c3";
const FLAT: &str = "#e0e0e0";

/// The plot area: margins left 60, right 20, top 36, bottom 44.
struct Chart {
    h: f64,
    left: f64,
    right: f64,
    top: f64,
    bottom: f64,
    out: String,
}

impl Chart {
    fn new(o: &PlotOptions, title: &str) -> Self {
        let (w, h) = (f64::from(o.width), f64::from(o.height));
        let mut out = String::new();
        let _ = writeln!(
            out,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" viewBox=\"0 0 {} {}\">",
            o.width, o.height, o.width, o.height
        );
        let _ = writeln!(
            out,
            "<rect width=\"{}\" height=\"{}\" fill=\"#ffffff\"/>",
            o.width, o.height
        );
        let _ = writeln!(
            out,
            "<text x=\"{}\" y=\"22\" text-anchor=\"middle\" font-size=\"14\" {FONT}>{}</text>",
            n1(w / 2.0),
            escape(title)
        );
        Chart {
            h,
            left: 60.0,
            right: w - 20.0,
            top: 36.0,
            bottom: h - 44.0,
            out,
        }
    }

    fn x(&self, t: f64, (a, b): (f64, f64)) -> f64 {
        self.left + (t - a) / (b - a).max(1e-300) * (self.right - self.left)
    }

    fn y(&self, v: f64, (lo, hi): (f64, f64)) -> f64 {
        self.bottom - (v - lo) / (hi - lo).max(1e-300) * (self.bottom - self.top)
    }

    fn text(&mut self, x: f64, y: f64, anchor: &str, size: u32, s: &str) {
        let _ = writeln!(
            self.out,
            "<text x=\"{}\" y=\"{}\" text-anchor=\"{anchor}\" font-size=\"{size}\" {FONT}>{}</text>",
            n1(x),
            n1(y),
            escape(s)
        );
    }

    fn line(&mut self, (x0, y0): (f64, f64), (x1, y1): (f64, f64), style: &str) {
        let _ = writeln!(
            self.out,
            "<polyline points=\"{},{} {},{}\" {style}/>",
            n1(x0),
            n1(y0),
            n1(x1),
            n1(y1)
        );
    }

    /// The y axis with ticks at nice values of `range`.
    fn y_axis(&mut self, range: (f64, f64)) {
        let (l, t, b) = (self.left, self.top, self.bottom);
        self.line((l, t), (l, b), "stroke=\"#444\"");
        let (step, decimals) = nice_step((range.1 - range.0) / 5.0);
        let mut k = (range.0 / step).ceil() as i64;
        while (k as f64) * step <= range.1 + 1e-9 * step {
            let v = k as f64 * step;
            let y = self.y(v, range);
            self.line((l - 4.0, y), (l, y), "stroke=\"#444\"");
            let label = format!("{:.*}", decimals, if v == 0.0 { 0.0 } else { v });
            self.text(l - 7.0, y + 4.0, "end", 11, &label);
            k += 1;
        }
    }

    fn finish(mut self) -> String {
        self.out.push_str("</svg>\n");
        self.out
    }
}

/// A step of 1, 2 or 5 times a power of ten near `raw`, and the decimals to print it.
fn nice_step(raw: f64) -> (f64, usize) {
    let raw = if raw > 0.0 && raw.is_finite() {
        raw
    } else {
        1.0
    };
    let e = raw.log10().floor();
    let mag = 10f64.powf(e);
    let f = raw / mag;
    let m = if f < 1.5 {
        1.0
    } else if f < 3.5 {
        2.0
    } else if f < 7.5 {
        5.0
    } else {
        10.0
    };
    let decimals = if m >= 10.0 { -e - 1.0 } else { -e };
    (m * mag, decimals.max(0.0) as usize)
}

/// A range holding `values` and 0, padded by 8%.
fn padded_range(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (mut lo, mut hi) = (0.0f64, 0.0f64);
    for v in values.filter(|v| v.is_finite()) {
        lo = lo.min(v);
        hi = hi.max(v);
    }
    if hi - lo < 1e-12 {
        hi = lo + 1.0;
    }
    let pad = 0.08 * (hi - lo);
    (lo - if lo < 0.0 { pad } else { 0.0 }, hi + pad)
}

/// The graph of a polynomial in one variable over `[a, b]`, e.g. the developability
/// polynomial `12 u - 8 u^3 - 4 u^2` of the notes' ruled patch over [0, 1]: the polynomial is
/// evaluated exactly at `samples + 1` equally spaced exact points; those where it is exactly
/// zero are marked and labelled (`u = 1`).
///
/// ```
/// use cagd_render::{plot_polynomial, PlotOptions};
/// use cagd_poly::{parse_poly, Var};
/// use cagd_scalar::{q, BigRational};
/// let p = parse_poly::<BigRational>("12 u - 8 u^3 - 4 u^2").unwrap();
/// let svg = plot_polynomial(&p, Var::U, (q!(0), q!(1)), &PlotOptions::default()).unwrap();
/// assert!(svg.contains(">u = 0<") && svg.contains(">u = 1<"));
/// ```
pub fn plot_polynomial<S: Scalar>(
    p: &Poly<S>,
    var: Var,
    interval: (S, S),
    options: &PlotOptions,
) -> Result<String, RenderError> {
    let n = crate::error::check_density(Sampling::Samples, options.samples, 2, 2000)?;
    if let Some(other) = p.vars().into_iter().find(|v| *v != var) {
        return Err(RenderError::Variables {
            what: Drawn::Polynomial { text: p.to_text() },
            found: format!("{var}, {other}"),
        });
    }
    if interval.0 >= interval.1 {
        return Err(RenderError::Plot(Unplotted::EmptyInterval {
            from: interval.0.to_text(),
            to: interval.1.to_text(),
        }));
    }
    let mut samples = Vec::with_capacity(n + 1);
    for k in 0..=n {
        let t = parameter(&interval, k, n);
        let value = p.eval(&[(var, t.clone())])?;
        samples.push((t, value));
    }
    let ab = (interval.0.to_f64(), interval.1.to_f64());
    let range = padded_range(samples.iter().map(|(_, v)| v.to_f64()));
    let title = options
        .title
        .clone()
        .unwrap_or_else(|| format!("p({var}) = {}", p.to_text()));
    let mut c = Chart::new(options, &title);
    c.y_axis(range);
    // x axis along y = 0 (or the bottom), ticks at a + (b - a) k / 4 with exact labels
    let y0 = c.y(0.0f64.clamp(range.0, range.1), range);
    let (l, r, b) = (c.left, c.right, c.bottom);
    c.line((l, y0), (r, y0), "stroke=\"#444\"");
    for k in 0..=4 {
        let t = parameter(&interval, k, 4);
        let x = c.x(t.to_f64(), ab);
        c.line((x, b), (x, b + 4.0), "stroke=\"#444\"");
        c.line((x, c.top), (x, b), "stroke=\"#eeeeee\"");
        c.text(x, b + 17.0, "middle", 11, &t.to_text());
    }
    c.line((l, b), (r, b), "stroke=\"#444\"");
    c.text((l + r) / 2.0, c.h - 8.0, "middle", 12, var.name());
    let pts: Vec<String> = samples
        .iter()
        .map(|(t, v)| format!("{},{}", n1(c.x(t.to_f64(), ab)), n1(c.y(v.to_f64(), range))))
        .collect();
    let _ = writeln!(
        c.out,
        "<polyline points=\"{}\" fill=\"none\" stroke=\"{LINE}\" stroke-width=\"2\" stroke-linejoin=\"round\"/>",
        pts.join(" ")
    );
    for (t, _) in samples.iter().filter(|(_, v)| v.is_zero()) {
        let x = c.x(t.to_f64(), ab);
        let _ = writeln!(
            c.out,
            "<circle cx=\"{}\" cy=\"{}\" r=\"4\" fill=\"{ZERO}\"/>",
            n1(x),
            n1(y0)
        );
        let anchor = if x > c.right - 30.0 { "end" } else { "start" };
        c.text(
            x + if anchor == "end" { -4.0 } else { 4.0 },
            y0 - 8.0,
            anchor,
            11,
            &format!("{var} = {}", t.to_text()),
        );
    }
    Ok(c.finish())
}

/// The weights along a row (or any list of weights) as a bar chart, each bar labelled with
/// its exact value (`√2/2`) and its name `w_0, w_1, ...` (or `names`).
///
/// ```
/// use cagd_render::{plot_weights, PlotOptions};
/// use cagd_scalar::{parse_number, Quadratic};
/// let w: Vec<Quadratic> = ["1", "sqrt2/2", "1"].iter().map(|t| parse_number(t).unwrap()).collect();
/// let svg = plot_weights(&w, None, &PlotOptions::default()).unwrap();
/// assert!(svg.contains(">√2/2<"));
/// ```
pub fn plot_weights<S: Scalar>(
    weights: &[S],
    names: Option<&[String]>,
    options: &PlotOptions,
) -> Result<String, RenderError> {
    if weights.is_empty() {
        return Err(RenderError::Plot(Unplotted::NoWeights));
    }
    let range = padded_range(weights.iter().map(ExactRational::to_f64));
    let title = options.title.clone().unwrap_or_else(|| "Weights".into());
    let mut c = Chart::new(options, &title);
    c.y_axis(range);
    let y0 = c.y(0.0, range);
    let slot = (c.right - c.left) / weights.len() as f64;
    for (k, w) in weights.iter().enumerate() {
        let x = c.left + slot * (k as f64 + 0.5);
        let y = c.y(w.to_f64(), range);
        let (top, height) = (y.min(y0), (y - y0).abs());
        let colour = if *w < S::zero() { NEGATIVE } else { LINE };
        let _ = writeln!(
            c.out,
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{colour}\"/>",
            n1(x - 0.3 * slot),
            n1(top),
            n1(0.6 * slot),
            n1(height)
        );
        let label_y = if *w < S::zero() { y + 14.0 } else { y - 5.0 };
        c.text(x, label_y, "middle", 11, &w.to_text());
        let name = names
            .and_then(|n| n.get(k).cloned())
            .unwrap_or_else(|| format!("w_{k}"));
        c.text(x, c.bottom + 17.0, "middle", 11, &name);
    }
    let (l, r) = (c.left, c.right);
    c.line((l, y0), (r, y0), "stroke=\"#444\"");
    Ok(c.finish())
}

/// The sign of the Gaussian curvature across a patch on an `n x n` grid of cells (u to the
/// right, v upward), computed exactly at the cell centres by [`gaussian_signs`]: red where
/// K > 0, blue where K < 0, grey where K = 0, white with a cross where `c_u x c_v = 0`.
pub fn plot_gaussian_sign<S: Scalar>(
    surface: &AnySurface<S>,
    n: usize,
    options: &PlotOptions,
) -> Result<String, RenderError> {
    let signs = gaussian_signs(surface, n)?;
    let ((a, b), (cc, d)) = surface.domain();
    let title = options
        .title
        .clone()
        .unwrap_or_else(|| "Sign of the Gaussian curvature".into());
    let mut c = Chart::new(options, &title);
    // a square grid, legend on the right
    let side = (c.bottom - c.top).min(c.right - c.left - 150.0).max(20.0);
    let cell = side / n as f64;
    let (x0, y0) = (c.left, c.top);
    for (i, row) in signs.iter().enumerate() {
        for (j, s) in row.iter().enumerate() {
            let (x, y) = (x0 + cell * i as f64, y0 + side - cell * (j as f64 + 1.0));
            let fill = match s {
                CurvatureSign::Positive => POSITIVE,
                CurvatureSign::Negative => NEGATIVE,
                CurvatureSign::Zero => FLAT,
                CurvatureSign::Undefined => "#ffffff",
            };
            let _ = writeln!(
                c.out,
                "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"{fill}\" stroke=\"#ffffff\" stroke-width=\"0.5\"/>",
                n1(x),
                n1(y),
                n1(cell),
                n1(cell)
            );
            if *s == CurvatureSign::Undefined {
                c.line(
                    (x + 2.0, y + 2.0),
                    (x + cell - 2.0, y + cell - 2.0),
                    "stroke=\"#888\"",
                );
                c.line(
                    (x + 2.0, y + cell - 2.0),
                    (x + cell - 2.0, y + 2.0),
                    "stroke=\"#888\"",
                );
            }
        }
    }
    let _ = writeln!(
        c.out,
        "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#444\"/>",
        n1(x0),
        n1(y0),
        n1(side),
        n1(side)
    );
    c.text(x0, y0 + side + 16.0, "middle", 11, &a.to_text());
    c.text(x0 + side, y0 + side + 16.0, "middle", 11, &b.to_text());
    c.text(x0 + side / 2.0, y0 + side + 30.0, "middle", 12, "u");
    c.text(x0 - 6.0, y0 + side + 4.0, "end", 11, &cc.to_text());
    c.text(x0 - 6.0, y0 + 4.0, "end", 11, &d.to_text());
    c.text(x0 - 24.0, y0 + side / 2.0 + 4.0, "middle", 12, "v");
    let entries = [
        (CurvatureSign::Positive, POSITIVE, "K > 0 (elliptic)"),
        (CurvatureSign::Zero, FLAT, "K = 0 (parabolic)"),
        (CurvatureSign::Negative, NEGATIVE, "K < 0 (hyperbolic)"),
        (CurvatureSign::Undefined, "#ffffff", "no normal"),
    ];
    let lx = x0 + side + 16.0;
    let mut ly = y0 + 8.0;
    for (sign, fill, label) in entries {
        let count = signs.iter().flatten().filter(|s| **s == sign).count();
        if count == 0 {
            continue;
        }
        let _ = writeln!(
            c.out,
            "<rect x=\"{}\" y=\"{}\" width=\"12\" height=\"12\" fill=\"{fill}\" stroke=\"#444\"/>",
            n1(lx),
            n1(ly)
        );
        c.text(
            lx + 18.0,
            ly + 10.0,
            "start",
            11,
            &format!("{label}: {count}"),
        );
        ly += 20.0;
    }
    Ok(c.finish())
}
