//! The printers: plain text, LaTeX and the JSON form that [`crate::parse_expr`] reads back.
//!
//! Terms are listed from the largest monomial down in the graded lexicographic order of
//! [`crate::Monomial`]: descending total degree, ties broken by the higher power of `u`, then
//! of `v`, `w`, `t`, `s`, `x`, `y`, `z`.

use crate::{Monomial, Poly, Var, VecPoly};
use cagd_scalar::{push_abs_rational, BigRational, Scalar};
use num_traits::{One, Signed};

/// Appends the decimal digits of `e`.
fn push_u32(out: &mut String, e: u32) {
    // the digits from the last, without the formatting machinery (an exponent per term)
    let mut digits = [0u8; 10];
    let mut start = digits.len();
    let mut rest = e;
    loop {
        start -= 1;
        if let Some(d) = digits.get_mut(start) {
            // rest % 10 < 10 fits a u8
            *d = b'0' + (rest % 10) as u8;
        }
        rest /= 10;
        if rest == 0 || start == 0 {
            break;
        }
    }
    for d in digits.iter().skip(start) {
        out.push(char::from(*d));
    }
}

/// Appends the decimal digits of `n` (one machine word's printer when it fits one).
fn push_u128(out: &mut String, n: u128) {
    let mut digits = itoa::Buffer::new();
    match u64::try_from(n) {
        Ok(n) => out.push_str(digits.format(n)),
        Err(_) => out.push_str(digits.format(n)),
    }
}

/// The three output forms.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Form {
    Text,
    Latex,
    Json,
}

impl Form {
    fn number<S: Scalar>(self, c: &S) -> String {
        match self {
            Form::Text => c.to_text(),
            Form::Latex => c.to_latex(),
            Form::Json => c.to_json_string(),
        }
    }

    fn monomial(self, m: &Monomial) -> String {
        let mut out = String::new();
        self.push_monomial(&mut out, m);
        out
    }

    /// Appends `u^2 v` (`u^2*v` in JSON, `u^{2} v` in LaTeX) to `out`.
    fn push_monomial(self, out: &mut String, m: &Monomial) {
        let mut first = true;
        for (v, &e) in Var::ALL.iter().zip(m.exponents()) {
            if e == 0 {
                continue;
            }
            if !first {
                out.push(if self == Form::Json { '*' } else { ' ' });
            }
            first = false;
            out.push_str(v.name());
            match (self, e) {
                (_, 1) => {}
                (Form::Text | Form::Json, 2..=9) => {
                    // one digit: the exponents of closed forms
                    out.push('^');
                    out.push(char::from(b'0' + e as u8));
                }
                (Form::Latex, e) => {
                    out.push_str("^{");
                    push_u32(out, e);
                    out.push('}');
                }
                (_, e) => {
                    out.push('^');
                    push_u32(out, e);
                }
            }
        }
    }

    /// Appends the term `c m` of a rational coefficient in text or JSON (which write a
    /// rational alike: `-5/6`), the sign first as [`Form::poly`] writes it: no coefficient
    /// printed twice, no negation, no allocation but `out`'s.
    fn push_rational_term(out: &mut String, sep: &str, m: &Monomial, c: &BigRational, first: bool) {
        let negative = c.is_negative();
        match (first, negative) {
            (true, false) => {}
            (true, true) => out.push('-'),
            (false, false) => out.push_str(" + "),
            (false, true) => out.push_str(" - "),
        }
        if m.is_one() {
            push_abs_rational(out, c);
            return;
        }
        if !(c.numer().magnitude().is_one() && c.denom().is_one()) {
            push_abs_rational(out, c);
            out.push_str(sep);
        }
    }

    /// [`Form::push_rational_term`] for a rational `p/q` of machine words (q > 0), written
    /// without a big rational: the same text.
    fn push_small_term(
        out: &mut String,
        sep: &str,
        m: &Monomial,
        (p, q): (i128, i128),
        first: bool,
    ) {
        match (first, p < 0) {
            (true, false) => {}
            (true, true) => out.push('-'),
            (false, false) => out.push_str(" + "),
            (false, true) => out.push_str(" - "),
        }
        let magnitude = p.unsigned_abs();
        let unit = magnitude == 1 && q == 1;
        if m.is_one() || !unit {
            push_u128(out, magnitude);
            if q != 1 {
                out.push('/');
                push_u128(out, q.unsigned_abs());
            }
            if !m.is_one() {
                out.push_str(sep);
            }
        }
    }

    /// `coefficient monomial`, with the coefficient's sign taken out (`first`: the term that
    /// opens the polynomial).
    fn term<S: Scalar>(self, m: &Monomial, c: &S, first: bool) -> (bool, String) {
        // each coefficient printed once in text (twice when negative), once more in another
        // form: the closed forms of the answers print thousands of long coefficients
        let text = c.to_text();
        let negative = text.starts_with('-');
        let abs = negative.then(|| -c.clone());
        let abs_text = match &abs {
            Some(a) => a.to_text(),
            None => text,
        };
        let number = match (self, &abs) {
            (Form::Text, _) => abs_text.clone(),
            (_, Some(a)) => self.number(a),
            (_, None) => self.number(c),
        };
        let abs = abs.as_ref().unwrap_or(c);
        // a two-term coefficient such as 1/2 + √2 is parenthesized, and a quotient in letters
        // (√2 R/2); a product in letters (2 a) is not
        let compound = abs_text.contains(" + ")
            || abs_text.contains(" - ")
            || (abs_text.contains('/') && abs_text.chars().any(char::is_alphabetic));
        let parenthesized = |number: String| {
            if self == Form::Latex {
                format!("\\left({number}\\right)")
            } else {
                format!("({number})")
            }
        };
        if m.is_one() {
            // -2 + √2 is -(2 - √2): its sign comes out only with the parentheses
            return match (compound && negative, first) {
                (false, _) => (negative, number),
                (true, true) => (false, self.number(c)),
                (true, false) => (true, parenthesized(number)),
            };
        }
        let mono = self.monomial(m);
        let coef = if abs.is_one() {
            return (negative, mono);
        } else if compound {
            parenthesized(number)
        } else {
            number
        };
        let sep = if self == Form::Json { "*" } else { " " };
        (negative, format!("{coef}{sep}{mono}"))
    }

    fn poly<S: Scalar>(self, p: &Poly<S>) -> String {
        let mut bytes = Vec::with_capacity(16 * p.num_terms().max(1));
        if self != Form::Latex && self.push_small_poly(&mut bytes, p) {
            // ASCII only
            return String::from_utf8(bytes)
                .unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned());
        }
        let mut out = String::new();
        self.push_poly(&mut out, p);
        out
    }

    /// Appends the polynomial to `out` (`0` when it has no terms).
    fn push_poly<S: Scalar>(self, out: &mut String, p: &Poly<S>) {
        let start = out.len();
        let sep = if self == Form::Json { "*" } else { " " };
        for (m, c) in p.terms().rev() {
            // a long polynomial's key may take long to write: within the problem's deadline
            cagd_scalar::cancel::checkpoint();
            // a rational coefficient prints alike in text and JSON: straight into `out`
            if self != Form::Latex {
                if let Some(ratio) = c.as_small_ratio() {
                    Self::push_small_term(out, sep, m, ratio, out.len() == start);
                    if !m.is_one() {
                        self.push_monomial(out, m);
                    }
                    continue;
                }
                if let Some(q) = c.as_rational() {
                    Self::push_rational_term(out, sep, m, &q, out.len() == start);
                    if !m.is_one() {
                        self.push_monomial(out, m);
                    }
                    continue;
                }
            }
            let first = out.len() == start;
            let (negative, body) = self.term(m, c, first);
            match (first, negative) {
                (true, false) => {}
                (true, true) => out.push('-'),
                (false, false) => out.push_str(" + "),
                (false, true) => out.push_str(" - "),
            }
            out.push_str(&body);
        }
        if out.len() == start {
            out.push('0');
        }
    }

    /// Appends the text or JSON of `p` to `out` as bytes, as [`Form::push_poly`] writes it,
    /// when every coefficient is a rational of machine words: each term `- 5/6 u^2 v` from its
    /// words, with no big rational and no formatting machinery. `false` (and `out` as it was)
    /// when a coefficient is not (a root, a letter, a long number).
    fn push_small_poly<S: Scalar>(self, out: &mut Vec<u8>, p: &Poly<S>) -> bool {
        let start = out.len();
        let sep = if self == Form::Json { b'*' } else { b' ' };
        let mut digits = itoa::Buffer::new();
        let mut push_digits = |out: &mut Vec<u8>, n: u128| match u64::try_from(n) {
            Ok(n) => out.extend_from_slice(digits.format(n).as_bytes()),
            Err(_) => out.extend_from_slice(digits.format(n).as_bytes()),
        };
        for (m, c) in p.terms().rev() {
            let Some((num, den)) = c.as_small_ratio() else {
                out.truncate(start);
                return false;
            };
            if out.len() != start {
                out.push(b' ');
                out.push(if num < 0 { b'-' } else { b'+' });
                out.push(b' ');
            } else if num < 0 {
                out.push(b'-');
            }
            let magnitude = num.unsigned_abs();
            let constant = m.is_one();
            if constant || !(magnitude == 1 && den == 1) {
                push_digits(out, magnitude);
                if den != 1 {
                    out.push(b'/');
                    push_digits(out, den.unsigned_abs());
                }
                if !constant {
                    out.push(sep);
                }
            }
            let mut first_power = true;
            for (name, &e) in b"uvwtsxyz".iter().zip(m.exponents()) {
                if e == 0 {
                    continue;
                }
                if !first_power {
                    out.push(sep);
                }
                first_power = false;
                out.push(*name);
                if e > 1 {
                    out.push(b'^');
                    if e < 10 {
                        // one digit: the exponents of closed forms
                        out.push(b'0' + e as u8);
                    } else {
                        push_digits(out, u128::from(e));
                    }
                }
            }
        }
        if out.len() == start {
            out.push(b'0');
        }
        true
    }

    fn vec_poly<S: Scalar>(self, c: &VecPoly<S>) -> String {
        // every coefficient a rational of machine words (the closed forms of rational
        // meshes): all the components written as bytes, checked as UTF-8 once
        if self != Form::Latex {
            let mut out: Vec<u8> = Vec::with_capacity(256);
            out.push(b'(');
            let mut small = true;
            for (k, p) in c.components().iter().enumerate() {
                if k > 0 {
                    out.extend_from_slice(b", ");
                }
                if !self.push_small_poly(&mut out, p) {
                    small = false;
                    break;
                }
            }
            if small {
                out.push(b')');
                // ASCII only
                return String::from_utf8(out)
                    .unwrap_or_else(|e| String::from_utf8_lossy(e.as_bytes()).into_owned());
            }
        }
        let mut out = String::from(if self == Form::Latex { "\\left(" } else { "(" });
        for (k, p) in c.components().iter().enumerate() {
            if k > 0 {
                out.push_str(", ");
            }
            self.push_poly(&mut out, p);
        }
        out.push_str(if self == Form::Latex { "\\right)" } else { ")" });
        out
    }
}

impl<S: Scalar> Poly<S> {
    /// Plain text, terms from the largest monomial down (see the crate docs for the order):
    /// `-u^3 v + u^3 + u^2 v`, `3/2 u^2 - √2/2 v`, `(1/2 + √2) u`. [`crate::parse_expr`] reads it
    /// back.
    ///
    /// ```
    /// use cagd_poly::parse_poly;
    /// use cagd_scalar::Quadratic;
    /// let p = parse_poly::<Quadratic>("3/2*u^2 - sqrt2/2*v + (1/2 + sqrt2) u").unwrap();
    /// assert_eq!(p.to_text(), "3/2 u^2 + (1/2 + √2) u - √2/2 v");
    /// ```
    pub fn to_text(&self) -> String {
        Form::Text.poly(self)
    }

    /// LaTeX: `\frac{3}{2} u^{2} - \frac{\sqrt{2}}{2} v`.
    ///
    /// ```
    /// use cagd_poly::parse_poly;
    /// use cagd_scalar::Quadratic;
    /// let p = parse_poly::<Quadratic>("3/2*u^2 - sqrt2/2*v").unwrap();
    /// assert_eq!(p.to_latex(), r"\frac{3}{2} u^{2} - \frac{\sqrt{2}}{2} v");
    /// ```
    pub fn to_latex(&self) -> String {
        Form::Latex.poly(self)
    }

    /// The JSON form: explicit `*` and `sqrt`, read back exactly by [`crate::parse_expr`]:
    /// `3/2*u^2*v - sqrt2/2*v`.
    ///
    /// ```
    /// use cagd_poly::parse_poly;
    /// use cagd_scalar::Quadratic;
    /// let p = parse_poly::<Quadratic>("3/2 u^2 v - √2/2 v").unwrap();
    /// assert_eq!(p.to_json_string(), "3/2*u^2*v - sqrt2/2*v");
    /// assert_eq!(parse_poly::<Quadratic>(&p.to_json_string()).unwrap(), p);
    /// ```
    pub fn to_json_string(&self) -> String {
        Form::Json.poly(self)
    }
}

impl<S: Scalar> VecPoly<S> {
    /// Plain text: `(u, v, -u^3 v + u^3 + u^2 v)`.
    pub fn to_text(&self) -> String {
        Form::Text.vec_poly(self)
    }

    /// LaTeX: `\left(u, v, -u^{3} v + u^{3} + u^{2} v\right)`.
    pub fn to_latex(&self) -> String {
        Form::Latex.vec_poly(self)
    }

    /// The JSON form, read back exactly by [`crate::parse_expr`]: `(u, v, -u^3*v + u^3 + u^2*v)`.
    /// A map with a single component prints as `(p)`, which reads back as a scalar.
    pub fn to_json_string(&self) -> String {
        Form::Json.vec_poly(self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exponents_are_written_in_decimal() {
        for e in [0, 1, 7, 9, 10, 42, 100, 65_536, u32::MAX] {
            let mut out = String::from("u^");
            push_u32(&mut out, e);
            assert_eq!(out, format!("u^{e}"));
        }
    }
    use crate::Var;
    use cagd_scalar::{BigInt, Quadratic, Rat};
    use proptest::prelude::*;

    /// Every term through [`Form::term`], the path of every coefficient type.
    fn reference<S: Scalar>(form: Form, p: &Poly<S>) -> String {
        let mut out = String::new();
        for (m, c) in p.terms().rev() {
            let (negative, body) = form.term(m, c, out.is_empty());
            match (out.is_empty(), negative) {
                (true, false) => {}
                (true, true) => out.push('-'),
                (false, false) => out.push_str(" + "),
                (false, true) => out.push_str(" - "),
            }
            out.push_str(&body);
        }
        if out.is_empty() {
            out.push('0');
        }
        out
    }

    fn poly<S: Scalar>(terms: &[(u32, u32, i64, i64)]) -> Poly<S> {
        Poly::from_terms(terms.iter().map(|&(a, b, p, q)| {
            (
                Monomial::from_powers(&[(Var::U, a), (Var::V, b)]),
                S::from_ratio(p, q),
            )
        }))
    }

    proptest! {
        /// The rational fast path prints as the generic term path, in every scalar that has
        /// rationals, including numbers beyond a machine word.
        #[test]
        fn rational_terms_print_as_the_generic_path(
            terms in proptest::collection::vec((0u32..4, 0u32..12, -3i64..4, 1i64..4), 0..8),
            big in proptest::bool::ANY,
        ) {
            let mut p = poly::<BigRational>(&terms);
            if big {
                p = p.scale(&BigRational::from_integer(BigInt::from(u64::MAX) * 3));
            }
            let q = p.map_coeffs(<Rat as cagd_scalar::ExactRational>::from_rational);
            let r = p.map_coeffs(|c| Quadratic::from_rational(c.clone()));
            for form in [Form::Text, Form::Json, Form::Latex] {
                let want = reference(form, &p);
                prop_assert_eq!(form.poly(&p), want.clone());
                prop_assert_eq!(form.poly(&q), want.clone());
                prop_assert_eq!(form.poly(&r), want);
            }
            let v = VecPoly::new(vec![p.clone(), Poly::zero(), p.clone()]);
            let t = reference(Form::Text, &p);
            prop_assert_eq!(v.to_text(), format!("({t}, 0, {t})"));
        }
    }
}
