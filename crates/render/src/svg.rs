//! The SVG figure: surfaces as nets of isoparametric curves over shaded cells in painter's
//! order, control meshes with their vertices, boundaries, normals, input curves, axes and a
//! legend, in a fixed axonometric [`View`].
//!
//! The output is deterministic: the same scene and options give the same bytes (page
//! coordinates with one decimal, no maps iterated, no dates).

use crate::sample::{sample, unit, Density, Sampled};
use crate::view::{cross, dot, escape, n1, n2, sub, Frame};
use crate::{Colour, RenderError, Sampling, Scene, View};
use cagd_scalar::Scalar;
use std::fmt::Write;

/// Which parts of a figure to draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Layers {
    /// The surface: shaded cells bounded by isoparametric curves.
    pub surface: bool,
    /// The control meshes, with their vertices marked.
    pub mesh: bool,
    /// The four boundary curves of each surface, thick.
    pub boundary: bool,
    /// Unit normals `c_u x c_v` at a 3 x 3 grid of interior points.
    pub normals: bool,
    /// The curves of the scene (the input curves of a construction) with their polygons.
    pub curves: bool,
    /// The x, y, z axes with their labels.
    pub axes: bool,
}

impl Default for Layers {
    /// Everything but the normals.
    fn default() -> Self {
        Layers {
            surface: true,
            mesh: true,
            boundary: true,
            normals: false,
            curves: true,
            axes: true,
        }
    }
}

/// Options of [`render_svg`].
#[derive(Clone, Debug, PartialEq)]
pub struct SvgOptions {
    /// Width of the picture in pixels.
    pub width: u32,
    /// Height of the picture in pixels (the legend is inside it).
    pub height: u32,
    /// The view angles.
    pub view: View,
    /// What to draw.
    pub layers: Layers,
    /// Isoparametric cells in each direction: `isolines + 1` curves of constant u and as many
    /// of constant v (2 to 64).
    pub isolines: usize,
    /// Exact sample points per cell edge, so each isoparametric curve has
    /// `isolines * samples + 1` points (1 to 16).
    pub samples: usize,
    /// Whether to draw the legend.
    pub legend: bool,
    /// Whether to draw each surface in a panel of its own (the steps of a construction, each
    /// visible alone: the surface, c_c, c_d, c_cd of a Coons patch), each panel
    /// `width x height` with the scene's curves and its own legend, two panels a row, under
    /// the scene's title; a scene of one surface is drawn as one figure.
    pub panels: bool,
}

impl Default for SvgOptions {
    fn default() -> Self {
        SvgOptions {
            width: 640,
            height: 480,
            view: View::default(),
            layers: Layers::default(),
            isolines: 10,
            samples: 3,
            legend: true,
            panels: false,
        }
    }
}

const AXIS: &str = "#555555";
/// The classes of the drawing: cells, boundaries, curves, dashed polygons.
const STYLE: &str = "<style>.c{stroke-width:0.7;stroke-linejoin:round}\
.i{fill:none;stroke-width:0.7;stroke-linejoin:round;stroke-linecap:round}\
.b{fill:none;stroke-width:1.8;stroke-linejoin:round;stroke-linecap:round}\
.k{fill:none;stroke-width:2.6;stroke-linejoin:round;stroke-linecap:round}\
.p{fill:none;stroke-width:1;stroke-dasharray:4 3}</style>\n";
const NORMAL: &str = "#1b7837";
const FONT: &str = "font-family=\"DejaVu Sans, Arial, sans-serif\"";

/// Draws the scene as an SVG document.
///
/// Every point is the exact value of the surface or curve at an exact parameter
/// `a + (b - a) k / n`, converted to f64 only to be drawn. Surfaces are drawn as
/// `isolines x isolines` cells whose edges are isoparametric curves, filled with a shade of
/// the surface's colour by the cosine between the cell's normal and the light, back to front
/// (painter's order), so nearer cells hide farther ones and their lines. Meshes, boundaries,
/// normals and curves are drawn over the surfaces, back to front, farther strokes lighter.
pub fn render_svg<S: Scalar>(
    scene: &Scene<S>,
    options: &SvgOptions,
) -> Result<String, RenderError> {
    crate::error::check_density(Sampling::Isolines, options.isolines, 2, 64)?;
    crate::error::check_density(Sampling::SamplesPerCell, options.samples, 1, 16)?;
    if options.panels && scene.surfaces.len() > 1 {
        return render_panels(scene, options);
    }
    let sampled = sample(
        scene,
        Density {
            cells: (options.isolines, options.isolines),
            sub: options.samples,
            normals: if options.layers.normals { 3 } else { 0 },
            curve_segments: 64,
        },
    )?;
    Ok(Figure::new(&sampled, options).draw())
}

/// The panels of [`SvgOptions::panels`]: one figure for each surface (a faint one stays
/// with every panel), titled with its name, with the scene's curves, in the colours it has
/// in the whole scene, two a row, nested `<svg>` elements under the scene's title.
fn render_panels<S: Scalar>(scene: &Scene<S>, options: &SvgOptions) -> Result<String, RenderError> {
    let mut whole = scene.clone();
    for (k, s) in whole.surfaces.iter_mut().enumerate() {
        s.colour = Some(scene.surface_colour(k));
        s.mesh_colour = Some(scene.mesh_colour(k));
    }
    for (k, c) in whole.curves.iter_mut().enumerate() {
        c.colour = Some(scene.curve_colour(k));
    }
    let faint: Vec<_> = whole.surfaces.iter().filter(|s| s.faint).cloned().collect();
    let panel_options = SvgOptions {
        panels: false,
        ..options.clone()
    };
    let mut panels = Vec::new();
    for s in whole.surfaces.iter().filter(|s| !s.faint) {
        let mut one = Scene {
            title: Some(s.name.clone()),
            surfaces: faint.clone(),
            curves: whole.curves.clone(),
        };
        one.surfaces.push(s.clone());
        panels.push(render_svg(&one, &panel_options)?);
    }
    let (pw, ph) = (options.width, options.height);
    let cols: u32 = if panels.len() > 1 { 2 } else { 1 };
    let rows = u32::try_from(panels.len()).unwrap_or(1).div_ceil(cols);
    let title = scene
        .title
        .as_deref()
        .map(|t| title_lines(t, pw * cols))
        .unwrap_or_default();
    let top = if title.is_empty() {
        0.0
    } else {
        10.0 + TITLE_LINE * title.len() as f64
    };
    let (w, h) = (pw * cols, top as u32 + ph * rows);
    let mut out = String::new();
    let _ = writeln!(
        out,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">"
    );
    let _ = writeln!(out, "<rect width=\"{w}\" height=\"{h}\" fill=\"#ffffff\"/>");
    for (i, line) in title.iter().enumerate() {
        let _ = writeln!(
            out,
            "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-size=\"16\" font-weight=\"bold\" {FONT}>{}</text>",
            n1(f64::from(w) / 2.0),
            n1(20.0 + TITLE_LINE * i as f64),
            escape(line)
        );
    }
    for (k, panel) in panels.iter().enumerate() {
        let k = u32::try_from(k).unwrap_or(0);
        let (x, y) = (pw * (k % cols), top as u32 + ph * (k / cols));
        // the panel's own document, placed: its root element gets its position
        let placed = panel.replacen(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" ",
            &format!("<svg x=\"{x}\" y=\"{y}\" "),
            1,
        );
        out.push_str(&placed);
    }
    out.push_str("</svg>\n");
    Ok(out)
}

/// A projected element to sort back to front.
struct Item {
    depth: f64,
    svg: String,
}

struct Figure<'a> {
    s: &'a Sampled,
    o: &'a SvgOptions,
    /// The view: the options' one, or, for a plane figure under the default view, the plan.
    view: View,
    frame: Frame,
    /// Range of depths, for the depth cue.
    depth: (f64, f64),
    /// Axis ends in space.
    axes: [[f64; 3]; 3],
    /// Size of the scene (largest extent of its bounding box).
    size: f64,
    legend_rows: Vec<Vec<LegendEntry>>,
}

enum LegendEntry {
    Surface {
        name: String,
        colour: Colour,
        mesh: Option<Colour>,
    },
    Curve {
        name: String,
        colour: Colour,
    },
}

impl LegendEntry {
    fn width(&self) -> f64 {
        let (name, swatches) = match self {
            LegendEntry::Surface { name, mesh, .. } => {
                (name, if mesh.is_some() { 40.0 } else { 18.0 })
            }
            LegendEntry::Curve { name, .. } => (name, 24.0),
        };
        swatches + 7.0 * name.chars().count() as f64 + 18.0
    }
}

impl<'a> Figure<'a> {
    fn new(s: &'a Sampled, o: &'a SvgOptions) -> Self {
        let l = &o.layers;
        // curves of the plane z = 0 (and no surface) are drawn as in the plane, x to the
        // right and y up, unless a view was asked for
        let plane = s.surfaces.is_empty() && s.all_points().all(|p| p[2] == 0.0);
        let view = if plane && o.view == View::default() {
            View::new(-90.0, 90.0)
        } else {
            o.view
        };
        let size = s.size().max(1e-9);
        // each axis reaches a little beyond the scene on its positive side
        let [ex, ey, ez] = s.bounds().1.map(|h| h.max(0.0) + 0.2 * size);
        let axes = [[ex, 0.0, 0.0], [0.0, ey, 0.0], [0.0, 0.0, ez]];
        // The legend, wrapped in rows.
        let mut entries = Vec::new();
        for surf in &s.surfaces {
            entries.push(LegendEntry::Surface {
                name: surf.name.clone(),
                colour: surf.colour,
                mesh: (l.mesh && !surf.faint).then_some(surf.mesh_colour),
            });
        }
        if l.curves {
            for c in &s.curves {
                entries.push(LegendEntry::Curve {
                    name: c.name.clone(),
                    colour: c.colour,
                });
            }
        }
        let mut legend_rows: Vec<Vec<LegendEntry>> = Vec::new();
        if o.legend {
            let mut x = 10.0;
            for e in entries {
                let w = e.width();
                match legend_rows.last_mut() {
                    Some(row) if x + w <= f64::from(o.width) - 10.0 => row.push(e),
                    _ => {
                        x = 10.0;
                        legend_rows.push(vec![e]);
                    }
                }
                x += w;
            }
        }
        let title_lines = s
            .title
            .as_deref()
            .map_or(0, |t| title_lines(t, o.width).len());
        let top = if title_lines > 0 {
            26.0 + TITLE_LINE * title_lines as f64
        } else {
            22.0
        };
        let bottom = 18.0 + 20.0 * legend_rows.len() as f64;
        let rect = (
            24.0,
            top,
            f64::from(o.width) - 48.0,
            (f64::from(o.height) - top - bottom).max(10.0),
        );
        let mut drawn: Vec<[f64; 3]> = s.all_points().copied().collect();
        if l.axes {
            drawn.push([0.0; 3]);
            drawn.extend(axes);
        }
        if l.normals {
            for surf in &s.surfaces {
                for (f, n) in &surf.normals {
                    drawn.push(add_scaled(*f, *n, 0.15 * size));
                }
            }
        }
        let projected: Vec<[f64; 3]> = drawn.iter().map(|p| view.project(*p)).collect();
        let frame = Frame::fit(projected.iter().map(|p| (p[0], p[1])), rect);
        let depth = projected
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p[2]), b.max(p[2])));
        Figure {
            s,
            o,
            view,
            frame,
            depth,
            axes,
            size,
            legend_rows,
        }
    }

    /// Page coordinates and depth of a point in space.
    fn page(&self, p: [f64; 3]) -> (f64, f64, f64) {
        let q = self.view.project(p);
        let (x, y) = self.frame.page(q[0], q[1]);
        (x, y, q[2])
    }

    fn xy(&self, p: [f64; 3]) -> String {
        let (x, y, _) = self.page(p);
        format!("{},{}", n1(x), n1(y))
    }

    /// 0 for the farthest depth, 1 for the nearest.
    fn nearness(&self, depth: f64) -> f64 {
        let (a, b) = self.depth;
        if b > a {
            ((depth - a) / (b - a)).clamp(0.0, 1.0)
        } else {
            1.0
        }
    }

    fn draw(&self) -> String {
        let (w, h) = (self.o.width, self.o.height);
        let mut out = String::new();
        let _ = writeln!(
            out,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">"
        );
        out.push_str(STYLE);
        let _ = writeln!(out, "<rect width=\"{w}\" height=\"{h}\" fill=\"#ffffff\"/>");
        if let Some(t) = &self.s.title {
            for (i, line) in title_lines(t, w).iter().enumerate() {
                let _ = writeln!(
                    out,
                    "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\" font-size=\"15\" {FONT}>{}</text>",
                    n1(f64::from(w) / 2.0),
                    n1(20.0 + TITLE_LINE * i as f64),
                    escape(line)
                );
            }
        }
        let l = self.o.layers;
        if l.axes {
            self.draw_axes(&mut out);
        }
        // A faint surface (the original of a restriction) lies under everything else.
        let mut faint = Vec::new();
        if l.surface {
            self.cells(&mut faint, true);
        }
        if l.boundary {
            self.boundaries(&mut faint, true);
        }
        emit_sorted(&mut out, faint);
        // Surfaces, their isolines and boundaries hide each other: one painter's list; the
        // curves over them where no surface hides them.
        let mut items = Vec::new();
        if l.surface {
            self.cells(&mut items, false);
        }
        if l.boundary {
            self.boundaries(&mut items, false);
        }
        emit_sorted(&mut out, items);
        if l.curves {
            self.draw_curves(&mut out);
            self.draw_polygons(&mut out);
        }
        if l.mesh {
            self.draw_meshes(&mut out);
        }
        if l.normals {
            self.draw_normals(&mut out);
        }
        if l.curves {
            self.draw_curve_labels(&mut out);
        }
        if l.axes {
            self.draw_axis_labels(&mut out);
        }
        self.draw_legend(&mut out);
        out.push_str("</svg>\n");
        out
    }

    /// Whether the axis to `end` is seen as a segment (the z axis of a plan is a point).
    fn seen(&self, end: [f64; 3]) -> bool {
        let (ox, oy, _) = self.page([0.0; 3]);
        let (x, y, _) = self.page(end);
        (x - ox).hypot(y - oy) > 1.0
    }

    fn draw_axes(&self, out: &mut String) {
        let _ = writeln!(out, "<g stroke=\"{AXIS}\" stroke-width=\"1\">");
        for e in self.axes.into_iter().filter(|e| self.seen(*e)) {
            let _ = writeln!(
                out,
                "<polyline points=\"{} {}\"/>",
                self.xy([0.0; 3]),
                self.xy(e)
            );
        }
        out.push_str("</g>\n");
    }

    fn draw_axis_labels(&self, out: &mut String) {
        let (ox, oy, _) = self.page([0.0; 3]);
        let _ = writeln!(
            out,
            "<g font-size=\"15\" font-style=\"italic\" fill=\"{AXIS}\" text-anchor=\"middle\" {FONT}>"
        );
        for (e, name) in self
            .axes
            .iter()
            .zip(["x", "y", "z"])
            .filter(|(e, _)| self.seen(**e) && !self.hidden(**e))
        {
            let (x, y, _) = self.page(*e);
            let (dx, dy) = (x - ox, y - oy);
            let len = (dx * dx + dy * dy).sqrt().max(1e-9);
            let (lx, ly) = (x + 11.0 * dx / len, y + 11.0 * dy / len + 5.0);
            let _ = writeln!(out, "<text x=\"{}\" y=\"{}\">{name}</text>", n1(lx), n1(ly));
        }
        out.push_str("</g>\n");
    }

    /// Every cell of every surface (faint or not, as asked), shaded by the cosine between its
    /// normal and the light (both sides lit; the back side greyer), bounded by its
    /// isoparametric curves. A cell on the silhouette (its facets, the steps of the fine grid,
    /// face the eye and away from it) is drawn facet by facet, each shaded by its own normal
    /// and stroked with its fill so that facets meet without seams, its border drawn a segment
    /// at a time among them: the outline is the fine grid's and no back face of the cell pokes
    /// out of it.
    fn cells(&self, items: &mut Vec<Item>, faint: bool) {
        let light = self.view.light();
        let toward = self.view.basis()[2];
        for surf in self.s.surfaces.iter().filter(|s| s.faint == faint) {
            let g = &surf.grid;
            let k = surf.sub.max(1);
            let darken = if faint { 0.2 } else { 0.55 };
            let line = surf.colour.mix(Colour::BLACK, darken).hex();
            let back = surf.colour.mix(Colour::rgb(0xb0, 0xb0, 0xb0), 0.5);
            let shade_of = |corners: [[f64; 3]; 4]| {
                let [p00, p01, p10, p11] = corners;
                let n = unit(cross(sub(p11, p00), sub(p01, p10)))?;
                let front = dot(n, toward) >= 0.0;
                Some((front, dot(n, light).abs()))
            };
            let fill_of = |shade: Option<(bool, f64)>| match shade {
                Some((front, lit)) => {
                    let base = if front { surf.colour } else { back };
                    let strength = if faint { 0.15 } else { 0.5 };
                    base.mix(Colour::BLACK, strength * (1.0 - lit))
                }
                None => surf.colour,
            };
            for ci in 0..surf.cells.0 {
                for cj in 0..surf.cells.1 {
                    // the grid has `cells * sub + 1` points each way, so every cell is there
                    let Some(Cell { ring, corners }) = Cell::of(g, ci * k, cj * k, k) else {
                        continue;
                    };
                    let facets = facets(g, ci * k, cj * k, k);
                    let sides: Vec<bool> = facets
                        .iter()
                        .filter_map(|f| shade_of(*f).map(|(front, _)| front))
                        .collect();
                    let silhouette = sides.iter().any(|f| *f) && sides.iter().any(|f| !*f);
                    if silhouette {
                        for f in facets {
                            let [p00, p01, p10, p11] = f;
                            let quad = [p00, p01, p11, p10];
                            let depth = quad.iter().map(|p| self.page(*p).2).sum::<f64>() / 4.0;
                            let pts: Vec<String> = quad.iter().map(|p| self.xy(*p)).collect();
                            let fill = fill_of(shade_of(f)).hex();
                            items.push(Item {
                                depth,
                                svg: format!(
                                    "<path class=\"c\" d=\"M{}Z\" fill=\"{fill}\" stroke=\"{fill}\"/>",
                                    pts.join(" "),
                                ),
                            });
                        }
                        let mut closed = ring.clone();
                        closed.extend(ring.first().copied());
                        self.pieces(items, &closed, 1, "i", &line);
                        continue;
                    }
                    let depth = corners.iter().map(|p| self.page(*p).2).sum::<f64>() / 4.0;
                    let pts: Vec<String> = ring.iter().map(|p| self.xy(*p)).collect();
                    items.push(Item {
                        depth,
                        svg: format!(
                            "<path class=\"c\" d=\"M{}Z\" fill=\"{}\" stroke=\"{line}\"/>",
                            pts.join(" "),
                            fill_of(shade_of(corners)).hex(),
                        ),
                    });
                }
            }
        }
    }

    fn polyline(&self, pts: &[[f64; 3]]) -> String {
        pts.iter()
            .map(|p| self.xy(*p))
            .collect::<Vec<_>>()
            .join(" ")
    }

    /// A polyline lying on a surface, cut into pieces of `piece` segments that take part in
    /// the painter's order, brought slightly forward so that the cells they bound do not hide
    /// them.
    fn pieces(
        &self,
        items: &mut Vec<Item>,
        pts: &[[f64; 3]],
        piece: usize,
        class: &str,
        colour: &str,
    ) {
        let bias = 0.02 * self.size;
        for run in runs(pts, piece) {
            let Some((first, rest)) = run.split_first() else {
                continue;
            };
            if rest.iter().all(|p| p == first) {
                // a collapsed border (the pole of the sphere octant) draws nothing
                continue;
            }
            let depth = run.iter().map(|p| self.page(*p).2).sum::<f64>() / run.len() as f64;
            items.push(Item {
                depth: depth + bias,
                svg: format!(
                    "<polyline class=\"{class}\" points=\"{}\" stroke=\"{colour}\"/>",
                    self.polyline(run)
                ),
            });
        }
    }

    fn boundaries(&self, items: &mut Vec<Item>, faint: bool) {
        for surf in self.s.surfaces.iter().filter(|s| s.faint == faint) {
            let darken = if faint { 0.3 } else { 0.6 };
            let colour = surf.colour.mix(Colour::BLACK, darken).hex();
            for b in surf.boundaries() {
                self.pieces(items, &b, surf.sub, "b", &colour);
            }
        }
    }

    /// The curves, thick, where no surface hides them: a segment is drawn when its middle is
    /// seen ([`Figure::hidden`]), so a curve on a surface (a Coons patch's boundary, the
    /// profile of a revolution on its meridian) is drawn whole where the surface faces the
    /// eye, and a curve behind a surface is cut where the surface covers it.
    fn draw_curves(&self, out: &mut String) {
        for c in &self.s.curves {
            let colour = c.colour.hex();
            let mut run: Vec<[f64; 3]> = Vec::new();
            let flush = |run: &mut Vec<[f64; 3]>, out: &mut String| {
                if run.len() > 1 {
                    let _ = writeln!(
                        out,
                        "<polyline class=\"k\" points=\"{}\" stroke=\"{colour}\"/>",
                        self.polyline(run)
                    );
                }
                run.clear();
            };
            for (p, q) in c.points.iter().zip(c.points.iter().skip(1)) {
                let middle = add_scaled(*p, sub(*q, *p), 0.5);
                if self.hidden(middle) {
                    flush(&mut run, out);
                    continue;
                }
                if run.is_empty() {
                    run.push(*p);
                }
                run.push(*q);
            }
            flush(&mut run, out);
        }
    }

    /// The control polygons of the curves, dashed, with their vertices.
    fn draw_polygons(&self, out: &mut String) {
        for c in &self.s.curves {
            let col = c.colour.hex();
            let _ = writeln!(
                out,
                "<polyline class=\"p\" points=\"{}\" stroke=\"{col}\"/>",
                self.polyline(&c.polygon)
            );
            for p in &c.polygon {
                let (x, y, _) = self.page(*p);
                let _ = writeln!(
                    out,
                    "<rect x=\"{}\" y=\"{}\" width=\"5\" height=\"5\" fill=\"{col}\"/>",
                    n1(x - 2.5),
                    n1(y - 2.5)
                );
            }
        }
    }

    /// The name of each curve next to a point of it that no surface hides: the visible
    /// point nearest to its middle (the middle first, then alternately after and before it);
    /// no label when the whole curve is hidden (the legend still names it).
    fn draw_curve_labels(&self, out: &mut String) {
        for c in &self.s.curves {
            let mid = c.points.len() / 2;
            let order = (0..c.points.len()).map(|k| {
                if k % 2 == 0 {
                    mid + k / 2
                } else {
                    mid.wrapping_sub(k / 2 + 1)
                }
            });
            let Some(at) = order
                .filter_map(|k| c.points.get(k))
                .find(|p| !self.hidden(**p))
            else {
                continue;
            };
            let (x, y, _) = self.page(*at);
            let _ = writeln!(
                out,
                "<text x=\"{}\" y=\"{}\" font-size=\"13\" font-weight=\"bold\" fill=\"{}\" stroke=\"#ffffff\" stroke-width=\"3\" paint-order=\"stroke\" {FONT}>{}</text>",
                n1(x + 6.0),
                n1(y - 6.0),
                c.colour.hex(),
                escape(&c.name)
            );
        }
    }

    /// Whether a surface drawn (not a faint one) hides the point: some facet covers it on the
    /// page and is nearer than it by more than the bias that lets a curve on a surface show
    /// (its depth at the point interpolated on one of the facet's two triangles).
    fn hidden(&self, p: [f64; 3]) -> bool {
        if !self.o.layers.surface {
            return false;
        }
        let (x, y, d) = self.page(p);
        let bias = 0.02 * self.size;
        self.s.surfaces.iter().filter(|s| !s.faint).any(|surf| {
            let g = &surf.grid;
            g.iter().zip(g.iter().skip(1)).any(|(row, next)| {
                row.iter()
                    .zip(row.iter().skip(1))
                    .zip(next.iter().zip(next.iter().skip(1)))
                    .any(|((p00, p01), (p10, p11))| {
                        let [a, b, c, e] = [p00, p01, p11, p10].map(|q| self.page(*q));
                        [[a, b, c], [a, c, e]]
                            .iter()
                            .any(|t| depth_at(t, x, y).is_some_and(|front| front > d + bias))
                    })
            })
        })
    }

    /// The control meshes: edges and vertices back to front, farther ones lighter.
    fn draw_meshes(&self, out: &mut String) {
        let mut items = Vec::new();
        for surf in self.s.surfaces.iter().filter(|s| !s.faint) {
            let col = surf.mesh_colour.hex();
            let net = &surf.net;
            let mut edges = Vec::new();
            for (i, row) in net.iter().enumerate() {
                for (j, p) in row.iter().enumerate() {
                    if let Some(q) = row.get(j + 1) {
                        edges.push((*p, *q));
                    }
                    if let Some(q) = net.get(i + 1).and_then(|r| r.get(j)) {
                        edges.push((*p, *q));
                    }
                }
            }
            for (p, q) in edges.into_iter().filter(|(p, q)| p != q) {
                let depth = (self.page(p).2 + self.page(q).2) / 2.0;
                items.push(Item {
                    depth,
                    svg: format!(
                        "<polyline points=\"{} {}\" stroke=\"{col}\" stroke-opacity=\"{}\"/>",
                        self.xy(p),
                        self.xy(q),
                        n2(0.35 + 0.65 * self.nearness(depth))
                    ),
                });
            }
            let mut seen: Vec<[f64; 3]> = Vec::new();
            for p in net.iter().flatten() {
                if seen.contains(p) {
                    continue;
                }
                seen.push(*p);
                let (x, y, depth) = self.page(*p);
                items.push(Item {
                    // vertices after the edges that end at them
                    depth: depth + 1e-9 * self.size,
                    svg: format!(
                        "<circle cx=\"{}\" cy=\"{}\" r=\"3\" fill=\"{col}\" fill-opacity=\"{}\"/>",
                        n1(x),
                        n1(y),
                        n2(0.45 + 0.55 * self.nearness(depth))
                    ),
                });
            }
        }
        let _ = writeln!(
            out,
            "<g stroke-width=\"1.2\" stroke-linecap=\"round\" fill=\"none\">"
        );
        emit_sorted(out, items);
        out.push_str("</g>\n");
    }

    fn draw_normals(&self, out: &mut String) {
        let _ = writeln!(
            out,
            "<g stroke=\"{NORMAL}\" stroke-width=\"1.4\" fill=\"none\" stroke-linecap=\"round\">"
        );
        let len = 0.15 * self.size;
        for surf in &self.s.surfaces {
            for (foot, n) in &surf.normals {
                let tip = add_scaled(*foot, *n, len);
                let (fx, fy, _) = self.page(*foot);
                let (tx, ty, _) = self.page(tip);
                let (dx, dy) = (tx - fx, ty - fy);
                let l = (dx * dx + dy * dy).sqrt();
                if l < 2.0 {
                    // seen end-on: a dot
                    let _ = writeln!(out, "<circle cx=\"{}\" cy=\"{}\" r=\"2\"/>", n1(fx), n1(fy));
                    continue;
                }
                let (ux, uy) = (dx / l, dy / l);
                let head = |s: f64| {
                    let (c, sn) = (0.906, 0.423 * s); // cos, sin of 25°
                    (tx - 7.0 * (c * ux - sn * uy), ty - 7.0 * (sn * ux + c * uy))
                };
                let (ax, ay) = head(1.0);
                let (bx, by) = head(-1.0);
                let _ = writeln!(
                    out,
                    "<polyline points=\"{},{} {},{}\"/><polyline points=\"{},{} {},{} {},{}\"/>",
                    n1(fx),
                    n1(fy),
                    n1(tx),
                    n1(ty),
                    n1(ax),
                    n1(ay),
                    n1(tx),
                    n1(ty),
                    n1(bx),
                    n1(by)
                );
            }
        }
        out.push_str("</g>\n");
    }

    fn draw_legend(&self, out: &mut String) {
        if self.legend_rows.is_empty() {
            return;
        }
        let h = f64::from(self.o.height);
        let n = self.legend_rows.len() as f64;
        let _ = writeln!(out, "<g font-size=\"12\" {FONT}>");
        for (r, row) in self.legend_rows.iter().enumerate() {
            let y = h - 10.0 - 20.0 * (n - 1.0 - r as f64);
            let mut x = 10.0;
            for e in row {
                match e {
                    LegendEntry::Surface { name, colour, mesh } => {
                        let _ = writeln!(
                            out,
                            "<rect x=\"{}\" y=\"{}\" width=\"14\" height=\"12\" fill=\"{}\" stroke=\"{}\"/>",
                            n1(x),
                            n1(y - 10.0),
                            colour.hex(),
                            colour.mix(Colour::BLACK, 0.55).hex()
                        );
                        let mut tx = x + 18.0;
                        if let Some(m) = mesh {
                            let _ = writeln!(
                                out,
                                "<polyline points=\"{},{} {},{}\" stroke=\"{}\" stroke-width=\"1.2\"/><circle cx=\"{}\" cy=\"{}\" r=\"3\" fill=\"{}\"/>",
                                n1(tx),
                                n1(y - 4.0),
                                n1(tx + 18.0),
                                n1(y - 4.0),
                                m.hex(),
                                n1(tx + 9.0),
                                n1(y - 4.0),
                                m.hex()
                            );
                            tx += 22.0;
                        }
                        let _ = writeln!(
                            out,
                            "<text x=\"{}\" y=\"{}\">{}</text>",
                            n1(tx),
                            n1(y),
                            escape(name)
                        );
                    }
                    LegendEntry::Curve { name, colour } => {
                        let _ = writeln!(
                            out,
                            "<polyline points=\"{},{} {},{}\" stroke=\"{}\" stroke-width=\"2.4\"/><text x=\"{}\" y=\"{}\">{}</text>",
                            n1(x),
                            n1(y - 4.0),
                            n1(x + 20.0),
                            n1(y - 4.0),
                            colour.hex(),
                            n1(x + 24.0),
                            n1(y),
                            escape(name)
                        );
                    }
                }
                x += e.width();
            }
        }
        out.push_str("</g>\n");
    }
}

/// One cell of a sampled grid: the `4 k` points around it (along the first row, down the last
/// column, back along the last row, up the first column) and its corners
/// `[g(i, j), g(i, j + k), g(i + k, j), g(i + k, j + k)]`.
struct Cell {
    ring: Vec<[f64; 3]>,
    corners: [[f64; 3]; 4],
}

impl Cell {
    /// The cell of `k x k` grid steps whose first corner is `grid[i][j]`; `None` if the grid
    /// does not reach that far.
    fn of(grid: &[Vec<[f64; 3]>], i: usize, j: usize, k: usize) -> Option<Cell> {
        // the k + 1 rows of the cell, each cut to its k + 1 columns
        let block = grid
            .get(i..=i + k)?
            .iter()
            .map(|row| row.get(j..=j + k))
            .collect::<Option<Vec<_>>>()?;
        let (top, bottom) = (block.first()?, block.last()?);
        let mut ring = Vec::with_capacity(4 * k);
        ring.extend(top.iter().take(k));
        ring.extend(block.iter().take(k).filter_map(|row| row.last()));
        ring.extend(bottom.iter().rev().take(k));
        ring.extend(block.iter().rev().take(k).filter_map(|row| row.first()));
        let corners = [
            *top.first()?,
            *top.last()?,
            *bottom.first()?,
            *bottom.last()?,
        ];
        Some(Cell { ring, corners })
    }
}

/// The `k x k` facets of the cell whose first corner is `grid[i][j]`, each as its corners
/// `[g(a, b), g(a, b + 1), g(a + 1, b), g(a + 1, b + 1)]` (those the grid reaches).
fn facets(grid: &[Vec<[f64; 3]>], i: usize, j: usize, k: usize) -> Vec<[[f64; 3]; 4]> {
    let mut out = Vec::with_capacity(k * k);
    for a in i..i + k {
        for b in j..j + k {
            let at = |r: usize, c: usize| grid.get(r).and_then(|row| row.get(c)).copied();
            if let (Some(p00), Some(p01), Some(p10), Some(p11)) =
                (at(a, b), at(a, b + 1), at(a + 1, b), at(a + 1, b + 1))
            {
                out.push([p00, p01, p10, p11]);
            }
        }
    }
    out
}

/// A polyline cut into runs of `piece` segments (`piece + 1` points, the last run shorter;
/// at least one segment), each run starting where the previous one ends.
fn runs(pts: &[[f64; 3]], piece: usize) -> impl Iterator<Item = &[[f64; 3]]> {
    let mut rest = pts;
    std::iter::from_fn(move || {
        if rest.len() < 2 {
            return None;
        }
        let run = rest.get(..=piece.max(1)).unwrap_or(rest);
        rest = rest.get(run.len() - 1..).unwrap_or_default();
        Some(run)
    })
}

/// The depth at page point (x, y) of a projected triangle (page x, page y, depth), by
/// barycentric interpolation; `None` when the point is outside it or it is seen edge-on.
fn depth_at(t: &[(f64, f64, f64); 3], x: f64, y: f64) -> Option<f64> {
    let [(x0, y0, d0), (x1, y1, d1), (x2, y2, d2)] = *t;
    let det = (y1 - y2) * (x0 - x2) + (x2 - x1) * (y0 - y2);
    if det.abs() < 1e-12 {
        return None;
    }
    let l0 = ((y1 - y2) * (x - x2) + (x2 - x1) * (y - y2)) / det;
    let l1 = ((y2 - y0) * (x - x2) + (x0 - x2) * (y - y2)) / det;
    let l2 = 1.0 - l0 - l1;
    let inside = [l0, l1, l2].iter().all(|l| *l >= -1e-9);
    inside.then_some(l0 * d0 + l1 * d1 + l2 * d2)
}

fn add_scaled(p: [f64; 3], d: [f64; 3], t: f64) -> [f64; 3] {
    [p[0] + t * d[0], p[1] + t * d[1], p[2] + t * d[2]]
}

/// Writes the items from the farthest to the nearest; ties keep their order.
fn emit_sorted(out: &mut String, mut items: Vec<Item>) {
    items.sort_by(|a, b| a.depth.total_cmp(&b.depth));
    for it in items {
        out.push_str(&it.svg);
        out.push('\n');
    }
}

/// The height of a line of the title, in pixels (font size 15).
const TITLE_LINE: f64 = 18.0;

/// The title as it is drawn: `^2` written as a superscript (u² for the `u^2` of a problem's
/// title), broken between words into lines of the figure's width (about 8 pixels a
/// character at font size 15), so that a long title is never cut at the edges.
fn title_lines(title: &str, width: u32) -> Vec<String> {
    let mut text = String::with_capacity(title.len());
    let mut chars = title.chars().peekable();
    while let Some(c) = chars.next() {
        match (c, chars.peek().and_then(|d| superscript(*d))) {
            ('^', Some(_)) => {
                while let Some(s) = chars.peek().and_then(|d| superscript(*d)) {
                    text.push(s);
                    chars.next();
                }
            }
            _ => text.push(c),
        }
    }
    let fits = ((f64::from(width) - 20.0) / 8.0).max(10.0) as usize;
    let mut lines: Vec<String> = Vec::new();
    for word in text.split_whitespace() {
        match lines.last_mut() {
            Some(line) if line.chars().count() + 1 + word.chars().count() <= fits => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines
}

/// The superscript form of a digit.
fn superscript(d: char) -> Option<char> {
    "⁰¹²³⁴⁵⁶⁷⁸⁹".chars().nth(d.to_digit(10)? as usize)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64) -> [f64; 3] {
        [x, 0.0, 0.0]
    }

    fn xs(run: &[[f64; 3]]) -> Vec<f64> {
        run.iter().map(|q| q[0]).collect()
    }

    #[test]
    fn runs_share_their_ends_and_the_last_is_shorter() {
        let pts: Vec<_> = (0..6).map(|k| p(f64::from(k))).collect();
        let cut: Vec<Vec<f64>> = runs(&pts, 2).map(xs).collect();
        assert_eq!(
            cut,
            [vec![0.0, 1.0, 2.0], vec![2.0, 3.0, 4.0], vec![4.0, 5.0]]
        );
        // one segment at a time, also for 0 (which would never advance)
        assert_eq!(runs(&pts, 0).count(), 5);
        assert_eq!(runs(&pts, 9).map(xs).collect::<Vec<_>>(), [xs(&pts)]);
        assert_eq!(runs(&pts[..1], 2).count(), 0);
    }

    #[test]
    fn a_long_title_is_broken_into_lines_and_its_powers_are_superscripts() {
        let t = "Continuity of two B-spline surfaces along a border, piece by piece: the two halves of z = u^2 + v^10";
        let lines = title_lines(t, 480);
        assert!(lines.len() >= 2, "{lines:?}");
        assert!(lines.iter().all(|l| l.chars().count() <= 58), "{lines:?}");
        assert_eq!(
            lines.join(" "),
            t.replace("u^2", "u²").replace("v^10", "v¹⁰")
        );
        assert_eq!(title_lines("x ^ y^a", 480), vec!["x ^ y^a".to_string()]);
    }
}
