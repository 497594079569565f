//! B-spline and NURBS versions: translational (4)-(5), ruled, Coons (knot insertion), and the
//! whole surface of revolution with the NURBS circle.

use crate::support::*;
use cagd_bezier::RationalBezierCurve;
use cagd_bspline::{circle_of_arcs, unit_circle, BSplineCurve, KnotVector, NurbsCurve};
use cagd_generate::*;
use cagd_linalg::Point;
use cagd_scalar::{q, ExactRational, FieldOps, Print, Quadratic};
use proptest::prelude::*;

type K = Quadratic;

/// A clamped B-spline curve of degree p on [0, 1] with the interior knots given.
fn bspline(p: usize, interior: &[Q], points: Vec<Point<Q>>) -> BSplineCurve<Q> {
    let mut breaks = vec![q!(0)];
    breaks.extend(interior.iter().cloned());
    breaks.push(q!(1));
    BSplineCurve::try_new(KnotVector::clamped(p, &breaks).unwrap(), points).unwrap()
}

/// A random clamped B-spline curve on [0, 1]: degree 1 or 2, no interior knot or one of
/// 1/3, 1/2, 2/3.
fn random_bspline() -> impl Strategy<Value = BSplineCurve<Q>> {
    (1usize..=2, 0usize..=3).prop_flat_map(|(p, k)| {
        let interior: Vec<Q> = match k {
            0 => vec![],
            1 => vec![q!(1 / 3)],
            2 => vec![q!(1 / 2)],
            _ => vec![q!(2 / 3)],
        };
        let count = p + 1 + interior.len();
        polygon(count).prop_map(move |pts| bspline(p, &interior, pts))
    })
}

fn with_points(c: &BSplineCurve<Q>, pts: Vec<Point<Q>>) -> BSplineCurve<Q> {
    BSplineCurve::try_new(c.knots().clone(), pts).unwrap()
}

fn kp(c: &[i64]) -> Point<K> {
    Point::from_ints(c)
}

fn sphere_profile() -> NurbsCurve<K> {
    let one = K::from_i64(1);
    let arc = RationalBezierCurve::try_new(
        vec![kp(&[1, 0, 0]), kp(&[1, 0, 1]), kp(&[0, 0, 1])],
        vec![one.clone(), qd("sqrt2/2"), one],
    )
    .unwrap();
    nurbs_from_bezier(&arc).unwrap()
}

#[test]
fn compatibility_errors() {
    let c1 = bspline(1, &[], vec![pi(&[0, 0, 0]), pi(&[1, 0, 0])]);
    let on_two = BSplineCurve::try_new(
        KnotVector::clamped(1, &[q!(0), q!(2)]).unwrap(),
        vec![pi(&[0, 1, 0]), pi(&[1, 1, 0])],
    )
    .unwrap();
    assert_eq!(
        ruled_bspline(&c1, &on_two, &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "c1 is defined on [0, 1] but c2 on [0, 2]: reparametrize them onto the same interval"
    );
    let unclamped = BSplineCurve::try_new(
        KnotVector::from_notes(vec![q!(0), q!(1), q!(2), q!(3)], 2).unwrap(),
        vec![pi(&[0, 0, 0]), pi(&[1, 0, 0]), pi(&[2, 1, 0])],
    )
    .unwrap();
    assert_eq!(
        ruled_bspline(&c1, &unclamped, &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "c2 is not clamped (knots {0, 1, 2, 3}): the construction needs curves that start and \
         end at their end control points (end knots repeated p times)"
    );
    let flat = bspline(1, &[], vec![pi(&[0, 0]), pi(&[1, 0])]);
    assert!(matches!(
        ruled_bspline(&c1, &flat, &mut NoSteps),
        Err(GenerateError::DimensionMismatch { .. })
    ));
}

#[test]
fn ruled_bspline_elevates_and_inserts() {
    let c1 = bspline(
        2,
        &[q!(1 / 2)],
        vec![
            pi(&[0, 0, 0]),
            pi(&[1, 0, 2]),
            pi(&[2, 0, 2]),
            pi(&[3, 0, 0]),
        ],
    );
    let c2 = bspline(1, &[], vec![pi(&[0, 1, 0]), pi(&[3, 1, 0])]);
    let r = ruled_bspline(&c1, &c2, &mut NoSteps).unwrap();
    let notes: Vec<String> = r
        .notes
        .iter()
        .take(2)
        .map(|n| format!("note: {n}"))
        .collect();
    assert_eq!(
        notes,
        [
            "note: c2 elevated from degree 1 to 2",
            "note: c2: knots 1/2 inserted"
        ]
    );
    assert_eq!(r.surface.knots_u().to_text(), "{0, 0, 1/2, 1, 1}");
    assert_eq!(r.surface.knots_v().to_text(), "{0, 1}");
    assert_eq!(
        r.surface.mesh().to_text(),
        "{(0, 0, 0), (0, 1, 0); (1, 0, 2), (3/4, 1, 0); (2, 0, 2), (9/4, 1, 0); (3, 0, 0), (3, 1, 0)}"
    );
    for u in [q!(0), q!(1 / 4), q!(1 / 2), q!(5 / 7), q!(1)] {
        assert_eq!(r.surface.eval(&u, &q!(0)).unwrap(), c1.eval(&u).unwrap());
        assert_eq!(r.surface.eval(&u, &q!(1)).unwrap(), c2.eval(&u).unwrap());
    }
}

#[test]
fn notes_examples_through_the_bspline_route() {
    // the Bézier Coons example of the notes, as clamped single-span B-splines
    let c1 = bspline(
        3,
        &[],
        vec![
            pt(&["0", "0", "0"]),
            pt(&["1/2", "0", "2"]),
            pt(&["1", "0", "3"]),
            pt(&["2", "0", "0"]),
        ],
    );
    let c2 = bspline(
        3,
        &[],
        vec![
            pt(&["0", "3", "0"]),
            pt(&["1/2", "3", "3"]),
            pt(&["1", "3", "1"]),
            pt(&["2", "4", "0"]),
        ],
    );
    let d1 = bspline(2, &[], vec![pi(&[0, 0, 0]), pi(&[0, 1, 3]), pi(&[0, 3, 0])]);
    let d2 = bspline(2, &[], vec![pi(&[2, 0, 0]), pi(&[2, 1, 2]), pi(&[2, 4, 0])]);
    let coons = coons_bspline(&c1, &c2, &d1, &d2, &mut NoSteps).unwrap();
    assert_eq!(
        coons.surface.mesh().to_text(),
        "{(0, 0, 0), (0, 1, 3), (0, 3, 0); (1/2, 0, 2), (1/2, 5/6, 31/6), (1/2, 3, 3); \
         (1, 0, 3), (1, 2/3, 13/3), (1, 3, 1); (2, 0, 0), (2, 1, 2), (2, 4, 0)}"
    );
    assert_eq!(
        coons.c_cd.mesh().get(2, 1).unwrap().to_text(),
        "(4/3, 11/6, 0)"
    );
    // translational: the two parabolas
    let t = translational_bspline(
        &bspline(2, &[], vec![pi(&[1, 0, 0]), pi(&[2, 0, 1]), pi(&[3, 0, 0])]),
        &bspline(
            2,
            &[],
            vec![pi(&[1, 0, 0]), pi(&[1, 1, -1]), pi(&[1, 2, 0])],
        ),
        &mut NoSteps,
    )
    .unwrap();
    assert_eq!(
        t.surface.mesh().to_text(),
        "{(1, 0, 0), (1, 1, -1), (1, 2, 0); (2, 0, 1), (2, 1, 0), (2, 2, 1); \
         (3, 0, 0), (3, 1, -1), (3, 2, 0)}"
    );
    let err = translational_bspline(
        &bspline(1, &[], vec![pi(&[1, 0, 0]), pi(&[2, 0, 0])]),
        &bspline(1, &[], vec![pi(&[0, 0, 0]), pi(&[0, 1, 0])]),
        &mut NoSteps,
    )
    .unwrap_err();
    assert_eq!(
        err.to_string(),
        "the curves do not meet: c1(0) = (1, 0, 0) but d1(0) = (0, 0, 0)"
    );
}

#[test]
fn coons_bspline_corner_error() {
    let c1 = bspline(1, &[], vec![pi(&[0, 0, 0]), pi(&[2, 0, 0])]);
    let c2 = bspline(1, &[], vec![pi(&[0, 2, 0]), pi(&[2, 2, 0])]);
    let d1 = bspline(1, &[], vec![pi(&[0, 0, 0]), pi(&[0, 2, 0])]);
    let d2 = bspline(1, &[], vec![pi(&[2, 0, 1]), pi(&[2, 2, 0])]);
    assert_eq!(
        coons_bspline(&c1, &c2, &d1, &d2, &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "curves c1 and d2 do not meet at corner b: c1(1) = (2, 0, 0), d2(0) = (2, 0, 1)"
    );
}

#[test]
fn notes_nine_point_circle_hemisphere() {
    let r = revolution_nurbs(&sphere_profile(), &unit_circle().unwrap(), &mut NoSteps).unwrap();
    assert_eq!(r.surface.knots_u().to_text(), "{0, 0, 1, 1}");
    assert_eq!(
        r.surface.knots_v().to_text(),
        "{0, 0, 1/4, 1/4, 1/2, 1/2, 3/4, 3/4, 1, 1}"
    );
    assert_eq!(
        r.surface
            .mesh()
            .row(0)
            .unwrap()
            .iter()
            .map(Point::to_text)
            .collect::<Vec<_>>(),
        [
            "(1, 0, 0)",
            "(1, 1, 0)",
            "(0, 1, 0)",
            "(-1, 1, 0)",
            "(-1, 0, 0)",
            "(-1, -1, 0)",
            "(0, -1, 0)",
            "(1, -1, 0)",
            "(1, 0, 0)"
        ]
    );
    for (u, v) in [("1/2", "1/8"), ("1/3", "5/8"), ("2/7", "9/10")] {
        let p = r.surface.eval(&qd(u), &qd(v)).unwrap();
        assert_eq!(p.dot(&p), K::from_i64(1), "({u}, {v})");
    }
    assert_eq!(r.notes[0].to_string(), "knots in u: {0, 0, 1, 1}");
}

#[test]
fn slides_hemisphere_on_zero_four() {
    let r = revolution_nurbs_arcs(
        &sphere_profile(),
        4,
        (K::from_i64(0), K::from_i64(4)),
        &mut NoSteps,
    )
    .unwrap();
    assert_eq!(
        r.surface.mesh().to_text(),
        "{(1, 0, 0), (1, 1, 0), (0, 1, 0), (-1, 1, 0), (-1, 0, 0), (-1, -1, 0), (0, -1, 0), \
         (1, -1, 0), (1, 0, 0); \
         (1, 0, 1), (1, 1, 1), (0, 1, 1), (-1, 1, 1), (-1, 0, 1), (-1, -1, 1), (0, -1, 1), \
         (1, -1, 1), (1, 0, 1); \
         (0, 0, 1), (0, 0, 1), (0, 0, 1), (0, 0, 1), (0, 0, 1), (0, 0, 1), (0, 0, 1), \
         (0, 0, 1), (0, 0, 1)}"
    );
    // 9 weights a row (the slide prints a tenth column: erratum)
    assert_eq!(
        r.surface.weights().to_text_numbers(),
        "{1, √2/2, 1, √2/2, 1, √2/2, 1, √2/2, 1; \
         √2/2, 1/2, √2/2, 1/2, √2/2, 1/2, √2/2, 1/2, √2/2; \
         1, √2/2, 1, √2/2, 1, √2/2, 1, √2/2, 1}"
    );
    assert_eq!(
        r.surface.knots_v().to_text(),
        "{0, 0, 1, 1, 2, 2, 3, 3, 4, 4}"
    );
    assert_eq!(r.surface.knots_u().to_text(), "{0, 0, 1, 1}");
    assert_eq!(
        r.surface.eval(&qd("1/2"), &qd("1/2")).unwrap().to_text(),
        "(1/2, 1/2, √2/2)"
    );
}

#[test]
fn three_and_six_arcs_over_root_three() {
    // a truncated cone, a polynomial segment from (2, 0, 0) to (1, 0, 1)
    let one = qd("1");
    let seg = NurbsCurve::try_new(
        KnotVector::clamped(1, &[qd("0"), qd("1")]).unwrap(),
        vec![kp(&[2, 0, 0]), kp(&[1, 0, 1])],
        vec![one.clone(), one],
    )
    .unwrap();
    for arcs in [3, 6] {
        let r = revolution_nurbs_arcs(&seg, arcs, (qd("0"), qd("1")), &mut NoSteps).unwrap();
        assert_eq!(r.surface.mesh().cols(), 2 * arcs + 1);
        let middle = r.surface.weights().get(0, 1).unwrap().to_text();
        assert_eq!(middle, if arcs == 3 { "1/2" } else { "√3/2" });
        for (u, v) in [("1/2", "1/7"), ("1/3", "2/3"), ("0", "5/6"), ("1", "1/2")] {
            assert!(
                r.on_parallel(&qd(u), &qd(v)).unwrap(),
                "{arcs} arcs at ({u}, {v})"
            );
        }
    }
    // N = 3 has a rational middle weight but vertices with √3: not over the rationals
    let qseg = NurbsCurve::try_new(
        KnotVector::clamped(1, &[q!(0), q!(1)]).unwrap(),
        vec![pi(&[2, 0, 0]), pi(&[1, 0, 1])],
        vec![q!(1), q!(1)],
    )
    .unwrap();
    let err = revolution_nurbs_arcs(&qseg, 3, (q!(0), q!(1)), &mut NoSteps).unwrap_err();
    assert!(
        err.to_string().contains("needs the quadratic field √3"),
        "{err}"
    );
    let err = revolution_nurbs_arcs(&qseg, 4, (q!(0), q!(1)), &mut NoSteps).unwrap_err();
    assert!(
        err.to_string().contains("needs the quadratic field √2"),
        "{err}"
    );
    // a circle off the XY plane is refused
    let lifted = NurbsCurve::try_new(
        KnotVector::clamped(1, &[q!(0), q!(1)]).unwrap(),
        vec![pi(&[1, 0, 1]), pi(&[0, 1, 1])],
        vec![q!(1), q!(1)],
    )
    .unwrap();
    assert_eq!(
        revolution_nurbs(&qseg, &lifted, &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "control point 0 of the circle, (1, 0, 1), is not a point (x, y) or (x, y, 0) of the XY \
         plane: the parallels need the unit circle about the origin"
    );
}

#[test]
fn ruled_and_translational_nurbs() {
    let w = |x: &[&str]| {
        x.iter()
            .map(|t| cagd_scalar::parse_rational(t).unwrap())
            .collect::<Vec<_>>()
    };
    let c1 = NurbsCurve::try_new(
        KnotVector::clamped(2, &[q!(0), q!(1)]).unwrap(),
        vec![pi(&[1, 0, 0]), pi(&[1, 1, 0]), pi(&[0, 1, 0])],
        w(&["1", "1/2", "1"]),
    )
    .unwrap();
    let c2 = NurbsCurve::try_new(
        KnotVector::clamped(1, &[q!(0), q!(1)]).unwrap(),
        vec![pi(&[1, 0, 1]), pi(&[0, 1, 1])],
        w(&["1", "3"]),
    )
    .unwrap();
    let r = ruled_nurbs(&c1, &c2, &mut NoSteps).unwrap();
    assert_eq!(r.notes[0].to_string(), "c2 elevated from degree 1 to 2");
    assert_eq!(
        r.surface.weights().to_text_numbers(),
        "{1, 1; 1/2, 2; 1, 3}"
    );
    for u in [q!(0), q!(1 / 3), q!(1)] {
        assert_eq!(r.surface.eval(&u, &q!(0)).unwrap(), c1.eval(&u).unwrap());
        assert_eq!(r.surface.eval(&u, &q!(1)).unwrap(), c2.eval(&u).unwrap());
    }
    let d1 = NurbsCurve::try_new(
        KnotVector::clamped(1, &[q!(0), q!(1)]).unwrap(),
        vec![pi(&[1, 0, 0]), pi(&[1, 0, 2])],
        w(&["2", "1"]),
    )
    .unwrap();
    let t = translational_nurbs(&c1, &d1, &mut NoSteps).unwrap();
    assert_eq!(
        t.surface.weights().to_text_numbers(),
        "{2, 1; 1, 1/2; 2, 1}"
    );
    let (u, v) = (q!(1 / 3), q!(3 / 4));
    let want = &(&c1.eval(&u).unwrap() + &d1.eval(&v).unwrap()) - &t.a;
    assert_eq!(t.surface.eval(&u, &v).unwrap(), want);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn translational_bspline_is_c1_plus_d1_minus_a(
        c in random_bspline(),
        d in random_bspline(),
        u in param(),
        v in param(),
    ) {
        let mut dp = d.points().to_vec();
        dp[0] = c.points()[0].clone();
        let d = with_points(&d, dp);
        let t = translational_bspline(&c, &d, &mut NoSteps).unwrap();
        let want = &(&c.eval(&u).unwrap() + &d.eval(&v).unwrap()) - &t.a;
        prop_assert_eq!(t.surface.eval(&u, &v).unwrap(), want);
    }

    #[test]
    fn ruled_bspline_joins_the_curves(c in random_bspline(), d in random_bspline(), u in param(), v in param()) {
        let r = ruled_bspline(&c, &d, &mut NoSteps).unwrap();
        let want = c.eval(&u).unwrap().lerp(&d.eval(&u).unwrap(), &v);
        prop_assert_eq!(r.surface.eval(&u, &v).unwrap(), want);
        prop_assert_eq!(r.c1.knots(), r.c2.knots());
    }

    #[test]
    fn coons_bspline_is_the_coons_formula(
        c1 in random_bspline(),
        c2 in random_bspline(),
        d1 in random_bspline(),
        d2 in random_bspline(),
        u in param(),
        v in param(),
    ) {
        // close the quadrilateral on the end control points (clamped curves)
        let (mut p1, mut p2) = (d1.points().to_vec(), d2.points().to_vec());
        let (l1, l2) = (p1.len() - 1, p2.len() - 1);
        p1[0] = c1.points()[0].clone();
        p2[0] = c1.points()[c1.points().len() - 1].clone();
        p1[l1] = c2.points()[0].clone();
        p2[l2] = c2.points()[c2.points().len() - 1].clone();
        let (d1, d2) = (with_points(&d1, p1), with_points(&d2, p2));
        let coons = coons_bspline(&c1, &c2, &d1, &d2, &mut NoSteps).unwrap();
        let ev = |c: &BSplineCurve<Q>, t: &Q| c.eval(t).unwrap();
        let c_c = ev(&c1, &u).lerp(&ev(&c2, &u), &v);
        let c_d = ev(&d1, &v).lerp(&ev(&d2, &v), &u);
        let c_cd = coons.a.lerp(&coons.b, &u).lerp(&coons.c.lerp(&coons.d, &u), &v);
        let want = &(&c_c + &c_d) - &c_cd;
        prop_assert_eq!(coons.surface.eval(&u, &v).unwrap(), want);
        prop_assert_eq!(coons.c_c.eval(&u, &v).unwrap(), c_c);
        prop_assert_eq!(coons.c_cd.eval(&u, &v).unwrap(), c_cd);
    }

    #[test]
    fn hemisphere_points_are_on_the_sphere(u in param(), v in param(), k in 0i64..4) {
        let r = revolution_nurbs_arcs(&sphere_profile(), 4, (K::from_i64(0), K::from_i64(4)), &mut NoSteps).unwrap();
        let (u, v) = (<K as ExactRational>::from_rational(&u), <K as ExactRational>::from_rational(&v) + K::from_i64(k));
        let p = r.surface.eval(&u, &v).unwrap();
        prop_assert_eq!(p.dot(&p), K::from_i64(1));
        prop_assert!(r.on_parallel(&u, &v).unwrap());
        prop_assert!(p.coords()[2] >= K::from_i64(0));
    }
}

#[test]
fn circle_of_arcs_is_used_as_given() {
    // the circle of the crate cagd-bspline, on [0, 1], is the notes' 9-point circle
    let c: NurbsCurve<K> = circle_of_arcs(4, &K::from_i64(1), None, (qd("0"), qd("1"))).unwrap();
    assert_eq!(c, unit_circle().unwrap());
}
