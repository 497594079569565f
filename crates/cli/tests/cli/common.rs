//! Shared helpers: run the built `cagd` binary, with or without standard input.

use std::io::{ErrorKind, Write};
use std::process::{Command, Output, Stdio};

/// Runs `cagd ARGS`.
pub fn cagd(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(args)
        .output()
        .expect("the cagd binary runs")
}

/// Runs `cagd ARGS` with `input` on standard input. A usage error exits before reading its
/// input: a closed pipe is not a failure here (the exit code and output say what happened).
pub fn cagd_stdin(args: &[&str], input: impl AsRef<[u8]>) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the cagd binary runs");
    let mut stdin = child.stdin.take().expect("piped stdin");
    let input = input.as_ref().to_vec();
    // written on a thread of its own: a batch is answered while it is read, so the output
    // must be drained while the input is written
    let writer = std::thread::spawn(move || {
        if let Err(e) = stdin.write_all(&input) {
            assert_eq!(e.kind(), ErrorKind::BrokenPipe, "write stdin: {e}");
        }
    });
    let out = child.wait_with_output().expect("cagd finishes");
    writer.join().expect("the input is written");
    out
}

/// The standard output, as text.
pub fn stdout(out: &Output) -> String {
    String::from_utf8(out.stdout.clone()).expect("utf-8 output")
}

/// The standard error, as text.
pub fn stderr(out: &Output) -> String {
    String::from_utf8(out.stderr.clone()).expect("utf-8 output")
}

/// The problems of docs/format.md (its blocks tagged `json problem`).
pub fn format_doc_problems() -> Vec<serde_json::Value> {
    let doc = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/format.md"))
        .expect("docs/format.md");
    let mut problems = Vec::new();
    let mut block: Option<String> = None;
    for line in doc.lines() {
        block = match (block, line.trim()) {
            (None, "```json problem") => Some(String::new()),
            (None, _) => None,
            (Some(b), "```") => {
                problems.push(serde_json::from_str(&b).expect("example is JSON"));
                None
            }
            (Some(mut b), _) => {
                b.push_str(line);
                Some(b)
            }
        };
    }
    problems
}
