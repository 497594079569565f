//! Property tests over random rational patches of degree 1..=4, each checked against an
//! independent route.

use crate::common::{bary, direction, map_point, patch, r, shift, Q};
use cagd_linalg::Point;
use cagd_triangle::{bernstein_basis, multi_indices, Barycentric, Edge, TriangularPatch};
use proptest::prelude::*;
use std::iter::repeat_n;

fn binomial(n: usize, k: usize) -> Q {
    (1..=k).fold(r(1, 1), |acc, l| acc * r((n - l + 1) as i64, l as i64))
}

/// The Bézier curve Σ c_l C(n, l) (1 - λ)^{n-l} λ^l, by its Bernstein sum.
fn curve_value(ctrl: &[Point<Q>], lambda: &Q) -> Point<Q> {
    let n = ctrl.len() - 1;
    let mu = r(1, 1) - lambda;
    let coefs: Vec<Q> = (0..=n)
        .map(|l| binomial(n, l) * pow(&mu, n - l) * pow(lambda, l))
        .collect();
    Point::combination(ctrl, &coefs, ctrl[0].dim())
}

fn pow(x: &Q, e: usize) -> Q {
    (0..e).fold(r(1, 1), |acc, _| acc * x)
}

/// The blossom with the vertices e1^i e2^j e3^k.
fn vertex_args(i: usize, j: usize, k: usize) -> Vec<Barycentric<Q>> {
    repeat_n(Barycentric::e1(), i)
        .chain(repeat_n(Barycentric::e2(), j))
        .chain(repeat_n(Barycentric::e3(), k))
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn de_casteljau_equals_bernstein_sum(p in patch(), x in bary()) {
        prop_assert_eq!(p.evaluate(&x), p.evaluate_bernstein(&x));
        let steps = p.de_casteljau(&x);
        prop_assert_eq!(steps.value(), &p.evaluate(&x));
    }

    #[test]
    fn bernstein_partition_of_unity(n in 0usize..=6, x in bary()) {
        let total = bernstein_basis(n, &x).into_iter().fold(r(0, 1), |acc, b| acc + b);
        prop_assert_eq!(total, r(1, 1));
    }

    #[test]
    fn blossom_is_diagonal_and_interpolates_the_net(p in patch(), x in bary()) {
        let n = p.degree();
        prop_assert_eq!(p.blossom(&vec![x.clone(); n]).unwrap(), p.evaluate(&x));
        for ((i, j, k), b) in p.indexed_points() {
            prop_assert_eq!(&p.blossom(&vertex_args(i, j, k)).unwrap(), b);
        }
    }

    #[test]
    fn blossom_is_symmetric(p in patch(), xs in prop::collection::vec(bary(), 4), rot in 0usize..4) {
        let n = p.degree();
        let args = &xs[..n];
        let value = p.blossom(args).unwrap();
        let mut rev = args.to_vec();
        rev.reverse();
        prop_assert_eq!(&p.blossom(&rev).unwrap(), &value);
        let mut rotated = args.to_vec();
        rotated.rotate_left(rot % n);
        prop_assert_eq!(&p.blossom(&rotated).unwrap(), &value);
    }

    #[test]
    fn blossom_is_multi_affine(
        p in patch(),
        xs in prop::collection::vec(bary(), 4),
        y in bary(),
        lambda in crate::common::small(),
        slot in 0usize..4,
    ) {
        let n = p.degree();
        let slot = slot % n;
        let a = xs[..n].to_vec();
        let mut b = a.clone();
        b[slot] = y.clone();
        let mut mixed = a.clone();
        mixed[slot] = a[slot].lerp(&y, &lambda);
        let lhs = p.blossom(&mixed).unwrap();
        let rhs = p.blossom(&a).unwrap().lerp(&p.blossom(&b).unwrap(), &lambda);
        prop_assert_eq!(lhs, rhs);
    }

    #[test]
    fn elevation_keeps_the_surface(p in patch(), x in bary(), e in 0usize..3) {
        let up = p.elevate_degree();
        prop_assert_eq!(up.degree(), p.degree() + 1);
        prop_assert_eq!(up.evaluate(&x), p.evaluate(&x));
        let by = p.elevate_degree_by(e).unwrap();
        let mut repeated = p.clone();
        for _ in 0..e {
            repeated = repeated.elevate_degree();
        }
        prop_assert_eq!(&by, &repeated);
        prop_assert_eq!(by.evaluate_bernstein(&x), p.evaluate(&x));
    }

    #[test]
    fn restriction_keeps_the_surface(
        p in patch(),
        a in bary(),
        b in bary(),
        c in bary(),
        y in bary(),
    ) {
        let sub = p.restrict(&a, &b, &c);
        prop_assert_eq!(sub.evaluate(&y), p.evaluate(&map_point(&y, [&a, &b, &c])));
    }

    #[test]
    fn split_gives_the_three_restrictions(p in patch(), x in bary(), y in bary()) {
        let (e1, e2, e3) = (Barycentric::e1(), Barycentric::e2(), Barycentric::e3());
        let parts = p.split(&x);
        let triangles = [[&x, &e2, &e3], [&e1, &x, &e3], [&e1, &e2, &x]];
        for (part, tri) in parts.iter().zip(triangles) {
            prop_assert_eq!(part, &p.restrict(tri[0], tri[1], tri[2]));
            prop_assert_eq!(part.evaluate(&y), p.evaluate(&map_point(&y, tri)));
        }
    }

    #[test]
    fn directional_derivative_three_ways(p in patch(), x in bary(), d in direction()) {
        let n = p.degree();
        let first_step = p.directional_derivative(&x, &d);
        // the last step in the direction d (level n - 1 at x)
        prop_assert_eq!(&p.de_casteljau(&x).directional_derivative(&d), &first_step);
        // n b[d, x, ..., x] through the higher derivative of order 1
        prop_assert_eq!(&p.higher_derivative(&x, std::slice::from_ref(&d)), &first_step);
        // evaluation only: f(h) = b(x + h d) is a polynomial of degree n in h, and
        // f'(0) = Σ_{m=1}^{n} (-1)^{m+1}/m Δ^m f(0) exactly (Newton's forward differences)
        let mut diffs: Vec<Point<Q>> = (0..=n)
            .map(|h| p.evaluate_bernstein(&shift(&x, &r(h as i64, 1), &d)))
            .collect();
        let mut newton = Point::zero(p.dim());
        for m in 1..=n {
            diffs = diffs.windows(2).map(|w| &w[1] - &w[0]).collect();
            let sign = if m % 2 == 1 { 1 } else { -1 };
            newton.add_scaled(&diffs[0], &r(sign, m as i64));
        }
        prop_assert_eq!(newton, first_step);
    }

    #[test]
    fn derivative_is_linear_in_the_direction(p in patch(), x in bary(), d in direction(), e in direction()) {
        let sum = cagd_triangle::Direction::try_new(
            d.coords()[0].clone() + &e.coords()[0],
            d.coords()[1].clone() + &e.coords()[1],
            d.coords()[2].clone() + &e.coords()[2],
        ).unwrap();
        prop_assert_eq!(
            p.directional_derivative(&x, &sum),
            &p.directional_derivative(&x, &d) + &p.directional_derivative(&x, &e)
        );
    }

    #[test]
    fn second_derivatives_are_derivatives_of_derivatives(
        p in patch(), x in bary(), d in direction(), e in direction()
    ) {
        let twice = p.derivative(&d).derivative(&e).evaluate(&x);
        prop_assert_eq!(&p.higher_derivative(&x, &[d.clone(), e.clone()]), &twice);
        prop_assert_eq!(&p.higher_derivative(&x, &[e, d]), &twice);
    }

    #[test]
    fn boundary_curves_are_the_patch_on_the_edges(p in patch(), lambda in crate::common::small()) {
        for edge in Edge::ALL {
            let ctrl = p.boundary_curve(edge);
            prop_assert_eq!(ctrl.len(), p.degree() + 1);
            prop_assert_eq!(curve_value(&ctrl, &lambda), p.evaluate(&edge.point_at(&lambda)));
        }
        let [a, b, c] = p.corners();
        let corners = [a.clone(), b.clone(), c.clone()];
        for (corner, vertex) in corners.iter().zip(Barycentric::<Q>::vertices()) {
            prop_assert_eq!(corner, &p.evaluate(&vertex));
        }
    }

    #[test]
    fn try_new_round_trips(p in patch()) {
        let again = TriangularPatch::try_new(p.degree(), p.points().to_vec()).unwrap();
        prop_assert_eq!(&again, &p);
        for ((i, j, k), b) in p.indexed_points() {
            prop_assert_eq!(p.point(i, j, k).unwrap(), b);
        }
        prop_assert_eq!(multi_indices(p.degree()).count(), p.points().len());
    }
}
