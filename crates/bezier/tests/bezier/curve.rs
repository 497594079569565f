//! The typed `BezierCurve`: validation, domains, and the operations as curves.

use crate::common::{ints, pt, qn, text};
use cagd_bezier::{BezierCurve, BezierError};
use cagd_linalg::Point;
use cagd_scalar::{q, BigRational, Quadratic};

fn cubic() -> BezierCurve<BigRational> {
    BezierCurve::try_new(ints(&[&[0, 0], &[1, 3], &[3, 3], &[4, 0]])).unwrap()
}

#[test]
fn construction_and_accessors() {
    let c = cubic();
    assert_eq!(c.degree(), 3);
    assert_eq!(c.dim(), 2);
    assert_eq!(c.domain(), (&q!(0), &q!(1)));
    assert_eq!(c.to_text(), "(0, 0), (1, 3), (3, 3), (4, 0)");
    assert_eq!(
        format!("{c:?}"),
        "BezierCurve(degree 3, [0, 1]: (0, 0), (1, 3), (3, 3), (4, 0))"
    );
    assert_eq!(
        BezierCurve::<BigRational>::try_new(vec![]).unwrap_err(),
        BezierError::EmptyPolygon
    );
    let bad = BezierCurve::try_new(vec![pt(&["1"]), pt(&["1", "2"])]).unwrap_err();
    assert!(matches!(
        bad,
        BezierError::DimensionMismatch {
            index: 1,
            expected: 1,
            found: 2
        }
    ));
    assert_eq!(
        cubic().with_domain(q!(2), q!(2)).unwrap_err().to_string(),
        "the interval [2, 2] is degenerate: its ends must satisfy a < b"
    );
    assert!(cubic().with_domain(q!(3), q!(2)).is_err());
    assert_eq!(c.reverse().points()[0], pt(&["4", "0"]));
    assert_eq!(c.clone().into_points().len(), 4);
}

#[test]
fn evaluation_on_the_domain() {
    let c = cubic();
    assert_eq!(c.eval(&q!(1 / 2)).unwrap(), pt(&["2", "9/4"]));
    assert_eq!(c.eval_bernstein(&q!(1 / 2)).unwrap(), pt(&["2", "9/4"]));
    assert_eq!(c.triangle(&q!(1 / 2)).unwrap()[3][0], pt(&["2", "9/4"]));
    assert_eq!(c.eval(&q!(0)).unwrap(), pt(&["0", "0"]));
    assert_eq!(c.eval(&q!(1)).unwrap(), pt(&["4", "0"]));
    assert_eq!(
        c.eval(&q!(3 / 2)).unwrap_err().to_string(),
        "parameter t = 3/2 is outside the domain [0, 1]"
    );
    assert!(c.eval_bernstein(&q!(-1 / 9)).is_err());
    assert!(c.triangle(&q!(2)).is_err());
    // the same polygon on [2, 4]: c(3) is the old c(1/2)
    let d = cubic().with_domain(q!(2), q!(4)).unwrap();
    assert_eq!(d.eval(&q!(3)).unwrap(), pt(&["2", "9/4"]));
    assert_eq!(d.local_parameter(&q!(5 / 2)), q!(1 / 4));
    assert_eq!(
        d.eval(&q!(1)).unwrap_err().to_string(),
        "parameter t = 1 is outside the domain [2, 4]"
    );
    // the blossom in the curve's own parameter: d[3, 3, 3] = d(3); d[2, 2, 4] = c_1
    assert_eq!(
        d.blossom(&[q!(3), q!(3), q!(3)]).unwrap(),
        pt(&["2", "9/4"])
    );
    assert_eq!(d.blossom(&[q!(2), q!(2), q!(4)]).unwrap(), pt(&["1", "3"]));
}

#[test]
fn subdivision_and_restriction_keep_the_parameter() {
    let c = cubic();
    let (l, r) = c.subdivide(&q!(1 / 2)).unwrap();
    assert_eq!(l.domain(), (&q!(0), &q!(1 / 2)));
    assert_eq!(r.domain(), (&q!(1 / 2), &q!(1)));
    assert_eq!(
        text(l.points()),
        ["(0, 0)", "(1/2, 3/2)", "(5/4, 9/4)", "(2, 9/4)"]
    );
    for t in [q!(1 / 7), q!(1 / 3), q!(1 / 2)] {
        assert_eq!(l.eval(&t).unwrap(), c.eval(&t).unwrap());
    }
    for t in [q!(1 / 2), q!(5 / 8), q!(1)] {
        assert_eq!(r.eval(&t).unwrap(), c.eval(&t).unwrap());
    }
    assert_eq!(
        c.subdivide(&q!(1)).unwrap_err().to_string(),
        "subdivision parameter t = 1 must lie strictly inside the domain (0, 1)"
    );
    let s = c.restrict(&q!(1 / 3), &q!(3 / 4)).unwrap();
    assert_eq!(
        s.to_text(),
        "(34/27, 2), (67/36, 29/12), (121/48, 37/16), (99/32, 27/16)"
    );
    assert_eq!(s.eval(&q!(1 / 2)).unwrap(), c.eval(&q!(1 / 2)).unwrap());
    // read over [0, 1]: the same control points, s(0) = c(1/3)
    let s01 = s.clone().with_domain(q!(0), q!(1)).unwrap();
    assert_eq!(s01.eval(&q!(0)).unwrap(), c.eval(&q!(1 / 3)).unwrap());
    // restricting beyond the domain extrapolates
    let big = c.restrict(&q!(-1), &q!(2)).unwrap();
    assert_eq!(big.restrict(&q!(0), &q!(1)).unwrap().points(), c.points());
    assert!(c.restrict(&q!(1 / 2), &q!(1 / 4)).is_err());
}

#[test]
fn elevation_and_derivatives_as_curves() {
    let c = cubic();
    let e = c.elevate_degree(2);
    assert_eq!(e.degree(), 5);
    assert_eq!(e.eval(&q!(2 / 5)).unwrap(), c.eval(&q!(2 / 5)).unwrap());
    let d = c.derivative(1);
    assert_eq!(d.degree(), 2);
    assert_eq!(d.to_text(), "(3, 9), (6, 0), (3, -9)");
    assert_eq!(d.eval(&q!(1 / 3)).unwrap(), pt(&["13/3", "3"]));
    assert_eq!(
        c.derivative(2).points(),
        c.derivative(1).derivative(1).points()
    );
    assert_eq!(c.derivative(7).to_text(), "(0, 0)");
    assert_eq!(text(&c.forward_differences(3)), ["(-2, 0)"]);
    // on [0, 2] the curve runs at half speed: c'(t) = (1/2) c'_{[0,1]}(t/2)
    let slow = cubic().with_domain(q!(0), q!(2)).unwrap();
    assert_eq!(
        slow.derivative(1).to_text(),
        "(3/2, 9/2), (3, 0), (3/2, -9/2)"
    );
    assert_eq!(slow.derivative(2).to_text(), "(3/2, -9/2), (-3/2, -9/2)");
    assert_eq!(
        slow.derivative(1).eval(&q!(2 / 3)).unwrap(),
        pt(&["13/6", "3/2"])
    );
}

#[test]
fn over_the_quadratic_field() {
    // control points with √2: the De Casteljau point and the elevation stay in Q(√2)
    let c = BezierCurve::try_new(vec![
        Point::new(vec![qn("0"), qn("sqrt2")]),
        Point::new(vec![qn("1"), qn("0")]),
        Point::new(vec![qn("sqrt2/2"), qn("1")]),
    ])
    .unwrap();
    let t = qn("1/2");
    let p = c.eval(&t).unwrap();
    // (1/4)(0, √2) + (1/2)(1, 0) + (1/4)(√2/2, 1) = (1/2 + √2/8, 1/4 + √2/4)
    assert_eq!(p.to_text(), "(1/2 + √2/8, 1/4 + √2/4)");
    assert_eq!(c.eval_bernstein(&t).unwrap(), p);
    assert_eq!(c.elevate_degree(1).eval(&t).unwrap(), p);
    let (l, r) = c.subdivide(&qn("1/3")).unwrap();
    assert_eq!(l.eval(&qn("1/5")).unwrap(), c.eval(&qn("1/5")).unwrap());
    assert_eq!(r.eval(&qn("1/2")).unwrap(), p);
    let parts: Vec<Quadratic> = c.derivative(1).eval(&t).unwrap().into_coords();
    // c'(1/2) = c2 - c0 = (√2/2, 1 - √2)
    assert_eq!(parts, vec![qn("sqrt2/2"), qn("1 - sqrt2")]);
}
