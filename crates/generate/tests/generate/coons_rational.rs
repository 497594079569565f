//! The rational caveat of §5: the naive homogeneous Coons mesh (19) in R^4.
//!
//! The example: the square of side 2 in the plane z = 0, each side replaced by a quadratic arc
//! whose middle control point is lifted to height 1 with weight `wm` (corner weights 1):
//!
//! c1 = {(0,0,0), (1,0,1), (2,0,0)}, c2 = {(0,2,0), (1,2,1), (2,2,0)},
//! d1 = {(0,0,0), (0,1,1), (0,2,0)}, d2 = {(2,0,0), (2,1,1), (2,2,0)}.
//!
//! The central weight is `w_11 = w_c,11 + w_d,11 - w_cd,11 = wm + wm - 1 = 2 wm - 1`: zero for
//! wm = 1/2 (the homogeneous vertex is (0, 0, 1, 0), a point at infinity in the direction of
//! z), negative for wm = 1/4. For wm = 2 every weight is positive, yet the projection at
//! (1/2, 1/2) is (1, 1, 1) while the Coons surface of the four arcs passes through
//! (1, 1, 4/3).

use crate::support::*;
use cagd_bezier::RationalBezierCurve;
use cagd_generate::*;
use cagd_linalg::Point;
use cagd_poly::{RationalMap, Var};
use cagd_scalar::q;
use proptest::prelude::*;

fn arcs(wm: &str) -> [RationalBezierCurve<Q>; 4] {
    let w = ["1", wm, "1"];
    [
        rcurve(&[&[0, 0, 0], &[1, 0, 1], &[2, 0, 0]], &w),
        rcurve(&[&[0, 2, 0], &[1, 2, 1], &[2, 2, 0]], &w),
        rcurve(&[&[0, 0, 0], &[0, 1, 1], &[0, 2, 0]], &w),
        rcurve(&[&[2, 0, 0], &[2, 1, 1], &[2, 2, 0]], &w),
    ]
}

fn build(wm: &str) -> ProjectiveCoons<Q> {
    let [c1, c2, d1, d2] = arcs(wm);
    coons_projective(&c1, &c2, &d1, &d2, &mut NoSteps).unwrap()
}

#[test]
fn zero_weight_sends_a_control_point_to_infinity() {
    let pc = build("1/2");
    assert_eq!(
        pc.weights.to_text_numbers(),
        "{1, 1/2, 1; 1/2, 0, 1/2; 1, 1/2, 1}"
    );
    assert_eq!(pc.nonpositive_weights, vec![(1, 1)]);
    assert_eq!(pc.homogeneous.get(1, 1).unwrap().to_text(), "(0, 0, 1, 0)");
    assert!(pc.surface.is_none());
    assert!(!pc.agrees);
    let [c1, c2, d1, d2] = arcs("1/2");
    let mut steps = Vec::new();
    coons_projective(&c1, &c2, &d1, &d2, &mut steps).unwrap();
    assert!(steps.iter().any(|s| s.name == "weights"));
}

#[test]
fn negative_weight() {
    let pc = build("1/4");
    assert_eq!(pc.weights.get(1, 1), Some(&q!(-1 / 2)));
    assert_eq!(pc.nonpositive_weights, vec![(1, 1)]);
    let s = pc.surface.expect("nonzero weights project");
    assert!(!s.has_positive_weights());
}

#[test]
fn positive_weights_still_give_another_surface() {
    let pc = build("2");
    assert!(pc.nonpositive_weights.is_empty());
    assert_eq!(pc.weights.to_text_numbers(), "{1, 2, 1; 2, 3, 2; 1, 2, 1}");
    let half = [(Var::U, q!(1 / 2)), (Var::V, q!(1 / 2))];
    assert_eq!(pc.projection.eval(&half).unwrap().to_text(), "(1, 1, 1)");
    assert_eq!(pc.coons.eval(&half).unwrap().to_text(), "(1, 1, 4/3)");
    assert!(!pc.agrees);
    // both interpolate the four arcs
    let [c1, c2, d1, d2] = arcs("2");
    for t in [q!(0), q!(1 / 3), q!(1 / 2), q!(1)] {
        for map in [&pc.projection, &pc.coons] {
            let ev = |u: &Q, v: &Q| {
                map.eval(&[(Var::U, u.clone()), (Var::V, v.clone())])
                    .unwrap()
            };
            assert_eq!(ev(&t, &q!(0)), c1.eval(&t).unwrap());
            assert_eq!(ev(&t, &q!(1)), c2.eval(&t).unwrap());
            assert_eq!(ev(&q!(0), &t), d1.eval(&t).unwrap());
            assert_eq!(ev(&q!(1), &t), d2.eval(&t).unwrap());
        }
    }
}

#[test]
fn polynomial_curves_agree() {
    let pc = build("1");
    assert!(pc.agrees);
    assert!(pc.surface.is_some());
    assert!(pc.weights.iter().all(|w| *w == q!(1)));
}

#[test]
fn corner_weights_must_match() {
    let [_, c2, d1, d2] = arcs("1");
    let c1 = rcurve(&[&[0, 0, 0], &[1, 0, 1], &[2, 0, 0]], &["2", "1", "1"]);
    assert_eq!(
        coons_projective(&c1, &c2, &d1, &d2, &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "the projective (homogeneous) Coons construction needs equal weights at corner a: c1 \
         has weight 2 there but d1 has 1 (scale the weights of one curve)"
    );
    let far = rcurve(&[&[0, 0, 0], &[1, 0, 1], &[3, 0, 0]], &["1", "1", "1"]);
    assert_eq!(
        coons_projective(&far, &c2, &d1, &d2, &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "curves c1 and d2 do not meet at corner b: c1(1) = (3, 0, 0), d2(0) = (2, 0, 0)"
    );
}

#[test]
fn rational_map_of_polynomial_curves_is_the_coons_surface() {
    let polys = [
        e("(u, 0, u^2)"),
        e("(u, 1, u^3 + 1)"),
        e("(0, v, v)"),
        e("(1, v, v^2 + 1)"),
    ];
    let maps = polys.clone().map(RationalMap::from_polynomial);
    let r = coons_rational_map(&maps[0], &maps[1], &maps[2], &maps[3]).unwrap();
    let c = coons_surface(&polys[0], &polys[1], &polys[2], &polys[3], &mut NoSteps).unwrap();
    assert_eq!(r.numerator(), &c.surface);
    assert!(coons_rational_map(&maps[0], &maps[1], &maps[3], &maps[2]).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    #[test]
    fn projection_interpolates_but_is_not_coons(
        mids in prop::collection::vec(crate::support::point3(), 4),
        w in weights(4),
        t in param(),
    ) {
        let corners = [pi(&[0, 0, 0]), pi(&[2, 0, 0]), pi(&[0, 2, 0]), pi(&[2, 2, 0])];
        let side = |p: &Point<Q>, m: &Point<Q>, q: &Point<Q>, wm: &Q| {
            RationalBezierCurve::try_new(vec![p.clone(), m.clone(), q.clone()], vec![q!(1), wm.clone(), q!(1)]).unwrap()
        };
        let c1 = side(&corners[0], &mids[0], &corners[1], &w[0]);
        let c2 = side(&corners[2], &mids[1], &corners[3], &w[1]);
        let d1 = side(&corners[0], &mids[2], &corners[2], &w[2]);
        let d2 = side(&corners[1], &mids[3], &corners[3], &w[3]);
        let pc = coons_projective(&c1, &c2, &d1, &d2, &mut NoSteps).unwrap();
        let ev = |u: &Q, v: &Q| pc.projection.eval(&[(Var::U, u.clone()), (Var::V, v.clone())]);
        prop_assert_eq!(ev(&t, &q!(0)).unwrap(), c1.eval(&t).unwrap());
        prop_assert_eq!(ev(&t, &q!(1)).unwrap(), c2.eval(&t).unwrap());
        prop_assert_eq!(ev(&q!(0), &t).unwrap(), d1.eval(&t).unwrap());
        prop_assert_eq!(ev(&q!(1), &t).unwrap(), d2.eval(&t).unwrap());
        // the weights are w_c + w_d - w_cd; the central one is (w0 + w1 + w2 + w3)/2 - 1
        let central = (w[0].clone() + &w[1] + &w[2] + &w[3]) / q!(2) - q!(1);
        prop_assert_eq!(pc.weights.get(1, 1), Some(&central));
        // equal weights 1 everywhere is the polynomial case, where the two agree
        let all_one = w.iter().all(|x| *x == q!(1));
        if all_one {
            prop_assert!(pc.agrees);
        }
    }
}
