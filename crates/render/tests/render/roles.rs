//! The roles of a figure: each drawn in a colour of its own that its legend shows, labels at
//! visible points, the steps of a construction in panels, a restriction inside its original,
//! a problem in letters drawn at its values or refused.

use crate::scenes::{self, pt};
use cagd_render::{render_svg, Legend, RenderError, Scene, SvgOptions};
use cagd_scalar::BigRational;
use cagd_surface::BezierSurface;
use cagd_words::{Lang, Message};
use serde_json::Value;

fn fixture(path: &str) -> Value {
    let p = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../fixtures")
        .join(path);
    serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
}

/// The entries of a figure's legend (the last `<g font-size="12"` group): (name, colours of
/// its swatches), in order.
fn legend(svg: &str) -> Vec<(String, Vec<String>)> {
    let start = svg.rfind("<g font-size=\"12\"").expect("a legend");
    let group = &svg[start..svg[start..].find("</g>").unwrap() + start];
    let mut entries = Vec::new();
    let mut colours = Vec::new();
    for line in group.lines().skip(1) {
        for attr in ["fill=\"#", "stroke=\"#"] {
            let mut rest = line;
            while let Some(i) = rest.find(attr) {
                let c = &rest[i + attr.len() - 1..i + attr.len() + 6];
                // the legend's surface swatch has a darker outline: only its fill
                if !(attr.starts_with("stroke") && line.starts_with("<rect")) {
                    colours.push(c.to_string());
                }
                rest = &rest[i + attr.len()..];
            }
        }
        if let Some(i) = line.find("<text") {
            let text = &line[i..];
            let name = &text[text.find('>').unwrap() + 1..text.find("</text>").unwrap()];
            colours.dedup();
            entries.push((name.to_string(), std::mem::take(&mut colours)));
        }
    }
    entries
}

/// The figure without its legend.
fn drawing(svg: &str) -> &str {
    &svg[..svg.rfind("<g font-size=\"12\"").unwrap()]
}

#[test]
fn the_legend_lists_exactly_the_roles_drawn_in_their_colours() {
    let problem = fixture("ch6/07-coons-bezier.json");
    let answer = cagd_problem::solve(&problem).unwrap();
    let scene = Scene::from_answer(&answer, false).unwrap();
    let svg = render_svg(&scene, &SvgOptions::default()).unwrap();
    let entries = legend(&svg);
    let names: Vec<&str> = entries.iter().map(|(n, _)| n.as_str()).collect();
    assert_eq!(names, ["surface", "c1", "c2", "d1", "d2"]);
    // the surface: its fill and its mesh; each curve: its stroke
    let (surface, mesh) = (scene.surface_colour(0).hex(), scene.mesh_colour(0).hex());
    assert_eq!(entries[0].1, [surface.clone(), mesh.clone()]);
    for (k, (name, colours)) in entries.iter().enumerate().skip(1) {
        assert_eq!(colours, &[scene.curve_colour(k - 1).hex()], "{name}");
    }
    // every colour of the legend is drawn in its role, and every role's colour is another
    let body = drawing(&svg);
    let drawn_as = |start: &str, colour: &str| {
        body.lines()
            .any(|l| l.starts_with(start) && l.contains(&format!("=\"{colour}\"")))
    };
    assert!(drawn_as("<circle cx=", &mesh), "the mesh's vertices");
    for k in 0..4 {
        let c = scene.curve_colour(k).hex();
        assert!(drawn_as("<polyline class=\"k\"", &c), "curve {k}");
    }
    let mut all: Vec<String> = entries.iter().flat_map(|(_, c)| c.clone()).collect();
    let n = all.len();
    all.sort();
    all.dedup();
    assert_eq!(all.len(), n, "a colour shared by two roles: {entries:?}");
}

#[test]
fn the_steps_of_a_coons_patch_have_colours_of_their_own_and_a_panel_each() {
    let problem = fixture("ch6/07-coons-bezier.json");
    let settings = cagd_problem::Settings {
        steps: true,
        ..Default::default()
    };
    let read = cagd_problem::Problem::read(&problem, &settings.limits).unwrap();
    let answer = cagd_problem::solve_problem(&std::sync::Arc::new(read), &settings).unwrap();
    let scene = Scene::from_answer(&answer, true).unwrap();
    // 4 surfaces, 4 meshes, 4 curves: 12 colours, all distinct
    let mut colours: Vec<String> = (0..4)
        .flat_map(|k| [scene.surface_colour(k).hex(), scene.mesh_colour(k).hex()])
        .chain((0..4).map(|k| scene.curve_colour(k).hex()))
        .collect();
    colours.sort();
    colours.dedup();
    assert_eq!(colours.len(), 12, "{colours:?}");
    let options = SvgOptions {
        panels: true,
        ..SvgOptions::default()
    };
    let svg = render_svg(&scene, &options).unwrap();
    // one panel per step, each titled by it, its legend the step and the four curves
    assert_eq!(svg.matches("<svg ").count(), 5);
    for (k, name) in ["surface", "c_c", "c_d", "c_cd"].iter().enumerate() {
        let start = svg.find(&format!(">{name}</text>")).unwrap();
        let panel = &svg[start..start + svg[start..].find("</svg>").unwrap()];
        let entries = legend(panel);
        let names: Vec<&str> = entries.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(names, [*name, "c1", "c2", "d1", "d2"]);
        assert_eq!(entries[0].1[0], scene.surface_colour(k).hex());
    }
    crate::debug_out::save("look-coons-step-panels", &svg);
}

/// A plane z = 0 over [-2, 2]² and two segments, one above it, one below it.
fn plane_with_a_curve_above_and_below() -> Scene<BigRational> {
    let plane = BezierSurface::<BigRational>::from_rows(vec![
        vec![pt(&["-2", "-2", "0"]), pt(&["-2", "2", "0"])],
        vec![pt(&["2", "-2", "0"]), pt(&["2", "2", "0"])],
    ])
    .unwrap();
    let mut scene = Scene::new();
    scene.add_surface("plane", plane);
    scene.add_curve(
        "above",
        scenes::curve(&[["-1/2", "0", "1/2"], ["1/2", "0", "1/2"]]),
    );
    scene.add_curve(
        "below",
        scenes::curve(&[["-1/2", "0", "-1/2"], ["1/2", "0", "-1/2"]]),
    );
    scene
}

#[test]
fn a_label_is_never_painted_over_a_hidden_curve() {
    // seen from above (elevation 25°), the curve under the plane is hidden: no label; the
    // legend still names it
    let scene = plane_with_a_curve_above_and_below();
    let svg = render_svg(&scene, &SvgOptions::default()).unwrap();
    assert!(drawing(&svg).contains(">above</text>"));
    assert!(!drawing(&svg).contains(">below</text>"));
    assert!(legend(&svg).iter().any(|(n, _)| n == "below"));
    // seen from below, the other way round
    let mut options = SvgOptions::default();
    options.view.elevation = -25.0;
    let svg = render_svg(&scene, &options).unwrap();
    assert!(drawing(&svg).contains(">below</text>"));
    assert!(!drawing(&svg).contains(">above</text>"));
    // without the surface layer nothing hides them
    options.layers.surface = false;
    let svg = render_svg(&scene, &options).unwrap();
    assert!(drawing(&svg).contains(">above</text>") && drawing(&svg).contains(">below</text>"));
}

/// The page y of the label `name` in a figure.
fn label_y(svg: &str, name: &str) -> f64 {
    let at = drawing(svg).find(&format!(">{name}</text>")).unwrap();
    let tag = &svg[svg[..at].rfind("<text").unwrap()..at];
    tag.split(" y=\"")
        .nth(1)
        .unwrap()
        .split('"')
        .next()
        .unwrap()
        .parse()
        .unwrap()
}

#[test]
fn a_label_goes_to_a_visible_point_of_a_half_hidden_curve() {
    // a vertical segment through the plane, its middle under it: the label moves up the
    // segment to where it comes out of the plane (page y grows downwards)
    let mut scene = plane_with_a_curve_above_and_below();
    scene.curves.clear();
    scene.add_curve(
        "through",
        scenes::curve(&[["0", "0", "-1"], ["0", "0", "-3/8"], ["0", "0", "1/4"]]),
    );
    let svg = render_svg(&scene, &SvgOptions::default()).unwrap();
    // the same frame without the surface drawn: the label at the middle
    let mut options = SvgOptions::default();
    options.layers.surface = false;
    let bare = render_svg(&scene, &options).unwrap();
    assert!(label_y(&svg, "through") < label_y(&bare, "through") - 10.0);
}

#[test]
fn a_restriction_is_drawn_inside_its_faint_original() {
    let problem = fixture("ch5/04-restriction.json");
    let answer = cagd_problem::solve(&problem).unwrap();
    let scene = Scene::from_answer(&answer, false).unwrap();
    let kinds: Vec<(&str, bool)> = scene
        .surfaces
        .iter()
        .map(|s| (s.name.as_str(), s.faint))
        .collect();
    assert_eq!(kinds, [("surface", false), ("surface (original)", true)]);
    assert!(matches!(scene.surfaces[1].legend, Legend::Original(_)));
    let svg = render_svg(&scene, &SvgOptions::default()).unwrap();
    // the original without its mesh in the legend; the restricted patch with its mesh
    let entries = legend(&svg);
    assert_eq!(entries.len(), 2);
    assert_eq!(entries[0].1.len(), 2);
    assert_eq!(entries[1].1, [cagd_render::ORIGINAL.hex()]);
    crate::debug_out::save("look-restriction", &svg);
}

#[test]
fn a_problem_in_letters_is_drawn_at_its_values_or_refused_asking_for_them() {
    let mut problem = fixture("slides/04-sphere-octant-radius-r.json");
    let answer = cagd_problem::solve(&problem).unwrap();
    let refused = Scene::from_answer(&answer, false).unwrap_err();
    assert_eq!(
        refused,
        RenderError::Letters {
            letters: "R".into(),
            values: "\"values\": {\"R\": 1}".into()
        }
    );
    assert!(refused
        .phrase(Lang::En)
        .text()
        .contains("\"values\": {\"R\": 1}"));
    assert!(refused
        .phrase(Lang::Es)
        .text()
        .contains("\"values\": {\"R\": 1}"));
    assert!(refused.phrase(Lang::Es).text().contains("letras"));
    problem["values"] = serde_json::json!({"R": 2});
    let answer = cagd_problem::solve(&problem).unwrap();
    let scene = Scene::from_answer(&answer, false).unwrap();
    // the surface at R = 2 and its profile, put in too
    assert_eq!(scene.surfaces.len(), 1);
    assert_eq!(scene.curves.len(), 1);
    let svg = render_svg(&scene, &SvgOptions::default()).unwrap();
    assert!(svg.contains(">curve</text>"));
}
