//! Integration tests of cagd-spline-surface: hand-checked values, the slides' hemisphere in
//! Q(√2), errors, and property tests over random rational surfaces against independent routes.

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

use cagd_linalg::Point;
use cagd_scalar::{parse_number, q, BigRational, FieldOps, Print, Quadratic};
use cagd_spline_surface::*;
use cagd_surface::{BezierSurface, Grid, Mesh};
use proptest::collection::vec;
use proptest::prelude::*;

type Q = BigRational;

fn num(text: &str) -> Quadratic {
    parse_number(text).unwrap()
}

fn p3(x: i64, y: i64, z: i64) -> Point<Q> {
    Point::from_ints(&[x, y, z])
}

/// Biquadratic, two spans in u (notes' knots {0, 0, 1, 2, 2}), one in v ({0, 0, 1, 1}); the
/// mesh d_{i,j} = (i, j, z_{i,j}).
fn biquadratic() -> BSplineSurface<Q> {
    let z = [[0, 2, 4], [4, 0, 8], [8, 4, 0], [0, 8, 4]];
    let rows = (0..4)
        .map(|i| (0..3).map(|j| p3(i as i64, j as i64, z[i][j])).collect())
        .collect();
    let knots_u = vec![q!(0), q!(0), q!(1), q!(2), q!(2)];
    let knots_v = vec![q!(0), q!(0), q!(1), q!(1)];
    let (s, conv) =
        BSplineSurface::read((2, 2), (knots_u, knots_v), Mesh::mesh(rows).unwrap()).unwrap();
    assert_eq!(conv, (KnotConvention::Notes, KnotConvention::Notes));
    s
}

// ---------------------------------------------------------------- hand-checked values

#[test]
fn biquadratic_by_hand() {
    let s = biquadratic();
    assert_eq!(s.bidegree(), (2, 2));
    assert_eq!(s.spans(), (2, 1));
    assert_eq!(s.domain(), ((q!(0), q!(2)), (q!(0), q!(1))));
    // Rows first at v = 1/2: the rows are Bézier, weights (1/4, 1/2, 1/4): y = 1 and
    // z = 2, 3, 4, 5 for rows 0..3.
    let mut steps = Vec::new();
    let point = s
        .de_boor_rows_first_recorded(&q!(3 / 2), &q!(1 / 2), &mut steps)
        .unwrap();
    let polygon: Vec<String> = steps[0].polygon.iter().map(Point::to_text).collect();
    assert_eq!(
        polygon,
        ["(0, 1, 2)", "(1, 1, 3)", "(2, 1, 4)", "(3, 1, 5)"]
    );
    // Then De Boor at u = 3/2 on full knots {0, 0, 0, 1, 2, 2, 2}, span k = 3:
    // α = 3/4, 1/2, then 1/2: c = (1/8) d_1 + (5/8) d_2 + (1/4) d_3
    // x = 1/8 + 10/8 + 6/8 = 17/8, z = 3/8 + 20/8 + 10/8 = 33/8.
    assert_eq!(point.to_text(), "(17/8, 1, 33/8)");
    assert_eq!(
        s.de_boor_columns_first(&q!(3 / 2), &q!(1 / 2)).unwrap(),
        point
    );
    assert_eq!(s.eval_basis(&q!(3 / 2), &q!(1 / 2)).unwrap(), point);
    // Corners of a clamped surface are corners of the mesh.
    assert_eq!(s.eval(&q!(0), &q!(0)).unwrap(), p3(0, 0, 0));
    assert_eq!(s.eval(&q!(2), &q!(1)).unwrap(), p3(3, 2, 4));

    // Bézier extraction: inserting u = 1 once gives rows d_0, d_1, (d_1 + d_2)/2, d_2, d_3.
    let pieces = s.bezier_patches().unwrap();
    assert_eq!(pieces.shape(), (2, 1));
    assert_eq!(pieces.u_intervals, vec![(q!(0), q!(1)), (q!(1), q!(2))]);
    assert_eq!(
        pieces.get(0, 0).unwrap().to_text(),
        "{(0, 0, 0), (0, 1, 2), (0, 2, 4); (1, 0, 4), (1, 1, 0), (1, 2, 8); \
         (3/2, 0, 6), (3/2, 1, 2), (3/2, 2, 4)}"
    );
    assert_eq!(
        pieces.get(1, 0).unwrap().mesh().row(0),
        pieces.get(0, 0).unwrap().mesh().row(2)
    );
    let patch = pieces.get(1, 0).unwrap();
    assert_eq!(
        patch.eval(&q!(3 / 2), &q!(1 / 2)).unwrap().to_text(),
        "(17/8, 1, 33/8)"
    );
    assert!(pieces.to_text().starts_with("[0, 1] x [0, 1]: {(0, 0, 0)"));
    assert!(!s.is_bezier());
    assert_eq!(
        s.to_bezier().unwrap_err().to_string(),
        "not a single Bézier patch in u: 4 control points for degree 2 (a single Bézier piece \
         has 3)"
    );

    // Knot insertion in u at 1: the same rows as the extraction, as one B-spline.
    let t = s.insert_knot(Direction::U, &q!(1), 1).unwrap();
    assert_eq!(t.knots_u().to_text(), "{0, 0, 1, 1, 2, 2}");
    assert_eq!(
        t.mesh().row(2).unwrap(),
        pieces.get(0, 0).unwrap().mesh().row(2).unwrap()
    );
    assert_eq!(
        t.eval(&q!(3 / 2), &q!(1 / 2)).unwrap().to_text(),
        "(17/8, 1, 33/8)"
    );

    // The partial derivative c_u, by the derivative surface and at the point:
    // Δ_u d_{i,j} = 2 (d_{i+1,j} - d_{i,j}) / (u_{i+2} - u_i), notes' knots {0, 0, 1, 2, 2}:
    // denominators 1, 2, 1.
    let du = s.derivative(Direction::U).unwrap();
    assert_eq!(du.bidegree(), (1, 2));
    assert_eq!(du.knots_u().to_text(), "{0, 1, 2}");
    assert_eq!(
        du.mesh().column(0).unwrap(),
        vec![p3(2, 0, 8), p3(1, 0, 4), p3(2, 0, -16)]
    );
    let cu = s.partial(&q!(3 / 2), &q!(1 / 2), 1, 0).unwrap();
    assert_eq!(du.eval(&q!(3 / 2), &q!(1 / 2)).unwrap(), cu);
    // By hand: the polygon (i, 1, 2 + i) has c_u = (x', 0, x') with x' = Σ Δ N^1 at 3/2 on
    // {0, 1, 2}: (1/2)·1 + (1/2)·2 = 3/2.
    assert_eq!(cu.to_text(), "(3/2, 0, 3/2)");
    // c_v at the corner (0, 0): 2 (d_{0,1} - d_{0,0}) / (v_2 - v_0) = 2 (0, 1, 2).
    assert_eq!(s.partial(&q!(0), &q!(0), 0, 1).unwrap(), p3(0, 2, 4));
    assert!(s.partial(&q!(1 / 2), &q!(1 / 2), 3, 0).unwrap().is_zero());
}

#[test]
fn bilinear_graph_and_elevation() {
    // z = u v on [0, 1] x [0, 1] (notes, eq. (3)): mesh {(0,0,0),(0,1,0);(1,0,0),(1,1,1)}.
    let mesh = Mesh::mesh(vec![
        vec![p3(0, 0, 0), p3(0, 1, 0)],
        vec![p3(1, 0, 0), p3(1, 1, 1)],
    ])
    .unwrap();
    let (s, conv) = BSplineSurface::read(
        (1, 1),
        (
            vec![q!(0), q!(0), q!(1), q!(1)],
            vec![q!(0), q!(0), q!(1), q!(1)],
        ),
        mesh,
    )
    .unwrap();
    assert_eq!(conv, (KnotConvention::Full, KnotConvention::Full));
    assert!(s.is_bezier());
    assert_eq!(
        s.eval(&q!(1 / 3), &q!(3 / 4)).unwrap().to_text(),
        "(1/3, 3/4, 1/4)"
    );
    let e = s.elevate_degree(1, 1).unwrap();
    assert_eq!(e.bidegree(), (2, 2));
    // Elevating xy to bidegree (2, 2): z_{i,j} = (i/2)(j/2).
    assert_eq!(e.mesh().get(1, 1).unwrap().to_text(), "(1/2, 1/2, 1/4)");
    assert_eq!(e.mesh().get(2, 1).unwrap().to_text(), "(1, 1/2, 1/2)");
    assert_eq!(
        e.to_bezier().unwrap().eval(&q!(1 / 3), &q!(3 / 4)).unwrap(),
        s.eval(&q!(1 / 3), &q!(3 / 4)).unwrap()
    );
    assert_eq!(
        e.to_text_in(KnotConvention::Full),
        "bidegree (2, 2)\nknots u {0, 0, 0, 1, 1, 1}\nknots v {0, 0, 0, 1, 1, 1}\nmesh \
         {(0, 0, 0), (0, 1/2, 0), (0, 1, 0); (1/2, 0, 0), (1/2, 1/2, 1/4), (1/2, 1, 1/2); \
         (1, 0, 0), (1, 1/2, 1/2), (1, 1, 1)}"
    );
    assert_eq!(
        e.knots_text(KnotConvention::Notes),
        ("{0, 0, 1, 1}".to_string(), "{0, 0, 1, 1}".to_string())
    );
    let latex = e.to_latex_in(KnotConvention::Notes);
    assert!(latex.contains("\\{u_i\\} = \\{0, 0, 1, 1\\}"), "{latex}");
    assert!(latex.contains("\\frac{1}{4}"));
    // A Bézier patch on another domain keeps it as its knots.
    let patch = s
        .to_bezier()
        .unwrap()
        .with_domain(q!(2), q!(4), q!(-1), q!(0))
        .unwrap();
    let b = BSplineSurface::from_bezier(&patch).unwrap();
    assert_eq!(b.knots_u().to_text(), "{2, 4}");
    assert_eq!(b.domain_text(), "[2, 4] x [-1, 0]");
    assert_eq!(b.to_bezier().unwrap(), patch);
}

/// The slides' hemisphere: the quarter circle {(1, 0, 0), (1, 0, 1), (0, 0, 1)} with weights
/// {1, √2/2, 1} (rows, along u) turned by the 9-point circle on [0, 4] (columns, along v):
/// d_{i,j} = (x_i a_j, x_i b_j, z_i), w_{i,j} = w_i ω_j.
fn hemisphere() -> NurbsSurface<Quadratic> {
    let circle = [
        (1, 0),
        (1, 1),
        (0, 1),
        (-1, 1),
        (-1, 0),
        (-1, -1),
        (0, -1),
        (1, -1),
        (1, 0),
    ];
    let omega = |j: usize| if j % 2 == 0 { num("1") } else { num("sqrt2/2") };
    let profile = [(1, 0, num("1")), (1, 1, num("sqrt2/2")), (0, 1, num("1"))];
    let rows = profile
        .iter()
        .map(|(x, z, _)| {
            circle
                .iter()
                .map(|(a, b)| Point::from_ints(&[x * a, x * b, *z]))
                .collect()
        })
        .collect();
    let weights = Grid::from_fn(3, 9, |i, j| profile[i].2.clone() * omega(j));
    let knots_u = [0, 0, 1, 1].into_iter().map(Quadratic::from_i64).collect();
    let knots_v = [0, 0, 1, 1, 2, 2, 3, 3, 4, 4]
        .into_iter()
        .map(Quadratic::from_i64)
        .collect();
    let (s, conv) = NurbsSurface::read(
        (2, 2),
        (knots_u, knots_v),
        Mesh::mesh(rows).unwrap(),
        weights,
    )
    .unwrap();
    assert_eq!(conv, (KnotConvention::Notes, KnotConvention::Notes));
    s
}

#[test]
fn hemisphere_of_the_slides() {
    let s = hemisphere();
    assert!(s.has_positive_weights());
    assert_eq!(s.spans(), (1, 4));
    assert_eq!(s.domain().1, (num("0"), num("4")));
    assert_eq!(
        s.weights().row(1).unwrap()[..3]
            .iter()
            .map(|w| w.to_text())
            .collect::<Vec<_>>(),
        ["√2/2", "1/2", "√2/2"]
    );
    let text = s.to_text();
    assert!(text.starts_with(
        "bidegree (2, 2)\nknots u {0, 0, 1, 1}\nknots v {0, 0, 1, 1, 2, 2, 3, 3, 4, 4}\nmesh \
         {(1, 0, 0), (1, 1, 0), (0, 1, 0)"
    ));
    assert!(text.ends_with("weights {1, √2/2, 1, √2/2, 1, √2/2, 1, √2/2, 1; √2/2, 1/2, √2/2, 1/2, √2/2, 1/2, √2/2, 1/2, √2/2; 1, √2/2, 1, √2/2, 1, √2/2, 1, √2/2, 1}"), "{text}");
    assert!(s
        .to_latex_in(KnotConvention::Full)
        .contains("\\frac{\\sqrt{2}}{2}"));
    // Equator, pole, and the point (1/2, 1/2, √2/2).
    assert_eq!(
        s.eval(&num("0"), &num("3")).unwrap().to_text(),
        "(0, -1, 0)"
    );
    assert_eq!(
        s.eval(&num("1"), &num("7/3")).unwrap().to_text(),
        "(0, 0, 1)"
    );
    assert_eq!(
        s.eval(&num("1/2"), &num("1/2")).unwrap().to_text(),
        "(1/2, 1/2, √2/2)"
    );
    // The sphere's tangent plane is orthogonal to the radius.
    let [c, cu, cv] = s.first_partials(&num("1/3"), &num("7/5")).unwrap();
    assert_eq!(c.dot(&c), num("1"));
    assert_eq!(c.dot(&cu), num("0"));
    assert_eq!(c.dot(&cv), num("0"));
    assert!(!cu.is_zero() && !cv.is_zero());
    // The rational Bézier pieces: four octant-pairs, each a biquadratic rational patch.
    let pieces = s.bezier_patches().unwrap();
    assert_eq!(pieces.shape(), (1, 4));
    let first = pieces.get(0, 0).unwrap();
    assert_eq!(
        first.to_text(),
        "{(1, 0, 0), (1, 1, 0), (0, 1, 0); (1, 0, 1), (1, 1, 1), (0, 1, 1); (0, 0, 1), (0, 0, 1), \
         (0, 0, 1)} with weights {1, √2/2, 1; √2/2, 1/2, √2/2; 1, √2/2, 1}"
    );
    assert!(pieces.to_text().contains("[0, 1] x [3, 4]: "));
    assert!(!s.is_bezier());
    assert!(s.to_rational_bezier().is_err());
    let back = NurbsSurface::from_rational_bezier(first).unwrap();
    assert!(back.is_bezier());
    assert_eq!(back.to_rational_bezier().unwrap(), *first);
}

#[test]
fn hemisphere_algorithms_stay_on_the_sphere() {
    let s = hemisphere();
    let refined = s
        .insert_knot(Direction::U, &num("1/2"), 1)
        .unwrap()
        .refine_knots(Direction::V, &[num("1/2"), num("5/2"), num("5/2")])
        .unwrap();
    assert_eq!(refined.knots_u().to_text(), "{0, 0, 1/2, 1, 1}");
    let elevated = s.elevate_degree(1, 1).unwrap();
    assert_eq!(elevated.bidegree(), (3, 3));
    for (u, v) in [("1/5", "2/7"), ("3/4", "13/4"), ("1/2", "2"), ("0", "4")] {
        let (u, v) = (num(u), num(v));
        let p = s.eval(&u, &v).unwrap();
        assert_eq!(p.dot(&p), num("1"));
        assert_eq!(refined.eval(&u, &v).unwrap(), p);
        assert_eq!(elevated.eval(&u, &v).unwrap(), p);
        assert_eq!(s.de_boor_columns_first(&u, &v).unwrap(), p);
        assert_eq!(s.eval_quotient(&u, &v).unwrap(), p);
    }
}

#[test]
fn over_f64_close_to_the_exact_answers() {
    let h = std::f64::consts::FRAC_1_SQRT_2;
    let circle = [(1.0, 0.0), (1.0, 1.0), (0.0, 1.0), (-1.0, 1.0), (-1.0, 0.0)];
    let omega = [1.0, h, 1.0, h, 1.0];
    let profile = [(1.0, 0.0, 1.0), (1.0, 1.0, h), (0.0, 1.0, 1.0)];
    let rows = profile
        .iter()
        .map(|(x, z, _)| {
            circle
                .iter()
                .map(|(a, b)| Point::new(vec![x * a, x * b, *z]))
                .collect()
        })
        .collect();
    let weights = Grid::from_fn(3, 5, |i, j| profile[i].2 * omega[j]);
    let (s, _) = NurbsSurface::read(
        (2, 2),
        (vec![0.0, 0.0, 1.0, 1.0], vec![0.0, 0.0, 1.0, 1.0, 2.0, 2.0]),
        Mesh::mesh(rows).unwrap(),
        weights,
    )
    .unwrap();
    for (u, v) in [(0.3, 0.7), (0.9, 1.6), (0.5, 0.5)] {
        let p = s.eval(&u, &v).unwrap();
        assert!((p.dot(&p) - 1.0).abs() < 1e-12);
        let q = s
            .insert_knot(Direction::V, &0.25, 1)
            .unwrap()
            .elevate_degree(1, 0)
            .unwrap()
            .de_boor_columns_first(&u, &v)
            .unwrap();
        assert!(p
            .coords()
            .iter()
            .zip(q.coords())
            .all(|(a, b)| (a - b).abs() < 1e-12));
    }
    let p = s.eval(&0.5, &0.5).unwrap();
    assert!((p.coords()[0] - 0.5).abs() < 1e-12 && (p.coords()[2] - h).abs() < 1e-12);
}

// ---------------------------------------------------------------- errors

#[test]
fn bad_input_gives_clear_errors() {
    let s = biquadratic();
    let (ku, kv, mesh) = s.clone().into_parts();
    // A mesh with a row too few.
    let short = Mesh::mesh(mesh.to_rows()[..3].to_vec()).unwrap();
    assert_eq!(
        BSplineSurface::try_new(ku.clone(), kv.clone(), short.clone())
            .unwrap_err()
            .to_string(),
        "the knot vectors are made for a mesh of 4 x 3 control points (4 rows for the knots in u \
         of degree 2, 3 columns for the knots in v of degree 2), but the mesh is 3 x 3"
    );
    let e = BSplineSurface::read(
        (2, 2),
        (ku.notes().to_vec(), kv.notes().to_vec()),
        short.clone(),
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "knot vector in u: a curve of degree 2 with 3 control points needs 4 knots (the notes' \
         convention, without end knots) or 6 (with one more knot at each end, as in The NURBS \
         Book); found 5"
    );
    // Decreasing knots in v.
    let e = BSplineSurface::read(
        (2, 2),
        (
            ku.notes().to_vec(),
            vec![q!(0), q!(1 / 2), q!(1 / 4), q!(1)],
        ),
        mesh.clone(),
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "knot vector in v: knot vector decreases at index 2: 1/2 > 1/4"
    );
    // Parameters outside the domain.
    assert_eq!(
        s.eval(&q!(3), &q!(0)).unwrap_err().to_string(),
        "parameter u = 3 is outside the domain [0, 2] x [0, 1]"
    );
    assert_eq!(
        s.de_boor_columns_first(&q!(1), &q!(-1 / 2))
            .unwrap_err()
            .to_string(),
        "parameter v = -1/2 is outside the domain [0, 2] x [0, 1]"
    );
    assert!(s.eval_basis(&q!(1), &q!(2)).is_err());
    assert!(s.partial(&q!(5 / 2), &q!(0), 1, 0).is_err());
    // Algorithms that cannot run.
    assert_eq!(
        s.insert_knot(Direction::V, &q!(1 / 2), 3)
            .unwrap_err()
            .to_string(),
        "in v (on the rows of the mesh): knot 1/2 cannot be inserted 3 more time(s): it already \
         has multiplicity 0, and insertion stops at multiplicity 2 (the degree)"
    );
    assert!(s.refine_knots(Direction::U, &[q!(7)]).is_err());
    let line = s.derivative(Direction::U).unwrap();
    assert!(line
        .derivative(Direction::U)
        .unwrap_err()
        .to_string()
        .starts_with("in u (on the columns of the mesh): the derivative is not a B-spline curve"));
    // Weights: wrong shape, zero, negative, and a point at infinity.
    let ones = Grid::from_fn(4, 3, |_, _| q!(1));
    assert_eq!(
        NurbsSurface::with_weights(s.clone(), Grid::from_fn(3, 3, |_, _| q!(1)))
            .unwrap_err()
            .to_string(),
        "the weights form a 3x3 grid but the mesh is 4x3"
    );
    let mut w = ones.to_rows();
    w[2][1] = q!(0);
    assert_eq!(
        NurbsSurface::with_weights(s.clone(), Grid::from_rows(w.clone()).unwrap())
            .unwrap_err()
            .to_string(),
        "weight w_2,1 is zero: weights must be nonzero"
    );
    w[2][1] = q!(-1);
    let n = NurbsSurface::with_weights(s.clone(), Grid::from_rows(w).unwrap()).unwrap();
    assert_eq!(n.negative_weights(), vec![(2, 1)]);
    assert!(!n.has_positive_weights());
    let flat = Mesh::mesh(vec![
        vec![p3(0, 0, 0), p3(1, 0, 0)],
        vec![p3(0, 1, 0), p3(1, 1, 0)],
    ])
    .unwrap();
    let (bad, _) = NurbsSurface::read(
        (1, 1),
        (vec![q!(0), q!(1)], vec![q!(0), q!(1)]),
        flat,
        Grid::from_rows(vec![vec![q!(1), q!(1)], vec![q!(-1), q!(-1)]]).unwrap(),
    )
    .unwrap();
    assert_eq!(
        bad.eval(&q!(1 / 2), &q!(1 / 3)).unwrap_err().to_string(),
        "the denominator of the rational surface vanishes at (u, v) = (1/2, 1/3): the point is \
         at infinity"
    );
    assert!(bad.eval_quotient(&q!(1 / 2), &q!(0)).is_err());
    assert!(bad.first_partials(&q!(1 / 2), &q!(0)).is_err());
    // A Bézier patch of degree 0 in a direction has no B-spline form of this crate.
    let row = BezierSurface::from_rows(vec![vec![p3(0, 0, 0), p3(1, 0, 0)]]).unwrap();
    assert!(BSplineSurface::from_bezier(&row)
        .unwrap_err()
        .to_string()
        .starts_with("knot vector in u: degree 0 is not allowed"));
}

// ---------------------------------------------------------------- property tests

fn rat() -> impl Strategy<Value = Q> {
    (-9i64..=9, 1i64..=9).prop_map(|(n, d)| Q::from_ratio(n, d))
}

fn unit_rat() -> impl Strategy<Value = Q> {
    (1i64..=9).prop_flat_map(|d| (0..=d).prop_map(move |n| Q::from_ratio(n, d)))
}

fn point3() -> impl Strategy<Value = Point<Q>> {
    (rat(), rat(), rat()).prop_map(|(x, y, z)| Point::new(vec![x, y, z]))
}

/// A random valid knot vector of degree 1..=3 with 1..=3 more control points than a single
/// piece, clamped or not at each end, with a repeated knot now and then.
fn knots() -> impl Strategy<Value = KnotVector<Q>> {
    (1usize..=3, 0usize..=2, any::<bool>(), any::<bool>())
        .prop_flat_map(|(p, m, clamp_left, clamp_right)| {
            let k = 2 * p + m;
            (
                Just(p),
                Just(clamp_left),
                Just(clamp_right),
                vec(rat(), k),
                vec(1usize..k, 0..=1),
            )
        })
        .prop_filter_map(
            "knot vector not valid",
            |(p, clamp_left, clamp_right, mut knots, dups)| {
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
                KnotVector::from_notes(knots, p).ok()
            },
        )
}

fn surface() -> impl Strategy<Value = BSplineSurface<Q>> {
    (knots(), knots()).prop_flat_map(|(ku, kv)| {
        let (r, c) = (ku.control_point_count(), kv.control_point_count());
        (Just(ku), Just(kv), vec(vec(point3(), c), r)).prop_map(|(ku, kv, rows)| {
            BSplineSurface::try_new(ku, kv, Mesh::mesh(rows).unwrap()).unwrap()
        })
    })
}

fn weights(rows: usize, cols: usize) -> impl Strategy<Value = Grid<Q>> {
    vec(
        vec(
            (1i64..=9, 1i64..=9).prop_map(|(a, b)| Q::from_ratio(a, b)),
            cols,
        ),
        rows,
    )
    .prop_map(|w| Grid::from_rows(w).unwrap())
}

fn nurbs() -> impl Strategy<Value = NurbsSurface<Q>> {
    surface().prop_flat_map(|s| {
        let (r, c) = (s.mesh().rows(), s.mesh().cols());
        (Just(s), weights(r, c)).prop_map(|(s, w)| NurbsSurface::with_weights(s, w).unwrap())
    })
}

/// A parameter of the domain: a + λ (b - a).
fn in_domain(k: &KnotVector<Q>, lambda: &Q) -> Q {
    let (a, b) = k.domain();
    a.clone() + (b - a) * lambda
}

/// The index of the interval [a, b) that holds t, or the last one at its right end: the
/// piece De Boor uses (it matters where the surface jumps, at a knot of multiplicity p + 1).
fn interval_of(intervals: &[(Q, Q)], t: &Q) -> usize {
    intervals
        .iter()
        .position(|(a, b)| a <= t && t < b)
        .unwrap_or(intervals.len() - 1)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn a_normalized_surface_is_the_same_point_set(
        n in nurbs(), lu in unit_rat(), lv in unit_rat()
    ) {
        let (u, v) = (in_domain(n.knots_u(), &lu), in_domain(n.knots_v(), &lv));
        let m = n.normalized();
        prop_assert_eq!(m.knots_u().domain(), (Q::from_i64(0), Q::from_i64(1)));
        prop_assert_eq!(m.knots_v().domain(), (Q::from_i64(0), Q::from_i64(1)));
        prop_assert_eq!(m.eval(&lu, &lv).unwrap(), n.eval(&u, &v).unwrap());
        let b = n.control_surface().normalized();
        prop_assert_eq!(b.eval(&lu, &lv).unwrap(), n.control_surface().eval(&u, &v).unwrap());
        prop_assert_eq!(m.mesh(), n.mesh());
    }

    #[test]
    fn both_de_boor_orders_and_the_basis_sum_agree(
        s in surface(), lu in unit_rat(), lv in unit_rat()
    ) {
        let (u, v) = (in_domain(s.knots_u(), &lu), in_domain(s.knots_v(), &lv));
        let p = s.de_boor_rows_first(&u, &v).unwrap();
        prop_assert_eq!(&p, &s.de_boor_columns_first(&u, &v).unwrap());
        prop_assert_eq!(&p, &s.eval_basis(&u, &v).unwrap());
        prop_assert_eq!(&p, &s.partial(&u, &v, 0, 0).unwrap());
    }

    #[test]
    fn insertion_and_refinement_keep_the_surface(
        s in surface(), lu in unit_rat(), lv in unit_rat(),
        lt in unit_rat(), ls in vec(unit_rat(), 2), in_u in any::<bool>()
    ) {
        let (u, v) = (in_domain(s.knots_u(), &lu), in_domain(s.knots_v(), &lv));
        let p = s.eval(&u, &v).unwrap();
        let direction = if in_u { Direction::U } else { Direction::V };
        let knots = s.knots(direction);
        let t = in_domain(knots, &lt);
        if knots.multiplicity(&t) < knots.degree() {
            let inserted = s.insert_knot(direction, &t, 1).unwrap();
            prop_assert_eq!(inserted.knots(direction).multiplicity(&t), knots.multiplicity(&t) + 1);
            prop_assert_eq!(inserted.knots(direction.other()), s.knots(direction.other()));
            prop_assert_eq!(&inserted.eval(&u, &v).unwrap(), &p);
        }
        let new_u: Vec<Q> = ls.iter().map(|l| in_domain(s.knots_u(), l)).collect();
        let new_v: Vec<Q> = ls.iter().map(|l| in_domain(s.knots_v(), l)).collect();
        if let (Ok(a), Ok(b)) = (s.refine_knots(Direction::U, &new_u), s.refine_knots(Direction::V, &new_v)) {
            prop_assert_eq!(&a.eval(&u, &v).unwrap(), &p);
            prop_assert_eq!(&b.de_boor_columns_first(&u, &v).unwrap(), &p);
        }
    }

    #[test]
    fn bezier_patches_are_the_surface(s in surface(), lu in unit_rat(), lv in unit_rat()) {
        let (u, v) = (in_domain(s.knots_u(), &lu), in_domain(s.knots_v(), &lv));
        let pieces = s.bezier_patches().unwrap();
        prop_assert_eq!(pieces.shape(), s.spans());
        let (a, b) = (interval_of(&pieces.u_intervals, &u), interval_of(&pieces.v_intervals, &v));
        let patch = pieces.get(a, b).unwrap();
        prop_assert_eq!(patch.bidegree(), s.bidegree());
        prop_assert_eq!(&patch.eval(&u, &v).unwrap(), &s.eval(&u, &v).unwrap());
        // Each piece back as a B-spline of one span is the same surface there.
        let single = BSplineSurface::from_bezier(patch).unwrap();
        prop_assert!(single.is_bezier());
        prop_assert_eq!(&single.eval(&u, &v).unwrap(), &s.eval(&u, &v).unwrap());
    }

    #[test]
    fn degree_elevation_keeps_the_surface(
        s in surface(), lu in unit_rat(), lv in unit_rat(), r in 0usize..=1, t in 0usize..=1
    ) {
        let (u, v) = (in_domain(s.knots_u(), &lu), in_domain(s.knots_v(), &lv));
        let e = s.elevate_degree(r, t).unwrap();
        prop_assert_eq!(e.bidegree(), (s.bidegree().0 + r, s.bidegree().1 + t));
        prop_assert_eq!(e.spans(), s.spans());
        prop_assert_eq!(&e.eval(&u, &v).unwrap(), &s.eval(&u, &v).unwrap());
    }

    #[test]
    fn derivative_surfaces_are_the_partial_derivatives(
        s in surface(), lu in unit_rat(), lv in unit_rat()
    ) {
        let (u, v) = (in_domain(s.knots_u(), &lu), in_domain(s.knots_v(), &lv));
        for (direction, (k, l)) in [(Direction::U, (1, 0)), (Direction::V, (0, 1))] {
            // Degree 1, or a knot of multiplicity p + 1, has no derivative surface.
            if let Ok(d) = s.derivative(direction) {
                prop_assert_eq!(&d.eval(&u, &v).unwrap(), &s.partial(&u, &v, k, l).unwrap());
            }
        }
        // The mixed partial in either order.
        if let (Ok(du), Ok(dv)) = (s.derivative(Direction::U), s.derivative(Direction::V)) {
            let uv = du.derivative(Direction::V);
            let vu = dv.derivative(Direction::U);
            if let (Ok(uv), Ok(vu)) = (uv, vu) {
                prop_assert_eq!(uv.eval(&u, &v).unwrap(), vu.eval(&u, &v).unwrap());
            }
        }
    }

    #[test]
    fn a_bezier_patch_as_a_bspline_evaluates_the_same(
        rows in (1usize..=3, 1usize..=3).prop_flat_map(|(m, n)| vec(vec(point3(), n + 1), m + 1)),
        lu in unit_rat(), lv in unit_rat()
    ) {
        let patch = BezierSurface::from_rows(rows).unwrap();
        let s = BSplineSurface::from_bezier(&patch).unwrap();
        prop_assert!(s.is_bezier());
        prop_assert_eq!(&s.eval(&lu, &lv).unwrap(), &patch.eval(&lu, &lv).unwrap());
        prop_assert_eq!(&s.to_bezier().unwrap(), &patch);
        let pieces = s.bezier_patches().unwrap();
        prop_assert_eq!(pieces.get(0, 0).unwrap(), &patch);
    }

    #[test]
    fn nurbs_algorithms_keep_the_rational_surface(
        s in nurbs(), lu in unit_rat(), lv in unit_rat(), lt in unit_rat(), in_u in any::<bool>()
    ) {
        let (u, v) = (in_domain(s.knots_u(), &lu), in_domain(s.knots_v(), &lv));
        let p = s.eval(&u, &v).unwrap();
        prop_assert_eq!(&p, &s.de_boor_columns_first(&u, &v).unwrap());
        prop_assert_eq!(&p, &s.eval_quotient(&u, &v).unwrap());
        prop_assert_eq!(&p, &s.first_partials(&u, &v).unwrap()[0]);
        let direction = if in_u { Direction::U } else { Direction::V };
        let t = in_domain(s.knots(direction), &lt);
        if s.knots(direction).multiplicity(&t) < s.knots(direction).degree() {
            prop_assert_eq!(&s.insert_knot(direction, &t, 1).unwrap().eval(&u, &v).unwrap(), &p);
        }
        let e = s.elevate_degree_in(direction, 1).unwrap();
        prop_assert_eq!(&e.eval(&u, &v).unwrap(), &p);
        let pieces = s.bezier_patches().unwrap();
        let (a, b) = (interval_of(&pieces.u_intervals, &u), interval_of(&pieces.v_intervals, &v));
        prop_assert_eq!(&pieces.get(a, b).unwrap().eval(&u, &v).unwrap(), &p);
        let h = NurbsSurface::from_homogeneous(s.homogeneous()).unwrap();
        prop_assert_eq!(&h, &s);
    }

    #[test]
    fn hemisphere_points_are_exactly_on_the_sphere(
        (a, b) in (1i64..=9).prop_flat_map(|d| (0..=d, Just(d))),
        (c, d) in (1i64..=9).prop_flat_map(|d| (0..=4 * d, Just(d)))
    ) {
        let s = hemisphere();
        let (u, v) = (Quadratic::from_ratio(a, b), Quadratic::from_ratio(c, d));
        let p = s.eval(&u, &v).unwrap();
        prop_assert_eq!(p.dot(&p), Quadratic::from_i64(1));
        prop_assert!(p.coords()[2] >= Quadratic::from_i64(0));
    }
}
