//! A batch read element by element: the answers the same bytes with any number of threads and
//! as one problem at a time, and a syntax error in the middle of a batch answers the problems
//! before it, then names its line, column and problem.

use crate::common::{cagd_stdin, stderr, stdout};
use serde_json::{json, Value};

/// Problems of uneven cost, some of them bad problems (valid JSON).
fn problems(n: usize) -> Vec<Value> {
    (0..n)
        .map(|i| match i % 4 {
            0 => json!({"op": "elevate", "surface": {"bezier": [[[0, 0, i], [1, 0, 1]], [[0, 1, 0], [1, 1, "1/3"]]]}, "by": [i % 3, 1]}),
            1 => json!({"op": "elevate", "surface": {"bezier": [[[0, 0, 0]]]}, "by": "two"}),
            2 => json!({"op": "closed_form", "surface": {"bezier": [[[i, 0, 0], [1, 0, 1]], [[0, 1, 0], [1, 1, "sqrt2"]]]}}),
            _ => json!({"op": "restrict", "surface": {"bezier": [[[0, 0, 0], [1, 0, 1]], [[0, 1, 0], [1, 1, i]]]}, "u": ["1/3", "3/4"], "v": ["0", "1/2"]}),
        })
        .collect()
}

#[test]
fn a_streamed_batch_answers_as_its_problems_alone_with_any_threads() {
    let batch = problems(150);
    // written with odd white space: the reader finds each element wherever it ends
    let text = format!(
        " \n[\n{}\n ]\n",
        batch
            .iter()
            .map(Value::to_string)
            .collect::<Vec<_>>()
            .join(" ,\n\t")
    );
    let one = cagd_stdin(&["solve", "-", "--format", "json"], &text);
    assert_eq!(one.status.code(), Some(1), "{}", stderr(&one));
    assert!(stderr(&one).is_empty(), "{}", stderr(&one));
    let answers: Vec<Value> = serde_json::from_str(&stdout(&one)).unwrap();
    assert_eq!(answers.len(), batch.len());
    for (i, p) in batch.iter().enumerate().step_by(7) {
        let alone = cagd_stdin(&["solve", "-", "--format", "json"], p.to_string());
        let alone: Value = serde_json::from_str(&stdout(&alone)).unwrap();
        if alone["ok"] == true {
            assert_eq!(answers[i], alone, "problem {i}");
        } else {
            let e = answers[i]["error"].as_str().unwrap();
            let prefix = format!("problem {}: ", i + 1);
            assert_eq!(e.strip_prefix(&prefix), alone["error"].as_str(), "{e}");
        }
    }
    for threads in ["2", "3"] {
        let out = cagd_stdin(
            &["solve", "-", "--format", "json", "--threads", threads],
            &text,
        );
        assert_eq!(stdout(&out), stdout(&one), "{threads} threads");
        assert_eq!(out.status.code(), Some(1));
    }
    let keys = cagd_stdin(&["solve", "-"], &text);
    let keys3 = cagd_stdin(&["solve", "-", "--threads", "3"], &text);
    assert_eq!(stdout(&keys), stdout(&keys3));
}

#[test]
fn a_syntax_error_in_a_batch_answers_the_problems_before_it() {
    let good = problems(4);
    // a problem that is not JSON is that problem's error, with its place in the file
    let text = format!(
        "[{},\n{},\n{{\"op\": \"elevate\" \"by\": 1}},\n{}]",
        good[0], good[3], good[2]
    );
    for threads in ["1", "2"] {
        let out = cagd_stdin(
            &["solve", "-", "--format", "json", "--threads", threads],
            &text,
        );
        assert_eq!(out.status.code(), Some(1));
        assert!(stderr(&out).is_empty(), "{}", stderr(&out));
        let answers: Vec<Value> = serde_json::from_str(&stdout(&out)).unwrap();
        assert_eq!(answers.len(), 4);
        assert_eq!(
            answers[2]["error"],
            "problem 3: cannot read the problem: expected `,` or `}` at line 3 column 18"
        );
        assert!([0, 1, 3].iter().all(|&i| answers[i]["ok"] == true));
    }
    // a syntax error between problems ends the batch there
    let text = format!("[{},\n{}\n  {},\n{}]", good[0], good[3], good[2], good[0]);
    for threads in ["1", "2"] {
        let out = cagd_stdin(
            &["solve", "-", "--format", "json", "--threads", threads],
            &text,
        );
        assert_eq!(out.status.code(), Some(1));
        // the answers before it, as a JSON list
        let answers: Vec<Value> = serde_json::from_str(&stdout(&out)).unwrap();
        assert_eq!(answers.len(), 2);
        assert!(answers.iter().all(|a| a["ok"] == true), "{answers:?}");
        let e = stderr(&out);
        assert_eq!(e.lines().count(), 1, "{e}");
        assert_eq!(
            e.trim_end(),
            "cagd: standard input: not valid JSON at line 3, column 3, in problem 3 of the \
             batch (the problems before it are answered): expected `,` or `]`"
        );
    }
    // in Spanish
    let out = cagd_stdin(&["solve", "-", "--lang", "es"], &text);
    assert!(
        stderr(&out).contains("JSON no válido en la línea 3, columna 3, en el problema 3 del lote"),
        "{}",
        stderr(&out)
    );
    // the end of the batch missing, or something after it
    for (text, says) in [
        (
            format!("[{}, {}", good[0], good[3]),
            "in problem 3 of the batch",
        ),
        (format!("[{}] x", good[0]), "in problem 2 of the batch"),
        (format!("[{},]", good[0]), "in problem 2 of the batch"),
    ] {
        let out = cagd_stdin(&["solve", "-", "--format", "json"], &text);
        assert_eq!(out.status.code(), Some(1));
        assert!(stderr(&out).contains(says), "{text}: {}", stderr(&out));
        let answers: Vec<Value> = serde_json::from_str(&stdout(&out)).unwrap();
        assert!(!answers.is_empty() && answers.iter().all(|a| a["ok"] == true));
    }
    // one problem (not a batch) with an error answers nothing, as before
    let out = cagd_stdin(&["solve", "-"], "{\"op\": 1 2}");
    assert_eq!(out.status.code(), Some(1));
    assert!(stdout(&out).is_empty());
}

#[test]
fn past_the_batch_limit_the_rest_is_counted_not_solved() {
    let batch: Vec<Value> = problems(40).into_iter().step_by(4).collect();
    let text = serde_json::to_string(&batch).unwrap();
    for threads in ["1", "2"] {
        let out = cagd_stdin(
            &[
                "solve",
                "-",
                "--format",
                "json",
                "--max-batch",
                "3",
                "--threads",
                threads,
            ],
            &text,
        );
        let answers: Vec<Value> = serde_json::from_str(&stdout(&out)).unwrap();
        assert_eq!(answers.len(), 10);
        assert!(answers[..3].iter().all(|a| a["ok"] == true));
        for (i, a) in answers.iter().enumerate().skip(3) {
            assert_eq!(
                a["error"],
                format!(
                    "problem {}: not solved: the batch holds 10 problems, more than the limit of 3 (raise it with --max-batch)",
                    i + 1
                )
            );
        }
    }
}
