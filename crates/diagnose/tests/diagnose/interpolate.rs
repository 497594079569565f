//! Interpolation mistakes over random grids (the exercises' generator: Bézier patches and
//! bicubic splines) and over drawn curves: Bézier curves at uniform parameters, at
//! parameters by chord length (Pythagorean steps, so that the lengths are integers), and
//! cubic splines with Bessel or clamped ends. Each mistaken answer is also checked against
//! its own definition here: Bᵗ P = A, B_U C B_V = A, the problem with natural ends or
//! uniform parameters written out.

// the helpers below serve the tests only: they may expect, index and panic, as the tests do
#![allow(clippy::expect_used, clippy::indexing_slicing, clippy::panic)]

use crate::common::{generated, holds_over, key, report};
use cagd_diagnose::Mistaken;
use cagd_linalg::Point;
use cagd_problem::diagnosis::InterpolateMistake;
use cagd_problem::input::{CurveIn, SurfaceIn};
use cagd_problem::{Exact, Mistake, Number};
use cagd_scalar::FieldOps;
use proptest::prelude::*;
use serde_json::{json, Value};

fn int(n: i64) -> Number {
    <Number as FieldOps>::from_i64(n)
}

/// The answer of `m` on `problem`.
fn mistaken(problem: &Value, m: InterpolateMistake) -> Option<Mistaken> {
    key(problem)
        .mistaken
        .into_iter()
        .find(|(k, _)| *k == Mistake::Interpolate(m))
        .map(|(_, x)| x)
}

/// The key's results of `problem`, as JSON by name.
fn results(problem: &Value) -> Value {
    let key = key(problem);
    crate::common::written(&key.answer.expect("an answer").result)
}

/// The results of a mistaken answer, as JSON by name.
fn written(x: &Mistaken) -> Value {
    crate::common::written(&x.result)
}

/// Σ_i m_{k,i} p_i, row by row of `m`.
fn times(m: &[Vec<Number>], p: &[Point<Number>]) -> Vec<Point<Number>> {
    m.iter()
        .map(|row| {
            let mut out = Point::zero(p.first().map_or(0, Point::dim));
            for (c, q) in row.iter().zip(p) {
                out.add_scaled(q, c);
            }
            out
        })
        .collect()
}

/// B_{k,i} = C(n, i) t_k^i (1 − t_k)^(n − i) at the uniform parameters t_k = k/n.
fn bernstein_uniform(n: usize) -> Vec<Vec<Number>> {
    let binomial = |n: usize, i: usize| -> i64 {
        (0..i).fold(1i64, |acc, j| acc * (n - j) as i64 / (j as i64 + 1))
    };
    let power = |x: &Number, e: usize| (0..e).fold(int(1), |acc, _| acc * x.clone());
    (0..=n)
        .map(|k| {
            let t = int(k as i64) / int(n as i64);
            let s = int(1) - t.clone();
            (0..=n)
                .map(|i| int(binomial(n, i)) * power(&t, i) * power(&s, n - i))
                .collect()
        })
        .collect()
}

fn points(ps: &[[i64; 2]]) -> Vec<Point<Number>> {
    ps.iter().map(|p| Point::from_ints(p)).collect()
}

/// Steps of integer length and not along y: (3, 4), (2, 0)...
const PYTHAGOREAN: [[i64; 2]; 6] = [[3, 4], [4, 3], [2, 0], [-3, 4], [5, 12], [6, -8]];

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4))]

    #[test]
    fn every_interpolation_mistake_is_diagnosed(
        seed in 0u64..1_000_000,
        data in prop::collection::vec(prop::array::uniform2(-3i64..=3), 3..=4),
        steps in prop::collection::vec(0usize..6, 1..=2),
        spline in prop::collection::vec(prop::array::uniform2(-3i64..=3), 4),
        tangents in prop::collection::vec(prop::array::uniform2(-2i64..=2), 2),
        clamped in any::<bool>(),
    ) {
        let n = data.len() - 1;
        let uniform: Vec<String> = (0..=n).map(|k| format!("{k}/{n}")).collect();
        let curve = json!({"op": "interpolate", "points": data, "params": uniform});
        // a first step of length 1 along y, the others longer and across: the parameters
        // are not uniform and the points not on a line
        let mut chord_points = vec![[0i64, 0], [0, 1]];
        for s in steps.iter().copied() {
            let [x, y] = chord_points[chord_points.len() - 1];
            let [dx, dy] = PYTHAGOREAN[s];
            chord_points.push([x + dx, y + dy]);
        }
        let chord = json!({
            "op": "interpolate", "points": chord_points, "parametrization": "chord_length",
        });
        let mut ends = json!({
            "op": "interpolate", "basis": "bicubic", "points": spline, "params": [0, 1, 2, 3],
            "end": if clamped { "clamped" } else { "bessel" },
        });
        if clamped {
            ends["tangents"] = json!(tangents);
        }
        let mut problems = generated("interpolate", 6, seed);
        problems.extend([curve.clone(), chord.clone(), ends.clone()]);
        for m in InterpolateMistake::ALL {
            holds_over(&problems, Mistake::Interpolate(*m));
        }

        // the data as the polygon
        if let Some(x) = mistaken(&curve, InterpolateMistake::DataAsControl) {
            prop_assert_eq!(written(&x), json!({"curve": {"bezier": data.iter().map(|p| p.map(|c| c.to_string())).collect::<Vec<_>>()}}));
        }
        // Bᵗ P = A
        if let Some(x) = mistaken(&curve, InterpolateMistake::TransposedMatrix) {
            let Some((_, Exact::Curve(CurveIn::Bezier { points: p, .. }))) = x.result.first() else {
                panic!("a Bézier curve: {x:?}");
            };
            let b = bernstein_uniform(n);
            let bt: Vec<Vec<Number>> = (0..=n).map(|i| b.iter().map(|r| r[i].clone()).collect()).collect();
            prop_assert_eq!(times(&bt, p), points(&data));
        }
        // natural ends: the problem so written
        if let Some(x) = mistaken(&ends, InterpolateMistake::NaturalEnds) {
            let mut natural = ends.clone();
            natural["end"] = "natural".into();
            if let Some(o) = natural.as_object_mut() {
                o.remove("tangents");
            }
            prop_assert_eq!(written(&x), results(&natural));
        }
        // uniform parameters: the problem with t_k = k/n written out
        if let Some(x) = mistaken(&chord, InterpolateMistake::UniformForChordLength) {
            let k = chord_points.len() - 1;
            let params: Vec<String> = (0..=k).map(|i| format!("{i}/{k}")).collect();
            let written_out = json!({"op": "interpolate", "points": chord_points, "params": params});
            // the mistaken answer also gives the parameters it computed, the uniform ones
            let mistaken_answer = written(&x);
            prop_assert_eq!(&mistaken_answer["curve"], &results(&written_out)["curve"]);
            let uniform = json!({"op": "interpolate", "points": chord_points, "parametrization": "uniform"});
            prop_assert_eq!(&mistaken_answer["parameters"], &results(&uniform)["parameters"]);
        }
        // B_U C B_V = A over the generated Bézier grids, with the key's B_U and B_V
        for p in generated("interpolate", 4, seed) {
            let Some(x) = mistaken(&p, InterpolateMistake::UntransposedBv) else {
                continue;
            };
            let k = key(&p);
            let answer = k.answer.as_ref().expect("an answer");
            let (Some(Exact::Matrix(b_u)), Some(Exact::Matrix(b_v))) = (answer.step("B_U"), answer.step("B_V")) else {
                panic!("B_U and B_V");
            };
            let Some((_, Exact::Surface(SurfaceIn::Bezier { mesh, .. }))) = x.result.first() else {
                panic!("a Bézier patch: {x:?}");
            };
            // Y = C B_V row by row: y_i = Σ_j c_{i,j} B_V[j][l]; then B_U Y column by column
            let b_v_t: Vec<Vec<Number>> = (0..b_v.len()).map(|l| b_v.iter().map(|r| r[l].clone()).collect()).collect();
            let y: Vec<Vec<Point<Number>>> = mesh.to_rows().iter().map(|row| times(&b_v_t, row)).collect();
            let y_columns: Vec<Vec<Point<Number>>> = (0..b_v.len()).map(|l| y.iter().map(|r| r[l].clone()).collect()).collect();
            let a_columns: Vec<Vec<Point<Number>>> = y_columns.iter().map(|col| times(b_u, col)).collect();
            let data = p["points"].clone();
            let data: cagd_problem::spec::MeshIn = cagd_problem::spec::read_value(&data, &[]).expect("a grid");
            prop_assert_eq!(a_columns, data.0.to_columns());
        }
    }
}

/// The student's report of the snapshot tests (`tests/reports/interpolate.json`) is diagnosed as its
/// mistake alone.
#[test]
fn the_report_is_diagnosed() {
    assert_eq!(
        report(include_str!("../reports/interpolate.json")).mistakes(),
        [Mistake::Interpolate(InterpolateMistake::DataAsControl)]
    );
}
