//! Snapshot tests: the SVG of the notes' figures, pinned in the top-level `snapshots/` folder
//! (`cargo insta review`, or `INSTA_UPDATE=always` and `git diff snapshots/`).

use crate::scenes;
use cagd_poly::{parse_poly, Var};
use cagd_render::{plot_polynomial, render_svg, PlotOptions, SvgOptions};
use cagd_scalar::{q, BigRational};

fn settings() -> insta::Settings {
    let mut s = insta::Settings::clone_current();
    // relative to this file: crates/render/tests/render/ -> the workspace's snapshots/
    s.set_snapshot_path("../../../../snapshots");
    s.set_prepend_module_to_snapshot(false);
    s
}

/// A figure stays small: whole cells off the silhouette, facets only on it.
fn small(svg: &str) {
    assert!(svg.len() < 100_000, "the SVG has {} bytes", svg.len());
}

#[test]
fn coons_svg() {
    let svg = render_svg(&scenes::coons_scene(), &SvgOptions::default()).unwrap();
    small(&svg);
    settings().bind(|| insta::assert_snapshot!("render__coons_svg", svg));
}

#[test]
fn sphere_octant_svg() {
    let svg = render_svg(&scenes::sphere_scene(), &SvgOptions::default()).unwrap();
    small(&svg);
    settings().bind(|| insta::assert_snapshot!("render__sphere_octant_svg", svg));
}

#[test]
fn ruled_non_developable_svg() {
    let svg = render_svg(&scenes::ruled_scene(), &SvgOptions::default()).unwrap();
    small(&svg);
    settings().bind(|| insta::assert_snapshot!("render__ruled_non_developable_svg", svg));
}

#[test]
fn c1_pair_svg() {
    let svg = render_svg(&scenes::c1_scene(), &SvgOptions::default()).unwrap();
    small(&svg);
    // two colours: blue and orange cells, red and violet meshes
    assert!(svg.contains("<rect x=\"10.0\"") && svg.matches("<text").count() >= 5);
    settings().bind(|| insta::assert_snapshot!("render__c1_pair_svg", svg));
}

#[test]
fn developability_plot_svg() {
    let p = parse_poly::<BigRational>("12 u - 8 u^3 - 4 u^2").unwrap();
    let svg = plot_polynomial(&p, Var::U, (q!(0), q!(1)), &PlotOptions::default()).unwrap();
    small(&svg);
    settings().bind(|| insta::assert_snapshot!("render__developability_plot_svg", svg));
}
