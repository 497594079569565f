//! The expression parser on arbitrary text: never a panic, and every expression it reads
//! prints (as JSON and as text) to strings that read back to the same polynomial.
#![no_main]

use cagd_poly::parse_expr;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(e) = parse_expr(text) {
        let json = e.to_json_string();
        assert_eq!(parse_expr(&json).as_ref(), Ok(&e), "{text:?} printed as {json:?}");
        let text_form = e.to_text();
        assert_eq!(parse_expr(&text_form).as_ref(), Ok(&e), "{text:?} printed as {text_form:?}");
        let _ = e.to_latex();
    }
});
