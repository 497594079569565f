//! Writes the JSON Schemas of problems and answers into `docs/` (`docs/problem.schema.json`,
//! `docs/answer.schema.json`) from the types that read problems:
//!
//! ```text
//! cargo run -p cagd-problem --example schema
//! ```
//!
//! `crates/problem/tests/problem/schema.rs` fails while the files in `docs/` differ from what this
//! writes.

use std::path::Path;
use std::process::ExitCode;

fn main() -> ExitCode {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    for (path, text) in cagd_problem::schema::schema_files() {
        let file = root.join(path);
        let same = std::fs::read_to_string(&file).is_ok_and(|old| old == text);
        if same {
            println!("{path}: unchanged");
            continue;
        }
        if let Err(e) = std::fs::write(&file, text) {
            eprintln!("cannot write {}: {e}", file.display());
            return ExitCode::FAILURE;
        }
        println!("{path}: written");
    }
    ExitCode::SUCCESS
}
