//! Curves: every fit checked exactly against an independent route (De Boor evaluation, Bézier
//! pieces and their derivatives, Bernstein sums).

use cagd_bezier::{bernstein_sum, BezierCurve};
use cagd_bspline::{bezier_pieces, BSplineCurve, KnotVector};
use cagd_fit::{
    approximate_bezier, approximate_bspline, bernstein_matrix, bessel_tangents, bspline_matrix,
    cubic_spline_system, end_derivative_system, interpolate_bezier,
    interpolate_bspline_end_derivatives, interpolate_cubic_spline, EndCondition, EndConditions,
    FitError,
};
use cagd_linalg::{Matrix, Point};
use cagd_scalar::{q, ExactRational, FieldOps, Quadratic};
use proptest::prelude::*;

use crate::common::{increasing, p2, point, texts, Q};

/// Knots u_0 < ... < u_N and data a_0, ..., a_N in the plane, N in 1..=max.
fn spline_data(max: usize) -> impl Strategy<Value = (Vec<Q>, Vec<Point<Q>>)> {
    (2..=max + 1).prop_flat_map(|n| (increasing(n), prop::collection::vec(point(2), n)))
}

/// Evaluates a B-spline on its Bézier pieces (knot insertion + Bernstein sums), a route
/// independent of De Boor's algorithm and of the basis functions that built the system.
fn eval_by_pieces(c: &BSplineCurve<Q>, t: &Q) -> Point<Q> {
    let pieces = bezier_pieces(c.knots(), c.points()).unwrap();
    let piece = pieces
        .iter()
        .find(|p| p.interval.0 <= *t && *t <= p.interval.1)
        .unwrap();
    let (a, b) = &piece.interval;
    bernstein_sum(&piece.points, &((t.clone() - a) / (b.clone() - a))).unwrap()
}

/// The derivative of order r at an end of a B-spline (start or end), from its first or last
/// Bézier piece.
fn end_derivative(c: &BSplineCurve<Q>, at_end: bool, r: usize) -> Point<Q> {
    let pieces = bezier_pieces(c.knots(), c.points()).unwrap();
    let piece = if at_end {
        pieces.last()
    } else {
        pieces.first()
    }
    .unwrap();
    let (a, b) = piece.interval.clone();
    let bez = BezierCurve::try_new(piece.points.clone())
        .unwrap()
        .with_domain(a.clone(), b.clone())
        .unwrap();
    bez.derivative(r)
        .eval(if at_end { &b } else { &a })
        .unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    #[test]
    fn bezier_interpolant_passes_through_the_data(
        (params, points, reversed) in (1usize..=5).prop_flat_map(|n| (
            increasing(n),
            prop::collection::vec(point(3), n),
            any::<bool>(),
        ))
    ) {
        // The parameters need not be sorted, nor lie in [0, 1].
        let params: Vec<Q> = if reversed { params.into_iter().rev().collect() } else { params };
        let c = interpolate_bezier(&params, &points).unwrap();
        prop_assert_eq!(c.degree(), points.len() - 1);
        for (u, a) in params.iter().zip(&points) {
            prop_assert_eq!(&c.eval(u).unwrap(), a);
            // Independent route: the Bernstein sum at the local parameter.
            let local = c.local_parameter(u);
            prop_assert_eq!(&bernstein_sum(c.points(), &local).unwrap(), a);
        }
    }

    #[test]
    fn bezier_least_squares_recovers_a_curve_of_its_space(
        (control, params) in (0usize..=3).prop_flat_map(|n| (
            prop::collection::vec(point(2), n + 1),
            (n + 1..=n + 4).prop_flat_map(increasing),
        ))
    ) {
        // Data sampled from a curve of degree n are fitted by that curve, exactly. The
        // parameters are moved into [0, 1): (u_i - u_0) / (u_last - u_0 + 1).
        let width = params[params.len() - 1].clone() - &params[0] + q!(1);
        let params: Vec<Q> = params.iter().map(|u| (u.clone() - &params[0]) / &width).collect();
        let data: Vec<Point<Q>> =
            params.iter().map(|u| bernstein_sum(&control, u).unwrap()).collect();
        let c = approximate_bezier(control.len() - 1, &params, &data).unwrap();
        prop_assert_eq!(c.points(), &control[..]);
    }

    #[test]
    fn bezier_least_squares_with_n_plus_one_points_is_the_interpolant(
        (params, points) in (1usize..=5).prop_flat_map(|n| (
            increasing(n),
            prop::collection::vec(point(2), n),
        ))
    ) {
        let ls = approximate_bezier(points.len() - 1, &params, &points).unwrap();
        let interp = interpolate_bezier(&params, &points).unwrap();
        prop_assert_eq!(ls, interp);
    }

    #[test]
    fn bezier_least_squares_residual_is_orthogonal(
        (params, points, degree) in (3usize..=6).prop_flat_map(|m| (
            increasing(m),
            prop::collection::vec(point(2), m),
            0..m.min(3),
        ))
    ) {
        // B^t (B C - A) = 0: the residual is orthogonal to every Bernstein column.
        let c = approximate_bezier(degree, &params, &points).unwrap();
        let residual: Vec<Point<Q>> = params
            .iter()
            .zip(&points)
            .map(|(u, a)| &c.eval(u).unwrap() - a)
            .collect();
        let local: Vec<Q> = params.iter().map(|u| c.local_parameter(u)).collect();
        let b = bernstein_matrix(degree, &local);
        for j in 0..=degree {
            let column: Vec<Q> = (0..b.rows()).map(|i| b.get(i, j).clone()).collect();
            prop_assert!(Point::combination(&residual, &column, 2).is_zero());
        }
    }

    #[test]
    fn bspline_interpolant_with_end_derivatives_holds_exactly(
        ((params, points), d0, dn, extra) in (spline_data(5), point(2), point(2), 0usize..=5)
    ) {
        // Every degree that fits: 2..=n + 2 for the n + 1 points.
        let degree = 2 + extra % points.len();
        let c = interpolate_bspline_end_derivatives(degree, &params, &points, &d0, &dn).unwrap();
        prop_assert_eq!(c.degree(), degree);
        prop_assert_eq!(c.points().len(), points.len() + 2);
        for (t, q) in params.iter().zip(&points) {
            prop_assert_eq!(&c.eval(t).unwrap(), q);
            prop_assert_eq!(&eval_by_pieces(&c, t), q);
        }
        prop_assert_eq!(end_derivative(&c, false, 1), d0);
        prop_assert_eq!(end_derivative(&c, true, 1), dn);
    }

    #[test]
    fn spline_interpolant_passes_through_the_data(
        ((knots, points), m0, mn, kind) in (spline_data(5), point(2), point(2), 0usize..3)
    ) {
        prop_assume!(kind != 2 || knots.len() >= 3);
        let ends = match kind {
            0 => EndConditions::natural(),
            1 => EndConditions::clamped(m0.clone(), mn.clone()),
            _ => EndConditions::bessel(),
        };
        let c = interpolate_cubic_spline(&knots, &points, &ends).unwrap();
        prop_assert_eq!(c.degree(), 3);
        prop_assert_eq!(c.points().len(), points.len() + 2);
        for (u, a) in knots.iter().zip(&points) {
            prop_assert_eq!(&c.eval(u).unwrap(), a);
            prop_assert_eq!(&eval_by_pieces(&c, u), a);
        }
        match kind {
            0 => {
                prop_assert!(end_derivative(&c, false, 2).is_zero());
                prop_assert!(end_derivative(&c, true, 2).is_zero());
            }
            1 => {
                prop_assert_eq!(end_derivative(&c, false, 1), m0);
                prop_assert_eq!(end_derivative(&c, true, 1), mn);
            }
            _ => {
                // The parabolas through the first and last three points, by Bézier
                // interpolation: their derivatives at the ends are the spline's.
                let n = knots.len();
                let first = interpolate_bezier(&knots[..3], &points[..3]).unwrap();
                let last = interpolate_bezier(&knots[n - 3..], &points[n - 3..]).unwrap();
                let f0 = first.derivative(1).eval(&knots[0]).unwrap();
                let fn_ = last.derivative(1).eval(&knots[n - 1]).unwrap();
                prop_assert_eq!(end_derivative(&c, false, 1), f0);
                prop_assert_eq!(end_derivative(&c, true, 1), fn_);
            }
        }
    }

    #[test]
    fn bspline_least_squares_with_as_many_points_reproduces_the_interpolant(
        (knots, points) in spline_data(4)
    ) {
        // The natural spline interpolant, sampled at the knots and at the midpoints of the
        // first and last spans (N + 3 parameters, one in each support: Schoenberg–Whitney).
        let c = interpolate_cubic_spline(&knots, &points, &EndConditions::natural()).unwrap();
        // With one span (N = 1), its thirds.
        let n = knots.len();
        let at = |i: usize, k: i64, d: i64| {
            knots[i].clone() + (knots[i + 1].clone() - &knots[i]) * Q::from_ratio(k, d)
        };
        let mut params = knots.clone();
        if n == 2 {
            params.insert(1, at(0, 1, 3));
            params.insert(2, at(0, 2, 3));
        } else {
            params.insert(1, at(0, 1, 2));
            params.insert(n, at(n - 2, 1, 2));
        }
        let data: Vec<Point<Q>> = params.iter().map(|u| c.eval(u).unwrap()).collect();
        let ls = approximate_bspline(c.knots(), &params, &data).unwrap();
        prop_assert_eq!(ls.points(), c.points());
    }
}

/// The notes, chapter 5, section 7: the bidegree (2, 3) surface through twelve points, built
/// as the notes suggest: interpolate each row in v, then each column of the result in u.
#[test]
fn notes_bidegree_two_three_by_curve_interpolation() {
    let a: [[[Q; 3]; 4]; 3] = [
        [
            [q!(0), q!(0), q!(0)],
            [q!(1), q!(0), q!(1)],
            [q!(2), q!(0), q!(0)],
            [q!(3), q!(0), q!(-1)],
        ],
        [
            [q!(0), q!(1), q!(1)],
            [q!(1), q!(1), q!(2)],
            [q!(2), q!(1), q!(1)],
            [q!(3), q!(1), q!(1 / 2)],
        ],
        [
            [q!(0), q!(2), q!(0)],
            [q!(1), q!(2), q!(1)],
            [q!(2), q!(2), q!(0)],
            [q!(3), q!(2), q!(-2)],
        ],
    ];
    let us = [q!(0), q!(1 / 2), q!(1)];
    let vs = [q!(0), q!(1 / 3), q!(2 / 3), q!(1)];
    let rows: Vec<Vec<Point<Q>>> = a
        .iter()
        .map(|row| {
            let pts: Vec<Point<Q>> = row.iter().map(|c| Point::new(c.to_vec())).collect();
            interpolate_bezier(&vs, &pts).unwrap().into_points()
        })
        .collect();
    let mesh: Vec<Vec<String>> = (0..4)
        .map(|j| {
            let column: Vec<Point<Q>> = rows.iter().map(|r| r[j].clone()).collect();
            texts(interpolate_bezier(&us, &column).unwrap().points())
        })
        .collect();
    // mesh[j][i] = c_{i,j}.
    let expected = [
        ["(0, 0, 0)", "(0, 1, 2)", "(0, 2, 0)"],
        ["(1, 0, 8/3)", "(1, 1, 31/6)", "(1, 2, 7/3)"],
        ["(2, 0, -2/3)", "(2, 1, 1/12)", "(2, 2, 1/6)"],
        ["(3, 0, -1)", "(3, 1, 5/2)", "(3, 2, -2)"],
    ];
    for j in 0..4 {
        assert_eq!(mesh[j], expected[j]);
    }
}

#[test]
fn bezier_interpolation_errors() {
    let pts: Vec<Point<Q>> = (0..4).map(|i| Point::from_ints(&[i, i * i])).collect();
    let e = interpolate_bezier(&[q!(0), q!(1 / 3), q!(1), q!(1 / 3)], &pts).unwrap_err();
    assert_eq!(
        e,
        FitError::RepeatedParameter {
            first: 1,
            second: 3,
            value: "1/3".into()
        }
    );
    assert!(e
        .to_string()
        .starts_with("singular: parameters u_1 and u_3 are equal (both 1/3)"));
    let e = interpolate_bezier(&[q!(0), q!(1)], &pts).unwrap_err();
    assert_eq!(
        e.to_string(),
        "4 data points but 2 parameters: give one parameter per point"
    );
    let mixed = vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 1, 1])];
    let e = interpolate_bezier(&[q!(0), q!(1)], &mixed).unwrap_err();
    assert_eq!(
        e.to_string(),
        "data point 1 has dimension 3, but data point 0 has dimension 2"
    );
    assert_eq!(
        interpolate_bezier::<Q>(&[], &[]).unwrap_err(),
        FitError::NoData
    );
}

#[test]
fn bezier_domain_follows_the_parameters() {
    // Parameters outside [0, 1]: the domain is [min, max] and the curve still interpolates.
    let pts = vec![p2(q!(0), q!(0)), p2(q!(1), q!(2)), p2(q!(2), q!(0))];
    let c = interpolate_bezier(&[q!(0), q!(1), q!(2)], &pts).unwrap();
    assert_eq!(c.domain(), (&q!(0), &q!(2)));
    assert_eq!(texts(c.points()), ["(0, 0)", "(1, 4)", "(2, 0)"]);
    // A single point is the constant curve of degree 0.
    let c = interpolate_bezier(&[q!(1 / 2)], &pts[1..2]).unwrap();
    assert_eq!(c.degree(), 0);
    assert_eq!(c.eval(&q!(1 / 2)).unwrap(), pts[1]);
}

#[test]
fn bezier_least_squares_errors_name_the_cause() {
    let pts: Vec<Point<Q>> = (0..3).map(|i| Point::from_ints(&[i, 1 - i])).collect();
    let e = approximate_bezier(3, &[q!(0), q!(1 / 2), q!(1)], &pts).unwrap_err();
    assert_eq!(
        e.to_string(),
        "least squares of degree 3 (4 unknown control points) needs at least 4 data points, found 3"
    );
    let e = approximate_bezier(2, &[q!(0), q!(1), q!(1)], &pts).unwrap_err();
    assert_eq!(
        e,
        FitError::TooFewDistinctParameters {
            degree: 2,
            found: 2
        }
    );
    assert!(e
        .to_string()
        .contains("needs at least 3 distinct parameters, found 2"));
}

/// Hand-checked: the line closest to four points (the regression line).
#[test]
fn bezier_least_squares_line_by_hand() {
    // y at u = 0, 1/3, 2/3, 1 is 0, 1, 1, 3: mean u 1/2, mean y 5/4, slope
    // Σ(u - 1/2)(y - 5/4) / Σ(u - 1/2)² = (3/2) / (5/9) = 27/10, so
    // c_0 = 5/4 - 27/20 = -1/10 and c_1 = c_0 + 27/10 = 13/5.
    let params = [q!(0), q!(1 / 3), q!(2 / 3), q!(1)];
    let pts: Vec<Point<Q>> = [0, 1, 1, 3]
        .iter()
        .map(|&y| Point::new(vec![Q::from_i64(y)]))
        .collect();
    let c = approximate_bezier(1, &params, &pts).unwrap();
    assert_eq!(texts(c.points()), ["(-1/10)", "(13/5)"]);
}

/// Hand-checked: the natural spline through (0, 0), (1, 1), (2, 0) at u = 0, 1, 2 (uniform
/// cubic, by symmetry d_1 = (1/3, α), d_2 = (1, β), with α/2 + β/2 = 1 and β = 3α).
#[test]
fn natural_spline_by_hand() {
    let pts = vec![p2(q!(0), q!(0)), p2(q!(1), q!(1)), p2(q!(2), q!(0))];
    let knots = [q!(0), q!(1), q!(2)];
    let system = cubic_spline_system(&knots, &pts, &EndConditions::natural()).unwrap();
    let (vector, matrix, rhs) = (system.knots, system.matrix, system.rhs);
    assert_eq!(vector.to_text(), "{0, 0, 0, 1, 2, 2, 2}");
    // Rows: c''(0) = 0; c(0), c(1), c(2); c''(2) = 0.
    assert_eq!(
        matrix.to_text(),
        "6  -9  3  0  0\n1  0  0  0  0\n0  1/4  1/2  1/4  0\n0  0  0  0  1\n0  0  3  -9  6"
    );
    assert_eq!(
        texts(&rhs),
        ["(0, 0)", "(0, 0)", "(1, 1)", "(2, 0)", "(0, 0)"]
    );
    let c = interpolate_cubic_spline(&knots, &pts, &EndConditions::natural()).unwrap();
    assert_eq!(
        texts(c.points()),
        ["(0, 0)", "(1/3, 1/2)", "(1, 3/2)", "(5/3, 1/2)", "(2, 0)"]
    );
}

/// Clamped and mixed ends, by hand: at a clamped end d_1 = a_0 + (Δ_0 / 3) m_0.
#[test]
fn clamped_and_mixed_ends() {
    let pts = vec![p2(q!(0), q!(0)), p2(q!(1), q!(1)), p2(q!(3), q!(0))];
    let knots = [q!(0), q!(1 / 2), q!(2)];
    let m0 = p2(q!(3), q!(0));
    let ends = EndConditions {
        start: EndCondition::Tangent(m0.clone()),
        end: EndCondition::Natural,
    };
    let c = interpolate_cubic_spline(&knots, &pts, &ends).unwrap();
    assert_eq!(c.points()[1], p2(q!(1 / 2), q!(0)));
    assert_eq!(end_derivative(&c, false, 1), m0);
    assert!(end_derivative(&c, true, 2).is_zero());
    let e = interpolate_cubic_spline(
        &knots,
        &pts,
        &EndConditions::clamped(m0.clone(), Point::from_ints(&[1, 2, 3])),
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "the end tangent has dimension 3, but data point 0 has dimension 2"
    );
}

/// Data on a parabola: the Bessel tangents are the parabola's, and the spline is the parabola.
#[test]
fn bessel_spline_reproduces_a_parabola() {
    let f = |u: &Q| p2(u.clone(), u.clone() * u - u * q!(1 / 2));
    let knots = [q!(-1), q!(0), q!(1 / 3), q!(2), q!(5 / 2)];
    let pts: Vec<Point<Q>> = knots.iter().map(f).collect();
    let (m0, mn) = bessel_tangents(&knots, &pts).unwrap();
    // f'(u) = (1, 2u - 1/2).
    assert_eq!(m0, p2(q!(1), q!(-5 / 2)));
    assert_eq!(mn, p2(q!(1), q!(9 / 2)));
    let c = interpolate_cubic_spline(&knots, &pts, &EndConditions::bessel()).unwrap();
    for t in [q!(-1), q!(-1 / 2), q!(1 / 7), q!(1), q!(9 / 4), q!(5 / 2)] {
        assert_eq!(c.eval(&t).unwrap(), f(&t));
    }
    // Linear data: the natural spline is the line itself.
    let line: Vec<Point<Q>> = knots
        .iter()
        .map(|u| p2(u.clone(), u * q!(3) + q!(1)))
        .collect();
    let c = interpolate_cubic_spline(&knots, &line, &EndConditions::natural()).unwrap();
    assert_eq!(c.eval(&q!(1 / 5)).unwrap(), p2(q!(1 / 5), q!(8 / 5)));
}

#[test]
fn spline_errors_name_the_cause() {
    let pts = vec![p2(q!(0), q!(0)), p2(q!(1), q!(1)), p2(q!(3), q!(0))];
    let e = interpolate_cubic_spline(
        &[q!(0), q!(1 / 2), q!(1 / 2)],
        &pts,
        &EndConditions::natural(),
    )
    .unwrap_err();
    assert_eq!(
        e.to_string(),
        "the knots must increase strictly: u_2 = 1/2 is not greater than u_1 = 1/2"
    );
    let e =
        interpolate_cubic_spline(&[q!(0), q!(1)], &pts[..2], &EndConditions::bessel()).unwrap_err();
    assert_eq!(
        e.to_string(),
        "a Bessel end tangent (the parabola through three points) needs at least 3 data points, found 2"
    );
    let e = interpolate_cubic_spline(&[q!(0)], &pts[..1], &EndConditions::natural()).unwrap_err();
    assert!(
        e.to_string()
            .contains("needs at least 2 data points, found 1"),
        "{e}"
    );
    // Two points with natural ends: the segment, uniformly parametrized.
    let c =
        interpolate_cubic_spline(&[q!(0), q!(1)], &pts[..2], &EndConditions::natural()).unwrap();
    assert_eq!(c.eval(&q!(1 / 4)).unwrap(), p2(q!(1 / 4), q!(1 / 4)));
}

#[test]
fn bspline_least_squares_errors_name_the_cause() {
    let u = KnotVector::clamped(2, &[q!(0), q!(1), q!(2), q!(3)]).unwrap();
    let pts: Vec<Point<Q>> = (0..5).map(|i| Point::from_ints(&[i, 0])).collect();
    let e = approximate_bspline(&u, &[q!(0), q!(1)], &pts[..2]).unwrap_err();
    assert_eq!(
        e.to_string(),
        "least squares with 5 unknown control points (degree 2) needs at least 5 data points, found 2"
    );
    // Every parameter in [0, 1]: N_3 (support [1, 3]) vanishes at all of them, so d_3 is not
    // determined (nor is d_4).
    let params = [q!(0), q!(1 / 4), q!(1 / 2), q!(3 / 4), q!(1)];
    let e = approximate_bspline(&u, &params, &pts).unwrap_err();
    assert_eq!(
        e.to_string(),
        "control point d_3 is not determined: no parameter lies in the support [1, 3] of its \
         basis function N_3"
    );
    // Five parameters, one in each support in order (Schoenberg–Whitney): the interpolant.
    let params = [q!(0), q!(1 / 2), q!(1), q!(5 / 2), q!(3)];
    let c = approximate_bspline(&u, &params, &pts).unwrap();
    for (t, a) in params.iter().zip(&pts) {
        assert_eq!(&c.eval(t).unwrap(), a);
    }
    // Every function is reached, but the repeated parameter 2 leaves four distinct parameters
    // for five coefficients: the normal matrix is singular.
    let params = [q!(0), q!(1 / 2), q!(2), q!(2), q!(3)];
    let e = approximate_bspline(&u, &params, &pts).unwrap_err();
    assert!(
        e.to_string().contains("the normal matrix BᵗB is singular"),
        "{e}"
    );
    let e = approximate_bspline(&u, &[q!(0), q!(1), q!(2), q!(3), q!(4)], &pts).unwrap_err();
    assert_eq!(
        e.to_string(),
        "parameter u_4 = 4 is outside the domain [0, 3] of the knot vector"
    );
}

#[test]
fn bspline_end_derivative_errors_name_the_cause() {
    let t = [q!(0), q!(1), q!(2)];
    let a = [p2(q!(0), q!(0)), p2(q!(1), q!(1)), p2(q!(2), q!(0))];
    let d = p2(q!(1), q!(0));
    for degree in [1, 5] {
        let e = interpolate_bspline_end_derivatives(degree, &t, &a, &d, &d).unwrap_err();
        assert_eq!(
            e.to_string(),
            format!(
                "a B-spline interpolant with end derivatives through 3 data points has a degree \
                 from 2 to 4, found {degree}"
            )
        );
    }
    let e = interpolate_bspline_end_derivatives(3, &t, &a, &d, &Point::from_ints(&[1, 0, 0]))
        .unwrap_err();
    assert!(
        matches!(&e, FitError::DimensionMismatch { what, expected: 2, found: 3 } if *what == cagd_fit::Datum::EndDerivative),
        "{e}"
    );
    let e = interpolate_bspline_end_derivatives(2, &t[..1], &a[..1], &d, &d).unwrap_err();
    assert!(
        matches!(
            e,
            FitError::TooFewPoints {
                needed: 2,
                found: 1,
                ..
            }
        ),
        "{e}"
    );
    let e = interpolate_bspline_end_derivatives(2, &[q!(0), q!(2), q!(1)], &a, &d, &d).unwrap_err();
    assert!(matches!(e, FitError::NotIncreasing { index: 2, .. }), "{e}");
}

#[test]
fn bspline_end_derivative_system_by_hand() {
    // Quadratic through (0, 0), (1, 1), (2, 0) at 0, 1, 2: knots {0, 0, 0, 1/2, 3/2, 2, 2, 2}.
    let a = [p2(q!(0), q!(0)), p2(q!(1), q!(1)), p2(q!(2), q!(0))];
    let s = end_derivative_system(
        2,
        &[q!(0), q!(1), q!(2)],
        &a,
        &p2(q!(1), q!(1)),
        &p2(q!(1), q!(-1)),
    )
    .unwrap();
    assert_eq!(
        s.knots.full(),
        [
            q!(0),
            q!(0),
            q!(0),
            q!(1 / 2),
            q!(3 / 2),
            q!(2),
            q!(2),
            q!(2)
        ]
    );
    assert_eq!(
        s.matrix.to_text(),
        "1  0  0  0  0\n-1  1  0  0  0\n0  1/6  2/3  1/6  0\n0  0  0  -1  1\n0  0  0  0  1"
    );
    assert_eq!(
        texts(&s.rhs),
        ["(0, 0)", "(1/4, 1/4)", "(1, 1)", "(1/4, -1/4)", "(2, 0)"]
    );
}

#[test]
fn bspline_matrix_by_hand() {
    let u = KnotVector::clamped(3, &[q!(0), q!(1), q!(2), q!(3)]).unwrap();
    let b: Matrix<Q> = bspline_matrix(&u, &[q!(0), q!(1), q!(2), q!(3)]).unwrap();
    // Uniform interior knots with triple ends: N(1) = (0, 1/4, 7/12, 1/6, 0, 0).
    assert_eq!(
        b.to_text(),
        "1  0  0  0  0  0\n0  1/4  7/12  1/6  0  0\n0  0  1/6  7/12  1/4  0\n0  0  0  0  0  1"
    );
}

/// Over a + b√2: the unit circle's points at the parameters 0, 1/2, 1 of a parabola, exactly.
#[test]
fn quadratic_field_interpolation() {
    let r2 = Quadratic::sqrt_of(&q!(2)).unwrap();
    let h = r2.clone() * Quadratic::from_rational(q!(1 / 2));
    let z = Quadratic::from_rational(q!(0));
    let one = Quadratic::from_rational(q!(1));
    let pts = vec![
        Point::new(vec![one.clone(), z.clone()]),
        Point::new(vec![h.clone(), h.clone()]),
        Point::new(vec![z.clone(), one.clone()]),
    ];
    let params = [z.clone(), Quadratic::from_rational(q!(1 / 2)), one.clone()];
    let c = interpolate_bezier(&params, &pts).unwrap();
    assert_eq!(texts(c.points())[1], "(-1/2 + √2, -1/2 + √2)");
    for (u, a) in params.iter().zip(&pts) {
        assert_eq!(&c.eval(u).unwrap(), a);
    }
    let s = interpolate_cubic_spline(&params, &pts, &EndConditions::bessel()).unwrap();
    for (u, a) in params.iter().zip(&pts) {
        assert_eq!(&s.eval(u).unwrap(), a);
    }
}

/// Over f64 the same fits agree with the exact ones to rounding.
#[test]
fn f64_fits_agree_with_the_exact_ones() {
    let knots = [q!(0), q!(1 / 3), q!(1), q!(3 / 2), q!(2)];
    let pts: Vec<Point<Q>> = [[0, 1], [1, 3], [2, -1], [4, 0], [5, 2]]
        .iter()
        .map(|c| Point::from_ints(c))
        .collect();
    let exact = interpolate_cubic_spline(&knots, &pts, &EndConditions::bessel()).unwrap();
    let kf: Vec<f64> = knots.iter().map(ExactRational::to_f64).collect();
    let pf: Vec<Point<f64>> = pts.iter().map(|p| Point::new(p.to_f64())).collect();
    let float = interpolate_cubic_spline(&kf, &pf, &EndConditions::bessel()).unwrap();
    for (e, f) in exact.points().iter().zip(float.points()) {
        for (x, y) in e.to_f64().iter().zip(f.coords()) {
            assert!((x - y).abs() < 1e-9, "{e} vs {f:?}");
        }
    }
    let ls_exact = approximate_bezier(2, &knots, &pts).unwrap();
    let ls_float = approximate_bezier(2, &kf, &pf).unwrap();
    for (e, f) in ls_exact.points().iter().zip(ls_float.points()) {
        for (x, y) in e.to_f64().iter().zip(f.coords()) {
            assert!((x - y).abs() < 1e-9, "{e} vs {f:?}");
        }
    }
}
