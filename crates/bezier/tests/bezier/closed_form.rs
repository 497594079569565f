//! Closed forms through cagd-poly: round trips and derivatives against the hodograph.

use crate::common::{polygon, qn, rat, weighted_polygon};
use cagd_bezier::*;
use cagd_linalg::Point;
use cagd_poly::{parse_vec_poly, RationalMap, Var};
use cagd_scalar::{q, BigRational, FieldOps, Quadratic};
use proptest::prelude::*;

#[test]
fn closed_forms_by_hand() {
    let c = BezierCurve::try_new(vec![
        Point::<BigRational>::from_ints(&[0, 0]),
        Point::from_ints(&[1, 3]),
        Point::from_ints(&[3, 3]),
        Point::from_ints(&[4, 0]),
    ])
    .unwrap();
    // x = 3t + 3t^2 - 2t^3, y = 9t - 9t^2
    assert_eq!(
        c.closed_form(Var::U).to_text(),
        "(-2 u^3 + 3 u^2 + 3 u, -9 u^2 + 9 u)"
    );
    // on [0, 2]: t ↦ t/2
    let slow = c.clone().with_domain(q!(0), q!(2)).unwrap();
    assert_eq!(
        slow.closed_form(Var::T).to_text(),
        "(-1/4 t^3 + 3/4 t^2 + 3/2 t, -9/4 t^2 + 9/2 t)"
    );
    let back = BezierCurve::from_closed_form(&c.closed_form(Var::U), Var::U, 3).unwrap();
    assert_eq!(back, c);
    let e = BezierCurve::from_closed_form(&c.closed_form(Var::U), Var::U, 5).unwrap();
    assert_eq!(e, c.elevate_degree(2));
    let err = BezierCurve::from_closed_form(&c.closed_form(Var::U), Var::U, 2).unwrap_err();
    assert!(matches!(err, BezierError::Poly(_)));
    let wrong_var = parse_vec_poly::<BigRational>("(u, v)").unwrap();
    assert!(BezierCurve::from_closed_form(&wrong_var, Var::U, 2).is_err());
}

#[test]
fn rational_closed_form_of_the_quarter_circle() {
    let c = quarter_circle::<Quadratic>(&qn("1")).unwrap();
    let map = c.closed_form(Var::T);
    // numerator and denominator in Q(√2); on the circle for every t
    assert_eq!(map.denominator().to_text(), "(2 - √2) t^2 - (2 - √2) t + 1");
    for t in ["1/3", "2/5", "9/10"] {
        let p = map.eval(&[(Var::T, qn(t))]).unwrap();
        assert_eq!(p, c.eval(&qn(t)).unwrap());
        assert_eq!(p.dot(&p), qn("1"));
    }
    let back = RationalBezierCurve::from_closed_form(&map, Var::T, 2).unwrap();
    assert_eq!(back, c);
    // the rational weights (1, 1/2, 1/2)
    let r = circle_four_arcs_rational::<BigRational>(&Point::zero(2), &q!(1)).unwrap();
    assert_eq!(
        r[0].closed_form(Var::T).to_text(),
        "(-t + 1, -1/2 t^2 + t) / (1/2 t^2 - t + 1)"
    );
    let zero_weight =
        RationalMap::from_homogeneous(&parse_vec_poly::<BigRational>("(1, t)").unwrap()).unwrap();
    // w(0) = 0: the first entry is the control vector (1)
    let c = RationalBezierCurve::from_closed_form(&zero_weight, Var::T, 1).unwrap();
    assert_eq!(c.to_text(), "vector (1) w = 0; (1) w = 1");
    assert_eq!(c.closed_form(Var::T).to_text(), "(1) / (t)");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn closed_form_round_trip_and_derivatives(c in polygon(5), t in rat()) {
        let curve = BezierCurve::try_new(c.clone()).unwrap();
        let f = curve.closed_form(Var::T);
        prop_assert_eq!(f.eval(&[(Var::T, t.clone())]).unwrap(), de_casteljau(&c, &t).unwrap());
        prop_assert_eq!(BezierCurve::from_closed_form(&f, Var::T, curve.degree()).unwrap(), curve.clone());
        // the derivative of the closed form is the closed form of the hodograph
        let mut df = f.clone();
        for r in 1..=curve.degree() + 1 {
            df = df.partial(Var::T);
            prop_assert_eq!(&curve.derivative(r).closed_form(Var::T), &df);
        }
    }

    #[test]
    fn rational_closed_form_and_quotient_rule((c, w) in weighted_polygon(4), t in 0i64..=9) {
        let t = BigRational::from_ratio(t, 9);
        let curve = RationalBezierCurve::try_new(c, w).unwrap();
        let map = curve.closed_form(Var::T);
        prop_assert_eq!(map.eval(&[(Var::T, t.clone())]).unwrap(), curve.eval(&t).unwrap());
        prop_assert_eq!(
            curve.derivative_closed_form(Var::T).eval(&[(Var::T, t.clone())]).unwrap(),
            curve.derivative_at(&t).unwrap()
        );
        prop_assert_eq!(RationalBezierCurve::from_closed_form(&map, Var::T, curve.degree()).unwrap(), curve);
    }
}
