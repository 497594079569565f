//! `f64`: for figures and speed comparisons only. Nothing exact is ever computed with it.

use crate::{
    rational::rational_to_f64, ExactRational, FieldOps, Print, Quadratic, ScalarError, SquareRoot,
};
use num_rational::BigRational;

impl FieldOps for f64 {
    fn from_i64(n: i64) -> Self {
        n as f64
    }

    fn from_ratio(num: i64, den: i64) -> Self {
        assert!(den != 0, "from_ratio: zero denominator");
        num as f64 / den as f64
    }

    fn checked_div(&self, rhs: &Self) -> Option<Self> {
        (*rhs != 0.0).then(|| self / rhs)
    }
}

impl ExactRational for f64 {
    fn is_exact() -> bool {
        false
    }

    fn from_rational(q: &BigRational) -> Self {
        rational_to_f64(q)
    }

    fn try_from_number(x: &Quadratic) -> Result<Self, ScalarError> {
        Ok(x.to_f64())
    }

    fn to_number(&self) -> Option<Quadratic> {
        None
    }

    fn to_f64(&self) -> f64 {
        *self
    }
}

impl SquareRoot for f64 {
    fn sqrt_exact(&self) -> Option<Self> {
        (*self >= 0.0).then(|| self.sqrt())
    }

    // Rounded, as every f64: √2/2 computed as sqrt_of(2) / 2 is the same f64 as `sqrt2/2` read.
    fn sqrt_of(n: u64) -> Option<Self> {
        Some((n as f64).sqrt())
    }
}

impl Print for f64 {
    fn to_latex(&self) -> String {
        format!("{self}")
    }

    fn to_json_string(&self) -> String {
        format!("{self}")
    }
}
