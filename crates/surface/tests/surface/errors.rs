//! Bad input gives errors that name the problem, never a panic.

use crate::common::{mesh, patch};
use cagd_linalg::Point;
use cagd_poly::parse_poly;
use cagd_scalar::{q, BigRational};
use cagd_surface::{
    c1_neighbour_rows, continuity, in_convex_hull, BezierSurface, Corner, Grid, Join, Mesh,
    RationalBezierSurface, SurfaceError,
};

type Q = BigRational;

fn bilinear() -> BezierSurface<Q> {
    patch("{(0, 0, 0), (0, 1, 0); (1, 0, 0), (1, 1, 1)}")
}

#[test]
fn ragged_and_mixed_meshes() {
    let p = |c: &[i64]| Point::<Q>::from_ints(c);
    let e = BezierSurface::from_rows(vec![
        vec![p(&[0, 0, 0]), p(&[1, 0, 0])],
        vec![p(&[0, 1, 0])],
    ])
    .unwrap_err();
    assert_eq!(
        e,
        SurfaceError::RaggedMesh {
            row: 1,
            len: 1,
            expected: 2
        }
    );
    assert_eq!(
        e.to_string(),
        "row 1 of the control mesh has 1 points but row 0 has 2: a mesh needs rows of equal length"
    );
    let e = BezierSurface::from_rows(vec![vec![p(&[0, 0, 0]), p(&[1, 0])]]).unwrap_err();
    assert!(matches!(
        e,
        SurfaceError::MixedDimensions { row: 0, col: 1, .. }
    ));
    assert_eq!(
        BezierSurface::<Q>::from_rows(vec![]).unwrap_err(),
        SurfaceError::EmptyMesh
    );
    assert_eq!(
        BezierSurface::<Q>::from_rows(vec![vec![]]).unwrap_err(),
        SurfaceError::EmptyMesh
    );
}

#[test]
fn bad_weights() {
    let m: Mesh<Q> = mesh("{(0, 0, 0), (0, 1, 0); (1, 0, 0), (1, 1, 1)}");
    let shape = Grid::from_rows(vec![vec![q!(1), q!(1), q!(1)]]).unwrap();
    let e = RationalBezierSurface::try_new(m.clone(), shape).unwrap_err();
    assert_eq!(
        e.to_string(),
        "the weights form a 1x3 grid but the mesh is 2x2"
    );
    let zero = Grid::from_rows(vec![vec![q!(1), q!(1)], vec![q!(1), q!(0)]]).unwrap();
    let e = RationalBezierSurface::try_new(m.clone(), zero).unwrap_err();
    assert_eq!(e, SurfaceError::ZeroWeight { row: 1, col: 1 });
    let ragged = Grid::<Q>::from_rows(vec![vec![q!(1), q!(1)], vec![q!(1)]]);
    assert!(matches!(ragged, Err(SurfaceError::RaggedMesh { .. })));
    // negative weights are allowed, but the convex-hull property is refused
    let neg = Grid::from_rows(vec![vec![q!(1), q!(-1)], vec![q!(1), q!(1)]]).unwrap();
    let s = RationalBezierSurface::try_new(m.clone(), neg).unwrap();
    let e = s.in_convex_hull(&Point::from_ints(&[0, 0, 0])).unwrap_err();
    assert_eq!(
        e.to_string(),
        "weight w_0,1 (the convex-hull property needs positive weights) must be positive, but it is -1"
    );
    // and a vanishing denominator is an error: w(1/2, 0) = 1/2 - 1/2 = 0
    let half = Grid::from_rows(vec![vec![q!(1), q!(1)], vec![q!(-1), q!(1)]]).unwrap();
    let s = RationalBezierSurface::try_new(m, half).unwrap();
    let e = s.eval(&q!(1 / 2), &q!(0)).unwrap_err();
    assert_eq!(
        e.to_string(),
        "the denominator of the rational patch vanishes at (u, v) = (1/2, 0): the point is at infinity"
    );
    assert!(s.closed_form().is_ok());
}

#[test]
fn parameters_out_of_range() {
    let s = bilinear();
    let e = s.eval(&q!(0), &q!(-1 / 2)).unwrap_err();
    assert_eq!(
        e.to_string(),
        "parameter v = -1/2 is outside the domain [0, 1] x [0, 1]"
    );
    // the raw algorithms extrapolate
    assert_eq!(s.eval_matrix(&q!(2), &q!(3)).to_text(), "(2, 3, 6)");
    let t = s.clone().with_domain(q!(1), q!(2), q!(0), q!(1)).unwrap();
    assert!(t.eval(&q!(1 / 2), &q!(0)).is_err());
    assert_eq!(
        s.clone()
            .with_domain(q!(2), q!(1), q!(0), q!(1))
            .unwrap_err()
            .to_string(),
        "the interval [2, 1] of u is degenerate: its ends must satisfy 2 < 1"
    );
    assert!(matches!(
        s.restrict(&q!(0), &q!(1), &q!(1 / 2), &q!(1 / 2)),
        Err(SurfaceError::DegenerateDomain { param: "v", .. })
    ));
    assert_eq!(
        s.subdivide(&q!(1), &q!(1 / 2)).unwrap_err().to_string(),
        "subdivision parameter u = 1 must lie strictly inside (0, 1)"
    );
}

#[test]
fn wrong_numbers_of_arguments_and_orders() {
    let s = bilinear();
    assert_eq!(
        s.blossom(&[q!(0), q!(1)], &[q!(0)])
            .unwrap_err()
            .to_string(),
        "the polar form takes 1 values of u (the degree in u), but 2 were given"
    );
    assert_eq!(
        s.forward_differences(2, 0).unwrap_err().to_string(),
        "the differences Δ^{2,0} need bidegree at least (2, 0), but the patch has bidegree (1, 1)"
    );
    assert!(c1_neighbour_rows(&s, 2, &q!(1), &q!(1)).is_err());
    assert!(matches!(
        c1_neighbour_rows(&s, 1, &q!(0), &q!(1)),
        Err(SurfaceError::NotPositive { .. })
    ));
}

#[test]
fn graph_degrees() {
    let f = parse_poly::<Q>("x y^2").unwrap();
    assert_eq!(
        BezierSurface::graph(&f, 1, 1).unwrap_err().to_string(),
        "f has degree 2 in y: its graph needs degree at least 2 in v, but the patch has degree 1"
    );
    assert!(BezierSurface::graph(&parse_poly::<Q>("1").unwrap(), 0, 1).is_err());
    assert!(BezierSurface::graph(&parse_poly::<Q>("x z").unwrap(), 1, 1).is_err());
    assert!(BezierSurface::graph(&parse_poly::<Q>("u v").unwrap(), 1, 1).is_ok());
}

#[test]
fn normals_need_three_dimensions() {
    let s = patch::<Q>("{(0, 0), (0, 1); (1, 0), (1, 1)}");
    assert_eq!(
        s.normal().unwrap_err().to_string(),
        "the normal c_u x c_v needs points with 3 coordinates, but they have 2"
    );
    assert!(s.normal_at_corner(Corner::U0V0).is_err());
    let curve = patch::<Q>("{(0, 0, 0), (1, 2, 3)}");
    assert_eq!(
        curve.normal_at_corner(Corner::U0V0).unwrap().to_text(),
        "degenerate at (0, 0): the patch has degree 0 in u: it has no tangent direction in u"
    );
}

#[test]
fn joins_that_do_not_share_a_border() {
    let s = bilinear();
    let t = patch::<Q>("{(1, 0, 0), (1, 1/2, 0), (1, 1, 1); (2, 0, 0), (2, 1/2, 0), (2, 1, 0)}");
    assert_eq!(
        continuity(&s, &t, Join::U, &q!(1), &q!(1))
            .unwrap_err()
            .to_string(),
        "the patches do not share a border: along v the first has degree 1 and the second degree 2"
    );
    let flat = patch::<Q>("{(1, 0), (1, 1); (2, 0), (2, 1)}");
    assert!(matches!(
        continuity(&s, &flat, Join::U, &q!(1), &q!(1)),
        Err(SurfaceError::Dimension { .. })
    ));
    assert!(continuity(&s, &s, Join::U, &q!(-1), &q!(1)).is_err());
    // a patch is not C^0 with itself across u: its first and last rows differ
    let k = continuity(&s, &s, Join::U, &q!(1), &q!(1)).unwrap();
    assert_eq!(
        k.to_text(),
        "not C^0; C^0 fails at j = 0: c_{1,0} = (1, 0, 0) but c~_{0,0} = (0, 0, 0)"
    );
    // across v the labels follow the columns
    let k = continuity(&s, &s, Join::V, &q!(1), &q!(1)).unwrap();
    assert_eq!(
        k.failure.unwrap().text,
        "C^0 fails at i = 0: c_{0,1} = (0, 1, 0) but c~_{0,0} = (0, 0, 0)"
    );
}

#[test]
fn convex_hull_input() {
    let pts: Vec<Point<Q>> = vec![Point::from_ints(&[0, 0]), Point::from_ints(&[1, 1])];
    assert!(in_convex_hull(&pts, &Point::from_ints(&[1, 1, 1])).is_err());
    assert_eq!(
        in_convex_hull::<Q>(&[], &Point::from_ints(&[0])).unwrap_err(),
        SurfaceError::EmptyMesh
    );
    // a segment: the midpoint is in, a point beside it is not
    assert!(in_convex_hull(&pts, &Point::new(vec![q!(1 / 2), q!(1 / 2)])).unwrap());
    assert!(!in_convex_hull(&pts, &Point::new(vec![q!(1 / 2), q!(1 / 3)])).unwrap());
    assert!(!in_convex_hull(&pts, &Point::from_ints(&[2, 2])).unwrap());
}
