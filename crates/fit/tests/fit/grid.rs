//! Tensor-grid interpolation by a Bézier patch (the notes' eqs. (26)-(27)), checked against
//! the notes' example, the Bernstein double sum and the matrix form B_U C B_Vᵗ = A.

use cagd_bezier::bernstein_all;
use cagd_fit::{coordinate_matrices, interpolate_bezier_surface, Direction, FitError, PassOrder};
use cagd_linalg::{Matrix, Point};
use cagd_scalar::{parse_number, q, ExactRational, FieldOps, Quadratic, Scalar};
use cagd_surface::{BezierSurface, Mesh};
use proptest::prelude::*;

use crate::common::{bezier_in_passes, grid, increasing, Q};

/// The notes' data: c(u_i, v_j) for u = 0, 1/2, 1 (rows) and v = 0, 1/3, 2/3, 1 (columns).
fn notes_data() -> Mesh<Q> {
    let p = |x: i64, y: i64, z: Q| Point::new(vec![Q::from_i64(x), Q::from_i64(y), z]);
    Mesh::mesh(vec![
        vec![
            p(0, 0, q!(0)),
            p(1, 0, q!(1)),
            p(2, 0, q!(0)),
            p(3, 0, q!(-1)),
        ],
        vec![
            p(0, 1, q!(1)),
            p(1, 1, q!(2)),
            p(2, 1, q!(1)),
            p(3, 1, q!(1 / 2)),
        ],
        vec![
            p(0, 2, q!(0)),
            p(1, 2, q!(1)),
            p(2, 2, q!(0)),
            p(3, 2, q!(-2)),
        ],
    ])
    .unwrap()
}

fn notes_u() -> Vec<Q> {
    vec![q!(0), q!(1 / 2), q!(1)]
}

fn notes_v() -> Vec<Q> {
    vec![q!(0), q!(1 / 3), q!(2 / 3), q!(1)]
}

/// The Bernstein double sum Σ_i Σ_j c_ij B_i^m(s) B_j^n(t) at local parameters (s, t): a
/// route independent of De Casteljau and of the solves.
fn bernstein_double_sum<S: Scalar>(mesh: &Mesh<S>, s: &S, t: &S) -> Point<S> {
    let bu = bernstein_all(mesh.rows() - 1, s);
    let bv = bernstein_all(mesh.cols() - 1, t);
    let mut x = Point::zero(mesh.dim());
    for ((i, j), c) in mesh.indexed() {
        x.add_scaled(c, &bu[i].mul_ref(&bv[j]));
    }
    x
}

#[test]
fn notes_bidegree_two_three_example() {
    let data = notes_data();
    let steps = bezier_in_passes(&notes_u(), &notes_v(), &data, PassOrder::RowsFirst).unwrap();
    assert_eq!(steps.matrix_u.to_text(), "1  0  0\n1/4  1/2  1/4\n0  0  1");
    assert_eq!(
        steps.matrix_v.to_text(),
        "1  0  0  0\n8/27  4/9  2/9  1/27\n1/27  2/9  4/9  8/27\n0  0  0  1"
    );
    // C̃ = B_U C: rows 0 and 2 are the boundary curves, row 1 their weighted average.
    assert_eq!(
        steps.intermediate.to_text(),
        "{(0, 0, 0), (1, 0, 8/3), (2, 0, -2/3), (3, 0, -1); \
         (0, 1, 1), (1, 1, 23/6), (2, 1, -1/12), (3, 1, 1/2); \
         (0, 2, 0), (1, 2, 7/3), (2, 2, 1/6), (3, 2, -2)}"
    );
    assert_eq!(
        steps.surface.to_text(),
        "{(0, 0, 0), (1, 0, 8/3), (2, 0, -2/3), (3, 0, -1); \
         (0, 1, 2), (1, 1, 31/6), (2, 1, 1/12), (3, 1, 5/2); \
         (0, 2, 0), (1, 2, 7/3), (2, 2, 1/6), (3, 2, -2)}"
    );
    assert_eq!(steps.surface.bidegree(), (2, 3));
    // The coordinate matrices of the notes.
    let c = coordinate_matrices(steps.surface.mesh()).unwrap();
    assert_eq!(c[0].to_text(), "0  1  2  3\n0  1  2  3\n0  1  2  3");
    assert_eq!(c[1].to_text(), "0  0  0  0\n1  1  1  1\n2  2  2  2");
    assert_eq!(
        c[2].to_text(),
        "0  8/3  -2/3  -1\n2  31/6  1/12  5/2\n0  7/3  1/6  -2"
    );
    let a = coordinate_matrices(&data).unwrap();
    assert_eq!(a[2].to_text(), "0  1  0  -1\n1  2  1  1/2\n0  1  0  -2");
    // Columns first: Ĉ = C B_Vᵗ, then the same mesh.
    let other = bezier_in_passes(&notes_u(), &notes_v(), &data, PassOrder::ColumnsFirst).unwrap();
    assert_eq!(other.surface, steps.surface);
    assert_ne!(other.intermediate, steps.intermediate);
    assert_eq!(other.order, PassOrder::ColumnsFirst);
    // The short form is the rows-first result.
    assert_eq!(
        interpolate_bezier_surface(&notes_u(), &notes_v(), &data).unwrap(),
        steps.surface
    );
}

/// The notes' closed form of the same patch:
/// z = 27/2 (u v³ − u v²) + 9 v³ + 18 (u² v² − v² − u² v³) + 3 u v + 8 v + 4 (u − u² − u² v).
#[test]
fn notes_example_matches_its_closed_form() {
    let s = interpolate_bezier_surface(&notes_u(), &notes_v(), &notes_data()).unwrap();
    let z = |u: &Q, v: &Q| -> Q {
        let (u2, v2) = (u.powi(2), v.powi(2));
        let v3 = v.powi(3);
        q!(27 / 2) * (u.clone() * &v3 - u.clone() * &v2)
            + q!(9) * &v3
            + q!(18) * (u2.clone() * &v2 - v2.clone() - u2.clone() * &v3)
            + q!(3) * u.clone() * v
            + q!(8) * v.clone()
            + q!(4) * (u.clone() - &u2 - u2.clone() * v)
    };
    for (u, v) in [
        (q!(1 / 4), q!(3 / 5)),
        (q!(1 / 2), q!(1 / 3)),
        (q!(7 / 9), q!(1 / 8)),
    ] {
        let x = s.eval(&u, &v).unwrap();
        let expected = Point::new(vec![q!(3) * v.clone(), q!(2) * u.clone(), z(&u, &v)]);
        assert_eq!(x, expected);
    }
}

/// The matrix form (27), B_U C B_Vᵗ = A, coordinate by coordinate, and C̃ = B_U C.
#[test]
fn notes_example_satisfies_the_matrix_form() {
    let data = notes_data();
    let steps = bezier_in_passes(&notes_u(), &notes_v(), &data, PassOrder::RowsFirst).unwrap();
    let c = coordinate_matrices(steps.surface.mesh()).unwrap();
    let a = coordinate_matrices(&data).unwrap();
    let tilde = coordinate_matrices(&steps.intermediate).unwrap();
    for k in 0..3 {
        let bc = steps.matrix_u.mul(&c[k]).unwrap();
        assert_eq!(bc, tilde[k]);
        assert_eq!(bc.mul(&steps.matrix_v.transpose()).unwrap(), a[k]);
    }
}

#[test]
fn grid_errors_name_the_cause() {
    let data = notes_data();
    let e = interpolate_bezier_surface(&notes_u(), &[q!(0), q!(1 / 3), q!(1), q!(1 / 3)], &data)
        .unwrap_err();
    assert_eq!(
        e,
        FitError::RepeatedGridParameter {
            direction: Direction::V,
            first: 1,
            second: 3,
            value: "1/3".into()
        }
    );
    assert_eq!(
        e.to_string(),
        "singular: parameters v_1 and v_3 are equal (both 1/3); the matrix B_V has two equal \
         rows, and a surface cannot interpolate two columns of data at one parameter"
    );
    let e = interpolate_bezier_surface(&[q!(1), q!(0), q!(1)], &notes_v(), &data).unwrap_err();
    assert!(e
        .to_string()
        .starts_with("singular: parameters u_0 and u_2 are equal (both 1)"));
    // Rows and columns swapped.
    let e = interpolate_bezier_surface(&notes_v(), &notes_u(), &data).unwrap_err();
    assert_eq!(
        e.to_string(),
        "the data grid has 3 rows and 4 columns, but 4 parameters u_i and 3 parameters v_j were \
         given: row i of the data is c(u_i, v_0), ..., c(u_i, v_n), so give one u_i per row and \
         one v_j per column"
    );
    let mixed = Mesh::from_fn(2, 2, |i, j| {
        if (i, j) == (1, 0) {
            Point::from_ints(&[1, 2])
        } else {
            Point::from_ints(&[0, 0, 0])
        }
    });
    let e = interpolate_bezier_surface(&[q!(0), q!(1)], &[q!(0), q!(1)], &mixed).unwrap_err();
    assert_eq!(
        e.to_string(),
        "data point a_1,0 (point 0 is a_0,0) has dimension 2, but data point 0 has dimension 3"
    );
    assert!(coordinate_matrices(&mixed).is_err());
    let empty: Mesh<Q> = Mesh::from_fn(0, 0, |_, _| Point::zero(3));
    assert_eq!(
        interpolate_bezier_surface(&[], &[], &empty).unwrap_err(),
        FitError::NoData
    );
}

#[test]
fn parameters_outside_the_unit_square_set_the_domain() {
    // u ∈ {1, 3} (decreasing order on purpose), v ∈ {0, 1, 2}: the domain is [1, 3] x [0, 2].
    let (u, v) = ([q!(3), q!(1)], [q!(0), q!(1), q!(2)]);
    let data = Mesh::from_fn(2, 3, |i, j| {
        Point::new(vec![
            u[i].clone(),
            v[j].clone(),
            u[i].clone() * &v[j] * &v[j],
        ])
    });
    let s = interpolate_bezier_surface(&u, &v, &data).unwrap();
    assert_eq!(s.domain().to_text(), "[1, 3] x [0, 2]");
    // z = u v² is of bidegree (1, 2): reproduced everywhere.
    assert_eq!(
        s.eval(&q!(2), &q!(3 / 2)).unwrap().to_text(),
        "(2, 3/2, 9/2)"
    );
    // A single row: bidegree (0, n).
    let row = Mesh::mesh(vec![data.row(0).unwrap().to_vec()]).unwrap();
    let s = interpolate_bezier_surface(&[q!(1 / 2)], &v, &row).unwrap();
    assert_eq!(s.bidegree(), (0, 2));
    assert_eq!(
        s.eval(&q!(1 / 2), &q!(1)).unwrap(),
        data.get(0, 1).unwrap().clone()
    );
}

#[test]
fn quadratic_field_grid_interpolation() {
    // Data with √2 in them, at parameters 0, √2/2, 1 in u: exact over a + b√2.
    let n = |t: &str| parse_number(t).unwrap();
    let u = [n("0"), n("sqrt2/2"), n("1")];
    let v = [n("0"), n("1")];
    let data: Mesh<Quadratic> = Mesh::from_fn(3, 2, |i, j| {
        Point::new(vec![
            u[i].clone(),
            v[j].clone(),
            u[i].clone() * &u[i] + &v[j],
        ])
    });
    let s = interpolate_bezier_surface(&u, &v, &data).unwrap();
    for ((i, j), a) in data.indexed() {
        assert_eq!(&s.eval(&u[i], &v[j]).unwrap(), a);
    }
    // z = u² + v is in the space: the middle row of the mesh is (1/2, v, v).
    assert_eq!(
        s.to_text(),
        "{(0, 0, 0), (0, 1, 1); (1/2, 0, 0), (1/2, 1, 1); (1, 0, 1), (1, 1, 2)}"
    );
    let t = n("sqrt2/3");
    assert_eq!(
        s.eval(&t, &n("1/2")).unwrap(),
        Point::new(vec![t.clone(), n("1/2"), t.clone() * &t + n("1/2")])
    );
}

#[test]
fn f64_grid_interpolation_agrees_with_the_exact_one() {
    let exact = interpolate_bezier_surface(&notes_u(), &notes_v(), &notes_data()).unwrap();
    let to_f64 = |m: &Mesh<Q>| m.map(|p| Point::new(p.to_f64()));
    let u: Vec<f64> = notes_u().iter().map(ExactRational::to_f64).collect();
    let v: Vec<f64> = notes_v().iter().map(ExactRational::to_f64).collect();
    let approx = interpolate_bezier_surface(&u, &v, &to_f64(&notes_data())).unwrap();
    for ((i, j), p) in approx.mesh().indexed() {
        let e = exact.mesh().get(i, j).unwrap().to_f64();
        for (x, y) in p.coords().iter().zip(e) {
            assert!((x - y).abs() < 1e-12, "c_{i},{j}: {x} vs {y}");
        }
    }
}

/// Grid sizes m + 1 in 1..=3, n + 1 in 1..=4, parameters anywhere (sorted or reversed), data
/// in R^3.
fn grid_data() -> impl Strategy<Value = (Vec<Q>, Vec<Q>, Mesh<Q>)> {
    (1usize..=3, 1usize..=4, any::<bool>()).prop_flat_map(|(r, c, reversed)| {
        (increasing(r), increasing(c), grid(r, c, 3)).prop_map(move |(mut u, v, data)| {
            if reversed {
                u.reverse();
            }
            (u, v, data)
        })
    })
}

fn local<S: Scalar>(s: &BezierSurface<S>, u: &S, v: &S) -> (S, S) {
    s.domain().local(u, v)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn grid_interpolant_passes_through_every_data_point((u, v, data) in grid_data()) {
        let rows = bezier_in_passes(&u, &v, &data, PassOrder::RowsFirst).unwrap();
        let columns =
            bezier_in_passes(&u, &v, &data, PassOrder::ColumnsFirst).unwrap();
        prop_assert_eq!(&rows.surface, &columns.surface);
        let s = &rows.surface;
        prop_assert_eq!(s.bidegree(), (u.len() - 1, v.len() - 1));
        for ((i, j), a) in data.indexed() {
            let (su, tv) = local(s, &u[i], &v[j]);
            prop_assert_eq!(&bernstein_double_sum(s.mesh(), &su, &tv), a);
            prop_assert_eq!(&s.eval(&u[i], &v[j]).unwrap(), a);
        }
        // The matrix form (27) and both intermediate meshes: C̃ = B_U C, Ĉ = C B_Vᵗ.
        let c = coordinate_matrices(s.mesh()).unwrap();
        let a = coordinate_matrices(&data).unwrap();
        let tilde = coordinate_matrices(&rows.intermediate).unwrap();
        let hat = coordinate_matrices(&columns.intermediate).unwrap();
        let bvt: Matrix<Q> = rows.matrix_v.transpose();
        for k in 0..3 {
            prop_assert_eq!(&rows.matrix_u.mul(&c[k]).unwrap(), &tilde[k]);
            prop_assert_eq!(&c[k].mul(&bvt).unwrap(), &hat[k]);
            prop_assert_eq!(&tilde[k].mul(&bvt).unwrap(), &a[k]);
        }
    }
}
