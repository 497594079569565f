//! The Gaussian curvature through `solve` on developable surfaces, where it is zero
//! (generalized cylinders and cones, ruled Bézier patches, rational cylinders, tangent
//! developables, whose normal vanishes on the edge of regression v = 0), and its numerator on a
//! paraboloid, a saddle and the octant of the sphere.

use cagd_linalg::Point;
use cagd_poly::Var;
use cagd_problem::{solve, Exact, Number};
use cagd_scalar::{BigRational, ExactRational, FieldOps};
use proptest::prelude::*;
use serde_json::{json, Value};

fn q(n: i64, d: i64) -> BigRational {
    BigRational::from_ratio(n, d)
}

fn num(x: &BigRational) -> Number {
    Number::from_rational(x)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 16, ..ProptestConfig::default() })]

    /// The Gaussian curvature of a developable surface is zero: generalized cylinders
    /// c(u) + v d and cones (1 - v) c(u) + v a over random cubic curves (as polynomial maps
    /// and as ruled Bézier patches), and rational cylinders (a rational curve extruded).
    #[test]
    fn developable_surfaces_have_zero_gaussian_curvature(
        c in prop::collection::vec(prop::collection::vec(-4i64..=4, 3), 4),
        d in prop::collection::vec(-3i64..=3, 3),
        w in prop::collection::vec(1i64..=4, 4),
    ) {
        let top: Vec<Vec<i64>> = c.iter().map(|p| p.iter().zip(&d).map(|(x, y)| x + y).collect()).collect();
        let apex = vec![d.clone(); 4];
        for other in [top.clone(), apex] {
            // rows i along u (the curve), columns j along v (the ruling)
            let mesh: Vec<Vec<Vec<i64>>> = c.iter().zip(&other).map(|(p, q)| vec![p.clone(), q.clone()]).collect();
            let a = solve(&json!({"op": "gaussian_curvature", "surface": {"bezier": mesh}})).unwrap();
            prop_assert_eq!(a.get("numerator").unwrap().to_json(), json!("0"));
            prop_assert_eq!(a.get("developable").unwrap().to_json(), json!(true));
        }
        let mesh: Vec<Vec<Vec<i64>>> = c.iter().zip(&top).map(|(p, q)| vec![p.clone(), q.clone()]).collect();
        let weights: Vec<Vec<i64>> = w.iter().map(|x| vec![*x, *x]).collect();
        let a = solve(&json!({"op": "gaussian_curvature", "surface": {"bezier": mesh, "weights": weights}})).unwrap();
        prop_assert_eq!(a.get("developable").unwrap().to_json(), json!(true));
    }
}

#[test]
fn gaussian_curvature_of_a_paraboloid_a_saddle_and_the_sphere_octant() {
    let g = |surface: Value| {
        let a = solve(&json!({"op": "gaussian_curvature", "surface": surface})).unwrap();
        (
            a.get("numerator").unwrap().to_json(),
            a.get("developable").unwrap().to_json(),
        )
    };
    // K = 4/(1 + 4u² + 4v²)² and -4/(...)²: the numerators 4 and -4
    assert_eq!(
        g(json!({"expr": "(u, v, u^2 + v^2)"})),
        (json!("4"), json!(false))
    );
    assert_eq!(
        g(json!({"expr": "(u, v, u^2 - v^2)"})),
        (json!("-4"), json!(false))
    );
    // the octant of the unit sphere: K = 1, so G = w⁸ |n|⁴ > 0 where n ≠ 0, and 0 at the pole
    let a = solve(&json!({"op": "gaussian_curvature", "surface": {
        "bezier": [[[1, 0, 0], [1, 1, 0], [0, 1, 0]], [[1, 0, 1], [1, 1, 1], [0, 1, 1]], [[0, 0, 1], [0, 0, 1], [0, 0, 1]]],
        "weights": [[1, "sqrt2/2", 1], ["sqrt2/2", "1/2", "sqrt2/2"], [1, "sqrt2/2", 1]]}}))
    .unwrap();
    assert_eq!(
        a.get("corners").unwrap().to_json(),
        json!({"G_00": "16", "G_10": "0", "G_01": "16", "G_11": "0"})
    );
    // and it equals w⁸ |c_u × c_v|⁴ at (0, 0): w = 1, c_u × c_v = (-2, 0, 0), |n|⁴ = 16
    let n = solve(&json!({"op": "normal", "surface": {
        "bezier": [[[1, 0, 0], [1, 1, 0], [0, 1, 0]], [[1, 0, 1], [1, 1, 1], [0, 1, 1]], [[0, 0, 1], [0, 0, 1], [0, 0, 1]]],
        "weights": [[1, "sqrt2/2", 1], ["sqrt2/2", "1/2", "sqrt2/2"], [1, "sqrt2/2", 1]]}}))
    .unwrap();
    assert_eq!(
        n.get("corner_00").unwrap().to_json(),
        json!(["-2", "0", "0"])
    );
}

/// The points of a curve or surface answer evaluated at `params`.
fn points_of(shape: &str, answer: &Value, params: Value) -> Vec<Point<Number>> {
    let a = solve(&json!({"op": "evaluate", shape: answer, "params": params})).unwrap();
    let Some(Exact::Points(p)) = a.get("points") else {
        panic!("no points")
    };
    p.clone()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 16, ..ProptestConfig::default() })]

    /// The tangent developable of a random cubic: the Bézier mesh evaluates to c(u) + v c'(u),
    /// the Gaussian curvature's numerator is zero, and the normal vanishes on the edge of
    /// regression v = 0.
    #[test]
    fn tangent_developables_are_developable_with_their_edge_at_v_0(
        c in prop::collection::vec(prop::collection::vec(-4i64..=4, 3), 4),
    ) {
        let a = solve(&json!({"op": "tangent_developable", "curve": {"bezier": c}})).unwrap();
        prop_assert_eq!(a.get("developable").unwrap().to_json(), json!(true));
        let Some(Exact::Map(normal)) = a.get("normal") else { panic!("no normal") };
        let at_edge = normal.eval(&[(Var::U, num(&q(1, 3))), (Var::V, num(&q(0, 1)))]).unwrap();
        prop_assert!(at_edge.coords().iter().all(|x| *x == Number::from_i64(0)));
        let surface = a.get("surface").unwrap().to_json();
        let Some(Exact::Map(closed)) = a.get("closed_form") else { panic!("no closed form") };
        let p = &points_of("surface", &surface, json!([["1/3", "2/5"]]))[0];
        prop_assert_eq!(p, &closed.eval(&[(Var::U, num(&q(1, 3))), (Var::V, num(&q(2, 5)))]).unwrap());
        let g = solve(&json!({"op": "gaussian_curvature", "surface": surface})).unwrap();
        prop_assert_eq!(g.get("developable").unwrap().to_json(), json!(true));
    }
}
