//! A combination of a worked solution, `a x + b y - c z`: its symbols, then its values.

use super::symbols::symbol_text;
use crate::values::{latex, text};
use crate::Lang;
use cagd_contract::{Exact, Number};
use cagd_scalar::{FieldOps, Print};

/// A coefficient before a symbol or value: `1` left out, `-1` as a sign, a negative one
/// subtracted; `(sign, magnitude)` with the magnitude empty for 1.
fn coefficient(c: &Exact, lang: Lang, latex_form: bool) -> (bool, String) {
    let Exact::Number(q) = c else {
        return (false, text(c, lang));
    };
    let negative = q.compare(&Number::from_i64(0)) == Some(std::cmp::Ordering::Less);
    let magnitude = if negative { -q.clone() } else { q.clone() };
    let shown = if magnitude == Number::from_i64(1) {
        String::new()
    } else if latex_form {
        format!("{}\\,", magnitude.to_latex())
    } else {
        format!("{} ", magnitude.to_text())
    };
    (negative, shown)
}

/// `a x + b y - c z`, each term through `show`.
fn sum(
    terms: &[(Exact, String, Exact)],
    lang: Lang,
    latex_form: bool,
    show: &dyn Fn(&str, &Exact) -> String,
) -> String {
    let mut out = String::new();
    for (k, (c, s, v)) in terms.iter().enumerate() {
        let (negative, magnitude) = coefficient(c, lang, latex_form);
        let sign = match (k, negative) {
            (0, false) => "",
            (0, true) => "-",
            (_, false) => " + ",
            (_, true) => " - ",
        };
        out += &format!("{sign}{magnitude}{}", show(s, v));
    }
    out
}

/// Whether the combination is one term with coefficient 1 (a point kept as it was).
fn kept(terms: &[(Exact, String, Exact)]) -> bool {
    matches!(terms, [(Exact::Number(q), _, _)] if *q == Number::from_i64(1))
}

pub(super) fn text_terms(terms: &[(Exact, String, Exact)], lang: Lang) -> String {
    if kept(terms) {
        return sum(terms, lang, false, &|s, _| symbol_text(s));
    }
    format!(
        "{} = {}",
        sum(terms, lang, false, &|s, _| symbol_text(s)),
        sum(terms, lang, false, &|_, v| text(v, lang))
    )
}

pub(super) fn latex_terms(terms: &[(Exact, String, Exact)], lang: Lang) -> String {
    if kept(terms) {
        return sum(terms, lang, true, &|s, _| s.to_string());
    }
    format!(
        "{} = {}",
        sum(terms, lang, true, &|s, _| s.to_string()),
        sum(terms, lang, true, &|_, v| latex(v, lang))
    )
}

/// The factors of a product, their symbols then their values: `w_{11} ω_{10} = 1/2 · 2`.
pub(super) fn product_text(factors: &[(String, Exact)], lang: Lang) -> String {
    let symbols: Vec<String> = factors.iter().map(|(s, _)| symbol_text(s)).collect();
    let values: Vec<String> = factors.iter().map(|(_, v)| text(v, lang)).collect();
    format!("{} = {}", symbols.join(" "), values.join(" · "))
}

/// A whole product step in LaTeX (math mode, without its `$`): the symbol, the factors'
/// symbols and values ([`product_text`] in LaTeX), and the value: `w_{1,1} = w_{11}\, ω_{11} =
/// 1/2 \cdot 2 = 1`. The LaTeX and Markdown keys both write it.
pub(super) fn product_latex(
    symbol: &str,
    factors: &[(String, Exact)],
    value: &Exact,
    lang: Lang,
) -> String {
    let symbols: Vec<&str> = factors.iter().map(|(s, _)| s.as_str()).collect();
    let values: Vec<String> = factors.iter().map(|(_, v)| latex(v, lang)).collect();
    format!(
        "{symbol} = {} = {} = {}",
        symbols.join("\\, "),
        values.join(" \\cdot "),
        latex(value, lang)
    )
}
