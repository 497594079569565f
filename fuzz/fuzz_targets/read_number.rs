//! The problem layer's number reader (`cagd_problem::read_number`, what `cagd solve` uses for
//! every number of a problem) on arbitrary text: never a panic, never a hang (powers and
//! products are bounded by the digit limit), and it agrees with the grammar's printer.
#![no_main]

use cagd_problem::{read_number, Limits};
use cagd_scalar::Print;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let limits = Limits::default();
    if let Ok(x) = read_number(text, &limits) {
        let printed = x.to_json_string();
        assert_eq!(read_number(&printed, &limits).as_ref(), Ok(&x), "{text:?} printed as {printed:?}");
    }
});
