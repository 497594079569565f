//! Bicubic B-spline interpolation of a grid: through every data point (De Boor in two passes,
//! independently of the surface type), both orders, reproduction of the functions each end
//! condition reproduces.

use cagd_bspline::de_boor;
use cagd_fit::{
    interpolate_bicubic_spline, interpolate_cubic_spline, Direction, EndCondition, EndConditions,
    FitError, PassOrder, SurfaceEndConditions,
};
use cagd_linalg::Point;
use cagd_scalar::{parse_number, q, FieldOps, Quadratic, Scalar};
use cagd_spline_surface::BSplineSurface;
use cagd_surface::Mesh;
use proptest::prelude::*;

use crate::common::{bicubic_in_passes, grid, increasing, sample, Q};

/// De Boor on every row in v, then on the resulting polygon in u, with `cagd_bspline::de_boor`
/// only (not the surface type's evaluator).
fn de_boor_two_passes<S: Scalar>(s: &BSplineSurface<S>, u: &S, v: &S) -> Point<S> {
    let polygon: Vec<Point<S>> = s
        .mesh()
        .to_rows()
        .iter()
        .map(|row| de_boor(s.knots_v(), row, v).unwrap())
        .collect();
    de_boor(s.knots_u(), &polygon, u).unwrap()
}

fn t012() -> Vec<Q> {
    vec![q!(0), q!(1), q!(2)]
}

#[test]
fn natural_ends_reproduce_a_bilinear_function() {
    // z = u v on {0, 1, 2}²: natural splines reproduce linear functions, so the mesh is
    // (ξ_i, ξ_j, ξ_i ξ_j) with the Greville abscissae ξ = 0, 1/3, 1, 5/3, 2 of the knots
    // {0, 0, 0, 1, 2, 2, 2}.
    let t = t012();
    let data = sample(&t, &t, |u, v| {
        Point::new(vec![u.clone(), v.clone(), u.clone() * v])
    });
    let steps = bicubic_in_passes(
        &t,
        &t,
        &data,
        &SurfaceEndConditions::natural(),
        PassOrder::RowsFirst,
    )
    .unwrap();
    let s = &steps.surface;
    assert_eq!(s.knots_u().to_text(), "{0, 0, 0, 1, 2, 2, 2}");
    assert_eq!(s.knots_v().to_text(), "{0, 0, 0, 1, 2, 2, 2}");
    assert_eq!(s.bidegree(), (3, 3));
    let xi = [q!(0), q!(1 / 3), q!(1), q!(5 / 3), q!(2)];
    let expected = sample(&xi, &xi, |a, b| {
        Point::new(vec![a.clone(), b.clone(), a.clone() * b])
    });
    assert_eq!(s.mesh(), &expected);
    assert_eq!(
        s.mesh().row(1).unwrap()[1].to_text(),
        "(1/3, 1/3, 1/9)",
        "d_1,1"
    );
    // The first pass: row i of d̃ is the natural spline through row i of the data.
    assert_eq!(
        (steps.intermediate.rows(), steps.intermediate.cols()),
        (3, 5)
    );
    let row1 =
        interpolate_cubic_spline(&t, data.row(1).unwrap(), &EndConditions::natural()).unwrap();
    assert_eq!(steps.intermediate.row(1).unwrap(), row1.points());
    // The system matrix of each spline: natural start c''(0) = 6 d_0 − 9 d_1 + 3 d_2 (the
    // first Bézier piece is d_0, d_1, (d_1 + d_2)/2), three interpolation rows (at the knot 1,
    // N_1, N_2, N_3 = 1/4, 1/2, 1/4), natural end.
    assert_eq!(
        steps.matrix_v.to_text(),
        "6  -9  3  0  0\n1  0  0  0  0\n0  1/4  1/2  1/4  0\n0  0  0  0  1\n0  0  3  -9  6"
    );
    assert_eq!(steps.matrix_u, steps.matrix_v);
    assert_eq!(
        s.eval(&q!(1 / 2), &q!(3 / 2)).unwrap().to_text(),
        "(1/2, 3/2, 3/4)"
    );
}

#[test]
fn bessel_ends_reproduce_a_biquadratic_function() {
    // Bessel ends reproduce quadratics in each direction, so z = u² v² is reproduced.
    let (u, v) = ([q!(0), q!(1), q!(3)], [q!(-1), q!(1 / 2), q!(1), q!(2)]);
    let f = |u: &Q, v: &Q| Point::new(vec![u.clone(), v.clone(), u.powi(2) * v.powi(2)]);
    let data = sample(&u, &v, f);
    let s = interpolate_bicubic_spline(&u, &v, &data, &SurfaceEndConditions::bessel()).unwrap();
    assert_eq!((s.mesh().rows(), s.mesh().cols()), (5, 6));
    assert_eq!(s.knots_v().to_text(), "{-1, -1, -1, 1/2, 1, 2, 2, 2}");
    for (a, b) in [
        (q!(1 / 2), q!(0)),
        (q!(2), q!(7 / 4)),
        (q!(5 / 2), q!(-1 / 3)),
    ] {
        assert_eq!(s.eval(&a, &b).unwrap(), f(&a, &b));
    }
}

#[test]
fn end_conditions_chosen_per_direction() {
    // Natural in u reproduces linear functions of u, Bessel in v quadratics of v: z = u v².
    let (u, v) = ([q!(0), q!(1), q!(2), q!(4)], [q!(0), q!(1), q!(3)]);
    let f = |u: &Q, v: &Q| Point::new(vec![u.clone() * v.powi(2)]);
    let data = sample(&u, &v, f);
    let ends = SurfaceEndConditions::new(EndConditions::natural(), EndConditions::bessel());
    let s = interpolate_bicubic_spline(&u, &v, &data, &ends).unwrap();
    let (a, b) = (q!(3), q!(1 / 2));
    assert_eq!(s.eval(&a, &b).unwrap(), f(&a, &b));
    // The other way round the quadratic in v is not reproduced (a natural spline through
    // v² has zero second derivative at the ends): the directions are not interchangeable.
    let swapped = SurfaceEndConditions::new(EndConditions::bessel(), EndConditions::natural());
    let t = interpolate_bicubic_spline(&u, &v, &data, &swapped).unwrap();
    assert_ne!(t.eval(&a, &b).unwrap(), f(&a, &b));
    for ((i, j), p) in data.indexed() {
        assert_eq!(&t.eval(&u[i], &v[j]).unwrap(), p);
    }
    // A natural start and a Bessel end in one direction.
    let mixed = SurfaceEndConditions::new(
        EndConditions {
            start: EndCondition::Natural,
            end: EndCondition::Bessel,
        },
        EndConditions::bessel(),
    );
    let m = interpolate_bicubic_spline(&u, &v, &data, &mixed).unwrap();
    for ((i, j), p) in data.indexed() {
        assert_eq!(&de_boor_two_passes(&m, &u[i], &v[j]), p);
    }
}

#[test]
fn spline_grid_errors_name_the_cause() {
    let t = t012();
    let data = sample(&t, &t, |u, v| Point::new(vec![u.clone(), v.clone()]));
    let clamped = SurfaceEndConditions::new(
        EndConditions::natural(),
        EndConditions::clamped(Point::from_ints(&[1, 0]), Point::from_ints(&[1, 0])),
    );
    let e = interpolate_bicubic_spline(&t, &t, &data, &clamped).unwrap_err();
    assert_eq!(
        e,
        FitError::ClampedSurfaceEnd {
            direction: Direction::V,
            at_end: false
        }
    );
    assert_eq!(
        e.to_string(),
        "a clamped start condition in v (one given tangent vector) does not apply to a surface: \
         every row of data would need its own tangent; use natural or Bessel ends"
    );
    let e = interpolate_bicubic_spline(
        &t,
        &[q!(0), q!(2), q!(1)],
        &data,
        &SurfaceEndConditions::natural(),
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "the parameters v_j of a spline interpolant must increase strictly: v_2 = 1 is not \
         greater than v_1 = 2"
    );
    let e = interpolate_bicubic_spline(
        &[q!(0), q!(0), q!(1)],
        &t,
        &data,
        &SurfaceEndConditions::natural(),
    )
    .unwrap_err();
    assert!(e
        .to_string()
        .contains("u_1 = 0 is not greater than u_0 = 0"));
    // Bessel ends need three parameters; natural ends only two.
    let two = sample(&[q!(0), q!(1)], &t, |u, v| {
        Point::new(vec![u.clone(), v.clone()])
    });
    let e = interpolate_bicubic_spline(&[q!(0), q!(1)], &t, &two, &SurfaceEndConditions::bessel())
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "a Bessel end in u (the parabola through three parameters u) needs at least 3 data \
         points, found 2"
    );
    let s = interpolate_bicubic_spline(&[q!(0), q!(1)], &t, &two, &SurfaceEndConditions::natural())
        .unwrap();
    assert_eq!((s.mesh().rows(), s.mesh().cols()), (4, 5));
    let e = interpolate_bicubic_spline(&t, &t, &two, &SurfaceEndConditions::natural()).unwrap_err();
    assert!(matches!(
        e,
        FitError::GridShape {
            rows: 2,
            cols: 3,
            ..
        }
    ));
}

#[test]
fn quadratic_and_f64_spline_grids() {
    // Data with √2, exact over a + b√2: z = u v reproduced by natural ends.
    let n = |t: &str| parse_number(t).unwrap();
    let u = [n("0"), n("sqrt2/2"), n("1")];
    let v = [n("0"), n("1"), n("3/2")];
    let data: Mesh<Quadratic> = Mesh::from_fn(3, 3, |i, j| Point::new(vec![u[i].clone() * &v[j]]));
    let s = interpolate_bicubic_spline(&u, &v, &data, &SurfaceEndConditions::natural()).unwrap();
    let (a, b) = (n("sqrt2/4"), n("1/3"));
    assert_eq!(s.eval(&a, &b).unwrap(), Point::new(vec![a.clone() * &b]));
    for ((i, j), p) in data.indexed() {
        assert_eq!(&de_boor_two_passes(&s, &u[i], &v[j]), p);
    }
    // f64 agrees with the exact mesh.
    let t = t012();
    let exact_data = sample(&t, &t, |u, v| Point::new(vec![u.clone() * v + u.powi(2)]));
    let exact =
        interpolate_bicubic_spline(&t, &t, &exact_data, &SurfaceEndConditions::bessel()).unwrap();
    let tf = [0.0, 1.0, 2.0];
    let approx_data = exact_data.map(|p| Point::new(p.to_f64()));
    let approx =
        interpolate_bicubic_spline(&tf, &tf, &approx_data, &SurfaceEndConditions::bessel())
            .unwrap();
    for ((i, j), p) in approx.mesh().indexed() {
        let e = exact.mesh().get(i, j).unwrap().to_f64();
        assert!((p.coords()[0] - e[0]).abs() < 1e-12);
    }
}

/// Grids of 2..=4 by 2..=4 points in the plane, increasing parameters, and end conditions per
/// direction (Bessel only with three parameters or more).
fn spline_grid_data() -> impl Strategy<Value = (Vec<Q>, Vec<Q>, Mesh<Q>, SurfaceEndConditions<Q>)> {
    (2usize..=4, 2usize..=4, 0usize..4).prop_flat_map(|(r, c, kind)| {
        (increasing(r), increasing(c), grid(r, c, 2)).prop_map(move |(u, v, data)| {
            let pick = |bessel: bool, count: usize| {
                if bessel && count >= 3 {
                    EndConditions::bessel()
                } else {
                    EndConditions::natural()
                }
            };
            let ends = SurfaceEndConditions::new(pick(kind & 1 == 1, r), pick(kind & 2 == 2, c));
            (u, v, data, ends)
        })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn spline_interpolant_passes_through_every_data_point(
        (u, v, data, ends) in spline_grid_data()
    ) {
        let rows =
            bicubic_in_passes(&u, &v, &data, &ends, PassOrder::RowsFirst).unwrap();
        let columns =
            bicubic_in_passes(&u, &v, &data, &ends, PassOrder::ColumnsFirst)
                .unwrap();
        prop_assert_eq!(&rows.surface, &columns.surface);
        let s = &rows.surface;
        prop_assert_eq!((s.mesh().rows(), s.mesh().cols()), (u.len() + 2, v.len() + 2));
        prop_assert_eq!(
            (columns.intermediate.rows(), columns.intermediate.cols()),
            (u.len() + 2, v.len())
        );
        for ((i, j), a) in data.indexed() {
            prop_assert_eq!(&de_boor_two_passes(s, &u[i], &v[j]), a);
            prop_assert_eq!(&s.eval(&u[i], &v[j]).unwrap(), a);
        }
        // Each row of the first pass is the curve interpolant of that row.
        let row0 = interpolate_cubic_spline(&v, data.row(0).unwrap(), &ends.v).unwrap();
        prop_assert_eq!(rows.intermediate.row(0).unwrap(), row0.points());
    }
}
