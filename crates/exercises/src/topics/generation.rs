//! Chapter 6: surfaces generated from curves (`000_4f266b7df5f64f70.txt` §2-§6).

use crate::draw::{bridge, poly2, tuple, Draft};
use crate::num::{
    add, bezier_curve_json, bezier_surface_json, int, point_text, pt, scale, sub, Poly2, P3,
};
use crate::rng::Rng;
use serde_json::json;

/// A Bézier polygon of degree p in the plane through `start` spanned by the x axis (or the
/// y axis when `along_y`): the k-th point is `start` + k·step along the axis, with small
/// heights after the first.
fn polygon(rng: &mut Rng, start: P3, p: usize, step: i64, along_y: bool) -> Vec<P3> {
    (0..=p)
        .map(|k| {
            if k == 0 {
                return start;
            }
            let d = int(step * k as i64);
            let z = start[2] + int(rng.range(-2, 2));
            if along_y {
                [start[0], start[1] + d, z]
            } else {
                [start[0] + d, start[1], z]
            }
        })
        .collect()
}

fn degree_word_en(p: usize) -> &'static str {
    match p {
        1 => "segment",
        2 => "parabola",
        _ => "cubic",
    }
}

fn degree_word_es(p: usize) -> &'static str {
    match p {
        1 => "segmento",
        2 => "parábola",
        _ => "cúbica",
    }
}

/// The Spanish noun of a polygon of degree p with its article, contracted after `de`
/// (`de` + `el` = `del`): `el segmento`, `la parábola`; after "de", `l segmento` and
/// ` la parábola`.
fn with_article(p: usize, after_de: bool) -> String {
    match (p, after_de) {
        (1, true) => "l segmento".into(),
        (1, false) => "el segmento".into(),
        (_, true) => format!(" la {}", degree_word_es(p)),
        (_, false) => format!("la {}", degree_word_es(p)),
    }
}

/// `translational`: c(u, v) = c(u) + d(v) - a, eq. (1), with c(0) = d(0) = a by
/// construction; Bézier polygons (mesh (4): c_ij = c_i + d_j - a) or, one in four,
/// polynomial curves in u and v.
pub(crate) fn translational(rng: &mut Rng) -> Draft {
    let a = pt(rng.range(0, 2), rng.range(0, 2), rng.range(-1, 1));
    if rng.chance(1, 4) {
        let (ax, ay, az) = (a[0].to_integer(), a[1].to_integer(), a[2].to_integer());
        let f = poly2(rng, 2, 3, 0);
        let g = poly2(rng, 2, 0, 3);
        // c(u) = (u + ax, ay, az + f(u) - f(0)), d(v) = (ax, v + ay, az + g(v) - g(0)).
        let lift = |p: &Poly2, shift: i64| -> Poly2 {
            let mut t: Vec<_> =
                p.0.iter()
                    .filter(|t| (t.1, t.2) != (0, 0))
                    .copied()
                    .collect();
            t.push((shift, 0, 0));
            Poly2(t)
        };
        let c = tuple(&[
            Poly2(vec![(1, 1, 0), (ax, 0, 0)]).to_expr("u", "v"),
            ay.to_string(),
            lift(&f, az).to_expr("u", "v"),
        ]);
        let d = tuple(&[
            ax.to_string(),
            Poly2(vec![(1, 0, 1), (ay, 0, 0)]).to_expr("u", "v"),
            lift(&g, az).to_expr("u", "v"),
        ]);
        return Draft::new(
            format!(
                "Translational surface c(u) + d(v) - a of the curves c(u) = {c} and d(v) = {d}"
            ),
            format!(
                "Superficie traslacional c(u) + d(v) - a de las curvas c(u) = {c} y d(v) = {d}"
            ),
            vec![("c", json!({"expr": c})), ("d", json!({"expr": d}))],
        );
    }
    let (p, q) = rng.pick(&[(1, 2), (2, 1), (2, 2), (2, 2), (3, 1), (2, 3), (3, 2)]);
    let c = polygon(rng, a, p, 1, false);
    let d = polygon(rng, a, q, 1, true);
    let at = point_text(&a);
    Draft::new(
        format!(
            "Translational Bézier surface of the {} c and the {} d, which start at a = {at}: mesh and closed form",
            degree_word_en(p),
            degree_word_en(q)
        ),
        format!(
            "Superficie traslacional de Bézier de{} c y {} d, que parten de a = {at}: malla de control y parametrización",
            with_article(p, true),
            with_article(q, false)
        ),
        vec![("c", bezier_curve_json(&c)), ("d", bezier_curve_json(&d))],
    )
}

/// `ruled`: c(u, v) = (1 - v) c1(u) + v c2(u), eq. (7), between two Bézier curves in the
/// planes y = 0 and y = 1 or 2 (of possibly different degrees: the lower one is elevated),
/// or, one in four, two polynomial curves (u, 0, f(u)) and (u, 1, g(u)).
pub(crate) fn ruled(rng: &mut Rng) -> Draft {
    if rng.chance(1, 4) {
        let f = poly2(rng, 2, 3, 0);
        let g = poly2(rng, 2, 3, 0);
        let c1 = tuple(&["u".into(), "0".into(), f.to_expr("u", "v")]);
        let c2 = tuple(&["u".into(), "1".into(), g.to_expr("u", "v")]);
        return Draft::new(
            format!("Ruled surface (1 - v) c1(u) + v c2(u) between c1(u) = {c1} and c2(u) = {c2}"),
            format!("Superficie reglada (1 - v) c1(u) + v c2(u) entre c1(u) = {c1} y c2(u) = {c2}"),
            vec![("c1", json!({"expr": c1})), ("c2", json!({"expr": c2}))],
        );
    }
    let (p1, p2) = rng.pick(&[(1, 2), (2, 2), (2, 2), (2, 3), (3, 3), (3, 2), (2, 1)]);
    let y2 = rng.range(1, 2);
    let (z1, z2) = (rng.range(-1, 1), rng.range(-1, 1));
    let c1 = polygon(rng, pt(0, 0, z1), p1, 1, false);
    let mut c2 = polygon(rng, pt(0, y2, z2), p2, 1, false);
    // Lean the second curve a little so that the rulings are not all parallel to y.
    if let Some(last) = c2.last_mut() {
        last[0] += int(rng.range(0, 1));
    }
    Draft::new(
        format!("Ruled Bézier surface (1 - v) c1(u) + v c2(u) between c1 (degree {p1}) and c2 (degree {p2}): mesh and closed form"),
        format!("Superficie reglada de Bézier (1 - v) c1(u) + v c2(u) entre c1 (grado {p1}) y c2 (grado {p2}): malla de control y parametrización"),
        vec![("c1", bezier_curve_json(&c1)), ("c2", bezier_curve_json(&c2))],
    )
}

/// How a ruled patch for the developability test is built.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Ruling {
    /// c2 = c1 + w, eq. (11): developable.
    Cylinder,
    /// c2 the apex a, eq. (12): developable.
    Cone,
    /// c1 = a + 2 (c2 - a): a truncated cone, developable.
    TruncatedCone,
    /// c2 drawn freely: in general not developable.
    Free,
}

/// `developable`: the test c_uv · (c_u × c_v) ≡ 0, eq. (9), on ruled patches of bidegree
/// (p, 1) that are cylindrical, conical or truncated cones by construction (developable)
/// or have a free second curve (in general not); given as a mesh or as the two curves.
pub(crate) fn developable(rng: &mut Rng) -> Draft {
    let kind = rng.pick(&[
        Ruling::Cylinder,
        Ruling::Cone,
        Ruling::TruncatedCone,
        Ruling::Free,
        Ruling::Free,
    ]);
    let p = rng.pick(&[2, 2, 3]);
    let c2_free: Vec<P3> = (0..=p)
        .map(|k| pt(k as i64, rng.range(0, 2), rng.range(-1, 2)))
        .collect();
    let (c1, c2) = match kind {
        Ruling::Cylinder => {
            let c1: Vec<P3> = (0..=p)
                .map(|k| pt(k as i64, rng.range(-1, 1), rng.range(-1, 2)))
                .collect();
            let w = pt(rng.range(-1, 1), rng.range(1, 2), rng.range(-1, 1));
            let c2 = c1.iter().map(|c| add(c, &w)).collect();
            (c1, c2)
        }
        Ruling::Cone => {
            let c1: Vec<P3> = (0..=p)
                .map(|k| pt(k as i64, rng.range(-1, 1), rng.range(-1, 2)))
                .collect();
            let apex = pt(rng.range(0, 2), rng.range(2, 3), rng.range(1, 3));
            (c1, vec![apex; p + 1])
        }
        Ruling::TruncatedCone => {
            let apex = pt(rng.range(0, 2), rng.range(2, 3), rng.range(1, 3));
            let c1 = c2_free
                .iter()
                .map(|c| add(&apex, &scale(&sub(c, &apex), int(2))))
                .collect();
            (c1, c2_free)
        }
        Ruling::Free => {
            let c1: Vec<P3> = (0..=p)
                .map(|k| pt(k as i64, rng.range(-2, -1), rng.range(-1, 2)))
                .collect();
            (c1, c2_free)
        }
    };
    if rng.chance(1, 2) {
        let rows: Vec<Vec<P3>> = c1.iter().zip(&c2).map(|(a, b)| vec![*a, *b]).collect();
        Draft::new(
            format!("Is the ruled Bézier patch of bidegree ({p}, 1) developable? Test c_uv · (c_u × c_v) ≡ 0"),
            format!("¿Es desarrollable la superficie reglada de Bézier de bigrado ({p}, 1)? Estudia c_uv · (c_u × c_v) ≡ 0"),
            vec![("surface", bezier_surface_json(&rows))],
        )
    } else {
        Draft::new(
            format!("Is the ruled surface between the Bézier curves c1 and c2 (degree {p}) developable? Test c_uv · (c_u × c_v) ≡ 0"),
            format!("¿Es desarrollable la superficie reglada entre las curvas de Bézier c1 y c2 (grado {p})? Estudia c_uv · (c_u × c_v) ≡ 0"),
            vec![("c1", bezier_curve_json(&c1)), ("c2", bezier_curve_json(&c2))],
        )
    }
}

/// A Bézier polygon of degree p from `a` to `b` whose inner points lie on the segment's
/// segment a + k (b - a)/p (rounded down to integers in x and y) with a small bump in z.
fn boundary(rng: &mut Rng, a: &P3, b: &P3, p: usize) -> Vec<P3> {
    (0..=p)
        .map(|k| {
            if k == 0 {
                return *a;
            }
            if k == p {
                return *b;
            }
            let t = crate::num::frac(k as i64, p as i64);
            let q = add(a, &scale(&sub(b, a), t));
            [
                q[0].floor(),
                q[1].floor(),
                q[2].round() + int(rng.range(-1, 2)),
            ]
        })
        .collect()
}

/// `coons`: the bilinearly blended Coons patch c_c + c_d - c_cd, eq. (15)-(17), of four
/// boundary curves that meet at the corners by construction, (13): Bézier polygons (mesh
/// (18)-(19)) or, one in four, polynomial curves as in the notes; some with cubic blending.
pub(crate) fn coons(rng: &mut Rng) -> Draft {
    let blend = if rng.chance(1, 4) { "cubic" } else { "linear" };
    let (blend_en, blend_es) = match blend {
        "cubic" => ("cubically blended", "con mezcla cúbica"),
        _ => ("bilinearly blended", "bilineal"),
    };
    let z: [i64; 4] = std::array::from_fn(|_| rng.range(-1, 2));
    let [z00, z10, z01, z11] = z;
    let mut args = Vec::new();
    if rng.chance(1, 4) {
        // x = u, y = v, heights bridging the corner heights (13).
        let c1 = tuple(&[
            "u".into(),
            "0".into(),
            bridge(rng, z00, z10, true).to_expr("u", "v"),
        ]);
        let c2 = tuple(&[
            "u".into(),
            "1".into(),
            bridge(rng, z01, z11, true).to_expr("u", "v"),
        ]);
        let d1 = tuple(&[
            "0".into(),
            "v".into(),
            bridge(rng, z00, z01, false).to_expr("v", "u"),
        ]);
        let d2 = tuple(&[
            "1".into(),
            "v".into(),
            bridge(rng, z10, z11, false).to_expr("v", "u"),
        ]);
        for (k, e) in [("c1", c1), ("c2", c2), ("d1", d1), ("d2", d2)] {
            args.push((k, json!({ "expr": e })));
        }
    } else {
        let (p, q) = rng.pick(&[(2, 2), (3, 2), (2, 3), (2, 1), (1, 2), (3, 3), (3, 1)]);
        // Sides that are multiples of the degrees keep the inner points on integers.
        let a = int(p as i64 * rng.range(1, 2));
        let b = int(q as i64 * rng.range(1, 2));
        let lean = int(rng.range(0, 1));
        let corner00 = [int(0), int(0), int(z00)];
        let corner10 = [a, int(0), int(z10)];
        let corner01 = [int(0), b, int(z01)];
        let corner11 = [a, b + lean, int(z11)];
        let c1 = boundary(rng, &corner00, &corner10, p);
        let c2 = boundary(rng, &corner01, &corner11, p);
        let d1 = boundary(rng, &corner00, &corner01, q);
        let d2 = boundary(rng, &corner10, &corner11, q);
        for (k, c) in [("c1", c1), ("c2", c2), ("d1", d1), ("d2", d2)] {
            args.push((k, bezier_curve_json(&c)));
        }
    }
    if blend == "cubic" {
        args.push(("blend", json!("cubic")));
    }
    Draft::new(
        format!(
            "Coons patch ({blend_en}) of the boundary curves c1, c2 (along u) and d1, d2 (along v)"
        ),
        format!(
            "Superficie de Coons ({blend_es}) de las curvas de borde c1, c2 (en u) y d1, d2 (en v)"
        ),
        args,
    )
}

/// `revolution`: the quadrant (arcs = 1) of the surface swept by a profile in the XZ plane
/// about the Z axis, eq. (21), as a rational Bézier mesh with weights √2/2: a segment or a
/// parabola with small coordinates (x ≥ 0), or, one in four, a quarter circle (a sphere or
/// torus quadrant).
pub(crate) fn revolution(rng: &mut Rng) -> Draft {
    if rng.chance(1, 4) {
        let c = rng.range(0, 2);
        let r = rng.range(1, 2);
        let h = rng.range(0, 1);
        let pts = [pt(c + r, 0, h), pt(c + r, 0, h + r), pt(c, 0, h + r)];
        let mut curve = bezier_curve_json(&pts);
        if let Some(map) = curve.as_object_mut() {
            map.insert("weights".into(), json!([1, "sqrt2/2", 1]));
        }
        let what_en = if c == 0 { "a sphere" } else { "a torus" };
        let what_es = if c == 0 { "una esfera" } else { "un toro" };
        return Draft::new(
            format!("Quadrant of {what_en}: surface of revolution about the Z axis of the quarter circle of centre ({c}, 0, {h}) and radius {r} in the XZ plane"),
            format!("Cuadrante de {what_es}: superficie de revolución alrededor del eje Z del cuarto de circunferencia de centro ({c}, 0, {h}) y radio {r} en el plano XZ"),
            vec![("curve", curve), ("arcs", json!(1))],
        );
    }
    let p = rng.pick(&[1, 2, 2]);
    let mut pts: Vec<P3> = Vec::new();
    let mut z = rng.range(0, 1);
    for _ in 0..=p {
        pts.push(pt(rng.range(0, 3), 0, z));
        z += rng.range(1, 2);
    }
    if pts.iter().all(|q| q[0] == int(0)) {
        if let Some(first) = pts.first_mut() {
            first[0] = int(1 + i64::from(rng.chance(1, 2)));
        }
    }
    Draft::new(
        format!(
            "Quadrant of the surface of revolution about the Z axis of the {} in the XZ plane: rational Bézier mesh and weights",
            degree_word_en(p)
        ),
        format!(
            "Cuadrante de la superficie de revolución alrededor del eje Z de{} del plano XZ: malla de control y pesos",
            with_article(p, true)
        ),
        vec![("curve", bezier_curve_json(&pts)), ("arcs", json!(1))],
    )
}
