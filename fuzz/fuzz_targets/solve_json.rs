//! `solve` on arbitrary bytes read as JSON: every problem of the batch gets an answer or an
//! error, never a panic; answers print as JSON and as an answer key.
#![no_main]

use cagd_keys::{example_text, Lang};
use cagd_problem::{check_batch, Settings, Verdict};
use libfuzzer_sys::fuzz_target;
use serde_json::Value;

fuzz_target!(|data: &[u8]| {
    let Ok(doc) = serde_json::from_slice::<Value>(data) else {
        return;
    };
    let problems = match &doc {
        Value::Array(items) => items.clone(),
        one => vec![one.clone()],
    };
    let verdicts: Vec<Verdict> = check_batch(&doc, &Settings::default(), 1);
    assert_eq!(verdicts.len(), problems.len());
    for v in &verdicts {
        match &v.answer {
            Ok(a) => {
                let _ = a.to_json(true);
            }
            Err(e) => assert!(!e.message.contains("internal error"), "{e}"),
        }
        let _ = example_text(v, Lang::En);
    }
});
