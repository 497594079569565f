//! IGES export read back by a small independent parser: fixed 80-column sections, directory
//! entries, and the parameters of entities 128 and 126 compared with the exact source.

use crate::scenes;
use cagd_linalg::Point;
use cagd_render::SurfaceAsNurbs;
use cagd_render::{to_iges, Scene};
use cagd_scalar::{parse_number, FieldOps, Quadratic, Scalar};
use cagd_spline_surface::NurbsSurface;
use cagd_surface::{Grid, Mesh};

/// A parsed IGES file: lines per section, directory entries, parameters per entity.
struct Iges {
    start: Vec<String>,
    global: Vec<String>,
    /// (type, parameter pointer, line count, colour, label, parameters)
    entities: Vec<Entity>,
    terminate: String,
}

#[derive(Debug)]
struct Entity {
    kind: i64,
    colour: i64,
    label: String,
    status: String,
    de: usize,
    params: Vec<String>,
}

fn field(line: &str, k: usize) -> &str {
    line[8 * k..8 * k + 8].trim()
}

fn parse(text: &str) -> Iges {
    let mut sections: std::collections::BTreeMap<char, Vec<String>> = Default::default();
    for (n, line) in text.lines().enumerate() {
        assert_eq!(line.len(), 80, "line {} is not 80 columns: {line:?}", n + 1);
        let letter = line.as_bytes()[72] as char;
        assert!("SGDPT".contains(letter), "line {}: section {letter}", n + 1);
        let seq: usize = line[73..].trim().parse().unwrap();
        let lines = sections.entry(letter).or_default();
        assert_eq!(seq, lines.len() + 1, "line {}: sequence number", n + 1);
        lines.push(line[..72].to_string());
    }
    let order: String = text.lines().map(|l| l.as_bytes()[72] as char).collect();
    let squeezed: String = order.chars().fold(String::new(), |mut s, c| {
        if !s.ends_with(c) {
            s.push(c);
        }
        s
    });
    assert_eq!(squeezed, "SGDPT", "sections in order");
    let d = &sections[&'D'];
    let p = &sections[&'P'];
    assert_eq!(d.len() % 2, 0);
    let mut entities = Vec::new();
    for (k, pair) in d.chunks(2).enumerate() {
        let de = 2 * k + 1;
        let kind: i64 = field(&pair[0], 0).parse().unwrap();
        assert_eq!(field(&pair[1], 0).parse::<i64>().unwrap(), kind);
        let pointer: usize = field(&pair[0], 1).parse().unwrap();
        let count: usize = field(&pair[1], 3).parse().unwrap();
        let mut data = String::new();
        for line in &p[pointer - 1..pointer - 1 + count] {
            let back: usize = line[65..72].trim().parse().unwrap();
            assert_eq!(back, de, "P line points back to its directory entry");
            data.push_str(&line[..64]);
        }
        let data = data.trim_end();
        assert!(data.ends_with(';'), "{data}");
        let params = data[..data.len() - 1]
            .split(',')
            .map(|t| t.trim().to_string())
            .collect();
        entities.push(Entity {
            kind,
            colour: field(&pair[1], 2).parse().unwrap(),
            label: field(&pair[1], 7).to_string(),
            status: field(&pair[0], 8).to_string(),
            de,
            params,
        });
    }
    Iges {
        start: sections[&'S'].clone(),
        global: sections[&'G'].clone(),
        entities,
        terminate: sections[&'T'][0].clone(),
    }
}

fn real(t: &str) -> f64 {
    t.replace('D', "E")
        .parse()
        .unwrap_or_else(|_| panic!("not a real: {t:?}"))
}

fn int(t: &str) -> usize {
    t.parse()
        .unwrap_or_else(|_| panic!("not an integer: {t:?}"))
}

fn close(a: f64, b: f64) {
    assert!((a - b).abs() <= 1e-12, "{a} != {b}");
}

/// Checks an entity 128 against the exact surface k of the scene.
fn check_surface<S: Scalar>(e: &Entity, scene: &Scene<S>, k: usize) {
    assert_eq!(e.kind, 128);
    let form = scene.surfaces[k].geometry.nurbs_form().unwrap();
    let p = &e.params;
    assert_eq!(int(&p[0]), 128);
    let (k1, k2, m1, m2) = (int(&p[1]), int(&p[2]), int(&p[3]), int(&p[4]));
    assert_eq!((k1 + 1, k2 + 1), (form.points.rows(), form.points.cols()));
    assert_eq!((m1, m2), form.degree);
    assert_eq!(
        int(&p[7]),
        usize::from(form.weights.is_none()),
        "PROP3: polynomial"
    );
    let mut at = 10;
    let (nu, nv) = (k1 + m1 + 2, k2 + m2 + 2);
    for (t, x) in p[at..at + nu].iter().zip(&form.knots_u) {
        close(real(t), x.to_f64());
    }
    at += nu;
    for (t, x) in p[at..at + nv].iter().zip(&form.knots_v) {
        close(real(t), x.to_f64());
    }
    at += nv;
    for j in 0..=k2 {
        for i in 0..=k1 {
            let w = form
                .weights
                .as_ref()
                .map_or(1.0, |w| w.get(i, j).unwrap().to_f64());
            close(real(&p[at]), w);
            at += 1;
        }
    }
    for j in 0..=k2 {
        for i in 0..=k1 {
            let c = form.points.get(i, j).unwrap().to_f64();
            for d in 0..3 {
                close(real(&p[at + d]), c.get(d).copied().unwrap_or(0.0));
            }
            at += 3;
        }
    }
    close(real(&p[at]), form.knots_u[m1].to_f64());
    close(
        real(&p[at + 1]),
        form.knots_u[form.knots_u.len() - 1 - m1].to_f64(),
    );
    assert_eq!(p.len(), at + 4, "nothing after the parameter ranges");
}

fn check_file<S: Scalar>(scene: &Scene<S>) -> Iges {
    let text = to_iges(scene).unwrap();
    assert_eq!(text, to_iges(scene).unwrap(), "deterministic");
    let iges = parse(&text);
    let counts = format!(
        "S{:>7}G{:>7}D{:>7}P{:>7}",
        iges.start.len(),
        iges.global.len(),
        2 * iges.entities.len(),
        text.lines().filter(|l| l.as_bytes()[72] == b'P').count()
    );
    assert_eq!(iges.terminate.trim_end(), counts);
    assert!(iges.global[0].starts_with("1H,,1H;,"));
    let surfaces: Vec<&Entity> = iges.entities.iter().filter(|e| e.kind == 128).collect();
    assert_eq!(surfaces.len(), scene.surfaces.len());
    for (k, e) in surfaces.iter().enumerate() {
        check_surface(e, scene, k);
        // the colour is a pointer to a colour definition
        assert!(e.colour < 0);
        let colour = iges
            .entities
            .iter()
            .find(|c| c.de as i64 == -e.colour)
            .unwrap();
        assert_eq!(colour.kind, 314);
        assert_eq!(colour.status, "00000200");
        assert_eq!(colour.params.len(), 5);
    }
    iges
}

#[test]
fn coons_patch_round_trips() {
    let scene = scenes::coons_scene();
    let iges = check_file(&scene);
    assert_eq!(
        iges.entities.iter().filter(|e| e.kind == 126).count(),
        4,
        "the four curves"
    );
    let c1 = iges.entities.iter().find(|e| e.label == "c1").unwrap();
    // 126, K = 3, M = 3, planar (y = 0 is not z = 0: not flagged), open, polynomial, not periodic
    assert_eq!(&c1.params[..7], &["126", "3", "3", "0", "0", "1", "0"]);
    assert_eq!(
        &c1.params[7..15],
        &["0.0", "0.0", "0.0", "0.0", "1.0", "1.0", "1.0", "1.0"]
    );
    // the second control point (1/2, 0, 2) after the four weights
    assert_eq!(
        &c1.params[19..25],
        &["0.0", "0.0", "0.0", "0.5", "0.0", "2.0"]
    );
    let patch = iges.entities.iter().find(|e| e.kind == 128).unwrap();
    assert_eq!(patch.label, "Coonspat");
    // (1/2, 5/6, 31/6) written with all the digits of the nearest f64
    let text = patch.params.join(",");
    assert!(
        text.contains("0.5,0.8333333333333334,5.166666666666667"),
        "{text}"
    );
}

#[test]
fn sphere_octant_keeps_its_irrational_weights() {
    let scene = scenes::sphere_scene();
    let iges = check_file(&scene);
    let patch = iges.entities.iter().find(|e| e.kind == 128).unwrap();
    assert_eq!(patch.params[7], "0", "rational");
    // weights after 10 header values and 6 + 6 knots
    let w: Vec<&str> = patch.params[22..31].iter().map(String::as_str).collect();
    let h = "0.7071067811865476";
    assert_eq!(w, ["1.0", h, "1.0", h, "0.5", h, "1.0", h, "1.0"]);
}

#[test]
fn c1_pair_and_ruled_patch_round_trip() {
    check_file(&scenes::c1_scene());
    check_file(&scenes::ruled_scene());
}

/// The slides' hemisphere: a NURBS surface of bidegree (2, 2) with 3 x 9 control points.
pub fn hemisphere() -> NurbsSurface<Quadratic> {
    let n = |t: &str| parse_number(t).unwrap();
    let circle = [
        (1, 0),
        (1, 1),
        (0, 1),
        (-1, 1),
        (-1, 0),
        (-1, -1),
        (0, -1),
        (1, -1),
        (1, 0),
    ];
    let omega = |j: usize| if j % 2 == 0 { n("1") } else { n("sqrt2/2") };
    let profile = [(1, 0, n("1")), (1, 1, n("sqrt2/2")), (0, 1, n("1"))];
    let mesh = Mesh::mesh(
        profile
            .iter()
            .map(|(x, z, _)| {
                circle
                    .iter()
                    .map(|(a, b)| Point::from_ints(&[x * a, x * b, *z]))
                    .collect()
            })
            .collect(),
    )
    .unwrap();
    let weights = Grid::from_fn(3, 9, |i, j| profile[i].2.clone() * omega(j));
    let knots_v: Vec<Quadratic> = [0, 0, 1, 1, 2, 2, 3, 3, 4, 4]
        .into_iter()
        .map(Quadratic::from_i64)
        .collect();
    NurbsSurface::read(
        (2, 2),
        (vec![n("0"), n("0"), n("1"), n("1")], knots_v),
        mesh,
        weights,
    )
    .unwrap()
    .0
}

#[test]
fn nurbs_hemisphere_keeps_its_knots() {
    let mut scene = Scene::new();
    scene.add_surface("hemisphere", hemisphere());
    let iges = check_file(&scene);
    let patch = iges.entities.iter().find(|e| e.kind == 128).unwrap();
    assert_eq!(&patch.params[1..5], &["2", "8", "2", "2"]);
    let knots_v: Vec<&str> = patch.params[16..28].iter().map(String::as_str).collect();
    assert_eq!(
        knots_v,
        ["0.0", "0.0", "0.0", "1.0", "1.0", "2.0", "2.0", "3.0", "3.0", "4.0", "4.0", "4.0"]
    );
}

#[test]
fn write_iges_for_a_look() {
    let d = crate::debug_out::out_dir();
    std::fs::write(
        d.join("sphere.igs"),
        to_iges(&scenes::sphere_scene()).unwrap(),
    )
    .unwrap();
}
