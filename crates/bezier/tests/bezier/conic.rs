//! Conics and circles: every point satisfies x^2 + y^2 = r^2 exactly.

use crate::common::{ints, pt, qn, rat};
use cagd_bezier::*;
use cagd_linalg::Point;
use cagd_scalar::{q, BigRational, FieldOps, Quadratic, Scalar};
use proptest::prelude::*;

/// |p - m|^2 in the plane of the first two coordinates.
fn dist2<S: Scalar>(p: &Point<S>, m: &Point<S>) -> S {
    let (dx, dy) = (p[0].sub_ref(&m[0]), p[1].sub_ref(&m[1]));
    dx.mul_ref(&dx) + dy.mul_ref(&dy)
}

/// A rational number in [0, 1] as an element of Q(√d).
fn unit_param() -> impl Strategy<Value = BigRational> {
    (0i64..=9, 1i64..=9).prop_map(|(n, d)| <BigRational as FieldOps>::from_ratio(n.min(d), d))
}

#[test]
fn quarter_circle_needs_root_two() {
    let c = quarter_circle::<Quadratic>(&qn("3")).unwrap();
    assert_eq!(c.to_text(), "(3, 0) w = 1; (3, 3) w = √2/2; (0, 3) w = 1");
    let mid = c.eval(&qn("1/2")).unwrap();
    // (3√2/2, 3√2/2)
    assert_eq!(mid.to_text(), "(3√2/2, 3√2/2)");
    let err = quarter_circle::<BigRational>(&q!(1)).unwrap_err();
    assert!(matches!(err, BezierError::Number { .. }));
    assert!(
        err.to_string().contains("√2/2 is not a rational number"),
        "{err}"
    );
    assert_eq!(
        quarter_circle::<Quadratic>(&qn("0"))
            .unwrap_err()
            .to_string(),
        "the radius must be positive, but it is 0"
    );
    // over f64 the weight is rounded: fine for figures
    let f = quarter_circle::<f64>(&2.0).unwrap();
    let p = f.eval(&0.3).unwrap();
    assert!((p.dot(&p) - 4.0).abs() < 1e-12);
}

#[test]
fn arcs_from_tangents_and_from_directions() {
    // legs of length 25 at cos = 7/25: cos(θ/2) = 3/5, centre (25, 75/4), radius 75/4
    let arc = circle_arc_from_tangents(
        pt(&["25", "0"]),
        pt(&["0", "0"]),
        pt(&["7", "24"]),
        q!(3 / 5),
    )
    .unwrap();
    let m = pt(&["25", "75/4"]);
    for t in [q!(0), q!(1 / 9), q!(1 / 2), q!(5 / 7), q!(1)] {
        assert_eq!(dist2(&arc.eval(&t).unwrap(), &m), q!(75 / 4) * q!(75 / 4));
    }
    let bad_legs =
        circle_arc_from_tangents(pt(&["2", "0"]), pt(&["0", "0"]), pt(&["0", "1"]), q!(1 / 2));
    assert!(bad_legs
        .unwrap_err()
        .to_string()
        .contains("|c0 - c1|^2 = 4 and |c2 - c1|^2 = 1"));
    let bad_w = circle_arc_from_tangents(pt(&["1", "0"]), pt(&["0", "0"]), pt(&["0", "1"]), q!(1));
    assert!(bad_w
        .unwrap_err()
        .to_string()
        .contains("strictly between 0 and 1"));
    // the same 90° arc from the centre and directions, over Q(√2)
    let o = Point::new(vec![qn("1"), qn("2")]);
    let r = qn("2");
    let e1 = Point::new(vec![qn("1"), qn("0")]);
    let e2 = Point::new(vec![qn("0"), qn("1")]);
    let arc = circle_arc(&o, &r, &e1, &e2, &qn("sqrt2/2")).unwrap();
    assert_eq!(arc.to_text(), "(3, 2) w = 1; (3, 4) w = √2/2; (1, 4) w = 1");
    assert_eq!(dist2(&arc.eval(&qn("2/7")).unwrap(), &o), qn("4"));
    // 120° from (1, 0) to (-1/2, √3/2), weight 1/2: the tangent point at distance 2r
    let d1 = Point::new(vec![qn("-1/2"), qn("sqrt3/2")]);
    let third = circle_arc(
        &Point::new(vec![qn("0"), qn("0")]),
        &qn("1"),
        &e1,
        &d1,
        &qn("1/2"),
    )
    .unwrap();
    assert_eq!(third.points()[1].to_text(), "(1, √3)");
    assert_eq!(
        dist2(&third.eval(&qn("3/8")).unwrap(), &Point::zero(2)),
        qn("1")
    );
    // inconsistent data
    let wrong_angle = circle_arc(&o, &r, &e1, &e2, &qn("1/2"));
    assert!(wrong_angle
        .unwrap_err()
        .to_string()
        .contains("cos θ = -1/2, but the directions have d0·d1 = 0"));
    let not_unit = circle_arc(
        &o,
        &r,
        &Point::new(vec![qn("2"), qn("0")]),
        &e2,
        &qn("sqrt2/2"),
    );
    assert!(not_unit
        .unwrap_err()
        .to_string()
        .contains("must be a unit vector"));
    // conic arcs of the three kinds
    let para = conic_arc(pt(&["0", "0"]), pt(&["1", "1"]), pt(&["2", "0"]), q!(1)).unwrap();
    assert_eq!(para.conic_kind(), Some(ConicKind::Parabola));
    assert_eq!(para.eval(&q!(1 / 2)).unwrap(), pt(&["1", "1/2"]));
    assert!(conic_arc(pt(&["0"]), pt(&["1"]), pt(&["2"]), q!(0)).is_err());
}

#[test]
fn whole_circles() {
    let m = Point::new(vec![qn("1"), qn("-1"), qn("5")]);
    let four = circle_four_arcs(&m, &qn("2")).unwrap();
    assert_eq!(four.len(), 4);
    assert_eq!(
        four[0].to_text(),
        "(3, -1, 5) w = 1; (3, 1, 5) w = √2/2; (1, 1, 5) w = 1"
    );
    assert_eq!(four[3].points()[2], four[0].points()[0]);
    let three = circle_three_arcs(&m, &qn("2")).unwrap();
    assert_eq!(three.len(), 3);
    assert_eq!(
        three[0].to_text(),
        "(3, -1, 5) w = 1; (3, -1 + 2√3, 5) w = 1/2; (0, -1 + √3, 5) w = 1"
    );
    assert_eq!(three[2].points()[2], three[0].points()[0]);
    let err = circle_three_arcs::<BigRational>(&Point::zero(2), &q!(1)).unwrap_err();
    assert!(
        err.to_string().contains("needs the quadratic field Q(√3)"),
        "{err}"
    );
    assert!(circle_four_arcs::<BigRational>(&Point::zero(2), &q!(1)).is_err());
    let rational = circle_four_arcs_rational::<BigRational>(&ints(&[&[0, 0]])[0], &q!(5)).unwrap();
    assert_eq!(
        rational[0].to_text(),
        "(5, 0) w = 1; (5, 5) w = 1/2; (0, 5) w = 1/2"
    );
    assert_eq!(
        rational[1].to_text(),
        "(0, 5) w = 1/2; (-5, 5) w = 1/2; (-5, 0) w = 1"
    );
    assert!(circle_four_arcs_rational::<BigRational>(&pt(&["1"]), &q!(1)).is_err());
    assert!(circle_four_arcs_rational::<BigRational>(&pt(&["0", "0"]), &q!(-1)).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn rational_circle_exact_over_the_rationals(t in unit_param(), r in rat(), cx in rat(), cy in rat()) {
        prop_assume!(r > q!(0));
        let m = Point::new(vec![cx, cy]);
        for arc in circle_four_arcs_rational(&m, &r).unwrap() {
            let p = arc.eval(&t).unwrap();
            prop_assert_eq!(dist2(&p, &m), r.clone() * &r);
            // the tangent is perpendicular to the radius
            prop_assert_eq!(arc.derivative_at(&t).unwrap().dot(&(&p - &m)), q!(0));
        }
    }

    #[test]
    fn four_arc_circle_exact_in_q_sqrt2(t in unit_param(), r in rat()) {
        prop_assume!(r > q!(0));
        let (t, r) = (Quadratic::from_rational(t), Quadratic::from_rational(r));
        let m = Point::new(vec![qn("1/2"), qn("sqrt2")]);
        for arc in circle_four_arcs(&m, &r).unwrap() {
            let p = arc.eval(&t).unwrap();
            prop_assert_eq!(dist2(&p, &m), r.clone() * &r);
            let (left, right) = arc.subdivide(&qn("1/3")).unwrap();
            for piece in [left, right] {
                let u = piece.domain().0.clone();
                prop_assert_eq!(dist2(&piece.eval(&u).unwrap(), &m), r.clone() * &r);
            }
            let e = arc.elevate_degree(1).unwrap();
            prop_assert_eq!(dist2(&e.eval(&t).unwrap(), &m), r.clone() * &r);
        }
    }

    #[test]
    fn three_arc_circle_exact_in_q_sqrt3(t in unit_param(), r in rat()) {
        prop_assume!(r > q!(0));
        let (t, r) = (Quadratic::from_rational(t), Quadratic::from_rational(r));
        let m = Point::new(vec![qn("-3"), qn("2/3")]);
        for arc in circle_three_arcs(&m, &r).unwrap() {
            prop_assert_eq!(arc.weights()[1].clone(), qn("1/2"));
            prop_assert_eq!(dist2(&arc.eval(&t).unwrap(), &m), r.clone() * &r);
        }
    }
}
