//! The worked examples of chapter 5, reproduced exactly.

use crate::common::{mesh, patch, r, vp};
use cagd_linalg::Point;
use cagd_poly::{parse_poly, Var};
use cagd_scalar::{q, BigRational};
use cagd_surface::{
    c1_neighbour_rows, continuity, BezierSurface, Border, Corner, DeCasteljauStep, Degeneracy,
    Join, NormalAtCorner, Smoothness,
};

const BIQUADRATIC: &str = "{(0, 0, 0), (1, 0, 4), (2, 0, 3); \
                           (0, 2, 1), (1, 2, 5), (2, 2, 4); \
                           (0, 4, 0), (1, 4, 4), (2, 4, 3)}";
const JOIN_FIRST: &str = "{(-1, -2, 0), (0, -1, 1), (1, -2, 0); \
                          (-1, -1, 0), (0, 0, 1), (1, -1, 0); \
                          (-1, 0, 0), (0, 0, 0), (1, 0, 0)}";
const JOIN_SECOND: &str = "{(-1, 0, 0), (0, 0, 0), (1, 0, 0); \
                           (-1, 1, 0), (0, 0, -2), (1, 1, 0); \
                           (-1, 2, 0), (0, 1, -2), (1, 2, 0)}";

fn xy() -> BezierSurface<BigRational> {
    patch("{(0, 0, 0), (0, 1, 0); (1, 0, 0), (1, 1, 1)}")
}

#[test]
fn closed_form_of_the_bidegree_2_3_mesh() {
    // §2: the last vertex is (2, 4, -3) as printed; the printed closed form is computed from it
    let s = patch::<BigRational>(
        "{(0, 0, -1), (1, 0, 4), (2, 0, 3), (3, 0, -3); \
          (0, 2, 2), (1, 2, 5), (2, 2, 6), (3, 2, 3); \
          (0, 4, -2), (1, 4, 4), (2, 4, 3), (2, 4, -3)}",
    );
    assert_eq!(s.bidegree(), (2, 3));
    // as printed, with a space between the variables of a term: the expression reader takes
    // `uv^3` as (uv)^3
    let printed = vp(
        "(-u^2 v^3 + 3v, 4u, 7u^2 v^3 - 6u v^3 + v^3 - 27u^2 v^2 + 24u v^2 \
                      - 18v^2 + 15u^2 v - 12u v + 15v - 7u^2 + 6u - 1)",
    );
    let c = s.closed_form().unwrap();
    assert_eq!(c, printed);
    // the matrix form (1) at a point agrees with the closed form
    let (u, v) = (q!(1 / 3), q!(3 / 4));
    assert_eq!(
        s.eval_matrix(&u, &v),
        c.eval(&[(Var::U, u), (Var::V, v)]).unwrap()
    );
}

#[test]
fn closed_form_of_the_bidegree_1_2_mesh_and_its_line() {
    // §3: no variation diminishing; the line (1, 1/2, u) lies on the patch at v = 1/2
    let s =
        patch::<BigRational>("{(0, 0, 0), (1, 1, 0), (2, 0, 0); (0, 0, 1), (1, 1, 1), (2, 0, 1)}");
    assert_eq!(s.closed_form().unwrap(), vp("(2v, 2v - 2v^2, u)"));
    for u in [q!(0), q!(1 / 4), q!(1)] {
        let x = s.eval(&u, &q!(1 / 2)).unwrap();
        assert_eq!(x, Point::new(vec![q!(1), q!(1 / 2), u]));
    }
}

#[test]
fn graph_of_xy() {
    // §2, eq. (3)
    let g = BezierSurface::graph(&parse_poly::<BigRational>("x y").unwrap(), 1, 1).unwrap();
    assert_eq!(g, xy());
    assert_eq!(g.closed_form().unwrap(), vp("(u, v, u v)"));
    // the same function at bidegree (2, 3): equidistant x, y and the Bernstein coefficients of xy
    let g = BezierSurface::graph(&parse_poly::<BigRational>("x y").unwrap(), 2, 3).unwrap();
    assert_eq!(g.mesh().get(1, 2).unwrap().to_text(), "(1/2, 2/3, 1/3)");
    assert_eq!(g.closed_form().unwrap(), vp("(u, v, u v)"));
}

#[test]
fn de_casteljau_steps_on_the_graph_of_xy() {
    let mut steps = Vec::new();
    let point = xy()
        .de_casteljau_columns_first_recorded(&q!(1 / 2), &q!(1 / 3), &mut steps)
        .unwrap();
    let [DeCasteljauStep::Column { j: 0, levels: c0 }, DeCasteljauStep::Column { j: 1, levels: c1 }, DeCasteljauStep::Row(row)] =
        steps.as_slice()
    else {
        panic!("two columns and a row: {steps:?}");
    };
    assert_eq!(c0[1][0].to_text(), "(1/2, 0, 0)");
    assert_eq!(c1[1][0].to_text(), "(1/2, 1, 1/2)");
    assert_eq!(row[1][0].to_text(), "(1/2, 1/3, 1/6)");
    assert_eq!(point.to_text(), "(1/2, 1/3, 1/6)");
}

#[test]
fn restriction_to_half_by_two_thirds_in_two_steps() {
    // §4, eq. (13)
    let s = patch::<BigRational>(BIQUADRATIC);
    let res = s.restrict(&q!(1 / 2), &q!(1), &q!(1 / 3), &q!(1)).unwrap();
    assert_eq!(
        res.rows_step.mesh(),
        &mesh(
            "{(2/3, 0, 19/9), (4/3, 0, 11/3), (2, 0, 3); \
                (2/3, 2, 28/9), (4/3, 2, 14/3), (2, 2, 4); \
                (2/3, 4, 19/9), (4/3, 4, 11/3), (2, 4, 3)}"
        )
    );
    assert_eq!(
        res.result.mesh(),
        &mesh(
            "{(2/3, 2, 47/18), (4/3, 2, 25/6), (2, 2, 7/2); \
                (2/3, 3, 47/18), (4/3, 3, 25/6), (2, 3, 7/2); \
                (2/3, 4, 19/9), (4/3, 4, 11/3), (2, 4, 3)}"
        )
    );
    assert_eq!(res.result.domain().to_text(), "[1/2, 1] x [1/3, 1]");
    // the vertices are values of the polar form (12)
    let c10 = s
        .blossom(&[q!(1 / 2), q!(1)], &[q!(1 / 3), q!(1 / 3)])
        .unwrap();
    assert_eq!(c10.to_text(), "(2/3, 3, 47/18)");
    assert_eq!(
        c10,
        s.blossom_rows_first(&[q!(1), q!(1 / 2)], &[q!(1 / 3), q!(1 / 3)])
            .unwrap()
    );
    // same points at the same parameters
    let (u, v) = (q!(3 / 4), q!(1 / 2));
    assert_eq!(res.result.eval(&u, &v).unwrap(), s.eval(&u, &v).unwrap());
}

#[test]
fn elevation_to_3_2_with_the_erratum() {
    // §5, eq. (14); the notes misprint the step c_{1,2}^{1,0} as (0, 4/3, 11/3)
    let s = patch::<BigRational>(BIQUADRATIC);
    let e = s.elevate_u().unwrap();
    assert_eq!(e.bidegree(), (3, 2));
    assert_eq!(
        e.mesh(),
        &mesh(
            "{(0, 0, 0), (1, 0, 4), (2, 0, 3); \
                (0, 4/3, 2/3), (1, 4/3, 14/3), (2, 4/3, 11/3); \
                (0, 8/3, 2/3), (1, 8/3, 14/3), (2, 8/3, 11/3); \
                (0, 4, 0), (1, 4, 4), (2, 4, 3)}"
        )
    );
    let step = e.mesh().get(1, 2).unwrap();
    assert_eq!(step.to_text(), "(2, 4/3, 11/3)");
    assert_ne!(step.to_text(), "(0, 4/3, 11/3)");
    assert_eq!(e.closed_form().unwrap(), s.closed_form().unwrap());
}

#[test]
fn elevation_to_2_3() {
    // §5, eq. (15)
    let s = patch::<BigRational>(BIQUADRATIC);
    let e = s.elevate_v().unwrap();
    assert_eq!(
        e.mesh(),
        &mesh(
            "{(0, 0, 0), (2/3, 0, 8/3), (4/3, 0, 11/3), (2, 0, 3); \
                (0, 2, 1), (2/3, 2, 11/3), (4/3, 2, 14/3), (2, 2, 4); \
                (0, 4, 0), (2/3, 4, 8/3), (4/3, 4, 11/3), (2, 4, 3)}"
        )
    );
    assert_eq!(s.elevate(1, 1).unwrap(), e.elevate_u().unwrap());
    assert_eq!(s.elevate(0, 0).unwrap(), s);
}

#[test]
fn c0_not_c1_join() {
    // §6: parallel but unequal differences
    let (c1, c2) = (
        patch::<BigRational>(JOIN_FIRST),
        patch::<BigRational>(JOIN_SECOND),
    );
    assert_eq!(
        c1.closed_form().unwrap(),
        vp("(2v - 1, 2u^2 v^2 - 2v^2 - 2u^2 v + 2v + 2u - 2, -2u^2 v + 2u^2 v^2 + 2v - 2v^2)")
    );
    assert_eq!(
        c2.closed_form().unwrap(),
        vp("(2v - 1, -2u^2 v^2 + 4u v^2 + 2u^2 v - 4u v + 2u, 4u^2 v - 4u^2 v^2 - 8u v + 8u v^2)")
    );
    let k = continuity(&c1, &c2, Join::U, &q!(1), &q!(1)).unwrap();
    assert_eq!(k.smoothness, Smoothness::C(0));
    assert_eq!(k.smoothness.to_string(), "C^0, not C^1");
    let failure = k.failure.clone().unwrap();
    assert_eq!((failure.order, failure.index), (1, 1));
    assert_eq!(
        failure.to_string(),
        "C^1 fails at j = 1: Δ^{1,0} c_{1,1} / Δu_0 = (0, 0, -1) but Δ^{1,0} c~_{0,1} / Δu_1 = (0, 0, -2)"
    );
    let text = |ps: &[Point<BigRational>]| ps.iter().map(Point::to_text).collect::<Vec<_>>();
    assert_eq!(
        text(&k.differences_first),
        ["(0, 1, 0)", "(0, 0, -1)", "(0, 1, 0)"]
    );
    assert_eq!(
        text(&k.differences_second),
        ["(0, 1, 0)", "(0, 0, -2)", "(0, 1, 0)"]
    );
    assert_eq!(k.derivative_first, vp("(0, 4v^2 - 4v + 2, -4v + 4v^2)"));
    assert_eq!(k.derivative_second, vp("(0, 4v^2 - 4v + 2, -8v + 8v^2)"));
    assert_eq!(
        k.normal_first.clone().unwrap(),
        vp("(0, -8v + 8v^2, -4 - 8v^2 + 8v)")
    );
    assert_eq!(
        k.normal_second.clone().unwrap(),
        vp("(0, -16v + 16v^2, -4 - 8v^2 + 8v)")
    );
    // as the brief writes them
    assert_eq!(
        k.normal_first.clone().unwrap(),
        vp("(0, 8v^2 - 8v, -8v^2 + 8v - 4)")
    );
    // the normals agree only at the ends v = 0, 1
    let at = |p: &cagd_poly::VecPoly<BigRational>, v: BigRational| p.eval(&[(Var::V, v)]).unwrap();
    let (n1, n2) = (
        k.normal_first.clone().unwrap(),
        k.normal_second.clone().unwrap(),
    );
    for v in [q!(0), q!(1)] {
        assert_eq!(at(&n1, v.clone()), at(&n2, v));
    }
    let cross = at(&n1, q!(1 / 2)).cross(&at(&n2, q!(1 / 2))).unwrap();
    assert!(!cross.is_zero());
    // the cross-boundary derivatives (19)-(20) are the same curves
    let d1 = c1.cross_boundary_derivative(Border::U1, 1).unwrap();
    assert_eq!(
        cagd_poly::from_bernstein_1d(d1.points(), Var::V).unwrap(),
        k.derivative_first
    );
    assert_eq!(k.to_text(), format!("C^0, not C^1; {failure}"));
}

#[test]
fn c1_neighbour_of_the_first_patch() {
    let (c1, c2) = (
        patch::<BigRational>(JOIN_FIRST),
        patch::<BigRational>(JOIN_SECOND),
    );
    let rows = c1_neighbour_rows(&c1, 1, &q!(1), &q!(1)).unwrap();
    assert_eq!(
        rows.to_text(),
        "{(-1, 0, 0), (0, 0, 0), (1, 0, 0); (-1, 1, 0), (0, 0, -1), (1, 1, 0)}"
    );
    // replace the first two rows of the second patch: now C^1 (and not C^2)
    let mut new_rows = rows.to_rows();
    new_rows.push(c2.mesh().row(2).unwrap().to_vec());
    let fixed = BezierSurface::from_rows(new_rows).unwrap();
    let k = continuity(&c1, &fixed, Join::U, &q!(1), &q!(1)).unwrap();
    assert_eq!(k.smoothness, Smoothness::C(1));
    assert_eq!(k.differences_first, k.differences_second);
    // with Δu_1 = 2 Δu_0 the next rows go twice as far
    let rows = c1_neighbour_rows(&c1, 2, &q!(1), &q!(2)).unwrap();
    let fixed = BezierSurface::from_rows(rows.to_rows()).unwrap();
    let k = continuity(&c1, &fixed, Join::U, &q!(1), &q!(2)).unwrap();
    assert_eq!(k.smoothness, Smoothness::Infinite);
}

#[test]
fn twists_and_corner_normals() {
    // c(u, v) = (u, v, uv) has twist (0, 0, 1) everywhere
    let g = xy();
    for t in g.twist_vectors().unwrap() {
        assert_eq!(t.to_text(), "(0, 0, 1)");
    }
    assert_eq!(
        g.forward_differences(1, 1).unwrap().to_text(),
        "{(0, 0, 1)}"
    );
    // the biquadratic of §4 has zero twists: Δ^{1,1} c_ij = 0 (a translational surface)
    let s = patch::<BigRational>(BIQUADRATIC);
    assert!(s
        .forward_differences(1, 1)
        .unwrap()
        .iter()
        .all(Point::is_zero));
    assert!(s.twist_vectors().unwrap().iter().all(Point::is_zero));
    // (25) at (0, 0): (0, 2, 1) x (1, 0, 4)
    let n = s.normal_at_corner(Corner::U0V0).unwrap();
    assert_eq!(n, NormalAtCorner::Normal(Point::from_ints(&[8, 1, -2])));
    // c_u x c_v = m n (25) at the corner
    let field = s.normal().unwrap();
    let at00 = field.eval(&[(Var::U, q!(0)), (Var::V, q!(0))]).unwrap();
    assert_eq!(at00, Point::from_ints(&[32, 4, -8]));
}

#[test]
fn collinear_corner_is_reported() {
    // c_00, c_10, c_01 on one line: (25) gives no normal
    let s = patch::<BigRational>("{(0, 0, 0), (2, 2, 0); (1, 1, 0), (1, 1, 1)}");
    let n = s.normal_at_corner(Corner::U0V0).unwrap();
    assert_eq!(
        n,
        NormalAtCorner::Degenerate {
            corner: Corner::U0V0,
            reason: Degeneracy::Collinear {
                vertices: [(0, 0), (1, 0), (0, 1)]
            }
        }
    );
    assert_eq!(
        n.to_text(),
        "degenerate at (0, 0): the vertices c_{0,0}, c_{1,0}, c_{0,1} are collinear, so the differences of (25) are parallel"
    );
    assert!(s.normal_at_corner(Corner::U1V1).unwrap().normal().is_some());
}

#[test]
fn boundary_curves_and_corners_of_the_biquadratic() {
    let s = patch::<BigRational>(BIQUADRATIC);
    assert_eq!(
        s.boundary(Border::U0).unwrap().to_text(),
        "(0, 0, 0), (1, 0, 4), (2, 0, 3)"
    );
    assert_eq!(
        s.boundary(Border::U1).unwrap().to_text(),
        "(0, 4, 0), (1, 4, 4), (2, 4, 3)"
    );
    assert_eq!(
        s.boundary(Border::V0).unwrap().to_text(),
        "(0, 0, 0), (0, 2, 1), (0, 4, 0)"
    );
    assert_eq!(
        s.boundary(Border::V1).unwrap().to_text(),
        "(2, 0, 3), (2, 2, 4), (2, 4, 3)"
    );
    let corners: Vec<String> = s.corners().iter().map(Point::to_text).collect();
    assert_eq!(
        corners,
        ["(0, 0, 0)", "(0, 4, 0)", "(2, 0, 3)", "(2, 4, 3)"]
    );
    // on [a, b] x [c, d] the same curves, on the matching intervals
    let t = s.clone().with_domain(q!(1), q!(3), q!(-1), q!(0)).unwrap();
    let b = t.boundary(Border::U1).unwrap();
    assert_eq!(b.domain(), (&q!(-1), &q!(0)));
    assert_eq!(
        b.eval(&q!(-1 / 2)).unwrap(),
        t.eval(&q!(3), &q!(-1 / 2)).unwrap()
    );
    assert_eq!(
        t.closed_form()
            .unwrap()
            .eval(&[(Var::U, q!(2)), (Var::V, q!(-1))])
            .unwrap(),
        s.eval(&q!(1 / 2), &q!(0)).unwrap()
    );
}

#[test]
fn convex_hull_of_the_biquadratic() {
    let s = patch::<BigRational>(BIQUADRATIC);
    let x = s.eval(&q!(1 / 3), &q!(5 / 7)).unwrap();
    assert!(s.in_convex_hull(&x).unwrap());
    assert!(s.in_convex_hull(&Point::from_ints(&[1, 2, 5])).unwrap());
    assert!(!s
        .in_convex_hull(&Point::new(vec![q!(1), q!(2), q!(51 / 10)]))
        .unwrap());
    assert!(!s.in_convex_hull(&Point::from_ints(&[3, 0, 0])).unwrap());
    // a planar mesh in R^3: points off the plane are outside
    let flat = patch::<BigRational>("{(0, 0, 0), (1, 0, 0); (0, 1, 0), (1, 1, 0)}");
    assert!(flat
        .in_convex_hull(&Point::new(vec![r(1, 2), r(1, 3), q!(0)]))
        .unwrap());
    assert!(!flat
        .in_convex_hull(&Point::new(vec![r(1, 2), r(1, 3), r(1, 9)]))
        .unwrap());
}

#[test]
fn partial_derivatives_of_the_biquadratic() {
    let s = patch::<BigRational>(BIQUADRATIC);
    let c = s.closed_form().unwrap();
    assert_eq!(
        s.derivative_u().unwrap().closed_form().unwrap(),
        c.partial(Var::U)
    );
    assert_eq!(
        s.derivative_v().unwrap().closed_form().unwrap(),
        c.partial(Var::V)
    );
    assert_eq!(
        s.partial_derivative(2, 1).unwrap().closed_form().unwrap(),
        c.partial(Var::U).partial(Var::U).partial(Var::V)
    );
    // beyond the degree: the zero patch
    let z = s.partial_derivative(3, 0).unwrap();
    assert_eq!(z.to_text(), "{(0, 0, 0), (0, 0, 0), (0, 0, 0)}");
}

#[test]
fn the_same_join_across_v() {
    // transposed meshes: the border is the last column of the first and the first column of
    // the second; the parametrization (u, v) -> c(v, u) reverses the normal
    let c1 = BezierSurface::try_new(patch::<BigRational>(JOIN_FIRST).mesh().transpose()).unwrap();
    let c2 = BezierSurface::try_new(patch::<BigRational>(JOIN_SECOND).mesh().transpose()).unwrap();
    let k = continuity(&c1, &c2, Join::V, &q!(1), &q!(1)).unwrap();
    assert_eq!(k.smoothness, Smoothness::C(0));
    assert_eq!(
        k.failure.unwrap().text,
        "C^1 fails at i = 1: Δ^{0,1} c_{1,1} / Δv_0 = (0, 0, -1) but Δ^{0,1} c~_{1,0} / Δv_1 = (0, 0, -2)"
    );
    assert_eq!(k.derivative_first, vp("(0, 4u^2 - 4u + 2, 4u^2 - 4u)"));
    assert_eq!(
        k.normal_first.unwrap(),
        vp("(0, -8u^2 + 8u, 8u^2 - 8u + 4)")
    );
    assert_eq!(
        k.normal_second.unwrap(),
        vp("(0, -16u^2 + 16u, 8u^2 - 8u + 4)")
    );
}
