//! Chapter 5 §7: interpolation and least-squares approximation by a patch, eq. (26)-(29).

use crate::draw::{height, uniform, Draft};
use crate::num::{int, num_json, numbers_json, point_json, set_text, P3, Q};
use crate::rng::Rng;
use serde_json::{json, Value};

/// A grid of data points a_ij = (x_i, y_j, z_ij) with x_i = i, y_j = j and small heights:
/// x and y are then linear in u and v, and only the heights carry the exercise.
fn grid(rng: &mut Rng, rows: usize, cols: usize) -> Vec<Vec<P3>> {
    (0..rows)
        .map(|i| {
            (0..cols)
                .map(|j| [int(i as i64), int(j as i64), height(rng, false)])
                .collect()
        })
        .collect()
}

fn grid_json(g: &[Vec<P3>]) -> Value {
    Value::Array(
        g.iter()
            .map(|r| Value::Array(r.iter().map(point_json).collect()))
            .collect(),
    )
}

/// `interpolate`: a Bézier patch of bidegree (m, n) through an (m + 1) × (n + 1) grid at
/// equally spaced parameters ({0, 1}, {0, 1/2, 1} or {0, 1/3, 2/3, 1}), eq. (26)-(27),
/// C = B_U^{-1} A B_V^{-T}; or, one problem in four, a bicubic spline (natural or Bessel
/// ends) through a 3 × 3 grid at the parameters {0, 1, 2}.
pub(crate) fn interpolate(rng: &mut Rng) -> Draft {
    if rng.chance(1, 4) {
        // 3 × 3 only: a 3 × 4 natural spline already shows denominators like 540.
        let points = grid(rng, 3, 3);
        let end = rng.pick(&["natural", "bessel"]);
        let u: Vec<Q> = (0..3).map(int).collect();
        let v = u.clone();
        let (su, sv) = (set_text(&u), set_text(&v));
        let (end_en, end_es) = match end {
            "natural" => ("natural end conditions", "condiciones naturales"),
            _ => ("Bessel end tangents", "tangentes de Bessel"),
        };
        return Draft::new(
            format!("Bicubic spline surface interpolating a 3 × 3 grid of points at u = {su}, v = {sv}, with {end_en}"),
            format!("Superficie spline bicúbica que interpola una malla de 3 × 3 puntos en u = {su}, v = {sv}, con {end_es}"),
            vec![
                ("basis", json!("bicubic")),
                ("end", json!(end)),
                ("u", numbers_json(&u)),
                ("v", numbers_json(&v)),
                ("points", grid_json(&points)),
            ],
        );
    }
    let (m, n) = rng.pick(&[(1, 2), (2, 1), (2, 2), (2, 2), (2, 3), (3, 2)]);
    let (u, v) = (uniform(m), uniform(n));
    let points = grid(rng, m + 1, n + 1);
    let (su, sv) = (set_text(&u), set_text(&v));
    Draft::new(
        format!("Bézier patch of bidegree ({m}, {n}) interpolating the {} × {} grid of points a_ij at u = {su}, v = {sv}", m + 1, n + 1),
        format!("Superficie de Bézier de bigrado ({m}, {n}) que interpola la malla de {} × {} puntos a_ij en u = {su}, v = {sv}", m + 1, n + 1),
        vec![
            ("basis", json!("bezier")),
            ("u", numbers_json(&u)),
            ("v", numbers_json(&v)),
            ("points", grid_json(&points)),
        ],
    )
}

/// `approximate`: the least-squares bilinear patch, eq. (28)-(29), B^t B C = B^t A, of a few
/// points (x, y, z) = (2u, 2v, z) with their parameters: the four corners and the centre
/// (as the notes' paraboloid), a 2 × 3 grid or the 3 × 3 grid at {0, 1/2, 1}.
pub(crate) fn approximate(rng: &mut Rng) -> Draft {
    let half = crate::num::frac(1, 2);
    let (zero, one) = (int(0), int(1));
    let params: Vec<(Q, Q)> = match rng.below(3) {
        0 => vec![
            (zero, zero),
            (one, zero),
            (zero, one),
            (one, one),
            (half, half),
        ],
        1 => [zero, one]
            .iter()
            .flat_map(|u| [zero, half, one].map(|v| (*u, v)))
            .collect(),
        _ => [zero, half, one]
            .iter()
            .flat_map(|u| [zero, half, one].map(|v| (*u, v)))
            .collect(),
    };
    let points: Vec<P3> = params
        .iter()
        .map(|(u, v)| [*u * int(2), *v * int(2), height(rng, false)])
        .collect();
    let k = points.len();
    Draft::new(
        format!("Least-squares Bézier patch of bidegree (1, 1) approximating {k} points with given parameters"),
        format!("Superficie de Bézier de bigrado (1, 1) que aproxima por mínimos cuadrados {k} puntos con parámetros dados"),
        vec![
            ("degree", json!([1, 1])),
            ("points", Value::Array(points.iter().map(point_json).collect())),
            (
                "params",
                Value::Array(params.iter().map(|(u, v)| json!([num_json(u), num_json(v)])).collect()),
            ),
        ],
    )
}
