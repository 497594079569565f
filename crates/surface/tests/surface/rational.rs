//! Rational patches: random ones against independent routes, and the sphere octant over Q(√2).

use crate::common::{interior, r, random_patch, random_rational, rat, rational, unit};
use cagd_linalg::Point;
use cagd_poly::{RationalMap, Var};
use cagd_scalar::{parse_number, BigRational, ExactRational, FieldOps, Quadratic, Scalar};
use cagd_surface::{
    BezierSurface, Border, Corner, Degeneracy, Grid, NormalAtCorner, RationalBezierSurface,
};
use proptest::prelude::*;

type Q = BigRational;

const OCTANT: &str = "{(1, 0, 0), (1, 1, 0), (0, 1, 0); \
                       (1, 0, 1), (1, 1, 1), (0, 1, 1); \
                       (0, 0, 1), (0, 0, 1), (0, 0, 1)}";
const OCTANT_WEIGHTS: &str = "{1, sqrt2/2, 1; sqrt2/2, 1/2, sqrt2/2; 1, sqrt2/2, 1}";

fn octant() -> RationalBezierSurface<Quadratic> {
    rational(OCTANT, OCTANT_WEIGHTS)
}

fn qd(x: &Q) -> Quadratic {
    <Quadratic as ExactRational>::from_rational(x)
}

fn norm2<S: Scalar>(p: &Point<S>) -> S {
    p.dot(p)
}

fn affine(a: &Q, b: &Q, t: &Q) -> Q {
    a.clone() + (b.clone() - a) * t
}

/// The polynomial patch as a rational patch with unit weights.
fn unit_weights(s: &BezierSurface<Q>) -> RationalBezierSurface<Q> {
    let w = Grid::from_fn(s.mesh().rows(), s.mesh().cols(), |_, _| r(1, 1));
    RationalBezierSurface::try_new(s.mesh().clone(), w).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn three_evaluations_agree(s in random_rational(3), u in unit(), v in unit()) {
        let x = s.eval(&u, &v).unwrap();
        prop_assert_eq!(&x, &s.eval_quotient(&u, &v).unwrap());
        prop_assert_eq!(&x, &s.de_casteljau_rows_first(&u, &v).unwrap());
        prop_assert!(s.in_convex_hull(&x).unwrap());
    }

    #[test]
    fn closed_form_and_blossom_diagonal(s in random_rational(2), u in unit(), v in unit()) {
        let x = s.eval(&u, &v).unwrap();
        prop_assert_eq!(&x, &s.closed_form().unwrap().eval(&[(Var::U, u.clone()), (Var::V, v.clone())]).unwrap());
        let (m, n) = s.bidegree();
        prop_assert_eq!(&x, &s.blossom(&vec![u.clone(); m], &vec![v.clone(); n]).unwrap());
    }

    #[test]
    fn restriction_subdivision_elevation_keep_the_surface(
        s in random_rational(2), a in unit(), b in unit(), c in unit(), d in unit(), p in unit(), q in unit(), u0 in interior(), v0 in interior(),
    ) {
        prop_assume!(a < b && c < d);
        let (u, v) = (affine(&a, &b, &p), affine(&c, &d, &q));
        let x = s.eval(&u, &v).unwrap();
        let res = s.restrict(&a, &b, &c, &d).unwrap();
        prop_assert_eq!(&res.result.eval(&u, &v).unwrap(), &x);
        prop_assert_eq!(&res.rows_step.eval_quotient(&u, &v).unwrap(), &x);
        prop_assert_eq!(&s.elevate(1, 2).unwrap().eval(&u, &v).unwrap(), &x);
        prop_assert_eq!(s.elevate_u().unwrap().elevate_v().unwrap(), s.elevate(1, 1).unwrap());
        let pieces = s.subdivide(&u0, &v0).unwrap();
        let i = usize::from(u > u0);
        let j = usize::from(v > v0);
        prop_assert_eq!(&pieces[i][j].eval(&u, &v).unwrap(), &x);
    }

    #[test]
    fn boundaries_and_corners(s in random_rational(3), t in unit()) {
        let one = r(1, 1);
        let zero = r(0, 1);
        prop_assert_eq!(s.boundary(Border::U0).unwrap().eval(&t).unwrap(), s.eval(&zero, &t).unwrap());
        prop_assert_eq!(s.boundary(Border::U1).unwrap().eval(&t).unwrap(), s.eval(&one, &t).unwrap());
        prop_assert_eq!(s.boundary(Border::V0).unwrap().eval(&t).unwrap(), s.eval(&t, &zero).unwrap());
        prop_assert_eq!(s.boundary(Border::V1).unwrap().eval(&t).unwrap(), s.eval(&t, &one).unwrap());
        let params = [(&zero, &zero), (&one, &zero), (&zero, &one), (&one, &one)];
        for (corner, (u, v)) in s.corners().iter().zip(params) {
            prop_assert_eq!(corner, &s.eval(u, v).unwrap());
        }
    }

    #[test]
    fn corner_normals_are_the_normal_field_over_mn(s in random_rational(2)) {
        let (m, n) = s.bidegree();
        let field = s.normal().unwrap();
        let mn = <Q as FieldOps>::from_i64(i64::try_from(m * n).unwrap());
        for (corner, (u, v)) in Corner::ALL.iter().zip([(0, 0), (1, 0), (0, 1), (1, 1)]) {
            let exact = field.eval(&[(Var::U, <Q as FieldOps>::from_i64(u)), (Var::V, <Q as FieldOps>::from_i64(v))]).unwrap();
            match s.normal_at_corner(*corner).unwrap() {
                NormalAtCorner::Normal(p) => prop_assert_eq!(exact, p.scale(&mn)),
                NormalAtCorner::Degenerate { .. } => prop_assert!(exact.is_zero()),
            }
        }
    }

    #[test]
    fn unit_weights_give_the_polynomial_patch(s in random_patch(), u in rat(), v in rat(), k in 0usize..=2) {
        let w = unit_weights(&s);
        prop_assert_eq!(w.eval_quotient(&u, &v).unwrap(), s.eval_matrix(&u, &v));
        prop_assert_eq!(w.closed_form().unwrap(), RationalMap::from_polynomial(s.closed_form().unwrap()));
        let d = w.partial_derivative(k, 1).unwrap();
        let e = s.partial_derivative(k, 1).unwrap().closed_form().unwrap();
        prop_assert_eq!(d, RationalMap::from_polynomial(e));
        let twists = w.twist_vectors().unwrap();
        prop_assert_eq!(&twists, &s.twist_vectors().unwrap());
        let cross = w.cross_boundary_derivative(Border::V1, k).unwrap();
        let curve = s.cross_boundary_derivative(Border::V1, k).unwrap();
        let t = u.clone();
        prop_assert_eq!(cross.eval(&[(Var::U, t.clone())]).unwrap(), cagd_bezier::de_casteljau(curve.points(), &t).unwrap());
        let whole = w.restrict(&r(0, 1), &r(1, 1), &r(0, 1), &r(1, 1)).unwrap().result;
        prop_assert_eq!(whole.mesh(), s.mesh());
    }

    #[test]
    fn the_octant_lies_on_the_unit_sphere(u in unit(), v in unit()) {
        let s = octant();
        let x = s.eval(&qd(&u), &qd(&v)).unwrap();
        prop_assert_eq!(norm2(&x), <Quadratic as FieldOps>::from_i64(1));
        prop_assert!(x.coords().iter().all(|c| *c >= <Quadratic as FieldOps>::from_i64(0)));
        prop_assert_eq!(&x, &s.eval_quotient(&qd(&u), &qd(&v)).unwrap());
    }
}

#[test]
fn octant_closed_form_is_on_the_sphere_identically() {
    let s = octant();
    let c = s.closed_form().unwrap();
    let n = c.numerator();
    let d = c.denominator();
    // N . N = D^2 as polynomials
    assert_eq!(n.dot(n).unwrap(), d * d);
    // the boundary u = 0 is the quarter circle of the equator
    let b = s.boundary(Border::U0).unwrap();
    let h = parse_number("1/3").unwrap();
    let p = b.eval(&h).unwrap();
    assert_eq!(p[2], <Quadratic as FieldOps>::from_i64(0));
    assert_eq!(norm2(&p), <Quadratic as FieldOps>::from_i64(1));
    // restricted, subdivided, elevated: still on the sphere
    let half = parse_number("1/2").unwrap();
    let r = s
        .restrict(
            &<Quadratic as FieldOps>::from_i64(0),
            &half,
            &half,
            &<Quadratic as FieldOps>::from_i64(1),
        )
        .unwrap();
    assert_eq!(
        norm2(&r.result.eval(&half, &half).unwrap()),
        <Quadratic as FieldOps>::from_i64(1)
    );
    assert_eq!(
        norm2(&r.result.mesh().get(0, 0).unwrap().clone()),
        <Quadratic as FieldOps>::from_i64(1)
    );
    let e = s.elevate(1, 1).unwrap();
    assert_eq!(
        norm2(&e.eval(&half, &h).unwrap()),
        <Quadratic as FieldOps>::from_i64(1)
    );
}

#[test]
fn octant_normals_degenerate_at_the_pole() {
    let s = octant();
    // at (0, 0): (25) with weights: (√2/2)^2 (0, 0, 1) x (0, 1, 0)
    let n00 = s.normal_at_corner(Corner::U0V0).unwrap();
    assert_eq!(n00.to_text(), "(-1/2, 0, 0)");
    let n01 = s.normal_at_corner(Corner::U0V1).unwrap();
    assert_eq!(n01.to_text(), "(0, -1/2, 0)");
    for corner in [Corner::U1V0, Corner::U1V1] {
        let n = s.normal_at_corner(corner).unwrap();
        assert!(matches!(
            n,
            NormalAtCorner::Degenerate {
                reason: Degeneracy::RepeatedVertices { .. },
                ..
            }
        ));
        // and the normal field does vanish there
        let (u, v) = if corner == Corner::U1V0 {
            (1, 0)
        } else {
            (1, 1)
        };
        let field = s.normal().unwrap();
        let at = field
            .eval(&[
                (Var::U, <Quadratic as FieldOps>::from_i64(u)),
                (Var::V, <Quadratic as FieldOps>::from_i64(v)),
            ])
            .unwrap();
        assert!(at.is_zero());
    }
    assert_eq!(
        s.normal_at_corner(Corner::U1V0).unwrap().to_text(),
        "degenerate at (1, 0): the vertices c_{2,0} and c_{2,1} coincide, so a difference of (25) is the zero vector"
    );
    // the notes' polynomial mesh alone (weights dropped) degenerates the same way
    let p = BezierSurface::try_new(s.mesh().clone()).unwrap();
    assert!(p.normal_at_corner(Corner::U1V1).unwrap().normal().is_none());
}

#[test]
fn text_of_a_rational_patch() {
    let s = octant();
    assert_eq!(
        s.to_text(),
        "{(1, 0, 0), (1, 1, 0), (0, 1, 0); (1, 0, 1), (1, 1, 1), (0, 1, 1); (0, 0, 1), (0, 0, 1), (0, 0, 1)} \
         with weights {1, √2/2, 1; √2/2, 1/2, √2/2; 1, √2/2, 1}"
    );
}
