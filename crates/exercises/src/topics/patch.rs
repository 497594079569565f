//! Chapter 5 on one patch: closed forms, evaluation, restriction, elevation, derivatives,
//! normals and graphs (`002_20d988b092ff1833.txt` §2-§6).

use crate::draw::{
    bidegree, interval, mesh, parameter_set, poly2, tuple, unit_knots, Draft, Layout,
};
use crate::num::{
    bezier_surface_json, int, interval_text, mesh_json, num_json, numbers_json, set_text, Q,
};
use crate::rng::Rng;
use serde_json::{json, Value};

const BIDEGREES: [(usize, usize); 5] = [(1, 1), (1, 2), (2, 1), (2, 2), (2, 2)];

fn layout(rng: &mut Rng) -> Layout {
    rng.pick(&[Layout::Grid, Layout::Grid, Layout::Jitter, Layout::Free])
}

/// The kind of a patch drawn for a topic of chapter 5 (where the operation takes it).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Basis {
    /// A polynomial Bézier patch, eq. (1).
    Bezier,
    /// A rational Bézier patch: weights 1 but one or two 2s.
    Rational,
    /// A B-spline surface with one inner knot in u (and sometimes in v), on [0, 1]².
    Bspline,
}

/// A patch of `basis` and bidegree (m, n) laid out by `layout`: its JSON and its name in
/// English and Spanish ("the rational Bézier patch of bidegree (2, 1)").
fn patch(
    rng: &mut Rng,
    basis: Basis,
    (m, n): (usize, usize),
    layout: Layout,
    halves: bool,
) -> (Value, String, String) {
    match basis {
        Basis::Bezier => {
            let rows = mesh(rng, m, n, layout, halves);
            (
                bezier_surface_json(&rows),
                format!("the Bézier patch of bidegree ({m}, {n})"),
                format!("la superficie de Bézier de bigrado ({m}, {n})"),
            )
        }
        Basis::Rational => {
            let rows = mesh(rng, m, n, layout, halves);
            let mut weights: Vec<Vec<Q>> = vec![vec![int(1); n + 1]; m + 1];
            for _ in 0..rng.range(1, 2) {
                let (i, j) = (rng.below((m + 1) as u64), rng.below((n + 1) as u64));
                if let Some(w) = weights
                    .get_mut(i as usize)
                    .and_then(|r| r.get_mut(j as usize))
                {
                    *w = int(2);
                }
            }
            let mut surface = bezier_surface_json(&rows);
            if let Some(o) = surface.as_object_mut() {
                o.insert(
                    "weights".into(),
                    Value::Array(weights.iter().map(|r| numbers_json(r)).collect()),
                );
            }
            (
                surface,
                format!("the rational Bézier patch of bidegree ({m}, {n})"),
                format!("la superficie de Bézier racional de bigrado ({m}, {n})"),
            )
        }
        Basis::Bspline => {
            let (rows, cols) = (m + 2, n + 1 + usize::from(rng.chance(1, 2)));
            let points = mesh(rng, rows - 1, cols - 1, layout, halves);
            let (ku, kv) = (unit_knots(rows, m), unit_knots(cols, n));
            let (tu, tv) = (set_text(&ku), set_text(&kv));
            let surface = json!({
                "bspline": mesh_json(&points),
                "degree": [m, n],
                "knots": [numbers_json(&ku), numbers_json(&kv)],
            });
            (
                surface,
                format!("the B-spline surface of bidegree ({m}, {n}) with knots {tu} × {tv}"),
                format!("la superficie B-spline de bigrado ({m}, {n}) con nudos {tu} × {tv}"),
            )
        }
    }
}

/// `closed_form`: c(u, v) = Σ c_ij B_i^m(u) B_j^n(v), eq. (1), of a mesh of bidegree up to
/// (2, 2) with small integer (sometimes half) coordinates, one in three rational (a quotient,
/// weights 1 and 2).
pub(crate) fn closed_form(rng: &mut Rng) -> Draft {
    let (m, n) = rng.pick(&BIDEGREES);
    let l = layout(rng);
    let basis = rng.pick(&[Basis::Bezier, Basis::Bezier, Basis::Rational]);
    let (surface, what_en, what_es) = patch(rng, basis, (m, n), l, true);
    Draft::new(
        format!("Closed form c(u, v) of {what_en}"),
        format!("Parametrización c(u, v) de {what_es}"),
        vec![("surface", surface)],
    )
}

/// `evaluate`: c(u, v) by De Casteljau, eq. (9)-(11), at one to three parameter pairs whose
/// coordinates come from {0, 1/2, 1}, {0, 1/3, 2/3, 1} or {0, 1/4, 1/2, 3/4, 1} (one set per
/// direction), never only corners; one patch in three rational (weights 1 and 2).
pub(crate) fn evaluate(rng: &mut Rng) -> Draft {
    let (m, n) = rng.pick(&BIDEGREES);
    let l = layout(rng);
    let basis = rng.pick(&[Basis::Bezier, Basis::Bezier, Basis::Rational]);
    let (surface, what_en, what_es) = patch(rng, basis, (m, n), l, true);
    let (us, vs) = (parameter_set(rng), parameter_set(rng));
    let count = rng.range(1, 3) as usize;
    let mut params: Vec<(Q, Q)> = Vec::new();
    for _ in 0..count * 6 {
        if params.len() >= count {
            break;
        }
        let u = rng.choose(&us).copied().unwrap_or_else(|| int(0));
        let v = rng.choose(&vs).copied().unwrap_or_else(|| int(0));
        let corner = (u == int(0) || u == int(1)) && (v == int(0) || v == int(1));
        if corner || params.contains(&(u, v)) {
            continue;
        }
        params.push((u, v));
    }
    let list = params
        .iter()
        .map(|(u, v)| format!("({u}, {v})"))
        .collect::<Vec<_>>()
        .join(", ");
    Draft::new(
        format!("Evaluate {what_en} at (u, v) = {list} (De Casteljau)"),
        format!("Evalúa {what_es} en (u, v) = {list} (De Casteljau)"),
        vec![
            ("surface", surface),
            (
                "params",
                Value::Array(
                    params
                        .iter()
                        .map(|(u, v)| json!([num_json(u), num_json(v)]))
                        .collect(),
                ),
            ),
        ],
    )
}

/// An interval with both ends from one friendly parameter set.
fn sub_interval(rng: &mut Rng) -> (Q, Q) {
    let set = parameter_set(rng);
    interval(rng, &set)
}

/// `restrict`: the mesh of c restricted to [a, b] × [c, d], eq. (13),
/// c̃_ij = c[a^⟨m-i⟩, b^⟨i⟩; c^⟨n-j⟩, d^⟨j⟩], with the ends from one parameter set per
/// direction and integer coordinates (the answers' denominators divide 4^m · 4^n); one patch
/// in three rational (weights 1 and 2).
pub(crate) fn restrict(rng: &mut Rng) -> Draft {
    let (m, n) = rng.pick(&BIDEGREES);
    let basis = rng.pick(&[Basis::Bezier, Basis::Bezier, Basis::Rational]);
    let (surface, what_en, what_es) = patch(rng, basis, (m, n), Layout::Grid, false);
    let whole = (int(0), int(1));
    let (mut iu, mut iv) = (whole, whole);
    match rng.below(4) {
        0 => iu = sub_interval(rng),
        1 => iv = sub_interval(rng),
        _ => {
            iu = sub_interval(rng);
            iv = sub_interval(rng);
        }
    }
    if iu == whole && iv == whole {
        iu = (int(0), crate::num::frac(1, 2));
    }
    let (tu, tv) = (interval_text(&iu.0, &iu.1), interval_text(&iv.0, &iv.1));
    Draft::new(
        format!("Control mesh of {what_en} restricted to {tu} × {tv} (blossom)"),
        format!("Malla de control de {what_es} restringida a {tu} × {tv} (forma polar)"),
        vec![
            ("surface", surface),
            ("u", json!([num_json(&iu.0), num_json(&iu.1)])),
            ("v", json!([num_json(&iv.0), num_json(&iv.1)])),
        ],
    )
}

/// `elevate`: degree elevation by (r, s), eq. (14)-(15), of a Bézier patch, a rational one
/// (weights 1 and 2) or a B-spline surface (each piece elevated, the knots' multiplicities
/// raised).
pub(crate) fn elevate(rng: &mut Rng) -> Draft {
    let (m, n) = rng.pick(&BIDEGREES);
    let l = layout(rng);
    let basis = rng.pick(&[
        Basis::Bezier,
        Basis::Bezier,
        Basis::Rational,
        Basis::Bspline,
    ]);
    let (surface, what_en, what_es) = patch(rng, basis, (m, n), l, true);
    let (r, s) = rng.pick(&[(1, 0), (0, 1), (1, 1), (1, 0), (0, 1), (2, 0), (0, 2)]);
    let (mm, nn) = (m + r, n + s);
    Draft::new(
        format!("Elevate {what_en} by ({r}, {s}) to bidegree ({mm}, {nn})"),
        format!("Eleva el grado de {what_es} en ({r}, {s}) hasta bigrado ({mm}, {nn})"),
        vec![("surface", surface), ("by", json!([r, s]))],
    )
}

/// The name of ∂^{r+s}c/∂u^r∂v^s as the notes write it: `c_u`, `c_uv`, `c_vv`.
fn derivative_name(r: usize, s: usize) -> String {
    format!("c_{}{}", "u".repeat(r), "v".repeat(s))
}

/// `derivative`: ∂^{r+s}c/∂u^r∂v^s, eq. (16)-(18), of a mesh (or of a polynomial patch
/// (u, v, f(u, v))), sometimes on a border u = 0, 1 or v = 0, 1, eq. (19)-(20); the mesh a
/// Bézier patch, a rational one (the quotient rule) or a B-spline surface (piece by piece).
pub(crate) fn derivative(rng: &mut Rng) -> Draft {
    let polynomial = rng.chance(1, 4);
    let (m, n) = if polynomial {
        (3, 2)
    } else {
        rng.pick(&BIDEGREES)
    };
    let orders: Vec<(usize, usize)> = [(1, 0), (0, 1), (1, 1), (2, 0), (0, 2)]
        .into_iter()
        .filter(|&(r, s)| r <= m && s <= n)
        .collect();
    let (r, s) = rng.choose(&orders).copied().unwrap_or((1, 0));
    let (surface, what_en, what_es) = if polynomial {
        let f = poly2(rng, 3, 3, 2);
        let e = tuple(&["u".into(), "v".into(), f.to_expr("u", "v")]);
        (
            json!({"expr": e}),
            "the patch".to_string(),
            "la superficie".to_string(),
        )
    } else {
        let l = layout(rng);
        let basis = rng.pick(&[
            Basis::Bezier,
            Basis::Bezier,
            Basis::Rational,
            Basis::Bspline,
        ]);
        patch(rng, basis, (m, n), l, true)
    };
    let name = derivative_name(r, s);
    let mut args = vec![("surface", surface), ("order", json!([r, s]))];
    let (mut on_en, mut on_es) = (String::new(), String::new());
    if rng.chance(1, 3) {
        let var = rng.pick(&["u", "v"]);
        let at = rng.range(0, 1);
        on_en = format!(" on the border {var} = {at}");
        on_es = format!(" en el borde {var} = {at}");
        args.push(("at", json!({ var: at })));
    }
    Draft::new(
        format!("Partial derivative {name} of {what_en}{on_en}"),
        format!("Derivada parcial {name} de {what_es}{on_es}"),
        args,
    )
}

/// `normal`: n = c_u × c_v as a closed form and at the corners, eq. (25); one patch in five
/// of Bézier has a row collapsed to a point, so that two corners are degenerate; some patches
/// rational (weights 1 and 2) or B-spline surfaces (the corners of each piece).
pub(crate) fn normal(rng: &mut Rng) -> Draft {
    let (m, n) = rng.pick(&BIDEGREES);
    let l = rng.pick(&[Layout::Grid, Layout::Jitter]);
    let basis = rng.pick(&[
        Basis::Bezier,
        Basis::Bezier,
        Basis::Bezier,
        Basis::Rational,
        Basis::Bspline,
    ]);
    if basis != Basis::Bezier {
        let (surface, what_en, what_es) = patch(rng, basis, (m, n), l, false);
        return Draft::new(
            format!("Normal vector n(u, v) = c_u × c_v of {what_en}: closed form and the four corners"),
            format!("Vector normal n(u, v) = c_u × c_v de {what_es}: parametrización y las cuatro esquinas"),
            vec![("surface", surface)],
        );
    }
    let mut rows = mesh(rng, m, n, l, false);
    if rng.chance(1, 5) {
        if let Some(first) = rows.first_mut() {
            let p = first.first().copied();
            if let Some(p) = p {
                first.iter_mut().for_each(|q| *q = p);
            }
        }
    }
    let (m, n) = bidegree(&rows);
    Draft::new(
        format!("Normal vector n(u, v) = c_u × c_v of the Bézier patch of bidegree ({m}, {n}): closed form and the four corners"),
        format!("Vector normal n(u, v) = c_u × c_v de la superficie de Bézier de bigrado ({m}, {n}): parametrización y las cuatro esquinas"),
        vec![("surface", bezier_surface_json(&rows))],
    )
}

/// `graph`: the Bézier patch of bidegree (m, n) of the graph of f(x, y) over [0, 1]²,
/// eq. (3): c_ij = (i/m, j/n, ĉ_ij), with f a sum of one to three small monomials.
pub(crate) fn graph(rng: &mut Rng) -> Draft {
    let terms = rng.range(1, 3) as usize;
    let mut f = poly2(rng, terms, 2, 2);
    if f.degrees() == (0, 0) {
        f.0.push((1, 1, 1));
    }
    let (dx, dy) = f.degrees();
    let m = dx.max(1) + u32::from(rng.chance(1, 4));
    let n = dy.max(1) + u32::from(rng.chance(1, 4));
    let e = f.to_expr("x", "y");
    Draft::new(
        format!("Bézier patch of bidegree ({m}, {n}) of the graph of f(x, y) = {e} over [0, 1] × [0, 1]"),
        format!("Malla de control de bigrado ({m}, {n}) de la gráfica de f(x, y) = {e} sobre [0, 1] × [0, 1]"),
        vec![("f", json!(e)), ("degree", json!([m, n]))],
    )
}
