//! Hand-checked exact values of the slice-level functions, and their errors.

use crate::common::{ints, pt, text};
use cagd_bezier::*;
use cagd_linalg::Point;
use cagd_scalar::{q, BigRational, ExactRational};

fn parabola() -> Vec<Point<BigRational>> {
    ints(&[&[0, 0], &[1, 2], &[3, 3]])
}

fn cubic() -> Vec<Point<BigRational>> {
    ints(&[&[0, 0], &[1, 3], &[3, 3], &[4, 0]])
}

#[test]
fn bernstein_values_and_partition_of_unity() {
    // B_1^3(1/3) = 3 · 1/3 · (2/3)^2 = 4/9
    assert_eq!(bernstein(1, 3, &q!(1 / 3)), q!(4 / 9));
    assert_eq!(bernstein(0, 0, &q!(5)), q!(1));
    assert_eq!(bernstein(3, 2, &q!(1 / 2)), q!(0));
    assert_eq!(binomial::<BigRational>(6, 2), q!(15));
    assert_eq!(binomial::<BigRational>(2, 6), q!(0));
    let all = bernstein_all(4, &q!(-2 / 3));
    assert_eq!(all.len(), 5);
    for (i, b) in all.iter().enumerate() {
        assert_eq!(*b, bernstein(i, 4, &q!(-2 / 3)), "B_{i}^4");
    }
    let sum = all.iter().fold(q!(0), |acc, b| acc + b);
    assert_eq!(sum, q!(1));
}

#[test]
fn de_casteljau_by_hand() {
    // level 1: (1/3, 2/3), (5/3, 7/3); level 2: 2/3 (1/3, 2/3) + 1/3 (5/3, 7/3) = (7/9, 11/9)
    let c = parabola();
    assert_eq!(de_casteljau(&c, &q!(1 / 3)).unwrap(), pt(&["7/9", "11/9"]));
    assert_eq!(bernstein_sum(&c, &q!(1 / 3)).unwrap(), pt(&["7/9", "11/9"]));
    let tri = de_casteljau_triangle(&c, &q!(1 / 3)).unwrap();
    assert_eq!(tri.len(), 3);
    assert_eq!(text(&tri[0]), ["(0, 0)", "(1, 2)", "(3, 3)"]);
    assert_eq!(text(&tri[1]), ["(1/3, 2/3)", "(5/3, 7/3)"]);
    assert_eq!(text(&tri[2]), ["(7/9, 11/9)"]);
    // extrapolation is allowed: c(2) = (1-2)^2 c0 + 2·2·(1-2) c1 + 4 c2 = (8, 4)
    assert_eq!(de_casteljau(&c, &q!(2)).unwrap(), pt(&["8", "4"]));
    // a degree-0 curve is constant
    assert_eq!(
        de_casteljau(&ints(&[&[4, 5]]), &q!(7)).unwrap(),
        pt(&["4", "5"])
    );
}

#[test]
fn blossom_by_hand() {
    let c = parabola();
    // c[t1, t2] = (1-t1)(1-t2) c0 + ((1-t1) t2 + t1 (1-t2)) c1 + t1 t2 c2
    // at (1/3, 1/2): 1/3 c0 + 1/2 c1 + 1/6 c2 = (1/2 + 1/2, 1 + 1/2) = (1, 3/2)
    assert_eq!(
        blossom(&c, &[q!(1 / 3), q!(1 / 2)]).unwrap(),
        pt(&["1", "3/2"])
    );
    assert_eq!(blossom(&c, &[q!(0), q!(0)]).unwrap(), c[0]);
    assert_eq!(blossom(&c, &[q!(1), q!(0)]).unwrap(), c[1]);
    assert_eq!(blossom(&c, &[q!(1), q!(1)]).unwrap(), c[2]);
    // a degree-0 curve takes no argument
    assert_eq!(blossom(&ints(&[&[1]]), &[]).unwrap(), pt(&["1"]));
}

#[test]
fn subdivision_by_hand() {
    let (l, r) = subdivide(&cubic(), &q!(1 / 2)).unwrap();
    // the midpoints: level 1 (1/2, 3/2) (2, 3) (7/2, 3/2); level 2 (5/4, 9/4) (11/4, 9/4); (2, 9/4)
    assert_eq!(text(&l), ["(0, 0)", "(1/2, 3/2)", "(5/4, 9/4)", "(2, 9/4)"]);
    assert_eq!(
        text(&r),
        ["(2, 9/4)", "(11/4, 9/4)", "(7/2, 3/2)", "(4, 0)"]
    );
}

#[test]
fn restriction_of_a_cubic() {
    // checked against the monomial form x = 3t + 3t^2 - 2t^3, y = 9t - 9t^2 and its blossom
    let r = restrict(&cubic(), &q!(1 / 3), &q!(3 / 4)).unwrap();
    assert_eq!(
        text(&r),
        [
            "(34/27, 2)",
            "(67/36, 29/12)",
            "(121/48, 37/16)",
            "(99/32, 27/16)"
        ]
    );
    // t^3 on [a, b]: a^3, a^2 b, a b^2, b^3
    let t3 = ints(&[&[0], &[0], &[0], &[1]]);
    let r = restrict(&t3, &q!(1 / 3), &q!(3 / 4)).unwrap();
    assert_eq!(text(&r), ["(1/27)", "(1/12)", "(3/16)", "(27/64)"]);
    // a > b reverses the orientation
    let back = restrict(&cubic(), &q!(1), &q!(0)).unwrap();
    assert_eq!(back, cubic().into_iter().rev().collect::<Vec<_>>());
}

#[test]
fn degree_elevation_by_hand() {
    let e = elevate_degree(&parabola(), 1).unwrap();
    // c1 = 1/3 c0 + 2/3 c1, c2 = 2/3 c1 + 1/3 c2
    assert_eq!(text(&e), ["(0, 0)", "(2/3, 4/3)", "(5/3, 7/3)", "(3, 3)"]);
    // the line from 0 to 3 raised to degree 3: equally spaced
    let line = elevate_degree(&ints(&[&[0], &[3]]), 2).unwrap();
    assert_eq!(text(&line), ["(0)", "(1)", "(2)", "(3)"]);
    // twice = once, twice
    let twice = elevate_degree(&parabola(), 2).unwrap();
    assert_eq!(twice, elevate_degree(&e, 1).unwrap());
    assert_eq!(elevate_degree(&parabola(), 0).unwrap(), parabola());
    // a point stays a point
    assert_eq!(
        text(&elevate_degree(&ints(&[&[2, 1]]), 2).unwrap()),
        ["(2, 1)", "(2, 1)", "(2, 1)"]
    );
}

#[test]
fn differences_and_derivatives_by_hand() {
    let c = cubic();
    assert_eq!(
        text(&forward_differences(&c, 1).unwrap()),
        ["(1, 3)", "(2, 0)", "(1, -3)"]
    );
    assert_eq!(
        text(&forward_differences(&c, 2).unwrap()),
        ["(1, -3)", "(-1, -3)"]
    );
    assert_eq!(text(&forward_differences(&c, 3).unwrap()), ["(-2, 0)"]);
    assert!(forward_differences(&c, 4).unwrap().is_empty());
    assert_eq!(forward_differences(&c, 0).unwrap(), c);
    // hodograph 3 Δc_i; second derivative 6 Δ^2 c_i; third 6 Δ^3 c_0
    assert_eq!(
        text(&derivative_points(&c, 1).unwrap()),
        ["(3, 9)", "(6, 0)", "(3, -9)"]
    );
    assert_eq!(
        text(&derivative_points(&c, 2).unwrap()),
        ["(6, -18)", "(-6, -18)"]
    );
    assert_eq!(text(&derivative_points(&c, 3).unwrap()), ["(-12, 0)"]);
    assert_eq!(text(&derivative_points(&c, 4).unwrap()), ["(0, 0)"]);
    // x = 3t + 3t^2 - 2t^3: x'(1/3) = 3 + 2 - 2/3 = 13/3; y'(1/3) = 9 - 6 = 3
    let d = de_casteljau(&derivative_points(&c, 1).unwrap(), &q!(1 / 3)).unwrap();
    assert_eq!(d, pt(&["13/3", "3"]));
}

#[test]
fn errors_name_the_problem() {
    let empty: Vec<Point<BigRational>> = vec![];
    let e = de_casteljau(&empty, &q!(0)).unwrap_err();
    assert_eq!(e, BezierError::EmptyPolygon);
    assert!(e.to_string().contains("at least one control point"));
    for f in [
        bernstein_sum(&empty, &q!(0)).err(),
        blossom(&empty, &[]).err(),
        subdivide(&empty, &q!(0))
            .err()
            .map(|_| BezierError::EmptyPolygon),
        restrict(&empty, &q!(0), &q!(1)).err(),
        elevate_degree(&empty, 1).err(),
        forward_differences(&empty, 1).err(),
        derivative_points(&empty, 1).err(),
        de_casteljau_triangle(&empty, &q!(0)).err(),
    ] {
        assert_eq!(f, Some(BezierError::EmptyPolygon));
    }
    let mixed = vec![pt(&["0", "0"]), pt(&["1", "2"]), pt(&["1", "2", "3"])];
    assert_eq!(
        de_casteljau(&mixed, &q!(1 / 2)).unwrap_err().to_string(),
        "control point 2 has dimension 3 but control point 0 has dimension 2"
    );
    assert!(elevate_degree(&mixed, 1).is_err());
    assert!(derivative_points(&mixed, 1).is_err());
    assert_eq!(
        blossom(&parabola(), &[q!(1)]).unwrap_err().to_string(),
        "the blossom of a curve of degree 2 takes 2 arguments, but 1 were given"
    );
    assert_eq!(
        restrict(&parabola(), &q!(1 / 2), &q!(1 / 2))
            .unwrap_err()
            .to_string(),
        "the interval [1/2, 1/2] is degenerate: its ends must satisfy a < b"
    );
}

#[test]
fn over_f64() {
    let c: Vec<Point<f64>> = vec![
        Point::new(vec![0.0, 0.0]),
        Point::new(vec![1.0, 2.0]),
        Point::new(vec![3.0, 3.0]),
    ];
    let p = de_casteljau(&c, &(1.0 / 3.0)).unwrap();
    assert!((p[0] - 7.0 / 9.0).abs() < 1e-12 && (p[1] - 11.0 / 9.0).abs() < 1e-12);
    let b = bernstein_sum(&c, &0.3).unwrap();
    let d = de_casteljau(&c, &0.3).unwrap();
    assert!((b[0] - d[0]).abs() < 1e-12 && (b[1] - d[1]).abs() < 1e-12);
    let e = elevate_degree(&c, 1).unwrap();
    let pe = de_casteljau(&e, &0.3).unwrap();
    assert!((pe[0] - d[0]).abs() < 1e-12 && (pe[1] - d[1]).abs() < 1e-12);
    assert!(!<f64 as ExactRational>::is_exact());
}
