//! Integration tests of cagd-bspline: hand-checked values, the notes' circle in Q(√2), and
//! property tests over random rational curves against independent routes.

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

use cagd_bspline::*;
use cagd_linalg::Point;
use cagd_scalar::{parse_number, q, BigRational, FieldOps, Print, Quadratic};
use proptest::collection::vec;
use proptest::prelude::*;

type Q = BigRational;

fn num(text: &str) -> Quadratic {
    parse_number(text).unwrap()
}

fn pts(c: &[[i64; 2]]) -> Vec<Point<Q>> {
    c.iter().map(|x| Point::from_ints(x)).collect()
}

fn texts(points: &[Point<Q>]) -> Vec<String> {
    points.iter().map(|p| p.to_text()).collect()
}

// ---------------------------------------------------------------- hand-checked values

#[test]
fn knot_insertion_piegl_tiller_style() {
    // Cubic on notes knots {0, 0, 0, 1, 2, 3, 4, 5, 5, 5} (The NURBS Book, Ex. 5.1 knots
    // {0,0,0,0,1,2,3,4,5,5,5,5}), 8 control points, insert t = 5/2 (span [2, 3], k = 5):
    // α_3 = (5/2 - 0)/(3 - 0) = 5/6, α_4 = (5/2 - 1)/(4 - 1) = 1/2, α_5 = (5/2 - 2)/(5 - 2) = 1/6.
    let (u, conv) = KnotVector::read(
        [0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5]
            .into_iter()
            .map(Q::from_i64)
            .collect(),
        3,
        8,
    )
    .unwrap();
    assert_eq!(conv, KnotConvention::Full);
    assert_eq!(u.to_text(), "{0, 0, 0, 1, 2, 3, 4, 5, 5, 5}");
    let d = pts(&[
        [0, 0],
        [6, 0],
        [6, 6],
        [12, 6],
        [12, 0],
        [18, 0],
        [18, 6],
        [24, 6],
    ]);
    let mut steps = Vec::new();
    insert_knot_recorded(&u, &d, &q!(5 / 2), 1, &mut steps).unwrap();
    assert_eq!(steps[0].first, 3);
    assert_eq!(steps[0].alphas, vec![q!(5 / 6), q!(1 / 2), q!(1 / 6)]);
    // Q_3 = (1/6) d_2 + (5/6) d_3 = (11, 6); Q_4 = (d_3 + d_4)/2 = (12, 3);
    // Q_5 = (5/6) d_4 + (1/6) d_5 = (13, 0).
    assert_eq!(
        texts(&steps[0].points),
        [
            "(0, 0)", "(6, 0)", "(6, 6)", "(11, 6)", "(12, 3)", "(13, 0)", "(18, 0)", "(18, 6)",
            "(24, 6)"
        ]
    );
    assert_eq!(
        steps[0].knots.to_text_in(KnotConvention::Full),
        "{0, 0, 0, 0, 1, 2, 5/2, 3, 4, 5, 5, 5, 5}"
    );
}

#[test]
fn degree_elevation_of_a_quadratic_by_hand() {
    // Uniform clamped quadratic {0, 0, 1, 2, 2}: the pieces' Bézier points are
    // (0,0),(1,2),(2,2) and (2,2),(3,2),(4,0); elevated, (0,0),(2/3,4/3),(4/3,2),(2,2) and
    // (2,2),(8/3,2),(10/3,4/3),(4,0); the joint (2,2) is removed once (C^1 at 1).
    let curve = BSplineCurve::try_new(
        KnotVector::clamped(2, &[q!(0), q!(1), q!(2)]).unwrap(),
        pts(&[[0, 0], [1, 2], [3, 2], [4, 0]]),
    )
    .unwrap();
    let e = curve.elevate_degree(1).unwrap();
    assert_eq!(e.knots().to_text(), "{0, 0, 0, 1, 1, 2, 2, 2}");
    assert_eq!(
        texts(e.points()),
        [
            "(0, 0)",
            "(2/3, 4/3)",
            "(4/3, 2)",
            "(8/3, 2)",
            "(10/3, 4/3)",
            "(4, 0)"
        ]
    );
    let e2 = curve.elevate_degree(2).unwrap();
    assert_eq!(e2.knots().to_text(), "{0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2}");
    assert_eq!(e2.degree(), 4);
    assert_eq!(
        curve.to_text_in(KnotConvention::Full),
        "degree 2\nknots {0, 0, 0, 1, 2, 2, 2}\npoints (0, 0), (1, 2), (3, 2), (4, 0)"
    );
}

#[test]
fn de_boor_at_a_knot_and_inside_a_span() {
    let c = BSplineCurve::read(
        2,
        vec![q!(0), q!(0), q!(1), q!(2), q!(2)],
        pts(&[[0, 0], [1, 2], [3, 2], [4, 0]]),
    )
    .unwrap()
    .0;
    // At the simple knot 1: the midpoint of d_1 d_2.
    let tri = c.de_boor_triangle(&q!(1)).unwrap();
    assert_eq!(tri.multiplicity, 1);
    assert_eq!(tri.point().unwrap().to_text(), "(2, 2)");
    // Inside [0, 1] at 1/2: (1/4)(0,0) + (5/8)(1,2) + (1/8)(3,2) = (1, 3/2).
    assert_eq!(c.eval(&q!(1 / 2)).unwrap().to_text(), "(1, 3/2)");
}

// ---------------------------------------------------------------- the notes' circle

#[test]
fn nine_point_circle_is_exact_in_q_sqrt2() {
    let c = unit_circle::<Quadratic>().unwrap();
    let p = c.eval(&num("1/8")).unwrap();
    assert_eq!(p.to_text(), "(√2/2, √2/2)");
    assert_eq!(p.dot(&p), num("1"));
    for t in ["1/3", "2/7", "5/9", "7/8", "0", "1", "1/4", "3/5"] {
        let p = c.eval(&num(t)).unwrap();
        assert_eq!(p.dot(&p), num("1"), "t = {t}: {p}");
    }
    // 12 knots read the same curve as the notes' 10.
    let full: Vec<Quadratic> = [
        "0", "0", "0", "1/4", "1/4", "1/2", "1/2", "3/4", "3/4", "1", "1", "1",
    ]
    .iter()
    .map(|t| num(t))
    .collect();
    let (c12, conv) = NurbsCurve::read(2, full, c.points().to_vec(), c.weights().to_vec()).unwrap();
    assert_eq!(conv, KnotConvention::Full);
    assert_eq!(c12, c);
    // The slides' circle on [0, 4] with R = 2 is the same circle scaled, reparametrized.
    let s = circle_slides(&num("2")).unwrap();
    assert_eq!(s.eval(&num("1/2")).unwrap().to_text(), "(√2, √2)");
    // Insertion, elevation and Bézier extraction keep the points on the circle.
    let refined = c.refine_knots(&[num("1/8"), num("2/3")]).unwrap();
    let elevated = c.elevate_degree(1).unwrap();
    for t in ["1/16", "1/5", "2/3", "9/10"] {
        let expected = c.eval(&num(t)).unwrap();
        assert_eq!(refined.eval(&num(t)).unwrap(), expected);
        assert_eq!(elevated.eval(&num(t)).unwrap(), expected);
    }
    assert_eq!(
        elevated.knots().to_text(),
        "{0, 0, 0, 1/4, 1/4, 1/4, 1/2, 1/2, 1/2, 3/4, 3/4, 3/4, 1, 1, 1}"
    );
    let pieces = c.bezier_pieces().unwrap();
    assert_eq!(pieces.len(), 4);
    let w: Vec<String> = pieces[1].weights.iter().map(|w| w.to_text()).collect();
    assert_eq!(w, ["1", "√2/2", "1"]);
    assert_eq!(pieces[1].interval, (num("1/4"), num("1/2")));
    assert!(c.negative_weights().is_empty());
    // c'(0) = (p / (u_3 - u_2)) (w_1 / w_0) (d_1 - d_0) = 8 (√2/2) (0, 1) (full convention).
    let d0 = c.derivatives(&num("0"), 2).unwrap();
    assert_eq!(d0[1].to_text(), "(0, 4√2)");
    // The curvature of the unit circle is 1: |c' × c''| = |c'|^3 shown squared.
    let cross = d0[1][0].clone() * &d0[2][1] - d0[1][1].clone() * &d0[2][0];
    let speed2 = d0[1].dot(&d0[1]);
    assert_eq!(cross.clone() * &cross, speed2.clone() * &speed2 * &speed2);
}

#[test]
fn nurbs_errors_and_flags() {
    let u = KnotVector::clamped(2, &[q!(0), q!(1)]).unwrap();
    let d = pts(&[[0, 0], [1, 1], [2, 0]]);
    let e = NurbsCurve::try_new(u.clone(), d.clone(), vec![q!(1), q!(1), q!(0)]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "weight 2 is zero: a control vector (weight zero) is taken in a rational Bézier curve, not in a NURBS curve"
    );
    let e = NurbsCurve::try_new(u.clone(), d.clone(), vec![q!(1), q!(1)]).unwrap_err();
    assert!(e.to_string().contains("3 control points but 2 weights"));
    // A negative middle weight: allowed, flagged; this one reaches infinity at t = 1/2.
    let c = NurbsCurve::try_new(u, d, vec![q!(1), q!(-1), q!(1)]).unwrap();
    assert_eq!(c.negative_weights(), vec![1]);
    assert_eq!(
        c.eval(&q!(1 / 2)).unwrap_err().to_string(),
        "the denominator of the rational curve vanishes at t = 1/2: the point is at infinity"
    );
    assert_eq!(c.eval(&q!(1 / 4)).unwrap().to_text(), "(-1, -3/2)");
}

#[test]
fn knot_count_and_order_errors() {
    let e = KnotVector::<Q>::read(vec![q!(0); 11], 2, 9).unwrap_err();
    assert_eq!(
        e.to_string(),
        "a curve of degree 2 with 9 control points needs 10 knots (the notes' convention, \
         without end knots) or 12 (with one more knot at each end, as in The NURBS Book); found 11"
    );
    let e =
        KnotVector::read(vec![q!(0), q!(0), q!(1 / 2), q!(1 / 4), q!(1), q!(1)], 2, 5).unwrap_err();
    assert_eq!(e.to_string(), "knot vector decreases at index 3: 1/2 > 1/4");
    let e = BSplineCurve::try_new(
        KnotVector::clamped(1, &[q!(0), q!(1)]).unwrap(),
        vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 1, 1])],
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "control point 1 has dimension 3 but control point 0 has dimension 2"
    );
}

// ---------------------------------------------------------------- over f64

#[test]
fn over_f64_close_to_the_exact_answers() {
    let exact = BSplineCurve::try_new(
        KnotVector::from_notes(vec![q!(0), q!(0), q!(1 / 3), q!(1), q!(1)], 2).unwrap(),
        pts(&[[0, 0], [1, 3], [4, 3], [5, -1]]),
    )
    .unwrap();
    let to_f = |p: &Point<Q>| Point::new(p.to_f64());
    let float = BSplineCurve::try_new(
        KnotVector::from_notes(vec![0.0, 0.0, 1.0 / 3.0, 1.0, 1.0], 2).unwrap(),
        exact.points().iter().map(to_f).collect(),
    )
    .unwrap();
    let close = |a: &Point<f64>, b: &Point<Q>| {
        a.coords()
            .iter()
            .zip(b.to_f64())
            .all(|(x, y)| (x - y).abs() < 1e-12)
    };
    let fe = float
        .elevate_degree(1)
        .unwrap()
        .insert_knot(&0.5, 2)
        .unwrap();
    let qe = exact
        .elevate_degree(1)
        .unwrap()
        .insert_knot(&q!(1 / 2), 2)
        .unwrap();
    assert_eq!(fe.points().len(), qe.points().len());
    assert!(fe
        .points()
        .iter()
        .zip(qe.points())
        .all(|(a, b)| close(a, b)));
    assert!(close(
        &float.eval(&0.25).unwrap(),
        &exact.eval(&q!(1 / 4)).unwrap()
    ));
}

// ---------------------------------------------------------------- property tests

fn rat() -> impl Strategy<Value = Q> {
    (-9i64..=9, 1i64..=9).prop_map(|(n, d)| Q::from_ratio(n, d))
}

fn unit_rat() -> impl Strategy<Value = Q> {
    (1i64..=9).prop_flat_map(|d| (0..=d).prop_map(move |n| Q::from_ratio(n, d)))
}

fn point2() -> impl Strategy<Value = Point<Q>> {
    (rat(), rat()).prop_map(|(x, y)| Point::new(vec![x, y]))
}

/// A random valid knot vector (clamped or not at each end, with repeated knots now and
/// then) and its control points.
fn curve() -> impl Strategy<Value = (KnotVector<Q>, Vec<Point<Q>>)> {
    (1usize..=3, 0usize..=4, any::<bool>(), any::<bool>())
        .prop_flat_map(|(p, m, clamp_left, clamp_right)| {
            let n = p + 1 + m;
            let k = n + p - 1;
            (
                Just(p),
                Just(clamp_left),
                Just(clamp_right),
                vec(rat(), k),
                vec(1usize..k, 0..=2),
                vec(point2(), n),
            )
        })
        .prop_filter_map(
            "knot vector not valid",
            |(p, clamp_left, clamp_right, mut knots, dups, points)| {
                knots.sort();
                for i in dups {
                    knots[i] = knots[i - 1].clone();
                }
                let k = knots.len();
                if clamp_left {
                    let a = knots[p - 1].clone();
                    knots[..p].fill(a);
                }
                if clamp_right {
                    let b = knots[k - p].clone();
                    knots[k - p..].fill(b);
                }
                KnotVector::from_notes(knots, p).ok().map(|u| (u, points))
            },
        )
}

/// A parameter of the domain: a + λ (b - a).
fn in_domain(u: &KnotVector<Q>, lambda: &Q) -> Q {
    let (a, b) = u.domain();
    a.clone() + (b - a) * lambda
}

fn weights(n: usize) -> impl Strategy<Value = Vec<Q>> {
    vec(
        (1i64..=9, 1i64..=9).prop_map(|(a, b)| Q::from_ratio(a, b)),
        n,
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn de_boor_is_the_basis_sum_and_a_partition_of_unity(
        (u, d) in curve(), lambda in unit_rat()
    ) {
        let t = in_domain(&u, &lambda);
        let (first, n) = basis_functions_at(&u, &t).unwrap();
        prop_assert_eq!(n.iter().fold(Q::from_i64(0), |acc, x| acc + x), Q::from_i64(1));
        prop_assert!(n.iter().all(|x| *x >= Q::from_i64(0)));
        let sum = Point::combination(&d[first..first + n.len()], &n, 2);
        prop_assert_eq!(de_boor(&u, &d, &t).unwrap(), sum.clone());
        // And every single N_i agrees with the span's list.
        for i in 0..d.len() {
            let expected = i.checked_sub(first).and_then(|j| n.get(j).cloned()).unwrap_or(Q::from_i64(0));
            prop_assert_eq!(basis_function(&u, i, &t).unwrap(), expected);
        }
    }

    #[test]
    fn conventions_round_trip((u, _d) in curve()) {
        let n = u.control_point_count();
        let p = u.degree();
        for conv in [KnotConvention::Notes, KnotConvention::Full] {
            let (v, c) = KnotVector::read(u.to_convention(conv), p, n).unwrap();
            prop_assert_eq!(c, conv);
            prop_assert_eq!(&v, &u);
        }
    }

    #[test]
    fn insertion_and_refinement_keep_the_curve(
        (u, d) in curve(), l1 in unit_rat(), l2 in unit_rat(), l3 in unit_rat(), ls in vec(unit_rat(), 3)
    ) {
        let t = in_domain(&u, &l1);
        if u.multiplicity(&t) < u.degree() {
            let (v, e) = insert_knot(&u, &d, &t, 1).unwrap();
            prop_assert_eq!(v.multiplicity(&t), u.multiplicity(&t) + 1);
            for s in ls.iter().map(|l| in_domain(&u, l)) {
                prop_assert_eq!(de_boor(&v, &e, &s).unwrap(), de_boor(&u, &d, &s).unwrap());
            }
            // Removing it again gives the curve back.
            if u.start() < &t && &t < u.end() {
                prop_assert_eq!(remove_knot(&v, &e, &t, 1).unwrap(), (u.clone(), d.clone()));
            }
        }
        let new: Vec<Q> = [l2, l3].iter().map(|l| in_domain(&u, l)).collect();
        if new.iter().all(|t| u.multiplicity(t) + new.iter().filter(|x| *x == t).count() <= u.degree()) {
            let (v, e) = refine_knots(&u, &d, &new).unwrap();
            prop_assert_eq!(e.len(), d.len() + 2);
            for s in ls.iter().map(|l| in_domain(&u, l)) {
                prop_assert_eq!(de_boor(&v, &e, &s).unwrap(), de_boor(&u, &d, &s).unwrap());
            }
        }
    }

    #[test]
    fn bezier_pieces_are_the_curve((u, d) in curve(), ls in vec(unit_rat(), 3)) {
        let pieces = bezier_pieces(&u, &d).unwrap();
        prop_assert_eq!(pieces.len(), u.spans().len());
        for s in ls.iter().map(|l| in_domain(&u, l)) {
            let piece = pieces.iter().rev().find(|pc| pc.interval.0 <= s).unwrap();
            let (a, b) = piece.interval.clone();
            let tau = (s.clone() - &a) / (b - a);
            let bez = cagd_bezier::de_casteljau(&piece.points, &tau).unwrap();
            prop_assert_eq!(bez, de_boor(&u, &d, &s).unwrap());
        }
    }

    #[test]
    fn degree_elevation_keeps_the_curve(
        (u, d) in curve(), r in 1usize..=2, ls in vec(unit_rat(), 3)
    ) {
        let (v, e) = elevate_degree(&u, &d, r).unwrap();
        prop_assert_eq!(v.degree(), u.degree() + r);
        prop_assert_eq!(v.domain(), u.domain());
        for (x, s) in u.breakpoints() {
            if u.start() < &x && &x < u.end() {
                prop_assert_eq!(v.multiplicity(&x), s + r);
            }
        }
        for s in ls.iter().map(|l| in_domain(&u, l)) {
            prop_assert_eq!(de_boor(&v, &e, &s).unwrap(), de_boor(&u, &d, &s).unwrap());
        }
    }

    #[test]
    fn derivative_curve_matches_the_basis_derivatives(
        (u, d) in curve(), lambda in unit_rat()
    ) {
        let t = in_domain(&u, &lambda);
        match derivative_curve(&u, &d) {
            Ok((v, e)) => {
                let ders = derivatives(&u, &d, &t, 2).unwrap();
                prop_assert_eq!(de_boor(&v, &e, &t).unwrap(), ders[1].clone());
                if let Ok((w, f)) = derivative_curve(&v, &e) {
                    prop_assert_eq!(de_boor(&w, &f, &t).unwrap(), ders[2].clone());
                }
            }
            Err(_) => {
                // Only degree 1 or a knot of multiplicity p + 1 inside.
                let jumps = u.notes()[1..u.notes().len() - 1]
                    .iter()
                    .any(|x| u.multiplicity(x) > u.degree());
                prop_assert!(u.degree() == 1 || jumps);
            }
        }
    }

    #[test]
    fn nurbs_algorithms_keep_the_rational_curve(
        ((u, d), w) in curve().prop_flat_map(|(u, d)| {
            let n = d.len();
            (Just((u, d)), weights(n))
        }),
        l1 in unit_rat(),
        ls in vec(unit_rat(), 2)
    ) {
        let c = NurbsCurve::try_new(u.clone(), d.clone(), w.clone()).unwrap();
        for s in ls.iter().map(|l| in_domain(&u, l)) {
            // Independent route: Σ w_i N_i d_i / Σ w_i N_i.
            let (first, n) = basis_functions_at(&u, &s).unwrap();
            let wn: Vec<Q> = n.iter().enumerate().map(|(j, x)| x.clone() * &w[first + j]).collect();
            let den = wn.iter().fold(Q::from_i64(0), |acc, x| acc + x);
            let num = Point::combination(&d[first..first + n.len()], &wn, 2);
            let expected = num.scale(&(Q::from_i64(1) / den));
            prop_assert_eq!(c.eval(&s).unwrap(), expected.clone());
            prop_assert_eq!(c.elevate_degree(1).unwrap().eval(&s).unwrap(), expected.clone());
            let t = in_domain(&u, &l1);
            if u.multiplicity(&t) < u.degree() {
                prop_assert_eq!(c.insert_knot(&t, 1).unwrap().eval(&s).unwrap(), expected);
            }
        }
    }

    #[test]
    fn circle_points_are_exactly_on_the_circle(n in 0i64..=40, den in 1i64..=40) {
        prop_assume!(n <= den);
        let c = unit_circle::<Quadratic>().unwrap();
        let t = Quadratic::from_ratio(n, den);
        let ders = c.derivatives(&t, 1).unwrap();
        prop_assert_eq!(ders[0].dot(&ders[0]), Quadratic::from_i64(1));
        prop_assert_eq!(ders[0].dot(&ders[1]), Quadratic::from_i64(0));
    }
}

// ---------------------------------------------------------------- knot vectors as objects

#[test]
fn the_nurbs_book_span_and_multiplicities() {
    // The NURBS Book, Ex. 2.3 and A2.1: U = {0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5}, p = 2; u = 5/2
    // is in span 4 (u_4 = 2 <= 5/2 < u_5 = 3)
    let full: Vec<Q> = [0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5].map(Q::from_i64).to_vec();
    let u = KnotVector::from_full(full.clone(), 2).unwrap();
    assert_eq!(u.span_in(&q!(5 / 2), KnotConvention::Full).unwrap(), 4);
    assert_eq!(u.span_in(&q!(5 / 2), KnotConvention::Notes).unwrap(), 3);
    assert_eq!(u.span_in(&q!(4), KnotConvention::Full).unwrap(), 7);
    assert_eq!(u.span_in(&q!(5), KnotConvention::Full).unwrap(), 7);
    assert_eq!(u.span_in(&q!(0), KnotConvention::Full).unwrap(), 2);
    assert_eq!(
        multiplicities(&full),
        vec![
            (q!(0), 3),
            (q!(1), 1),
            (q!(2), 1),
            (q!(3), 1),
            (q!(4), 2),
            (q!(5), 3)
        ]
    );
    assert!(u.span_in(&q!(6), KnotConvention::Full).is_err());
}

#[test]
fn spaced_knot_vectors() {
    let t = |v: Vec<Q>| v.iter().map(|u| u.to_text()).collect::<Vec<_>>().join(", ");
    let u = knots_spaced(Spacing::OpenUniform, 3, 4, &q!(0), &q!(1)).unwrap();
    assert_eq!(t(u), "0, 0, 0, 0, 1, 1, 1, 1");
    let u = knots_spaced(Spacing::OpenUniform, 1, 3, &q!(-1), &q!(1)).unwrap();
    assert_eq!(t(u), "-1, -1, 0, 1, 1");
    let u = knots_spaced(Spacing::Uniform, 1, 2, &q!(0), &q!(1)).unwrap();
    assert_eq!(t(u), "0, 1/3, 2/3, 1");
    assert!(knots_spaced(Spacing::Uniform, 2, 2, &q!(0), &q!(1)).is_err());
    assert!(knots_spaced(Spacing::Uniform, 2, 4, &q!(1), &q!(1)).is_err());
    assert!(knots_spaced(Spacing::Uniform, 0, 4, &q!(0), &q!(1)).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn a_span_holds_its_parameter((u, _d) in curve(), lambda in unit_rat()) {
        let t = in_domain(&u, &lambda);
        for convention in [KnotConvention::Full, KnotConvention::Notes] {
            let knots = u.to_convention(convention);
            let i = u.span_in(&t, convention).unwrap();
            prop_assert!(knots[i] <= t);
            if t == *u.end() {
                prop_assert!(knots[i] < knots[i + 1] && knots[i + 1] == t);
            } else {
                prop_assert!(t < knots[i + 1]);
            }
        }
    }

    #[test]
    fn open_uniform_vectors_are_clamped(p in 1usize..=4, extra in 0usize..=5, a in rat(), len in 1i64..=5) {
        let n = p + 1 + extra;
        let b = a.clone() + Q::from_i64(len);
        let full = knots_spaced(Spacing::OpenUniform, p, n, &a, &b).unwrap();
        prop_assert_eq!(full.len(), n + p + 1);
        let m = multiplicities(&full);
        prop_assert_eq!(m.first().cloned(), Some((a.clone(), p + 1)));
        prop_assert_eq!(m.last().cloned(), Some((b.clone(), p + 1)));
        prop_assert!(m[1..m.len() - 1].iter().all(|(_, k)| *k == 1));
        let u = KnotVector::from_full(full, p).unwrap();
        prop_assert!(u.is_clamped());
        prop_assert_eq!(u.domain(), (a, b));
        let uniform = knots_spaced(Spacing::Uniform, p, n, &Q::from_i64(0), &Q::from_i64(1)).unwrap();
        prop_assert_eq!(multiplicities(&uniform).len(), n + p + 1);
    }

    #[test]
    fn a_normalized_curve_is_the_same_point_set(
        (u, d) in curve(), lambda in unit_rat(), w in weights(12)
    ) {
        let c = BSplineCurve::try_new(u.clone(), d.clone()).unwrap();
        let r = NurbsCurve::try_new(u.clone(), d.clone(), w[..d.len()].to_vec()).unwrap();
        let (cn, rn) = (c.normalized(), r.normalized());
        prop_assert_eq!(cn.knots().domain(), (Q::from_i64(0), Q::from_i64(1)));
        let t = in_domain(&u, &lambda);
        let (a, b) = u.domain();
        let s = (t.clone() - a) / (b - u.start().clone());
        prop_assert_eq!(&s, &lambda);
        prop_assert_eq!(cn.eval(&s).unwrap(), c.eval(&t).unwrap());
        prop_assert_eq!(rn.eval(&s).unwrap(), r.eval(&t).unwrap());
        prop_assert_eq!(cn.points(), c.points());
    }
}
