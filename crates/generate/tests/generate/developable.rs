//! Developable surfaces, §4.

use crate::support::*;
use cagd_bezier::{BezierCurve, RationalBezierCurve};
use cagd_generate::*;
use cagd_linalg::Point;
use cagd_poly::{from_bernstein_1d, Var};
use cagd_surface::BezierSurface;
use proptest::prelude::*;

fn notes_patch() -> BezierSurface<Q> {
    BezierSurface::from_rows(vec![
        vec![pi(&[0, -1, 1]), pi(&[0, -2, 0])],
        vec![pi(&[0, 0, 1]), pi(&[0, 0, 0])],
        vec![pi(&[2, 0, 1]), pi(&[1, 0, -1])],
    ])
    .unwrap()
}

#[test]
fn notes_non_developable_patch_with_planar_end_cells() {
    let mut steps = Vec::new();
    let d = developability_bezier(&notes_patch(), &mut steps).unwrap();
    let t = &d.test;
    assert_eq!(
        t.surface,
        e("(2u^2 - u^2 v, 2u v - v - u^2 v - 1 + 2u - u^2, 1 - u^2 v - v)")
    );
    assert_eq!(t.c_u, e("(4u - 2u v, 2v - 2u v + 2 - 2u, -2u v)"));
    assert_eq!(t.c_v, e("(-u^2, 2u - 1 - u^2, -u^2 - 1)"));
    assert_eq!(t.c_uv, e("(-2u, 2 - 2u, -2u)"));
    assert_eq!(t.polynomial, p("12u - 8u^3 - 4u^2"));
    assert!(!t.developable);
    assert!(d.first_cell_planar && d.last_cell_planar);
    // it vanishes at the ends, u = 0 and u = 1, as the notes remark
    assert!(t.polynomial.eval(&[(Var::U, r(0, 1))]).unwrap() == r(0, 1));
    assert!(t.polynomial.eval(&[(Var::U, r(1, 1))]).unwrap() == r(0, 1));
    let names: Vec<&str> = steps.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["c", "c_u", "c_v", "c_uv", "c_uv · (c_u × c_v)"]);
    assert_eq!(
        steps[4].to_text(),
        "c_uv · (c_u × c_v) = -8 u^3 - 4 u^2 + 12 u"
    );
}

#[test]
fn bilinear_patches() {
    // a non-planar cell: hyperbolic paraboloid, not developable; a planar one: a plane
    let h = BezierSurface::from_rows(vec![
        vec![pi(&[0, 0, 0]), pi(&[0, 1, 0])],
        vec![pi(&[1, 0, 0]), pi(&[1, 1, 1])],
    ])
    .unwrap();
    let d = developability_bezier(&h, &mut NoSteps).unwrap();
    assert!(!d.first_cell_planar && !d.test.developable);
    let plane = BezierSurface::from_rows(vec![
        vec![pi(&[0, 0, 0]), pi(&[0, 1, 0])],
        vec![pi(&[1, 0, 0]), pi(&[2, 3, 0])],
    ])
    .unwrap();
    let d = developability_bezier(&plane, &mut NoSteps).unwrap();
    assert!(d.first_cell_planar && d.test.developable);
}

#[test]
fn errors() {
    assert_eq!(
        developability(&e("(u, v, v^2)"), &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "not a ruled surface: c has degree 2 in v; the test (9) is for ruled parametrizations \
         (1 - v) c1(u) + v c2(u), of degree 1 in v"
    );
    assert_eq!(
        developability(&e("(u, v)"), &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "the developability test needs points of R^3, but c has 2 coordinates"
    );
    assert_eq!(
        developability(&e("(u, v, t)"), &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "c must be a curve in u, v, but it uses t"
    );
    let s = BezierSurface::from_rows(vec![vec![pi(&[0, 0, 0]), pi(&[0, 1, 0]), pi(&[0, 2, 1])]])
        .unwrap();
    assert_eq!(
        developability_bezier(&s, &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "not a ruled surface: a ruled Bézier patch has bidegree (m, 1), this one has (0, 2)"
    );
    assert!(cylindrical_surface(&e("(u, u)"), &pi(&[0, 0, 1])).is_err());
    assert!(conical_surface(&e("(v, 0, 0)"), &pi(&[0, 0, 1])).is_err());
}

#[test]
fn constructors_over_f64() {
    let pf = |c: &[f64]| Point::new(c.to_vec());
    let c = BezierCurve::try_new(vec![
        pf(&[0.0, 0.0, 0.0]),
        pf(&[1.0, 0.0, 0.0]),
        pf(&[1.0, 1.0, 0.0]),
    ])
    .unwrap();
    let s = tangent_bezier(&c).unwrap();
    // c(0) + c'(0) with c'(0) = 2 (c1 - c0) = (2, 0, 0)
    assert_eq!(s.mesh().get(0, 1).unwrap().coords(), &[2.0, 0.0, 0.0]);
    let d = developability_bezier(&s, &mut NoSteps).unwrap();
    assert!(d.test.developable);
}

#[test]
fn rational_cones_and_cylinders_over_a_circle() {
    let arc = rcurve(&[&[1, 0, 0], &[1, 1, 0], &[0, 1, 0]], &["1", "1", "2"]);
    let cyl = cylindrical_rational(&arc, &pi(&[0, 0, 1])).unwrap();
    let t = developability_rational(&cyl.closed_form().unwrap()).unwrap();
    assert!(t.developable);
    let cone = conical_rational(&arc, &pi(&[0, 0, 1])).unwrap();
    assert!(
        developability_rational(&cone.closed_form().unwrap())
            .unwrap()
            .developable
    );
    // a twisted rational ruled patch is not developable
    let other = rcurve(&[&[1, 0, 1], &[0, 1, 2], &[-1, 0, 1]], &["1", "3", "1"]);
    let r = ruled_rational(&arc, &other, &mut NoSteps).unwrap();
    let t = developability_rational(&r.surface.closed_form().unwrap()).unwrap();
    assert!(!t.developable);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn cylinders_cones_and_tangent_surfaces_are_developable(
        c in polygon(4),
        w in point3(),
        m in 1usize..=3,
    ) {
        let c = c[..=m].to_vec();
        let f = from_bernstein_1d(&c, Var::U).unwrap();
        prop_assert!(developability(&cylindrical_surface(&f, &w).unwrap(), &mut NoSteps).unwrap().developable);
        prop_assert!(developability(&conical_surface(&f, &w).unwrap(), &mut NoSteps).unwrap().developable);
        let tangent = tangent_surface(&f).unwrap();
        prop_assert!(developability(&tangent, &mut NoSteps).unwrap().developable);
        let curve = BezierCurve::try_new(c.clone()).unwrap();
        let tb = tangent_bezier(&curve).unwrap();
        prop_assert_eq!(tb.closed_form().unwrap(), tangent);
        let cb = cylindrical_bezier(&curve, &w).unwrap();
        prop_assert_eq!(cb.closed_form().unwrap(), cylindrical_surface(&f, &w).unwrap());
        let kb = conical_bezier(&curve, &w).unwrap();
        prop_assert_eq!(kb.closed_form().unwrap(), conical_surface(&f, &w).unwrap());
        prop_assert!(developability_bezier(&kb, &mut NoSteps).unwrap().test.developable);
    }

    #[test]
    fn test_nine_is_the_coplanarity_ten(a in polygon(3), b in polygon(3)) {
        // (9) does not depend on v and equals c2' · (c1' × (c2 - c1)) of (10)
        let c1 = from_bernstein_1d(&a, Var::U).unwrap();
        let c2 = from_bernstein_1d(&b, Var::U).unwrap();
        let ruled = ruled_surface(&c1, &c2, &mut NoSteps).unwrap();
        let t = developability(&ruled.surface, &mut NoSteps).unwrap();
        let ten = c2
            .partial(Var::U)
            .dot(&c1.partial(Var::U).cross(&c2.checked_sub(&c1).unwrap()).unwrap())
            .unwrap();
        prop_assert_eq!(t.polynomial, ten);
    }

    #[test]
    fn rational_cylinders_are_developable(c in polygon(3), w in weights(3), dir in point3()) {
        let arc = RationalBezierCurve::try_new(c, w).unwrap();
        let cyl = cylindrical_rational(&arc, &dir).unwrap();
        prop_assert!(developability_rational(&cyl.closed_form().unwrap()).unwrap().developable);
    }
}
