//! Property tests: the points drawn are the exact points of the surface, computed by an
//! independent route (De Casteljau of cagd-surface against the closed forms used here).

use cagd_linalg::Point;
use cagd_poly::Var;
use cagd_render::{tessellate, Scene};
use cagd_scalar::{BigInt, BigRational, ExactRational};
use cagd_surface::{BezierSurface, RationalBezierSurface};
use proptest::prelude::*;

fn rational() -> impl Strategy<Value = BigRational> {
    (-9i64..=9, 1i64..=9).prop_map(|(n, d)| BigRational::new(BigInt::from(n), BigInt::from(d)))
}

fn positive() -> impl Strategy<Value = BigRational> {
    (1i64..=9, 1i64..=9).prop_map(|(n, d)| BigRational::new(BigInt::from(n), BigInt::from(d)))
}

fn mesh(m: usize, n: usize) -> impl Strategy<Value = Vec<Vec<Point<BigRational>>>> {
    prop::collection::vec(
        prop::collection::vec(
            prop::collection::vec(rational(), 3).prop_map(Point::new),
            n + 1,
        ),
        m + 1,
    )
}

fn params(k: usize, n: usize) -> BigRational {
    BigRational::new(BigInt::from(k as i64), BigInt::from(n as i64))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn tessellation_vertices_are_de_casteljau_points(
        (m, n) in (1usize..=3, 1usize..=3),
        seed in mesh(3, 3),
    ) {
        let rows: Vec<Vec<Point<BigRational>>> =
            seed.iter().take(m + 1).map(|r| r.iter().take(n + 1).cloned().collect()).collect();
        let patch = BezierSurface::from_rows(rows).unwrap();
        let mut scene = Scene::new();
        scene.add_surface("s", patch.clone());
        let t = &tessellate(&scene, 3).unwrap()[0];
        let normal = patch.normal().unwrap();
        for k in 0..=3 {
            for l in 0..=3 {
                let (u, v) = (params(k, 3), params(l, 3));
                let exact = patch.de_casteljau_rows_first(&u, &v).unwrap().to_f64();
                prop_assert_eq!(t.vertices[4 * k + l].to_vec(), exact);
                let nn = normal.eval(&[(Var::U, u), (Var::V, v)]).unwrap();
                if !nn.is_zero() {
                    let f = nn.to_f64();
                    let len = (f[0] * f[0] + f[1] * f[1] + f[2] * f[2]).sqrt();
                    for c in 0..3 {
                        prop_assert!((t.normals[4 * k + l][c] - f[c] / len).abs() < 1e-12);
                    }
                }
            }
        }
    }

    #[test]
    fn rational_tessellation_matches_the_quotient(
        seed in mesh(2, 2),
        weights in prop::collection::vec(prop::collection::vec(positive(), 3), 3),
    ) {
        let patch = RationalBezierSurface::from_rows(seed, weights).unwrap();
        let mut scene = Scene::new();
        scene.add_surface("r", patch.clone());
        let t = &tessellate(&scene, 2).unwrap()[0];
        for k in 0..=2 {
            for l in 0..=2 {
                let p = patch.eval_quotient(&params(k, 2), &params(l, 2)).unwrap();
                prop_assert_eq!(t.vertices[3 * k + l].to_vec(), p.to_f64());
            }
        }
    }
}

#[test]
fn f64_scenes_draw_too() {
    // the same patch over f64 (figures only) gives the same tessellation up to rounding
    let exact = crate::scenes::coons_patch::<BigRational>();
    let float = crate::scenes::coons_patch::<f64>();
    let (mut a, mut b) = (Scene::new(), Scene::new());
    a.add_surface("s", exact);
    b.add_surface("s", float);
    let (ta, tb) = (
        &tessellate(&a, 4).unwrap()[0],
        &tessellate(&b, 4).unwrap()[0],
    );
    for (p, q) in ta.vertices.iter().zip(&tb.vertices) {
        for c in 0..3 {
            assert!((p[c] - q[c]).abs() < 1e-12);
        }
    }
    assert!(!f64::is_exact());
}
