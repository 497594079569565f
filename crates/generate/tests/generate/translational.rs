//! Translational surfaces, §2.

use crate::support::*;
use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_generate::*;
use cagd_linalg::Point;
use cagd_poly::{from_bernstein_1d, Var};
use cagd_scalar::{q, FieldOps, Quadratic};
use proptest::prelude::*;

#[test]
fn notes_parametric_example() {
    let mut steps = Vec::new();
    let t = translational_surface(&e("(u, 1, u^2)"), &e("(0, v + 1, v^3)"), &mut steps).unwrap();
    assert_eq!(t.a, pi(&[0, 1, 0]));
    assert_eq!(t.surface, e("(u, v + 1, u^2 + v^3)"));
    assert!(has_zero_twist(&t.surface));
    assert_eq!(
        steps_to_text(&steps),
        "a = (0, 1, 0)\nc(u, v) = (u, v + 1, v^3 + u^2)"
    );
}

#[test]
fn notes_bezier_example() {
    let c1 = icurve(&[&[1, 0, 0], &[2, 0, 1], &[3, 0, 0]]);
    let d1 = icurve(&[&[1, 0, 0], &[1, 1, -1], &[1, 2, 0]]);
    let mut steps = Vec::new();
    let t = translational_bezier(&c1, &d1, &mut steps).unwrap();
    let expected = vec![
        vec![pi(&[1, 0, 0]), pi(&[1, 1, -1]), pi(&[1, 2, 0])],
        vec![pi(&[2, 0, 1]), pi(&[2, 1, 0]), pi(&[2, 2, 1])],
        vec![pi(&[3, 0, 0]), pi(&[3, 1, -1]), pi(&[3, 2, 0])],
    ];
    assert_eq!(t.surface.mesh().to_rows(), expected);
    assert_eq!(t.a.to_text(), "(1, 0, 0)");
    // the notes list every vertex: c_1,1 = c11 + d11 - a = (2, 1, 0), c_2,1 = (3, 1, -1)
    assert_eq!(
        find_step(&steps, "c_1,1"),
        Some(&StepValue::Point(pi(&[2, 1, 0])))
    );
    assert_eq!(
        find_step(&steps, "c_2,1"),
        Some(&StepValue::Point(pi(&[3, 1, -1])))
    );
    assert!(mesh_twists(t.surface.mesh()).iter().all(Point::is_zero));
    assert_eq!(mesh_twists(t.surface.mesh()).rows(), 2);
    // the patch's closed form is the translational surface of the curves' closed forms
    let c = t.surface.closed_form().unwrap();
    let direct = translational_surface(
        &from_bernstein_1d(c1.points(), Var::U).unwrap(),
        &from_bernstein_1d(d1.points(), Var::V).unwrap(),
        &mut NoSteps,
    )
    .unwrap();
    assert_eq!(c, direct.surface);
}

#[test]
fn errors_name_the_points_and_the_curves() {
    let err =
        translational_surface(&e("(1 + u, 0, 0)"), &e("(v, v, 0)"), &mut NoSteps).unwrap_err();
    assert_eq!(
        err.to_string(),
        "the curves do not meet: c1(0) = (1, 0, 0) but d1(0) = (0, 0, 0)"
    );
    let err = translational_surface(&e("(u, 0, 0)"), &e("(u, 0, 0)"), &mut NoSteps).unwrap_err();
    assert_eq!(err.to_string(), "d1 must be a curve in v, but it uses u");
    let err = translational_surface(&e("(u, 0, 0)"), &e("(v, 0)"), &mut NoSteps).unwrap_err();
    assert_eq!(
        err.to_string(),
        "c1 has 3 coordinates but d1 has 2: they must live in the same space"
    );
    let c1 = icurve(&[&[1, 0, 0], &[2, 0, 1]]);
    let d1 = icurve(&[&[0, 0, 0], &[1, 1, 0]]);
    assert_eq!(
        translational_bezier(&c1, &d1, &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "the curves do not meet: c1(0) = (1, 0, 0) but d1(0) = (0, 0, 0)"
    );
    let d2 = icurve(&[&[1, 0], &[1, 1]]);
    assert!(matches!(
        translational_bezier(&c1, &d2, &mut NoSteps),
        Err(GenerateError::DimensionMismatch { .. })
    ));
}

#[test]
fn twist_of_a_mesh_that_is_not_translational() {
    let mesh = cagd_surface::Mesh::mesh(vec![
        vec![pi(&[0, 0, 0]), pi(&[0, 1, 0])],
        vec![pi(&[1, 0, 0]), pi(&[1, 1, 1])],
    ])
    .unwrap();
    assert_eq!(mesh_twists(&mesh).get(0, 0).unwrap().to_text(), "(0, 0, 1)");
    assert!(!has_zero_twist(&e("(u, v, u v)")));
}

#[test]
fn rational_weights_multiply_and_the_twist_vanishes() {
    let c1 = rcurve(&[&[1, 0, 0], &[1, 1, 0], &[0, 1, 0]], &["1", "1/2", "1"]);
    let d1 = rcurve(&[&[1, 0, 0], &[1, 0, 1], &[2, 0, 2]], &["1", "3", "2"]);
    let mut steps = Vec::new();
    let t = translational_rational(&c1, &d1, &mut steps).unwrap();
    assert_eq!(
        t.surface.weights().to_text_numbers(),
        "{1, 3, 2; 1/2, 3/2, 1; 1, 3, 2}"
    );
    let closed = t.surface.closed_form().unwrap();
    assert!(rational_twist(&closed).numerator().is_zero());
    // but a generic rational patch has a twist
    let other = cagd_surface::RationalBezierSurface::try_new(
        t.surface.mesh().clone(),
        cagd_surface::Grid::from_fn(3, 3, |i, j| if (i, j) == (1, 1) { q!(5) } else { q!(1) }),
    )
    .unwrap();
    assert!(!rational_twist(&other.closed_form().unwrap())
        .numerator()
        .is_zero());
    assert_eq!(
        find_step(&steps, "weights").map(|w| w.to_text()),
        Some("{1, 3, 2; 1/2, 3/2, 1; 1, 3, 2}".to_string())
    );
}

#[test]
fn quadratic_and_float_scalars() {
    let h = qd("sqrt2/2");
    let one = Quadratic::from_i64(1);
    let pq = |c: &[i64]| Point::<Quadratic>::from_ints(c);
    let c1 = RationalBezierCurve::try_new(
        vec![pq(&[1, 0, 0]), pq(&[1, 1, 0]), pq(&[0, 1, 0])],
        vec![one.clone(), h.clone(), one.clone()],
    )
    .unwrap();
    let d1 =
        RationalBezierCurve::try_new(vec![pq(&[1, 0, 0]), pq(&[1, 0, 1])], vec![one.clone(), h])
            .unwrap();
    let t = translational_rational(&c1, &d1, &mut NoSteps).unwrap();
    assert_eq!(
        t.surface.weights().to_text_numbers(),
        "{1, √2/2; √2/2, 1/2; 1, √2/2}"
    );
    // a point of the patch is c1(u) + d1(v) - a exactly in Q(√2)
    let (u, v) = (qd("1/3"), qd("2/5"));
    let closed = t.surface.closed_form().unwrap();
    let got = closed
        .eval(&[(Var::U, u.clone()), (Var::V, v.clone())])
        .unwrap();
    let want = &(&c1.eval(&u).unwrap() + &d1.eval(&v).unwrap()) - &t.a;
    assert_eq!(got, want);

    let pf = |c: &[f64]| Point::new(c.to_vec());
    let c1 = BezierCurve::try_new(vec![pf(&[1.0, 0.0, 0.0]), pf(&[2.0, 0.0, 1.0])]).unwrap();
    let d1 = BezierCurve::try_new(vec![pf(&[1.0, 0.0, 0.0]), pf(&[1.0, 0.5, 0.0])]).unwrap();
    let t = translational_bezier(&c1, &d1, &mut NoSteps).unwrap();
    assert_eq!(
        t.surface.mesh().get(1, 1).unwrap().coords(),
        &[2.0, 0.5, 1.0]
    );
}

/// Two random Bézier polygons with a common first point.
fn meeting_polygons() -> impl Strategy<Value = (Vec<Point<Q>>, Vec<Point<Q>>)> {
    (1usize..=3, 1usize..=3).prop_flat_map(|(m, n)| {
        (polygon(m + 1), polygon(n + 1)).prop_map(|(c, mut d)| {
            d[0] = c[0].clone();
            (c, d)
        })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn parametric_surface_interpolates_both_curves((c, d) in meeting_polygons()) {
        let c1 = from_bernstein_1d(&c, Var::U).unwrap();
        let d1 = from_bernstein_1d(&d, Var::V).unwrap();
        let t = translational_surface(&c1, &d1, &mut NoSteps).unwrap();
        prop_assert_eq!(at(&t.surface, Var::V, &q!(0)), c1);
        prop_assert_eq!(at(&t.surface, Var::U, &q!(0)), d1);
        prop_assert!(has_zero_twist(&t.surface));
    }

    #[test]
    fn bezier_mesh_is_the_translational_surface((c, d) in meeting_polygons()) {
        let c1 = BezierCurve::try_new(c.clone()).unwrap();
        let d1 = BezierCurve::try_new(d.clone()).unwrap();
        let t = translational_bezier(&c1, &d1, &mut NoSteps).unwrap();
        let direct = translational_surface(
            &from_bernstein_1d(&c, Var::U).unwrap(),
            &from_bernstein_1d(&d, Var::V).unwrap(),
         &mut NoSteps,).unwrap();
        prop_assert_eq!(t.surface.closed_form().unwrap(), direct.surface);
        prop_assert!(mesh_twists(t.surface.mesh()).iter().all(Point::is_zero));
    }

    #[test]
    fn rational_patch_is_c1_plus_d1_minus_a(
        (c, d) in meeting_polygons(),
        w in weights(4),
        o in weights(4),
        u in param(),
        v in param(),
    ) {
        let c1 = RationalBezierCurve::try_new(c.clone(), w[..c.len()].to_vec()).unwrap();
        let d1 = RationalBezierCurve::try_new(d.clone(), o[..d.len()].to_vec()).unwrap();
        let t = translational_rational(&c1, &d1, &mut NoSteps).unwrap();
        let closed = t.surface.closed_form().unwrap();
        let got = closed.eval(&[(Var::U, u.clone()), (Var::V, v.clone())]).unwrap();
        let want = &(&c1.eval(&u).unwrap() + &d1.eval(&v).unwrap()) - &t.a;
        prop_assert_eq!(got, want);
    }
}
