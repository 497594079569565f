use crate::{
    parse_literal, parse_number, parse_number_with, parse_with, word_literal, BigInt, BigRational,
    ExactRational, FieldOps, Limits, NumberBuilder, Print, Quadratic, Scalar, ScalarError,
    SquareRoot,
};
use num_traits::{One, Zero};
use proptest::prelude::*;

fn rat() -> impl Strategy<Value = BigRational> {
    (-50i64..50, 1i64..20).prop_map(|(n, d)| BigRational::new(BigInt::from(n), BigInt::from(d)))
}

fn quad() -> impl Strategy<Value = Quadratic> {
    (rat(), rat()).prop_map(|(a, b)| Quadratic::new(a, b, 2).expect("2 is square-free"))
}

/// The field axioms, checked on any scalar.
fn field_axioms<S: Scalar>(a: S, b: S, c: S) {
    assert_eq!(a.clone() + b.clone(), b.clone() + a.clone());
    assert_eq!(a.clone() * b.clone(), b.clone() * a.clone());
    assert_eq!(
        (a.clone() + b.clone()) + c.clone(),
        a.clone() + (b.clone() + c.clone())
    );
    assert_eq!(
        (a.clone() * b.clone()) * c.clone(),
        a.clone() * (b.clone() * c.clone())
    );
    assert_eq!(
        a.clone() * (b.clone() + c.clone()),
        a.clone() * b.clone() + a.clone() * c.clone()
    );
    assert_eq!(a.clone() + S::zero(), a.clone());
    assert_eq!(a.clone() * S::one(), a.clone());
    assert_eq!(a.clone() - a.clone(), S::zero());
    if !a.is_zero() {
        assert_eq!(a.clone() * (S::one() / a.clone()), S::one());
        assert_eq!(b.checked_div(&a).map(|x| x * &a), Some(b.clone()));
    }
    // by-reference forms agree with the by-value ones
    assert_eq!(a.add_ref(&b), a.clone() + b.clone());
    assert_eq!(a.sub_ref(&b), a.clone() - &b);
    assert_eq!(a.mul_ref(&b), a.clone() * &b);
    let mut x = a.clone();
    x += &b;
    x *= &c;
    x -= b.clone();
    assert_eq!(x, (a.clone() + &b) * &c - b.clone());
    assert_eq!(a.powi(3), a.clone() * &a * &a);
}

proptest! {
    #[test]
    fn rationals_form_a_field(a in rat(), b in rat(), c in rat()) {
        field_axioms(a, b, c);
    }

    #[test]
    fn quadratic_numbers_form_a_field(a in quad(), b in quad(), c in quad()) {
        field_axioms(a, b, c);
    }

    #[test]
    fn quadratic_order_agrees_with_f64(a in quad(), b in quad()) {
        let (x, y) = (a.to_f64(), b.to_f64());
        if (x - y).abs() > 1e-9 {
            prop_assert_eq!(a < b, x < y);
        }
        prop_assert_eq!(a.partial_cmp(&a), Some(std::cmp::Ordering::Equal));
    }

    #[test]
    fn numbers_read_back_from_every_printer(a in quad()) {
        prop_assert_eq!(parse_number(&a.to_json_string()).unwrap(), a.clone());
        prop_assert_eq!(parse_number(&a.to_text()).unwrap(), a.clone());
    }

    #[test]
    fn rationals_read_back(a in rat()) {
        prop_assert_eq!(parse_number(&a.to_json_string()).unwrap().to_rational(), Some(a.clone()));
        prop_assert_eq!(BigRational::try_from_number(&parse_number(&a.to_text()).unwrap()).unwrap(), a);
    }
}

#[test]
fn grammar_examples() {
    let t = |s: &str| parse_number(s).unwrap().to_text();
    assert_eq!(t("5/6"), "5/6");
    assert_eq!(t("0.125"), "1/8");
    assert_eq!(t("-3"), "-3");
    assert_eq!(t("sqrt2/2"), "√2/2");
    assert_eq!(t("√2/2"), "√2/2");
    assert_eq!(t("1/2 + 3/4*sqrt(2)"), "1/2 + 3√2/4");
    assert_eq!(t("1/2 - 3/4*√(2)"), "1/2 - 3√2/4");
    assert_eq!(t("(sqrt2/2)^2"), "1/2");
    assert_eq!(t("1/sqrt2"), "√2/2");
    assert_eq!(t("sqrt(1/2)"), "√2/2");
    assert_eq!(t("sqrt12"), "2√3");
    assert_eq!(t("sqrt(9/4)"), "3/2");
    assert_eq!(t("2^-1"), "1/2");
    assert_eq!(t("2^(-2)"), "1/4");
    assert_eq!(t("3 √2 / 4"), "3√2/4");
    assert_eq!(t("−1.5"), "-3/2");
    assert_eq!(t("-√3"), "-√3");
    assert_eq!(t("sqrt2 * sqrt2 + sqrt3"), "2 + √3");
}

#[test]
fn printers() {
    let x = parse_number("1/2 + 3/4*sqrt2").unwrap();
    assert_eq!(x.to_latex(), r"\frac{1}{2} + \frac{3\sqrt{2}}{4}");
    assert_eq!(x.to_json_string(), "1/2 + 3*sqrt2/4");
    let h = parse_number("sqrt2/2").unwrap();
    assert_eq!(h.to_latex(), r"\frac{\sqrt{2}}{2}");
    assert_eq!(h.to_json_string(), "sqrt2/2");
    assert_eq!(crate::q!(5 / 6).to_latex(), r"\frac{5}{6}");
    assert_eq!(crate::q!(-5 / 6).to_latex(), r"-\frac{5}{6}");
    assert_eq!(crate::q!(-7).to_latex(), "-7");
    assert_eq!(parse_number("-sqrt3").unwrap().to_latex(), r"-\sqrt{3}");
    assert_eq!(
        parse_number("2 - sqrt3/2").unwrap().to_latex(),
        r"2 - \frac{\sqrt{3}}{2}"
    );
}

#[test]
fn conversions_between_scalars() {
    let h = parse_number("sqrt2/2").unwrap();
    let err = BigRational::try_from_number(&h).unwrap_err();
    assert!(matches!(err, ScalarError::NotRational { .. }));
    assert!(err.to_string().contains("√2/2 is not a rational number"));
    assert!((f64::try_from_number(&h).unwrap() - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-15);
    assert_eq!(Quadratic::try_from_number(&h).unwrap(), h);
    assert_eq!(crate::q!(9 / 4).sqrt_exact(), Some(crate::q!(3 / 2)));
    assert_eq!(crate::q!(2).sqrt_exact(), None);
    assert!(BigRational::is_exact() && Quadratic::is_exact() && !f64::is_exact());
    assert_eq!(<f64 as FieldOps>::from_ratio(1, 4), 0.25);
}

/// The roots algorithms take from the field (`S::sqrt_of(2) / 2`, never the text "sqrt2/2") are
/// the numbers the grammar reads, in every field that has them.
#[test]
fn roots_come_from_the_field() {
    fn half_root<S: Scalar>(n: u64) -> Option<S> {
        S::sqrt_of(n).map(|r| r / S::from_i64(2))
    }
    for (n, text) in [(2, "sqrt2/2"), (3, "sqrt3/2"), (8, "sqrt8/2"), (9, "3/2")] {
        let read = parse_number(text).unwrap();
        assert_eq!(half_root::<Quadratic>(n), Some(read.clone()), "{text}");
        assert_eq!(
            half_root::<f64>(n),
            Some(f64::try_from_number(&read).unwrap()),
            "{text}"
        );
    }
    assert_eq!(half_root::<BigRational>(2), None);
    assert_eq!(half_root::<BigRational>(3), None);
    assert_eq!(half_root::<BigRational>(9), Some(crate::q!(3 / 2)));
    assert_eq!(
        <BigRational as SquareRoot>::sqrt_of(0),
        Some(BigRational::zero())
    );
    assert_eq!(
        <Quadratic as SquareRoot>::sqrt_of(0),
        Some(Quadratic::zero())
    );
    assert_eq!(
        <Quadratic as SquareRoot>::sqrt_of(crate::quadratic::MAX_RADICAND + 1),
        None
    );
}

/// `compare` is the order where it is decided and `None` where it is not.
#[test]
fn compare_answers_none_where_the_order_is_undecided() {
    use std::cmp::Ordering;
    let n = |s: &str| parse_number(s).unwrap();
    assert_eq!(
        n("3 - 2*sqrt2").compare(&Quadratic::zero()),
        Some(Ordering::Greater)
    );
    assert_eq!(n("sqrt2").compare(&n("sqrt3")), None);
    assert_eq!(
        crate::q!(1 / 3).compare(&crate::q!(1 / 2)),
        Some(Ordering::Less)
    );
    assert_eq!(f64::NAN.compare(&0.0), None);
}

#[test]
fn bad_input_is_a_clear_error() {
    let e = |s: &str| parse_number(s).unwrap_err().to_string();
    assert_eq!(e("1/0"), "at column 2: division by zero");
    assert_eq!(e("(1/3)^0 / (1-1)"), "at column 9: division by zero");
    assert!(e("sqrt(-2)").contains("square root of a negative number (-2)"));
    assert!(e("sqrt2 + sqrt3").contains("√2 and √3 cannot be mixed"));
    assert_eq!(
        e("(1 + 2"),
        "at column 7: expected ')' (unbalanced parenthesis), found the end of the input"
    );
    assert!(e("1 + 2)").starts_with("at column 6: expected an operator or the end of the input"));
    assert_eq!(
        e("1 + u"),
        "at column 5: expected a number (variables are not allowed here), found 'u'"
    );
    assert_eq!(
        e("1 $ 2"),
        "at column 3: expected a number, a name, an operator or a parenthesis, found '$'"
    );
    assert_eq!(
        e(""),
        "at column 1: expected an expression, found the end of the input"
    );
    assert!(e("(1/3)^(10^9)").contains("exponent 1000000000 at column 6 is larger than 1000"));
    assert!(e("2^(1/2)").contains("expected an integer exponent"));
    let deep = "(".repeat(500) + "1" + &")".repeat(500);
    assert!(e(&deep).contains("nested deeper than 200"));
    assert!(e("1 +").contains("at column 4"));
    // mixing through the operators is refused loudly by the checked forms
    let r2 = parse_number("sqrt2").unwrap();
    let r3 = parse_number("sqrt3").unwrap();
    assert_eq!(
        r2.checked_mul(&r3),
        Err(ScalarError::MixedRoots {
            first: 2,
            second: 3
        })
    );
    assert_eq!(r2.partial_cmp(&r3), None);
    assert!(Quadratic::new(BigRational::one(), BigRational::one(), 8).is_err());
}

#[test]
fn quadratic_sign_is_exact() {
    // 3 - 2√2 = 0.1715... > 0 and 2√2 - 3 < 0: decided without floats
    let a = parse_number("3 - 2*sqrt2").unwrap();
    assert!(a > Quadratic::zero());
    assert!(-a < Quadratic::zero());
    // 1.4142 < √2 < 1.4143
    let r = parse_number("sqrt2").unwrap();
    assert!(parse_number("1.4142").unwrap() < r && r < parse_number("1.4143").unwrap());
}

/// Inputs found by the `parse_number` fuzz target (timeouts of the instrumented build, and a
/// value that printed to text longer than a literal may be): every power is bounded by the
/// digit limit before it is computed, also inside a parenthesized exponent.
#[test]
fn towers_of_powers_are_refused_before_they_are_computed() {
    let refused = |text: &str| match parse_number(text) {
        Err(ScalarError::Limit { what }) => what.to_string(),
        other => panic!("{text}: expected a limit error, got {other:?}"),
    };
    assert_eq!(
        refused("((10^3)^1000)^1000"),
        "the power at column 14 would have more than 10000 digits"
    );
    assert_eq!(
        refused("(((1010^151)^4)^151)^4), 1"),
        "the power at column 16 would have more than 10000 digits"
    );
    assert_eq!(
        refused("sqrt(4500700120.00046747^00847"),
        "the power at column 25 would have more than 10000 digits"
    );
    assert_eq!(
        refused("(24512^27)^375"),
        "the power at column 11 would have more than 10000 digits"
    );
    // inside an exponent, the bound is 1000 digits whatever the limits
    assert_eq!(
        refused("2^(((10^3)^1000)^1000)"),
        "the power at column 11 would have more than 1000 digits"
    );
    assert_eq!(
        refused("1022^((202-(2/3)^903)^80/4"),
        "the power at column 22 would have more than 1000 digits"
    );
    // a product of powers within the limit each is bounded too
    assert_eq!(
        refused("((10^1000)^6)*((10^1000)^6)"),
        "a number of more than 10000 digits"
    );
    // the slow input of the first fuzz run now reads its power, then finds the names
    assert!(parse_number("4.356200003211410^0380qr9")
        .unwrap_err()
        .to_string()
        .contains("variables are not allowed"));
    // what is within the limits still reads, exactly
    let x = parse_number("2^(2*5) - 2^(3^2)").unwrap();
    assert_eq!(x, Quadratic::from_i64(512));
    let big = parse_number("(1/3)^1000").unwrap();
    assert_eq!(big.to_text().len(), "1/".len() + 478);
}

/// Every number that reads prints to text that reads back to it, up to the limit.
#[test]
fn what_reads_prints_to_text_that_reads_back() {
    for text in [
        "(24512^27)^37",
        "(1/3)^1000",
        "(1 + sqrt2)^500",
        "3/7 - (2/9)^800*sqrt(5)",
    ] {
        let x = parse_number(text).unwrap();
        assert_eq!(parse_number(&x.to_json_string()).unwrap(), x, "{text}");
    }
    // the border is counted in digits, exactly
    let ten = crate::Limits {
        max_digits: 10,
        ..crate::Limits::default()
    };
    assert!(crate::parse_number_with("(10^9)*9", &ten).is_ok());
    assert_eq!(
        crate::parse_number_with("(10^9)*10", &ten)
            .unwrap_err()
            .to_string(),
        "limit exceeded: a number of 11 digits is longer than the limit of 10 digits"
    );
}

/// The grammar alone, without the literal fast path: the route [`parse_literal`] must agree
/// with.
fn grammar_only(text: &str, limits: &Limits) -> Result<Quadratic, ScalarError> {
    let x = parse_with(text, &mut NumberBuilder::new(limits), limits)?;
    limits.check_digits(&x)?;
    Ok(x)
}

/// Literal-shaped texts, some past the limits below, some not literals at all.
fn literal_text() -> impl Strategy<Value = String> {
    let digits = "[0-9]{0,14}";
    prop_oneof![
        ("-?", digits).prop_map(|(s, d)| format!("{s}{d}")),
        ("-?", digits, digits).prop_map(|(s, p, q)| format!("{s}{p}/{q}")),
        ("-?", digits, digits).prop_map(|(s, p, q)| format!("{s}{p}.{q}")),
        "[-0-9./ +]{0,8}",
    ]
}

proptest! {
    /// The fast path reads what the grammar reads, to the same value, and leaves the rest
    /// (and every error) to the grammar: `parse_number_with` answers as the grammar does.
    #[test]
    fn the_literal_fast_path_agrees_with_the_grammar(
        text in literal_text(),
        max_digits in 1usize..16,
        max_length in 1usize..20,
    ) {
        let limits = Limits { max_digits, max_length, ..Limits::default() };
        let grammar = grammar_only(&text, &limits);
        match parse_literal(&text, &limits) {
            Some(x) => prop_assert_eq!(Ok(x), grammar.clone()),
            None => {
                let plain = text.trim_start_matches('-');
                let literal_shaped = !text.is_empty()
                    && plain.bytes().all(|b| b.is_ascii_digit() || b == b'.' || b == b'/')
                    && plain.matches(['.', '/']).count() <= 1
                    && !text.starts_with("--");
                // a literal the grammar reads is one the fast path reads
                prop_assert!(!(literal_shaped && grammar.is_ok()),
                    "{text:?} read by the grammar only: {grammar:?}");
            }
        }
        prop_assert_eq!(parse_number_with(&text, &limits), grammar);
    }

    /// The one-pass reader of `±p` and `±p/q` reads what the grammar reads, to the same value
    /// (`0/9` is 0, `8/4` is 2); what it leaves (`1/0`, a decimal, a run past the limit or past
    /// 18 digits) is the grammar's.
    #[test]
    fn the_word_literal_agrees_with_the_grammar(
        text in prop_oneof![
            literal_text(),
            ("-?", "[0-9]{15,20}", "[0-9]{0,20}").prop_map(|(s, p, q)| format!("{s}{p}/{q}")),
        ],
        max_digits in 1usize..22,
    ) {
        let limits = Limits { max_digits, ..Limits::default() };
        let grammar = grammar_only(&text, &limits);
        match word_literal(&text, max_digits) {
            Some(x) => prop_assert_eq!(Ok(Quadratic::from_rat(x)), grammar),
            None => {
                let plain = text.strip_prefix('-').unwrap_or(&text);
                let (p, q) = plain.split_once('/').unwrap_or((plain, "1"));
                let short = |s: &str| !s.is_empty() && s.len() <= 18.min(max_digits)
                    && s.bytes().all(|b| b.is_ascii_digit());
                let word = short(p) && short(q)
                    && q.bytes().any(|b| b != b'0');
                prop_assert!(!word, "{text:?} left to the grammar");
            }
        }
    }
}

#[test]
fn long_literals_are_read_exactly_and_reduced() {
    let limits = Limits {
        max_digits: 1_000_000,
        ..Limits::default()
    };
    let ones = "1".repeat(300_000);
    let x = parse_literal(&format!("{ones}/3"), &limits).unwrap();
    // 111...1 (300,000 ones: the sum of its digits is a multiple of 3) is divisible by 3
    assert_eq!(x, grammar_only(&format!("{ones}/3"), &limits).unwrap());
    assert_eq!(*x.rational_part().denom(), BigInt::from(1));
    let half = parse_literal(&format!("-{ones}.50"), &limits).unwrap();
    assert_eq!(*half.rational_part().denom(), BigInt::from(2));
    assert_eq!(parse_literal("-0", &limits), Some(Quadratic::zero()));
    assert_eq!(parse_literal("-0.000", &limits), Some(Quadratic::zero()));
}
