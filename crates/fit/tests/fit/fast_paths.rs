//! The fast exact paths of the short forms (`interpolate_bezier_surface`,
//! `approximate_bezier_surface`: integer matrices, the Bernstein–Vandermonde inverse, integer
//! normal equations solved fraction-free or modulo primes) against the step-by-step functions
//! (one `Factorization` per direction, `NormalEquations`), on random rational data.

use cagd_fit::{approximate_bezier_surface, interpolate_bezier_surface, PassOrder};
use cagd_linalg::Point;
use cagd_scalar::{ExactRational, FieldOps, Rat};
use proptest::prelude::*;

use crate::common::{
    bezier_in_passes, grid, increasing, normal_equations, point, unit_rational, Q,
};

/// Distinct parameters in any order: increasing ones, reversed half of the time.
fn parameters(count: usize) -> impl Strategy<Value = Vec<Q>> {
    (increasing(count), any::<bool>()).prop_map(|(mut u, rev)| {
        if rev {
            u.reverse();
        }
        u
    })
}

fn grid_data() -> impl Strategy<Value = (Vec<Q>, Vec<Q>, cagd_surface::Mesh<Q>)> {
    (1usize..=5, 1usize..=5).prop_flat_map(|(r, c)| (parameters(r), parameters(c), grid(r, c, 3)))
}

/// Bidegree (m, n), parameters and points of a least-squares problem.
type Scattered = (usize, usize, Vec<(Q, Q)>, Vec<Point<Q>>);

fn scattered() -> impl Strategy<Value = Scattered> {
    (0usize..=2, 0usize..=2, 0usize..=6).prop_flat_map(|(m, n, extra)| {
        let count = (m + 1) * (n + 1) + 1 + extra;
        (
            Just(m),
            Just(n),
            prop::collection::vec((unit_rational(), unit_rational()), count),
            prop::collection::vec(point(3), count),
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    #[test]
    fn grid_interpolation_equals_the_two_passes((u, v, data) in grid_data()) {
        let fast = interpolate_bezier_surface(&u, &v, &data).unwrap();
        let steps = bezier_in_passes(&u, &v, &data, PassOrder::RowsFirst).unwrap();
        prop_assert_eq!(&fast, &steps.surface);
    }

    #[test]
    fn least_squares_equals_the_normal_equations((m, n, params, points) in scattered()) {
        // the same answer, or the same error when the data do not determine the patch
        let fast = approximate_bezier_surface(m, n, &params, &points);
        let steps = normal_equations(m, n, &params, &points).map(|s| s.surface);
        prop_assert_eq!(fast, steps);
    }

    #[test]
    fn least_squares_on_machine_word_rationals_equals_the_normal_equations(
        (m, n, params, points) in scattered(),
        wide in any::<bool>(),
    ) {
        // the same over `Rat` (parameters read from its machine words), with parameters of
        // large denominators half of the time (β then overflows i128: the big rows)
        let rat = |x: &Q| Rat::from_rational(x);
        let scale = Q::from_ratio(1, 1_000_000_007);
        let params: Vec<(Rat, Rat)> = params
            .iter()
            .map(|(u, v)| {
                let u = if wide { u * (Q::from_i64(1) - &scale) } else { u.clone() };
                (rat(&u), rat(v))
            })
            .collect();
        let points: Vec<Point<Rat>> = points
            .iter()
            .map(|p| Point::new(p.coords().iter().map(rat).collect()))
            .collect();
        let fast = approximate_bezier_surface(m, n, &params, &points);
        let steps = normal_equations(m, n, &params, &points).map(|s| s.surface);
        prop_assert_eq!(fast, steps);
    }
}

#[test]
fn large_least_squares_goes_modulo_primes_and_stays_exact() {
    // bidegree (3, 3) from 30 points with denominators 5, 7, 8, 9: the common denominator of
    // B is (2^6 3^4 5^2 7^2)^3, the normal matrix has entries of about 140 bits and Hadamard's
    // bound is above 2^1500, so the integer normal equations are solved modulo primes
    let mut params = Vec::new();
    let mut points = Vec::new();
    let dens = [5, 7, 8, 9];
    for k in 0..30i64 {
        let i = usize::try_from(k).unwrap();
        let (q, s) = (dens[i % 4], dens[(i / 4) % 4]);
        let (p, r) = ((k * 3) % (q + 1), (k * 5) % (s + 1));
        params.push((Q::from_ratio(p, q), Q::from_ratio(r, s)));
        points.push(Point::new(vec![
            Q::from_ratio(k % 19 - 9, 1 + k % 9),
            Q::from_ratio(k % 5, 7),
            Q::from_ratio(2 - k % 4, 3),
        ]));
    }
    let fast = approximate_bezier_surface(3, 3, &params, &points).unwrap();
    let steps = normal_equations(3, 3, &params, &points).unwrap();
    assert_eq!(fast, steps.surface);
}

/// Parameters and points of a least-squares curve of degree `degree` (more points than control
/// points, at least degree + 1 distinct parameters).
fn curve_data() -> impl Strategy<Value = (usize, Vec<Q>, Vec<Point<Q>>)> {
    (0usize..=4, 1usize..=6).prop_flat_map(|(degree, extra)| {
        let count = degree + 1 + extra;
        (
            Just(degree),
            parameters(count),
            prop::collection::vec(point(3), count),
        )
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    #[test]
    fn curve_interpolation_on_integers_equals_the_factorization(
        (u, points) in (1usize..=7).prop_flat_map(|n| (parameters(n), prop::collection::vec(point(3), n))),
    ) {
        // the fast path (Bernstein–Vandermonde inverse, degree 0 in v) and one
        // factorization of the Bernstein matrix, on the same local parameters
        let fast = cagd_fit::interpolate_bezier(&u, &points).unwrap();
        let (a, b) = cagd_fit::bezier_domain(&u);
        let local: Vec<Q> = u.iter().map(|x| (x.clone() - &a) / (b.clone() - &a)).collect();
        let matrix = cagd_fit::bernstein_matrix(points.len() - 1, &local);
        let slow = cagd_linalg::Factorization::new(&matrix).unwrap().solve_points(&points).unwrap();
        prop_assert_eq!(fast.points(), &slow[..]);
    }

    #[test]
    fn curve_least_squares_on_integers_equals_the_normal_equations(
        (degree, u, points) in curve_data(),
    ) {
        let fast = cagd_fit::approximate_bezier(degree, &u, &points).unwrap();
        let (a, b) = cagd_fit::bezier_domain(&u);
        let local: Vec<Q> = u.iter().map(|x| (x.clone() - &a) / (b.clone() - &a)).collect();
        let matrix = cagd_fit::bernstein_matrix(degree, &local);
        let slow = cagd_linalg::NormalEquations::new(&matrix).unwrap().solve_points(&points).unwrap();
        prop_assert_eq!(fast.points(), &slow[..]);
    }
}
