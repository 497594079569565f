//! Words with their symbols in inline math: `B_i^n(t_k)` or `α` in `$...$`, the other words
//! escaped.

use crate::escape::escape_latex;

/// Text inside LaTeX: the key's escaping, with `_`-subscripted symbols in math mode.
pub(super) fn latex_words(s: &str) -> String {
    math_words(s, &escape_latex)
}

/// Words with their symbols (a token with `_`, `^` or a Unicode symbol) in `$...$`, LaTeX
/// inside; the other words through `plain`.
pub(super) fn math_words(s: &str, plain: &dyn Fn(&str) -> String) -> String {
    /// The symbols written in Unicode in the sentences, and their LaTeX.
    const MATH: [(&str, &str); 16] = [
        ("ĉ", "\\hat{c}"),
        ("d̂", "\\hat{d}"),
        ("c̃", "\\tilde{c}"),
        ("C̃", "\\tilde{C}"),
        ("d̃", "\\tilde{d}"),
        ("α", "\\alpha "),
        ("μ", "\\mu "),
        ("ξ", "\\xi "),
        ("ω", "\\omega "),
        ("Δ", "\\Delta "),
        ("π", "\\pi "),
        ("≤", "\\le "),
        ("×", "\\times "),
        ("·", "\\cdot "),
        ("Σ", "\\sum "),
        ("∈", "\\in "),
    ];
    let mut out = Vec::new();
    for token in s.split(' ') {
        let (lead, body, tail) = split_punctuation(token);
        let special = MATH.iter().any(|(u, _)| body.contains(u));
        if body.contains(['_', '^']) || special {
            let mut math = body.to_string();
            for (u, l) in MATH {
                math = math.replace(u, l);
            }
            out.push(format!("{lead}${}${tail}", math.trim_end()));
        } else {
            out.push(plain(token));
        }
    }
    out.join(" ")
}

/// A word as (opening parentheses, body, closing punctuation): a parenthesis stays in the
/// body when the body opens (closes) it, so `B_i^n(t_k)` keeps its own.
fn split_punctuation(token: &str) -> (&str, &str, &str) {
    let opens = |s: &str| s.matches('(').count();
    let closes = |s: &str| s.matches(')').count();
    let mut start = 0;
    while token[start..].starts_with('(') && opens(&token[start..]) > closes(&token[start..]) {
        start += 1;
    }
    let mut end = token.len();
    loop {
        let body = &token[start..end];
        let Some(last) = body.chars().last() else {
            break;
        };
        let strip =
            matches!(last, ',' | '.' | ';' | ':') || (last == ')' && closes(body) > opens(body));
        if !strip {
            break;
        }
        end -= last.len_utf8();
    }
    (&token[..start], &token[start..end], &token[end..])
}
