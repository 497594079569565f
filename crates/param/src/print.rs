//! The printers of [`Param`]: text as the notes write (`√2 R/2`, `(2 a + c)/3`), LaTeX, and a
//! JSON string that [`crate::parse_param`] reads back.

use crate::field::{Param, ParamPoly};
use crate::letters::Letters;
use cagd_poly::Term;
use cagd_scalar::{BigInt, BigRational, Print, Quadratic, Rat};
use num_integer::Integer;
use num_traits::{One, Signed, Zero};

#[derive(Clone, Copy, PartialEq)]
enum Style {
    Text,
    Latex,
    Json,
}

/// Plain text.
pub fn text(x: &Param) -> String {
    write(x, Style::Text)
}

/// LaTeX.
pub fn latex(x: &Param) -> String {
    write(x, Style::Latex)
}

/// The JSON form (`sqrt(2)*R/2`).
pub fn json(x: &Param) -> String {
    write(x, Style::Json)
}

impl Print for Param {
    fn to_text(&self) -> String {
        text(self)
    }
    fn to_latex(&self) -> String {
        latex(self)
    }
    fn to_json_string(&self) -> String {
        json(self)
    }
}

fn write(x: &Param, style: Style) -> String {
    match x {
        Param::Const(q) => match style {
            Style::Text => q.to_text(),
            Style::Latex => q.to_latex(),
            Style::Json => q.to_json_string(),
        },
        Param::Ratio(r) => {
            if r.den.is_one_poly() {
                let l = denominators_lcm([&r.num]);
                let body = terms(
                    &r.num
                        .scale(&Quadratic::from_rational(BigRational::from(l.clone()))),
                    style,
                );
                if l.is_one() {
                    body.text
                } else {
                    over(&body, &Part::integer(&l), style)
                }
            } else {
                let l = denominators_lcm([&r.num, &r.den]);
                let scale = Quadratic::from_rational(BigRational::from(l));
                over(
                    &terms(&r.num.scale(&scale), style),
                    &terms(&r.den.scale(&scale), style),
                    style,
                )
            }
        }
    }
}

trait IsOnePoly {
    fn is_one_poly(&self) -> bool;
}

impl IsOnePoly for ParamPoly {
    fn is_one_poly(&self) -> bool {
        self.as_constant().is_some_and(|c| c.is_one())
    }
}

/// The least common multiple of the denominators of every coefficient's two parts.
fn denominators_lcm<'a>(polys: impl IntoIterator<Item = &'a ParamPoly>) -> BigInt {
    let mut l = BigInt::one();
    for p in polys {
        for (_, c) in p.terms() {
            l = l
                .lcm(&c.rational_part().denom())
                .lcm(&c.root_part().denom());
        }
    }
    l
}

/// A printed sum: its text, how many terms, and whether it starts with a minus sign.
struct Part {
    text: String,
    terms: usize,
}

impl Part {
    fn integer(n: &BigInt) -> Part {
        Part {
            text: n.to_string(),
            terms: 1,
        }
    }
}

/// `num / den`, with parentheses where a sum needs them.
fn over(num: &Part, den: &Part, style: Style) -> String {
    match style {
        Style::Latex => {
            if let Some(positive) = num.text.strip_prefix('-').filter(|_| num.terms == 1) {
                format!("-\\frac{{{positive}}}{{{}}}", den.text)
            } else {
                format!("\\frac{{{}}}{{{}}}", num.text, den.text)
            }
        }
        Style::Text | Style::Json => {
            let wrap = |p: &Part, is_den: bool| {
                let product = p.text.contains(' ') || p.text.contains('*');
                if p.terms > 1 || (is_den && product) {
                    format!("({})", p.text)
                } else {
                    p.text.clone()
                }
            };
            format!("{}/{}", wrap(num, false), wrap(den, true))
        }
    }
}

/// The terms of a polynomial with integer coefficient parts, largest first.
fn terms(p: &ParamPoly, style: Style) -> Part {
    let mut out = String::new();
    let mut n = 0;
    // largest term first, but a sum opens with a positive term when it has one (`b - a`,
    // not `-a + b`)
    let mut written: Vec<(bool, String)> =
        p.terms().rev().map(|(m, c)| term(c, m, style)).collect();
    if let Some(k) = written.iter().position(|(negative, _)| !negative) {
        if let Some(head) = written.get_mut(..=k) {
            head.rotate_right(1);
        }
    }
    for (negative, body) in written {
        if n == 0 {
            if negative {
                out.push('-');
            }
        } else {
            out.push_str(if negative { " - " } else { " + " });
        }
        out.push_str(&body);
        n += 1;
    }
    if n == 0 {
        out.push('0');
    }
    Part {
        text: out,
        terms: n.max(1),
    }
}

/// The numerator of a coefficient made integral (by the lcm of the denominators).
fn int(q: &Rat) -> BigInt {
    q.numer().into_owned()
}

/// One term `c m`: whether it is written with a minus sign, and its text without the sign.
fn term(c: &Quadratic, m: &Letters, style: Style) -> (bool, String) {
    let (a, b, d) = (int(c.rational_part()), int(c.root_part()), c.radicand());
    let root = |k: &BigInt| -> String {
        let k = k.abs();
        let r = match style {
            Style::Text => format!("√{d}"),
            Style::Latex => format!("\\sqrt{{{d}}}"),
            Style::Json => format!("sqrt({d})"),
        };
        if k.is_one() {
            r
        } else if style == Style::Json {
            format!("{k}*{r}")
        } else {
            format!("{k}{r}")
        }
    };
    let (negative, coef) = if b.is_zero() {
        let s = if a.abs().is_one() && !m.is_one() {
            String::new()
        } else {
            a.abs().to_string()
        };
        (a.is_negative(), s)
    } else if a.is_zero() {
        (b.is_negative(), root(&b))
    } else {
        let sign = if b.is_negative() { " - " } else { " + " };
        let inner = format!("{a}{sign}{}", root(&b));
        let s = match style {
            Style::Latex => format!("\\left({inner}\\right)"),
            _ => format!("({inner})"),
        };
        (false, s)
    };
    let letters = monomial(m, style);
    let body = match (coef.is_empty(), letters.is_empty()) {
        (true, _) => letters,
        (false, true) => coef,
        (false, false) => {
            let sep = match style {
                Style::Json => "*",
                Style::Latex => " ",
                Style::Text => " ",
            };
            format!("{coef}{sep}{letters}")
        }
    };
    (negative, body)
}

fn monomial(m: &Letters, style: Style) -> String {
    let parts: Vec<String> = m
        .powers()
        .map(|(n, e)| {
            let name = match style {
                Style::Latex => n.to_latex(),
                Style::Text => n.to_string(),
                Style::Json => n.as_str().to_string(),
            };
            match (e, style) {
                (1, _) => name,
                (e, Style::Latex) => format!("{name}^{{{e}}}"),
                (e, _) => format!("{name}^{e}"),
            }
        })
        .collect();
    parts.join(match style {
        Style::Json => "*",
        Style::Latex => " ",
        Style::Text => " ",
    })
}
