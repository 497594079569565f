//! Chapter 5 §6: the continuity of two patches sharing a border, eq. (21)-(23).

use crate::draw::{height, mesh, Draft, Layout};
use crate::num::{add, bezier_surface_json, frac, int, scale, sub, transpose, P3, Q};
use crate::rng::Rng;
use serde_json::json;

/// How the second patch is built from the first.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    /// c̃_1j = c_mj + (Δu_1/Δu_0)(c_mj - c_{m-1,j}): C^1 by (22), equal lengths.
    C1,
    /// The same with parameter lengths (1, 2) or (2, 1), given in the problem.
    C1Lengths,
    /// c̃_1j - c̃_0j = λ_j (c_mj - c_{m-1,j}) with λ_j not all equal: parallel but unequal
    /// differences, the notes' example of a join that is C^0 and not C^1.
    Parallel,
    /// The second row drawn freely: C^0.
    Free,
    /// C^1 for equal lengths, but the problem gives lengths (1, 2) or (2, 1): only C^0.
    WrongLengths,
    /// One point of the common row moved: not even C^0.
    Broken,
}

/// `continuity`: the order of contact across the common border of two patches of the same
/// bidegree, built so that the join is C^1 by the condition (22), or is not (parallel but
/// unequal differences, a free second row, lengths that break (22), a broken border).
pub(crate) fn continuity(rng: &mut Rng) -> Draft {
    let kind = rng.pick(&[
        Kind::C1,
        Kind::C1,
        Kind::C1,
        Kind::C1Lengths,
        Kind::Parallel,
        Kind::Parallel,
        Kind::Free,
        Kind::WrongLengths,
        Kind::Broken,
    ]);
    // m across the border (u for border "u"), n along it.
    let m = if kind == Kind::Free || kind == Kind::Broken {
        rng.range(1, 2) as usize
    } else {
        2
    };
    let n = rng.range(1, 2) as usize;
    let first = mesh(rng, m, n, Layout::Grid, false);
    let last = first.last().cloned().unwrap_or_default();
    let before = first.get(m - 1).cloned().unwrap_or_default();
    let diffs: Vec<P3> = last.iter().zip(&before).map(|(a, b)| sub(a, b)).collect();
    let step = last
        .first()
        .zip(before.first())
        .map_or(int(1), |(a, b)| a[0] - b[0]);
    let lengths: Option<(i64, i64)> = match kind {
        Kind::C1Lengths | Kind::WrongLengths => Some(rng.pick(&[(1, 2), (2, 1)])),
        _ => None,
    };
    // Δu_1/Δu_0 of (22); the C^1 row is c̃_1j = c_mj + ratio (c_mj - c_{m-1,j}).
    let ratio = match (kind, lengths) {
        (Kind::C1Lengths, Some((d0, d1))) => frac(d1, d0),
        _ => int(1),
    };
    // The second patch continues the grid in x (with steps scaled by the ratio of the
    // lengths, so that x stays linear), with its own heights.
    let mut second: Vec<Vec<P3>> = (0..=m)
        .map(|k| {
            last.iter()
                .map(|p| {
                    if k == 0 {
                        *p
                    } else {
                        [
                            p[0] + step * ratio * int(k as i64),
                            p[1],
                            height(rng, false),
                        ]
                    }
                })
                .collect()
        })
        .collect();
    let continue_row = |ratio: Q| -> Vec<P3> {
        last.iter()
            .zip(&diffs)
            .map(|(p, d)| add(p, &scale(d, ratio)))
            .collect()
    };
    match kind {
        Kind::C1 | Kind::C1Lengths | Kind::WrongLengths => {
            if let Some(row) = second.get_mut(1) {
                *row = continue_row(ratio);
            }
        }
        Kind::Parallel => {
            let mut lambdas: Vec<i64> = (0..=n).map(|_| rng.range(1, 2)).collect();
            let first = lambdas.first().copied();
            if lambdas.iter().all(|l| Some(*l) == first) {
                let j = rng.below(lambdas.len() as u64) as usize;
                if let Some(l) = lambdas.get_mut(j) {
                    *l = 3 - *l;
                }
            }
            if let Some(row) = second.get_mut(1) {
                *row = last
                    .iter()
                    .zip(&diffs)
                    .zip(&lambdas)
                    .map(|((p, d), l)| add(p, &scale(d, int(*l))))
                    .collect();
            }
        }
        Kind::Free => {}
        Kind::Broken => {
            let j = rng.below((n + 1) as u64) as usize;
            if let Some(z) = second
                .first_mut()
                .and_then(|row| row.get_mut(j))
                .and_then(|p| p.get_mut(2))
            {
                *z += int(rng.pick(&[-1, 1]));
            }
        }
    }
    let border = rng.pick(&["u", "v"]);
    let (first, second) = if border == "u" {
        (first, second)
    } else {
        (transpose(&first), transpose(&second))
    };
    let (bm, bn) = (first.len() - 1, first.first().map_or(1, Vec::len) - 1);
    let side_en = format!("first's {border} = 1 meets second's {border} = 0");
    let side_es = format!("{border} = 1 de la primera con {border} = 0 de la segunda");
    let mut args = vec![
        ("first", bezier_surface_json(&first)),
        ("second", bezier_surface_json(&second)),
        ("border", json!(border)),
    ];
    let (mut len_en, mut len_es) = (String::new(), String::new());
    if let Some((d0, d1)) = lengths {
        len_en = format!(", parameter lengths Δ{border}_0 = {d0}, Δ{border}_1 = {d1}");
        len_es = format!(", longitudes de los intervalos Δ{border}_0 = {d0}, Δ{border}_1 = {d1}");
        args.push(("lengths", json!([d0, d1])));
    }
    Draft::new(
        format!("Order of continuity of two Bézier patches of bidegree ({bm}, {bn}) along their common border ({side_en}{len_en})"),
        format!("Orden de continuidad de dos superficies de Bézier de bigrado ({bm}, {bn}) a lo largo del borde común ({side_es}{len_es})"),
        args,
    )
}
