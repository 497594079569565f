//! Circles, conics and surfaces of revolution through `solve`: arcs of exact angles on their
//! circle, angles whose sine is in no quadratic field refused, B-spline profiles turned about Z
//! on their parallels (notes eq. (21)), and conics from a shape factor.

use cagd_linalg::Point;
use cagd_problem::{solve, Exact, Number};
use cagd_scalar::FieldOps;
use proptest::prelude::*;
use serde_json::{json, Value};

/// The points of a curve or surface answer evaluated at `params`.
fn points_of(shape: &str, answer: &Value, params: Value) -> Vec<Point<Number>> {
    let a = solve(&json!({"op": "evaluate", shape: answer, "params": params})).unwrap();
    let Some(Exact::Points(p)) = a.get("points") else {
        panic!("no points")
    };
    p.clone()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// An arc of any exact angle lies on its circle (x² + y² = r², exactly in Q(√2) or
    /// Q(√3)) and runs from the start angle to start + sweep.
    #[test]
    fn arcs_of_exact_angles_lie_on_their_circle(
        thirty in any::<bool>(),
        start_k in -6i64..=12,
        sweep_k in 1i64..=12,
        extra in 0usize..=2,
        r in 1i64..=5,
    ) {
        let step = if thirty { 30 } else { 45 };
        let (start, sweep) = (start_k * step, (sweep_k * step).min(360));
        let arcs = usize::try_from((sweep + 89) / 90).unwrap() + extra;
        let a = solve(&json!({"op": "circle", "radius": r, "sweep": sweep, "start": start, "arcs": arcs}));
        // an odd number of arcs of a multiple of 45° can put the joints at multiples of 22.5°
        let Ok(a) = a else { return Ok(()); };
        let curve = a.get("curve").unwrap().to_json();
        let pts = points_of("curve", &curve, json!([0, "1/7", "1/3", "1/2", 1]));
        let rr = Number::from_i64(r * r);
        for p in &pts {
            let (x, y) = (p.coords()[0].clone(), p.coords()[1].clone());
            prop_assert_eq!(x.clone() * x + y.clone() * y, rr.clone());
        }
        // the ends: the start of the arc of two steps from there
        let end = |deg: i64| {
            let one = solve(&json!({"op": "circle", "radius": r, "sweep": 2 * step, "start": deg, "arcs": 1})).unwrap();
            points_of("curve", &one.get("curve").unwrap().to_json(), json!([0]))[0].clone()
        };
        prop_assert_eq!(&pts[0], &end(start));
        prop_assert_eq!(&pts[4], &end(start + sweep));
    }

    /// A surface of revolution of a B-spline profile: every point lies on the parallel of its
    /// profile point, x² + y² = f(u)², z = g(u) (notes eq. (21)), for the full turn and for a
    /// partial one.
    #[test]
    fn revolution_of_bspline_profiles_lies_on_the_parallels(
        xs in prop::collection::vec(1i64..=4, 4),
        zs in prop::collection::vec(-3i64..=3, 4),
        sweep in prop::sample::select(vec![60i64, 90, 120, 180, 270, 360]),
    ) {
        let profile: Vec<[i64; 3]> = xs.iter().zip(&zs).map(|(x, z)| [*x, 0, *z]).collect();
        let curve = json!({"bspline": profile, "degree": 2, "knots": [0, 0, 1, 2, 2]});
        let a = solve(&json!({"op": "revolution", "curve": curve, "sweep": sweep})).unwrap();
        let surface = a.get("surface").unwrap().to_json();
        for (u, v) in [("1/2", "1/3"), ("3/2", "1/2"), ("1", "1"), ("2", "0")] {
            let p = &points_of("surface", &surface, json!([[u, v]]))[0];
            let f = &points_of("curve", &curve, json!([u]))[0];
            let (x, y, z) = (p.coords()[0].clone(), p.coords()[1].clone(), p.coords()[2].clone());
            let (fx, fz) = (f.coords()[0].clone(), f.coords()[2].clone());
            prop_assert_eq!(x.clone() * x + y.clone() * y, fx.clone() * fx);
            prop_assert_eq!(z, fz);
        }
    }
}

#[test]
fn arcs_whose_sines_are_in_no_quadratic_field_are_refused() {
    let e = solve(&json!({"op": "circle", "sweep": 72})).unwrap_err();
    assert!(e.to_string().contains("cos and sin of 36°"), "{e}");
    // 15° needs √2 and √3 together
    let e = solve(&json!({"op": "circle", "sweep": 30, "arcs": 1})).unwrap_err();
    assert!(e.to_string().contains("15°"), "{e}");
    // a sweep is never ignored: an expression profile has no control points to turn
    let e = solve(&json!({"op": "revolution", "curve": {"expr": "(1 + u, 0, u)"}, "sweep": 60}))
        .unwrap_err();
    assert!(e.to_string().contains("sweep"), "{e}");
    // the quarter of the notes, from a B-spline profile: the mesh of Figure 13's construction
    let a = solve(&json!({"op": "revolution", "curve": {"bspline": [[1, 0, 0], [2, 0, 1], [1, 0, 2]], "degree": 2, "knots": [0, 0, 1, 1]}, "sweep": 60})).unwrap();
    assert_eq!(
        a.get("surface").unwrap().to_json()["weights"][0],
        json!(["1", "sqrt3/2", "1"])
    );
}

#[test]
fn conics_from_a_shape_factor() {
    let kind = |w: Value| {
        let a = solve(&json!({"op": "conic", "points": [[1, 0], [1, 1], [0, 1]], "weight": w}))
            .unwrap();
        a.get("kind").unwrap().to_json()
    };
    assert_eq!(kind(json!("1/2")), json!("ellipse"));
    assert_eq!(kind(json!(1)), json!("parabola"));
    assert_eq!(kind(json!(2)), json!("hyperbola"));
    // w = √2/2 on the isosceles right angle: the quarter of the unit circle
    let a = solve(&json!({"op": "conic", "points": [[1, 0], [1, 1], [0, 1]], "weight": "sqrt2/2"}))
        .unwrap();
    let curve = a.get("curve").unwrap().to_json();
    for p in points_of("curve", &curve, json!(["1/3", "1/2", "4/5"])) {
        let (x, y) = (p.coords()[0].clone(), p.coords()[1].clone());
        assert_eq!(x.clone() * x + y.clone() * y, Number::from_i64(1));
    }
}
