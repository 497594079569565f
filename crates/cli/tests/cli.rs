//! Runs the built `cagd` binary.

use std::process::{Command, Output};

fn cagd(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(args)
        .output()
        .expect("the cagd binary runs")
}

fn stdout(out: &Output) -> String {
    String::from_utf8(out.stdout.clone()).expect("utf-8 output")
}

fn stderr(out: &Output) -> String {
    String::from_utf8(out.stderr.clone()).expect("utf-8 output")
}

/// Runs `cagd expand EXPR` expecting success; returns stdout.
fn expand_ok(args: &[&str]) -> String {
    let mut all = vec!["expand"];
    all.extend_from_slice(args);
    let out = cagd(&all);
    assert_eq!(out.status.code(), Some(0), "stderr: {}", stderr(&out));
    assert!(stderr(&out).is_empty());
    stdout(&out)
}

/// Runs `cagd expand EXPR` expecting bad input; returns the one-line stderr.
fn expand_err(expr: &str) -> String {
    let out = cagd(&["expand", expr]);
    assert_eq!(out.status.code(), Some(1), "input {expr}");
    assert!(stdout(&out).is_empty());
    let err = stderr(&out);
    assert_eq!(err.lines().count(), 1, "one line: {err}");
    assert!(!err.contains("panicked"));
    err
}

#[test]
fn expands_the_ruled_surface() {
    assert_eq!(
        expand_ok(&["(1-v)*(u,0,u^3) + v*(u,1,u^2)"]),
        "(u, v, -u^3 v + u^3 + u^2 v)\n"
    );
    assert_eq!(
        expand_ok(&["(1-v)(u,0,u^3) + v(u,1,u^2)"]),
        "(u, v, -u^3 v + u^3 + u^2 v)\n"
    );
}

#[test]
fn expands_exact_roots() {
    assert_eq!(expand_ok(&["(sqrt2/2)^2"]), "1/2\n");
    assert_eq!(expand_ok(&["3/2*u^2 - sqrt2/2*v"]), "3/2 u^2 - √2/2 v\n");
    assert_eq!(
        expand_ok(&["3/2*u^2 - sqrt2/2*v", "--format", "latex"]),
        "\\frac{3}{2} u^{2} - \\frac{\\sqrt{2}}{2} v\n"
    );
    assert_eq!(
        expand_ok(&["--format=text", "(u, v + 1, u^2 + v^3)"]),
        "(u, v + 1, v^3 + u^2)\n"
    );
    assert_eq!(expand_ok(&["--", "-u + 1"]), "-u + 1\n");
}

#[test]
fn json_output_reads_back() {
    let input = "(1 - v)*(u, 0, u^3) + v*(u, 1, u^2)";
    let out = expand_ok(&[input, "--format", "json"]);
    let value: serde_json::Value = serde_json::from_str(&out).expect("valid JSON");
    assert_eq!(value["expr"], input);
    assert_eq!(value["closed_form"], "(u, v, -u^3 v + u^3 + u^2 v)");
    assert_eq!(
        value["latex"],
        "\\left(u, v, -u^{3} v + u^{3} + u^{2} v\\right)"
    );
    assert_eq!(value["json"], "(u, v, -u^3*v + u^3 + u^2*v)");
    // the json form expands to the same closed form
    let json_form = value["json"].as_str().expect("a string");
    assert_eq!(expand_ok(&[json_form]), "(u, v, -u^3 v + u^3 + u^2 v)\n");
    // fields in the documented order
    let keys: Vec<usize> = ["\"expr\"", "\"closed_form\"", "\"latex\"", "\"json\""]
        .iter()
        .map(|k| out.find(k).expect("key present"))
        .collect();
    assert!(keys.windows(2).all(|w| w[0] < w[1]), "{out}");
}

#[test]
fn bad_input_names_the_column() {
    assert_eq!(
        expand_err("(u + 1"),
        "cagd: at column 7: expected ')' (unbalanced parenthesis), found the end of the input\n"
    );
    assert_eq!(
        expand_err("u + q"),
        "cagd: at column 5: unknown variable 'q' (the variables are u, v, w, t, s, x, y, z; 'uv' means u v)\n"
    );
    assert_eq!(expand_err("1/0"), "cagd: at column 2: division by zero\n");
    assert_eq!(
        expand_err("sqrt(-2)"),
        "cagd: at column 1: square root of a negative number (-2) is not real\n"
    );
    assert_eq!(
        expand_err("sqrt2 + sqrt3"),
        "cagd: at column 9: numbers with √2 and √3 cannot be mixed: an expression runs in one field a + b√d\n"
    );
    assert!(expand_err("(u, v)*(u, v)")
        .starts_with("cagd: at column 7: cannot multiply a tuple by a tuple"));
    assert!(expand_err("1/u")
        .starts_with("cagd: at column 2: division by a polynomial is not a polynomial"));
    assert!(expand_err("u^99999").contains("limit exceeded"));
    assert!(expand_err("").contains("expected an expression"));
}

#[test]
fn usage_errors_exit_2() {
    for args in [
        &[][..],
        &["frobnicate"][..],
        &["expand"][..],
        &["expand", "u", "v"][..],
        &["expand", "u", "--format"][..],
        &["expand", "u", "--format", "pdf"][..],
        &["expand", "u", "--colour"][..],
        &["help", "frobnicate"][..],
    ] {
        let out = cagd(args);
        assert_eq!(out.status.code(), Some(2), "args {args:?}");
        assert!(stdout(&out).is_empty());
        assert_eq!(
            stderr(&out).lines().count(),
            1,
            "args {args:?}: {}",
            stderr(&out)
        );
        assert!(stderr(&out).contains("cagd help"));
    }
}

#[test]
fn help_lists_the_commands() {
    for args in [&["--help"][..], &["help"][..], &["-h"][..]] {
        let out = cagd(args);
        assert_eq!(out.status.code(), Some(0));
        let text = stdout(&out);
        assert!(text.contains("Commands:"));
        assert!(text.contains("expand EXPR"));
    }
    for args in [&["help", "expand"][..], &["expand", "--help"][..]] {
        let out = cagd(args);
        assert_eq!(out.status.code(), Some(0));
        assert!(stdout(&out).starts_with("Usage: cagd expand EXPR"));
    }
    let out = cagd(&["--version"]);
    assert!(stdout(&out).starts_with("cagd "));
}
