//! Chapter 6: surfaces generated from curves (`000_4f266b7df5f64f70.txt` §2-§6).

use crate::draw::{bridge, clamped_knots, poly2, tuple, Draft};
use crate::num::{
    add, bezier_curve_json, bezier_surface_json, bspline_curve_json, frac, int, point_text, pt,
    rational_curve_json, scale, set_text, sub, Poly2, P3, Q,
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

/// The weights (1, w, 1) of a rational quadratic, w one of 2, 3 and 1/2.
fn middle_weight(rng: &mut Rng) -> Vec<Q> {
    let w = rng.pick(&[int(2), int(3), frac(1, 2)]);
    vec![int(1), w, int(1)]
}

/// `(1, 2, 1)` in text.
fn weights_text(ws: &[Q]) -> String {
    format!(
        "({})",
        ws.iter().map(Q::to_string).collect::<Vec<_>>().join(", ")
    )
}

/// The kinds of curves a construction of chapter 6 is drawn with.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Curves {
    /// Polynomial Bézier polygons (the notes' meshes).
    Bezier,
    /// Polynomial maps in u (and v), as the notes' closed forms.
    Expression,
    /// A rational quadratic Bézier curve (weights (1, w, 1)) with a polynomial one.
    Rational,
    /// Quadratic B-spline curves with knots.
    Bspline,
}

/// The kinds of the two curves of a translational or ruled surface, Bézier twice as often.
const CURVE_KINDS: [Curves; 5] = [
    Curves::Bezier,
    Curves::Bezier,
    Curves::Expression,
    Curves::Rational,
    Curves::Bspline,
];

/// `translational`: c(u, v) = c(u) + d(v) - a, eq. (1), with c(0) = d(0) = a by
/// construction; Bézier polygons (mesh (4): c_ij = c_i + d_j - a), polynomial curves in u and
/// v, a rational quadratic c with a Bézier d, or two quadratic B-splines.
pub(crate) fn translational(rng: &mut Rng) -> Draft {
    let a = pt(rng.range(0, 2), rng.range(0, 2), rng.range(-1, 1));
    let kind = rng.pick(&CURVE_KINDS);
    let at = point_text(&a);
    match kind {
        Curves::Expression => {
            let (ax, ay, az) = (a[0].to_integer(), a[1].to_integer(), a[2].to_integer());
            let f = poly2(rng, 2, 3, 0);
            let g = poly2(rng, 2, 0, 3);
            let (sx, sy) = (rng.range(1, 2), rng.range(1, 2));
            // c(u) = (sx u + ax, ay, az + f(u) - f(0)), d(v) = (ax, sy v + ay, az + g(v) - g(0)).
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
                Poly2(vec![(sx, 1, 0), (ax, 0, 0)]).to_expr("u", "v"),
                ay.to_string(),
                lift(&f, az).to_expr("u", "v"),
            ]);
            let d = tuple(&[
                ax.to_string(),
                Poly2(vec![(sy, 0, 1), (ay, 0, 0)]).to_expr("u", "v"),
                lift(&g, az).to_expr("u", "v"),
            ]);
            Draft::new(
                format!(
                    "Translational surface c(u) + d(v) - a of the curves c(u) = {c} and d(v) = {d}"
                ),
                format!(
                    "Superficie traslacional c(u) + d(v) - a de las curvas c(u) = {c} y d(v) = {d}"
                ),
                vec![("c", json!({"expr": c})), ("d", json!({"expr": d}))],
            )
        }
        Curves::Rational => {
            let c = polygon(rng, a, 2, 1, false);
            let ws = middle_weight(rng);
            let q = rng.pick(&[1, 2]);
            let d = polygon(rng, a, q, 1, true);
            let wt = weights_text(&ws);
            Draft::new(
                format!(
                    "Translational surface of the rational quadratic Bézier curve c with weights {wt} and the {} d, which start at a = {at}: mesh, weights and closed form",
                    degree_word_en(q)
                ),
                format!(
                    "Superficie traslacional de la curva de Bézier racional cuadrática c de pesos {wt} y {} d, que parten de a = {at}: malla de control, pesos y parametrización",
                    with_article(q, false)
                ),
                vec![
                    ("c", rational_curve_json(&c, &ws)),
                    ("d", bezier_curve_json(&d)),
                ],
            )
        }
        Curves::Bspline => {
            let (nc, nd) = rng.pick(&[(4, 3), (3, 4), (4, 4), (5, 3), (4, 5)]);
            let c = polygon(rng, a, nc - 1, 1, false);
            let d = polygon(rng, a, nd - 1, 1, true);
            let (kc, kd) = (clamped_knots(nc, 2), clamped_knots(nd, 2));
            let (tc, td) = (set_text(&kc), set_text(&kd));
            Draft::new(
                format!(
                    "Translational surface of the quadratic B-spline curves c (knots {tc}) and d (knots {td}), which start at a = {at}: control mesh and knots"
                ),
                format!(
                    "Superficie traslacional de las curvas B-spline cuadráticas c (nudos {tc}) y d (nudos {td}), que parten de a = {at}: malla de control y nudos"
                ),
                vec![
                    ("c", bspline_curve_json(&c, 2, &kc)),
                    ("d", bspline_curve_json(&d, 2, &kd)),
                ],
            )
        }
        Curves::Bezier => {
            let (p, q) = rng.pick(&[(1, 2), (2, 1), (2, 2), (2, 2), (3, 1), (2, 3), (3, 2)]);
            let c = polygon(rng, a, p, 1, false);
            let d = polygon(rng, a, q, 1, true);
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
    }
}

/// `ruled`: c(u, v) = (1 - v) c1(u) + v c2(u), eq. (7), between two Bézier curves in the
/// planes y = 0 and y = 1 or 2 (of possibly different degrees: the lower one is elevated),
/// two polynomial curves (u, 0, f(u)) and (a u + b, h, g(u)), a rational quadratic c1 with a
/// Bézier c2, or two quadratic B-splines on the same knots.
pub(crate) fn ruled(rng: &mut Rng) -> Draft {
    let kind = rng.pick(&CURVE_KINDS);
    if kind == Curves::Expression {
        let f = poly2(rng, 2, 3, 0);
        let g = poly2(rng, 2, 3, 0);
        let x2 = Poly2(vec![(rng.range(1, 2), 1, 0), (rng.range(0, 1), 0, 0)]).to_expr("u", "v");
        let h = rng.range(1, 2);
        let c1 = tuple(&["u".into(), "0".into(), f.to_expr("u", "v")]);
        let c2 = tuple(&[x2, h.to_string(), g.to_expr("u", "v")]);
        return Draft::new(
            format!("Ruled surface (1 - v) c1(u) + v c2(u) between c1(u) = {c1} and c2(u) = {c2}"),
            format!("Superficie reglada (1 - v) c1(u) + v c2(u) entre c1(u) = {c1} y c2(u) = {c2}"),
            vec![("c1", json!({"expr": c1})), ("c2", json!({"expr": c2}))],
        );
    }
    let (p1, p2) = match kind {
        Curves::Rational => (2, rng.pick(&[1, 2])),
        Curves::Bspline => {
            let n = rng.pick(&[4, 5]);
            (n - 1, n - 1)
        }
        _ => rng.pick(&[(1, 2), (2, 2), (2, 2), (2, 3), (3, 3), (3, 2), (2, 1)]),
    };
    let y2 = rng.range(1, 2);
    let (z1, z2) = (rng.range(-1, 1), rng.range(-1, 1));
    let c1 = polygon(rng, pt(0, 0, z1), p1, 1, false);
    let mut c2 = polygon(rng, pt(0, y2, z2), p2, 1, false);
    // Lean the second curve a little so that the rulings are not all parallel to y.
    if let Some(last) = c2.last_mut() {
        last[0] += int(rng.range(0, 1));
    }
    match kind {
        Curves::Rational => {
            let ws = middle_weight(rng);
            let wt = weights_text(&ws);
            Draft::new(
                format!("Ruled surface (1 - v) c1(u) + v c2(u) between the rational quadratic Bézier curve c1 with weights {wt} and the Bézier curve c2 of degree {p2}: mesh and weights"),
                format!("Superficie reglada (1 - v) c1(u) + v c2(u) entre la curva de Bézier racional cuadrática c1 de pesos {wt} y la curva de Bézier c2 de grado {p2}: malla de control y pesos"),
                vec![("c1", rational_curve_json(&c1, &ws)), ("c2", bezier_curve_json(&c2))],
            )
        }
        Curves::Bspline => {
            let knots = clamped_knots(c1.len(), 2);
            let kt = set_text(&knots);
            Draft::new(
                format!("Ruled surface (1 - v) c1(u) + v c2(u) between the quadratic B-spline curves c1 and c2 with knots {kt}: control mesh and knots"),
                format!("Superficie reglada (1 - v) c1(u) + v c2(u) entre las curvas B-spline cuadráticas c1 y c2 de nudos {kt}: malla de control y nudos"),
                vec![
                    ("c1", bspline_curve_json(&c1, 2, &knots)),
                    ("c2", bspline_curve_json(&c2, 2, &knots)),
                ],
            )
        }
        _ => Draft::new(
            format!("Ruled Bézier surface (1 - v) c1(u) + v c2(u) between c1 (degree {p1}) and c2 (degree {p2}): mesh and closed form"),
            format!("Superficie reglada de Bézier (1 - v) c1(u) + v c2(u) entre c1 (grado {p1}) y c2 (grado {p2}): malla de control y parametrización"),
            vec![("c1", bezier_curve_json(&c1)), ("c2", bezier_curve_json(&c2))],
        ),
    }
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

/// A control polygon of `segments` + 1 points from `a` to `b` whose inner points lie on the
/// segment, a + k (b - a)/segments (rounded down to integers in x and y), with a small bump
/// in z.
fn boundary(rng: &mut Rng, a: &P3, b: &P3, segments: usize) -> Vec<P3> {
    (0..=segments)
        .map(|k| {
            if k == 0 {
                return *a;
            }
            if k == segments {
                return *b;
            }
            let t = frac(k as i64, segments as i64);
            let q = add(a, &scale(&sub(b, a), t));
            [
                q[0].floor(),
                q[1].floor(),
                q[2].round() + int(rng.range(-1, 2)),
            ]
        })
        .collect()
}

/// `coons`: the Coons patch c_c + c_d - c_cd, eq. (15)-(17), of four boundary curves that
/// meet at the corners by construction, (13): Bézier polygons (mesh (18)-(19)), polynomial
/// curves as in the notes, or quadratic B-splines with knots; blended bilinearly or, one in
/// three, with the cubic blending functions.
pub(crate) fn coons(rng: &mut Rng) -> Draft {
    let kind = rng.pick(&[
        Curves::Bezier,
        Curves::Bezier,
        Curves::Expression,
        Curves::Bspline,
    ]);
    let blend = if rng.chance(1, 3) { "cubic" } else { "linear" };
    let (blend_en, blend_es) = match blend {
        "cubic" => ("cubically blended", "con mezcla cúbica"),
        _ => ("bilinearly blended", "bilineal"),
    };
    let z: [i64; 4] = std::array::from_fn(|_| rng.range(-1, 2));
    let [z00, z10, z01, z11] = z;
    let mut args = Vec::new();
    // The curves' kind and knots, in the title: "the Bézier boundary curves c1, c2 (along u)".
    let (mut kind_en, mut kind_es) = (String::new(), String::new());
    let (mut knots_en, mut knots_es) = (
        [String::new(), String::new()],
        [String::new(), String::new()],
    );
    if kind == Curves::Expression {
        // x = a u, y = b v, heights bridging the corner heights (13).
        let (a, b) = (rng.range(1, 2), rng.range(1, 2));
        let au = Poly2(vec![(a, 1, 0)]).to_expr("u", "v");
        let bv = Poly2(vec![(b, 0, 1)]).to_expr("u", "v");
        let c1 = tuple(&[
            au.clone(),
            "0".into(),
            bridge(rng, z00, z10, true).to_expr("u", "v"),
        ]);
        let c2 = tuple(&[
            au,
            b.to_string(),
            bridge(rng, z01, z11, true).to_expr("u", "v"),
        ]);
        let d1 = tuple(&[
            "0".into(),
            bv.clone(),
            bridge(rng, z00, z01, false).to_expr("v", "u"),
        ]);
        let d2 = tuple(&[
            a.to_string(),
            bv,
            bridge(rng, z10, z11, false).to_expr("v", "u"),
        ]);
        for (k, e) in [("c1", c1), ("c2", c2), ("d1", d1), ("d2", d2)] {
            args.push((k, json!({ "expr": e })));
        }
    } else {
        // Control points per curve along u (c1, c2) and along v (d1, d2).
        let (nc, nd) = if kind == Curves::Bspline {
            rng.pick(&[(4, 3), (3, 4), (4, 4), (5, 3)])
        } else {
            let (p, q) = rng.pick(&[(2, 2), (3, 2), (2, 3), (2, 1), (1, 2), (3, 3), (3, 1)]);
            (p + 1, q + 1)
        };
        // Sides that are multiples of the segments keep the inner points on integers.
        let a = int((nc - 1) as i64 * rng.range(1, 2));
        let b = int((nd - 1) as i64 * rng.range(1, 2));
        let lean = int(rng.range(0, 1));
        let corner00 = [int(0), int(0), int(z00)];
        let corner10 = [a, int(0), int(z10)];
        let corner01 = [int(0), b, int(z01)];
        let corner11 = [a, b + lean, int(z11)];
        let c1 = boundary(rng, &corner00, &corner10, nc - 1);
        let c2 = boundary(rng, &corner01, &corner11, nc - 1);
        let d1 = boundary(rng, &corner00, &corner01, nd - 1);
        let d2 = boundary(rng, &corner10, &corner11, nd - 1);
        if kind == Curves::Bspline {
            let (kc, kd) = (clamped_knots(nc, 2), clamped_knots(nd, 2));
            let (tc, td) = (set_text(&kc), set_text(&kd));
            kind_en = "quadratic B-spline ".into();
            kind_es = " B-spline cuadráticas".into();
            knots_en = [format!(", knots {tc}"), format!(", knots {td}")];
            knots_es = [format!(", nudos {tc}"), format!(", nudos {td}")];
            for (k, c, knots) in [
                ("c1", c1, &kc),
                ("c2", c2, &kc),
                ("d1", d1, &kd),
                ("d2", d2, &kd),
            ] {
                args.push((k, bspline_curve_json(&c, 2, knots)));
            }
        } else {
            kind_en = "Bézier ".into();
            kind_es = " de Bézier".into();
            for (k, c) in [("c1", c1), ("c2", c2), ("d1", d1), ("d2", d2)] {
                args.push((k, bezier_curve_json(&c)));
            }
        }
    }
    if blend == "cubic" {
        args.push(("blend", json!("cubic")));
    }
    Draft::new(
        format!(
            "Coons patch ({blend_en}) of the {kind_en}boundary curves c1, c2 (along u{}) and d1, d2 (along v{})",
            knots_en[0],
            knots_en[1]
        ),
        format!(
            "Superficie de Coons ({blend_es}) de las curvas de borde{kind_es} c1, c2 (en u{}) y d1, d2 (en v{})",
            knots_es[0],
            knots_es[1]
        ),
        args,
    )
}

/// How much of the turn a surface of revolution sweeps.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Turn {
    /// A quarter turn, one arc (`arcs` = 1): a rational Bézier patch.
    Quadrant,
    /// Half a turn (`sweep` = 180, two arcs): a NURBS patch.
    Half,
    /// The full turn in four arcs (`arcs` = 4): a NURBS patch closed in v.
    Full,
}

impl Turn {
    fn arg(self) -> (&'static str, serde_json::Value) {
        match self {
            Turn::Quadrant => ("arcs", json!(1)),
            Turn::Half => ("sweep", json!(180)),
            Turn::Full => ("arcs", json!(4)),
        }
    }

    fn en(self) -> &'static str {
        match self {
            Turn::Quadrant => "Quadrant",
            Turn::Half => "Half turn (two arcs of 90°)",
            Turn::Full => "Full turn (four arcs of 90°)",
        }
    }

    fn es(self) -> &'static str {
        match self {
            Turn::Quadrant => "Cuadrante",
            Turn::Half => "Media vuelta (dos arcos de 90°)",
            Turn::Full => "Vuelta completa (cuatro arcos de 90°)",
        }
    }
}

/// The profile of a surface of revolution.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Profile {
    /// A segment or a parabola (polynomial Bézier).
    Polynomial,
    /// A rational quadratic Bézier curve with weights (1, w, 1).
    Rational,
    /// A quarter circle (weights 1, √2/2, 1): a piece of a sphere or a torus.
    QuarterCircle,
    /// A quadratic B-spline with 4 or 5 control points.
    Bspline,
}

/// A profile polygon in the XZ plane: `n` points with x in 0..3 (not all 0) and z rising.
fn profile_points(rng: &mut Rng, n: usize) -> Vec<P3> {
    let mut pts: Vec<P3> = Vec::new();
    let mut z = rng.range(0, 1);
    for _ in 0..n {
        pts.push(pt(rng.range(0, 3), 0, z));
        z += rng.range(1, 2);
    }
    if pts.iter().all(|q| q[0] == int(0)) {
        if let Some(first) = pts.first_mut() {
            first[0] = int(1 + i64::from(rng.chance(1, 2)));
        }
    }
    pts
}

/// `revolution`: the surface swept by a profile in the XZ plane about the Z axis, eq. (21),
/// rows of circles (weights √2/2 at the arcs' middle points): a quadrant (a rational Bézier
/// patch), half a turn or the full turn (NURBS); the profile a segment or a parabola, a
/// rational quadratic with weights (1, w, 1), a quarter circle (a piece of a sphere or a
/// torus) or a quadratic B-spline with knots.
pub(crate) fn revolution(rng: &mut Rng) -> Draft {
    let turn = rng.pick(&[
        Turn::Quadrant,
        Turn::Quadrant,
        Turn::Half,
        Turn::Full,
        Turn::Full,
    ]);
    let profile = rng.pick(&[
        Profile::Polynomial,
        Profile::Polynomial,
        Profile::Rational,
        Profile::QuarterCircle,
        Profile::Bspline,
        Profile::Bspline,
    ]);
    let (find_en, find_es) = if turn == Turn::Quadrant && profile != Profile::Bspline {
        (
            "rational Bézier mesh and weights",
            "malla de control y pesos",
        )
    } else {
        (
            "NURBS control mesh, weights and knots",
            "malla de control, pesos y nudos",
        )
    };
    let (curve, of_en, of_es) = match profile {
        Profile::QuarterCircle => {
            let c = rng.range(0, 2);
            let r = rng.range(1, 2);
            let h = rng.range(0, 1);
            let pts = [pt(c + r, 0, h), pt(c + r, 0, h + r), pt(c, 0, h + r)];
            let mut curve = bezier_curve_json(&pts);
            if let Some(map) = curve.as_object_mut() {
                map.insert("weights".into(), json!([1, "sqrt2/2", 1]));
            }
            let (what_en, what_es) = if c == 0 {
                ("part of a sphere", "parte de una esfera")
            } else {
                ("part of a torus", "parte de un toro")
            };
            (
                curve,
                format!("the quarter circle of centre ({c}, 0, {h}) and radius {r} ({what_en})"),
                format!(
                    "l cuarto de circunferencia de centro ({c}, 0, {h}) y radio {r} ({what_es})"
                ),
            )
        }
        Profile::Rational => {
            let pts = profile_points(rng, 3);
            let ws = middle_weight(rng);
            let wt = weights_text(&ws);
            (
                rational_curve_json(&pts, &ws),
                format!("the rational quadratic Bézier curve with weights {wt}"),
                format!(" la curva de Bézier racional cuadrática de pesos {wt}"),
            )
        }
        Profile::Bspline => {
            let n = rng.pick(&[4, 5]);
            let pts = profile_points(rng, n);
            let knots = clamped_knots(n, 2);
            let kt = set_text(&knots);
            (
                bspline_curve_json(&pts, 2, &knots),
                format!("the quadratic B-spline curve with knots {kt}"),
                format!(" la curva B-spline cuadrática de nudos {kt}"),
            )
        }
        Profile::Polynomial => {
            let p = rng.pick(&[1, 2, 2]);
            let pts = profile_points(rng, p + 1);
            (
                bezier_curve_json(&pts),
                format!("the {}", degree_word_en(p)),
                with_article(p, true),
            )
        }
    };
    Draft::new(
        format!(
            "{} of the surface of revolution about the Z axis of {of_en} in the XZ plane: {find_en}",
            turn.en()
        ),
        format!(
            "{} de la superficie de revolución alrededor del eje Z de{of_es} del plano XZ: {find_es}",
            turn.es()
        ),
        vec![("curve", curve), turn.arg()],
    )
}
