//! The exact-number parser on arbitrary text: never a panic, no hang (every power is bounded by
//! the digit limit before it is computed), and every number it reads prints (as JSON) to a
//! string that reads back to the same number.
#![no_main]

use cagd_scalar::{parse_number, Print};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    if let Ok(x) = parse_number(text) {
        let printed = x.to_json_string();
        assert_eq!(
            parse_number(&printed).as_ref(),
            Ok(&x),
            "{text:?} printed as {printed:?}"
        );
        let _ = x.to_text();
        let _ = x.to_latex();
    }
});
