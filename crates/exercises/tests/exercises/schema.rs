//! Every problem `cagd generate` writes (`problems.json`) is valid by the problem schema of
//! `docs/problem.schema.json`, and every answer of its key (`key.json`) by the answer schema
//! (`docs/answer.schema.json`); `crates/problem/tests/problem/schema.rs` checks that the files in
//! `docs/` are the generated schemas.

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

use cagd_exercises::{problem_set_files, topics, Lang};
use cagd_problem::schema::{answer_schema, problem_schema};
use serde_json::Value;

const SEEDS: [u64; 3] = [0, 1, 20240601];
const COUNT: usize = 10;

/// A compiled schema.
struct Validator {
    schemas: boon::Schemas,
    index: boon::SchemaIndex,
}

impl Validator {
    fn new(schema: Value) -> Validator {
        let url = "file:///schema.json";
        let mut schemas = boon::Schemas::new();
        let mut compiler = boon::Compiler::new();
        compiler.add_resource(url, schema).expect("a schema");
        let index = compiler
            .compile(url, &mut schemas)
            .unwrap_or_else(|e| panic!("the schema does not compile: {e:#}"));
        Validator { schemas, index }
    }

    /// Why `v` is invalid, or `None`.
    fn errors(&self, v: &Value) -> Option<String> {
        self.schemas
            .validate(v, self.index)
            .err()
            .map(|e| format!("{e:#}"))
    }
}

#[test]
fn every_generated_problem_and_answer_is_valid_by_the_schemas() {
    let problems = Validator::new(problem_schema());
    let answers = Validator::new(answer_schema());
    let mut failures = Vec::new();
    let mut count = 0;
    for t in topics() {
        for (seed, lang) in SEEDS.iter().zip([Lang::En, Lang::Es, Lang::En]) {
            let files = problem_set_files(t.name, COUNT, *seed, lang)
                .unwrap_or_else(|e| panic!("{} seed {seed}: {e}", t.name));
            let file = |name: &str| -> Value {
                let text = &files.iter().find(|(n, _)| n == name).unwrap().1;
                serde_json::from_str(text).unwrap()
            };
            let (set, key) = (file("problems.json"), file("key.json"));
            // the file as a batch, and each problem alone
            if let Some(e) = problems.errors(&set) {
                failures.push(format!("{} seed {seed}: problems.json: {e}", t.name));
            }
            for p in set.as_array().unwrap() {
                count += 1;
                if let Some(e) = problems.errors(p) {
                    failures.push(format!("{} seed {seed}: {e}\n{p}", t.name));
                }
            }
            if let Some(e) = answers.errors(&key) {
                failures.push(format!("{} seed {seed}: key.json: {e}", t.name));
            }
        }
    }
    assert_eq!(count, topics().len() * SEEDS.len() * COUNT);
    assert!(failures.is_empty(), "{}", failures.join("\n\n"));
}
