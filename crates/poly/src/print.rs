//! The printers: plain text, LaTeX and the JSON form that [`crate::parse_expr`] reads back.
//!
//! Terms are listed from the largest monomial down in the graded lexicographic order of
//! [`crate::Monomial`]: descending total degree, ties broken by the higher power of `u`, then
//! of `v`, `w`, `t`, `s`, `x`, `y`, `z`.

use crate::{Monomial, Poly, VecPoly};
use cagd_scalar::Scalar;

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
        let factors: Vec<String> = m
            .powers()
            .map(|(v, e)| match (self, e) {
                (_, 1) => v.name().to_string(),
                (Form::Latex, e) => format!("{v}^{{{e}}}"),
                (_, e) => format!("{v}^{e}"),
            })
            .collect();
        factors.join(if self == Form::Json { "*" } else { " " })
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
        let mut out = String::new();
        for (m, c) in p.terms().rev() {
            let (negative, body) = self.term(m, c, out.is_empty());
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

    fn vec_poly<S: Scalar>(self, c: &VecPoly<S>) -> String {
        let parts: Vec<String> = c.components().iter().map(|p| self.poly(p)).collect();
        match self {
            Form::Latex => format!("\\left({}\\right)", parts.join(", ")),
            _ => format!("({})", parts.join(", ")),
        }
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
