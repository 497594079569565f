//! `RationalBezierCurve`: validation, homogeneous form, and the operations.

use crate::common::{ints, pt, qn, text};
use cagd_bezier::{bernstein_sum, derivative_points, BezierError, ConicKind, RationalBezierCurve};
use cagd_linalg::Point;
use cagd_scalar::{q, BigRational};

/// The quarter of the unit circle with the rational weights {1, 1/2, 1/2}.
fn quarter() -> RationalBezierCurve<BigRational> {
    RationalBezierCurve::try_new(
        ints(&[&[1, 0], &[1, 1], &[0, 1]]),
        vec![q!(1), q!(1 / 2), q!(1 / 2)],
    )
    .unwrap()
}

fn on_unit_circle(p: &Point<BigRational>) -> bool {
    p.dot(p) == q!(1)
}

#[test]
fn validation() {
    let pts = ints(&[&[1, 0], &[1, 1], &[0, 1]]);
    assert_eq!(
        RationalBezierCurve::try_new(pts.clone(), vec![q!(1), q!(1)])
            .unwrap_err()
            .to_string(),
        "a rational curve needs one weight per control point: 3 control points but 2 weights"
    );
    // a zero weight is a control vector: accepted, refused where points are needed
    assert_eq!(
        RationalBezierCurve::try_new(pts.clone(), vec![q!(1), q!(1), q!(0)])
            .unwrap()
            .require_points()
            .unwrap_err()
            .to_string(),
        "weight 2 is zero: that entry is a control vector, not a point, and this needs every \
         control point to be a point"
    );
    let neg = RationalBezierCurve::try_new(pts, vec![q!(1), q!(-1), q!(1)]).unwrap();
    assert!(!neg.has_positive_weights());
    assert!(quarter().has_positive_weights());
    assert_eq!(
        RationalBezierCurve::<BigRational>::try_new(vec![], vec![]).unwrap_err(),
        BezierError::EmptyPolygon
    );
    assert_eq!(
        RationalBezierCurve::from_homogeneous(&[Point::<BigRational>::new(vec![])]).unwrap_err(),
        BezierError::HomogeneousWithoutWeight
    );
    // a homogeneous point of weight zero is a control vector, kept as written
    let with_vector =
        RationalBezierCurve::from_homogeneous(&[pt(&["1", "1"]), pt(&["2", "0"])]).unwrap();
    assert_eq!(with_vector.points(), &[pt(&["1"]), pt(&["2"])]);
    assert_eq!(with_vector.weights(), &[q!(1), q!(0)]);
    assert_eq!(with_vector.first_vector(), Some(1));
    assert_eq!(
        with_vector.require_points().unwrap_err(),
        BezierError::ZeroWeight { index: 1 }
    );
    assert_eq!(
        RationalBezierCurve::from_homogeneous(&[pt(&["1", "0"]), pt(&["2", "0"])]).unwrap_err(),
        BezierError::AllWeightsZero
    );
    assert_eq!(
        RationalBezierCurve::try_new(vec![pt(&["1"])], vec![q!(0)]).unwrap_err(),
        BezierError::AllWeightsZero
    );
}

#[test]
fn homogeneous_form_and_evaluation() {
    let c = quarter();
    assert_eq!(c.degree(), 2);
    assert_eq!(c.dim(), 2);
    assert_eq!(
        text(&c.homogeneous()),
        ["(1, 0, 1)", "(1/2, 1/2, 1/2)", "(0, 1/2, 1/2)"]
    );
    assert_eq!(
        RationalBezierCurve::from_homogeneous(&c.homogeneous()).unwrap(),
        c
    );
    assert_eq!(c.to_text(), "(1, 0) w = 1; (1, 1) w = 1/2; (0, 1) w = 1/2");
    // u = 1/2: (x, y, w) = (1/2, 3/8, 5/8)
    assert_eq!(
        c.eval_homogeneous(&q!(1 / 2)).unwrap(),
        pt(&["1/2", "3/8", "5/8"])
    );
    assert_eq!(c.weight_at(&q!(1 / 2)).unwrap(), q!(5 / 8));
    assert_eq!(c.eval(&q!(1 / 2)).unwrap(), pt(&["4/5", "3/5"]));
    assert_eq!(
        c.triangle_homogeneous(&q!(1 / 2)).unwrap()[2][0],
        pt(&["1/2", "3/8", "5/8"])
    );
    for t in [q!(0), q!(1 / 7), q!(2 / 3), q!(1)] {
        assert!(on_unit_circle(&c.eval(&t).unwrap()));
    }
    assert_eq!(
        c.eval(&q!(2)).unwrap_err().to_string(),
        "parameter t = 2 is outside the domain [0, 1]"
    );
    // weights 1, -1, 1 over (0), (1), (2): w(1/2) = 1/4 - 1/2 + 1/4 = 0
    let neg = RationalBezierCurve::try_new(ints(&[&[0], &[1], &[2]]), vec![q!(1), q!(-1), q!(1)])
        .unwrap();
    assert_eq!(
        neg.eval(&q!(1 / 2)).unwrap_err().to_string(),
        "the denominator w(t) of the rational curve vanishes at t = 1/2: c(t) is a point at infinity"
    );
    assert!(neg.derivative_at(&q!(1 / 2)).is_err());
    assert!(neg.blossom(&[q!(1 / 2), q!(1 / 2)]).is_err());
}

#[test]
fn blossom_subdivision_restriction_elevation() {
    let c = quarter();
    let t = q!(1 / 3);
    assert_eq!(
        c.blossom(&[t.clone(), t.clone()]).unwrap(),
        c.eval(&t).unwrap()
    );
    assert_eq!(c.blossom(&[q!(0), q!(1)]).unwrap(), pt(&["1", "1"]));
    assert_eq!(
        c.blossom_homogeneous(&[q!(0), q!(1)]).unwrap(),
        pt(&["1/2", "1/2", "1/2"])
    );
    let (l, r) = c.subdivide(&q!(1 / 2)).unwrap();
    assert_eq!(l.points().last(), Some(&pt(&["4/5", "3/5"])));
    assert_eq!(r.points()[0], pt(&["4/5", "3/5"]));
    assert_eq!(l.eval(&q!(1 / 4)).unwrap(), c.eval(&q!(1 / 4)).unwrap());
    assert_eq!(r.eval(&q!(3 / 4)).unwrap(), c.eval(&q!(3 / 4)).unwrap());
    let s = c.restrict(&q!(1 / 4), &q!(1 / 2)).unwrap();
    assert_eq!(s.domain(), (&q!(1 / 4), &q!(1 / 2)));
    assert_eq!(s.eval(&q!(1 / 3)).unwrap(), c.eval(&q!(1 / 3)).unwrap());
    let e = c.elevate_degree(2).unwrap();
    assert_eq!(e.degree(), 4);
    assert_eq!(e.eval(&q!(5 / 9)).unwrap(), c.eval(&q!(5 / 9)).unwrap());
    // elevated weights: (1, 1/2, 1/2) -> (1, 2/3, 1/2, 1/2)
    assert_eq!(
        c.elevate_degree(1).unwrap().weights(),
        &[q!(1), q!(2 / 3), q!(1 / 2), q!(1 / 2)]
    );
    // a weight that elevates to zero: (1, -1) -> (1, 0, -1), the middle entry the control
    // vector (0·1 + (-1)·1)/2 = -1/2
    let mixed = RationalBezierCurve::try_new(ints(&[&[0], &[1]]), vec![q!(1), q!(-1)]).unwrap();
    let up = mixed.elevate_degree(1).unwrap();
    assert_eq!(up.weights(), &[q!(1), q!(0), q!(-1)]);
    assert_eq!(up.points()[1], pt(&["-1/2"]));
    assert!(c.subdivide(&q!(0)).is_err());
    assert!(c.restrict(&q!(1 / 2), &q!(1 / 2)).is_err());
}

#[test]
fn derivative_by_the_quotient_rule() {
    let c = quarter();
    // at u = 0: c'(0) = n w1/w0 (c1 - c0) = 2 · 1/2 · (0, 1) = (0, 1)
    assert_eq!(c.derivative_at(&q!(0)).unwrap(), pt(&["0", "1"]));
    // at u = 1: c'(1) = n w1/w2 (c2 - c1) = 2 · (−1, 0)
    assert_eq!(c.derivative_at(&q!(1)).unwrap(), pt(&["-2", "0"]));
    // tangent ⟂ radius everywhere on a circle
    for t in [q!(1 / 5), q!(1 / 2), q!(7 / 8)] {
        let p = c.eval(&t).unwrap();
        let d = c.derivative_at(&t).unwrap();
        assert_eq!(p.dot(&d), q!(0));
        // independent route: w c' = p' - w' c with p', w' from the hodograph's Bernstein sum
        let h = derivative_points(&c.homogeneous(), 1).unwrap();
        let dh = bernstein_sum(&h, &t).unwrap().into_coords();
        let w = c.weight_at(&t).unwrap();
        let (dw, dp) = dh.split_last().unwrap();
        for k in 0..2 {
            assert_eq!(w.clone() * &d[k], dp[k].clone() - dw.clone() * &p[k]);
        }
    }
    // on [0, 2] the speed halves
    let slow = quarter().with_domain(q!(0), q!(2)).unwrap();
    assert_eq!(slow.derivative_at(&q!(0)).unwrap(), pt(&["0", "1/2"]));
    // degree 0: constant
    let k = RationalBezierCurve::try_new(ints(&[&[3, 4]]), vec![q!(2)]).unwrap();
    assert_eq!(k.derivative_at(&q!(1 / 2)).unwrap(), pt(&["0", "0"]));
}

#[test]
fn reweighting_is_a_reparametrization() {
    let root = qn("sqrt2/2");
    let standard = RationalBezierCurve::try_new(
        vec![
            Point::new(vec![qn("1"), qn("0")]),
            Point::new(vec![qn("1"), qn("1")]),
            Point::new(vec![qn("0"), qn("1")]),
        ],
        vec![qn("1"), root.clone(), qn("1")],
    )
    .unwrap();
    let re = standard.reweight(&root).unwrap();
    assert_eq!(re.weights(), &[qn("1"), qn("1/2"), qn("1/2")]);
    // new(u) = old(ρu / (1 - u + ρu))
    for u in [qn("1/3"), qn("1/2"), qn("4/5")] {
        let one = qn("1");
        let mapped = root.clone() * &u / (one - &u + root.clone() * &u);
        assert_eq!(re.eval(&u).unwrap(), standard.eval(&mapped).unwrap());
    }
    assert_eq!(
        standard.reweight(&qn("-1")).unwrap_err().to_string(),
        "the reweighting factor ρ must be positive, but it is -1"
    );
}

#[test]
fn conic_kinds() {
    let pts = ints(&[&[0, 0], &[1, 1], &[2, 0]]);
    let kind = |w: BigRational| {
        RationalBezierCurve::try_new(pts.clone(), vec![q!(1), w, q!(1)])
            .unwrap()
            .conic_kind()
    };
    assert_eq!(kind(q!(1 / 2)), Some(ConicKind::Ellipse));
    assert_eq!(kind(q!(1)), Some(ConicKind::Parabola));
    assert_eq!(kind(q!(2)), Some(ConicKind::Hyperbola));
    assert_eq!(kind(q!(-2)), Some(ConicKind::Hyperbola));
    assert_eq!(quarter().conic_kind(), Some(ConicKind::Ellipse));
    let cubic = RationalBezierCurve::try_new(
        ints(&[&[0], &[1], &[2], &[3]]),
        vec![q!(1), q!(1), q!(1), q!(1)],
    )
    .unwrap();
    assert_eq!(cubic.conic_kind(), None);
    let mixed = RationalBezierCurve::try_new(pts.clone(), vec![q!(1), q!(1), q!(-1)]).unwrap();
    assert_eq!(mixed.conic_kind(), None);
}

#[test]
fn over_f64() {
    let c = RationalBezierCurve::try_new(
        vec![
            Point::new(vec![1.0, 0.0]),
            Point::new(vec![1.0, 1.0]),
            Point::new(vec![0.0, 1.0]),
        ],
        vec![1.0, std::f64::consts::FRAC_1_SQRT_2, 1.0],
    )
    .unwrap();
    for t in [0.1, 0.5, 0.9] {
        let p = c.eval(&t).unwrap();
        assert!((p.dot(&p) - 1.0).abs() < 1e-12);
        let d = c.derivative_at(&t).unwrap();
        assert!(p.dot(&d).abs() < 1e-12);
    }
}
