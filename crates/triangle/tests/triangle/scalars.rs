//! The algorithms over the quadratic field a + b√2 and over f64.

use cagd_linalg::Point;
use cagd_scalar::{parse_number, Quadratic};
use cagd_triangle::{Barycentric, Direction, TriangularPatch};

fn qn(text: &str) -> Quadratic {
    parse_number(text).unwrap()
}

fn qpt(coords: &[&str]) -> Point<Quadratic> {
    Point::new(coords.iter().map(|c| qn(c)).collect())
}

/// A quadratic patch with √2/2 in its net (the kind of numbers of circles and spheres).
fn root_patch() -> TriangularPatch<Quadratic> {
    TriangularPatch::try_new(
        2,
        vec![
            qpt(&["1", "0", "0"]),
            qpt(&["sqrt2/2", "sqrt2/2", "0"]),
            qpt(&["sqrt2/2", "0", "sqrt2/2"]),
            qpt(&["0", "1", "0"]),
            qpt(&["0", "sqrt2/2", "sqrt2/2"]),
            qpt(&["0", "0", "1"]),
        ],
    )
    .unwrap()
}

#[test]
fn quadratic_field_evaluation_is_exact() {
    let p = root_patch();
    // centroid: (1/9)(1 + 0 + 0) + (2/9)(√2/2 + √2/2 + 0) = 1/9 + 2√2/9 in every coordinate
    let c = Barycentric::centroid();
    let value = p.evaluate(&c);
    assert_eq!(value.to_text(), "(1/9 + 2√2/9, 1/9 + 2√2/9, 1/9 + 2√2/9)");
    assert_eq!(p.evaluate_bernstein(&c), value);
    // a barycentric point with a root in it
    let x = Barycentric::from_uv(qn("sqrt2/4"), qn("1/4"));
    assert_eq!(p.evaluate(&x), p.evaluate_bernstein(&x));
    let y = Barycentric::try_new(qn("1 - sqrt2/2"), qn("sqrt2/4"), qn("sqrt2/4")).unwrap();
    assert_eq!(p.evaluate(&y), p.evaluate_bernstein(&y));
}

#[test]
fn quadratic_field_blossom_elevation_split_derivative() {
    let p = root_patch();
    let x = Barycentric::from_uv(qn("sqrt2/4"), qn("1/3"));
    let y = Barycentric::from_uv(qn("1/5"), qn("sqrt2/8"));
    assert_eq!(
        p.blossom(&[x.clone(), y.clone()]).unwrap(),
        p.blossom(&[y.clone(), x.clone()]).unwrap()
    );
    assert_eq!(p.blossom(&[x.clone(), x.clone()]).unwrap(), p.evaluate(&x));
    assert_eq!(p.elevate_degree().evaluate(&y), p.evaluate(&y));
    assert_eq!(
        p.elevate_degree_by(2).unwrap(),
        p.elevate_degree().elevate_degree()
    );
    let (e1, e2, e3) = (Barycentric::e1(), Barycentric::e2(), Barycentric::e3());
    let [a, b, c] = p.split(&x);
    assert_eq!(a, p.restrict(&x, &e2, &e3));
    assert_eq!(b, p.restrict(&e1, &x, &e3));
    assert_eq!(c, p.restrict(&e1, &e2, &x));
    // the patch over (x, e2, e3) at its vertex e1 is b(x)
    assert_eq!(a.evaluate(&e1), p.evaluate(&x));
    let d = Direction::from_uv(qn("sqrt2"), qn("-1"));
    assert_eq!(
        p.directional_derivative(&y, &d),
        p.de_casteljau(&y).directional_derivative(&d)
    );
    // the corner derivative along the edge t = 0: 2(b110 - b200) = (√2 - 2, √2, 0)
    assert_eq!(
        p.directional_derivative(&e1, &Direction::du()).to_text(),
        "(-2 + √2, √2, 0)"
    );
}

#[test]
fn f64_agrees_with_exact() {
    let net: Vec<Point<f64>> = vec![
        Point::from_ints(&[0, 0, 0]),
        Point::from_ints(&[1, 0, 1]),
        Point::from_ints(&[0, 1, 2]),
        Point::from_ints(&[2, 0, 0]),
        Point::from_ints(&[1, 1, 3]),
        Point::from_ints(&[0, 2, 0]),
    ];
    let p = TriangularPatch::try_new(2, net).unwrap();
    // a dyadic point: everything is exact in binary floating point
    let x = Barycentric::try_new(0.5, 0.25, 0.25).unwrap();
    // b = (1/4)·0 + (1/4)(1,0,1) + (1/4)(0,1,2) + (1/16)(2,0,0) + (1/8)(1,1,3) + (1/16)(0,2,0)
    assert_eq!(p.evaluate(&x).coords(), &[0.5, 0.5, 1.125]);
    assert_eq!(p.evaluate_bernstein(&x), p.evaluate(&x));
    // at the centroid f64 rounds; the two routes agree to rounding and match 2/3, 2/3, 4/3
    let c = Barycentric::centroid();
    let (a, b) = (p.evaluate(&c), p.evaluate_bernstein(&c));
    for (m, exact) in [2.0 / 3.0, 2.0 / 3.0, 4.0 / 3.0].into_iter().enumerate() {
        assert!((a[m] - exact).abs() < 1e-12 && (b[m] - exact).abs() < 1e-12);
    }
    let du = p.directional_derivative(&x, &Direction::du());
    assert_eq!(
        du,
        p.de_casteljau(&x).directional_derivative(&Direction::du())
    );
    let [s, _, _] = p.split(&x);
    assert_eq!(s.evaluate(&Barycentric::e1()), p.evaluate(&x));
    // elevation divides by n + 1 = 3, which rounds in f64
    let up = p.elevate_degree().evaluate(&x);
    for m in 0..3 {
        assert!((up[m] - p.evaluate(&x)[m]).abs() < 1e-12);
    }
}
