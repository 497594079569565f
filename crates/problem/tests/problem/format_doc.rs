//! Every example problem in `docs/format.md` (code blocks tagged `json problem`) is solved,
//! and must be answered without error.

use cagd_problem::solve;

pub fn doc_examples() -> Vec<(usize, String)> {
    let doc = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../docs/format.md"))
        .expect("docs/format.md");
    let mut out = Vec::new();
    let mut current: Option<(usize, String)> = None;
    for (n, line) in doc.lines().enumerate() {
        let fence = line.trim();
        current = match current {
            None if fence == "```json problem" => Some((n + 1, String::new())),
            None => None,
            Some(block) if fence == "```" => {
                out.push(block);
                None
            }
            Some((start, mut text)) => {
                text.push_str(line);
                text.push('\n');
                Some((start, text))
            }
        };
    }
    out
}

#[test]
fn format_doc_has_one_example_per_operation() {
    let examples = doc_examples();
    for op in cagd_problem::operations() {
        assert!(
            examples
                .iter()
                .any(|(_, text)| text.contains(&format!("\"op\": \"{op}\""))),
            "docs/format.md has no runnable example of {op}"
        );
    }
}

#[test]
fn every_example_of_the_format_doc_is_answered() {
    let mut failures = Vec::new();
    for (line, text) in doc_examples() {
        let problem: serde_json::Value = match serde_json::from_str(&text) {
            Ok(v) => v,
            Err(e) => {
                failures.push(format!("docs/format.md:{line}: not JSON: {e}"));
                continue;
            }
        };
        if let Err(e) = solve(&problem) {
            failures.push(format!("docs/format.md:{line}: {e}"));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
