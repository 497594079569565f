//! Words with their symbols in inline math: `B_i^n(t_k)` or `α` in `$...$`, the other words
//! escaped.

use crate::escape::escape_latex;

/// Text inside LaTeX: the key's escaping, with `_`-subscripted symbols in math mode.
pub(super) fn latex_words(s: &str) -> String {
    math_words(s, &escape_latex)
}

/// Words with their symbols (a token with `_`, `^` or a Unicode symbol) in `$...$`, LaTeX
/// inside, a subscript of several letters in braces (`c_cd` is `c_{cd}`), symbols next to
/// each other in one formula (`∂^k c/∂u^k` is `$\partial^k c/\partial u^k$`, not two); the
/// other words through `plain`.
pub(super) fn math_words(s: &str, plain: &dyn Fn(&str) -> String) -> String {
    /// The symbols written in Unicode in the sentences, and their LaTeX.
    const MATH: [(&str, &str); 18] = [
        ("∂", "\\partial "),
        ("c~", "\\tilde{c}"),
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
    let mut out: Vec<String> = Vec::new();
    // whether the last word written ends in a formula open to the next one (no punctuation
    // after it)
    let mut open = false;
    for token in s.split(' ') {
        let (lead, body, tail) = split_punctuation(token);
        let special = MATH.iter().any(|(u, _)| body.contains(u));
        if body.contains(['_', '^']) || special {
            let mut math = braced_subscripts(body);
            for (u, l) in MATH {
                math = math.replace(u, l);
            }
            let math = math.trim_end();
            match (open && lead.is_empty(), out.last_mut()) {
                (true, Some(last)) => {
                    // `$a$` and `b` → `$a b$`
                    last.pop();
                    *last += &format!(" {math}${tail}");
                }
                _ => out.push(format!("{lead}${math}${tail}")),
            }
            open = tail.is_empty();
        } else {
            out.push(plain(token));
            open = false;
        }
    }
    out.join(" ")
}

/// A subscript of two or more letters or digits in braces: `c_cd` → `c_{cd}`, `G_10` →
/// `G_{10}` (TeX takes one character after `_`); `u_{k+1}` and `b_i` as they are.
fn braced_subscripts(math: &str) -> String {
    let mut out = String::with_capacity(math.len() + 4);
    let mut rest = math;
    while let Some(i) = rest.find('_') {
        let (before, after) = rest.split_at(i);
        out += before;
        out.push('_');
        let after = &after[1..];
        let run = after
            .find(|c: char| !c.is_ascii_alphanumeric())
            .unwrap_or(after.len());
        match run {
            0 | 1 => rest = after,
            n => {
                out += &format!("{{{}}}", &after[..n]);
                rest = &after[n..];
            }
        }
    }
    out + rest
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
