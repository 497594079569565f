//! OBJ and STL tessellations read back.

use crate::scenes;
use cagd_render::{tessellate, to_obj, to_stl_ascii, to_stl_binary, RenderError, Scene};
use cagd_scalar::{q, BigRational};

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[test]
fn sphere_tessellation_lies_on_the_sphere_with_radial_normals() {
    let parts = tessellate(&scenes::sphere_scene(), 16).unwrap();
    let t = &parts[0];
    assert_eq!(t.vertices.len(), 17 * 17);
    // the pole row collapses: its 16 cells lose one triangle each
    assert_eq!(t.triangles.len(), 2 * 16 * 16 - 16);
    for (p, n) in t.vertices.iter().zip(&t.normals) {
        assert!((dot(*p, *p) - 1.0).abs() < 1e-14, "{p:?} off the sphere");
        assert!((dot(*n, *n) - 1.0).abs() < 1e-12);
        // c_u x c_v points inward on this parametrization; at the pole the fallback normal is
        // the mean of the facets around it, close to radial
        assert!(dot(*n, *p) < -0.99, "normal {n:?} at {p:?} is not radial");
    }
}

#[test]
fn obj_has_vertices_normals_and_faces() {
    let obj = to_obj(&scenes::coons_scene(), 2).unwrap();
    let count = |prefix: &str| obj.lines().filter(|l| l.starts_with(prefix)).count();
    assert_eq!(count("o "), 1);
    assert_eq!(count("v "), 9);
    assert_eq!(count("vn "), 9);
    assert_eq!(count("f "), 8);
    // c(1/2, 1/2) of the Coons patch, exactly (1, 3/2 + 1/24, ...), printed with 6 decimals
    let centre = scenes::coons_patch::<BigRational>()
        .eval(&q!(1 / 2), &q!(1 / 2))
        .unwrap();
    let line = format!(
        "v {:.6} {:.6} {:.6}",
        centre.to_f64()[0],
        centre.to_f64()[1],
        centre.to_f64()[2]
    );
    assert!(obj.lines().any(|l| l == line), "{line} missing from\n{obj}");
    for l in obj.lines().filter(|l| l.starts_with("f ")) {
        for v in l[2..].split(' ') {
            let (a, b) = v.split_once("//").unwrap();
            assert_eq!(a, b);
            let i: usize = a.parse().unwrap();
            assert!((1..=9).contains(&i));
        }
    }
    assert_eq!(obj, to_obj(&scenes::coons_scene(), 2).unwrap());
}

#[test]
fn two_patches_number_their_vertices_on() {
    let obj = to_obj(&scenes::c1_scene(), 3).unwrap();
    assert_eq!(obj.lines().filter(|l| l.starts_with("o ")).count(), 2);
    let last_face = obj.lines().rfind(|l| l.starts_with("f ")).unwrap();
    let max: usize = last_face[2..]
        .split(' ')
        .map(|v| v.split("//").next().unwrap().parse::<usize>().unwrap())
        .max()
        .unwrap();
    assert_eq!(
        max, 32,
        "second patch indices follow the first's 16 vertices"
    );
}

#[test]
fn stl_ascii_and_binary_agree() {
    let scene = scenes::sphere_scene();
    let ascii = to_stl_ascii(&scene, 8).unwrap();
    let binary = to_stl_binary(&scene, 8).unwrap();
    let facets = ascii.matches("facet normal").count();
    assert_eq!(facets, 2 * 64 - 8);
    assert!(
        ascii.starts_with("solid Sphere_octant\n") && ascii.ends_with("endsolid Sphere_octant\n")
    );
    assert_eq!(binary.len(), 84 + 50 * facets);
    assert_eq!(
        u32::from_le_bytes(binary[80..84].try_into().unwrap()) as usize,
        facets
    );
    // first facet: normal and first vertex as in the ASCII file
    let f = |k: usize| f32::from_le_bytes(binary[84 + 4 * k..88 + 4 * k].try_into().unwrap());
    let first_vertex = ascii
        .lines()
        .find(|l| l.trim_start().starts_with("vertex"))
        .unwrap();
    let xyz: Vec<f32> = first_vertex
        .split_whitespace()
        .skip(1)
        .map(|t| t.parse().unwrap())
        .collect();
    for k in 0..3 {
        assert!((f(3 + k) - xyz[k]).abs() < 1e-6);
    }
    let n = [f(0), f(1), f(2)];
    assert!((n[0] * n[0] + n[1] * n[1] + n[2] * n[2] - 1.0).abs() < 1e-5);
}

#[test]
fn bad_density_and_empty_scene_are_errors() {
    assert_eq!(
        to_obj(&scenes::coons_scene(), 0).unwrap_err(),
        RenderError::Density {
            what: cagd_render::Sampling::Tessellation,
            value: 0,
            min: 1,
            max: 256
        }
    );
    assert_eq!(
        to_obj(&scenes::coons_scene(), 1000)
            .unwrap_err()
            .to_string(),
        "tessellation density 1000 is out of range: choose 1 to 256"
    );
    assert_eq!(
        to_stl_ascii(&Scene::<BigRational>::new(), 4).unwrap_err(),
        RenderError::EmptyScene
    );
}

/// A patch whose coordinates have `digits` zeros after a 1 (negative: 1/10^-digits).
fn scaled_patch(digits: i32) -> Scene<cagd_problem::Number> {
    let unit = if digits >= 0 {
        format!("1{}", "0".repeat(digits as usize))
    } else {
        format!("1/1{}", "0".repeat((-digits) as usize))
    };
    let mesh: Vec<Vec<serde_json::Value>> = (0..3)
        .map(|i| {
            (0..3)
                .map(|j| {
                    serde_json::json!([
                        format!("{i}*{unit}"),
                        format!("{j}*{unit}"),
                        format!("{}*{unit}", (i + j) % 3)
                    ])
                })
                .collect()
        })
        .collect();
    Scene::from_json(&serde_json::json!({"bezier": mesh}), false).unwrap()
}

/// Coordinates beyond floating point are refused with the reason, never drawn at the origin
/// or at infinity; so is a figure whose extent rounds to nothing.
#[test]
fn huge_and_tiny_coordinates_are_refused_not_drawn_wrong() {
    let huge = scaled_patch(400);
    let refused = |e: RenderError| {
        let text = e.to_string();
        assert!(matches!(e, RenderError::Range { .. }), "{text}");
        assert!(text.contains("cannot be drawn"), "{text}");
        text
    };
    let e = refused(to_obj(&huge, 4).unwrap_err());
    assert!(e.contains("a coordinate is beyond 1e308"), "{e}");
    refused(to_stl_binary(&huge, 4).unwrap_err());
    refused(cagd_render::to_iges(&huge).unwrap_err());
    refused(cagd_render::render_svg(&huge, &cagd_render::SvgOptions::default()).unwrap_err());
    let tiny = scaled_patch(-400);
    let e = refused(to_obj(&tiny, 4).unwrap_err());
    assert!(e.contains("its points are equal in floating point"), "{e}");
    refused(cagd_render::render_svg(&tiny, &cagd_render::SvgOptions::default()).unwrap_err());
    // within the range, the same patch is drawn to scale
    let big = to_obj(&scaled_patch(100), 2).unwrap();
    assert!(big.contains("v 100000000000000001590289110975991804683608085639452813897813275577478387721703810608134699858568151"), "{big}");
}
