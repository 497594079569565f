//! Unit and property tests of the polynomial module.

use crate::*;
use cagd_linalg::Point;
use cagd_scalar::{q, BigRational, Print, Quadratic};

type Q = BigRational;

fn p(text: &str) -> Poly<Q> {
    parse_poly(text).unwrap()
}

fn pq(text: &str) -> Poly<Quadratic> {
    parse_poly(text).unwrap()
}

fn vp(text: &str) -> VecPoly<Q> {
    parse_vec_poly(text).unwrap()
}

fn err(text: &str) -> String {
    parse_expr(text).unwrap_err().to_string()
}

// ---------------------------------------------------------------- ring and structure

#[test]
fn zero_coefficients_are_never_stored() {
    let a = p("u^2 + v");
    let b = p("-u^2 + 1");
    let s = &a + &b;
    assert_eq!(s.num_terms(), 2);
    assert_eq!(s, p("v + 1"));
    assert!((&a - &a).is_zero());
    assert_eq!(Poly::<Q>::constant(q!(0)), Poly::zero());
    assert_eq!(a.scale(&q!(0)), Poly::zero());
    assert_eq!(Poly::<Q>::zero().to_text(), "0");
    assert_eq!(Poly::<Q>::zero().degree(), 0);
}

#[test]
fn operator_forms_agree() {
    let a = p("u^2 - 2 u v + 3");
    let b = p("v - 1/2");
    let sum = &a + &b;
    assert_eq!(a.clone() + b.clone(), sum);
    assert_eq!(a.clone() + &b, sum);
    assert_eq!(&a + b.clone(), sum);
    assert_eq!(sum.to_text(), "u^2 - 2 u v + v + 5/2");
    let prod = &a * &b;
    assert_eq!(a.clone() * b.clone(), prod);
    assert_eq!(
        prod.to_text(),
        "u^2 v - 2 u v^2 - 1/2 u^2 + u v + 3 v - 3/2"
    );
    assert_eq!(&a - &b, a.clone() + (-b.clone()));
    assert_eq!(-&a, a.scale(&q!(-1)));
}

#[test]
fn degrees_vars_and_coefficients() {
    let a = p("u^3 v + w^2 - 7");
    assert_eq!(a.degree(), 4);
    assert_eq!(a.degree_in(Var::U), 3);
    assert_eq!(a.degree_in(Var::W), 2);
    assert_eq!(a.degree_in(Var::Z), 0);
    assert_eq!(a.vars(), vec![Var::U, Var::V, Var::W]);
    assert_eq!(a.coeff_of(&[(Var::U, 3), (Var::V, 1)]), q!(1));
    assert_eq!(a.coeff(&Monomial::one()), q!(-7));
    assert_eq!(a.as_constant(), None);
    assert_eq!(p("5/3").as_constant(), Some(q!(5 / 3)));
    assert_eq!(p("1 - u").pow(3).to_text(), "-u^3 + 3 u^2 - 3 u + 1");
    assert_eq!(p("u").pow(0), Poly::one());
}

#[test]
fn evaluation() {
    let a = p("u^2 v - 3 u + 1/2");
    assert_eq!(
        a.eval(&[(Var::U, q!(2)), (Var::V, q!(1 / 4))]).unwrap(),
        q!(-9 / 2)
    );
    let e = a.eval(&[(Var::U, q!(2))]).unwrap_err();
    assert_eq!(e, PolyError::MissingVariable { var: "v".into() });
    assert_eq!(e.to_string(), "no value given for the variable v");
    // unused variables may be given; the first value of a variable counts
    assert_eq!(
        p("u")
            .eval(&[(Var::U, q!(1)), (Var::U, q!(2)), (Var::Z, q!(9))])
            .unwrap(),
        q!(1)
    );
    assert_eq!(p("7").eval(&[]).unwrap(), q!(7));
    assert_eq!(a.substitute_value(Var::U, &q!(2)).to_text(), "4 v - 11/2");
}

#[test]
fn composition_and_affine_maps() {
    let a = p("u^2 v + u");
    assert_eq!(
        a.substitute(Var::U, &p("1 - v")).to_text(),
        "v^3 - 2 v^2 + 1"
    );
    assert_eq!(a.substitute(Var::W, &p("u")), a);
    assert_eq!(
        a.affine_substitute(Var::U, &q!(2), &q!(1)),
        a.substitute(Var::U, &p("2 u + 1"))
    );
    let r = a.reparametrize_affine(Var::U, &q!(1 / 2), &q!(1)).unwrap();
    // r(u) = a(2u - 1)
    assert_eq!(r, a.substitute(Var::U, &p("2 u - 1")));
    let e = a
        .reparametrize_affine(Var::U, &q!(1 / 2), &q!(1 / 2))
        .unwrap_err();
    assert_eq!(
        e.to_string(),
        "the interval [1/2, 1/2] has length zero: cannot reparametrize onto it"
    );
}

#[test]
fn conversions_between_number_types() {
    let a = pq("sqrt2/2 u + 1/3");
    assert_eq!(
        a.convert::<Q>().unwrap_err().to_string(),
        "coefficient √2/2 cannot be converted: √2/2 is not a rational number (it has a square root) where a rational is required"
    );
    let b = pq("u/2 + 1/3").convert::<Q>().unwrap();
    assert_eq!(b, p("1/2 u + 1/3"));
    let f = b.convert::<f64>().unwrap();
    assert_eq!(f.eval(&[(Var::U, 1.0)]).unwrap(), 0.5 + 1.0 / 3.0);
    assert!(f
        .convert::<Q>()
        .unwrap_err()
        .to_string()
        .contains("not an exact number"));
    let m: Poly<Quadratic> = b.map_coeffs(|c| Quadratic::from_rational(c.clone()));
    assert_eq!(m, pq("1/2 u + 1/3"));
}

#[test]
fn quadratic_coefficients() {
    let a = pq("sqrt2/2 u + 1");
    let sq = &a * &a;
    assert_eq!(sq.to_text(), "1/2 u^2 + √2 u + 1");
    assert_eq!(sq.to_latex(), r"\frac{1}{2} u^{2} + \sqrt{2} u + 1");
    assert_eq!(sq.to_json_string(), "1/2*u^2 + sqrt2*u + 1");
    let x = a.eval(&[(Var::U, parse_number_q("sqrt2"))]).unwrap();
    assert_eq!(x.to_text(), "2");
    let c = pq("(1/2 + sqrt2) u - (1/2 - sqrt2) v + (1 - sqrt2)");
    assert_eq!(c.to_text(), "(1/2 + √2) u - (1/2 - √2) v + 1 - √2");
    assert_eq!(
        c.to_latex(),
        r"\left(\frac{1}{2} + \sqrt{2}\right) u - \left(\frac{1}{2} - \sqrt{2}\right) v + 1 - \sqrt{2}"
    );
    assert_eq!(parse_expr(&c.to_text()).unwrap(), Expr::Scalar(c.clone()));
    assert_eq!(parse_expr(&c.to_json_string()).unwrap(), Expr::Scalar(c));
}

fn parse_number_q(text: &str) -> Quadratic {
    cagd_scalar::parse_number(text).unwrap()
}

// ---------------------------------------------------------------- vectors and rational maps

#[test]
fn vector_maps() {
    let c = vp("(u, v + 1, u^2 + v^3)");
    assert_eq!(c.dim(), 3);
    assert_eq!(c.degree(), 3);
    assert_eq!(c.vars(), vec![Var::U, Var::V]);
    // the variables of the components together, in canonical order, whatever each holds
    assert_eq!(vp("(z, 1, t^2 u)").vars(), vec![Var::U, Var::T, Var::Z]);
    assert_eq!(vp("(1, 2)").vars(), Vec::<Var>::new());
    assert_eq!(c.partial(Var::U).to_text(), "(1, 0, 2 u)");
    assert_eq!(c.partial(Var::V).to_text(), "(0, 1, 3 v^2)");
    let n = c.partial(Var::U).cross(&c.partial(Var::V)).unwrap();
    assert_eq!(n.to_text(), "(-2 u, -3 v^2, 1)");
    assert!(n.dot(&c.partial(Var::U)).unwrap().is_zero());
    assert!(n.dot(&c.partial(Var::V)).unwrap().is_zero());
    let pt = c.eval(&[(Var::U, q!(1 / 2)), (Var::V, q!(-1))]).unwrap();
    assert_eq!(pt, Point::new(vec![q!(1 / 2), q!(0), q!(-3 / 4)]));
    let a = Point::from_ints(&[0, 1, 0]);
    assert_eq!(c.add_point(&-a).unwrap().to_text(), "(u, v, v^3 + u^2)");
    let flat = vp("(u, v)");
    assert_eq!(
        c.checked_add(&flat).unwrap_err().to_string(),
        "adding polynomial maps: expected dimension 3, found 2"
    );
    assert!(flat.cross(&flat).is_err());
    assert!(c.checked_sub(&c).unwrap().is_zero());
    assert_eq!(c.substitute_value(Var::V, &q!(0)).to_text(), "(u, 1, u^2)");
    assert_eq!(VecPoly::<Q>::zero(2).to_text(), "(0, 0)");
    assert_eq!(c.to_latex(), r"\left(u, v + 1, v^{3} + u^{2}\right)");
    assert_eq!(
        c.mul_poly(&p("u")).scale(&q!(2)).to_text(),
        "(2 u^2, 2 u v + 2 u, 2 u v^3 + 2 u^3)"
    );
}

#[test]
fn rational_maps() {
    let h = vp("(1 - t^2, 2 t, 1 + t^2)");
    let c = RationalMap::from_homogeneous(&h).unwrap();
    assert_eq!(c.dim(), 2);
    assert_eq!(c.to_homogeneous(), h);
    assert_eq!(c.eval(&[(Var::T, q!(1))]).unwrap().to_text(), "(0, 1)");
    let d = c.partial(Var::T);
    assert_eq!(d.denominator().to_text(), "t^4 + 2 t^2 + 1");
    assert_eq!(d.numerator().to_text(), "(-4 t, -2 t^2 + 2)");
    // the quarter circle's tangent at t = 1/2 is orthogonal to the radius
    let at = [(Var::T, q!(1 / 2))];
    let pt = c.eval(&at).unwrap();
    assert_eq!(pt.dot(&d.eval(&at).unwrap()), q!(0));
    let line = RationalMap::from_homogeneous(&vp("(t, t - 1)")).unwrap();
    assert_eq!(
        line.eval(&[(Var::T, q!(1))]).unwrap_err().to_string(),
        "the denominator vanishes at (t = 1)"
    );
    assert!(RationalMap::new(vp("(t, 1)"), Poly::zero()).is_err());
    let poly = RationalMap::from_polynomial(vp("(t, t^2)"));
    assert_eq!(poly.to_text(), "(t, t^2)");
    assert_eq!(poly.partial(Var::T).eval(&at).unwrap().to_text(), "(1, 1)");
    assert_eq!(
        c.to_latex(),
        r"\frac{1}{t^{2} + 1} \left(-t^{2} + 1, 2 t\right)"
    );
}

#[test]
fn rational_map_over_quadratic_and_f64() {
    // quarter circle as a rational quadratic Bézier curve, weights 1, √2/2, 1
    let w = parse_number_q("sqrt2/2");
    let one = Quadratic::from_rational(q!(1));
    let zero = Quadratic::from_rational(q!(0));
    let pts = [
        Point::new(vec![one.clone(), zero.clone()]).to_homogeneous(&one),
        Point::new(vec![one.clone(), one.clone()]).to_homogeneous(&w),
        Point::new(vec![zero.clone(), one.clone()]).to_homogeneous(&one),
    ];
    let h = from_bernstein_1d(&pts, Var::T).unwrap();
    let c = RationalMap::from_homogeneous(&h).unwrap();
    let half = Quadratic::from_rational(q!(1 / 2));
    let pt = c.eval(&[(Var::T, half)]).unwrap();
    assert_eq!(pt.to_text(), "(√2/2, √2/2)");
    assert_eq!(pt.dot(&pt), one);
    let cf = RationalMap::from_homogeneous(&h.map_coeffs(|x| x.to_f64())).unwrap();
    let pf = cf.eval(&[(Var::T, 0.25)]).unwrap();
    assert!((pf.dot(&pf) - 1.0).abs() < 1e-12);
}

// ---------------------------------------------------------------- Bernstein

#[test]
fn bernstein_polynomials() {
    assert_eq!(bernstein::<Q>(0, 2, Var::U).to_text(), "u^2 - 2 u + 1");
    assert_eq!(bernstein::<Q>(2, 2, Var::U).to_text(), "u^2");
    assert!(bernstein::<Q>(3, 2, Var::U).is_zero());
    // partition of unity
    let sum = (0..=5).fold(Poly::<Q>::zero(), |acc, i| acc + bernstein(i, 5, Var::V));
    assert_eq!(sum, Poly::one());
}

#[test]
fn bernstein_xy_of_chapter_5() {
    let xy = p("x y");
    let c = to_bernstein_2d(&xy, Var::X, Var::Y, 1, 1).unwrap();
    assert_eq!(c, vec![vec![q!(0), q!(0)], vec![q!(0), q!(1)]]);
    // the graph (x, y, xy) has the mesh {(0,0,0), (0,1,0); (1,0,0), (1,1,1)}
    let graph = vp("(x, y, x y)");
    let mesh = control_mesh(&graph, Var::X, Var::Y, 1, 1).unwrap();
    let text: Vec<Vec<String>> = mesh
        .iter()
        .map(|row| row.iter().map(|pt| pt.to_text()).collect())
        .collect();
    assert_eq!(
        text,
        [["(0, 0, 0)", "(0, 1, 0)"], ["(1, 0, 0)", "(1, 1, 1)"]]
    );
    assert_eq!(from_bernstein_2d(&mesh, Var::X, Var::Y).unwrap(), graph);
    // at bidegree (2, 1) the x coordinates are i/m = 0, 1/2, 1 (chapter 5, eq. (3))
    let mesh21 = control_mesh(&graph, Var::X, Var::Y, 2, 1).unwrap();
    assert_eq!(mesh21[1][1].to_text(), "(1/2, 1, 1/2)");
}

#[test]
fn bernstein_errors() {
    let a = p("u^3 + v");
    assert_eq!(
        to_bernstein_1d(&a, Var::U, 3).unwrap_err().to_string(),
        "the polynomial depends on v, but the Bernstein basis is in u only"
    );
    assert_eq!(
        to_bernstein_2d(&a, Var::U, Var::V, 2, 1)
            .unwrap_err()
            .to_string(),
        "the polynomial has degree 3 in u, more than the degree 2 of the Bernstein basis"
    );
    assert!(to_bernstein_2d(&a, Var::U, Var::U, 3, 3).is_err());
    let ragged = vec![vec![q!(1), q!(2)], vec![q!(3)]];
    assert_eq!(
        poly_from_bernstein_2d(&ragged, Var::U, Var::V)
            .unwrap_err()
            .to_string(),
        "row 1 of the control mesh has 1 points but row 0 has 2"
    );
    assert!(poly_from_bernstein_2d::<Q>(&[], Var::U, Var::V).is_err());
    assert_eq!(
        from_bernstein_1d::<Q>(&[], Var::U).unwrap_err().to_string(),
        "the control polygon is empty"
    );
    let mixed: Vec<Point<Q>> = vec![Point::from_ints(&[1, 2]), Point::from_ints(&[1, 2, 3])];
    assert_eq!(
        from_bernstein_1d(&mixed, Var::U).unwrap_err().to_string(),
        "points of the control polygon: expected dimension 2, found 3"
    );
    assert!(poly_from_bernstein_1d::<Q>(&[], Var::U).is_zero());
    assert_eq!(
        to_bernstein_1d(&Poly::<Q>::zero(), Var::U, 0).unwrap(),
        vec![q!(0)]
    );
}

#[test]
fn bernstein_over_f64() {
    let c = poly_from_bernstein_1d(&[0.0, 1.0, 0.0], Var::T);
    assert_eq!(c.eval(&[(Var::T, 0.5)]).unwrap(), 0.5);
    let back = to_bernstein_1d(&c, Var::T, 3).unwrap();
    let expect = [0.0, 2.0 / 3.0, 2.0 / 3.0, 0.0];
    for (a, b) in back.iter().zip(expect) {
        assert!((a - b).abs() < 1e-12);
    }
}

// ---------------------------------------------------------------- parser and printers

#[test]
fn brief_examples_parse() {
    assert_eq!(
        parse_expr("(u, v + 1, u^2 + v^3)").unwrap().to_text(),
        "(u, v + 1, v^3 + u^2)"
    );
    let ruled = parse_expr("(1 - v)*(u, 0, u^3) + v*(u, 1, u^2)").unwrap();
    assert_eq!(ruled.to_text(), "(u, v, -u^3 v + u^3 + u^2 v)");
    let s = parse_expr("3/2*u^2 - sqrt2/2*v").unwrap();
    assert_eq!(s.to_text(), "3/2 u^2 - √2/2 v");
    assert_eq!(s.to_latex(), r"\frac{3}{2} u^{2} - \frac{\sqrt{2}}{2} v");
    assert_eq!(s.to_json_string(), "3/2*u^2 - sqrt2/2*v");
    assert_eq!(
        parse_expr("(1-v)(u,0,u^3)").unwrap(),
        parse_expr("(1-v)*(u,0,u^3)").unwrap()
    );
    assert_eq!(parse_expr("(sqrt2/2)^2").unwrap().to_text(), "1/2");
    assert_eq!(parse_expr("2uv").unwrap().to_text(), "2 u v");
    assert_eq!(parse_expr("uvu").unwrap().to_text(), "u^2 v");
    // a power binds to the last letter of a name, as the notes write vu^2 and uv^2
    assert_eq!(parse_expr("vu^2").unwrap().to_text(), "u^2 v");
    assert_eq!(
        parse_expr("uv^2 - (uv)^2").unwrap().to_text(),
        "-u^2 v^2 + u v^2"
    );
    assert_eq!(
        parse_expr("2uvw^-1").unwrap_err().to_string(),
        "at column 5: a negative power of the polynomial w is not a polynomial"
    );
    assert_eq!(parse_expr("(u, v)/2").unwrap().to_text(), "(1/2 u, 1/2 v)");
    assert_eq!(parse_expr("(u, v) * u").unwrap().to_text(), "(u^2, u v)");
    assert_eq!(
        parse_expr("-(u, v) + (1, 1)").unwrap().to_text(),
        "(-u + 1, -v + 1)"
    );
    assert_eq!(parse_expr("2^-2 u").unwrap().to_text(), "1/4 u");
    assert_eq!(parse_expr("sqrt(8) x").unwrap().to_text(), "2√2 x");
    assert_eq!(parse_expr("0.125 z").unwrap().to_text(), "1/8 z");
    assert_eq!(parse_expr("−u · v").unwrap().to_text(), "-u v");
}

#[test]
fn parse_errors_name_their_column() {
    assert_eq!(
        err("(u + 1"),
        "at column 7: expected ')' (unbalanced parenthesis), found the end of the input"
    );
    assert_eq!(
        err("u + 1)"),
        "at column 6: expected an operator or the end of the input (is a parenthesis unbalanced?), found ')'"
    );
    assert_eq!(
        err("u + q"),
        "at column 5: unknown variable 'q' (the variables are u, v, w, t, s, x, y, z; 'uv' means u v)"
    );
    assert!(err("2 uq").starts_with("at column 4: unknown variable 'q'"));
    assert!(err("sin(u)").starts_with("at column 2: unknown variable 'i'"));
    assert_eq!(err("1/0"), "at column 2: division by zero");
    assert_eq!(err("u/(1 - 1)"), "at column 2: division by zero");
    assert_eq!(
        err("sqrt(-2)"),
        "at column 1: square root of a negative number (-2) is not real"
    );
    assert_eq!(
        err("sqrt2 u + sqrt3"),
        "at column 11: numbers with √2 and √3 cannot be mixed: an expression runs in one field a + b√d"
    );
    assert_eq!(
        err("(u, v) * (u, v)"),
        "at column 8: cannot multiply a tuple by a tuple (multiply a tuple by a scalar polynomial)"
    );
    assert_eq!(
        err("(u, v)(u, v)"),
        err("(u, v) * (u, v)").replace("column 8", "column 7")
    );
    assert_eq!(
        err("1/u"),
        "at column 2: division by a polynomial is not a polynomial (divisor u; only nonzero constants can divide)"
    );
    assert!(err("sqrt(u)").contains("sqrt of the polynomial u is not a polynomial"));
    assert!(err("sqrt(sqrt2)").contains("a number with a root"));
    assert!(err("(u, v) + 1").contains("cannot add a scalar and a tuple"));
    assert!(err("(u, v) - (u, v, w)").contains("cannot subtract tuples of 2 and 3 components"));
    assert!(err("((u, v), w)").contains("a tuple inside a tuple"));
    assert!(err("(u, v)^2").contains("cannot raise a tuple to a power"));
    assert!(err("u^-1").contains("a negative power of the polynomial u is not a polynomial"));
    assert!(err("0^-1").contains("division by zero"));
    assert!(err("u/(u, v)").contains("cannot divide by a tuple"));
    assert!(err("sqrt((1, 2))").contains("sqrt of a tuple"));
    assert!(err("").contains("expected an expression"));
    assert!(err("u^1000 * v^1000 * w")
        .contains("at column 17: expression too large to expand: degree 2001 is more than 2000"));
    let big = "(u + v + w + t + s + x + y + z + 1)^4";
    assert_eq!(parse_poly::<Q>(big).unwrap().num_terms(), 495);
    assert_eq!(
        err(&format!("{big} * {big}")),
        "at column 39: expression too large to expand: more than 100000 products of 64-bit words (at a product of 495 by 495 terms)"
    );
    // large but admissible
    assert_eq!(parse_poly::<Q>("(1 + u)^30").unwrap().num_terms(), 31);
    assert_eq!(parse_poly::<Q>("u^1000 v^1000").unwrap().degree(), 2000);
    assert_eq!(
        parse_poly::<Q>("(u, v)").unwrap_err().to_string(),
        "expected a scalar polynomial, found a tuple of 2 polynomials"
    );
    assert_eq!(
        parse_vec_poly::<Q>("u").unwrap_err().to_string(),
        "expected a tuple of polynomials, found the scalar polynomial u"
    );
    assert!(parse_poly::<Q>("sqrt2 u").is_err());
}

/// Found by the `parse_expr` fuzz target: `((u + 0)^37)^37y` read as u^1369 y, which prints
/// to text the reader refuses (an exponent above 1000). Whatever reads now prints to text
/// that reads back: exponents and coefficients are bounded by the grammar's limits.
#[test]
fn what_reads_prints_to_text_that_reads_back() {
    let e = crate::parse_expr("((u + 0)^37)^37y")
        .unwrap_err()
        .to_string();
    assert_eq!(
        e,
        "at column 13: expression too large to expand: the power u^1369, above the exponent limit of 1000"
    );
    let c = crate::parse_expr("(10^999*u)^11").unwrap_err().to_string();
    assert!(c.contains("a coefficient: a number of"), "{c}");
    for text in ["(u^30 v)^33", "((u + 1)^2)^3 * v^1000", "(3/7)^900 u"] {
        let x = crate::parse_expr(text).unwrap();
        assert_eq!(crate::parse_expr(&x.to_text()).unwrap(), x, "{text}");
        assert_eq!(crate::parse_expr(&x.to_json_string()).unwrap(), x, "{text}");
    }
}
