//! The symbols of the steps, written in LaTeX by the engine, in plain text.

/// A symbol of the steps in plain text: `\alpha_{3}` → `α_3`, `c_{1,2}` stays.
///
/// ```
/// use cagd_keys::steps::symbol_text;
/// assert_eq!(symbol_text("\\hat{f}_{2,0,0}"), "f\u{302}_{2,0,0}");
/// assert_eq!(symbol_text("\\hat{\\omega} + \\hat{f}"), "\\hat{ω} + f\u{302}");
/// ```
pub fn symbol_text(s: &str) -> String {
    let mut t = s.to_string();
    // an accented letter, `\hat{c}` → ĉ, `\tilde{w}` → w̃ (the letter and a combining accent)
    // (an accent over anything else, `\hat{\alpha}`, stays as written, and the search goes on
    // after it)
    for (accent, mark) in [("\\hat{", '\u{302}'), ("\\tilde{", '\u{303}')] {
        let mut from = 0;
        while let Some(i) = t.get(from..).and_then(|r| r.find(accent)).map(|k| from + k) {
            let body = i + accent.len();
            let mut cs = t.get(body..).unwrap_or_default().chars();
            match (cs.next(), cs.next()) {
                (Some(x), Some('}')) if x.is_ascii_alphabetic() => {
                    // the precomposed letters where Unicode has them (ĉ, û)
                    let accented = match (x, mark) {
                        ('c', '\u{302}') => "ĉ".to_string(),
                        ('u', '\u{302}') => "û".to_string(),
                        _ => format!("{x}{mark}"),
                    };
                    t.replace_range(i..body + x.len_utf8() + 1, &accented);
                    from = i + accented.len();
                }
                _ => from = body,
            }
        }
    }
    for (from, to) in [
        ("\\alpha", "α"),
        ("\\mu", "μ"),
        ("\\sigma", "σ"),
        ("\\omega", "ω"),
        ("\\Delta", "Δ"),
        ("\\cdot", "·"),
        ("\\times", "×"),
        ("\\sum", "Σ"),
        ("\\iint", "∬"),
        ("\\int", "∫"),
        ("\\, ", " "),
        ("\\,", " "),
        ("\\ ", " "),
    ] {
        t = t.replace(from, to);
    }
    // one-character indices lose their braces: `d_{3}` → `d_3`
    let mut out = String::with_capacity(t.len());
    let chars: Vec<char> = t.chars().collect();
    let mut k = 0;
    while let Some(&c) = chars.get(k) {
        if let (true, Some('{'), Some(&x), Some('}')) = (
            c == '_' || c == '^',
            chars.get(k + 1),
            chars.get(k + 2),
            chars.get(k + 3),
        ) {
            out.push(c);
            out.push(x);
            k += 4;
            continue;
        }
        out.push(c);
        k += 1;
    }
    out
}
