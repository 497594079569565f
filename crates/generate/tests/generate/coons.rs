//! Coons surfaces, §5: bilinear and cubic blending, Bézier meshes, cross-boundary derivatives.

use crate::support::*;
use cagd_bezier::BezierCurve;
use cagd_generate::*;
use cagd_linalg::Point;
use cagd_poly::{from_bernstein_1d, Poly, Var, VecPoly};
use cagd_scalar::{q, FieldOps, Quadratic};
use proptest::prelude::*;

fn notes_curves() -> [BezierCurve<Q>; 4] {
    [
        curve(&[
            &["0", "0", "0"],
            &["1/2", "0", "2"],
            &["1", "0", "3"],
            &["2", "0", "0"],
        ]),
        curve(&[
            &["0", "3", "0"],
            &["1/2", "3", "3"],
            &["1", "3", "1"],
            &["2", "4", "0"],
        ]),
        curve(&[&["0", "0", "0"], &["0", "1", "3"], &["0", "3", "0"]]),
        curve(&[&["2", "0", "0"], &["2", "1", "2"], &["2", "4", "0"]]),
    ]
}

fn notes_parametric() -> [VecPoly<Q>; 4] {
    [
        e("(u, 0, u^2)"),
        e("(u, 1, u^3 + 1)"),
        e("(0, v, v)"),
        e("(1, v, v^2 + 1)"),
    ]
}

#[test]
fn notes_parametric_example() {
    let [c1, c2, d1, d2] = notes_parametric();
    let mut steps = Vec::new();
    let coons = coons_surface(&c1, &c2, &d1, &d2, &mut steps).unwrap();
    assert_eq!(
        coons.surface,
        e("(u, v, u^2 - v u^2 + v + v u^3 - u v + u v^2)")
    );
    let corners: Vec<String> = [&coons.a, &coons.b, &coons.c, &coons.d]
        .iter()
        .map(|p| p.to_text())
        .collect();
    assert_eq!(
        corners,
        ["(0, 0, 0)", "(1, 0, 1)", "(0, 1, 1)", "(1, 1, 2)"]
    );
    assert_eq!(coons.c_c, e("(1 - v)*(u, 0, u^2) + v*(u, 1, u^3 + 1)"));
    assert_eq!(coons.c_d, e("(1 - u)*(0, v, v) + u*(1, v, v^2 + 1)"));
    assert_eq!(
        coons.c_cd,
        e("(1 - u)*v*(0, 1, 1) + u*((1 - v)*(1, 0, 1) + v*(1, 1, 2))")
    );
    assert_eq!(steps.len(), 8);
    assert_eq!(steps[1].to_text(), "b = (1, 0, 1)");
}

#[test]
fn notes_bezier_example() {
    let [c1, c2, d1, d2] = notes_curves();
    let mut steps = Vec::new();
    let coons = coons_bezier(&c1, &c2, &d1, &d2, &mut steps).unwrap();
    assert_eq!(
        coons.surface.mesh().to_text(),
        "{(0, 0, 0), (0, 1, 3), (0, 3, 0); (1/2, 0, 2), (1/2, 5/6, 31/6), (1/2, 3, 3); \
         (1, 0, 3), (1, 2/3, 13/3), (1, 3, 1); (2, 0, 0), (2, 1, 2), (2, 4, 0)}"
    );
    let g = |s: &cagd_surface::BezierSurface<Q>, i: usize, j: usize| {
        s.mesh().get(i, j).unwrap().to_text()
    };
    assert_eq!(g(&coons.c_c, 1, 1), "(1/2, 3/2, 5/2)");
    assert_eq!(g(&coons.c_c, 2, 1), "(1, 3/2, 2)");
    assert_eq!(g(&coons.c_d, 1, 1), "(2/3, 1, 8/3)");
    assert_eq!(g(&coons.c_d, 2, 1), "(4/3, 1, 7/3)");
    assert_eq!(g(&coons.c_cd, 1, 1), "(2/3, 5/3, 0)");
    assert_eq!(g(&coons.c_cd, 2, 1), "(4/3, 11/6, 0)");
    // the whole auxiliary meshes, as in the fixture
    assert_eq!(
        coons.c_c.mesh().to_text(),
        "{(0, 0, 0), (0, 3/2, 0), (0, 3, 0); (1/2, 0, 2), (1/2, 3/2, 5/2), (1/2, 3, 3); \
         (1, 0, 3), (1, 3/2, 2), (1, 3, 1); (2, 0, 0), (2, 2, 0), (2, 4, 0)}"
    );
    assert_eq!(
        coons.c_d.mesh().to_text(),
        "{(0, 0, 0), (0, 1, 3), (0, 3, 0); (2/3, 0, 0), (2/3, 1, 8/3), (2/3, 10/3, 0); \
         (4/3, 0, 0), (4/3, 1, 7/3), (4/3, 11/3, 0); (2, 0, 0), (2, 1, 2), (2, 4, 0)}"
    );
    assert_eq!(
        coons.c_cd.mesh().to_text(),
        "{(0, 0, 0), (0, 3/2, 0), (0, 3, 0); (2/3, 0, 0), (2/3, 5/3, 0), (2/3, 10/3, 0); \
         (4/3, 0, 0), (4/3, 11/6, 0), (4/3, 11/3, 0); (2, 0, 0), (2, 2, 0), (2, 4, 0)}"
    );
    assert_eq!(coons.surface.bidegree(), (3, 2));
    let names: Vec<&str> = steps.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "a", "b", "c", "d", "c_c,1,1", "c_c,2,1", "c_d,1,1", "c_d,2,1", "c_cd,1,1", "c_cd,2,1",
            "c,1,1", "c,2,1", "c_c", "c_d", "c_cd", "c"
        ]
    );
    let step = |name: &str| find_step(&steps, name).unwrap().to_text();
    assert_eq!(step("c_c,1,1"), "(1/2, 3/2, 5/2)");
    assert_eq!(step("c_d,2,1"), "(4/3, 1, 7/3)");
    assert_eq!(step("c_cd,2,1"), "(4/3, 11/6, 0)");
    assert_eq!(step("c,1,1"), "(1/2, 5/6, 31/6)");
    assert_eq!(step("c,2,1"), "(1, 2/3, 13/3)");
    assert_eq!(coons.d.to_text(), "(2, 4, 0)");
}

#[test]
fn corner_errors_name_the_corner() {
    let err = coons_surface(
        &e("(2u, 0, 0)"),
        &e("(2u, 1, 0)"),
        &e("(0, v, 0)"),
        &e("(2, v, 1)"),
        &mut NoSteps,
    )
    .unwrap_err();
    assert_eq!(
        err.to_string(),
        "curves c1 and d2 do not meet at corner b: c1(1) = (2, 0, 0), d2(0) = (2, 0, 1)"
    );
    let [c1, c2, d1, _] = notes_curves();
    let d2 = curve(&[&["2", "0", "1"], &["2", "1", "2"], &["2", "4", "0"]]);
    assert_eq!(
        coons_bezier(&c1, &c2, &d1, &d2, &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "curves c1 and d2 do not meet at corner b: c1(1) = (2, 0, 0), d2(0) = (2, 0, 1)"
    );
    let d1 = curve(&[&["0", "0", "0"], &["0", "1", "3"], &["0", "3", "1"]]);
    let [_, _, _, d2] = notes_curves();
    assert_eq!(
        coons_bezier(&c1, &c2, &d1, &d2, &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "curves c2 and d1 do not meet at corner c: c2(0) = (0, 3, 0), d1(1) = (0, 3, 1)"
    );
    let [c1, c2, d1, d2] = notes_parametric();
    assert_eq!(
        coons_surface(&c1, &c2, &d2, &d1, &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "curves c1 and d1 do not meet at corner a: c1(0) = (0, 0, 0), d1(0) = (1, 0, 1)"
    );
    assert_eq!(
        coons_surface(&c1, &c2, &c1, &d2, &mut NoSteps)
            .unwrap_err()
            .to_string(),
        "d1 must be a curve in v, but it uses u"
    );
    assert!(matches!(
        coons_surface(&c1, &c2, &d1, &e("(1, v)"), &mut NoSteps),
        Err(GenerateError::DimensionMismatch { .. })
    ));
}

#[test]
fn cross_boundary_derivative_and_the_sign_erratum() {
    let [c1, c2, d1, d2] = notes_parametric();
    let coons = coons_surface(&c1, &c2, &d1, &d2, &mut NoSteps).unwrap();
    let exact = coons.cross_boundary_derivative(Border::U1);
    assert_eq!(exact, e("(1, 0, 2 + v^2)"));
    assert_eq!(cross_boundary_formula(&c1, &c2, &d1, &d2).unwrap(), exact);
    // the printed formula, with + (1 - v)(b - a) + v(d - c), is wrong
    let one_v = Poly::one() - Poly::var(Var::V);
    let sides = VecPoly::constant(&(&coons.b - &coons.a))
        .mul_poly(&one_v)
        .checked_add(&VecPoly::constant(&(&coons.d - &coons.c)).mul_poly(&Poly::var(Var::V)))
        .unwrap();
    let printed = exact.checked_add(&sides.scale(&q!(2))).unwrap();
    assert_eq!(printed, e("(3, 0, 4 + v^2)"));
    // the other borders: c(u, 0) = c1, so ∂c/∂v there is the cross derivative in v
    assert_eq!(
        coons.cross_boundary_derivative(Border::U0),
        e("(1, 0, v^2 - v)")
    );
    assert_eq!(
        at(&coons.surface, Var::V, &q!(0)).partial(Var::U),
        c1.partial(Var::U)
    );
    let dv0 = coons.cross_boundary_derivative(Border::V0);
    assert_eq!(
        dv0,
        coons
            .surface
            .partial(Var::V)
            .substitute_value(Var::V, &q!(0))
    );
    assert_eq!(dv0.vars(), vec![Var::U]);
    // the Bézier form of (20), with m Δc_{1,m-1}, agrees with the derivative of the mesh
    let [b1, b2, b3, b4] = notes_curves();
    let bez = coons_bezier(&b1, &b2, &b3, &b4, &mut NoSteps).unwrap();
    let closed = bez.surface.closed_form().unwrap();
    assert_eq!(
        bez.cross_boundary_u1().unwrap(),
        closed.partial(Var::U).substitute_value(Var::U, &q!(1))
    );
}

#[test]
fn cubic_blending_decouples_the_opposite_curve() {
    let [c1, c2, d1, d2] = notes_parametric();
    // another d1 with the same ends (0, 0, 0) and (0, 1, 1)
    let other = e("(0, v, v^3)");
    for blending in [Blending::Bilinear, Blending::Cubic] {
        let s = coons_surface_blended(&c1, &c2, &d1, &d2, blending, &mut NoSteps).unwrap();
        let t = coons_surface_blended(&c1, &c2, &other, &d2, blending, &mut NoSteps).unwrap();
        let same =
            s.cross_boundary_derivative(Border::U1) == t.cross_boundary_derivative(Border::U1);
        assert_eq!(same, blending == Blending::Cubic, "{blending:?}");
    }
    // cubic: ∂c/∂u at u = 1 is F0(v) c1'(1) + F1(v) c2'(1)
    let s = coons_surface_blended(&c1, &c2, &d1, &d2, Blending::Cubic, &mut NoSteps).unwrap();
    let (f0, f1) = blending_functions::<Q>(Blending::Cubic, Var::V);
    let want = VecPoly::constant(&pi(&[1, 0, 2]))
        .mul_poly(&f0)
        .checked_add(&VecPoly::constant(&pi(&[1, 0, 3])).mul_poly(&f1))
        .unwrap();
    assert_eq!(s.cross_boundary_derivative(Border::U1), want);
    assert_eq!(f0.to_text(), "2 v^3 - 3 v^2 + 1");
    assert_eq!((&f0 + &f1), Poly::one());
}

#[test]
fn degree_zero_and_unequal_degrees_are_raised() {
    // c1 is a point (degenerate side), c2 a segment; d1, d2 of degrees 1 and 2
    let c1 = icurve(&[&[0, 0, 0]]);
    let c2 = icurve(&[&[0, 2, 0], &[2, 2, 0]]);
    let d1 = icurve(&[&[0, 0, 0], &[0, 2, 0]]);
    let d2 = icurve(&[&[0, 0, 0], &[2, 1, 1], &[2, 2, 0]]);
    let coons = coons_bezier(&c1, &c2, &d1, &d2, &mut NoSteps).unwrap();
    let notes: Vec<String> = coons.notes.iter().map(|n| format!("note: {n}")).collect();
    assert_eq!(
        notes,
        [
            "note: c1 elevated from degree 0 to 1",
            "note: d1 elevated from degree 1 to 2"
        ]
    );
    assert_eq!(coons.surface.bidegree(), (1, 2));
    let closed = coons.surface.closed_form().unwrap();
    assert_eq!(
        at(&closed, Var::U, &q!(1)),
        from_bernstein_1d(d2.points(), Var::V).unwrap()
    );
}

#[test]
fn quadratic_and_float() {
    let h = qd("sqrt2/2");
    let pq = |c: &[i64]| Point::<Quadratic>::from_ints(c);
    let c1 = BezierCurve::try_new(vec![
        pq(&[0, 0, 0]),
        Point::new(vec![h.clone(), Quadratic::from_i64(0), h.clone()]),
        pq(&[2, 0, 0]),
    ])
    .unwrap();
    let c2 = BezierCurve::try_new(vec![pq(&[0, 2, 0]), pq(&[2, 2, 0])]).unwrap();
    let d1 = BezierCurve::try_new(vec![pq(&[0, 0, 0]), pq(&[0, 2, 0])]).unwrap();
    let d2 = BezierCurve::try_new(vec![pq(&[2, 0, 0]), pq(&[2, 2, 0])]).unwrap();
    let coons = coons_bezier(&c1, &c2, &d1, &d2, &mut NoSteps).unwrap();
    assert_eq!(
        coons.surface.mesh().get(1, 0).unwrap().to_text(),
        "(√2/2, 0, √2/2)"
    );
    assert_eq!(
        coons.surface.mesh().get(1, 1).unwrap().to_text(),
        "(1, 2, 0)"
    );
    let forms: Vec<VecPoly<Quadratic>> =
        [(&c1, Var::U), (&c2, Var::U), (&d1, Var::V), (&d2, Var::V)]
            .iter()
            .map(|(c, var)| from_bernstein_1d(c.points(), *var).unwrap())
            .collect();
    let direct = coons_surface(&forms[0], &forms[1], &forms[2], &forms[3], &mut NoSteps).unwrap();
    assert_eq!(coons.surface.closed_form().unwrap(), direct.surface);

    let pf = |c: &[f64]| Point::new(c.to_vec());
    let line = |a: &[f64], b: &[f64]| BezierCurve::try_new(vec![pf(a), pf(b)]).unwrap();
    let coons = coons_bezier(
        &line(&[0.0, 0.0, 0.0], &[1.0, 0.0, 0.0]),
        &line(&[0.0, 1.0, 0.0], &[1.0, 1.0, 1.0]),
        &line(&[0.0, 0.0, 0.0], &[0.0, 1.0, 0.0]),
        &line(&[1.0, 0.0, 0.0], &[1.0, 1.0, 1.0]),
        &mut NoSteps,
    )
    .unwrap();
    assert_eq!(
        coons.surface.mesh().get(1, 1).unwrap().coords(),
        &[1.0, 1.0, 1.0]
    );
}

/// Four random polygons forming a closed quadrilateral (13), of degrees 1..=3 (opposite
/// curves may differ in degree).
fn quadrilateral() -> impl Strategy<Value = [Vec<Point<Q>>; 4]> {
    (1usize..=3, 1usize..=3, 1usize..=2, 1usize..=2).prop_flat_map(|(m1, m2, n1, n2)| {
        (
            polygon(m1 + 1),
            polygon(m2 + 1),
            polygon(n1 + 1),
            polygon(n2 + 1),
        )
            .prop_map(|(c1, c2, mut d1, mut d2)| {
                d1[0] = c1[0].clone();
                d2[0] = c1[c1.len() - 1].clone();
                let (l1, l2) = (d1.len() - 1, d2.len() - 1);
                d1[l1] = c2[0].clone();
                d2[l2] = c2[c2.len() - 1].clone();
                [c1, c2, d1, d2]
            })
    })
}

fn forms(q: &[Vec<Point<Q>>; 4]) -> [VecPoly<Q>; 4] {
    [
        from_bernstein_1d(&q[0], Var::U).unwrap(),
        from_bernstein_1d(&q[1], Var::U).unwrap(),
        from_bernstein_1d(&q[2], Var::V).unwrap(),
        from_bernstein_1d(&q[3], Var::V).unwrap(),
    ]
}

fn curves(q: &[Vec<Point<Q>>; 4]) -> [BezierCurve<Q>; 4] {
    q.clone().map(|p| BezierCurve::try_new(p).unwrap())
}

/// The mesh of (18)-(19) written directly from the formulas of the notes.
fn formula_19(c: &[BezierCurve<Q>; 4]) -> Vec<Vec<Point<Q>>> {
    let [c1, c2, d1, d2] = c;
    let (m, n) = (c1.degree(), d1.degree());
    let (a, b) = (&c1.points()[0], &c1.points()[m]);
    let (cc, d) = (&c2.points()[0], &c2.points()[m]);
    let (mq, nq) = (r(m as i64, 1), r(n as i64, 1));
    (0..=m)
        .map(|i| {
            (0..=n)
                .map(|j| {
                    let (fi, fj) = (r(i as i64, 1) / &mq, r(j as i64, 1) / &nq);
                    let c_c = c1.points()[i].lerp(&c2.points()[i], &fj);
                    let c_d = d1.points()[j].lerp(&d2.points()[j], &fi);
                    let c_cd = a.lerp(b, &fi).lerp(&cc.lerp(d, &fi), &fj);
                    &(&c_c + &c_d) - &c_cd
                })
                .collect()
        })
        .collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(40))]

    #[test]
    fn coons_interpolates_all_four_borders(q in quadrilateral()) {
        let [c1, c2, d1, d2] = forms(&q);
        for blending in [Blending::Bilinear, Blending::Cubic] {
            let s = coons_surface_blended(&c1, &c2, &d1, &d2, blending, &mut NoSteps).unwrap().surface;
            prop_assert_eq!(at(&s, Var::V, &q!(0)), c1.clone());
            prop_assert_eq!(at(&s, Var::V, &q!(1)), c2.clone());
            prop_assert_eq!(at(&s, Var::U, &q!(0)), d1.clone());
            prop_assert_eq!(at(&s, Var::U, &q!(1)), d2.clone());
        }
    }

    #[test]
    fn bezier_mesh_is_the_coons_surface(q in quadrilateral()) {
        let coons = coons_bezier(&curves(&q)[0], &curves(&q)[1], &curves(&q)[2], &curves(&q)[3], &mut NoSteps).unwrap();
        let [c1, c2, d1, d2] = forms(&q);
        let direct = coons_surface(&c1, &c2, &d1, &d2, &mut NoSteps).unwrap();
        prop_assert_eq!(&coons.surface.closed_form().unwrap(), &direct.surface);
        prop_assert_eq!(&coons.c_c.closed_form().unwrap(), &direct.c_c);
        prop_assert_eq!(&coons.c_d.closed_form().unwrap(), &direct.c_d);
        prop_assert_eq!(&coons.c_cd.closed_form().unwrap(), &direct.c_cd);
        // (18)-(19) written out agree with the elevation route
        prop_assert_eq!(coons.surface.mesh().to_rows(), formula_19(&coons.curves));
        // (20) with the corrected sign is the derivative of the patch
        let derivative = direct.cross_boundary_derivative(Border::U1);
        prop_assert_eq!(coons.cross_boundary_u1().unwrap(), derivative.clone());
        prop_assert_eq!(cross_boundary_formula(&c1, &c2, &d1, &d2).unwrap(), derivative);
    }

    #[test]
    fn ruled_inputs_give_the_ruled_surface(a in polygon(4), b in polygon(3)) {
        let c1 = BezierCurve::try_new(a.clone()).unwrap();
        let c2 = BezierCurve::try_new(b.clone()).unwrap();
        let d1 = BezierCurve::try_new(vec![a[0].clone(), b[0].clone()]).unwrap();
        let d2 = BezierCurve::try_new(vec![a[3].clone(), b[2].clone()]).unwrap();
        let coons = coons_bezier(&c1, &c2, &d1, &d2, &mut NoSteps).unwrap();
        let ruled = ruled_bezier(&c1, &c2, &mut NoSteps).unwrap();
        prop_assert_eq!(&coons.surface, &ruled.surface);
        let f1 = from_bernstein_1d(&a, Var::U).unwrap();
        let f2 = from_bernstein_1d(&b, Var::U).unwrap();
        let g1 = from_bernstein_1d(d1.points(), Var::V).unwrap();
        let g2 = from_bernstein_1d(d2.points(), Var::V).unwrap();
        prop_assert_eq!(
            coons_surface(&f1, &f2, &g1, &g2, &mut NoSteps).unwrap().surface,
            ruled_surface(&f1, &f2, &mut NoSteps).unwrap().surface
        );
    }

    #[test]
    fn translational_inputs_give_the_translational_surface(
        (c, d) in (polygon(4), polygon(3)).prop_map(|(c, mut d)| { d[0] = c[0].clone(); (c, d) })
    ) {
        // c2 = c1 + (c - a), d2 = d1 + (b - a): opposite curves are translates
        let (a, b, cc) = (&c[0], &c[3], &d[2]);
        let shift = |p: &[Point<Q>], by: &Point<Q>| -> Vec<Point<Q>> {
            p.iter().map(|x| &(x + by) - a).collect()
        };
        let (c2, d2) = (shift(&c, cc), shift(&d, b));
        let q = [c.clone(), c2, d.clone(), d2];
        let [f1, f2, g1, g2] = forms(&q);
        let coons = coons_surface(&f1, &f2, &g1, &g2, &mut NoSteps).unwrap();
        prop_assert_eq!(&coons.surface, &translational_surface(&f1, &g1, &mut NoSteps).unwrap().surface);
        let bez = coons_bezier(&curves(&q)[0], &curves(&q)[1], &curves(&q)[2], &curves(&q)[3], &mut NoSteps).unwrap();
        let trans = translational_bezier(&curves(&q)[0], &curves(&q)[2], &mut NoSteps).unwrap();
        prop_assert_eq!(bez.surface, trans.surface);
    }
}
