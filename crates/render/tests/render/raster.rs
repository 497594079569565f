//! Rasterized checks: the SVG is rendered to pixels with resvg, saved as PNG under the
//! system's temporary folder (to look at), and checked for content.

use crate::debug_out::out_dir;
use crate::scenes;
use cagd_render::{render_svg, Colour, SvgOptions, MESH_PALETTE, SURFACE_PALETTE};

/// Renders an SVG to RGBA pixels (width, height, data).
pub fn rasterize(svg: &str) -> resvg::tiny_skia::Pixmap {
    let mut opt = resvg::usvg::Options::default();
    opt.fontdb_mut().load_system_fonts();
    let tree = resvg::usvg::Tree::from_str(svg, &opt).expect("the SVG parses");
    let size = tree.size().to_int_size();
    let mut pixmap = resvg::tiny_skia::Pixmap::new(size.width(), size.height()).unwrap();
    resvg::render(
        &tree,
        resvg::tiny_skia::Transform::default(),
        &mut pixmap.as_mut(),
    );
    pixmap
}

/// Pixels within `tol` (per channel) of a colour.
fn count_near(p: &resvg::tiny_skia::Pixmap, c: Colour, tol: u8) -> usize {
    p.pixels()
        .iter()
        .filter(|px| {
            let d = |a: u8, b: u8| a.abs_diff(b) <= tol;
            px.alpha() == 255 && d(px.red(), c.r) && d(px.green(), c.g) && d(px.blue(), c.b)
        })
        .count()
}

fn non_white(p: &resvg::tiny_skia::Pixmap) -> usize {
    p.pixels()
        .iter()
        .filter(|px| px.red() < 245 || px.green() < 245 || px.blue() < 245)
        .count()
}

/// Hue-ish test: pixels that are "surface-like": bluish (b clearly above r).
fn bluish(p: &resvg::tiny_skia::Pixmap) -> usize {
    p.pixels()
        .iter()
        .filter(|px| u16::from(px.blue()) > u16::from(px.red()) + 40)
        .count()
}

fn check(name: &str, svg: &str) {
    let pixmap = rasterize(svg);
    pixmap
        .save_png(out_dir().join(format!("{name}.png")))
        .unwrap();
    let total = pixmap.pixels().len();
    let drawn = non_white(&pixmap);
    assert!(
        drawn > total / 20,
        "{name}: only {drawn} of {total} pixels drawn"
    );
    let mesh = count_near(&pixmap, MESH_PALETTE[0], 30);
    assert!(mesh > 150, "{name}: only {mesh} mesh-coloured pixels");
    let surface = bluish(&pixmap);
    assert!(
        surface > total / 30,
        "{name}: only {surface} surface-coloured pixels"
    );
    let _ = SURFACE_PALETTE;
}

#[test]
fn sphere_octant_png_shows_surface_and_mesh() {
    check(
        "sphere",
        &render_svg(&scenes::sphere_scene(), &SvgOptions::default()).unwrap(),
    );
}

#[test]
fn coons_png_shows_surface_and_mesh() {
    check(
        "coons",
        &render_svg(&scenes::coons_scene(), &SvgOptions::default()).unwrap(),
    );
}
