//! Property tests on random rational polygons, each against an independent route.

use crate::common::{polygon, rat, weighted_polygon};
use cagd_bezier::*;
use cagd_linalg::Point;
use cagd_scalar::{q, BigRational, FieldOps};
use proptest::prelude::*;

type P = Point<BigRational>;

fn eval(c: &[P], t: &BigRational) -> P {
    de_casteljau(c, t).unwrap()
}

/// Σ_r h^r / r! c^(r)(t): the exact Taylor expansion of a polynomial of degree n.
fn taylor(c: &[P], t: &BigRational, h: &BigRational) -> P {
    let n = c.len() - 1;
    let mut acc = Point::zero(c[0].dim());
    let mut coef = q!(1);
    for r in 0..=n {
        let d = eval(&derivative_points(c, r).unwrap(), t);
        acc.add_scaled(&d, &coef);
        coef = coef * h / BigRational::from_i64(r as i64 + 1);
    }
    acc
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// The triangle of De Casteljau on integers (every number rational) is the triangle of the
    /// lerps `c_i^r = (1 - t) c_i^{r-1} + t c_{i+1}^{r-1}` over `BigRational`, level by level.
    #[test]
    fn casteljau_triangle_on_integers_is_the_lerp_triangle(c in polygon(7), t in rat()) {
        let triangle = de_casteljau_triangle(&c, &t).unwrap();
        let mut level = c.clone();
        for (r, shown) in triangle.iter().enumerate() {
            prop_assert_eq!(shown, &level, "level {}", r);
            level = level.iter().zip(level.iter().skip(1)).map(|(a, b)| a.lerp(b, &t)).collect();
        }
        prop_assert_eq!(triangle.len(), c.len());
    }


    #[test]
    fn de_casteljau_equals_the_bernstein_sum(c in polygon(6), t in rat()) {
        prop_assert_eq!(eval(&c, &t), bernstein_sum(&c, &t).unwrap());
        let tri = de_casteljau_triangle(&c, &t).unwrap();
        prop_assert_eq!(tri.len(), c.len());
        for (r, level) in tri.iter().enumerate() {
            prop_assert_eq!(level.len(), c.len() - r);
        }
        prop_assert_eq!(&tri[c.len() - 1][0], &eval(&c, &t));
        let b = bernstein_all(c.len() - 1, &t);
        prop_assert_eq!(b.iter().fold(q!(0), |acc, x| acc + x), q!(1));
    }

    #[test]
    fn the_integer_bernstein_sum_equals_de_casteljau(
        c in polygon(8),
        (p, q) in (0i64..=1000, 1i64..=1000).prop_filter("t in [0, 1]", |(p, q)| p <= q),
        long in prop::bool::ANY,
    ) {
        // long numbers (past machine integers) take the big-integer kernel
        let scale = if long { q!(1) + BigRational::from_i64(10).powi(40) / q!(7) } else { q!(1) };
        let c: Vec<P> = c.iter().map(|x| x.scale(&scale)).collect();
        let t = BigRational::from_ratio(p, q);
        let curve = BezierCurve::try_new(c.clone()).unwrap();
        prop_assert_eq!(curve.eval(&t).unwrap(), eval(&c, &t));
        let weights: Vec<BigRational> = (0..c.len()).map(|i| BigRational::from_ratio(i as i64 + 1, 3)).collect();
        let r = RationalBezierCurve::try_new(c.clone(), weights.clone()).unwrap();
        let h: Vec<P> = c.iter().zip(&weights).map(|(x, w)| x.to_homogeneous(w)).collect();
        prop_assert_eq!(r.eval_homogeneous(&t).unwrap(), eval(&h, &t));
    }

    #[test]
    fn blossom_is_symmetric_multiaffine_and_diagonal(
        c in polygon(5), args in prop::collection::vec(rat(), 5), x in rat(), y in rat(), l in rat(),
    ) {
        let n = c.len() - 1;
        let args = &args[..n];
        let b = blossom(&c, args).unwrap();
        // symmetric: reversed and rotated argument lists
        let rev: Vec<BigRational> = args.iter().rev().cloned().collect();
        prop_assert_eq!(&blossom(&c, &rev).unwrap(), &b);
        let mut rot = args.to_vec();
        rot.rotate_left(1.min(n));
        prop_assert_eq!(&blossom(&c, &rot).unwrap(), &b);
        // diagonal
        prop_assert_eq!(blossom(&c, &vec![x.clone(); n]).unwrap(), eval(&c, &x));
        // control points c_i = c[0^<n-i>, 1^<i>]
        for i in 0..=n {
            let mut a = vec![q!(0); n - i];
            a.extend(vec![q!(1); i]);
            prop_assert_eq!(&blossom(&c, &a).unwrap(), &c[i]);
        }
        // affine in the first argument
        if n > 0 {
            let with = |v: &BigRational| {
                let mut a = args.to_vec();
                a[0] = v.clone();
                blossom(&c, &a).unwrap()
            };
            let mix = (q!(1) - &l) * &x + l.clone() * &y;
            prop_assert_eq!(with(&mix), with(&x).lerp(&with(&y), &l));
        }
    }

    #[test]
    fn subdivision_keeps_the_curve(c in polygon(5), t in rat(), s in rat()) {
        let (left, right) = subdivide(&c, &t).unwrap();
        // left(s) = c(t s), right(s) = c(t + (1 - t) s)
        prop_assert_eq!(eval(&left, &s), eval(&c, &(t.clone() * &s)));
        let mapped = t.clone() + (q!(1) - &t) * &s;
        prop_assert_eq!(eval(&right, &s), eval(&c, &mapped));
        prop_assert_eq!(left.last(), right.first());
    }

    #[test]
    fn restriction_keeps_the_curve(c in polygon(5), a in rat(), b in rat(), s in rat()) {
        prop_assume!(a != b);
        let r = restrict(&c, &a, &b).unwrap();
        let mapped = (q!(1) - &s) * &a + s.clone() * &b;
        prop_assert_eq!(eval(&r, &s), eval(&c, &mapped));
        // restricting to [0, 1] changes nothing; back from [a, b] to the original
        prop_assert_eq!(&restrict(&c, &q!(0), &q!(1)).unwrap(), &c);
        let back_a = -a.clone() / (b.clone() - &a);
        let back_b = (q!(1) - &a) / (b.clone() - &a);
        prop_assert_eq!(restrict(&r, &back_a, &back_b).unwrap(), c);
    }

    #[test]
    fn elevation_keeps_the_curve(c in polygon(5), r in 0usize..4, t in rat()) {
        let e = elevate_degree(&c, r).unwrap();
        prop_assert_eq!(e.len(), c.len() + r);
        prop_assert_eq!(eval(&e, &t), eval(&c, &t));
        prop_assert_eq!(e.first(), c.first());
        prop_assert_eq!(e.last(), c.last());
    }

    #[test]
    fn derivatives_agree_with_independent_routes(c in polygon(5), t in rat(), h in rat()) {
        let n = c.len() - 1;
        let tri = de_casteljau_triangle(&c, &t).unwrap();
        let hodograph = derivative_points(&c, 1).unwrap();
        if n > 0 {
            // c'(t) = n (c_1^{n-1} - c_0^{n-1})
            let last = &tri[n - 1];
            let expect = (&last[1] - &last[0]).scale(&BigRational::from_i64(n as i64));
            prop_assert_eq!(eval(&hodograph, &t), expect);
            // the r-th derivative is the derivative of the (r-1)-th
            for r in 2..=n + 1 {
                let prev = derivative_points(&c, r - 1).unwrap();
                prop_assert_eq!(derivative_points(&prev, 1).unwrap(), derivative_points(&c, r).unwrap());
            }
        } else {
            prop_assert!(hodograph[0].is_zero());
        }
        // exact Taylor: c(t + h) = Σ h^r/r! c^(r)(t)
        prop_assert_eq!(taylor(&c, &t, &h), eval(&c, &(t.clone() + &h)));
        // Δ^r c_i = Σ_j (-1)^{r-j} C(r, j) c_{i+j}
        for r in 0..=n {
            let d = forward_differences(&c, r).unwrap();
            prop_assert_eq!(d.len(), n - r + 1);
            for (i, di) in d.iter().enumerate() {
                let mut acc = Point::zero(c[0].dim());
                for j in 0..=r {
                    let sign = if (r - j) % 2 == 0 { q!(1) } else { q!(-1) };
                    acc.add_scaled(&c[i + j], &(sign * binomial::<BigRational>(r, j)));
                }
                prop_assert_eq!(di, &acc);
            }
        }
        prop_assert!(forward_differences(&c, n + 1).unwrap().is_empty());
    }

    #[test]
    fn typed_curve_on_a_domain(c in polygon(4), a in rat(), len in 1i64..5, s in 0i64..=8) {
        let b = a.clone() + BigRational::from_i64(len);
        let curve = BezierCurve::try_new(c.clone()).unwrap().with_domain(a.clone(), b.clone()).unwrap();
        let t = a.clone() + BigRational::from_ratio(s * len, 8);
        let u = BigRational::from_ratio(s, 8);
        prop_assert_eq!(curve.eval(&t).unwrap(), eval(&c, &u));
        // derivative w.r.t. t: (1/(b - a)) · derivative w.r.t. u
        let d = curve.derivative(1).eval(&t).unwrap();
        let du = eval(&derivative_points(&c, 1).unwrap(), &u);
        prop_assert_eq!(d, du.scale(&(q!(1) / BigRational::from_i64(len))));
        if s > 0 && s < 8 {
            let (l, r) = curve.subdivide(&t).unwrap();
            let mid = (a.clone() + &t) / BigRational::from_i64(2);
            prop_assert_eq!(l.eval(&mid).unwrap(), curve.eval(&mid).unwrap());
            let mid = (t.clone() + &b) / BigRational::from_i64(2);
            prop_assert_eq!(r.eval(&mid).unwrap(), curve.eval(&mid).unwrap());
        }
    }

    #[test]
    fn rational_curve_against_the_quotient_of_sums(
        (c, w) in weighted_polygon(4), t in 0i64..=9, s in 1i64..=8,
    ) {
        let t = BigRational::from_ratio(t, 9);
        let curve = RationalBezierCurve::try_new(c.clone(), w.clone()).unwrap();
        // c(t) = Σ w_i B_i c_i / Σ w_i B_i
        let n = c.len() - 1;
        let b = bernstein_all(n, &t);
        let den = b.iter().zip(&w).fold(q!(0), |acc, (bi, wi)| acc + bi.clone() * wi);
        let coefs: Vec<BigRational> = b.iter().zip(&w).map(|(bi, wi)| bi.clone() * wi / &den).collect();
        let expect = Point::combination(&c, &coefs, c[0].dim());
        let p = curve.eval(&t).unwrap();
        prop_assert_eq!(&p, &expect);
        prop_assert_eq!(curve.blossom(&vec![t.clone(); n]).unwrap(), p.clone());
        // the operations keep the curve
        let e = curve.elevate_degree(2).unwrap();
        prop_assert_eq!(e.eval(&t).unwrap(), p.clone());
        let cut = BigRational::from_ratio(s, 9);
        let (l, r) = curve.subdivide(&cut).unwrap();
        let piece = if t <= cut { l } else { r };
        prop_assert_eq!(piece.eval(&t).unwrap(), p.clone());
        // inside [0, 1] (beyond it a positive-weight denominator may vanish)
        let (lo, hi) = if t < cut { (t.clone(), cut.clone()) } else if t > cut { (cut.clone(), t.clone()) } else { (q!(0), cut.clone()) };
        let rr = curve.restrict(&lo, &hi).unwrap();
        prop_assert_eq!(rr.eval(&t).unwrap(), p.clone());
        // quotient rule: w c' = p' - w' c
        let d = curve.derivative_at(&t).unwrap();
        let hd = bernstein_sum(&derivative_points(&curve.homogeneous(), 1).unwrap(), &t).unwrap().into_coords();
        let (dw, dp) = hd.split_last().unwrap();
        for k in 0..p.dim() {
            prop_assert_eq!(den.clone() * &d[k], dp[k].clone() - dw.clone() * &p[k]);
        }
    }
}
