//! The exact-number parser on arbitrary text: never a panic, and every number it reads prints
//! (as JSON) to a string that reads back to the same number, unless that string is past the
//! grammar's input limits (a power such as `(24512^27)^375` builds a value of more digits than
//! a literal may have: a known limitation of crates/scalar, see
//! crates/problem/tests/scalar_issues.rs).
#![no_main]

use cagd_scalar::{parse_number, Scalar, ScalarError};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(x) = parse_number(text) {
        let printed = x.to_json_string();
        match parse_number(&printed) {
            Err(ScalarError::Limit { .. }) => {}
            back => assert_eq!(back.as_ref(), Ok(&x), "{text:?} printed as {printed:?}"),
        }
        let _ = x.to_text();
        let _ = x.to_latex();
    }
});
