//! Circle mistakes over random circles and arcs (a radius, a center, N = 3, 4 or 6 arcs, or
//! an arc of a sweep of 60° to 270°), with the mistaken circles checked against the
//! geometry: the middle vertices on the circle, the weights, the knots.

use crate::common::{holds_over, key, settings};
use cagd_linalg::Point;
use cagd_problem::diagnosis::CircleMistake;
use cagd_problem::input::CurveIn;
use cagd_problem::{Catalogued, Mistake};
use cagd_problem::{Exact, Number};
use cagd_scalar::FieldOps;
use proptest::prelude::*;
use serde_json::{json, Value};

fn n(a: i64, b: i64) -> Number {
    <Number as FieldOps>::from_ratio(a, b)
}

/// A circle of radius 1..=4 about a center of two or three small coordinates: N = 3, 4 or
/// 6 arcs, or an arc of a sweep of 60°, 90°, 120°, 180° or 270° from a start of 0° or 90°.
fn problem() -> impl Strategy<Value = Value> {
    (
        1i64..=4,
        prop::sample::select(vec![3i64, 4, 6]),
        proptest::collection::vec(-3i64..=3, 3),
        any::<bool>(),
        prop::option::of((
            prop::sample::select(vec![60i64, 90, 120, 180, 270]),
            prop::sample::select(vec![0i64, 90]),
        )),
    )
        .prop_map(|(r, arcs, c, plane, sweep)| {
            let center = if plane { json!([c[0], c[1]]) } else { json!(c) };
            match sweep {
                None => json!({"op": "circle", "radius": r, "arcs": arcs, "center": center}),
                Some((s, a)) => {
                    json!({"op": "circle", "radius": r, "sweep": s, "start": a, "center": center})
                }
            }
        })
}

/// The mistaken circle of `m`: its points, weights and knots.
fn mistaken(p: &Value, m: CircleMistake) -> (Vec<Point<Number>>, Vec<Number>, Vec<Number>) {
    let k = key(p);
    let (_, x) = k
        .mistaken
        .iter()
        .find(|(k, _)| *k == Mistake::Circle(m))
        .unwrap_or_else(|| panic!("{} applies to {p}", m.id()));
    match x.result.first() {
        Some((
            _,
            Exact::Curve(CurveIn::BSpline {
                points,
                knots,
                weights: Some(w),
                ..
            }),
        )) => (points.clone(), w.clone(), knots.clone()),
        other => panic!("{other:?}"),
    }
}

/// The problem's center (z = 0 when it has two coordinates: the circle of the key is in
/// R³ or in the plane as the center is) and radius.
fn center_and_radius(p: &Value) -> (Vec<Number>, Number) {
    let c = p["center"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| n(x.as_i64().unwrap(), 1))
        .collect();
    (c, n(p["radius"].as_i64().unwrap(), 1))
}

/// |b − c|², over the coordinates of b (the center's missing ones 0).
fn squared_distance(b: &Point<Number>, c: &[Number]) -> Number {
    b.coords()
        .iter()
        .enumerate()
        .map(|(i, x)| {
            let d = x.clone() - c.get(i).cloned().unwrap_or_else(|| n(0, 1));
            d.clone() * d
        })
        .fold(n(0, 1), |a, b| a + b)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(4))]

    #[test]
    fn every_circle_mistake_is_diagnosed(problems in proptest::collection::vec(problem(), 6)) {
        for m in CircleMistake::ALL {
            holds_over(&problems, Mistake::Circle(*m));
        }
    }

    /// The middle vertices pulled onto the circle: every vertex at distance r from the
    /// center, the problem's.
    #[test]
    fn on_the_circle_every_vertex_is_at_distance_r(problems in proptest::collection::vec(problem(), 4)) {
        for p in &problems {
            let (points, _, _) = mistaken(p, CircleMistake::MiddleVertexOnCircle);
            let (c, r) = center_and_radius(p);
            for b in &points {
                prop_assert_eq!(squared_distance(b, &c), r.clone() * r.clone(), "{}", p);
            }
        }
    }

    /// The weights: all 1; or cos θ = cos(2π/N) at the middle vertices of a full circle
    /// (−1/2, 0, 1/2 for N = 3, 4, 6).
    #[test]
    fn the_mistaken_weights(problems in proptest::collection::vec(problem(), 4)) {
        for p in &problems {
            let (_, ones, _) = mistaken(p, CircleMistake::MiddleWeightOne);
            prop_assert!(ones.iter().all(|w| *w == n(1, 1)));
            if p.get("sweep").is_none() {
                let (_, w, _) = mistaken(p, CircleMistake::WeightWholeAngle);
                let expected = match p["arcs"].as_i64() {
                    Some(3) => n(-1, 2),
                    Some(4) => n(0, 1),
                    _ => n(1, 2),
                };
                prop_assert_eq!(&w[1], &expected);
            }
        }
    }

    /// Single knots: the interior knots equally spaced.
    #[test]
    fn single_knots_are_equally_spaced(problems in proptest::collection::vec(problem(), 4)) {
        for p in problems.iter().filter(|p| p.get("sweep").is_none()) {
            let (_, _, u) = mistaken(p, CircleMistake::SingleKnots);
            let steps: Vec<_> = u.windows(2).map(|w| w[1].clone() - w[0].clone()).filter(|d| *d != n(0, 1)).collect();
            prop_assert!(steps.windows(2).all(|s| s[0] == s[1]), "{:?}", u);
        }
    }
}

/// The report of the snapshot tests: the unit circle of four arcs with
/// its middle vertices on the circle, at (√2/2, √2/2, 0).
#[test]
fn the_report_is_diagnosed() {
    let report: Value = serde_json::from_str(include_str!("../reports/circle.json")).unwrap();
    let v = cagd_diagnose::diagnose(&report, &settings());
    let a = v.assessment.expect("assessed");
    assert!(!a.correct());
    assert_eq!(
        a.mistakes(),
        [Mistake::Circle(CircleMistake::MiddleVertexOnCircle)]
    );
}
