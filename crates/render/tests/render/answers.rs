//! Figures of problems and answers: the lecture fixtures, solved and drawn.

use cagd_render::SurfaceNet;
use cagd_render::{render_svg, AnySurface, Scene, SvgOptions};
use serde_json::Value;

fn fixture(path: &str) -> Value {
    let p = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../fixtures")
        .join(path);
    serde_json::from_str(&std::fs::read_to_string(p).unwrap()).unwrap()
}

/// The figure of a problem: solved once (with or without steps), drawn from its answer.
fn drawn(problem: &Value, steps: bool) -> Scene<cagd_problem::Number> {
    let answer = cagd_problem::solve(problem).unwrap();
    Scene::from_answer(&answer, steps).unwrap()
}

fn names(scene: &Scene<cagd_problem::Number>) -> (Vec<&str>, Vec<&str>) {
    (
        scene.surfaces.iter().map(|s| s.name.as_str()).collect(),
        scene.curves.iter().map(|c| c.name.as_str()).collect(),
    )
}

/// A problem's data alone: the Coons patch's four curves, never the patch (the answer); a
/// problem with a surface given draws that surface; a problem in letters without values is
/// refused.
#[test]
fn the_data_of_a_problem_without_its_answer() {
    let read = |v: &Value| cagd_problem::Problem::read(v, &cagd_problem::Limits::DEFAULT).unwrap();
    let coons = read(&fixture("ch6/07-coons-bezier.json"));
    let scene = Scene::from_problem(&coons).unwrap();
    assert_eq!(names(&scene), (vec![], vec!["c1", "c2", "d1", "d2"]));
    assert!(render_svg(&scene, &SvgOptions::default()).is_ok());
    let restriction = read(&fixture("ch5/04-restriction.json"));
    let scene = Scene::from_problem(&restriction).unwrap();
    assert_eq!(scene.surfaces.len(), 1);
    assert!(!scene.surfaces[0].faint);
    let letters = read(&fixture("slides/04-sphere-octant-radius-r.json"));
    assert!(matches!(
        Scene::from_problem(&letters),
        Err(cagd_render::RenderError::Letters { .. })
    ));
}

#[test]
fn coons_problem_shows_the_patch_and_its_four_curves() {
    let problem = fixture("ch6/07-coons-bezier.json");
    let scene = drawn(&problem, false);
    assert_eq!(
        names(&scene),
        (vec!["surface"], vec!["c1", "c2", "d1", "d2"])
    );
    let AnySurface::Bezier(s) = &scene.surfaces[0].geometry else {
        panic!("a Bézier patch")
    };
    assert_eq!(
        s.to_text(),
        "{(0, 0, 0), (0, 1, 3), (0, 3, 0); (1/2, 0, 2), (1/2, 5/6, 31/6), (1/2, 3, 3); \
         (1, 0, 3), (1, 2/3, 13/3), (1, 3, 1); (2, 0, 0), (2, 1, 2), (2, 4, 0)}"
    );
    let with_steps = drawn(&problem, true);
    assert_eq!(names(&with_steps).0, vec!["surface", "c_c", "c_d", "c_cd"]);
    let svg = render_svg(&with_steps, &SvgOptions::default()).unwrap();
    assert!(svg.contains(">c_cd</text>"));
    crate::debug_out::save("look-coons-steps", &svg);
}

#[test]
fn sphere_problem_is_drawn_over_the_quadratic_field() {
    let problem = fixture("ch6/10-sphere-octant.json");
    let scene = drawn(&problem, false);
    assert_eq!(names(&scene), (vec!["surface"], vec!["curve"]));
    let net = scene.surfaces[0].geometry.control_net().unwrap();
    assert_eq!(net.weights.unwrap().get(1, 1).unwrap().to_string(), "1/2");
}

#[test]
fn continuity_problem_shows_its_two_input_patches() {
    let problem = fixture("ch5/07-c1-join.json");
    let scene = drawn(&problem, false);
    assert_eq!(names(&scene), (vec!["first", "second"], vec![]));
}

#[test]
fn answer_json_and_bare_surfaces_are_figures_too() {
    let problem = fixture("ch6/07-coons-bezier.json");
    let answer = cagd_problem::solve(&problem).unwrap();
    let json = answer.to_json(true);
    let scene = Scene::from_json(&json, true).unwrap();
    assert_eq!(names(&scene).0, vec!["surface", "c_c", "c_d", "c_cd"]);
    let bare: Value =
        serde_json::json!({"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]});
    assert_eq!(
        names(&Scene::from_json(&bare, false).unwrap()).0,
        vec!["figure"]
    );
    let curve: Value = serde_json::json!({"expr": "(u, 0, u^2)"});
    assert_eq!(
        names(&Scene::from_json(&curve, false).unwrap()).1,
        vec!["figure"]
    );
    // a problem is solved by the caller, never by the figure crate
    assert_eq!(
        Scene::from_json(&problem, false).unwrap_err().to_string(),
        "there is nothing to draw: the figure has no surface and no curve"
    );
    let nothing: Value = serde_json::json!({"hello": 1});
    assert_eq!(
        Scene::from_json(&nothing, false).unwrap_err().to_string(),
        "there is nothing to draw: the figure has no surface and no curve"
    );
}

/// Triangular patches are drawn as the map b(u (1 - v), v) of the unit square, which traces the
/// same patch: the problem's triangle for an evaluation, the three pieces of a subdivision; the
/// pieces of a surface subdivision are drawn too.
#[test]
fn triangles_and_pieces_are_drawn() {
    let t = serde_json::json!({"triangle": [[[0, 0, 0]], [["1/2", 0, 0], [0, "1/2", 0]], [[1, 0, 0], ["1/2", "1/2", "1/2"], [0, 1, 0]]]});
    let e = drawn(
        &serde_json::json!({"op": "evaluate", "triangle": t, "params": [["1/3", "1/3"]]}),
        false,
    );
    assert_eq!(names(&e), (vec!["triangle"], vec![]));
    let AnySurface::Map(m) = &e.surfaces[0].geometry else {
        panic!("a map")
    };
    // z = u v at (u (1 - v), v)
    assert_eq!(m.to_text(), "(-u v + u, v, -u v^2 + u v)");
    let s = drawn(
        &serde_json::json!({"op": "subdivide", "triangle": t, "u": "1/3", "v": "1/3"}),
        false,
    );
    assert_eq!(
        names(&s).0,
        ["triangles[0]", "triangles[1]", "triangles[2]"]
    );
    let q = drawn(
        &serde_json::json!({"op": "subdivide", "surface": {"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]}, "u": "1/2"}),
        false,
    );
    assert_eq!(names(&q).0, ["surfaces[0]", "surfaces[1]"]);
}
