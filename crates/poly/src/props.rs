//! Property tests of the polynomial module, over random small rationals (numerators in
//! [-9, 9], denominators 1..9), each against an independent route.

use crate::*;
use cagd_scalar::{q, BigRational, Quadratic};
use proptest::prelude::*;

type Q = BigRational;

fn parse_number_q(text: &str) -> Quadratic {
    cagd_scalar::parse_number(text).unwrap()
}

/// A small rational: numerator in [-9, 9], denominator in 1..9.
fn small_q() -> impl Strategy<Value = Q> {
    (-9i64..=9, 1i64..=9).prop_map(|(n, d)| Q::new(n.into(), d.into()))
}

/// A random polynomial of up to 5 terms in u, v, w, of degree ≤ 3 in each.
fn small_poly() -> impl Strategy<Value = Poly<Q>> {
    prop::collection::vec((small_q(), 0u32..=3, 0u32..=3, 0u32..=2), 0..5).prop_map(|terms| {
        Poly::from_terms(terms.into_iter().map(|(c, a, b, e)| {
            (
                Monomial::from_powers(&[(Var::U, a), (Var::V, b), (Var::W, e)]),
                c,
            )
        }))
    })
}

fn small_point() -> impl Strategy<Value = [Q; 3]> {
    [small_q(), small_q(), small_q()]
}

fn at(x: &[Q; 3]) -> Vec<(Var, Q)> {
    vec![
        (Var::U, x[0].clone()),
        (Var::V, x[1].clone()),
        (Var::W, x[2].clone()),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn ring_laws(a in small_poly(), b in small_poly(), c in small_poly()) {
        prop_assert_eq!(&a + &b, &b + &a);
        prop_assert_eq!(&a * &b, &b * &a);
        prop_assert_eq!(&(&a + &b) + &c, &a + &(&b + &c));
        prop_assert_eq!(&(&a * &b) * &c, &a * &(&b * &c));
        prop_assert_eq!(&a * &(&b + &c), &(&a * &b) + &(&a * &c));
        prop_assert_eq!(&a - &b, &a + &(-&b));
        prop_assert!((&a - &a).is_zero());
        prop_assert_eq!(&a * &Poly::one(), a.clone());
        // every by-value and by-reference form agrees
        prop_assert_eq!(a.clone() + b.clone(), &a + &b);
        prop_assert_eq!(a.clone() - &b, &a - b.clone());
        prop_assert_eq!(a.clone() * &b, &a * b.clone());
        prop_assert_eq!(a.scale(&q!(3/2)), &a * &Poly::constant(q!(3/2)));
        prop_assert_eq!(a.pow(3), &(&a * &a) * &a);
    }

    #[test]
    fn evaluation_is_a_ring_homomorphism(a in small_poly(), b in small_poly(), x in small_point()) {
        let pt = at(&x);
        let (ea, eb) = (a.eval(&pt).unwrap(), b.eval(&pt).unwrap());
        prop_assert_eq!((&a + &b).eval(&pt).unwrap(), ea.clone() + &eb);
        prop_assert_eq!((&a * &b).eval(&pt).unwrap(), ea * eb);
    }

    #[test]
    fn leibniz_rule(a in small_poly(), b in small_poly()) {
        for v in [Var::U, Var::V, Var::W] {
            let lhs = (&a * &b).partial(v);
            let rhs = &a.partial(v) * &b + &a * &b.partial(v);
            prop_assert_eq!(lhs, rhs);
        }
    }

    #[test]
    fn substitution_agrees_with_evaluation(a in small_poly(), q in small_poly(), x in small_point()) {
        // a(q(x), v, w) evaluated at x equals a evaluated at (q(x), x_v, x_w)
        let pt = at(&x);
        let qx = q.eval(&pt).unwrap();
        let composed = a.substitute(Var::U, &q).eval(&pt).unwrap();
        let direct = a.eval(&[(Var::U, qx.clone()), (Var::V, x[1].clone()), (Var::W, x[2].clone())]).unwrap();
        prop_assert_eq!(composed, direct.clone());
        prop_assert_eq!(a.substitute_value(Var::U, &qx).eval(&pt).unwrap(), direct);
    }

    #[test]
    fn affine_reparametrization_round_trip(a in small_poly(), lo in small_q(), len in small_q()) {
        prop_assume!(len != q!(0));
        let hi = lo.clone() + &len;
        let r = a.reparametrize_affine(Var::U, &lo, &hi).unwrap();
        // undo with u ↦ (hi - lo) u + lo
        prop_assert_eq!(r.affine_substitute(Var::U, &len, &lo), a.clone());
        let x = [q!(0), q!(1/2), q!(1)];
        for t in x {
            let s = lo.clone() + len.clone() * &t;
            let pt = [(Var::U, s), (Var::V, q!(2)), (Var::W, q!(3))];
            let orig = [(Var::U, t), (Var::V, q!(2)), (Var::W, q!(3))];
            prop_assert_eq!(r.eval(&pt).unwrap(), a.eval(&orig).unwrap());
        }
    }

    #[test]
    fn bernstein_round_trip_1d(coefs in prop::collection::vec(small_q(), 1..6), extra in 0usize..3) {
        let n = coefs.len() - 1;
        let f = poly_from_bernstein_1d(&coefs, Var::U);
        // independent route: the Bernstein sum
        let sum = coefs.iter().enumerate().fold(Poly::zero(), |acc, (i, c)| {
            acc + bernstein::<Q>(i, n, Var::U).scale(c)
        });
        prop_assert_eq!(&f, &sum);
        prop_assert_eq!(to_bernstein_1d(&f, Var::U, n).unwrap(), coefs.clone());
        // degree elevation keeps the polynomial
        let up = to_bernstein_1d(&f, Var::U, n + extra).unwrap();
        prop_assert_eq!(poly_from_bernstein_1d(&up, Var::U), f);
    }

    #[test]
    fn bernstein_round_trip_2d(m in 0usize..4, n in 0usize..4, seed in prop::collection::vec(small_q(), 16)) {
        let grid: Vec<Vec<Q>> = (0..=m)
            .map(|i| (0..=n).map(|j| seed[i * 4 + j].clone()).collect())
            .collect();
        let f = poly_from_bernstein_2d(&grid, Var::U, Var::V).unwrap();
        let mut sum = Poly::zero();
        for i in 0..=m {
            for j in 0..=n {
                sum = sum + (bernstein::<Q>(i, m, Var::U) * bernstein(j, n, Var::V)).scale(&grid[i][j]);
            }
        }
        prop_assert_eq!(&f, &sum);
        prop_assert_eq!(to_bernstein_2d(&f, Var::U, Var::V, m, n).unwrap(), grid);
    }

    #[test]
    fn monomial_round_trip_2d(a in small_poly()) {
        let a = a.substitute_value(Var::W, &q!(1));
        let (m, n) = (a.degree_in(Var::U) as usize, a.degree_in(Var::V) as usize);
        let grid = to_bernstein_2d(&a, Var::U, Var::V, m + 1, n).unwrap();
        prop_assert_eq!(poly_from_bernstein_2d(&grid, Var::U, Var::V).unwrap(), a);
    }

    #[test]
    fn print_parse_round_trip(a in small_poly(), b in small_poly()) {
        for text in [a.to_text(), a.to_json_string()] {
            prop_assert_eq!(parse_poly::<Q>(&text).unwrap(), a.clone(), "{}", text);
        }
        let c = VecPoly::new(vec![a.clone(), b.clone()]);
        for text in [c.to_text(), c.to_json_string()] {
            prop_assert_eq!(parse_vec_poly::<Q>(&text).unwrap(), c.clone(), "{}", text);
        }
    }

    #[test]
    fn print_parse_round_trip_quadratic(a in small_poly(), b in small_poly()) {
        // coefficients a + b√2
        let root = parse_number_q("sqrt2");
        let p = a.map_coeffs(|c| Quadratic::from_rational(c.clone()))
            + b.map_coeffs(|c| Quadratic::from_rational(c.clone()) * &root);
        for text in [p.to_text(), p.to_json_string()] {
            prop_assert_eq!(parse_poly::<Quadratic>(&text).unwrap(), p.clone(), "{}", text);
        }
    }
}
