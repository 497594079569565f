//! Scattered data (the notes' eqs. (28)-(29)): the notes' least-squares example, singular
//! interpolation problems, and properties against independent routes (grid interpolation,
//! residual orthogonality, recovery of a surface of the space).

use cagd_bspline::KnotVector;
use cagd_fit::{
    approximate_bezier_surface, approximate_bspline_surface, bezier_surface_matrix,
    bspline_surface_matrix, interpolate_bezier_surface, interpolate_bezier_surface_scattered,
    Direction, FitError,
};
use cagd_linalg::{Matrix, Point};
use cagd_scalar::{parse_number, q, ExactRational, FieldOps, Print, Quadratic};
use cagd_spline_surface::BSplineSurface;
use cagd_surface::Mesh;
use proptest::prelude::*;

use crate::common::{grid, normal_equations, point, unit_rational, Q};

fn notes_points() -> Vec<Point<Q>> {
    vec![
        Point::new(vec![q!(0), q!(0), q!(1 / 4)]),
        Point::new(vec![q!(1), q!(0), q!(1 / 3)]),
        Point::new(vec![q!(0), q!(1), q!(1 / 2)]),
        Point::new(vec![q!(1), q!(1), q!(3 / 4)]),
        Point::new(vec![q!(1 / 2), q!(1 / 2), q!(1 / 4)]),
    ]
}

fn notes_params() -> Vec<(Q, Q)> {
    vec![
        (q!(0), q!(0)),
        (q!(1), q!(0)),
        (q!(0), q!(1)),
        (q!(1), q!(1)),
        (q!(1 / 2), q!(1 / 2)),
    ]
}

fn matrix(rows: &[&[Q]]) -> Matrix<Q> {
    Matrix::from_rows(rows.iter().map(|r| r.to_vec()).collect()).unwrap()
}

#[test]
fn notes_hyperbolic_paraboloid_by_least_squares() {
    let fit = normal_equations(1, 1, &notes_params(), &notes_points()).unwrap();
    assert_eq!(
        fit.collocation.to_text(),
        "1  0  0  0\n0  0  1  0\n0  1  0  0\n0  0  0  1\n1/4  1/4  1/4  1/4"
    );
    let (a, b) = (q!(17), q!(1));
    let sixteenth = q!(1 / 16);
    let expected = matrix(&[
        &[a.clone(), b.clone(), b.clone(), b.clone()],
        &[b.clone(), a.clone(), b.clone(), b.clone()],
        &[b.clone(), b.clone(), a.clone(), b.clone()],
        &[b.clone(), b.clone(), b.clone(), a.clone()],
    ])
    .scale(&sixteenth);
    assert_eq!(fit.normal_matrix, expected);
    let rhs: Vec<Point<Q>> = [
        [q!(2), q!(2), q!(5)],
        [q!(2), q!(18), q!(9)],
        [q!(18), q!(2), q!(19 / 3)],
        [q!(18), q!(18), q!(13)],
    ]
    .into_iter()
    .map(|r| Point::new(r.to_vec()).scale(&sixteenth))
    .collect();
    assert_eq!(fit.rhs, rhs);
    assert_eq!(
        fit.surface.to_text(),
        "{(0, 0, 5/24), (0, 1, 11/24); (1, 0, 7/24), (1, 1, 17/24)}"
    );
    // The short form takes the same route with five points.
    assert_eq!(
        approximate_bezier_surface(1, 1, &notes_params(), &notes_points()).unwrap(),
        fit.surface
    );
}

#[test]
fn four_points_of_the_notes_are_interpolated() {
    // The first four points of the example at the corners: the mesh is the data, reordered
    // (a_1 = c(1, 0) is c_10, a_2 = c(0, 1) is c_01), and det B = −1 (one swap).
    let fit =
        interpolate_bezier_surface_scattered(1, 1, &notes_params()[..4], &notes_points()[..4])
            .unwrap();
    assert_eq!(fit.determinant, q!(-1));
    assert_eq!(
        fit.surface.to_text(),
        "{(0, 0, 1/4), (0, 1, 1/2); (1, 0, 1/3), (1, 1, 3/4)}"
    );
}

#[test]
fn swapping_two_parameters_changes_the_sign_of_det_b() {
    // The notes' argument: swapping the parameters of two points swaps two rows of B.
    let points = &notes_points()[..4];
    let params = [
        (q!(0), q!(0)),
        (q!(1), q!(0)),
        (q!(0), q!(1)),
        (q!(3 / 4), q!(1 / 2)),
    ];
    let mut swapped = params.clone();
    swapped.swap(0, 3);
    let d = interpolate_bezier_surface_scattered(1, 1, &params, points)
        .unwrap()
        .determinant;
    let e = interpolate_bezier_surface_scattered(1, 1, &swapped, points)
        .unwrap()
        .determinant;
    assert_eq!(d, q!(-3 / 8));
    assert_eq!(e, -d);
    // On the way from one to the other, det B vanishes: moving the fourth parameter along
    // v = 0 (where the bilinear patch is a line, and two other points already lie) ...
    let mut on_a_line = params.clone();
    on_a_line[3] = (q!(1 / 2), q!(0));
    let e = interpolate_bezier_surface_scattered(1, 1, &on_a_line, points).unwrap_err();
    assert!(matches!(
        e,
        FitError::SingularScattered {
            bidegree: (1, 1),
            ..
        }
    ));
    let text = e.to_string();
    assert!(text.starts_with(
        "the interpolation problem with scattered parameters is singular for these parameters: \
         det B = 0 for the collocation matrix B of eq. (28), bidegree (1, 1): column 3 has no pivot"
    ));
    assert!(text.contains(
        "swapping the parameters (u_i, v_i) and (u_j, v_j) of two points swaps two rows of B and \
         changes the sign of det B"
    ));
    // ... and halfway along the straight path from params to swapped, points a_0 and a_3
    // share their parameters.
    let halfway: Vec<(Q, Q)> = params
        .iter()
        .zip(&swapped)
        .map(|((a, b), (c, d))| ((a.clone() + c) / q!(2), (b.clone() + d) / q!(2)))
        .collect();
    let e = interpolate_bezier_surface_scattered(1, 1, &halfway, points).unwrap_err();
    assert!(e.to_string().contains(
        "bidegree (1, 1): points a_0 and a_3 have the same parameters (3/8, 1/4), so B has two \
         equal rows. This is not the data's fault"
    ));
}

#[test]
fn four_parameters_on_one_line_are_singular() {
    // On the diagonal u = v a bilinear patch is a parabola in t: four points cannot fix it.
    let line: Vec<(Q, Q)> = (0..4)
        .map(|k| (Q::from_ratio(k, 3), Q::from_ratio(k, 3)))
        .collect();
    let points = &notes_points()[..4];
    let e = interpolate_bezier_surface_scattered(1, 1, &line, points).unwrap_err();
    assert!(matches!(e, FitError::SingularScattered { .. }));
    // Least squares with a fifth point on the same line: B^t B is singular too.
    let five: Vec<(Q, Q)> = (0..5)
        .map(|k| (Q::from_ratio(k, 4), Q::from_ratio(k, 4)))
        .collect();
    let e = approximate_bezier_surface(1, 1, &five, &notes_points()).unwrap_err();
    assert!(matches!(e, FitError::UndeterminedMesh { .. }));
    assert!(e.to_string().starts_with(
        "least squares by a Bézier patch of bidegree (1, 1) is singular for these parameters \
         (u_k, v_k): they do not determine every control point (as when they all lie on one \
         line of the domain); the normal matrix BᵗB is singular"
    ));
}

#[test]
fn scattered_errors_name_the_cause() {
    let (params, points) = (notes_params(), notes_points());
    let e = interpolate_bezier_surface_scattered(1, 1, &params, &points).unwrap_err();
    assert_eq!(
        e.to_string(),
        "interpolation by a patch of bidegree (1, 1) with scattered parameters (4 control \
         points) takes exactly 4 data points (one per control point), found 5: approximate \
         them by least squares instead"
    );
    let e = interpolate_bezier_surface_scattered(2, 1, &params, &points).unwrap_err();
    assert_eq!(
        e.to_string(),
        "interpolation by a patch of bidegree (2, 1) with scattered parameters (6 control \
         points) needs at least 6 data points, found 5"
    );
    let e = normal_equations(2, 1, &params, &points).unwrap_err();
    assert_eq!(
        e.to_string(),
        "least squares by a patch of bidegree (2, 1) (6 unknown control points) needs at least \
         6 data points, found 5"
    );
    // Only two distinct values of v for degree 2 in v.
    let e = approximate_bezier_surface(1, 2, &params[..4], &points[..4]).unwrap_err();
    assert!(matches!(e, FitError::TooFewPoints { .. }));
    let six: Vec<(Q, Q)> = (0..6)
        .map(|k| (Q::from_ratio(k, 5), Q::from_ratio(k % 2, 1)))
        .collect();
    let pts: Vec<Point<Q>> = (0..6).map(|k| Point::from_ints(&[k])).collect();
    let e = approximate_bezier_surface(1, 2, &six, &pts).unwrap_err();
    assert_eq!(
        e,
        FitError::TooFewDistinctSurfaceParameters {
            direction: Direction::V,
            degree: 2,
            found: 2
        }
    );
    assert_eq!(
        e.to_string(),
        "a patch of degree 2 in v needs at least 3 distinct values of v among the parameters \
         (u_k, v_k), found 2: the columns of the collocation matrix B are linearly dependent \
         whatever the data"
    );
    let e = approximate_bezier_surface(1, 1, &params[..4], &points).unwrap_err();
    assert_eq!(
        e.to_string(),
        "5 data points but 4 parameters: give one parameter per point"
    );
    assert_eq!(
        approximate_bezier_surface::<Q>(1, 1, &[], &[]).unwrap_err(),
        FitError::NoData
    );
}

#[test]
fn bezier_surface_matrix_orders_the_mesh_row_by_row() {
    // Column i (n + 1) + j is c_ij: bidegree (1, 2) at (u, v) = (1/3, 1/2).
    let b = bezier_surface_matrix(1, 2, &[(q!(1 / 3), q!(1 / 2))]);
    assert_eq!(b.to_text(), "1/6  1/3  1/6  1/12  1/6  1/12");
}

#[test]
fn quadratic_and_f64_scattered_fits() {
    let n = |t: &str| parse_number(t).unwrap();
    // A plane z = √2 u − v sampled at five points is recovered exactly over a + b√2.
    let params: Vec<(Quadratic, Quadratic)> = [
        ("0", "0"),
        ("1", "0"),
        ("0", "1"),
        ("1", "1"),
        ("sqrt2/2", "1/3"),
    ]
    .iter()
    .map(|(u, v)| (n(u), n(v)))
    .collect();
    let plane = |u: &Quadratic, v: &Quadratic| Point::new(vec![n("sqrt2") * u - v]);
    let points: Vec<Point<Quadratic>> = params.iter().map(|(u, v)| plane(u, v)).collect();
    let s = approximate_bezier_surface(1, 1, &params, &points).unwrap();
    assert_eq!(s.to_text(), "{(0), (-1); (√2), (-1 + √2)}");
    // Four of them (one at u = √2/2) by eq. (28) directly: the same plane.
    let direct = interpolate_bezier_surface_scattered(1, 1, &params[1..], &points[1..]).unwrap();
    assert_eq!(direct.surface, s);
    // det B = (1 − √2/2)(1 − 1/3), the entry of the one row with a nonzero first column (the
    // rows take the columns by an even permutation).
    assert_eq!(direct.determinant.to_text(), "2/3 - √2/3");
    // And by a bilinear B-spline surface with one span: the same mesh.
    let k = KnotVector::clamped(1, &[n("0"), n("1")]).unwrap();
    let b = approximate_bspline_surface(&k, &k, &params, &points).unwrap();
    assert_eq!(b.mesh(), s.mesh());
    // f64: the notes' example to 1e-12.
    let pf: Vec<(f64, f64)> = notes_params()
        .iter()
        .map(|(u, v)| (u.to_f64(), v.to_f64()))
        .collect();
    let af: Vec<Point<f64>> = notes_points()
        .iter()
        .map(|p| Point::new(p.to_f64()))
        .collect();
    let s = approximate_bezier_surface(1, 1, &pf, &af).unwrap();
    let z = s.mesh().get(1, 1).unwrap().coords()[2];
    assert!((z - 17.0 / 24.0).abs() < 1e-12);
}

#[test]
fn bspline_surface_least_squares_recovers_and_names_errors() {
    // A bilinear-by-quadratic spline sampled at a 4 x 5 grid of parameters is recovered.
    let ku = KnotVector::clamped(1, &[q!(0), q!(1 / 2), q!(1)]).unwrap();
    let kv = KnotVector::clamped(2, &[q!(0), q!(1)]).unwrap();
    let mesh = Mesh::from_fn(3, 3, |i, j| {
        Point::from_ints(&[i as i64, j as i64, (i * j) as i64 - 1])
    });
    let s = BSplineSurface::try_new(ku.clone(), kv.clone(), mesh.clone()).unwrap();
    let params: Vec<(Q, Q)> = (0..4)
        .flat_map(|i| (0..5).map(move |j| (Q::from_ratio(i, 3), Q::from_ratio(j, 4))))
        .collect();
    let points: Vec<Point<Q>> = params.iter().map(|(u, v)| s.eval(u, v).unwrap()).collect();
    let fit = approximate_bspline_surface(&ku, &kv, &params, &points).unwrap();
    assert_eq!(fit.mesh(), &mesh);
    let b = bspline_surface_matrix(&ku, &kv, &params).unwrap();
    assert_eq!((b.rows(), b.cols()), (20, 9));
    // A parameter outside the domain in v.
    let mut bad = params.clone();
    bad[7].1 = q!(2);
    let e = approximate_bspline_surface(&ku, &kv, &bad, &points).unwrap_err();
    assert_eq!(
        e.to_string(),
        "parameter v_7 = 2 (of data point a_7) is outside the domain [0, 1] of the knot vector in v"
    );
    // No parameter with u in (1/2, 1]: d_2,j is not determined.
    let left: Vec<(Q, Q)> = (0..3)
        .flat_map(|i| (0..5).map(move |j| (Q::from_ratio(i, 4), Q::from_ratio(j, 4))))
        .collect();
    let pts: Vec<Point<Q>> = left.iter().map(|(u, v)| s.eval(u, v).unwrap()).collect();
    let e = approximate_bspline_surface(&ku, &kv, &left, &pts).unwrap_err();
    assert_eq!(
        e.to_string(),
        "control point d_2,0 is not determined: no parameter (u_k, v_k) lies in the support \
         [1/2, 1] x [0, 1] of its basis function N_2(u) N_0(v)"
    );
    let e = approximate_bspline_surface(&ku, &kv, &params[..8], &points[..8]).unwrap_err();
    assert!(e
        .to_string()
        .ends_with("needs at least 9 data points, found 8"));
}

/// Parameter pairs (u_k, v_k).
type Params = Vec<(Q, Q)>;

/// Bidegree (m, n) with m, n ≤ 2 and (m + 1)(n + 1) + extra parameters in [0, 1]² with
/// data in R^2.
fn scattered_data(extra: usize) -> impl Strategy<Value = (usize, usize, Params, Vec<Point<Q>>)> {
    (0usize..=2, 0usize..=2, 0..=extra).prop_flat_map(|(m, n, e)| {
        let count = (m + 1) * (n + 1) + e;
        (
            Just(m),
            Just(n),
            prop::collection::vec((unit_rational(), unit_rational()), count),
            prop::collection::vec(point(2), count),
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn least_squares_with_as_many_points_is_the_interpolant(
        (m, n, params, points) in scattered_data(0)
    ) {
        let direct = interpolate_bezier_surface_scattered(m, n, &params, &points);
        let normal = normal_equations(m, n, &params, &points);
        match (direct, normal) {
            (Ok(d), Ok(l)) => {
                prop_assert_ne!(&d.determinant, &Q::from_i64(0));
                prop_assert_eq!(&d.surface, &l.surface);
                for ((u, v), a) in params.iter().zip(&points) {
                    prop_assert_eq!(&d.surface.eval(u, v).unwrap(), a);
                }
            }
            // Both routes fail for the same parameters (the problem is singular).
            (Err(_), Err(_)) => {}
            (d, l) => prop_assert!(false, "one route failed: {:?} / {:?}", d.err(), l.err()),
        }
    }

    #[test]
    fn scattered_parameters_on_a_grid_give_the_grid_interpolant(
        data in (1usize..=3, 1usize..=3).prop_flat_map(|(r, c)| grid(r, c, 3)),
    ) {
        // Parameters i/m, j/n on the grid (0 for degree 0); the mesh is that of (26)-(27).
        let (m, n) = (data.rows() - 1, data.cols() - 1);
        let at = |k: usize, d: usize| if d == 0 { q!(0) } else { Q::from_ratio(k as i64, d as i64) };
        let u: Vec<Q> = (0..=m).map(|i| at(i, m)).collect();
        let v: Vec<Q> = (0..=n).map(|j| at(j, n)).collect();
        let params: Vec<(Q, Q)> =
            data.indexed().map(|((i, j), _)| (u[i].clone(), v[j].clone())).collect();
        let points: Vec<Point<Q>> = data.iter().cloned().collect();
        let grid_fit = interpolate_bezier_surface(&u, &v, &data).unwrap();
        let scattered = approximate_bezier_surface(m, n, &params, &points).unwrap();
        prop_assert_eq!(grid_fit.mesh(), scattered.mesh());
    }

    #[test]
    fn least_squares_residual_is_orthogonal((m, n, params, points) in scattered_data(4)) {
        let Ok(fit) = normal_equations(m, n, &params, &points) else {
            // Too few distinct parameters or a singular BᵗB: nothing to check.
            return Ok(());
        };
        let b = &fit.collocation;
        prop_assert_eq!(&b.transpose().mul(b).unwrap(), &fit.normal_matrix);
        // Bᵗ (B C − A) = 0, with C the mesh row by row.
        let c: Vec<Point<Q>> = fit.surface.mesh().iter().cloned().collect();
        for col in 0..b.cols() {
            let mut r = Point::zero(2);
            for (k, a) in points.iter().enumerate() {
                let row: Vec<Q> = b.row(k).to_vec();
                let bc = Point::combination(&c, &row, 2);
                r.add_scaled(&(&bc - a), b.get(k, col));
            }
            prop_assert!(r.is_zero(), "column {}: {}", col, r.to_text());
        }
        // Row k of B C is the patch at (u_k, v_k).
        for (k, (u, v)) in params.iter().enumerate() {
            let row: Vec<Q> = b.row(k).to_vec();
            prop_assert_eq!(Point::combination(&c, &row, 2), fit.surface.eval(u, v).unwrap());
        }
        // Bᵗ A is the right-hand side shown.
        let bta: Vec<Point<Q>> = (0..b.cols())
            .map(|col| {
                let column: Vec<Q> = (0..b.rows()).map(|k| b.get(k, col).clone()).collect();
                Point::combination(&points, &column, 2)
            })
            .collect();
        prop_assert_eq!(&bta, &fit.rhs);
    }
}
