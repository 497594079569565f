//! The notes' examples as scenes.

use cagd_bezier::BezierCurve;
use cagd_linalg::Point;
use cagd_render::Scene;
use cagd_scalar::{parse_number, BigRational, Quadratic, Scalar};
use cagd_surface::{BezierSurface, RationalBezierSurface};

/// A point from exact strings: `pt(&["1/2", "5/6", "31/6"])`.
pub fn pt<S: Scalar>(c: &[&str]) -> Point<S> {
    Point::new(
        c.iter()
            .map(|t| S::try_from_number(&parse_number(t).unwrap()).unwrap())
            .collect(),
    )
}

/// A mesh from rows of exact strings.
pub fn rows<S: Scalar>(m: &[&[[&str; 3]]]) -> Vec<Vec<Point<S>>> {
    m.iter()
        .map(|row| row.iter().map(|p| pt(p)).collect())
        .collect()
}

pub fn bezier<S: Scalar>(m: &[&[[&str; 3]]]) -> BezierSurface<S> {
    BezierSurface::from_rows(rows(m)).unwrap()
}

pub fn curve<S: Scalar>(points: &[[&str; 3]]) -> BezierCurve<S> {
    BezierCurve::try_new(points.iter().map(|p| pt(p)).collect()).unwrap()
}

/// The Coons Bézier patch of the notes (chapter 6, §5) with its four input curves.
pub fn coons_patch<S: Scalar>() -> BezierSurface<S> {
    bezier(&[
        &[["0", "0", "0"], ["0", "1", "3"], ["0", "3", "0"]],
        &[["1/2", "0", "2"], ["1/2", "5/6", "31/6"], ["1/2", "3", "3"]],
        &[["1", "0", "3"], ["1", "2/3", "13/3"], ["1", "3", "1"]],
        &[["2", "0", "0"], ["2", "1", "2"], ["2", "4", "0"]],
    ])
}

pub fn coons_scene() -> Scene<BigRational> {
    let mut scene = Scene::new().with_title("Bézier Coons patch");
    scene.add_surface("Coons patch", coons_patch());
    scene.add_curve(
        "c1",
        curve(&[
            ["0", "0", "0"],
            ["1/2", "0", "2"],
            ["1", "0", "3"],
            ["2", "0", "0"],
        ]),
    );
    scene.add_curve(
        "c2",
        curve(&[
            ["0", "3", "0"],
            ["1/2", "3", "3"],
            ["1", "3", "1"],
            ["2", "4", "0"],
        ]),
    );
    scene.add_curve(
        "d1",
        curve(&[["0", "0", "0"], ["0", "1", "3"], ["0", "3", "0"]]),
    );
    scene.add_curve(
        "d2",
        curve(&[["2", "0", "0"], ["2", "1", "2"], ["2", "4", "0"]]),
    );
    scene
}

/// The sphere octant of chapter 6, §6, over the quadratic field (weights √2/2).
pub fn sphere_octant() -> RationalBezierSurface<Quadratic> {
    let w = |t: &str| parse_number(t).unwrap();
    RationalBezierSurface::from_rows(
        rows(&[
            &[["1", "0", "0"], ["1", "1", "0"], ["0", "1", "0"]],
            &[["1", "0", "1"], ["1", "1", "1"], ["0", "1", "1"]],
            &[["0", "0", "1"], ["0", "0", "1"], ["0", "0", "1"]],
        ]),
        vec![
            vec![w("1"), w("sqrt2/2"), w("1")],
            vec![w("sqrt2/2"), w("1/2"), w("sqrt2/2")],
            vec![w("1"), w("sqrt2/2"), w("1")],
        ],
    )
    .unwrap()
}

pub fn sphere_scene() -> Scene<Quadratic> {
    let mut scene = Scene::new().with_title("Sphere octant");
    scene.add_surface("octant", sphere_octant());
    scene
}

/// The ruled (2, 1) patch of chapter 6, §4, that is not developable.
pub fn ruled_patch<S: Scalar>() -> BezierSurface<S> {
    bezier(&[
        &[["0", "-1", "1"], ["0", "-2", "0"]],
        &[["0", "0", "1"], ["0", "0", "0"]],
        &[["2", "0", "1"], ["1", "0", "-1"]],
    ])
}

pub fn ruled_scene() -> Scene<BigRational> {
    let mut scene = Scene::new().with_title("Ruled, not developable");
    scene.add_surface("ruled patch", ruled_patch());
    scene
}

/// The two biquadratic patches of chapter 5, §6, joined along u = 1 / u = 0.
pub fn c1_pair<S: Scalar>() -> (BezierSurface<S>, BezierSurface<S>) {
    (
        bezier(&[
            &[["-1", "-2", "0"], ["0", "-1", "1"], ["1", "-2", "0"]],
            &[["-1", "-1", "0"], ["0", "0", "1"], ["1", "-1", "0"]],
            &[["-1", "0", "0"], ["0", "0", "0"], ["1", "0", "0"]],
        ]),
        bezier(&[
            &[["-1", "0", "0"], ["0", "0", "0"], ["1", "0", "0"]],
            &[["-1", "1", "0"], ["0", "0", "-2"], ["1", "1", "0"]],
            &[["-1", "2", "0"], ["0", "1", "-2"], ["1", "2", "0"]],
        ]),
    )
}

pub fn c1_scene() -> Scene<BigRational> {
    let (a, b) = c1_pair();
    let mut scene = Scene::new().with_title("Two patches joined along a border");
    scene.add_surface("first", a);
    scene.add_surface("second", b);
    scene
}
