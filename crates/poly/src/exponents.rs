//! The parenthesized exponents of a text, `x^(e)`.
//!
//! The grammar of cagd-scalar evaluates a parenthesized exponent with its own number builder,
//! whatever builder reads the rest, and that builder bounds literals and exponents but not the
//! size of a value: `2^(((10^3)^1000)^1000)` would compute 10^3000000 before finding that it
//! is no exponent. The readers of this crate (and of the problem layer) therefore read each
//! parenthesized exponent first, innermost first, under a bounded builder, and refuse the text
//! when one is too large; what is left for the grammar's builder is then cheap.

/// The parenthesized exponents `^(e)` and `^-(e)` of `text`: the 1-based column of the first
/// character of `e` and the text of `e`, innermost first (each exponent comes before every
/// exponent that contains it). An exponent whose parenthesis is never closed runs to the end
/// of the text.
///
/// ```
/// use cagd_poly::parenthesized_exponents;
/// assert_eq!(
///     parenthesized_exponents("2^((10^(3))^2) + u^-(1)"),
///     vec![(9, "3"), (22, "1"), (4, "(10^(3))^2")]
/// );
/// ```
pub fn parenthesized_exponents(text: &str) -> Vec<(usize, &str)> {
    // (byte index after '(', its column, whether it opens an exponent)
    let mut open: Vec<(usize, usize, bool)> = Vec::new();
    let mut spans: Vec<(usize, usize, usize)> = Vec::new();
    let mut after_caret = false;
    for (column, (pos, c)) in text.char_indices().enumerate() {
        match c {
            '(' => {
                open.push((pos + 1, column + 2, after_caret));
                after_caret = false;
            }
            ')' => {
                if let Some((start, col, true)) = open.pop() {
                    spans.push((start, pos, col));
                }
                after_caret = false;
            }
            '^' => after_caret = true,
            '-' | '\u{2212}' => {}
            c if c.is_whitespace() => {}
            _ => after_caret = false,
        }
    }
    // an exponent left open runs to the end (the grammar reads it before it finds no ')')
    for (start, col, exponent) in open {
        if exponent {
            spans.push((start, text.len(), col));
        }
    }
    // an exponent inside another is shorter than it
    spans.sort_by_key(|&(start, end, _)| end - start);
    spans
        .into_iter()
        .filter_map(|(start, end, col)| text.get(start..end).map(|e| (col, e)))
        .collect()
}
