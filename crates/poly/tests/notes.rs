//! The closed forms of the notes' parametric examples, computed through the polynomial module
//! from their input curves and meshes, pinned as insta snapshots in the top-level `snapshots/`
//! folder, and checked against the notes' printed form (an independent route: a wrong
//! expansion fails even if a bad snapshot were accepted).

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

use cagd_linalg::Point;
use cagd_poly::{control_mesh, from_bernstein_2d, parse_poly, parse_vec_poly, Poly, Var, VecPoly};
use cagd_scalar::{q, BigRational};

type Q = BigRational;

fn vp(text: &str) -> VecPoly<Q> {
    parse_vec_poly(text).unwrap()
}

fn p(text: &str) -> Poly<Q> {
    parse_poly(text).unwrap()
}

fn pt(coords: &[i64]) -> Point<Q> {
    Point::from_ints(coords)
}

/// Pins a text and a LaTeX form under `name` in the top-level `snapshots/` folder, with a
/// description of the example.
fn snapshot(name: &str, description: &str, text: &str, latex: &str) {
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path("../../../snapshots");
    settings.set_prepend_module_to_snapshot(false);
    settings.set_description(description);
    settings.set_omit_expression(true);
    settings.bind(|| {
        insta::assert_snapshot!(name, format!("text:  {text}\nlatex: {latex}\n"));
    });
}

fn snapshot_map(name: &str, description: &str, c: &VecPoly<Q>) {
    snapshot(name, description, &c.to_text(), &c.to_latex());
}

/// `(1 - t) a + t b` for polynomial maps.
fn blend(t: &Poly<Q>, a: &VecPoly<Q>, b: &VecPoly<Q>) -> VecPoly<Q> {
    let one_minus_t = Poly::one() - t;
    a.mul_poly(&one_minus_t)
        .checked_add(&b.mul_poly(t))
        .unwrap()
}

#[test]
fn translational_parametric() {
    // chapter 6, eq. (1): c(u, v) = c1(u) + d1(v) - a
    let c1 = vp("(u, 1, u^2)");
    let d1 = vp("(0, v + 1, v^3)");
    let a = pt(&[0, 1, 0]);
    assert_eq!(c1.eval(&[(Var::U, q!(0))]).unwrap(), a);
    assert_eq!(d1.eval(&[(Var::V, q!(0))]).unwrap(), a);
    let c = c1.checked_add(&d1).unwrap().add_point(&-a).unwrap();
    assert_eq!(c, vp("(u, v + 1, u^2 + v^3)"));
    snapshot_map(
        "poly__translational_parametric",
        "chapter 6, translational surface c1(u) + d1(v) - a: c1 = (u, 1, u^2), d1 = (0, v + 1, v^3), a = (0, 1, 0)",
        &c,
    );
}

#[test]
fn ruled_parametric() {
    // chapter 6, eq. (7): c(u, v) = (1 - v) c1(u) + v c2(u)
    let c1 = vp("(u, 0, u^3)");
    let c2 = vp("(u, 1, u^2)");
    let c = blend(&p("v"), &c1, &c2);
    assert_eq!(c, vp("(u, v, u^3 - u^3v + u^2v)"));
    assert_eq!(c.substitute_value(Var::V, &q!(0)), c1);
    assert_eq!(c.substitute_value(Var::V, &q!(1)), c2);
    snapshot_map(
        "poly__ruled_parametric",
        "chapter 6, ruled surface (1 - v) c1(u) + v c2(u): c1 = (u, 0, u^3), c2 = (u, 1, u^2)",
        &c,
    );
}

#[test]
fn coons_parametric() {
    // chapter 6, eq. (16): c = c_c + c_d - c_cd
    let c1 = vp("(u, 0, u^2)");
    let c2 = vp("(u, 1, u^3 + 1)");
    let d1 = vp("(0, v, v)");
    let d2 = vp("(1, v, v^2 + 1)");
    let (a, b, c, d) = (
        pt(&[0, 0, 0]),
        pt(&[1, 0, 1]),
        pt(&[0, 1, 1]),
        pt(&[1, 1, 2]),
    );
    let at = |curve: &VecPoly<Q>, var: Var, t: i64| {
        curve.eval(&[(var, Q::from_integer(t.into()))]).unwrap()
    };
    // the corners where the curves meet
    assert_eq!(
        (at(&c1, Var::U, 0), at(&d1, Var::V, 0)),
        (a.clone(), a.clone())
    );
    assert_eq!(
        (at(&c1, Var::U, 1), at(&d2, Var::V, 0)),
        (b.clone(), b.clone())
    );
    assert_eq!(
        (at(&c2, Var::U, 0), at(&d1, Var::V, 1)),
        (c.clone(), c.clone())
    );
    assert_eq!(
        (at(&c2, Var::U, 1), at(&d2, Var::V, 1)),
        (d.clone(), d.clone())
    );
    let (u, v) = (p("u"), p("v"));
    let cc = blend(&v, &c1, &c2);
    let cd = blend(&u, &d1, &d2);
    let ccd = blend(
        &u,
        &blend(&v, &VecPoly::constant(&a), &VecPoly::constant(&c)),
        &blend(&v, &VecPoly::constant(&b), &VecPoly::constant(&d)),
    );
    assert_eq!(cc, vp("(1-v)(u, 0, u^2) + v(u, 1, u^3 + 1)"));
    assert_eq!(cd, vp("(1-u)(0, v, v) + u(1, v, v^2 + 1)"));
    assert_eq!(ccd, vp("(1-u)v(0, 1, 1) + u((1-v)(1, 0, 1) + v(1, 1, 2))"));
    let coons = cc.checked_add(&cd).unwrap().checked_sub(&ccd).unwrap();
    assert_eq!(coons, vp("(u, v, u^2 - vu^2 + v + vu^3 - uv + uv^2)"));
    // it interpolates the four curves
    assert_eq!(coons.substitute_value(Var::V, &q!(0)), c1);
    assert_eq!(coons.substitute_value(Var::V, &q!(1)), c2);
    assert_eq!(coons.substitute_value(Var::U, &q!(0)), d1);
    assert_eq!(coons.substitute_value(Var::U, &q!(1)), d2);
    snapshot_map(
        "poly__coons_parametric",
        "chapter 6, bilinear Coons surface c_c + c_d - c_cd: c1 = (u, 0, u^2), c2 = (u, 1, u^3 + 1), d1 = (0, v, v), d2 = (1, v, v^2 + 1)",
        &coons,
    );
}

#[test]
fn developable_test_of_a_ruled_mesh() {
    // chapter 6: the ruled surface of bidegree (2, 1) with two planar cells is not developable
    let mesh = vec![
        vec![pt(&[0, -1, 1]), pt(&[0, -2, 0])],
        vec![pt(&[0, 0, 1]), pt(&[0, 0, 0])],
        vec![pt(&[2, 0, 1]), pt(&[1, 0, -1])],
    ];
    let c = from_bernstein_2d(&mesh, Var::U, Var::V).unwrap();
    assert_eq!(
        c,
        vp("(2u^2 - u^2v, 2uv - v - u^2v - 1 + 2u - u^2, 1 - u^2v - v)")
    );
    let cu = c.partial(Var::U);
    let cv = c.partial(Var::V);
    let cuv = cu.partial(Var::V);
    assert_eq!(cu, vp("(4u - 2uv, 2v - 2uv + 2 - 2u, -2uv)"));
    assert_eq!(cv, vp("(-u^2, 2u - 1 - u^2, -u^2 - 1)"));
    assert_eq!(cuv, vp("(-2u, 2 - 2u, -2u)"));
    // eq. (10): c_uv · (c_u × c_v)
    let triple = cuv.dot(&cu.cross(&cv).unwrap()).unwrap();
    assert_eq!(triple, p("12u - 8u^3 - 4u^2"));
    assert_eq!(control_mesh(&c, Var::U, Var::V, 2, 1).unwrap(), mesh);
    snapshot(
        "poly__developable_triple_product",
        "chapter 6, ruled mesh {(0,-1,1), (0,-2,0); (0,0,1), (0,0,0); (2,0,1), (1,0,-1)} of bidegree (2, 1) is not developable: eq. (10)",
        &format!("c = {}\nc_uv · (c_u × c_v) = {}", c.to_text(), triple.to_text()),
        &format!("c = {}\nc_uv · (c_u × c_v) = {}", c.to_latex(), triple.to_latex()),
    );
}

#[test]
fn tensor_product_mesh_of_bidegree_2_3() {
    // chapter 5, section 2: the mesh as printed (its last point is (2, 4, -3))
    let rows: [[[i64; 3]; 4]; 3] = [
        [[0, 0, -1], [1, 0, 4], [2, 0, 3], [3, 0, -3]],
        [[0, 2, 2], [1, 2, 5], [2, 2, 6], [3, 2, 3]],
        [[0, 4, -2], [1, 4, 4], [2, 4, 3], [2, 4, -3]],
    ];
    let mesh: Vec<Vec<Point<Q>>> = rows
        .iter()
        .map(|row| row.iter().map(|c| pt(c)).collect())
        .collect();
    let c = from_bernstein_2d(&mesh, Var::U, Var::V).unwrap();
    // the notes' intermediate sum, written out (with a `*` where a number follows a tuple)
    let by_hand = vp("(1-v)^3 ((0,0,-1)(1-u)^2 + (0,2,2)*2u(1-u) + (0,4,-2)u^2) \
        + 3v(1-v)^2 ((1,0,4)(1-u)^2 + (1,2,5)*2u(1-u) + (1,4,4)u^2) \
        + 3v^2(1-v) ((2,0,3)(1-u)^2 + (2,2,6)*2u(1-u) + (2,4,3)u^2) \
        + v^3 ((3,0,-3)(1-u)^2 + (3,2,3)*2u(1-u) + (2,4,-3)u^2)");
    assert_eq!(c, by_hand);
    // the notes' printed closed form
    let printed = vp(
        "(-u^2v^3 + 3v, 4u, 7u^2v^3 - 6uv^3 + v^3 - 27u^2v^2 + 24uv^2 \
        - 18v^2 + 15u^2v - 12uv + 15v - 7u^2 + 6u - 1)",
    );
    assert_eq!(c, printed);
    assert_eq!(control_mesh(&c, Var::U, Var::V, 2, 3).unwrap(), mesh);
    snapshot_map(
        "poly__tensor_product_2_3",
        "chapter 5, section 2: Bézier surface of the (2, 3) mesh, closed form",
        &c,
    );
}

#[test]
fn graph_of_xy_as_a_bilinear_mesh() {
    // chapter 5: f(x, y) = xy has the mesh {(0,0,0), (0,1,0); (1,0,0), (1,1,1)}
    let mesh = vec![
        vec![pt(&[0, 0, 0]), pt(&[0, 1, 0])],
        vec![pt(&[1, 0, 0]), pt(&[1, 1, 1])],
    ];
    let c = from_bernstein_2d(&mesh, Var::X, Var::Y).unwrap();
    assert_eq!(c, vp("(x, y, xy)"));
    snapshot_map(
        "poly__graph_xy",
        "chapter 5: graph of f(x, y) = xy from the mesh {(0,0,0), (0,1,0); (1,0,0), (1,1,1)}",
        &c,
    );
}

/// Found by fuzzing (a slow unit of the parse_expr target): the expansion of a power of a
/// long sum, printed and read back.
#[test]
fn a_large_expansion_reads_back() {
    let e = cagd_poly::parse_expr("(u+v+w+t+s+x+y+z)^6").unwrap();
    assert_eq!(cagd_poly::parse_expr(&e.to_json_string()).unwrap(), e);
    assert_eq!(cagd_poly::parse_expr(&e.to_text()).unwrap(), e);
    // C(13, 7) monomials of degree 6 in 8 variables
    assert_eq!(
        e.scalar::<cagd_scalar::BigRational>().unwrap().num_terms(),
        1716
    );
}

/// The budgets of docs/format.md (Limits): refused before they are expanded.
#[test]
fn hostile_expressions_are_refused() {
    let sum = cagd_poly::parse_expr("(u+v+w+t+s+x+y+z)^20")
        .unwrap_err()
        .to_string();
    assert!(
        sum.contains("expression too large to expand: more than 100000 products"),
        "{sum}"
    );
    let tower = cagd_poly::parse_expr("((10^1000)^1000)^1000")
        .unwrap_err()
        .to_string();
    assert_eq!(
        tower,
        "at column 11: expression too large to expand: a coefficient of about 52000 64-bit words, more than 2048"
    );
    let inverse = cagd_poly::parse_expr("((1/10)^1000)^-1000 u")
        .unwrap_err()
        .to_string();
    assert!(inverse.contains("more than 2048"), "{inverse}");
}

/// Found by the parse_expr fuzz target (`1/(sqrt2 - 2)` printed as `-1 + sqrt2/2`): a constant
/// term whose coefficient is negative and has a root, such as -1 - √2/2 = -(1 + √2/2), lost
/// the parentheses when its sign was taken out, so the root part printed with the wrong sign.
#[test]
fn negative_constants_with_a_root_print_and_read_back() {
    let cases = [
        ("1/(sqrt2 - 2)", "-1 - √2/2", "-1 - sqrt2/2"),
        ("sqrt2 - 2", "-2 + √2", "-2 + sqrt2"),
        ("u + sqrt2 - 2", "u - (2 - √2)", "u - (2 - sqrt2)"),
        ("u - 1 - sqrt2/2", "u - (1 + √2/2)", "u - (1 + sqrt2/2)"),
        ("u + 1 + sqrt2", "u + 1 + √2", "u + 1 + sqrt2"),
        ("(1 - sqrt2) u - 3", "(1 - √2) u - 3", "(1 - sqrt2)*u - 3"),
        ("(sqrt2 - 1) u", "-(1 - √2) u", "-(1 - sqrt2)*u"),
    ];
    for (input, text, json) in cases {
        let e = cagd_poly::parse_expr(input).unwrap();
        assert_eq!(
            (e.to_text().as_str(), e.to_json_string().as_str()),
            (text, json),
            "{input}"
        );
        assert_eq!(cagd_poly::parse_expr(text).unwrap(), e, "{text}");
        assert_eq!(cagd_poly::parse_expr(json).unwrap(), e, "{json}");
    }
    let latex = cagd_poly::parse_expr("u + sqrt2 - 2").unwrap().to_latex();
    assert_eq!(latex, r"u - \left(2 - \sqrt{2}\right)");
}
