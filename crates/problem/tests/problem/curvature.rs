//! Where the numerator G of the Gaussian curvature vanishes on the domain (issue 16, item 6):
//! the verdicts (one strict sign, a zero at an exact point, a change of sign between two exact
//! points, not decided) checked against G evaluated at those points and at random points.

use cagd_poly::{parse_poly, Var};
use cagd_problem::{solve, Exact};
use cagd_scalar::{BigRational, FieldOps};
use proptest::prelude::*;
use serde_json::{json, Value};

fn curvature(surface: Value) -> cagd_problem::Answer {
    solve(&json!({"op": "gaussian_curvature", "surface": surface})).unwrap()
}

fn text(a: &cagd_problem::Answer, key: &str) -> String {
    match a.get(key) {
        Some(Exact::Text(t)) => t.clone(),
        Some(Exact::Sentence(m)) => m.to_string(),
        other => panic!("{key}: {other:?}"),
    }
}

#[test]
fn a_paraboloid_is_elliptic_and_a_saddle_hyperbolic_on_the_whole_domain() {
    let a = curvature(json!({"expr": "(u, v, u^2 + v^2)"}));
    assert_eq!(a.get("sign").unwrap().to_json(), json!(1));
    assert_eq!(
        text(&a, "zeros"),
        "G > 0 on the whole domain (its Bernstein coefficients on the domain are all positive): K > 0, the surface is elliptic there"
    );
    let a = curvature(json!({"expr": "(u, v, u^2 - v^2)"}));
    assert_eq!(a.get("sign").unwrap().to_json(), json!(-1));
    assert!(text(&a, "zeros").contains("hyperbolic"));
    // a developable surface: G ≡ 0
    let a = curvature(json!({"expr": "(u, v, u^2)"}));
    assert_eq!(a.get("sign").unwrap().to_json(), json!(0));
    assert!(text(&a, "zeros").contains("developable"));
}

#[test]
fn a_piece_of_the_unit_sphere_away_from_the_poles_has_a_certified_positive_sign() {
    // the arc of 60° from (1, 0, 0) to (1/2, 0, √3/2), weight cos 30° = √3/2, revolved by
    // 120° about the z axis (weights 1, cos 60° = 1/2, 1): K = 1 everywhere
    let rot = |x: &str, z: &str| {
        // (x, 0, z), (x, √3 x, z), (-x/2, √3 x/2, z)
        vec![
            json!([x, "0", z]),
            json!([x, format!("sqrt3*({x})"), z]),
            json!([format!("-({x})/2"), format!("sqrt3*({x})/2"), z]),
        ]
    };
    let mesh = vec![rot("1", "0"), rot("1", "sqrt3/3"), rot("1/2", "sqrt3/2")];
    let a = curvature(json!({"bezier": mesh, "weights": [
        [1, "1/2", 1], ["sqrt3/2", "sqrt3/4", "sqrt3/2"], [1, "1/2", 1]]}));
    assert_eq!(a.get("sign").unwrap().to_json(), json!(1));
    assert!(
        text(&a, "zeros").contains("elliptic"),
        "{}",
        text(&a, "zeros")
    );
}

#[test]
fn the_sphere_octant_has_g_zero_at_the_pole() {
    // n = c_u × c_v vanishes at the pole (u = 1), where K is not defined
    let a = curvature(json!({
        "bezier": [[[1, 0, 0], [1, 1, 0], [0, 1, 0]], [[1, 0, 1], [1, 1, 1], [0, 1, 1]], [[0, 0, 1], [0, 0, 1], [0, 0, 1]]],
        "weights": [[1, "sqrt2/2", 1], ["sqrt2/2", "1/2", "sqrt2/2"], [1, "sqrt2/2", 1]]}));
    assert_eq!(a.get("sign").unwrap().to_json(), json!(0));
    assert_eq!(a.get("zero").unwrap().to_json(), json!(["1", "0"]));
    assert_eq!(
        text(&a, "zeros"),
        "G vanishes on the domain: G = 0 at (u, v) = (1, 0)"
    );
}

#[test]
fn a_change_of_sign_is_proved_between_two_exact_points() {
    // z = (u - 1/2)³ + v²: G = f_uu f_vv - f_uv² = 12 (u - 1/2)
    let a = curvature(json!({"expr": "(u, v, (u - 1/2)^3 + v^2)"}));
    assert_eq!(a.get("numerator").unwrap().to_json(), json!("12*u - 6"));
    assert_eq!(a.get("sign").unwrap().to_json(), json!(0));
    assert_eq!(
        a.get("sign_change").unwrap().to_json(),
        json!([["1", "0"], ["0", "0"]])
    );
    assert!(text(&a, "zeros").contains("G > 0 at (u, v) = (1, 0) and G < 0 at (u, v) = (0, 0)"));
}

#[test]
fn a_double_zero_off_the_dyadic_points_is_not_decided_and_no_sign_is_guessed() {
    // z = (u - 1/3)⁴/12 + v²/2: G = (u - 1/3)² ≥ 0, zero on the line u = 1/3, which no
    // halving of [0, 1] reaches; the Bernstein coefficients around it keep both signs
    let a = curvature(json!({"expr": "(u, v, (u - 1/3)^4/12 + v^2/2)"}));
    assert_eq!(
        a.get("numerator").unwrap().to_json(),
        json!("u^2 - 2/3*u + 1/9")
    );
    assert!(a.get("sign").is_none());
    assert_eq!(
        text(&a, "zeros"),
        "where G vanishes is not decided within 4 halvings of the domain: on some rectangle the Bernstein coefficients of G have both signs, and no corner gave a zero or a change of sign"
    );
}

#[test]
fn a_bspline_surface_gets_a_verdict_per_piece_and_overall() {
    // a bicubic-in-u graph with two spans in u: z = f(u) + v²/2 with f a C² cubic spline
    let a = curvature(json!({"bspline": [
        [[0, 0, 0], [0, 1, "1/2"]], [[1, 0, 1], [1, 1, "3/2"]], [[2, 0, 0], [2, 1, "1/2"]], [[3, 0, 1], [3, 1, "3/2"]]],
        "degree": [2, 1], "knots": [[0, 0, 1, 2, 2], [0, 1]]}));
    let pieces = a.get("pieces").unwrap().to_json();
    assert_eq!(pieces.as_array().unwrap().len(), 2);
    for p in pieces.as_array().unwrap() {
        assert!(p.get("sign").is_some(), "{p}");
    }
    assert!(a.get("zeros").is_some());
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 24, ..ProptestConfig::default() })]

    /// For graphs z = f(u, v) of random cubics, the verdict is proved by G itself: a strict
    /// sign is the sign of G at random points of the domain, a zero is a zero of G, a change
    /// of sign is one between the two points named.
    #[test]
    fn the_verdict_agrees_with_g_at_its_points_and_at_random_points(
        c in prop::collection::vec(-3i64..=3, 6),
        pts in prop::collection::vec((0i64..=7, 0i64..=7), 8),
    ) {
        let f = format!(
            "{} u^3 + {} u^2 v + {} u v^2 + {} v^3 + {} u^2 + {} v^2",
            c[0], c[1], c[2], c[3], c[4], c[5]
        );
        let a = curvature(json!({"expr": format!("(u, v, {f})")}));
        let g = parse_poly::<BigRational>(a.get("numerator").unwrap().to_json().as_str().unwrap()).unwrap();
        let at = |p: &Value| {
            let x = |i: usize| parse_poly::<BigRational>(p[i].as_str().unwrap()).unwrap().as_constant().unwrap();
            g.eval(&[(Var::U, x(0)), (Var::V, x(1))]).unwrap()
        };
        let zero = BigRational::from_i64(0);
        match a.get("sign").map(|s| s.to_json()) {
            Some(s) if s == json!(1) || s == json!(-1) => {
                for (i, j) in &pts {
                    let p = json!([format!("{i}/7"), format!("{j}/7")]);
                    let v = at(&p);
                    prop_assert!(if s == json!(1) { v > zero } else { v < zero }, "{} at {}", f, p);
                }
            }
            Some(_) => {
                if g.is_zero() {
                    prop_assert!(text(&a, "zeros").contains("developable"));
                } else if let Some(z) = a.get("zero") {
                    prop_assert_eq!(at(&z.to_json()), zero);
                } else {
                    let pq = a.get("sign_change").unwrap().to_json();
                    prop_assert!(at(&pq[0]) > zero && at(&pq[1]) < zero);
                }
            }
            None => prop_assert!(text(&a, "zeros").contains("not decided")),
        }
    }
}
