//! Surface of revolution mistakes over random problems of the exercises' generator
//! (quadrant, half or full turn; polynomial, rational, quarter-circle or B-spline profile),
//! with the mistaken meshes checked against the construction: the rows of weights, the
//! radii of the parallels, the shape.

use crate::common::{generated, holds_over, key, report};
use cagd_problem::diagnosis::RevolutionMistake;
use cagd_problem::input::SurfaceIn;
use cagd_problem::{Mistake, Number};
use cagd_surface::{Grid, Mesh};
use proptest::prelude::*;
use serde_json::Value;

/// The key's and the mistaken surface's meshes and weights, when `m` applies.
#[allow(clippy::type_complexity)]
fn surfaces(
    p: &Value,
    m: RevolutionMistake,
) -> Option<((Mesh<Number>, Grid<Number>), (Mesh<Number>, Grid<Number>))> {
    let k = key(p);
    let parts = |x: &cagd_problem::Exact| match x {
        cagd_problem::Exact::Surface(
            SurfaceIn::Bezier {
                mesh,
                weights: Some(w),
            }
            | SurfaceIn::BSpline {
                mesh,
                weights: Some(w),
                ..
            },
        ) => Some((mesh.clone(), w.clone())),
        _ => None,
    };
    let right = parts(&k.answer.as_ref().ok()?.result.first()?.1)?;
    let (_, x) = k
        .mistaken
        .iter()
        .find(|(k, _)| *k == Mistake::Revolution(m))?;
    Some((right, parts(&x.result.first()?.1)?))
}

/// x² + y²: the squared distance to the Z axis.
fn radius2(q: &cagd_linalg::Point<Number>) -> Number {
    let c = q.coords();
    c[0].clone() * c[0].clone() + c[1].clone() * c[1].clone()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3))]

    #[test]
    fn every_revolution_mistake_is_diagnosed(seed in 0u64..1_000_000) {
        let problems = generated("revolution", 24, seed);
        for m in RevolutionMistake::ALL {
            holds_over(&problems, Mistake::Revolution(*m));
        }
    }

    /// Against the construction: without the profile's weights every row of weights is
    /// the circle's (all rows equal); with middle weights 1 each row is constant; with the
    /// middle vertices on the parallels every vertex of row i is at the distance of c_i from
    /// the axis; transposed, the mesh has the key's shape the other way round.
    #[test]
    fn the_mistaken_meshes_against_the_construction(seed in 0u64..1_000_000) {
        for p in generated("revolution", 8, seed) {
            if let Some((_, (_, w))) = surfaces(&p, RevolutionMistake::ProfileWeightLeftOut) {
                let rows = w.to_rows();
                prop_assert!(rows.iter().all(|r| *r == rows[0]), "{}", p);
            }
            if let Some((_, (_, w))) = surfaces(&p, RevolutionMistake::MiddleWeightOne) {
                prop_assert!(w.to_rows().iter().all(|r| r.iter().all(|x| *x == r[0])), "{}", p);
            }
            if let Some((_, (mesh, _))) = surfaces(&p, RevolutionMistake::MiddleVertexOnParallel) {
                for row in mesh.to_rows() {
                    let r0 = radius2(&row[0]);
                    prop_assert!(row.iter().all(|q| radius2(q) == r0), "{}", p);
                }
            }
            if let Some(((m, _), (t, _))) = surfaces(&p, RevolutionMistake::Transposed) {
                prop_assert_eq!((m.rows(), m.cols()), (t.cols(), t.rows()));
            }
        }
    }
}

/// The report of the snapshot tests: the octant of the unit sphere of chapter 6 with every
/// row of weights {1, √2/2, 1} (the profile's weight √2/2 not multiplied into the middle row).
#[test]
fn the_report_is_diagnosed() {
    assert_eq!(
        report(include_str!("../reports/revolution.json")).mistakes(),
        [Mistake::Revolution(RevolutionMistake::ProfileWeightLeftOut)]
    );
}

/// The notes' truncated-cone quadrant written as a plain mesh (the classic "forgot the
/// weights"): every weight is marked as not written, and the mistake named is the weights
/// left out, for the whole result.
#[test]
fn the_cone_without_its_weights() {
    let fixture: Value = serde_json::from_str(include_str!(
        "../../../../fixtures/ch6/09-truncated-cone-quadrant.json"
    ))
    .expect("the fixture reads");
    let mut student = fixture.clone();
    let mesh = fixture["expected"]["surface"]["bezier"].clone();
    student["expected"] = serde_json::json!({ "surface": { "bezier": mesh } });
    let v = cagd_diagnose::diagnose(&student, &crate::common::settings());
    let a = v.assessment.expect("assessed");
    let surface = &a.results[0];
    assert!(!surface.correct());
    assert!(surface.wrong().all(|m| m.written.is_none()), "{surface:?}");
    assert_eq!(surface.wrong().count(), 6, "the 2 × 3 weights");
    assert_eq!(surface.diagnoses.len(), 1);
    let d = &surface.diagnoses[0];
    assert!(d.whole);
    assert_eq!(
        d.mistakes,
        [Mistake::Revolution(RevolutionMistake::WeightsLeftOut)]
    );
    assert!(
        !v.mismatches.is_empty(),
        "the check says the weights are missing"
    );
}
