//! Batch isolation and reproducibility: 1,000 problems from the exercise generator (every
//! topic, one seed), 10% of them corrupted in ten ways. Every good problem is answered exactly
//! as it is alone, every bad one with a one-line error naming its index and field; `cagd
//! solve` prints the same bytes on every run and with any number of threads.

use crate::common::cagd_stdin;
use cagd_problem::{solve, solve_batch_with, Limit, Limits};
use serde_json::{json, Value};

const SEED: u64 = 2026;
const SIZE: usize = 1000;

/// The generated problems of each topic.
fn pools() -> Vec<(&'static str, Vec<Value>)> {
    let topics = cagd_exercises::topics();
    let per = SIZE.div_ceil(topics.len());
    topics
        .iter()
        .map(|t| (t.name, cagd_exercises::generate(t.name, per, SEED).unwrap()))
        .collect()
}

fn pool<'a>(pools: &'a [(&str, Vec<Value>)], topic: &str) -> &'a [Value] {
    &pools.iter().find(|(n, _)| *n == topic).unwrap().1
}

/// A corruption: the bad problem made from a generated one, the field its error must name,
/// and a piece of the message.
struct Bad {
    problem: Value,
    field: String,
    says: String,
}

/// The `k`-th corruption of `kind` (0..10), from the generated problems.
fn corrupt(pools: &[(&str, Vec<Value>)], kind: usize, k: usize) -> Bad {
    let pick = |topic: &str, ok: &dyn Fn(&Value) -> bool| -> Value {
        let candidates: Vec<&Value> = pool(pools, topic).iter().filter(|p| ok(p)).collect();
        assert!(!candidates.is_empty(), "no {topic} problem fits");
        candidates[k % candidates.len()].clone()
    };
    let any = |_: &Value| true;
    let bad = |problem: Value, field: &str, says: &str| Bad {
        problem,
        field: field.to_string(),
        says: says.to_string(),
    };
    match kind {
        // missing fields
        0 => {
            let mut p = pick("evaluate", &any);
            p.as_object_mut().unwrap().remove("params");
            bad(p, "params", "missing (this operation needs it)")
        }
        // wrong shapes
        1 => {
            let mut p = pick("restrict", &any);
            p["surface"]["bezier"] = json!([1, 2, 3]);
            bad(
                p,
                "surface.bezier[0]",
                "expected a list, found the number 1",
            )
        }
        // curves that do not meet
        2 => {
            let mut p = pick("coons", &|p: &Value| p["d1"].get("bezier").is_some());
            p["d1"]["bezier"][0][2] = json!(100);
            bad(p, "d1", "curves c1 and d1 do not meet at corner a")
        }
        // zero weights
        3 => {
            let mut p = pick("revolution", &|p: &Value| {
                p["curve"].get("bezier").is_some()
            });
            let n = p["curve"]["bezier"].as_array().unwrap().len();
            let mut w = vec![json!(1); n];
            w[1] = json!(0);
            p["curve"]["weights"] = json!(w);
            bad(p, "curve", "weight 1 is zero")
        }
        // singular interpolation
        4 => {
            let mut p = pick("interpolate", &|p: &Value| p.get("u").is_some());
            p["u"][1] = p["u"][0].clone();
            bad(p, "u[1]", "the interpolation system is singular")
        }
        // decreasing knots: the patch as a B-spline surface with its knots reversed
        5 => {
            let mut p = pick("evaluate", &any);
            let mesh = p["surface"]["bezier"].clone();
            let (m, n) = (
                mesh.as_array().unwrap().len() - 1,
                mesh[0].as_array().unwrap().len() - 1,
            );
            let knots = |d: usize| -> Value {
                let mut k: Vec<i64> = vec![1; d];
                k.extend(vec![0; d]);
                json!(k)
            };
            p["surface"] =
                json!({"bspline": mesh, "degree": [m, n], "knots": [knots(m), knots(n)]});
            bad(p, "surface", "decreases")
        }
        // huge numbers: more digits than the limit
        6 => {
            let mut p = pick("closed_form", &any);
            p["surface"]["bezier"][0][0][0] = json!(format!("1{}", "0".repeat(1000)));
            bad(p, "surface.bezier[0][0][0]", "has more than 1000 digits")
        }
        // a degree above the limit
        7 => {
            let mut p = pick("elevate", &any);
            p["by"] = json!([60, 0]);
            bad(p, "by", "above the limit of 50")
        }
        // an unknown operation
        8 => {
            let mut p = pick("normal", &any);
            p["op"] = json!("normals");
            bad(p, "op", "unknown operation \"normals\"")
        }
        // an expression that does not parse
        _ => {
            let mut p = pick("graph", &any);
            p["f"] = json!("x*(y");
            bad(p, "f", "expected ')' (unbalanced parenthesis)")
        }
    }
}

/// The batch, and for each problem what its answer must be: `None` for a good one (the
/// answer it has alone), the corruption for a bad one.
fn batch() -> (Vec<Value>, Vec<Option<Bad>>) {
    let pools = pools();
    let mut next = vec![0usize; pools.len()];
    let (mut problems, mut expected) = (Vec::new(), Vec::new());
    for i in 0..SIZE {
        if i % 10 == 3 {
            let b = corrupt(&pools, (i / 10) % 10, i / 100);
            problems.push(b.problem.clone());
            expected.push(Some(b));
        } else {
            let t = i % pools.len();
            problems.push(pools[t].1[next[t]].clone());
            next[t] += 1;
            expected.push(None);
        }
    }
    (problems, expected)
}

fn cagd_solve(input: &[u8], args: &[&str]) -> (Vec<u8>, Option<i32>) {
    let mut all = vec!["solve", "-"];
    all.extend_from_slice(args);
    let out = cagd_stdin(&all, input);
    assert!(
        out.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    (out.stdout, out.status.code())
}

#[test]
fn a_thousand_problems_ten_percent_corrupted() {
    let (problems, expected) = batch();
    assert_eq!(problems.len(), SIZE);
    assert_eq!(expected.iter().filter(|e| e.is_some()).count(), SIZE / 10);
    let doc = Value::Array(problems.clone());
    let limits = Limits::default();
    let answers = solve_batch_with(&doc, &limits, 1);
    assert_eq!(answers.len(), SIZE);
    for (i, ((p, a), e)) in problems.iter().zip(&answers).zip(&expected).enumerate() {
        match e {
            None => {
                let a = a.as_ref().unwrap_or_else(|e| panic!("problem {i}: {e}"));
                assert_eq!(Ok(a), solve(p).as_ref(), "problem {i} alone");
            }
            Some(bad) => {
                let msg = a.as_ref().map(|_| ()).unwrap_err().to_string();
                let head = format!("problem {}: field `{}`: ", i + 1, bad.field);
                assert!(msg.starts_with(&head), "problem {i}: {msg}");
                assert!(msg.contains(&bad.says), "problem {i}: {msg}");
                assert!(!msg.contains('\n'));
            }
        }
    }
    // the same answers on several threads
    assert_eq!(solve_batch_with(&doc, &limits, 3), answers);

    // `cagd solve`: the same bytes on every run and with any number of threads
    let input = serde_json::to_vec(&doc).unwrap();
    let (first, code) = cagd_solve(&input, &["--format", "json"]);
    assert_eq!(code, Some(1), "some problems failed");
    let (again, _) = cagd_solve(&input, &["--format", "json", "--threads", "2"]);
    assert!(first == again, "the output differs between runs");
    let out: Value = serde_json::from_slice(&first).unwrap();
    // streamed, the bytes are serde_json's pretty form of the whole list
    assert!(
        first == (serde_json::to_string_pretty(&out).unwrap() + "\n").into_bytes(),
        "the streamed output is not the pretty form of the list"
    );
    let items = out.as_array().unwrap();
    assert_eq!(items.len(), SIZE);
    for (i, (item, a)) in items.iter().zip(&answers).enumerate() {
        match a {
            Ok(a) => assert_eq!(item, &a.to_json(false), "problem {i}"),
            // the command line adds the flag that raises a limit to the engine's message
            Err(e) => {
                let flag = match e.limit {
                    Some(Limit::Digits) => " (raise it with --max-digits)",
                    Some(Limit::Degree) => " (raise it with --max-degree)",
                    Some(other) => panic!("problem {i}: unexpected limit {other:?}"),
                    None => "",
                };
                assert_eq!(item, &json!({"ok": false, "error": format!("{e}{flag}")}));
            }
        }
    }
}

/// The document's shapes, written as they are solved: one problem, an empty batch, a batch of
/// one, each in serde_json's pretty form; a UTF-8 byte-order mark before the document is
/// skipped (issue 19).
#[test]
fn documents_of_every_shape_are_written_in_the_pretty_form() {
    let p = json!({"op": "circle", "arcs": 4});
    for (doc, code) in [
        (p.clone(), Some(0)),
        (json!([]), Some(0)),
        (json!([p.clone()]), Some(0)),
        (
            json!([p.clone(), {"op": "circle", "arcs": "four"}, p.clone()]),
            Some(1),
        ),
    ] {
        let input = serde_json::to_vec(&doc).unwrap();
        for threads in ["1", "2"] {
            let (out, status) = cagd_solve(&input, &["--format", "json", "--threads", threads]);
            assert_eq!(status, code, "{doc}");
            let value: Value = serde_json::from_slice(&out).unwrap();
            let pretty = serde_json::to_string_pretty(&value).unwrap() + "\n";
            assert_eq!(String::from_utf8(out).unwrap(), pretty, "{doc}");
        }
        let mut with_bom = b"\xEF\xBB\xBF".to_vec();
        with_bom.extend_from_slice(&input);
        assert_eq!(
            cagd_solve(&with_bom, &["--format", "json"]),
            cagd_solve(&input, &["--format", "json"])
        );
    }
}

/// An answer that cannot be written is an error (exit code 1, with the reason), not a
/// silent success; `/dev/full` refuses every write.
#[cfg(target_os = "linux")]
#[test]
fn an_output_that_cannot_be_written_is_an_error() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(["solve", "-", "--format", "json"])
        .stdin(std::process::Stdio::piped())
        .stdout(std::fs::File::create("/dev/full").unwrap())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .and_then(|mut child| {
            use std::io::Write;
            child
                .stdin
                .take()
                .unwrap()
                .write_all(br#"{"op": "circle", "arcs": 4}"#)?;
            child.wait_with_output()
        })
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let stderr = String::from_utf8(out.stderr).unwrap();
    assert!(
        stderr.starts_with("cagd: cannot write the output: "),
        "{stderr}"
    );
}
