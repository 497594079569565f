//! The largest legal problems: one per operation, at the default limits (degree 50, 1000
//! points, long numbers), each answered or refused within a budget of work counted by the
//! engine's checkpoints (`cagd_scalar::cancel::work`), not by a clock: the same verdict on
//! any machine, under any load.
//!
//! Unoptimized, these problems take minutes; the test runs in release builds only
//! (`cargo test --release -p cagd-problem --test battery`, which `.ci/run` calls; the
//! dependencies are those of `cargo run --release`). `-- --nocapture` prints the work and the
//! time of each case: docs/format.md's Limits section quotes them.
#![cfg_attr(debug_assertions, allow(dead_code, unused_imports))]
// Test helpers outside #[test] functions may index, as tests do (as the other test crates).
#![allow(clippy::indexing_slicing)]

use cagd_problem::{solve_problem, Limit, Limits, Problem, Settings};
use cagd_scalar::cancel::{with_work_budget, work};
use serde_json::{json, Value};
use std::sync::Arc;

/// The budget of every case, in checkpoints: about ten seconds of work in a release build on
/// this project's 2-core machine (a checkpoint is a point operation, a row of a product or an
/// elimination, one step of a gcd).
const BUDGET: u64 = 20_000_000;

/// A deterministic rational of about `digits` digits over about `digits` digits.
fn long(seed: u64, digits: usize) -> String {
    let mut x = seed
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    let mut digit = || {
        x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        char::from(b'1' + ((x >> 33) % 9) as u8)
    };
    let num: String = (0..digits).map(|_| digit()).collect();
    let den: String = (0..digits).map(|_| digit()).collect();
    format!("{num}/{den}")
}

/// A polygon of `n` points of space with coordinates of `digits` digits.
fn polygon(n: usize, digits: usize) -> Vec<Value> {
    (0..n)
        .map(|i| {
            let i = i as u64;
            json!([
                long(3 * i, digits),
                long(3 * i + 1, digits),
                long(3 * i + 2, digits)
            ])
        })
        .collect()
}

/// A polygon of `n` points of space with integer coordinates of `digits` digits.
fn integers(n: usize, digits: usize) -> Vec<Value> {
    let integer = |seed: u64| {
        long(seed, digits)
            .split('/')
            .next()
            .unwrap_or("1")
            .to_string()
    };
    (0..n)
        .map(|i| {
            let i = i as u64;
            json!([integer(3 * i), integer(3 * i + 1), integer(3 * i + 2)])
        })
        .collect()
}

/// A mesh of `rows` x `cols` points of space with coordinates of `digits` digits.
fn mesh(rows: usize, cols: usize, digits: usize) -> Vec<Vec<Value>> {
    (0..rows)
        .map(|i| {
            let row = polygon(cols, digits);
            row.into_iter()
                .enumerate()
                .map(|(j, p)| {
                    let seed = (i * cols + j) as u64;
                    json!([p[0], long(seed + 7, digits), p[2]])
                })
                .collect()
        })
        .collect()
}

/// `n` parameters in [0, 1] with `digits` digits.
fn params(n: usize, digits: usize) -> Vec<Value> {
    (0..n)
        .map(|k| {
            let d = "9".repeat(digits);
            json!(format!(
                "{}/{d}",
                (k as u64 + 1) * 7 % 10u64.pow(digits.min(15) as u32)
            ))
        })
        .collect()
}

/// Clamped uniform knots (notes' convention) for `n` control points of degree `p`.
fn knots(n: usize, p: usize) -> Vec<Value> {
    let inner = n - p - 1;
    let mut k = vec![json!(0); p];
    k.extend((1..=inner).map(|i| json!(format!("{i}/{}", inner + 1))));
    k.extend(vec![json!(1); p]);
    k
}

/// The cases: a name and the problem.
fn cases() -> Vec<(&'static str, Value)> {
    let curve50 = json!({"bezier": polygon(51, 100)});
    let patch = json!({"bezier": mesh(20, 50, 30)});
    let small_patch = json!({"bezier": mesh(4, 4, 100)});
    let w4: Vec<Vec<Value>> = (0..4)
        .map(|i| {
            (0..4)
                .map(|j| json!(format!("{}", 1 + (i * j) % 5)))
                .collect()
        })
        .collect();
    let rational_patch = json!({"bezier": mesh(4, 4, 20), "weights": w4});
    let bspline = json!({"bspline": polygon(990, 30), "degree": 3, "knots": knots(990, 3)});
    let bspline_surface = json!({"bspline": mesh(29, 33, 20), "degree": [3, 3],
        "knots": [knots(29, 3), knots(33, 3)]});
    // four corners, and a curve of degree 20 between two of them
    let corner = polygon(4, 30);
    let joining = |a: &Value, b: &Value, seed: usize| -> Vec<Value> {
        let mut inner = polygon(21 + seed, 30).split_off(seed);
        inner[0] = a.clone();
        inner[20] = b.clone();
        inner
    };
    // a profile in the XZ plane
    let profile: Vec<Value> = polygon(51, 30)
        .into_iter()
        .map(|p| json!([p[0], 0, p[2]]))
        .collect();
    let data: Vec<Vec<Value>> = mesh(20, 20, 10);
    let u20 = params(20, 10);
    let scattered: Vec<Value> = (0..200)
        .map(|k| {
            json!([
                format!("{}/199", k % 200),
                format!("{}/199", (k * 37) % 200)
            ])
        })
        .collect();
    let int_mesh = |rows: usize, cols: usize| -> Vec<Vec<Value>> {
        (0..rows)
            .map(|i| {
                (0..cols)
                    .map(|j| json!([i, j, (i * i + 3 * j * j) % 11]))
                    .collect()
            })
            .collect()
    };
    vec![
        // the cases of the issue that asked for this test (issue 19), then one of each
        // operation at its largest sizes
        (
            "evaluate a degree-50 curve of 200-digit numbers at a 200-digit parameter",
            json!({"op": "evaluate", "curve": {"bezier": polygon(51, 200)}, "params": params(1, 200)}),
        ),
        (
            "evaluate a degree-50 curve of 100-digit numbers at 100 parameters of 100 digits",
            json!({"op": "evaluate", "curve": curve50, "params": params(100, 100)}),
        ),
        (
            "evaluate a (19, 49) patch at 100 parameters",
            json!({"op": "evaluate", "surface": patch,
            "params": (0..100).map(|k| json!([format!("{k}/99"), format!("{}/99", 99 - k)])).collect::<Vec<_>>()}),
        ),
        (
            "closed form of a (19, 49) patch",
            json!({"op": "closed_form", "surface": patch}),
        ),
        (
            "restrict a (19, 49) patch",
            json!({"op": "restrict", "surface": patch, "u": ["1/3", "7/9"], "v": ["1/7", "5/6"]}),
        ),
        (
            "elevate a line by 49",
            json!({"op": "elevate", "curve": {"bezier": polygon(2, 100)}, "by": 49}),
        ),
        (
            "elevate a (18, 49) patch by (1, 0)",
            json!({"op": "elevate", "surface": {"bezier": mesh(19, 50, 30)}, "by": [1, 0]}),
        ),
        (
            "elevate a 31 x 32 B-spline surface by (10, 10)",
            json!({"op": "elevate", "by": [10, 10],
            "surface": {"bspline": int_mesh(31, 32), "degree": [3, 3], "knots": [knots(31, 3), knots(32, 3)]}}),
        ),
        (
            "elevate a B-spline curve of 990 points by 1",
            json!({"op": "elevate", "curve": bspline, "by": 1}),
        ),
        (
            "derivative (3, 3) of a rational 3x3 patch",
            json!({"op": "derivative", "surface": rational_patch, "order": [3, 3]}),
        ),
        (
            "derivative (10, 0) of a rational 3x3 patch",
            json!({"op": "derivative", "surface": rational_patch, "order": [10, 0]}),
        ),
        (
            "normal of a (30, 31) patch",
            json!({"op": "normal", "surface": {"bezier": int_mesh(31, 32)}}),
        ),
        (
            "normal of a rational 3x3 patch",
            json!({"op": "normal", "surface": rational_patch}),
        ),
        (
            "continuity of two (3, 3) patches",
            json!({"op": "continuity", "first": small_patch, "second": small_patch}),
        ),
        (
            "interpolate 20 x 20 points (Bezier)",
            json!({"op": "interpolate", "basis": "bezier", "u": u20, "v": u20, "points": data}),
        ),
        (
            "interpolate 20 x 20 points (bicubic)",
            json!({"op": "interpolate", "basis": "bicubic", "end": "natural",
            "u": (0..20).map(|k| json!(k)).collect::<Vec<_>>(), "v": (0..20).map(|k| json!(k)).collect::<Vec<_>>(), "points": data}),
        ),
        (
            "least squares (6, 6) through 200 points",
            json!({"op": "approximate", "degree": [6, 6],
            "points": polygon(200, 10), "params": scattered}),
        ),
        (
            "translational of two degree-50 curves",
            json!({"op": "translational", "c": curve50, "d": {"bezier": polygon(20, 100)}}),
        ),
        (
            "ruled between two degree-50 curves",
            json!({"op": "ruled", "c1": curve50, "c2": {"bezier": polygon(51, 90)}}),
        ),
        (
            "developable test of two degree-50 curves of 1000-digit integers",
            json!({"op": "developable",
            "c1": {"bezier": integers(51, 1000)}, "c2": {"bezier": integers(51, 999)}}),
        ),
        (
            "coons of four degree-20 curves",
            json!({"op": "coons",
                "c1": {"bezier": joining(&corner[0], &corner[1], 0)},
                "c2": {"bezier": joining(&corner[2], &corner[3], 1)},
                "d1": {"bezier": joining(&corner[0], &corner[2], 2)},
                "d2": {"bezier": joining(&corner[1], &corner[3], 3)}}),
        ),
        (
            "revolution of a degree-50 profile, full turn",
            json!({"op": "revolution", "curve": {"bezier": profile}, "arcs": 4}),
        ),
        (
            "insert a knot into a 29 x 33 B-spline surface",
            json!({"op": "insert_knot", "surface": bspline_surface,
            "direction": "u", "knot": "1/3", "times": 1}),
        ),
        (
            "graph of a bidegree-(30, 30) expression",
            json!({"op": "graph", "f": "(x + y/3)^15 * (x - 2 y)^15", "degree": [30, 30]}),
        ),
        (
            "circle of a radius of 300 digits, 6 arcs",
            json!({"op": "circle", "radius": long(1, 300), "arcs": 6}),
        ),
    ]
}

#[test]
#[cfg_attr(debug_assertions, ignore = "minutes unoptimized: run with --release")]
fn the_largest_legal_problems_are_answered_or_refused_within_the_budget() {
    let settings = Settings {
        limits: Limits {
            max_seconds: None,
            ..Limits::default()
        },
        steps: false,
    };
    let mut over = Vec::new();
    for (name, p) in cases() {
        let start = std::time::Instant::now();
        let before = work();
        let outcome = with_work_budget(BUDGET, || {
            Problem::read(&p, &settings.limits)
                .and_then(|problem| solve_problem(&Arc::new(problem), &settings))
        });
        let used = work() - before;
        let verdict = match &outcome {
            Ok(Ok(_)) => "answered".to_string(),
            Ok(Err(e)) => format!("refused: {e}"),
            Err(_) => {
                over.push(name);
                "over the budget".to_string()
            }
        };
        println!(
            "{name}: {verdict}; {used} checkpoints, {:.2} s",
            start.elapsed().as_secs_f64()
        );
    }
    assert!(
        over.is_empty(),
        "over the budget of {BUDGET} checkpoints: {over:?}"
    );
}

/// A triangle of degree `n` (the largest under the default points limit is 43: 990 points),
/// its coordinates made by `coord(i, k, c)` for the point b_{n-i, i-k, k}.
fn triangle(n: usize, dim: usize, coord: impl Fn(usize, usize, usize) -> Value) -> Value {
    let rows: Vec<Vec<Value>> = (0..=n)
        .map(|i| {
            (0..=i)
                .map(|k| Value::Array((0..dim).map(|c| coord(i, k, c)).collect()))
                .collect()
        })
        .collect();
    json!(rows)
}

/// Weights 1..9 in the shape of a triangle of degree `n`.
fn triangle_weights(n: usize) -> Value {
    json!((0..=n)
        .map(|i| (0..=i).map(|k| 1 + (i + 2 * k) % 9).collect::<Vec<_>>())
        .collect::<Vec<_>>())
}

/// The heavy problems of issue 32 (docs/format.md, Limits, measures each with the `cagd`
/// binary): the limit each is refused by, or `None` when it may be answered or stopped at the
/// deadline (how long it takes depends on the machine).
fn heavy_cases() -> Vec<(&'static str, Value, Option<Limit>)> {
    // 1000 parameters with unrelated 3-digit denominators
    let params: Vec<Value> = (0..1000u64)
        .map(|k| {
            let q = 101 + (k * 7919) % 898;
            let s = 101 + (k * 104729 + 13) % 898;
            json!([
                format!("{}/{q}", (k * 31) % (q - 1) + 1),
                format!("{}/{s}", (k * 17) % (s - 1) + 1)
            ])
        })
        .collect();
    let points: Vec<Value> = (0..1000)
        .map(|k| json!([k % 10, (k * 3) % 10, (k * 7) % 10]))
        .collect();
    let digit = |i: usize, k: usize, c: usize| match c {
        0 => json!((i * 7 + k * 3 + 1) % 10),
        1 => json!((i * 5 + k) % 10),
        _ => json!((i * i + 3 * k * k + i * k) % 10),
    };
    let one_digit = triangle(43, 3, digit);
    let mut seed = 0u64;
    let long_coords: Vec<Vec<Value>> = (0..=43)
        .map(|i| {
            (0..=i)
                .map(|_| {
                    (0..4)
                        .map(|_| {
                            seed += 1;
                            json!(long(seed, 30))
                        })
                        .collect::<Vec<_>>()
                })
                .map(Value::Array)
                .collect()
        })
        .collect();
    vec![
        (
            "least squares (30, 31) through 1000 points, unrelated 3-digit denominators",
            json!({"op": "approximate", "degree": [30, 31], "params": params, "points": points}),
            Some(Limit::Memory),
        ),
        (
            "Gaussian curvature of a degree-43 triangle of one-digit integers",
            json!({"op": "gaussian_curvature", "triangle": {"triangle": one_digit}}),
            None,
        ),
        (
            "Gaussian curvature of a rational degree-43 triangle of one-digit integers",
            json!({"op": "gaussian_curvature", "triangle": {"triangle": one_digit,
                "weights": triangle_weights(43)}}),
            None,
        ),
        (
            "closed form of a rational degree-43 triangle in R^4 of 30-digit numbers",
            json!({"op": "closed_form", "triangle": {"triangle": long_coords,
                "weights": triangle_weights(43)}}),
            None,
        ),
    ]
}

/// The heavy problems of issue 32 under the default limits (deadline and memory budget
/// included, as `cagd solve` runs them): each answered, or refused by the limit it names (the
/// least squares before the work, by its memory), or stopped at its deadline; and within the
/// budget of checkpoints whatever the machine.
#[test]
#[cfg_attr(debug_assertions, ignore = "minutes unoptimized: run with --release")]
fn the_heavy_problems_are_answered_or_refused_by_a_limit() {
    let settings = Settings {
        limits: Limits::default(),
        steps: false,
    };
    let mut wrong = Vec::new();
    for (name, p, refused_by) in heavy_cases() {
        let start = std::time::Instant::now();
        let before = work();
        let outcome = with_work_budget(BUDGET, || {
            Problem::read(&p, &settings.limits)
                .and_then(|problem| solve_problem(&Arc::new(problem), &settings))
        });
        let used = work() - before;
        let verdict = match &outcome {
            Ok(Ok(_)) => "answered".to_string(),
            Ok(Err(e)) => format!("refused: {e}"),
            Err(_) => "over the budget".to_string(),
        };
        let right = match (&outcome, refused_by) {
            (Ok(Err(e)), Some(limit)) => e.limit == Some(limit),
            (_, Some(_)) => false,
            (Ok(Ok(_)), None) => true,
            (Ok(Err(e)), None) => e.limit == Some(Limit::Seconds),
            (Err(_), None) => false,
        };
        if !right {
            wrong.push(name);
        }
        println!(
            "{name}: {verdict}; {used} checkpoints, {:.2} s",
            start.elapsed().as_secs_f64()
        );
    }
    assert!(
        wrong.is_empty(),
        "not answered nor refused by their limit: {wrong:?}"
    );
}
