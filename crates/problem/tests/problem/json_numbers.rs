//! How JSON itself is read (issue 19): integers of any length exactly, `-0` and `1.0` as the
//! integers they are, an unknown key refused without reading what it holds, a long number
//! string read once within the limits.

use cagd_problem::{solve, solve_batch, solve_with, Limits, Problem};
use serde_json::Value;

/// A problem as a teacher writes it: text, read by serde_json as `cagd solve` reads it.
fn parse(text: &str) -> Value {
    serde_json::from_str(text).unwrap()
}

/// `elevate` of a quadratic curve whose second control point is `x` (JSON text).
fn elevate_with(x: &str) -> String {
    format!(r#"{{"op": "elevate", "curve": {{"bezier": [[0, 0], [{x}, 2], [3, 3]]}}, "by": 1}}"#)
}

fn answer(text: &str) -> Value {
    solve(&parse(text)).unwrap().to_json(false)
}

fn error(text: &str) -> String {
    solve(&parse(text)).unwrap_err().to_string()
}

#[test]
fn json_integers_of_any_length_are_read_exactly() {
    for digits in [19, 20, 25, 308, 309, 400, 1000] {
        let n = "7".repeat(digits);
        assert_eq!(
            answer(&elevate_with(&n)),
            answer(&elevate_with(&format!("\"{n}\""))),
            "{digits} digits"
        );
        assert_eq!(
            answer(&elevate_with(&format!("-{n}"))),
            answer(&elevate_with(&format!("\"-{n}\""))),
            "-{digits} digits"
        );
    }
}

#[test]
fn a_json_integer_past_the_digit_limit_fails_its_problem_alone() {
    let long = elevate_with(&"9".repeat(1001));
    let good = elevate_with("1");
    let batch = parse(&format!("[{good}, {long}, {good}]"));
    let answers = solve_batch(&batch);
    assert!(answers[0].is_ok() && answers[2].is_ok());
    assert_eq!(
        answers[1].as_ref().unwrap_err().to_string(),
        "problem 2: field `curve.bezier[1][0]`: the number 999…9 has 1001 digits, more than the \
         limit of 1000 digits"
            .replace("999…9", &"9".repeat(1001))
    );
    // written with an exponent, refused before its digits are written out
    assert_eq!(
        error(&elevate_with("1e999999999999")),
        "field `curve.bezier[1][0]`: the number 1e+999999999999 has 1000000000000 digits, more \
         than the limit of 1000 digits"
    );
}

#[test]
fn integral_json_numbers_are_the_integers_they_are() {
    let one = answer(&elevate_with("1"));
    assert_eq!(answer(&elevate_with("1.0")), one);
    assert_eq!(answer(&elevate_with("1.000e0")), one);
    assert_eq!(answer(&elevate_with("0.1e1")), one);
    assert_eq!(answer(&elevate_with("-0")), answer(&elevate_with("0")));
    assert_eq!(answer(&elevate_with("-0.0")), answer(&elevate_with("0")));
    assert_eq!(answer(&elevate_with("2e3")), answer(&elevate_with("2000")));
}

#[test]
fn json_numbers_with_a_fraction_part_name_the_exact_way() {
    for (written, shown) in [("0.5", "0.5"), ("1.25e0", "1.25e+0"), ("25e-1", "25e-1")] {
        assert_eq!(
            error(&elevate_with(written)),
            format!(
                "field `curve.bezier[1][0]`: the number {shown} has a fraction part; write it as \
                 a string (\"{shown}\") so it is read exactly"
            )
        );
    }
}

#[test]
fn an_unknown_key_is_refused_without_reading_what_it_holds() {
    // a √3 under an unknown key does not clash with the √2 of the problem
    let p = r#"{"op": "elevate", "comment": "sqrt3",
               "curve": {"bezier": [[0, 0], ["sqrt2", 2], [3, 3]]}, "by": 1}"#;
    assert_eq!(
        error(p),
        "field `comment`: unknown key: `elevate` takes `surface`, `curve`, `triangle`, `by`"
    );
    let p = r#"{"op": "elevate", "curve": {"bezier": [[0, 0], ["sqrt2", 2], [3, 3]]}, "by": 1,
               "byy": "sqrt3"}"#;
    assert_eq!(
        error(p),
        "field `byy`: unknown key: did you mean `by`? `elevate` takes `surface`, `curve`, `triangle`, `by`"
    );
    // text that is no number at all, and long, is not read as one
    let junk = "x".repeat(900_000);
    let p = format!(r#"{{"op": "circle", "arcs": 4, "comment": "{junk}"}}"#);
    assert_eq!(
        error(&p),
        "field `comment`: unknown key: `circle` takes `radius`, `arcs`, `center`, `interval`, `sweep`, `start`"
    );
}

#[test]
fn a_long_number_string_is_read_once_within_the_limits() {
    let limits = Limits {
        max_digits: 1_000_000,
        ..Limits::default()
    };
    // 999,000 characters: under the 1,000,000 of the grammar's length limit
    let n = "1".repeat(998_998);
    let text = format!(r#"{{"op": "closed_form", "curve": {{"bezier": [[0, 0], ["{n}/3", 1]]}}}}"#);
    let problem = Problem::read(&parse(&text), &limits).unwrap();
    assert_eq!(problem.op_name(), "closed_form");
    // past the default digit limit: refused, naming the limit
    let e = solve_with(&parse(&text), &Limits::default())
        .unwrap_err()
        .to_string();
    assert!(e.contains("has more than 1000 digits"), "{e}");
}

/// A decimal that looks like a truncated repeating fraction is read exactly as written, with a
/// remark naming the fraction that may be meant; other decimals get none.
#[test]
fn a_truncated_repeating_decimal_gets_a_remark() {
    use cagd_problem::spec::repeating_decimal;
    let fraction = |s: &str| {
        repeating_decimal(s).map(|e| {
            cagd_scalar::Print::to_text(&cagd_problem::read_number(&e, &Limits::DEFAULT).unwrap())
        })
    };
    assert_eq!(fraction("0.3333").as_deref(), Some("1/3"));
    assert_eq!(fraction("0.6667").as_deref(), Some("2/3"));
    assert_eq!(fraction("0.16667").as_deref(), Some("1/6"));
    assert_eq!(fraction("2.1111").as_deref(), Some("19/9"));
    assert_eq!(fraction("-0.33333333").as_deref(), Some("-1/3"));
    for exact in [
        "0.25", "0.333", "0.125", "0.0000", "0.9999", "1.2345", "1/3", "3333",
    ] {
        assert_eq!(fraction(exact), None, "{exact}");
    }
    let a = solve(&parse(
        r#"{"op": "evaluate", "curve": {"bezier": [[0, 0], [3, 3]]}, "params": ["0.3333", "0.25"]}"#,
    ))
    .unwrap();
    assert_eq!(
        a.remarks,
        [r#""0.3333" is read exactly as 3333/10000; if 1/3 is meant, write "1/3""#]
    );
    assert_eq!(a.to_json(false)["result"]["points"][0][0], "9999/10000");
    assert!(answer(&elevate_with("\"0.25\"")).get("remarks").is_none());
}
