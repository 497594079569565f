//! The fast exact paths (integer matrix products) against the step-by-step algorithms, on
//! random rational data: the same exact values.

use crate::common::{random_mesh, random_patch, rat, unit};
use cagd_bezier::{elevate_degree, restrict};
use cagd_linalg::Point;
use cagd_scalar::{BigRational, FieldOps, Quadratic, Scalar};
use cagd_surface::{BezierSurface, Mesh, SurfaceError};
use proptest::prelude::*;

type Q = BigRational;

fn qr(x: &Q) -> Quadratic {
    Quadratic::from_rational(x.clone())
}

/// The mesh over Q(√2) with the same rational values (still rational: the fast path again).
fn quadratic(mesh: &Mesh<Q>) -> Mesh<Quadratic> {
    mesh.map(|p| Point::new(p.coords().iter().map(qr).collect()))
}

/// A mesh over Q(√2) with a root part in every coordinate: the generic path.
fn with_root(mesh: &Mesh<Q>) -> Mesh<Quadratic> {
    let r2 = Quadratic::sqrt_of(&Q::from_i64(2)).unwrap();
    mesh.map(|p| Point::new(p.coords().iter().map(|x| qr(x) + &r2).collect()))
}

fn elevate_by_curves<S: Scalar>(mesh: &Mesh<S>, r: usize, s: usize) -> Mesh<S> {
    let cols = mesh
        .map_columns(|c| Ok::<_, SurfaceError>(elevate_degree(c, r).unwrap()))
        .unwrap();
    cols.map_rows(|row| Ok::<_, SurfaceError>(elevate_degree(row, s).unwrap()))
        .unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn eval_equals_de_casteljau(s in random_patch(), u in unit(), v in unit()) {
        let x = s.eval(&u, &v).unwrap();
        prop_assert_eq!(&x, &s.de_casteljau_columns_first(&u, &v).unwrap());
        prop_assert_eq!(&x, &s.de_casteljau_columns_first_recorded(&u, &v, &mut Vec::new()).unwrap());
        // the same values over Q(√2), fast path and generic path
        let q = BezierSurface::try_new(quadratic(s.mesh())).unwrap();
        let (qu, qv) = (qr(&u), qr(&v));
        let qx = q.eval(&qu, &qv).unwrap();
        prop_assert_eq!(qx.to_text(), x.to_text());
        let root = BezierSurface::try_new(with_root(s.mesh())).unwrap();
        prop_assert_eq!(root.eval(&qu, &qv).unwrap(), root.de_casteljau_rows_first(&qu, &qv).unwrap());
    }

    #[test]
    fn eval_with_long_numbers_equals_de_casteljau(
        mesh in random_mesh(6, 3),
        (p, q) in (0u64..=u64::MAX / 2, 1u64..=u64::MAX / 2),
        (a, b) in (0u64..=1000, 1u64..=1000),
        long in prop::bool::ANY,
    ) {
        // parameters of 20 digits (u^m past machine integers), a mesh of 40-digit numbers or
        // of small ones, wide or tall: the reduction over q_u, q_v and the mesh's denominator
        let (p, q) = (Q::from(cagd_scalar::BigInt::from(p.min(q))), Q::from(cagd_scalar::BigInt::from(p.max(q))));
        let u = p / q;
        let v = Q::from_ratio(a.min(b) as i64, a.max(b) as i64);
        let big = Q::from_i64(10).powi(40) / Q::from_i64(3);
        let mesh = if long { mesh.map(|x| x.scale(&big)) } else { mesh };
        let s = BezierSurface::try_new(mesh).unwrap();
        prop_assert_eq!(s.eval(&u, &v).unwrap(), s.de_casteljau_columns_first(&u, &v).unwrap());
        prop_assert_eq!(s.eval(&v, &u).unwrap(), s.de_casteljau_rows_first(&v, &u).unwrap());
    }

    #[test]
    fn eval_extrapolates_like_de_casteljau(s in random_patch(), u in rat(), v in rat()) {
        // outside [0, 1] the matrix form on integers still agrees (negative numerators)
        let t = s.clone().with_domain(Q::from_i64(-9), Q::from_i64(9), Q::from_i64(-9), Q::from_i64(9)).unwrap();
        prop_assert_eq!(t.eval(&u, &v).unwrap(), t.de_casteljau_columns_first(&u, &v).unwrap());
    }

    #[test]
    fn elevation_equals_curve_elevation_in_two_passes(mesh in random_mesh(4, 3), r in 0usize..4, s in 0usize..4) {
        let patch = BezierSurface::try_new(mesh.clone()).unwrap();
        let fast = patch.elevate(r, s).unwrap();
        prop_assert_eq!(fast.mesh(), &elevate_by_curves(&mesh, r, s));
        let root = BezierSurface::try_new(with_root(&mesh)).unwrap();
        let elevated = root.elevate(r, s).unwrap();
        prop_assert_eq!(elevated.mesh(), &elevate_by_curves(&with_root(&mesh), r, s));
    }

    #[test]
    fn restriction_equals_curve_restriction_and_the_blossom(
        mesh in random_mesh(4, 3), a in rat(), b in rat(), c in rat(), d in rat(),
    ) {
        prop_assume!(a < b && c < d);
        let patch = BezierSurface::try_new(mesh.clone()).unwrap();
        let r = patch.restrict(&a, &b, &c, &d).unwrap();
        let rows = mesh
            .map_rows(|row| Ok::<_, SurfaceError>(restrict(row, &c, &d).unwrap()))
            .unwrap();
        prop_assert_eq!(r.rows_step.mesh(), &rows);
        let cols = rows
            .map_columns(|col| Ok::<_, SurfaceError>(restrict(col, &a, &b).unwrap()))
            .unwrap();
        prop_assert_eq!(r.result.mesh(), &cols);
        let (m, n) = patch.bidegree();
        let (i, j) = (m / 2, n / 2);
        let us: Vec<Q> = (0..m).map(|k| if k < m - i { a.clone() } else { b.clone() }).collect();
        let vs: Vec<Q> = (0..n).map(|k| if k < n - j { c.clone() } else { d.clone() }).collect();
        prop_assert_eq!(r.result.mesh().get(i, j).unwrap(), &patch.blossom(&us, &vs).unwrap());
    }
}
