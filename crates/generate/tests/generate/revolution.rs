//! Surfaces of revolution, §6.

use crate::support::*;
use cagd_bezier::RationalBezierCurve;
use cagd_generate::*;
use cagd_linalg::Point;
use cagd_poly::{parse_vec_poly, Var};
use cagd_scalar::{q, ExactRational, FieldOps, Quadratic};
use proptest::prelude::*;

type K = Quadratic;

fn kp(c: &[i64]) -> Point<K> {
    Point::from_ints(c)
}

fn quarter_arc_xz() -> RationalBezierCurve<K> {
    let one = K::from_i64(1);
    RationalBezierCurve::try_new(
        vec![kp(&[1, 0, 0]), kp(&[1, 0, 1]), kp(&[0, 0, 1])],
        vec![one.clone(), qd("sqrt2/2"), one],
    )
    .unwrap()
}

#[test]
fn parametric_form_as_text() {
    let s = revolution_surface(&e("(u + 1, 0, u^2)")).unwrap();
    assert_eq!(s.to_text(), "((u + 1) cos v, (u + 1) sin v, u^2)");
    assert_eq!(
        s.to_latex(),
        "\\left((u + 1) \\cos v, (u + 1) \\sin v, u^{2}\\right)"
    );
    let cone = revolution_surface(&e("(2 - u, 0, u)")).unwrap();
    assert_eq!(cone.to_text(), "((-u + 2) cos v, (-u + 2) sin v, u)");
    let cylinder = revolution_surface(&e("(1, 0, u)")).unwrap();
    assert_eq!(cylinder.to_text(), "(cos v, sin v, u)");
    let axis = revolution_surface(&e("(0, 0, u)")).unwrap();
    assert_eq!(axis.to_text(), "(0, 0, u)");
    let line = revolution_surface(&e("(2 u, 0, 1)")).unwrap();
    assert_eq!(line.to_text(), "(2 u cos v, 2 u sin v, 1)");
    // exact points at rational angles: cos v = 3/5, sin v = 4/5
    let p = s.point(&q!(1), &q!(3 / 5), &q!(4 / 5)).unwrap();
    assert_eq!(p.to_text(), "(6/5, 8/5, 1)");
    assert_eq!(
        s.point(&q!(1), &q!(1 / 2), &q!(1 / 2))
            .unwrap_err()
            .to_string(),
        "cos v = 1/2 and sin v = 1/2 are not the cosine and sine of an angle: cos² v + sin² v ≠ 1"
    );
}

#[test]
fn parametric_errors() {
    assert_eq!(
        revolution_surface(&e("(u, u^2, 1)"))
            .unwrap_err()
            .to_string(),
        "the curve is not in the XZ plane: its y coordinate is u^2, not 0 (a surface of \
         revolution about the Z axis rotates a curve (f(u), 0, g(u)))"
    );
    assert_eq!(
        revolution_surface(&e("(u, 0)")).unwrap_err().to_string(),
        "a surface of revolution about Z needs points of R^3, but c1 has 2 coordinates"
    );
    assert!(matches!(
        revolution_surface(&e("(u, 0, v)")),
        Err(GenerateError::WrongVariable { .. })
    ));
}

#[test]
fn truncated_cone_quadrant() {
    // the segment {(a, 0, b), (c, 0, d)} with a = 2, b = 0, c = 1, d = 1
    let one = K::from_i64(1);
    let seg =
        RationalBezierCurve::try_new(vec![kp(&[2, 0, 0]), kp(&[1, 0, 1])], vec![one.clone(), one])
            .unwrap();
    let r = revolution_bezier(&seg, &mut NoSteps).unwrap();
    assert_eq!(
        r.surface.mesh().to_text(),
        "{(2, 0, 0), (2, 2, 0), (0, 2, 0); (1, 0, 1), (1, 1, 1), (0, 1, 1)}"
    );
    assert_eq!(
        r.surface.weights().to_text_numbers(),
        "{1, √2/2, 1; 1, √2/2, 1}"
    );
    assert_eq!(r.surface.bidegree(), (1, 2));
    // symbolic in a, b, c, d: rows (a, 0, b), (a, a, b), (0, a, b)
    let seg = RationalBezierCurve::try_new(
        vec![
            Point::new(vec![qd("7/3"), K::from_i64(0), qd("-1/2")]),
            Point::new(vec![qd("-5"), K::from_i64(0), qd("4")]),
        ],
        vec![K::from_i64(1), K::from_i64(1)],
    )
    .unwrap();
    let r = revolution_bezier(&seg, &mut NoSteps).unwrap();
    assert_eq!(
        r.surface.mesh().to_text(),
        "{(7/3, 0, -1/2), (7/3, 7/3, -1/2), (0, 7/3, -1/2); (-5, 0, 4), (-5, -5, 4), (0, -5, 4)}"
    );
}

#[test]
fn sphere_octant() {
    let mut steps = Vec::new();
    let r = revolution_bezier(&quarter_arc_xz(), &mut steps).unwrap();
    assert_eq!(
        r.surface.mesh().to_text(),
        "{(1, 0, 0), (1, 1, 0), (0, 1, 0); (1, 0, 1), (1, 1, 1), (0, 1, 1); \
         (0, 0, 1), (0, 0, 1), (0, 0, 1)}"
    );
    // the pole row is one point repeated, but its weights are not equal
    assert_eq!(
        r.surface.weights().to_text_numbers(),
        "{1, √2/2, 1; √2/2, 1/2, √2/2; 1, √2/2, 1}"
    );
    assert_eq!(steps.len(), 2);
    let closed = r.surface.closed_form().unwrap();
    for (u, v) in [("1/2", "1/2"), ("1/3", "3/4"), ("0", "2/7"), ("1", "1/5")] {
        let p = closed.eval(&[(Var::U, qd(u)), (Var::V, qd(v))]).unwrap();
        let c = p.coords();
        let norm = c[0].clone() * &c[0] + c[1].clone() * &c[1] + c[2].clone() * &c[2];
        assert_eq!(norm, K::from_i64(1), "at ({u}, {v}): {p}");
        assert!(r.on_parallel(&qd(u), &qd(v)).unwrap());
    }
}

#[test]
fn exact_rationals_cannot_hold_the_weight() {
    let c = rcurve(&[&[1, 0, 0], &[1, 0, 1]], &["1", "1"]);
    let err = revolution_bezier(&c, &mut NoSteps).unwrap_err();
    assert!(matches!(err, GenerateError::NeedsQuadraticField { .. }));
    assert!(err
        .to_string()
        .starts_with("the weight of a quarter circle needs √2/2, which this number type cannot hold exactly: compute in the quadratic field a + b√d"));
    let off = RationalBezierCurve::try_new(
        vec![kp(&[1, 0, 0]), kp(&[1, 2, 3])],
        vec![K::from_i64(1); 2],
    )
    .unwrap();
    assert_eq!(
        revolution_bezier(&off, &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "control point c_1 = (1, 2, 3) is not in the XZ plane (y ≠ 0): a surface of revolution \
         about the Z axis rotates a curve of the XZ plane"
    );
}

#[test]
fn four_quadrants_close_the_circle() {
    let arc = quarter_arc_xz();
    let quads: Vec<_> = (0..4)
        .map(|k| revolution_bezier_quadrant(&arc, k, &mut NoSteps).unwrap())
        .collect();
    for k in 0..4 {
        let here = quads[k].surface.mesh();
        let next = quads[(k + 1) % 4].surface.mesh();
        for i in 0..3 {
            assert_eq!(here.get(i, 2), next.get(i, 0), "quadrant {k}, row {i}");
        }
        assert_eq!(quads[k].surface.weights(), quads[0].surface.weights());
    }
    assert_eq!(
        quads[2].surface.mesh().to_rows()[0]
            .iter()
            .map(Point::to_text)
            .collect::<Vec<_>>(),
        ["(-1, 0, 0)", "(-1, -1, 0)", "(0, -1, 0)"]
    );
    assert_eq!(
        revolution_bezier_quadrant(&arc, 5, &mut NoSteps)
            .unwrap()
            .quadrant,
        1
    );
}

#[test]
fn float_weights() {
    let c = RationalBezierCurve::try_new(
        vec![
            Point::new(vec![1.0, 0.0, 0.0]),
            Point::new(vec![1.0, 0.0, 1.0]),
        ],
        vec![1.0, 1.0],
    )
    .unwrap();
    let r = revolution_bezier(&c, &mut NoSteps).unwrap();
    let w = r.surface.weights().get(0, 1).unwrap();
    assert!((w - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-15);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn points_lie_on_their_parallels(
        xs in prop::collection::vec(small(), 3),
        zs in prop::collection::vec(small(), 3),
        w in weights(3),
        quadrant in 0usize..4,
        u in param(),
        v in param(),
    ) {
        let k = |x: &Q| <K as ExactRational>::from_rational(x);
        let points = xs.iter().zip(&zs).map(|(x, z)| Point::new(vec![k(x), K::from_i64(0), k(z)])).collect();
        let curve = RationalBezierCurve::try_new(points, w.iter().map(k).collect()).unwrap();
        let r = revolution_bezier_quadrant(&curve, quadrant, &mut NoSteps).unwrap();
        prop_assert!(r.on_parallel(&k(&u), &k(&v)).unwrap());
        // v = 0 of the first quadrant is the curve itself
        if quadrant == 0 {
            let closed = r.surface.closed_form().unwrap();
            let p = closed.eval(&[(Var::U, k(&u)), (Var::V, K::from_i64(0))]).unwrap();
            prop_assert_eq!(p, curve.eval(&k(&u)).unwrap());
        }
    }
}

#[test]
fn two_different_roots_are_an_error_not_a_panic() {
    // a profile in Q(√3) cannot take the quarter circle's √2/2
    let r3 = qd("sqrt3");
    let curve = RationalBezierCurve::try_new(
        vec![
            Point::new(vec![r3.clone(), K::from_i64(0), K::from_i64(0)]),
            kp(&[1, 0, 1]),
        ],
        vec![K::from_i64(1), K::from_i64(1)],
    )
    .unwrap();
    assert_eq!(
        revolution_bezier(&curve, &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "numbers with √3 and √2 cannot be mixed: a problem runs in one field a + b√d"
    );
    let ok = revolution_bezier(&quarter_arc_xz(), &mut NoSteps).unwrap();
    assert!(ok.on_parallel(&qd("sqrt3/3"), &qd("1/2")).is_err());
    // and two curves of a translational surface in different fields
    let c1 = cagd_bezier::BezierCurve::try_new(vec![
        kp(&[0, 0, 0]),
        Point::new(vec![qd("sqrt2"), K::from_i64(0), K::from_i64(0)]),
    ])
    .unwrap();
    let d1 = cagd_bezier::BezierCurve::try_new(vec![
        kp(&[0, 0, 0]),
        Point::new(vec![K::from_i64(0), r3, K::from_i64(0)]),
    ])
    .unwrap();
    assert!(matches!(
        translational_bezier(&c1, &d1, &mut NoSteps),
        Err(GenerateError::Scalar(
            cagd_scalar::ScalarError::MixedRoots { .. }
        ))
    ));
    let s = revolution_surface(&parse_vec_poly::<K>("(sqrt2 u, 0, 1)").unwrap()).unwrap();
    assert!(s
        .point(&qd("sqrt3"), &K::from_i64(1), &K::from_i64(0))
        .is_err());
}
