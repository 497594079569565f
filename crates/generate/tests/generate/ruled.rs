//! Ruled surfaces, §3.

use crate::support::*;
use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_generate::*;
use cagd_linalg::Point;
use cagd_poly::{from_bernstein_1d, Var};
use cagd_scalar::{q, FieldOps, Quadratic};
use proptest::prelude::*;

#[test]
fn notes_parametric_example() {
    let r = ruled_surface(&e("(u, 0, u^3)"), &e("(u, 1, u^2)"), &mut NoSteps).unwrap();
    assert_eq!(r.surface, e("(u, v, u^3 - u^3 v + u^2 v)"));
    assert_eq!(at(&r.surface, Var::V, &q!(0)), e("(u, 0, u^3)"));
    assert_eq!(at(&r.surface, Var::V, &q!(1)), e("(u, 1, u^2)"));
}

#[test]
fn notes_bezier_example() {
    let c1 = curve(&[&["0", "0", "0"], &["1", "0", "1"], &["2", "0", "0"]]);
    let c2 = curve(&[&["0", "1", "0"], &["3/2", "1", "2"], &["3", "2", "1"]]);
    let r = ruled_bezier(&c1, &c2, &mut NoSteps).unwrap();
    assert_eq!(
        r.surface.mesh().to_rows(),
        vec![
            vec![pt(&["0", "0", "0"]), pt(&["0", "1", "0"])],
            vec![pt(&["1", "0", "1"]), pt(&["3/2", "1", "2"])],
            vec![pt(&["2", "0", "0"]), pt(&["3", "2", "1"])],
        ]
    );
    assert_eq!(r.surface.bidegree(), (2, 1));
    assert!(r.notes.is_empty());
}

#[test]
fn slides_rational_mesh_and_weights() {
    // slides: the mesh is {c10, c20; ...; c1m, c2m} (the slide's last row repeats c1m: erratum)
    let c1 = rcurve(&[&[1, 0, 0], &[1, 1, 0], &[0, 1, 0]], &["1", "1/2", "1"]);
    let c2 = rcurve(&[&[2, 0, 1], &[2, 2, 1], &[0, 2, 1]], &["1", "1/2", "1"]);
    let r = ruled_rational(&c1, &c2, &mut NoSteps).unwrap();
    assert_eq!(
        r.surface.mesh().to_text(),
        "{(1, 0, 0), (2, 0, 1); (1, 1, 0), (2, 2, 1); (0, 1, 0), (0, 2, 1)}"
    );
    assert_eq!(
        r.surface.weights().to_text_numbers(),
        "{1, 1; 1/2, 1/2; 1, 1}"
    );
    // equal weights: the two parametrizations coincide
    let cmp = r.parametrizations(&mut NoSteps).unwrap();
    assert!(cmp.same_segments && cmp.same_points);
}

#[test]
fn lower_degree_is_elevated_and_said() {
    let c1 = icurve(&[&[0, 0, 0], &[1, 0, 3], &[2, 0, 3], &[3, 0, 0]]);
    let c2 = icurve(&[&[0, 1, 0], &[3, 1, 3], &[3, 1, 0]]);
    let r = ruled_bezier(&c1, &c2, &mut NoSteps).unwrap();
    assert_eq!(r.notes[0].to_string(), "c2 elevated from degree 2 to 3");
    assert_eq!(r.surface.bidegree(), (3, 1));
    assert_eq!(r.c2.points()[1].to_text(), "(2, 1, 2)");
    let closed = r.surface.closed_form().unwrap();
    assert_eq!(
        at(&closed, Var::V, &q!(1)),
        from_bernstein_1d(c2.points(), Var::U).unwrap()
    );
    assert_eq!(
        at(&closed, Var::V, &q!(0)),
        from_bernstein_1d(c1.points(), Var::U).unwrap()
    );
    // the same in the other order, and for rational curves
    let r = ruled_bezier(&c2, &c1, &mut NoSteps).unwrap();
    assert_eq!(r.notes[0].to_string(), "c1 elevated from degree 2 to 3");
    let w1 = rcurve(&[&[0, 0, 0], &[1, 0, 3]], &["1", "2"]);
    let w2 = rcurve(&[&[0, 1, 0], &[1, 1, 1], &[2, 1, 0]], &["1", "1/2", "1"]);
    let r = ruled_rational(&w1, &w2, &mut NoSteps).unwrap();
    assert_eq!(r.notes[0].to_string(), "c1 elevated from degree 1 to 2");
    assert_eq!(
        r.surface.weights().to_text_numbers(),
        "{1, 1; 3/2, 1/2; 2, 1}"
    );
}

#[test]
fn projective_and_blended_parametrizations_differ_on_the_same_segments() {
    let c1 = rcurve(&[&[1, 0, 0], &[1, 1, 0], &[0, 1, 0]], &["1", "1/2", "1"]);
    let c2 = rcurve(&[&[2, 0, 1], &[2, 2, 1], &[0, 2, 1]], &["1", "2", "1"]);
    let mut steps = Vec::new();
    let cmp = ruled_rational(&c1, &c2, &mut NoSteps)
        .unwrap()
        .parametrizations(&mut steps)
        .unwrap();
    assert!(cmp.same_segments);
    assert!(!cmp.same_points);
    let (u, v) = (q!(1 / 2), q!(1 / 2));
    let at_uv = [(Var::U, u.clone()), (Var::V, v.clone())];
    let c = cmp.projective.eval(&at_uv).unwrap();
    let ct = cmp.blended.eval(&at_uv).unwrap();
    let (p1, p2) = (c1.eval(&u).unwrap(), c2.eval(&u).unwrap());
    // W1(1/2) = 3/4, W2(1/2) = 3/2
    assert_eq!(p1.to_text(), "(2/3, 2/3, 0)");
    assert_eq!(p2.to_text(), "(5/3, 5/3, 1)");
    // blended: the midpoint; projective: s = v W2 / ((1 - v) W1 + v W2) = (3/4)/(3/8 + 3/4) = 2/3
    assert_eq!(ct.to_text(), "(7/6, 7/6, 1/2)");
    assert_eq!(c.to_text(), "(4/3, 4/3, 2/3)");
    let s = cmp.segment_parameter.eval(&at_uv).unwrap();
    assert_eq!(s.to_text(), "(2/3)");
    assert_eq!(c, p1.lerp(&p2, &s[0]));
    assert_ne!(c, ct);
    assert_eq!(steps.len(), 3);
}

#[test]
fn errors() {
    assert_eq!(
        ruled_surface(&e("(u, 0, u^3)"), &e("(u, 1)"), &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "c1 has 3 coordinates but c2 has 2: they must live in the same space"
    );
    assert_eq!(
        ruled_surface(&e("(u, 0, u^3)"), &e("(u, v, 1)"), &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "c2 must be a curve in u, but it uses v"
    );
    let c1 = icurve(&[&[0, 0, 0], &[1, 0, 3]]);
    let c2 = icurve(&[&[0, 0], &[1, 0]]);
    assert!(matches!(
        ruled_bezier(&c1, &c2, &mut NoSteps),
        Err(GenerateError::DimensionMismatch { .. })
    ));
    // every weight zero is refused where the curve is built (one zero weight is a control
    // vector, which the problem layer's reading refuses for a ruled surface)
    let bad =
        RationalBezierCurve::try_new(vec![pi(&[0, 0, 0]), pi(&[1, 0, 0])], vec![q!(0), q!(0)]);
    assert!(bad.is_err());
}

#[test]
fn quadratic_and_float() {
    let h = qd("sqrt2/2");
    let one = Quadratic::from_i64(1);
    let pq = |c: &[i64]| Point::<Quadratic>::from_ints(c);
    let c1 = RationalBezierCurve::try_new(
        vec![pq(&[1, 0, 0]), pq(&[1, 1, 0]), pq(&[0, 1, 0])],
        vec![one.clone(), h.clone(), one.clone()],
    )
    .unwrap();
    let c2 = RationalBezierCurve::try_new(
        vec![pq(&[1, 0, 1]), pq(&[1, 1, 1]), pq(&[0, 1, 1])],
        vec![one.clone(), h, one],
    )
    .unwrap();
    let r = ruled_rational(&c1, &c2, &mut NoSteps).unwrap();
    assert_eq!(
        r.surface.weights().to_text_numbers(),
        "{1, 1; √2/2, √2/2; 1, 1}"
    );
    let cmp = r.parametrizations(&mut NoSteps).unwrap();
    assert!(cmp.same_points && cmp.same_segments);
    // a cylinder over the circle: x^2 + y^2 = 1 at a point of the patch
    let p = cmp
        .projective
        .eval(&[(Var::U, qd("1/3")), (Var::V, qd("1/2"))])
        .unwrap();
    assert_eq!(
        p[0].clone() * &p[0] + p[1].clone() * &p[1],
        Quadratic::from_i64(1)
    );

    let pf = |c: &[f64]| Point::new(c.to_vec());
    let c1 = BezierCurve::try_new(vec![pf(&[0.0, 0.0, 0.0]), pf(&[1.0, 0.0, 0.0])]).unwrap();
    let c2 = BezierCurve::try_new(vec![pf(&[0.0, 1.0, 0.0]), pf(&[1.0, 1.0, 1.0])]).unwrap();
    let r = ruled_bezier(&c1, &c2, &mut NoSteps).unwrap();
    assert_eq!(
        r.surface.mesh().get(1, 1).unwrap().coords(),
        &[1.0, 1.0, 1.0]
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn bezier_patch_is_the_ruled_surface_of_its_curves(
        a in polygon(4),
        b in polygon(3),
        m in 0usize..=3,
        n in 0usize..=2,
    ) {
        let (a, b) = (a[..=m].to_vec(), b[..=n].to_vec());
        let c1 = BezierCurve::try_new(a.clone()).unwrap();
        let c2 = BezierCurve::try_new(b.clone()).unwrap();
        let r = ruled_bezier(&c1, &c2, &mut NoSteps).unwrap();
        let f1 = from_bernstein_1d(&a, Var::U).unwrap();
        let f2 = from_bernstein_1d(&b, Var::U).unwrap();
        let closed = r.surface.closed_form().unwrap();
        prop_assert_eq!(&closed, &ruled_surface(&f1, &f2, &mut NoSteps).unwrap().surface);
        prop_assert_eq!(at(&closed, Var::V, &q!(0)), f1);
        prop_assert_eq!(at(&closed, Var::V, &q!(1)), f2);
        prop_assert_eq!(r.notes.len(), usize::from(m != n));
    }

    #[test]
    fn rational_patch_joins_the_curves_by_segments(
        a in polygon(3),
        b in polygon(3),
        w in weights(3),
        o in weights(3),
        u in param(),
    ) {
        let c1 = RationalBezierCurve::try_new(a, w).unwrap();
        let c2 = RationalBezierCurve::try_new(b, o).unwrap();
        let r = ruled_rational(&c1, &c2, &mut NoSteps).unwrap();
        let cmp = r.parametrizations(&mut NoSteps).unwrap();
        prop_assert!(cmp.same_segments);
        let p0 = cmp.projective.eval(&[(Var::U, u.clone()), (Var::V, q!(0))]).unwrap();
        let p1 = cmp.projective.eval(&[(Var::U, u.clone()), (Var::V, q!(1))]).unwrap();
        prop_assert_eq!(p0, c1.eval(&u).unwrap());
        prop_assert_eq!(p1, c2.eval(&u).unwrap());
        let b0 = cmp.blended.eval(&[(Var::U, u.clone()), (Var::V, q!(0))]).unwrap();
        prop_assert_eq!(b0, c1.eval(&u).unwrap());
    }
}
