//! Chapter 5 §7: interpolation and least-squares approximation by a patch, eq. (26)-(29).

use crate::draw::{height, uniform, Draft};
use crate::num::{frac, int, mesh_json, num_json, numbers_json, point_json, set_text, P3, Q};
use crate::rng::Rng;
use serde_json::{json, Value};

/// A grid of data points a_ij = (x_i, y_j, z_ij) with x_i = i, y_j = j shifted by an origin
/// and small heights: x and y are then linear in u and v, and only the heights carry the
/// exercise.
fn grid(rng: &mut Rng, rows: usize, cols: usize, origin: (i64, i64)) -> Vec<Vec<P3>> {
    (0..rows)
        .map(|i| {
            (0..cols)
                .map(|j| {
                    [
                        int(origin.0 + i as i64),
                        int(origin.1 + j as i64),
                        height(rng, false),
                    ]
                })
                .collect()
        })
        .collect()
}

/// The Bernstein matrix of interpolation at the parameters t_0, ..., t_m: row k holds
/// B_0^m(t_k), ..., B_m^m(t_k) (B_U of eq. (27)).
fn bernstein_matrix(ts: &[Q]) -> Vec<Vec<Q>> {
    let m = ts.len().saturating_sub(1);
    ts.iter()
        .map(|t| {
            (0..=m)
                .map(|i| {
                    let binomial =
                        (0..i).fold(int(1), |b, k| b * int((m - k) as i64) / int((k + 1) as i64));
                    binomial * pow(*t, i) * pow(int(1) - *t, m - i)
                })
                .collect()
        })
        .collect()
}

fn pow(x: Q, e: usize) -> Q {
    (0..e).fold(int(1), |p, _| p * x)
}

/// The inverse of a square matrix by Gauss-Jordan elimination, or `None` when it is singular.
fn inverse(a: &[Vec<Q>]) -> Option<Vec<Vec<Q>>> {
    let n = a.len();
    let mut rows: Vec<Vec<Q>> = a
        .iter()
        .enumerate()
        .map(|(i, r)| {
            let mut row = r.clone();
            row.extend((0..n).map(|j| int(i64::from(i == j))));
            row
        })
        .collect();
    for col in 0..n {
        let pivot =
            (col..n).find(|&r| rows.get(r).and_then(|row| row.get(col)) != Some(&int(0)))?;
        rows.swap(col, pivot);
        let p = *rows.get(col)?.get(col)?;
        let pivot_row: Vec<Q> = rows.get(col)?.iter().map(|x| *x / p).collect();
        for (r, row) in rows.iter_mut().enumerate() {
            if r == col {
                *row = pivot_row.clone();
                continue;
            }
            let f = row.get(col).copied().unwrap_or_else(|| int(0));
            for (x, y) in row.iter_mut().zip(&pivot_row) {
                *x -= f * *y;
            }
        }
    }
    Some(
        rows.into_iter()
            .map(|r| r.into_iter().skip(n).collect())
            .collect(),
    )
}

/// A data vector p (heights at the parameters of one direction) and the control points
/// q = B⁻¹ p of the Bézier curve of degree m through them.
type Pair = (Vec<i64>, Vec<Q>);

/// The friendly pairs of the parameters `ts`: every data vector with entries in
/// -`reach`..=`reach`, not constant, whose control points q = B⁻¹ p are integers or halves
/// of absolute value at most 3. The heights of an interpolation problem are sums of products
/// of such vectors, so that its data and its answer are small by construction.
fn friendly_pairs(ts: &[Q], reach: i64) -> Vec<Pair> {
    let Some(inv) = inverse(&bernstein_matrix(ts)) else {
        return vec![];
    };
    let k = ts.len() as u32;
    let side = (2 * reach + 1) as u64;
    (0..side.pow(k))
        .filter_map(|code| {
            let p: Vec<i64> = (0..k)
                .map(|d| (code / side.pow(d) % side) as i64 - reach)
                .collect();
            if p.iter().all(|x| Some(x) == p.first()) {
                return None;
            }
            let q: Vec<Q> = inv
                .iter()
                .map(|row| row.iter().zip(&p).map(|(m, x)| *m * int(*x)).sum())
                .collect();
            let friendly = q
                .iter()
                .all(|x| *x.denom() <= 2 && x.numer().abs() <= 3 * *x.denom());
            friendly.then_some((p, q))
        })
        .collect()
}

/// The parameter sets drawn for a Bézier interpolation of degree m: equally spaced, and for
/// m = 2 the unequally spaced {0, 1/3, 1}, {0, 2/3, 1} and {0, 1/4, 1}.
fn parameter_sets(m: usize) -> Vec<Vec<Q>> {
    match m {
        2 => vec![
            uniform(2),
            uniform(2),
            vec![int(0), frac(1, 3), int(1)],
            vec![int(0), frac(2, 3), int(1)],
            vec![int(0), frac(1, 4), int(1)],
        ],
        // {0, 1/4, 3/4, 1} would show B_U's 27/64 in the steps.
        m => vec![uniform(m)],
    }
}

/// The grid coordinate of each parameter: x_k = origin + X t_k, X the least common multiple
/// of the parameters' denominators (so that x is an integer and linear in t).
fn grid_line(ts: &[Q], origin: i64) -> Vec<Q> {
    let scale = ts.iter().fold(1i64, |l, t| {
        let d = *t.denom();
        l / gcd(l, d) * d
    });
    ts.iter().map(|t| int(origin) + *t * int(scale)).collect()
}

fn gcd(a: i64, b: i64) -> i64 {
    if b == 0 {
        a.abs().max(1)
    } else {
        gcd(b, a % b)
    }
}

/// The heights z_ij = Σ s_t p_t(i) p'_t(j) + c of an interpolation problem of Bézier patch:
/// two products of friendly pairs (one factor with entries up to 3, the other up to 1) and a
/// constant, so that |z| ≤ 7 and the control points' heights are the same sums of the q's:
/// quarters at worst, of absolute value at most 19.
fn friendly_heights(rng: &mut Rng, us: &[Q], vs: &[Q]) -> Vec<Vec<i64>> {
    let (wide_u, narrow_u) = (friendly_pairs(us, 3), friendly_pairs(us, 1));
    let (wide_v, narrow_v) = (friendly_pairs(vs, 3), friendly_pairs(vs, 1));
    let narrow_u = if narrow_u.is_empty() {
        &wide_u
    } else {
        &narrow_u
    };
    let narrow_v = if narrow_v.is_empty() {
        &wide_v
    } else {
        &narrow_v
    };
    let zero = |n: usize| vec![0; n];
    let term = |rng: &mut Rng, a: &[Pair], b: &[Pair]| -> Vec<Vec<i64>> {
        let sign = rng.pick(&[1, -1]);
        let pa = rng
            .choose(a)
            .map_or_else(|| zero(us.len()), |p| p.0.clone());
        let pb = rng
            .choose(b)
            .map_or_else(|| zero(vs.len()), |p| p.0.clone());
        pa.iter()
            .map(|x| pb.iter().map(|y| sign * x * y).collect())
            .collect()
    };
    let mut z = vec![vec![0; vs.len()]; us.len()];
    for _ in 0..8 {
        let first = term(rng, &wide_u, narrow_v);
        let second = term(rng, narrow_u, &wide_v);
        let c = rng.range(-1, 1);
        z = first
            .iter()
            .zip(&second)
            .map(|(r, s)| r.iter().zip(s).map(|(a, b)| a + b + c).collect())
            .collect();
        let z0 = z.first().and_then(|r| r.first()).copied();
        if z.iter().flatten().any(|x| Some(*x) != z0) {
            break;
        }
    }
    z
}

/// `interpolate`: a Bézier patch of bidegree (m, n) through an (m + 1) × (n + 1) grid at the
/// parameters u_k, v_l, eq. (26)-(27), C = B_U^{-1} A B_V^{-T}; or, one problem in five, a
/// bicubic spline (natural or Bessel ends) through a 3 × 3 grid at the parameters {0, 1, 2}.
/// The Bézier grids lie at x = x_0 + X u_k, y = y_0 + Y v_l (X, Y making them integers) and
/// their heights are built from friendly pairs ([`friendly_heights`]): the data are integers
/// of absolute value at most 9 and the control points quarters at worst.
pub(crate) fn interpolate(rng: &mut Rng) -> Draft {
    if rng.chance(1, 5) {
        // 3 × 3 only: a 3 × 4 natural spline already shows denominators like 540.
        let origin = (rng.range(0, 1), rng.range(0, 1));
        let points = grid(rng, 3, 3, origin);
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
                ("points", mesh_json(&points)),
            ],
        );
    }
    let (m, n) = rng.pick(&[(1, 2), (2, 1), (2, 2), (2, 2), (2, 3), (3, 2), (3, 3)]);
    let u = rng
        .choose(&parameter_sets(m))
        .cloned()
        .unwrap_or_else(|| uniform(m));
    let v = rng
        .choose(&parameter_sets(n))
        .cloned()
        .unwrap_or_else(|| uniform(n));
    let (xs, ys) = (
        grid_line(&u, rng.range(0, 1)),
        grid_line(&v, rng.range(0, 1)),
    );
    let z = friendly_heights(rng, &u, &v);
    let points: Vec<Vec<P3>> = xs
        .iter()
        .zip(&z)
        .map(|(x, row)| ys.iter().zip(row).map(|(y, h)| [*x, *y, int(*h)]).collect())
        .collect();
    let (su, sv) = (set_text(&u), set_text(&v));
    Draft::new(
        format!("Bézier patch of bidegree ({m}, {n}) interpolating the {} × {} grid of points a_ij at u = {su}, v = {sv}", m + 1, n + 1),
        format!("Superficie de Bézier de bigrado ({m}, {n}) que interpola la malla de {} × {} puntos a_ij en u = {su}, v = {sv}", m + 1, n + 1),
        vec![
            ("basis", json!("bezier")),
            ("u", numbers_json(&u)),
            ("v", numbers_json(&v)),
            ("points", mesh_json(&points)),
        ],
    )
}

/// The heights of a bilinear patch at its corners, (z_00, z_10, z_01, z_11): small integers
/// of one parity whose sum is a multiple of 4, so that the patch is an integer at every
/// parameter pair of {0, 1/2, 1}².
fn bilinear_corners(rng: &mut Rng) -> [i64; 4] {
    let parity = rng.range(0, 1);
    let mut k: [i64; 4] = std::array::from_fn(|_| rng.range(-1, 1));
    if k.iter().sum::<i64>() % 2 != 0 {
        k[3] += if k[3] > 0 { -1 } else { 1 };
    }
    k.map(|k| parity + 2 * k)
}

/// The bilinear patch of corner heights `z` at (u, v).
fn bilinear(z: &[i64; 4], u: Q, v: Q) -> Q {
    let one = int(1);
    (one - u) * (one - v) * int(z[0])
        + u * (one - v) * int(z[1])
        + (one - u) * v * int(z[2])
        + u * v * int(z[3])
}

/// `approximate`: the least-squares bilinear patch, eq. (28)-(29), B^t B C = B^t A, of a few
/// points with their parameters: the four corners and the centre (as the notes' paraboloid),
/// a 2 × 3, 3 × 2 or 3 × 3 grid at {0, 1/2, 1}. Built backwards: the answer is a bilinear
/// patch with integer corners (x = x_0 + X u, y = y_0 + Y v, X, Y ∈ {2, 4}), and the data
/// are its values plus a residual orthogonal to the bilinear functions (B^t r = 0: the
/// centre's 4 against the corners' -1, or multiples of (1, -2, 1) along a line of three
/// parameters), so that the least-squares patch is that patch exactly.
pub(crate) fn approximate(rng: &mut Rng) -> Draft {
    let half = frac(1, 2);
    let (zero, one) = (int(0), int(1));
    let three = [zero, half, one];
    let variant = rng.below(4);
    let params: Vec<(Q, Q)> = match variant {
        0 => vec![
            (zero, zero),
            (one, zero),
            (zero, one),
            (one, one),
            (half, half),
        ],
        1 => [zero, one]
            .iter()
            .flat_map(|u| three.map(|v| (*u, v)))
            .collect(),
        2 => three
            .iter()
            .flat_map(|u| [zero, one].map(|v| (*u, v)))
            .collect(),
        _ => three.iter().flat_map(|u| three.map(|v| (*u, v))).collect(),
    };
    // The residual r(u, v) of each data point: B^t r = 0 for the bilinear basis.
    let second = |t: Q| -> i64 {
        if t == half {
            -2
        } else {
            1
        }
    };
    let index = |t: Q| -> usize {
        if t == zero {
            0
        } else if t == half {
            1
        } else {
            2
        }
    };
    let mut residual: Vec<i64> = vec![0; params.len()];
    for _ in 0..8 {
        let s: [i64; 3] = std::array::from_fn(|_| rng.range(-1, 1));
        let t: [i64; 3] = std::array::from_fn(|_| rng.range(-1, 1));
        let centre = rng.pick(&[1, -1]);
        residual = params
            .iter()
            .map(|&(u, v)| match variant {
                0 => centre * if u == half { 4 } else { -1 },
                1 => s.get(index(u)).copied().unwrap_or(0) * second(v),
                2 => second(u) * t.get(index(v)).copied().unwrap_or(0),
                _ => {
                    s.get(index(u)).copied().unwrap_or(0) * second(v)
                        + second(u) * t.get(index(v)).copied().unwrap_or(0)
                }
            })
            .collect();
        if residual.iter().any(|r| *r != 0) {
            break;
        }
    }
    let corners = bilinear_corners(rng);
    let (x0, y0) = (rng.range(0, 1), rng.range(0, 1));
    let (sx, sy) = (rng.pick(&[2, 2, 4]), rng.pick(&[2, 2, 4]));
    let points: Vec<P3> = params
        .iter()
        .zip(&residual)
        .map(|((u, v), r)| {
            [
                int(x0) + *u * int(sx),
                int(y0) + *v * int(sy),
                bilinear(&corners, *u, *v) + int(*r),
            ]
        })
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_parameter_set_has_friendly_pairs() {
        for m in 1..=3 {
            for ts in parameter_sets(m) {
                let b = bernstein_matrix(&ts);
                let inv = inverse(&b).unwrap();
                for (i, row) in b.iter().enumerate() {
                    for (j, _) in row.iter().enumerate() {
                        let e: Q = row.iter().zip(&inv).map(|(x, r)| *x * r[j]).sum();
                        assert_eq!(e, int(i64::from(i == j)), "{ts:?}");
                    }
                }
                let (wide, narrow) = (friendly_pairs(&ts, 3), friendly_pairs(&ts, 1));
                assert!(wide.len() >= 4 && !narrow.is_empty(), "{ts:?}: {wide:?}");
                for (p, q) in &wide {
                    let back: Vec<Q> = b
                        .iter()
                        .map(|r| r.iter().zip(q).map(|(x, y)| *x * *y).sum())
                        .collect();
                    assert_eq!(back, p.iter().map(|x| int(*x)).collect::<Vec<_>>());
                }
            }
        }
    }

    #[test]
    fn grid_lines_are_integers_linear_in_the_parameters() {
        let ts = vec![int(0), frac(1, 4), frac(3, 4), int(1)];
        assert_eq!(grid_line(&ts, 1), [1, 2, 4, 5].map(int));
        assert_eq!(
            grid_line(&[int(0), frac(2, 3), int(1)], 1),
            [1, 3, 4].map(int)
        );
        assert_eq!(grid_line(&uniform(2), 0), [0, 1, 2].map(int));
    }
}
