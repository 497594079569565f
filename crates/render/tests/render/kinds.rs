//! Every kind of geometry a scene holds: B-spline and NURBS surfaces (whole or as Bézier
//! pieces), polynomial maps, planar patches, curves of every kind; and the errors.

use crate::iges::hemisphere;
use crate::scenes::{self, pt};
use cagd_bspline::{unit_circle, BSplineCurve};
use cagd_linalg::Point;
use cagd_poly::parse_vec_poly;
use cagd_render::{
    render_svg, tessellate, to_html, AnyCurve, AnySurface, HtmlOptions, RenderError, Scene,
    SvgOptions,
};
use cagd_render::{SurfaceAsNurbs, SurfaceNet};
use cagd_scalar::{q, BigRational, FieldOps, Quadratic};
use cagd_spline_surface::BSplineSurface;
use cagd_surface::{BezierSurface, Mesh};

fn on_unit_sphere(t: &cagd_render::Tessellation) {
    for p in &t.vertices {
        let r = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
        assert!((r - 1.0).abs() < 1e-14, "{p:?}");
    }
}

#[test]
fn nurbs_hemisphere_whole_and_in_pieces() {
    let h = hemisphere();
    let mut whole = Scene::new();
    whole.add_surface("hemisphere", h.clone());
    on_unit_sphere(&tessellate(&whole, 12).unwrap()[0]);
    let mut pieces = Scene::new();
    pieces.add_rational_bezier_pieces("h", &h).unwrap();
    let names: Vec<&str> = pieces.surfaces.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "h [0, 1] x [0, 1]",
            "h [0, 1] x [1, 2]",
            "h [0, 1] x [2, 3]",
            "h [0, 1] x [3, 4]"
        ]
    );
    for t in tessellate(&pieces, 6).unwrap() {
        on_unit_sphere(&t);
    }
    let svg = render_svg(&pieces, &SvgOptions::default()).unwrap();
    // four colours in the legend
    for c in cagd_render::SURFACE_PALETTE.iter().take(4).map(|c| c.hex()) {
        assert!(svg.contains(&format!("fill=\"{c}\"")), "{c}");
    }
    crate::debug_out::save("look-hemisphere-pieces", &svg);
}

#[test]
fn bspline_surface_is_sampled_across_its_spans() {
    let p = |c: &[i64]| Point::<BigRational>::from_ints(c);
    let mesh = Mesh::mesh(vec![
        vec![p(&[0, 0, 0]), p(&[0, 1, 0])],
        vec![p(&[1, 0, 0]), p(&[1, 1, 1])],
        vec![p(&[2, 0, 0]), p(&[2, 1, 2])],
    ])
    .unwrap();
    let (s, _) = BSplineSurface::read(
        (1, 1),
        (vec![q!(0), q!(1), q!(2)], vec![q!(0), q!(1)]),
        mesh,
    )
    .unwrap();
    let mut scene = Scene::new();
    scene.add_surface("bilinear pieces", s.clone());
    let t = &tessellate(&scene, 4).unwrap()[0];
    // u = 3/2, v = 1/4: z = u v on [1, 2] (the second span): (3/2, 1/4, 3/8)
    assert_eq!(t.vertices[3 * 5 + 1], [1.5, 0.25, 0.375]);
    let mut split = Scene::new();
    split.add_bezier_pieces("b", &s).unwrap();
    assert_eq!(split.surfaces.len(), 2);
    let form = scene.surfaces[0].geometry.nurbs_form().unwrap();
    assert_eq!(form.knots_u, [q!(0), q!(0), q!(1), q!(2), q!(2)]);
}

#[test]
fn polynomial_maps_get_their_bezier_mesh() {
    let saddle = AnySurface::Map(parse_vec_poly::<BigRational>("(u, v, u v)").unwrap());
    let net = saddle.control_net().unwrap();
    assert_eq!(
        net.points.to_text(),
        "{(0, 0, 0), (0, 1, 0); (1, 0, 0), (1, 1, 1)}"
    );
    let wrong = AnySurface::Map(parse_vec_poly::<BigRational>("(u, w, 0)").unwrap());
    let mut scene = Scene::new();
    scene.add_surface("wrong", wrong);
    assert_eq!(
        render_svg(&scene, &SvgOptions::default()).unwrap_err().to_string(),
        "surface \"wrong\" is written in the variables u, w: a curve uses one variable, a surface u and v"
    );
}

#[test]
fn planar_patches_lie_in_z_0_and_4d_points_are_refused() {
    let planar = BezierSurface::<BigRational>::from_rows(vec![
        vec![pt(&["0", "0"]), pt(&["0", "1"])],
        vec![pt(&["1", "0"]), pt(&["2", "2"])],
    ])
    .unwrap();
    let mut scene = Scene::new();
    scene.add_surface("planar", planar);
    let t = &tessellate(&scene, 2).unwrap()[0];
    assert!(t.vertices.iter().all(|p| p[2] == 0.0));
    assert!(t.normals.iter().all(|n| n[2].abs() == 1.0));
    let four = BezierSurface::<BigRational>::from_rows(vec![
        vec![pt(&["0", "0", "0", "0"]), pt(&["0", "1", "0", "0"])],
        vec![pt(&["1", "0", "0", "0"]), pt(&["2", "2", "0", "1"])],
    ])
    .unwrap();
    let mut bad = Scene::new();
    bad.add_surface("in R^4", four);
    assert_eq!(
        render_svg(&bad, &SvgOptions::default()).unwrap_err(),
        RenderError::Dimension {
            what: cagd_render::Drawn::Surface {
                name: "in R^4".into()
            },
            dim: 4
        }
    );
}

#[test]
fn curves_of_every_kind_are_drawn_exactly() {
    let mut scene: Scene<Quadratic> = Scene::new();
    scene.add_curve("circle", unit_circle::<Quadratic>().unwrap());
    let b = BSplineCurve::read(
        2,
        [0, 0, 1, 2, 2]
            .into_iter()
            .map(Quadratic::from_i64)
            .collect(),
        vec![
            pt(&["0", "0", "0"]),
            pt(&["1", "2", "0"]),
            pt(&["2", "0", "1"]),
            pt(&["3", "1", "0"]),
        ],
    )
    .unwrap()
    .0;
    scene.add_curve("spline", b);
    scene.add_curve(
        "parabola",
        AnyCurve::Map(parse_vec_poly::<Quadratic>("(t, 0, t^2)").unwrap()),
    );
    let page = to_html(&scene, &HtmlOptions::default()).unwrap();
    let start = page.find("id=\"scene-data\">").unwrap() + "id=\"scene-data\">".len();
    let end = start + page[start..].find("</script>").unwrap();
    let data: serde_json::Value = serde_json::from_str(&page[start..end]).unwrap();
    let circle = data["curves"][0]["points"].as_array().unwrap();
    assert_eq!(circle.len(), 65);
    for p in circle {
        let (x, y) = (p[0].as_f64().unwrap(), p[1].as_f64().unwrap());
        assert!((x * x + y * y - 1.0).abs() < 1e-4, "({x}, {y})");
    }
    assert_eq!(data["curves"][0]["weights_text"][1], "√2/2");
    assert_eq!(data["curves"][2]["polygon_text"][1], "(1/2, 0, 0)");
    let svg = render_svg(&scene, &SvgOptions::default()).unwrap();
    assert_eq!(
        svg.matches("stroke-dasharray").count(),
        1,
        "one style for the polygons"
    );
    assert_eq!(svg.matches("<polyline class=\"p\"").count(), 3);
    crate::debug_out::save("look-curves", &svg);
}

#[test]
fn layers_and_view_change_the_picture() {
    let scene = scenes::coons_scene();
    let all = render_svg(&scene, &SvgOptions::default()).unwrap();
    let mut o = SvgOptions::default();
    o.layers.surface = false;
    o.layers.curves = false;
    let mesh_only = render_svg(&scene, &o).unwrap();
    assert!(all.contains("<path class=\"c\"") && !mesh_only.contains("<path"));
    assert!(mesh_only.contains("<circle"));
    o.layers.mesh = false;
    o.layers.boundary = false;
    o.layers.normals = true;
    let normals = render_svg(&scene, &o).unwrap();
    assert!(normals.contains("stroke=\"#1b7837\"") && !normals.contains("<circle cx"));
    let turned = SvgOptions {
        view: cagd_render::View::new(120.0, 40.0),
        ..SvgOptions::default()
    };
    assert_ne!(render_svg(&scene, &turned).unwrap(), all);
    let bad = SvgOptions {
        isolines: 1,
        ..SvgOptions::default()
    };
    assert_eq!(
        render_svg(&scene, &bad).unwrap_err().to_string(),
        "number of isolines 1 is out of range: choose 2 to 64"
    );
}

/// Curves of the plane z = 0 are drawn in the plane: x to the right, y up, no z axis; a curve
/// out of the plane keeps the axonometric view with its z axis.
#[test]
fn plane_curves_are_drawn_in_their_plane() {
    let mut scene: Scene<Quadratic> = Scene::new();
    scene.add_curve("circle", unit_circle::<Quadratic>().unwrap());
    let svg = render_svg(&scene, &SvgOptions::default()).unwrap();
    assert!(
        svg.contains(">x</text>") && svg.contains(">y</text>"),
        "{svg}"
    );
    assert!(!svg.contains(">z</text>"), "a plane figure has no z axis");
    // the x axis is horizontal: its polyline keeps one page height
    let axis = svg
        .lines()
        .find(|l| l.starts_with("<polyline points="))
        .unwrap();
    let ys: Vec<&str> = axis
        .trim_start_matches("<polyline points=\"")
        .split(['"', ' '])
        .filter_map(|xy| xy.split(',').nth(1))
        .collect();
    assert_eq!(ys.len(), 2, "{axis}");
    assert_eq!(ys[0], ys[1], "{axis}");
    scene.add_curve(
        "parabola",
        AnyCurve::Map(parse_vec_poly::<Quadratic>("(t, 0, t^2)").unwrap()),
    );
    let svg = render_svg(&scene, &SvgOptions::default()).unwrap();
    assert!(svg.contains(">z</text>"), "a space curve keeps the z axis");
}
