//! Property tests on random polynomial patches, each against an independent route.

use crate::common::{interior, r, random_domain, random_mesh, random_patch, rat, unit};
use cagd_linalg::Point;
use cagd_poly::{from_bernstein_1d, Poly, Var, VecPoly};
use cagd_scalar::{BigRational, FieldOps};
use cagd_surface::{
    c1_neighbour_columns, c1_neighbour_rows, continuity, in_convex_hull, BezierSurface, Border,
    Corner, Join, NormalAtCorner, Smoothness,
};
use proptest::prelude::*;

type Q = BigRational;

fn at(c: &VecPoly<Q>, u: &Q, v: &Q) -> Point<Q> {
    c.eval(&[(Var::U, u.clone()), (Var::V, v.clone())]).unwrap()
}

fn affine(a: &Q, b: &Q, t: &Q) -> Q {
    a.clone() + (b.clone() - a) * t
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn matrix_form_equals_de_casteljau_in_both_orders(s in random_patch(), u in rat(), v in rat()) {
        let x = s.eval_matrix(&u, &v);
        prop_assert_eq!(&x, &s.de_casteljau_columns_first(&u, &v).unwrap());
        prop_assert_eq!(&x, &s.de_casteljau_rows_first(&u, &v).unwrap());
        prop_assert_eq!(&x, &s.de_casteljau_columns_first_recorded(&u, &v, &mut Vec::new()).unwrap());
        prop_assert_eq!(&x, &at(&s.closed_form().unwrap(), &u, &v));
    }

    #[test]
    fn eval_on_a_domain_is_the_reparametrization(s in random_patch(), d in random_domain(), p in unit(), q in unit()) {
        let t = s.clone().with_domain(d.0.clone(), d.1.clone(), d.2.clone(), d.3.clone()).unwrap();
        let (u, v) = (affine(&d.0, &d.1, &p), affine(&d.2, &d.3, &q));
        prop_assert_eq!(t.eval(&u, &v).unwrap(), s.eval(&p, &q).unwrap());
        prop_assert_eq!(at(&t.closed_form().unwrap(), &u, &v), s.eval(&p, &q).unwrap());
    }

    #[test]
    fn blossom_is_symmetric_multiaffine_with_the_surface_on_the_diagonal(
        s in random_patch(), args in prop::collection::vec(rat(), 6), x in rat(), y in rat(), t in rat(), u in rat(), v in rat(),
    ) {
        let (m, n) = s.bidegree();
        let us: Vec<Q> = args.iter().take(m).cloned().collect();
        let vs: Vec<Q> = args.iter().rev().take(n).cloned().collect();
        let b = s.blossom(&us, &vs).unwrap();
        prop_assert_eq!(&b, &s.blossom_rows_first(&us, &vs).unwrap());
        let (mut ru, mut rv) = (us.clone(), vs.clone());
        ru.reverse();
        rv.rotate_left(usize::from(n > 0));
        prop_assert_eq!(&b, &s.blossom(&ru, &rv).unwrap());
        // affine in the first u argument
        if m > 0 {
            let mut ux = us.clone();
            let mut uy = us.clone();
            let mut ut = us.clone();
            ux[0] = x.clone();
            uy[0] = y.clone();
            ut[0] = affine(&x, &y, &t);
            let bx = s.blossom(&ux, &vs).unwrap();
            let by = s.blossom(&uy, &vs).unwrap();
            prop_assert_eq!(s.blossom(&ut, &vs).unwrap(), bx.lerp(&by, &t));
        }
        // and in the last v argument
        if n > 0 {
            let mut vx = vs.clone();
            let mut vy = vs.clone();
            let mut vt = vs.clone();
            vx[n - 1] = x.clone();
            vy[n - 1] = y.clone();
            vt[n - 1] = affine(&x, &y, &t);
            let bx = s.blossom(&us, &vx).unwrap();
            let by = s.blossom(&us, &vy).unwrap();
            prop_assert_eq!(s.blossom(&us, &vt).unwrap(), bx.lerp(&by, &t));
        }
        prop_assert_eq!(s.blossom(&vec![u.clone(); m], &vec![v.clone(); n]).unwrap(), s.eval_matrix(&u, &v));
    }

    #[test]
    fn restriction_keeps_the_surface(s in random_patch(), a in rat(), b in rat(), c in rat(), d in rat(), p in unit(), q in unit()) {
        prop_assume!(a < b && c < d);
        let res = s.restrict(&a, &b, &c, &d).unwrap();
        let (u, v) = (affine(&a, &b, &p), affine(&c, &d, &q));
        let x = s.eval_matrix(&u, &v);
        prop_assert_eq!(&res.result.eval(&u, &v).unwrap(), &x);
        // over [0, 1]^2 the same mesh at the mapped parameters
        let unit_square = res.result.clone().with_domain(r(0, 1), r(1, 1), r(0, 1), r(1, 1)).unwrap();
        prop_assert_eq!(&unit_square.eval(&p, &q).unwrap(), &x);
        // the row step is the surface restricted in v only
        prop_assert_eq!(&res.rows_step.eval_matrix(&u, &v), &x);
        // (13): c̃_ij = c[a^<m-i>, b^<i>; c^<n-j>, d^<j>]
        let (m, n) = s.bidegree();
        let us: Vec<Q> = (0..m).map(|k| if k < m - 1 { a.clone() } else { b.clone() }).collect();
        let vs: Vec<Q> = (0..n).map(|k| if k < 1 { c.clone() } else { d.clone() }).collect();
        let (i, j) = (usize::from(m > 0), n.saturating_sub(1));
        prop_assert_eq!(res.result.mesh().get(i, j).unwrap(), &s.blossom(&us, &vs).unwrap());
    }

    #[test]
    fn subdivision_keeps_the_surface(s in random_patch(), u0 in interior(), v0 in interior(), p in unit(), q in unit()) {
        let pieces = s.subdivide(&u0, &v0).unwrap();
        for row in &pieces {
            for piece in row {
                let (a, b) = piece.domain().u_interval();
                let (c, d) = piece.domain().v_interval();
                let (u, v) = (affine(a, b, &p), affine(c, d, &q));
                prop_assert_eq!(piece.eval(&u, &v).unwrap(), s.eval(&u, &v).unwrap());
            }
        }
        prop_assert_eq!(pieces[1][1].corner(Corner::U0V0), s.eval(&u0, &v0).unwrap());
    }

    #[test]
    fn elevation_keeps_the_surface(s in random_patch(), r in 0usize..=2, t in 0usize..=2, u in rat(), v in rat()) {
        let e = s.elevate(r, t).unwrap();
        let (m, n) = s.bidegree();
        prop_assert_eq!(e.bidegree(), (m + r, n + t));
        prop_assert_eq!(e.eval_matrix(&u, &v), s.eval_matrix(&u, &v));
        prop_assert_eq!(e.closed_form().unwrap(), s.closed_form().unwrap());
        prop_assert_eq!(s.elevate_u().unwrap().elevate_v().unwrap(), s.elevate(1, 1).unwrap());
    }

    #[test]
    fn corners_and_boundaries_are_the_mesh(s in random_patch(), d in random_domain(), p in unit()) {
        let s = s.with_domain(d.0.clone(), d.1.clone(), d.2.clone(), d.3.clone()).unwrap();
        let (m, n) = s.bidegree();
        let mesh = s.mesh();
        for (corner, (u, v)) in Corner::ALL.iter().zip([(&d.0, &d.2), (&d.1, &d.2), (&d.0, &d.3), (&d.1, &d.3)]) {
            let (i, j) = corner.index(m, n);
            prop_assert_eq!(&s.eval(u, v).unwrap(), mesh.get(i, j).unwrap());
            prop_assert_eq!(&s.corner(*corner), mesh.get(i, j).unwrap());
        }
        let (u, v) = (affine(&d.0, &d.1, &p), affine(&d.2, &d.3, &p));
        prop_assert_eq!(s.boundary(Border::U0).unwrap().eval(&v).unwrap(), s.eval(&d.0, &v).unwrap());
        prop_assert_eq!(s.boundary(Border::U1).unwrap().eval(&v).unwrap(), s.eval(&d.1, &v).unwrap());
        prop_assert_eq!(s.boundary(Border::V0).unwrap().eval(&u).unwrap(), s.eval(&u, &d.2).unwrap());
        prop_assert_eq!(s.boundary(Border::V1).unwrap().eval(&u).unwrap(), s.eval(&u, &d.3).unwrap());
        let (b0, b1) = (s.boundary(Border::U0).unwrap(), s.boundary(Border::V1).unwrap());
        prop_assert_eq!(b0.points(), mesh.row(0).unwrap());
        prop_assert_eq!(b1.points(), &mesh.column(n).unwrap()[..]);
    }

    #[test]
    fn derivative_patches_are_the_partials_of_the_closed_form(s in random_patch(), d in random_domain(), r in 0usize..=4, t in 0usize..=4) {
        let s = s.with_domain(d.0.clone(), d.1.clone(), d.2.clone(), d.3.clone()).unwrap();
        let mut c = s.closed_form().unwrap();
        for _ in 0..r { c = c.partial(Var::U); }
        for _ in 0..t { c = c.partial(Var::V); }
        prop_assert_eq!(s.partial_derivative(r, t).unwrap().closed_form().unwrap(), c);
        // cross-boundary derivatives (19)-(20): the partial on the border
        let du = s.closed_form().unwrap();
        let mut dr = du.clone();
        for _ in 0..r { dr = dr.partial(Var::U); }
        let curve = s.cross_boundary_derivative(Border::U1, r).unwrap();
        let (c0, c1) = s.domain().v_interval();
        let local = from_bernstein_1d(curve.points(), Var::V).unwrap().reparametrize_affine(Var::V, c0, c1).unwrap();
        prop_assert_eq!(local, dr.substitute_value(Var::U, &d.1));
        let mut dv = du;
        for _ in 0..t { dv = dv.partial(Var::V); }
        let curve = s.cross_boundary_derivative(Border::V0, t).unwrap();
        let (a0, a1) = s.domain().u_interval();
        let local = from_bernstein_1d(curve.points(), Var::U).unwrap().reparametrize_affine(Var::U, a0, a1).unwrap();
        prop_assert_eq!(local, dv.substitute_value(Var::V, &d.2));
    }

    #[test]
    fn differences_and_twists_match_the_definitions(s in random_patch()) {
        let (m, n) = s.bidegree();
        if m >= 1 && n >= 1 {
            let d = s.forward_differences(1, 1).unwrap();
            let c = s.mesh();
            for i in 0..m {
                for j in 0..n {
                    let expected = &(&(c.get(i + 1, j + 1).unwrap() - c.get(i + 1, j).unwrap()) - c.get(i, j + 1).unwrap()) + c.get(i, j).unwrap();
                    prop_assert_eq!(d.get(i, j).unwrap(), &expected);
                }
            }
            let mn = <Q as FieldOps>::from_i64(i64::try_from(m * n).unwrap());
            prop_assert_eq!(s.twist_vectors().unwrap()[0].clone(), d.get(0, 0).unwrap().scale(&mn));
            prop_assert_eq!(s.twist_vectors().unwrap()[3].clone(), d.get(m - 1, n - 1).unwrap().scale(&mn));
        }
        let tw = s.closed_form().unwrap().partial(Var::U).partial(Var::V);
        let corners = [(0, 0), (1, 0), (0, 1), (1, 1)];
        for (t, (u, v)) in s.twist_vectors().unwrap().iter().zip(corners) {
            prop_assert_eq!(t, &at(&tw, &<Q as FieldOps>::from_i64(u), &<Q as FieldOps>::from_i64(v)));
        }
    }

    #[test]
    fn corner_normals_are_the_normal_field_over_mn(s in random_patch()) {
        let (m, n) = s.bidegree();
        let field = s.normal().unwrap();
        let mn = <Q as FieldOps>::from_i64(i64::try_from(m * n).unwrap());
        let corners = [(0, 0), (1, 0), (0, 1), (1, 1)];
        for (corner, (u, v)) in Corner::ALL.iter().zip(corners) {
            let exact = at(&field, &<Q as FieldOps>::from_i64(u), &<Q as FieldOps>::from_i64(v));
            match s.normal_at_corner(*corner).unwrap() {
                NormalAtCorner::Normal(p) => prop_assert_eq!(exact, p.scale(&mn)),
                NormalAtCorner::Degenerate { .. } => prop_assert!(exact.is_zero()),
            }
        }
    }

    #[test]
    fn points_of_the_patch_lie_in_the_convex_hull(mesh in random_mesh(2, 3), u in unit(), v in unit(), far in 10i64..20) {
        let s = BezierSurface::try_new(mesh).unwrap();
        prop_assert!(s.in_convex_hull(&s.eval(&u, &v).unwrap()).unwrap());
        prop_assert!(!s.in_convex_hull(&Point::from_ints(&[far, 0, 0])).unwrap());
        // an independent check in the plane: hull of a triangle by signs of areas
        let tri: Vec<Point<Q>> = vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 0]), Point::from_ints(&[0, 1])];
        let inside = u.clone() + &v <= r(1, 1);
        prop_assert_eq!(in_convex_hull(&tri, &Point::new(vec![u, v])).unwrap(), inside);
    }

    #[test]
    fn c_r_neighbours_join_with_c_r(s in random_patch(), r in 0usize..=3, du0 in crate::common::positive(), du1 in crate::common::positive(), extra in random_mesh(3, 3)) {
        let (m, n) = s.bidegree();
        prop_assume!(r <= m);
        let mut rows = c1_neighbour_rows(&s, r, &du0, &du1).unwrap().to_rows();
        // free rows: anything of the right length
        for i in r + 1..=m {
            rows.push((0..=n).map(|j| extra.get(i % extra.rows(), j % extra.cols()).unwrap().clone()).collect());
        }
        let next = BezierSurface::from_rows(rows).unwrap();
        let k = continuity(&s, &next, Join::U, &du0, &du1).unwrap();
        match k.smoothness {
            Smoothness::C(q) => prop_assert!(q >= r),
            Smoothness::Infinite => {}
            Smoothness::NotContinuous => prop_assert!(false, "not even C^0"),
        }
        // the same across v
        let (_, n) = s.bidegree();
        if r <= n {
            let cols = c1_neighbour_columns(&s, r, &du0, &du1).unwrap();
            let mut columns = cols.to_columns();
            for j in r + 1..=n {
                columns.push(s.mesh().column(j).unwrap());
            }
            let next = BezierSurface::try_new(cagd_surface::Mesh::from_columns(columns).unwrap()).unwrap();
            let k = continuity(&s, &next, Join::V, &du0, &du1).unwrap();
            prop_assert!(!matches!(k.smoothness, Smoothness::NotContinuous));
            if let Smoothness::C(q) = k.smoothness { prop_assert!(q >= r) }
        }
    }

    #[test]
    fn pieces_of_one_patch_join_smoothly(s in random_patch(), u0 in interior()) {
        let (a, b) = (s.restrict(&r(0, 1), &u0, &r(0, 1), &r(1, 1)).unwrap().result,
                      s.restrict(&u0, &r(1, 1), &r(0, 1), &r(1, 1)).unwrap().result);
        let du1 = r(1, 1) - &u0;
        let k = continuity(&a, &b, Join::U, &u0, &du1).unwrap();
        prop_assert_eq!(k.smoothness, Smoothness::Infinite);
        prop_assert_eq!(k.derivative_first, k.derivative_second);
        prop_assert_eq!(k.normal_first, k.normal_second);
        // and across v
        let (c, d) = (s.restrict(&r(0, 1), &r(1, 1), &r(0, 1), &u0).unwrap().result,
                      s.restrict(&r(0, 1), &r(1, 1), &u0, &r(1, 1)).unwrap().result);
        let k = continuity(&c, &d, Join::V, &u0, &du1).unwrap();
        prop_assert_eq!(k.smoothness, Smoothness::Infinite);
        prop_assert_eq!(k.normal_first, k.normal_second);
        // a patch is C^∞ with its own continuation past u = 1
        let e = s.restrict(&r(1, 1), &r(2, 1), &r(0, 1), &r(1, 1)).unwrap().result;
        let k = continuity(&s, &e, Join::U, &r(1, 1), &r(1, 1)).unwrap();
        prop_assert_eq!(k.smoothness, Smoothness::Infinite);
    }

    #[test]
    fn graph_of_a_random_polynomial(coefs in prop::collection::vec(rat(), 16), m in 1usize..=3, n in 1usize..=3) {
        let mut f = Poly::<Q>::zero();
        for k in 0..=m {
            for l in 0..=n {
                f = f + Poly::monomial(coefs[k * 4 + l].clone(), &[(Var::X, k as u32), (Var::Y, l as u32)]);
            }
        }
        let g = BezierSurface::graph(&f, m, n).unwrap();
        let fuv = f.substitute(Var::X, &Poly::var(Var::U)).substitute(Var::Y, &Poly::var(Var::V));
        let expected = VecPoly::new(vec![Poly::var(Var::U), Poly::var(Var::V), fuv]);
        prop_assert_eq!(g.closed_form().unwrap(), expected);
    }
}

#[test]
fn one_patch_over_f64() {
    let p = |c: &[i64]| Point::<f64>::from_ints(c);
    let s = BezierSurface::from_rows(vec![
        vec![p(&[0, 0, 0]), p(&[1, 0, 4]), p(&[2, 0, 3])],
        vec![p(&[0, 2, 1]), p(&[1, 2, 5]), p(&[2, 2, 4])],
        vec![p(&[0, 4, 0]), p(&[1, 4, 4]), p(&[2, 4, 3])],
    ])
    .unwrap();
    let x = s.eval(&0.5, &(1.0 / 3.0)).unwrap();
    let expected = [2.0 / 3.0, 2.0, 47.0 / 18.0];
    for (a, b) in x.coords().iter().zip(expected) {
        assert!((a - b).abs() < 1e-12, "{a} vs {b}");
    }
    let y = s.eval_matrix(&0.5, &(1.0 / 3.0));
    assert!(x
        .coords()
        .iter()
        .zip(y.coords())
        .all(|(a, b)| (a - b).abs() < 1e-12));
    let r = s.restrict(&0.5, &1.0, &(1.0 / 3.0), &1.0).unwrap();
    let c = r.result.mesh().get(1, 1).unwrap();
    assert!((c[2] - 25.0 / 6.0).abs() < 1e-12);
}
