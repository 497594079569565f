//! `BigRational`, the default scalar: exact, unbounded.

use crate::{latex_fraction, ExactRational, FieldOps, Print, Quadratic, ScalarError, SquareRoot};
use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use std::borrow::Cow;

impl FieldOps for BigRational {
    fn from_i64(n: i64) -> Self {
        BigRational::from_integer(BigInt::from(n))
    }

    fn from_ratio(num: i64, den: i64) -> Self {
        BigRational::new(BigInt::from(num), BigInt::from(den))
    }

    fn checked_div(&self, rhs: &Self) -> Option<Self> {
        if rhs.is_zero() {
            None
        } else {
            Some(self / rhs)
        }
    }

    fn add_ref(&self, rhs: &Self) -> Self {
        self + rhs
    }
    fn sub_ref(&self, rhs: &Self) -> Self {
        self - rhs
    }
    fn mul_ref(&self, rhs: &Self) -> Self {
        self * rhs
    }
}

impl ExactRational for BigRational {
    fn is_exact() -> bool {
        true
    }

    fn from_rational(q: &BigRational) -> Self {
        q.clone()
    }

    fn from_rational_owned(q: BigRational) -> Self {
        q
    }

    fn try_from_number(x: &Quadratic) -> Result<Self, ScalarError> {
        x.to_rational()
            .ok_or_else(|| ScalarError::NotRational { value: x.to_text() })
    }

    fn to_number(&self) -> Option<Quadratic> {
        Some(Quadratic::from_rational(self.clone()))
    }

    fn as_rational(&self) -> Option<Cow<'_, BigRational>> {
        Some(Cow::Borrowed(self))
    }

    fn to_f64(&self) -> f64 {
        rational_to_f64(self)
    }
}

impl SquareRoot for BigRational {
    fn sqrt_exact(&self) -> Option<Self> {
        if Signed::is_negative(self) {
            return None;
        }
        let n = self.numer().sqrt();
        let d = self.denom().sqrt();
        (&n * &n == *self.numer() && &d * &d == *self.denom()).then(|| BigRational::new(n, d))
    }

    // Only the roots of squares: √9 = 3, no √2.
    fn sqrt_of(n: u64) -> Option<Self> {
        let n = BigInt::from(n);
        let root = n.sqrt();
        (&root * &root == n).then(|| BigRational::from_integer(root))
    }
}

impl Print for BigRational {
    fn to_text(&self) -> String {
        crate::rational_text(self)
    }

    fn to_latex(&self) -> String {
        let sign = if Signed::is_negative(self) { "-" } else { "" };
        format!(
            "{sign}{}",
            latex_fraction(&self.numer().abs().to_string(), self.denom())
        )
    }

    fn to_json_string(&self) -> String {
        crate::rational_text(self)
    }
}

/// The nearest f64 to a big rational, also when numerator and denominator overflow f64.
pub(crate) fn rational_to_f64(q: &BigRational) -> f64 {
    if let (Some(n), Some(d)) = (q.numer().to_f64(), q.denom().to_f64()) {
        if n.is_finite() && d.is_finite() && d != 0.0 {
            return n / d;
        }
    }
    ToPrimitive::to_f64(q).unwrap_or(f64::NAN)
}
