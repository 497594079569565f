use super::*;
use cagd_scalar::{FieldOps, Limits, Print, Quadratic, SquareRoot};
use num_traits::{One, Zero};
use proptest::prelude::*;

fn p(text: &str) -> Param {
    let names: Vec<Name> = ["R", "a", "b", "c", "d", "w"]
        .iter()
        .map(|n| Name::new(n))
        .collect();
    parse_param(text, &names, &Limits::default()).unwrap()
}

#[test]
fn prints_as_the_notes() {
    assert_eq!(p("sqrt2/2*R").to_text(), "√2 R/2");
    assert_eq!(p("sqrt2/2*R").to_latex(), r"\frac{\sqrt{2} R}{2}");
    assert_eq!(p("(2a + c)/3").to_text(), "(2 a + c)/3");
    assert_eq!(p("(2a + c)/3").to_latex(), r"\frac{2 a + c}{3}");
    assert_eq!(p("-R").to_text(), "-R");
    assert_eq!(p("-R/2").to_latex(), r"-\frac{R}{2}");
    assert_eq!(p("a^2 b - 1").to_text(), "a^2 b - 1");
    assert_eq!(p("1/(a+b)").to_text(), "1/(a + b)");
    assert_eq!(p("R/(2a)").to_text(), "R/(2 a)");
    assert_eq!(p("(1 + sqrt2) a").to_text(), "(1 + √2) a");
    assert_eq!(p("3/4").to_text(), "3/4");
}

#[test]
fn json_reads_back() {
    for t in [
        "sqrt2/2*R",
        "(2a + c)/3",
        "1/(a+b)",
        "(1 - sqrt2) a^2/(b - 3)",
        "R/(2a)",
        "-a b/7",
    ] {
        let x = p(t);
        let back = p(&x.to_json_string());
        assert_eq!(back, x, "{t} → {}", x.to_json_string());
    }
}

#[test]
fn reduces() {
    assert_eq!(p("R^2/R"), p("R"));
    assert!(p("R/R").is_const());
    assert_eq!(p("(a^2 - b^2)/(a - b)").to_text(), "a + b");
    assert_eq!(p("(a - b)/(a^2 - b^2)").to_text(), "1/(a + b)");
    // not reduced, but equal
    let x = p("((a+b)(a-c))/((a+b)(a+c))");
    assert_eq!(x, p("(a-c)/(a+c)"));
    assert!((x - p("(a-c)/(a+c)")).is_zero());
}

#[test]
fn no_sign_for_letters() {
    assert_eq!(p("a").compare(&p("b")), None);
    assert_eq!(p("a").compare(&p("a")), Some(std::cmp::Ordering::Equal));
    assert_eq!(
        p("1/2").compare(&p("1/3")),
        Some(std::cmp::Ordering::Greater)
    );
}

#[test]
fn undeclared_letter_is_named() {
    let e = parse_param("2 q", &[Name::new("R")], &Limits::default()).unwrap_err();
    assert!(
        e.to_string()
            .contains("'q', which is not a declared parameter"),
        "{e}"
    );
    assert!(e.to_string().contains("(R)"), "{e}");
}

#[test]
fn roots_stay_exact() {
    let h = <Param as SquareRoot>::sqrt_of(2).unwrap() / Param::from_i64(2);
    assert_eq!((h.clone() * &h).to_text(), "1/2");
    assert_eq!((h * p("R") * p("R")).to_text(), "√2 R^2/2");
    assert!(parse_param("sqrt2 a + sqrt3", &[Name::new("a")], &Limits::default()).is_err());
}

#[test]
fn natural_order_of_subscripts() {
    let mut names = [Name::new("c_{10,0}"), Name::new("c_{2,0}"), Name::new("a")];
    names.sort();
    let s: Vec<&str> = names.iter().map(Name::as_str).collect();
    assert_eq!(s, ["a", "c_{2,0}", "c_{10,0}"]);
}

fn small() -> impl Strategy<Value = Param> {
    (-4i64..5, -4i64..5, -3i64..4, 1i64..4)
        .prop_map(|(x, y, k, q)| p(&format!("({x} a + {y} b + {k})/{q}")))
}

proptest! {
    #[test]
    fn field_laws(x in small(), y in small(), z in small()) {
        prop_assert_eq!(x.clone() * (y.clone() + &z), x.clone() * &y + x.clone() * &z);
        prop_assert_eq!((x.clone() + &y) - &y, x.clone());
        if !y.is_zero() {
            prop_assert_eq!((x.clone() / &y) * &y, x.clone());
        }
    }

    #[test]
    fn substitution_is_a_homomorphism(x in small(), y in small(), a in -5i64..6, b in -5i64..6) {
        let v = [(Name::new("a"), Param::from_i64(a)), (Name::new("b"), Param::from_i64(b))];
        let s = |t: &Param| t.substitute(&v).unwrap();
        prop_assert_eq!(s(&(x.clone() * &y)), s(&x) * s(&y));
        prop_assert_eq!(s(&(x.clone() + &y)), s(&x) + s(&y));
        prop_assert!(s(&x).is_const());
    }
}

#[test]
fn constants_are_quadratic() {
    assert_eq!(p("1/2").as_const(), Some(&Quadratic::from_ratio(1, 2)));
    assert!(Param::one().is_one());
}
