//! `cagd solve` flags that raise the limits, and their usage errors.

use crate::common::{cagd_stdin, stderr, stdout};

/// Runs `cagd solve - ARGS` on `input`: (exit code, stdout, stderr).
fn solve(input: &str, args: &[&str]) -> (Option<i32>, String, String) {
    let mut all = vec!["solve", "-"];
    all.extend_from_slice(args);
    let out = cagd_stdin(&all, input);
    (out.status.code(), stdout(&out), stderr(&out))
}

const ELEVATE: &str = r#"{"op": "elevate", "curve": {"bezier": [[0, 0], [1, 2]]}, "by": 59}"#;

#[test]
fn a_limit_refuses_and_its_flag_raises_it() {
    let (code, out, _) = solve(ELEVATE, &["--format", "json"]);
    assert_eq!(code, Some(1));
    assert!(
        out.contains("\"error\": \"field `by`: elevating degree 1 by 59 gives degree 60, above the limit of 50 (raise it with --max-degree)\""),
        "{out}"
    );
    let (code, out, _) = solve(ELEVATE, &["--format", "json", "--max-degree", "60"]);
    assert_eq!(code, Some(0), "{out}");
    assert!(out.contains("\"ok\": true"));
    let (code, _, _) = solve(ELEVATE, &["--max-degree=60"]);
    assert_eq!(code, Some(0));
}

#[test]
fn every_limit_has_a_flag() {
    let long = format!("1{}", "0".repeat(30));
    let digits = format!(r#"{{"op": "circle", "radius": "{long}"}}"#);
    assert_eq!(solve(&digits, &["--max-digits", "20"]).0, Some(1));
    assert_eq!(solve(&digits, &["--max-digits", "40"]).0, Some(0));
    let points = r#"{"op": "evaluate", "curve": {"bezier": [[0], [1], [2]]}, "params": [0]}"#;
    assert_eq!(solve(points, &["--max-points", "2"]).0, Some(1));
    assert_eq!(solve(points, &["--max-points", "3"]).0, Some(0));
    let batch = format!("[{points}, {points}, {points}]");
    let (code, out, _) = solve(&batch, &["--max-batch", "2", "--format", "json"]);
    assert_eq!(code, Some(1));
    assert!(out.contains("problem 3: not solved: the batch holds 3 problems, more than the limit of 2 (raise it with --max-batch)"), "{out}");
    let deep = format!(
        r#"{{"op": "circle", "radius": "{}1{}"}}"#,
        "(".repeat(20),
        ")".repeat(20)
    );
    assert_eq!(solve(&deep, &["--max-depth", "10"]).0, Some(1));
    assert_eq!(solve(&deep, &["--max-depth", "30"]).0, Some(0));
    let power = r#"{"op": "circle", "radius": "2^20"}"#;
    assert_eq!(solve(power, &["--max-exponent", "10"]).0, Some(1));
    assert_eq!(solve(power, &["--max-exponent", "20"]).0, Some(0));
    // the memory of a problem: a flag of its own, a positive number of megabytes
    assert_eq!(solve(power, &["--max-memory", "1"]).0, Some(0));
    assert_eq!(solve(power, &["--max-memory", "0"]).0, Some(2));
}

/// A cubic elevated by 3000 (legal under the raised limits of the test): over a minute of
/// work in a release build.
const SLOW: &str = r#"{"op": "elevate", "by": 3000,
    "curve": {"bezier": [[0, "1/3"], ["7/11", 2], ["5/13", "2/17"], [1, 1]]}}"#;

#[test]
fn a_slow_problem_stops_at_its_deadline_and_the_batch_goes_on() {
    let quick = r#"{"op": "elevate", "curve": {"bezier": [[0, 0], [1, 2]]}, "by": 1}"#;
    let batch = format!("[{quick}, {SLOW}, {{\"op\": \"circle\", \"arcs\": 4}}]");
    let raised = ["--max-degree", "3100", "--max-points", "3100"];
    let (code, out, _) = solve(
        &batch,
        &[&raised[..], &["--format", "json", "--max-seconds", "2"]].concat(),
    );
    assert_eq!(code, Some(1), "{out}");
    let answers: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(answers[0]["ok"], true, "{out}");
    assert_eq!(
        answers[1]["error"],
        "problem 2: not answered within the limit of 2 s: the work was stopped (raise it with --max-seconds)"
    );
    assert_eq!(answers[2]["ok"], true, "{out}");
}

/// The counting allocator of `cagd` measures what a problem's work holds: at a checkpoint past
/// `--max-memory`, the problem gets the error with the figures, and the batch goes on.
#[test]
fn a_problem_that_holds_too_much_memory_stops_and_the_batch_goes_on() {
    let quick = r#"{"op": "elevate", "curve": {"bezier": [[0, 0], [1, 2]]}, "by": 1}"#;
    // the closed form of a rational triangle of degree 30 in R^4: a quotient of polynomials
    // of 496 terms with long coefficients, some megabytes
    let n = 30;
    let rows: Vec<serde_json::Value> = (0..=n)
        .map(|i| {
            (0..=i)
                .map(|k| {
                    serde_json::json!([
                        format!("{}/{}", (i * 7 + k * 3 + 1) % 10, 1 + (i + k) % 7),
                        (i * 5 + k) % 10,
                        (i * i + 3 * k * k) % 10,
                        format!("{}/{}", (i + 2 * k) % 9, 2 + (i * k) % 5)
                    ])
                })
                .collect()
        })
        .collect();
    let weights: Vec<Vec<usize>> = (0..=n)
        .map(|i| (0..=i).map(|k| 1 + (i + 2 * k) % 9).collect())
        .collect();
    let big = serde_json::json!({"op": "closed_form",
        "triangle": {"triangle": rows, "weights": weights}});
    let batch = format!("[{quick}, {big}, {{\"op\": \"circle\", \"arcs\": 4}}]");
    let (code, out, _) = solve(
        &batch,
        &[
            "--format",
            "json",
            "--max-seconds",
            "120",
            "--max-memory",
            "2",
        ],
    );
    assert_eq!(code, Some(1), "{out}");
    let answers: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(answers[0]["ok"], true, "{out}");
    let error = answers[1]["error"].as_str().unwrap();
    let held: u64 = error
        .strip_prefix("problem 2: not answered within the memory limit of 2 MB: the work was stopped holding ")
        .and_then(|e| e.strip_suffix(" MB (raise it with --max-memory)"))
        .unwrap_or_else(|| panic!("{error}"))
        .parse()
        .unwrap();
    assert!(held > 2, "{error}");
    assert_eq!(answers[2]["ok"], true, "{out}");
}

#[test]
fn bad_flag_values_are_usage_errors() {
    for args in [
        &["--max-degree", "many"][..],
        &["--max-points", "0"],
        &["--max-depth", "5000"],
        &["--threads", "-1"],
        &["--max-exponent", "99999999999"],
        &["--max-batch"],
        &["--max-seconds", "-1"],
        &["--max-seconds", "soon"],
        &["--max-seconds", "inf"],
    ] {
        let (code, out, err) = solve(ELEVATE, args);
        assert_eq!(code, Some(2), "{args:?}");
        assert!(out.is_empty());
        assert_eq!(err.lines().count(), 1, "{err}");
    }
    let (_, _, err) = solve(ELEVATE, &["--max-depth", "5000"]);
    assert_eq!(
        err,
        "cagd: --max-depth is at most 1000 (run `cagd help` for the list of commands)\n"
    );
}

#[test]
fn the_same_bytes_on_every_run() {
    let batch = format!("[{ELEVATE}, {{\"op\": \"circle\", \"arcs\": 4}}, {{\"op\": \"nope\"}}]");
    for format in ["text", "json", "latex", "markdown"] {
        let first = solve(&batch, &["--format", format, "--steps"]);
        let second = solve(&batch, &["--format", format, "--steps", "--threads", "3"]);
        assert_eq!(first, second, "{format}");
    }
}
