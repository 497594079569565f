//! Translational-surface mistakes over random translational problems (the exercises'
//! generator: Bézier, rational, B-spline and polynomial curves) and over two rational
//! Bézier curves from a drawn common point a, whose mistaken meshes and weights are also
//! built here: c_{1i} + d_{1j}, w_{1i} + ω_{1j} − 1.

// the helpers below serve the tests only: they may expect, index and panic, as the tests do
#![allow(clippy::expect_used, clippy::indexing_slicing, clippy::panic)]

use crate::common::{generated, holds_over, key, report};
use cagd_problem::diagnosis::TranslationalMistake;
use cagd_problem::input::SurfaceIn;
use cagd_problem::spec::read_value;
use cagd_problem::{Exact, Mistake, Number};
use proptest::prelude::*;
use serde_json::{json, Value};

type P = [i64; 3];

/// The mistaken surface of `m` on `problem`, as JSON.
fn mistaken_surface(problem: &Value, m: TranslationalMistake) -> Option<Value> {
    let key = key(problem);
    let (_, x) = key
        .mistaken
        .iter()
        .find(|(k, _)| *k == Mistake::Translational(m))?;
    let (_, s) = x.result.iter().find(|(q, _)| q.name() == "surface")?;
    Some(s.to_json())
}

/// The rational Bézier surface of mesh `rows` and weights `weights`, as JSON.
fn surface(rows: &[Vec<P>], weights: &[Vec<i64>]) -> Value {
    let s: SurfaceIn<Number> =
        read_value(&json!({ "bezier": rows, "weights": weights }), &[]).expect("a surface");
    Exact::Surface(s).to_json()
}

fn add(p: P, q: P) -> P {
    [p[0] + q[0], p[1] + q[1], p[2] + q[2]]
}

fn sub(p: P, q: P) -> P {
    [p[0] - q[0], p[1] - q[1], p[2] - q[2]]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4))]

    #[test]
    fn every_translational_mistake_is_diagnosed(
        seed in 0u64..1_000_000,
        a in prop::array::uniform3(-2i64..=2),
        c_steps in prop::collection::vec(prop::array::uniform3(-2i64..=2), 1..=2),
        d_steps in prop::collection::vec(prop::array::uniform3(-2i64..=2), 1..=2),
        w in prop::collection::vec(1i64..=3, 2),
        omega in prop::collection::vec(1i64..=3, 2),
    ) {
        // polygons from a, the first weights 1
        let walk = |steps: &[P]| -> Vec<P> {
            let mut out = vec![a];
            for s in steps {
                let last = out[out.len() - 1];
                out.push(add(last, *s));
            }
            out
        };
        let (c, d) = (walk(&c_steps), walk(&d_steps));
        let weights = |w: &[i64], n: usize| -> Vec<i64> {
            (0..n).map(|i| if i == 0 { 1 } else { w[i - 1] }).collect()
        };
        let (wc, wd) = (weights(&w, c.len()), weights(&omega, d.len()));
        let built = json!({
            "op": "translational",
            "c": {"bezier": c, "weights": wc},
            "d": {"bezier": d, "weights": wd},
        });
        let mut problems = generated("translational", 6, seed);
        problems.push(built.clone());
        for m in TranslationalMistake::ALL {
            holds_over(&problems, Mistake::Translational(*m));
        }

        // each mistaken mesh and weights from the polygons
        let grid = |f: &dyn Fn(usize, usize) -> P| -> Vec<Vec<P>> {
            (0..c.len()).map(|i| (0..d.len()).map(|j| f(i, j)).collect()).collect()
        };
        let products: Vec<Vec<i64>> =
            wc.iter().map(|x| wd.iter().map(|y| x * y).collect()).collect();
        let sums: Vec<Vec<i64>> =
            wc.iter().map(|x| wd.iter().map(|y| x + y - 1).collect()).collect();
        let right = grid(&|i, j| sub(add(c[i], d[j]), a));
        let kept = grid(&|i, j| add(c[i], d[j]));
        let end = c[c.len() - 1];
        let other_end = grid(&|i, j| sub(add(c[i], d[j]), end));
        let expected = [
            (TranslationalMistake::CommonPointKept, surface(&kept, &products)),
            (TranslationalMistake::OtherEndSubtracted, surface(&other_end, &products)),
            (TranslationalMistake::WeightsAdded, surface(&right, &sums)),
        ];
        let key_surface = surface(&right, &products);
        for (m, want) in expected {
            match mistaken_surface(&built, m) {
                Some(got) => prop_assert_eq!(got, want),
                None => prop_assert_eq!(&key_surface, &want),
            }
        }
    }
}

/// The student's report of the snapshot tests (`tests/reports/translational.json`) is diagnosed as its
/// mistake alone.
#[test]
fn the_report_is_diagnosed() {
    assert_eq!(
        report(include_str!("../reports/translational.json")).mistakes(),
        [Mistake::Translational(
            TranslationalMistake::CommonPointKept
        )]
    );
}
