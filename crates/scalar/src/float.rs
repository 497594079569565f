//! `f64`: for figures and speed comparisons only. Nothing exact is ever computed with it.

use crate::{rational::rational_to_f64, Quadratic, Scalar, ScalarError};
use num_rational::BigRational;

impl Scalar for f64 {
    fn from_i64(n: i64) -> Self {
        n as f64
    }

    fn from_ratio(num: i64, den: i64) -> Self {
        assert!(den != 0, "from_ratio: zero denominator");
        num as f64 / den as f64
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

    fn is_exact() -> bool {
        false
    }

    fn to_f64(&self) -> f64 {
        *self
    }

    fn checked_div(&self, rhs: &Self) -> Option<Self> {
        (*rhs != 0.0).then(|| self / rhs)
    }

    fn sqrt_exact(&self) -> Option<Self> {
        (*self >= 0.0).then(|| self.sqrt())
    }

    fn to_latex(&self) -> String {
        format!("{self}")
    }

    fn to_json_string(&self) -> String {
        format!("{self}")
    }
}
