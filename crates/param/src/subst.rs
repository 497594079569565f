//! Substitution: an answer in letters specialized to values.

use crate::field::{Param, ParamPoly};
use crate::letters::Name;
use cagd_scalar::FieldOps;
use num_traits::Zero;

/// `p` with each parameter of `values` replaced by its value (the others stay).
fn substitute_poly(p: &ParamPoly, values: &[(Name, Param)]) -> Param {
    let mut sum = Param::zero();
    for (m, c) in p.terms() {
        let mut t = Param::Const(c.clone());
        for (n, e) in m.powers() {
            let factor = match values.iter().find(|(k, _)| k == n) {
                Some((_, v)) => v.powi(e),
                None => Param::named(n.clone()).powi(e),
            };
            t = t.mul_ref(&factor);
        }
        sum += t;
    }
    sum
}

impl Param {
    /// The value with the parameters of `values` replaced: `None` when the denominator
    /// vanishes at these values (the answer in letters does not specialize there).
    ///
    /// ```
    /// use cagd_param::{Name, Param};
    /// use cagd_scalar::{FieldOps, Print};
    /// let r = Param::var("R");
    /// let x = r.clone() * Param::from_ratio(1, 2) + Param::from_i64(1);
    /// let two = x.substitute(&[(Name::new("R"), Param::from_i64(2))]).unwrap();
    /// assert_eq!(two.to_text(), "2");
    /// ```
    pub fn substitute(&self, values: &[(Name, Param)]) -> Option<Param> {
        match self {
            Param::Const(_) => Some(self.clone()),
            Param::Ratio(r) => {
                let num = substitute_poly(&r.num, values);
                let den = substitute_poly(&r.den, values);
                num.checked_div(&den)
            }
        }
    }
}
