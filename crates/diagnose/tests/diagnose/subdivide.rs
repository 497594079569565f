//! Restriction and subdivision mistakes over random problems: the exercises' restrictions of
//! patches (rational ones too), and curves and patches drawn from small integers (subdivided
//! at t, in u, in v or both; restricted), each mistaken answer also checked against an
//! independent computation.

// test helpers: a problem the test builds has an answer, a result its shape
#![allow(clippy::expect_used, clippy::panic, clippy::indexing_slicing)]

use crate::common::{generated, holds_over, key};
use cagd_diagnose::change::{reverse, transpose};
use cagd_problem::diagnosis::SubdivideMistake;
use cagd_problem::{Exact, Mistake, Quantity};
use proptest::prelude::*;
use serde_json::{json, Value};

fn polygon(points: &[(i64, i64)], weights: Option<&[i64]>) -> Value {
    let mut c = json!({ "bezier": points.iter().map(|(x, y)| json!([x, y])).collect::<Vec<_>>() });
    if let Some(w) = weights {
        c["weights"] = json!(w);
    }
    c
}

/// A 3 × 2 mesh of heights `z` over the grid (i, j).
fn mesh(z: &[i64]) -> Value {
    let rows: Vec<Value> = (0..3)
        .map(|i| {
            json!((0..2)
                .map(|j| json!([i, j, z[2 * i + j]]))
                .collect::<Vec<_>>())
        })
        .collect();
    json!({ "bezier": rows })
}

/// The mistaken result `q` of `m` on `problem` (`None` when it does not apply).
fn mistaken(problem: &Value, m: SubdivideMistake, q: &Quantity) -> Option<Exact> {
    let key = key(problem);
    let (_, x) = key
        .mistaken
        .iter()
        .find(|(k, _)| *k == Mistake::Subdivide(m))?;
    x.result
        .iter()
        .find(|(k, _)| k == q)
        .map(|(_, x)| x.clone())
}

/// The key's result `q`.
fn solved(problem: &Value, q: &Quantity) -> Exact {
    let a = key(problem).answer.expect("an answer");
    a.result
        .into_iter()
        .find(|(k, _)| k == q)
        .expect("the result")
        .1
}

/// A Bézier curve's control points.
fn polygon_of(x: &Exact) -> Vec<cagd_linalg::Point<cagd_problem::Number>> {
    match x {
        Exact::Curve(cagd_problem::input::CurveIn::Bezier { points, .. }) => points.clone(),
        _ => panic!("not a Bézier curve: {x:?}"),
    }
}

fn points() -> impl Strategy<Value = Vec<(i64, i64)>> {
    prop::collection::vec((-3i64..=3, -3i64..=3), 3..=4)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4))]

    #[test]
    fn every_subdivision_mistake_is_diagnosed(
        seed in 0u64..1_000_000,
        ps in points(),
        ws in prop::collection::vec(1i64..=3, 4),
        z in prop::collection::vec(-3i64..=3, 6),
        k in 1i64..=4,
        l in 1i64..=4,
    ) {
        let w = &ws[..ps.len()];
        let t = format!("{k}/5");
        let s = format!("{l}/6");
        let mut problems = generated("restrict", 3, seed);
        problems.extend([
            json!({"op": "subdivide", "curve": polygon(&ps, None), "t": t}),
            json!({"op": "subdivide", "curve": polygon(&ps, Some(w)), "t": t}),
            json!({"op": "subdivide", "surface": mesh(&z), "u": t}),
            json!({"op": "subdivide", "surface": mesh(&z), "v": t}),
            json!({"op": "subdivide", "surface": mesh(&z), "u": t, "v": s}),
            json!({"op": "restrict", "curve": polygon(&ps, None), "t": [format!("{k}/10"), format!("{}/10", 5 + l)]}),
            json!({"op": "restrict", "surface": mesh(&z), "u": [t, 1], "v": [0, s]}),
        ]);
        for m in SubdivideMistake::ALL {
            holds_over(&problems, Mistake::Subdivide(*m));
        }
    }

    #[test]
    fn the_subdivision_mistakes_are_what_they_say(
        ps in points(),
        ws in prop::collection::vec(1i64..=3, 4),
        z in prop::collection::vec(-3i64..=3, 6),
        k in 1i64..=4,
        l in 1i64..=4,
    ) {
        let w = &ws[..ps.len()];
        let t = format!("{k}/5");
        let s = format!("{l}/6");
        let curves = Quantity::Curves;
        for weights in [None, Some(w)] {
            let p = json!({"op": "subdivide", "curve": polygon(&ps, weights), "t": t});
            // at 1 − t: the reversed curve's pieces at t, reversed and in the other order
            let rev: Vec<_> = ps.iter().rev().copied().collect();
            let wrev: Vec<i64> = w.iter().rev().copied().collect();
            let r = json!({
                "op": "subdivide",
                "curve": polygon(&rev, weights.map(|_| wrev.as_slice())),
                "t": t,
            });
            if let (Some(Exact::List(x)), Exact::List(y)) = (
                mistaken(&p, SubdivideMistake::AtOneMinusT, &curves),
                solved(&r, &curves),
            ) {
                prop_assert_eq!(x, vec![reverse(&y[1]).unwrap(), reverse(&y[0]).unwrap()]);
            }
            // the right piece reversed: it starts at the last control point, ends at c(t)
            if let (Some(Exact::List(x)), Exact::List(y)) = (
                mistaken(&p, SubdivideMistake::RightPieceReversed, &curves),
                solved(&p, &curves),
            ) {
                prop_assert_eq!(&x[0], &y[0]);
                let (right, left) = (polygon_of(&x[1]), polygon_of(&y[0]));
                let last = ps.last().map(|(a, b)| cagd_linalg::Point::from_ints(&[*a, *b]));
                prop_assert_eq!(right.first(), last.as_ref());
                prop_assert_eq!(right.last(), left.last());
            }
        }
        // points on the curve: the curve evaluated at a + i(b − a)/n
        let (a, b) = (k, 5 + l); // over 10
        let p = json!({
            "op": "restrict",
            "curve": polygon(&ps, None),
            "t": [format!("{a}/10"), format!("{b}/10")],
        });
        if let Some(Exact::Curve(cagd_problem::input::CurveIn::Bezier { points, .. })) =
            mistaken(&p, SubdivideMistake::PointsOnCurve, &Quantity::Curve)
        {
            let n = ps.len() as i64 - 1;
            let params: Vec<String> = (0..=n)
                .map(|i| format!("{}/{}", a * n + i * (b - a), 10 * n))
                .collect();
            let e = json!({"op": "evaluate", "curve": polygon(&ps, None), "params": params});
            prop_assert_eq!(Exact::Points(points), solved(&e, &Quantity::Points));
        }
        // u and v exchanged: the transposed patch restricted as written, transposed back
        let p = json!({"op": "restrict", "surface": mesh(&z), "u": [t, 1], "v": [0, s]});
        let transposed = transpose(&Exact::Surface(
            cagd_problem::spec::read_value(&mesh(&z), &[]).unwrap(),
        ))
        .unwrap();
        let Exact::Surface(ts) = &transposed else { unreachable!() };
        let ts_json = Exact::Surface(ts.clone()).to_json();
        let pt = json!({"op": "restrict", "surface": ts_json, "u": [t, 1], "v": [0, s]});
        if let Some(x) = mistaken(&p, SubdivideMistake::UvSwapped, &Quantity::Surface) {
            prop_assert_eq!(Some(x), transpose(&solved(&pt, &Quantity::Surface)));
        }
    }
}

/// The student's report of `tests/reports/subdivide.json` is diagnosed as its mistake, alone.
#[test]
fn the_students_report_is_diagnosed() {
    let text = include_str!("../reports/subdivide.json");
    let problem: Value = serde_json::from_str(text).expect("the report reads");
    let verdict = cagd_diagnose::diagnose(&problem, &crate::common::settings());
    let a = verdict.assessment.expect("an assessment");
    assert!(!a.correct());
    assert_eq!(
        a.mistakes(),
        [Mistake::Subdivide(SubdivideMistake::PointsOnCurve)]
    );
}
