//! Integration tests of cagd-linalg: exact solves checked against independent routes.

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

use cagd_linalg::{
    determinant, inverse, least_squares, least_squares_points, solve, solve_matrix, solve_points,
    Elimination, Factorization, LinalgError, Matrix, NormalEquations, Point,
};
use cagd_scalar::{q, BigRational, ExactRational, FieldOps, Quadratic};
use proptest::prelude::*;

fn m(rows: Vec<Vec<BigRational>>) -> Matrix<BigRational> {
    Matrix::from_rows(rows).unwrap()
}

fn pts(rows: &[[BigRational; 3]]) -> Vec<Point<BigRational>> {
    rows.iter().map(|r| Point::new(r.to_vec())).collect()
}

/// The determinant by cofactor expansion along the first row: an independent route.
fn cofactor_det(a: &[Vec<BigRational>]) -> BigRational {
    let n = a.len();
    if n == 0 {
        return q!(1);
    }
    let mut det = q!(0);
    for j in 0..n {
        let minor: Vec<Vec<BigRational>> = a[1..]
            .iter()
            .map(|r| {
                r.iter()
                    .enumerate()
                    .filter(|(k, _)| *k != j)
                    .map(|(_, x)| x.clone())
                    .collect()
            })
            .collect();
        let term = a[0][j].clone() * cofactor_det(&minor);
        det = if j % 2 == 0 { det + term } else { det - term };
    }
    det
}

fn mat_vec(a: &Matrix<BigRational>, x: &[BigRational]) -> Vec<BigRational> {
    (0..a.rows())
        .map(|i| a.row(i).iter().zip(x).map(|(p, q)| p * q).sum())
        .collect()
}

fn small_rational() -> impl Strategy<Value = BigRational> {
    (-9i64..=9, 1i64..=9).prop_map(|(n, d)| BigRational::from_ratio(n, d))
}

fn square(n: usize) -> impl Strategy<Value = Matrix<BigRational>> {
    prop::collection::vec(prop::collection::vec(small_rational(), n), n).prop_map(m)
}

fn square_and_vector() -> impl Strategy<Value = (Matrix<BigRational>, Vec<BigRational>)> {
    (1usize..=5).prop_flat_map(|n| (square(n), prop::collection::vec(small_rational(), n)))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn solve_recovers_x_exactly((a, x) in square_and_vector()) {
        let det = cofactor_det(&a.to_rows());
        prop_assume!(det != q!(0));
        let b = mat_vec(&a, &x);
        for method in [Elimination::Auto, Elimination::Gauss, Elimination::FractionFree] {
            let f = Factorization::with_method(&a, method).unwrap();
            prop_assert_eq!(f.solve(&b).unwrap(), x.clone());
            prop_assert_eq!(f.determinant(), det.clone());
        }
        prop_assert_eq!(solve(&a, &b).unwrap(), x);
    }

    #[test]
    fn determinant_matches_cofactors_and_is_multiplicative(
        (a, b) in (1usize..=4).prop_flat_map(|n| (square(n), square(n)))
    ) {
        let da = determinant(&a).unwrap();
        prop_assert_eq!(&da, &cofactor_det(&a.to_rows()));
        let db = determinant(&b).unwrap();
        let dab = determinant(&a.mul(&b).unwrap()).unwrap();
        prop_assert_eq!(dab, da * db);
    }

    #[test]
    fn inverse_is_two_sided((a, _x) in square_and_vector()) {
        prop_assume!(cofactor_det(&a.to_rows()) != q!(0));
        let inv = inverse(&a).unwrap();
        let id = Matrix::identity(a.rows());
        prop_assert_eq!(a.mul(&inv).unwrap(), id.clone());
        prop_assert_eq!(inv.mul(&a).unwrap(), id);
        let gauss = Factorization::with_method(&a, Elimination::Gauss).unwrap().inverse();
        prop_assert_eq!(gauss, inverse(&a).unwrap());
    }

    #[test]
    fn dependent_rows_are_singular(
        (a, coefs, k) in (2usize..=5).prop_flat_map(|n| (
            square(n),
            prop::collection::vec(small_rational(), n),
            1..n,
        ))
    ) {
        // Replace row k by a combination of rows 0..k: the rows become dependent.
        let mut rows = a.to_rows();
        let n = rows.len();
        let combo: Vec<BigRational> = (0..n)
            .map(|j| (0..k).map(|i| &coefs[i] * &rows[i][j]).sum())
            .collect();
        rows[k] = combo;
        let dep = m(rows);
        for method in [Elimination::Gauss, Elimination::FractionFree] {
            let err = Factorization::with_method(&dep, method).unwrap_err();
            let singular = matches!(&err, LinalgError::Singular { .. });
            prop_assert!(singular);
            prop_assert!(err.to_string().contains("has no pivot"), "{}", err);
        }
        prop_assert_eq!(determinant(&dep).unwrap(), q!(0));
    }

    #[test]
    fn points_are_solved_per_coordinate(
        (a, data) in (1usize..=4).prop_flat_map(|n| (
            square(n),
            prop::collection::vec(prop::collection::vec(small_rational(), 3), n),
        ))
    ) {
        prop_assume!(cofactor_det(&a.to_rows()) != q!(0));
        let points: Vec<Point<BigRational>> = data.iter().cloned().map(Point::new).collect();
        let sol = solve_points(&a, &points).unwrap();
        for c in 0..3 {
            let column: Vec<BigRational> = points.iter().map(|p| p[c].clone()).collect();
            let x = solve(&a, &column).unwrap();
            let got: Vec<BigRational> = sol.iter().map(|p| p[c].clone()).collect();
            prop_assert_eq!(got, x);
        }
    }

    #[test]
    fn least_squares_residual_is_orthogonal_to_the_columns(
        (b, a) in (1usize..=3).prop_flat_map(|k| (2usize..=3).prop_flat_map(move |extra| (
            prop::collection::vec(prop::collection::vec(small_rational(), k), k + extra)
                .prop_map(m),
            prop::collection::vec(small_rational(), k + extra),
        )))
    ) {
        let bt = b.transpose();
        prop_assume!(cofactor_det(&bt.mul(&b).unwrap().to_rows()) != q!(0));
        let c = least_squares(&b, &a).unwrap();
        let residual: Vec<BigRational> =
            mat_vec(&b, &c).iter().zip(&a).map(|(x, y)| x - y).collect();
        let zeros = vec![q!(0); b.cols()];
        prop_assert_eq!(mat_vec(&bt, &residual), zeros);
    }
}

#[test]
fn least_squares_with_a_square_matrix_is_the_solve() {
    let b = m(vec![vec![q!(1), q!(2)], vec![q!(3), q!(5)]]);
    let a = [q!(1 / 2), q!(-1)];
    assert_eq!(least_squares(&b, &a).unwrap(), solve(&b, &a).unwrap());
}

/// The notes, chapter 5, section 7: the hyperbolic paraboloid closest to five points.
#[test]
fn notes_hyperbolic_paraboloid_least_squares() {
    let b = m(vec![
        vec![q!(1), q!(0), q!(0), q!(0)],
        vec![q!(0), q!(0), q!(1), q!(0)],
        vec![q!(0), q!(1), q!(0), q!(0)],
        vec![q!(0), q!(0), q!(0), q!(1)],
        vec![q!(1 / 4), q!(1 / 4), q!(1 / 4), q!(1 / 4)],
    ]);
    let a = pts(&[
        [q!(0), q!(0), q!(1 / 4)],
        [q!(1), q!(0), q!(1 / 3)],
        [q!(0), q!(1), q!(1 / 2)],
        [q!(1), q!(1), q!(3 / 4)],
        [q!(1 / 2), q!(1 / 2), q!(1 / 4)],
    ]);
    let normal = NormalEquations::new(&b).unwrap();
    let expected_btb =
        Matrix::from_fn(4, 4, |i, j| if i == j { q!(17) } else { q!(1) }).scale(&q!(1 / 16));
    assert_eq!(normal.normal_matrix(), &expected_btb);
    let bta = normal.rhs_points(&a).unwrap();
    let expected_bta: Vec<Point<BigRational>> = pts(&[
        [q!(2), q!(2), q!(5)],
        [q!(2), q!(18), q!(9)],
        [q!(18), q!(2), q!(19 / 3)],
        [q!(18), q!(18), q!(13)],
    ])
    .iter()
    .map(|p| p.scale(&q!(1 / 16)))
    .collect();
    assert_eq!(bta, expected_bta);
    let c = least_squares_points(&b, &a).unwrap();
    let text: Vec<String> = c.iter().map(Point::to_text).collect();
    assert_eq!(
        text,
        [
            "(0, 0, 5/24)",
            "(0, 1, 11/24)",
            "(1, 0, 7/24)",
            "(1, 1, 17/24)"
        ]
    );
    assert_eq!(c, normal.solve_points(&a).unwrap());
}

#[test]
fn least_squares_errors_name_the_cause() {
    let b = m(vec![vec![q!(1), q!(0), q!(0)], vec![q!(0), q!(1), q!(0)]]);
    let e = least_squares(&b, &[q!(1), q!(2)]).unwrap_err();
    assert!(matches!(
        e,
        LinalgError::Underdetermined {
            equations: 2,
            unknowns: 3
        }
    ));
    assert!(e.to_string().contains("2 equations for 3 unknowns"), "{e}");
    // Enough rows, but columns 0 and 1 are equal.
    let b = m(vec![
        vec![q!(1), q!(1), q!(0)],
        vec![q!(2), q!(2), q!(1)],
        vec![q!(0), q!(0), q!(3)],
    ]);
    let e = least_squares(&b, &[q!(1), q!(2), q!(3)]).unwrap_err();
    assert!(e.to_string().contains("BᵗB is singular"), "{e}");
    assert!(e.to_string().contains("column 1 has no pivot"), "{e}");
    let b = m(vec![vec![q!(1)], vec![q!(2)]]);
    assert!(least_squares(&b, &[q!(1)]).is_err());
}

/// The notes, chapter 5, section 7: the bidegree (2, 3) interpolating surface,
/// C_z = B_U⁻¹ A_z (B_Vᵗ)⁻¹, solved as the notes do: first C̃ B_Vᵗ = A, then B_U C = C̃.
#[test]
fn notes_bidegree_two_three_interpolation() {
    let bu = m(vec![
        vec![q!(1), q!(0), q!(0)],
        vec![q!(1 / 4), q!(1 / 2), q!(1 / 4)],
        vec![q!(0), q!(0), q!(1)],
    ]);
    let bv = m(vec![
        vec![q!(1), q!(0), q!(0), q!(0)],
        vec![q!(8 / 27), q!(4 / 9), q!(2 / 9), q!(1 / 27)],
        vec![q!(1 / 27), q!(2 / 9), q!(4 / 9), q!(8 / 27)],
        vec![q!(0), q!(0), q!(0), q!(1)],
    ]);
    let az = m(vec![
        vec![q!(0), q!(1), q!(0), q!(-1)],
        vec![q!(1), q!(2), q!(1), q!(1 / 2)],
        vec![q!(0), q!(1), q!(0), q!(-2)],
    ]);
    // C̃ B_Vᵗ = A  ⇔  B_V C̃ᵗ = Aᵗ.
    let c_tilde = solve_matrix(&bv, &az.transpose()).unwrap().transpose();
    let cz = solve_matrix(&bu, &c_tilde).unwrap();
    assert_eq!(
        cz.to_text(),
        "0  8/3  -2/3  -1\n2  31/6  1/12  5/2\n0  7/3  1/6  -2"
    );
    // The closed form with inverses agrees.
    let by_inverses = inverse(&bu)
        .unwrap()
        .mul(&az)
        .unwrap()
        .mul(&inverse(&bv.transpose()).unwrap())
        .unwrap();
    assert_eq!(by_inverses, cz);
}

#[test]
fn quadratic_system_is_exact() {
    // A = P + √2 Q with rational P, Q; b = A x for x with √2 entries; the solve returns x.
    let r2 = Quadratic::sqrt_of(&q!(2)).unwrap();
    let r = |x: BigRational| Quadratic::from_rational(x);
    let p = [
        [q!(1), q!(2), q!(0)],
        [q!(-1), q!(1 / 2), q!(3)],
        [q!(0), q!(1), q!(1)],
    ];
    let qq = [
        [q!(0), q!(1), q!(1)],
        [q!(1 / 3), q!(0), q!(0)],
        [q!(2), q!(0), q!(-1)],
    ];
    let a = Matrix::from_fn(3, 3, |i, j| {
        r(p[i][j].clone()) + r2.clone() * r(qq[i][j].clone())
    });
    let x = vec![r2.clone() * r(q!(1 / 2)), r(q!(-1)), r(q!(2)) + &r2];
    let b: Vec<Quadratic> = (0..3)
        .map(|i| (0..3).fold(r(q!(0)), |acc, j| acc + a.get(i, j).clone() * &x[j]))
        .collect();
    let f = Factorization::new(&a).unwrap();
    assert_eq!(f.method(), Elimination::Gauss);
    assert_eq!(f.solve(&b).unwrap(), x);
    let inv = f.inverse();
    assert_eq!(a.mul(&inv).unwrap(), Matrix::identity(3));
    // The determinant agrees with the rule of Sarrus.
    let g = |i: usize, j: usize| a.get(i, j).clone();
    let sarrus =
        g(0, 0) * g(1, 1) * g(2, 2) + g(0, 1) * g(1, 2) * g(2, 0) + g(0, 2) * g(1, 0) * g(2, 1)
            - g(0, 2) * g(1, 1) * g(2, 0)
            - g(0, 0) * g(1, 2) * g(2, 1)
            - g(0, 1) * g(1, 0) * g(2, 2);
    assert_eq!(f.determinant(), sarrus);
}

#[test]
fn f64_agrees_with_the_exact_solution() {
    let exact = m(vec![
        vec![q!(1 / 3), q!(2), q!(-1)],
        vec![q!(4), q!(1 / 7), q!(0)],
        vec![q!(-2), q!(5), q!(1 / 2)],
    ]);
    let b = [q!(1), q!(-2), q!(3 / 5)];
    let x = solve(&exact, &b).unwrap();
    let af = Matrix::from_fn(3, 3, |i, j| exact.get(i, j).to_f64());
    let bf: Vec<f64> = b.iter().map(ExactRational::to_f64).collect();
    let xf = solve(&af, &bf).unwrap();
    for (e, f) in x.iter().zip(&xf) {
        assert!((e.to_f64() - f).abs() < 1e-12, "{e} vs {f}");
    }
    let df = determinant(&af).unwrap();
    assert!((determinant(&exact).unwrap().to_f64() - df).abs() < 1e-12);
}

mod exact_kernels {
    use cagd_linalg::exact::{ratio, ratio_over_bases, solve_integer, IntMatrix};
    use cagd_scalar::gcd::gcd_lehmer;
    use cagd_scalar::{BigInt, BigRational};
    use num_integer::Integer;
    use proptest::prelude::*;

    fn big() -> impl Strategy<Value = BigInt> {
        // up to ~400 bits, either sign
        (prop::collection::vec(any::<u64>(), 1..7), any::<bool>()).prop_map(|(limbs, neg)| {
            let x = limbs
                .iter()
                .fold(BigInt::from(0u8), |acc, &l| (acc << 64) + BigInt::from(l));
            if neg {
                -x
            } else {
                x
            }
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        #[test]
        fn lehmer_gcd_equals_stein((a, b, g) in (big(), big(), big())) {
            let (a, b) = (&a * &g, &b * &g);
            prop_assert_eq!(gcd_lehmer(a.magnitude(), b.magnitude()), a.gcd(&b));
            if b != BigInt::from(0u8) {
                prop_assert_eq!(ratio(a.clone(), b.clone()), BigRational::new(a, b));
            }
        }

        #[test]
        fn reducing_over_the_bases_equals_the_gcd(
            (p, b1, b2) in (big(), 1u64..=5000, big()),
            (e1, e2, g1, g2) in (0u32..=40, 0u32..=8, 0u32..=20, 0u32..=4),
        ) {
            // q = b1^e1 b2^e2, and p with factors in common with both
            let b2 = if b2 == BigInt::from(0u8) { BigInt::from(7u8) } else { b2 };
            let b1 = BigInt::from(b1);
            let q = b1.pow(e1) * b2.pow(e2);
            let p = p * b1.pow(g1) * b2.pow(g2);
            prop_assert_eq!(
                ratio_over_bases(p.clone(), q.clone(), &[b1, b2]),
                BigRational::new(p, q)
            );
        }

        #[test]
        fn integer_solves_are_the_rational_solution(
            n in 1usize..=7, entries in prop::collection::vec(big(), 56), rhs in prop::collection::vec(big(), 14),
        ) {
            // 400-bit entries put Hadamard's bound above 2^1500 from n = 4 on (modulo primes)
            let a = IntMatrix::from_big(n, n, entries[..n * n].to_vec());
            let b = IntMatrix::from_big(n, 2, rhs[..2 * n].to_vec());
            if let Some((y, d)) = solve_integer(&a, &b) {
                // A Y = d B exactly
                let ay = a.mul(&y);
                for i in 0..n {
                    for c in 0..2 {
                        prop_assert_eq!(ay.get(i, c), b.get(i, c) * &d);
                    }
                }
            } else {
                prop_assert!(false, "random big matrices are not singular");
            }
        }
    }

    #[test]
    fn singular_integer_systems_are_none() {
        let a = IntMatrix::from_i128(3, 3, vec![1, 2, 3, 2, 4, 6, 0, 1, 1]);
        assert!(solve_integer(&a, &IntMatrix::from_i128(3, 1, vec![1, 2, 3])).is_none());
        // and with huge entries (the multimodular path gives up, elimination confirms)
        let h = BigInt::from(3u8).pow(400);
        let a = IntMatrix::from_big(
            3,
            3,
            vec![
                h.clone(),
                h.clone() * 2,
                h.clone() + 1,
                h.clone() * 2,
                h.clone() * 4,
                h.clone() * 2 + 2,
                h.clone(),
                h.clone(),
                h.clone(),
            ],
        );
        assert!(solve_integer(
            &a,
            &IntMatrix::from_big(3, 1, vec![h.clone(), h.clone(), h])
        )
        .is_none());
    }
}
