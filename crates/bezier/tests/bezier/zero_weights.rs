//! Zero weights: an entry of weight zero is a control vector (Farin, rational Bézier curves):
//! the semicircle as one quadratic, and random curves with control vectors against the
//! homogeneous De Casteljau projected.

use crate::common::{ints, pt, rat};
use cagd_bezier::*;
use cagd_linalg::Point;
use cagd_poly::Var;
use cagd_scalar::{q, BigRational, FieldOps};
use proptest::prelude::*;

type P = Point<BigRational>;

/// (1, 0), the vector (0, 1), (-1, 0) with weights 1, 0, 1: the upper unit semicircle.
fn semicircle() -> RationalBezierCurve<BigRational> {
    RationalBezierCurve::try_new(
        ints(&[&[1, 0], &[0, 1], &[-1, 0]]),
        vec![q!(1), q!(0), q!(1)],
    )
    .unwrap()
}

#[test]
fn the_semicircle_of_one_quadratic() {
    let c = semicircle();
    assert_eq!(c.first_vector(), Some(1));
    assert_eq!(c.homogeneous()[1], pt(&["0", "1", "0"]));
    assert_eq!(c.eval(&q!(1 / 2)).unwrap(), pt(&["0", "1"]));
    assert_eq!(c.eval(&q!(1 / 3)).unwrap(), pt(&["3/5", "4/5"]));
    assert_eq!(
        c.closed_form(Var::T).to_text(),
        "(-2 t + 1, -2 t^2 + 2 t) / (2 t^2 - 2 t + 1)"
    );
    // c'(0) = (0, 2): the tangent at (1, 0) is the direction of the control vector
    assert_eq!(c.derivative_at(&q!(0)).unwrap(), pt(&["0", "2"]));
    assert_eq!(c.conic_kind(), Some(ConicKind::Ellipse));
    assert_eq!(
        c.require_points().unwrap_err().to_string(),
        "weight 1 is zero: that entry is a control vector, not a point, and this needs every \
         control point to be a point"
    );
    assert_eq!(
        c.to_text(),
        "(1, 0) w = 1; vector (0, 1) w = 0; (-1, 0) w = 1"
    );
}

#[test]
fn the_semicircle_elevated_and_split() {
    let c = semicircle();
    let up = c.elevate_degree(1).unwrap();
    assert_eq!(up.weights(), &[q!(1), q!(1 / 3), q!(1 / 3), q!(1)]);
    assert_eq!(
        up.points(),
        &ints(&[&[1, 0], &[1, 2], &[-1, 2], &[-1, 0]])[..]
    );
    let (left, right) = c.subdivide(&q!(1 / 2)).unwrap();
    // the two quarter circles of weights 1, 1/2, 1/2 and 1/2, 1/2, 1
    assert_eq!(left.points(), &ints(&[&[1, 0], &[1, 1], &[0, 1]])[..]);
    assert_eq!(left.weights(), &[q!(1), q!(1 / 2), q!(1 / 2)]);
    assert_eq!(right.points(), &ints(&[&[0, 1], &[-1, 1], &[-1, 0]])[..]);
    assert_eq!(right.weights(), &[q!(1 / 2), q!(1 / 2), q!(1)]);
    // c[0, 1] is the homogeneous (0, 1, 0): the control vector, a point at infinity
    assert_eq!(
        c.blossom_homogeneous(&[q!(0), q!(1)]).unwrap(),
        pt(&["0", "1", "0"])
    );
    assert!(c.blossom(&[q!(0), q!(1)]).is_err());
    // c[0, 0] is c(0); c[1/2, 1/2] the apex
    assert_eq!(c.blossom(&[q!(1 / 2), q!(1 / 2)]).unwrap(), pt(&["0", "1"]));
}

#[test]
fn a_vanishing_denominator_is_a_point_at_infinity() {
    // weights 0, 1: w(0) = 0, c(0) is the point at infinity in the direction (1, 0)
    let c = RationalBezierCurve::try_new(ints(&[&[1, 0], &[0, 0]]), vec![q!(0), q!(1)]).unwrap();
    assert_eq!(
        c.eval(&q!(0)).unwrap_err(),
        BezierError::VanishingDenominator { t: "0".into() }
    );
    assert_eq!(c.eval(&q!(1 / 2)).unwrap(), pt(&["1", "0"]));
}

#[test]
fn reweighting_scales_a_control_vector() {
    let c = semicircle();
    let re = c.reweight(&q!(2)).unwrap();
    assert_eq!(re.weights(), &[q!(1), q!(0), q!(4)]);
    assert_eq!(re.points()[1], pt(&["0", "2"]));
    // the same point set: c(1/2) = (0, 1) is re(1/3), since u ↦ 2u/((1 - u) + 2u) maps 1/3 to 1/2
    assert_eq!(re.eval(&q!(1 / 3)).unwrap(), pt(&["0", "1"]));
}

/// A random polygon whose weights are 0 or nonzero (at least one nonzero), degree 1..=5.
fn polygon_with_vectors() -> impl Strategy<Value = (Vec<P>, Vec<BigRational>)> {
    (1usize..=3, 1usize..=5).prop_flat_map(|(dim, n)| {
        (
            prop::collection::vec(prop::collection::vec(rat(), dim), n + 1)
                .prop_map(|pts| pts.into_iter().map(Point::new).collect()),
            prop::collection::vec(prop_oneof![Just(q!(0)), rat()], n + 1)
                .prop_filter("a weight not zero", |w| w.iter().any(|x| *x != q!(0))),
        )
    })
}

/// The homogeneous points written out by hand: (w p, w), or (v, 0).
fn by_hand(points: &[P], weights: &[BigRational]) -> Vec<P> {
    points
        .iter()
        .zip(weights)
        .map(|(p, w)| {
            let mut c: Vec<BigRational> = if *w == q!(0) {
                p.coords().to_vec()
            } else {
                p.coords().iter().map(|x| x.clone() * w).collect()
            };
            c.push(w.clone());
            Point::new(c)
        })
        .collect()
}

/// The projection of a homogeneous point; `None` at infinity.
fn project(h: &P) -> Option<P> {
    h.from_homogeneous().map(|(p, _)| p)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// c(t) is the homogeneous De Casteljau of (w p, w) / (v, 0), projected; at infinity
    /// exactly where that weight vanishes.
    #[test]
    fn evaluation_is_the_homogeneous_casteljau_projected(
        (points, weights) in polygon_with_vectors(),
        t in (0i64..=12).prop_map(|k| <BigRational as FieldOps>::from_ratio(k, 12)),
    ) {
        let c = RationalBezierCurve::try_new(points.clone(), weights.clone()).unwrap();
        let h = de_casteljau(&by_hand(&points, &weights), &t).unwrap();
        match project(&h) {
            Some(p) => prop_assert_eq!(c.eval(&t).unwrap(), p),
            None => prop_assert!(c.eval(&t).is_err()),
        }
    }

    /// Degree elevation and subdivision keep the curve: at every parameter where the weight
    /// is nonzero, the same point.
    #[test]
    fn elevation_and_subdivision_keep_the_curve(
        (points, weights) in polygon_with_vectors(),
        r in 1usize..=2,
        k in 1i64..=11,
        ts in prop::collection::vec(0i64..=24, 1..=4),
    ) {
        let c = RationalBezierCurve::try_new(points, weights).unwrap();
        let up = c.elevate_degree(r).unwrap();
        let split = <BigRational as FieldOps>::from_ratio(k, 12);
        let (left, right) = c.subdivide(&split).unwrap();
        for t in ts {
            let t = <BigRational as FieldOps>::from_ratio(t, 24);
            let Ok(p) = c.eval(&t) else { continue };
            prop_assert_eq!(up.eval(&t).unwrap(), p.clone());
            let half = if t <= split { &left } else { &right };
            prop_assert_eq!(half.eval(&t).unwrap(), p);
        }
    }
}
