//! Ruled-surface mistakes over random ruled problems (the exercises' generator: Bézier,
//! rational, B-spline and polynomial curves) and over two Bézier curves of drawn degrees,
//! whose mistaken meshes are also built here from the polygons, column by column.

// the helpers below serve the tests only: they may expect, index and panic, as the tests do
#![allow(clippy::expect_used, clippy::indexing_slicing, clippy::panic)]

use crate::common::{generated, holds_over, key, report};
use cagd_problem::diagnosis::RuledMistake;
use cagd_problem::input::SurfaceIn;
use cagd_problem::spec::read_value;
use cagd_problem::{Exact, Mistake, Number};
use proptest::prelude::*;
use serde_json::{json, Value};

type P = [i64; 3];

/// The problem `ruled` between the Bézier polygons `c1` and `c2`.
fn problem(c1: &[P], c2: &[P]) -> Value {
    json!({"op": "ruled", "c1": {"bezier": c1}, "c2": {"bezier": c2}})
}

/// The mistaken surface of `m` on `problem`, as JSON.
fn mistaken_surface(problem: &Value, m: RuledMistake) -> Option<Value> {
    let key = key(problem);
    let (_, x) = key.mistaken.iter().find(|(k, _)| *k == Mistake::Ruled(m))?;
    let (_, s) = x.result.iter().find(|(q, _)| q.name() == "surface")?;
    Some(s.to_json())
}

/// The Bézier mesh of rows `rows`, as the answer's JSON writes it.
fn mesh(rows: &[Vec<P>]) -> Value {
    let s: SurfaceIn<Number> = read_value(&json!({ "bezier": rows }), &[]).expect("a mesh");
    Exact::Surface(s).to_json()
}

fn polygon(points: usize) -> impl Strategy<Value = Vec<P>> {
    prop::collection::vec(prop::array::uniform3(-3i64..=3), points)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4))]

    #[test]
    fn every_ruled_mistake_is_diagnosed(
        seed in 0u64..1_000_000,
        p in 1usize..=3,
        step in 1usize..=2,
        c1 in polygon(4),
        c2 in polygon(4),
    ) {
        let q = (p + step - 1) % 3 + 1; // another degree in 1..=3
        let (same_a, same_b) = (&c1[..=p], &c2[..=p]);
        let other = &c2[..=q];
        let mut problems = generated("ruled", 6, seed);
        problems.push(problem(same_a, same_b));
        problems.push(problem(same_a, other));
        for m in RuledMistake::ALL {
            holds_over(&problems, Mistake::Ruled(*m));
        }

        // the same degree: each mistaken mesh from the polygons
        let eq = problem(same_a, same_b);
        let rows = |f: &dyn Fn(usize) -> Vec<P>| (0..=p).map(f).collect::<Vec<_>>();
        let exchanged = mesh(&rows(&|i| vec![same_b[i], same_a[i]]));
        let reversed = mesh(&rows(&|i| vec![same_a[i], same_b[p - i]]));
        let transposed = mesh(&[same_a.to_vec(), same_b.to_vec()]);
        let expected = [
            (RuledMistake::CurvesExchanged, exchanged),
            (RuledMistake::CurveReversed, reversed),
            (RuledMistake::MeshTransposed, transposed),
        ];
        let key_mesh = mesh(&rows(&|i| vec![same_a[i], same_b[i]]));
        for (m, want) in expected {
            match mistaken_surface(&eq, m) {
                Some(got) => prop_assert_eq!(got, want),
                // a mistake whose answer is the key's is left out
                None => prop_assert_eq!(&key_mesh, &want),
            }
        }
        prop_assert!(mistaken_surface(&eq, RuledMistake::LastPointRepeated).is_none());

        // another degree: the lower polygon padded with its last point
        let padded = |c: &[P], to: usize| -> Vec<P> {
            (0..=to).map(|i| c[i.min(c.len() - 1)]).collect()
        };
        let top = p.max(q);
        let (a, b) = (padded(same_a, top), padded(other, top));
        let want = mesh(&(0..=top).map(|i| vec![a[i], b[i]]).collect::<Vec<_>>());
        // (left out only when padding gives the raised polygon: a constant one)
        if let Some(got) = mistaken_surface(&problem(same_a, other), RuledMistake::LastPointRepeated) {
            prop_assert_eq!(got, want);
        }
    }
}

/// The student's report of the snapshot tests (`tests/reports/ruled.json`) is diagnosed as its
/// mistake alone.
#[test]
fn the_report_is_diagnosed() {
    assert_eq!(
        report(include_str!("../reports/ruled.json")).mistakes(),
        [Mistake::Ruled(RuledMistake::CurveReversed)]
    );
}
