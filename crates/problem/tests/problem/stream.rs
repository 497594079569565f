//! `check_stream` on several threads: the verdicts of a batch in the order of its problems,
//! whatever the number of threads, and a failing sink stops the batch.

use cagd_problem::{check_stream, Limits, Settings};
use serde_json::{json, Value};

/// A batch of `n` problems of uneven cost, some of them bad.
fn batch(n: usize) -> Vec<Value> {
    (0..n)
        .map(|i| match i % 5 {
            0 => json!({"op": "elevate", "surface": {"bezier": [[[0, 0, i], [1, 0, 1]], [[0, 1, 0], [1, 1, "1/3"]]]}, "by": [i % 4, 1]}),
            1 => json!({"op": "elevate", "surface": {"bezier": [[[0, 0, 0]]]}, "by": "two"}),
            2 => json!({"op": "nothing"}),
            3 => json!({"op": "closed_form", "surface": {"bezier": [[[i, 0, 0], [1, 0, 1]], [[0, 1, 0], [1, 1, 1]]]}}),
            _ => json!({"op": "restrict", "surface": {"bezier": [[[0, 0, 0], [1, 0, 1]], [[0, 1, 0], [1, 1, i]]]}, "u": ["1/3", "3/4"], "v": ["0", "1/2"]}),
        })
        .collect()
}

fn settings() -> Settings {
    Settings {
        limits: Limits::DEFAULT,
        steps: false,
    }
}

/// Each verdict as text, in the order the sink received them.
fn run(problems: &[Value], threads: usize) -> Vec<String> {
    let mut out = Vec::new();
    let done: Result<(), ()> = check_stream(
        problems,
        &settings(),
        threads,
        |v| format!("{:?} {:?}", v.index, v.answer),
        |t| {
            out.push(t);
            Ok(())
        },
    );
    assert_eq!(done, Ok(()));
    out
}

#[test]
fn the_verdicts_do_not_depend_on_the_threads() {
    // more problems than the threads may answer ahead of the output (64 each)
    let problems = batch(300);
    let one = run(&problems, 1);
    assert_eq!(one.len(), 300);
    for (i, v) in one.iter().enumerate() {
        assert!(v.starts_with(&format!("Some({i}) ")), "{v}");
    }
    for threads in [2, 3, 7] {
        assert_eq!(run(&problems, threads), one, "{threads} threads");
    }
    assert!(run(&[], 4).is_empty());
}

#[test]
fn a_failing_sink_stops_the_batch() {
    let problems = batch(500);
    for threads in [1, 2, 3] {
        let mut seen = 0usize;
        let done = check_stream(
            &problems,
            &settings(),
            threads,
            |v| v.index,
            |index| {
                assert_eq!(index, Some(seen));
                seen += 1;
                if seen == 10 {
                    Err(seen)
                } else {
                    Ok(())
                }
            },
        );
        assert_eq!(done, Err(10), "{threads} threads");
        assert_eq!(seen, 10);
    }
}
