//! Text of a problem made safe for each kind of key: LaTeX's text mode ([`escape_latex`]),
//! Markdown ([`escape_markdown`], and [`escape_html`] for the engine's own words) and plain
//! text or a terminal ([`escape_text`]).

use crate::tex;

/// Text for LaTeX's text mode, every special character escaped: [`tex::text`], the one
/// escaper, under its older name.
pub fn escape_latex(s: &str) -> String {
    tex::text(s)
}

/// The engine's own words for Markdown, which passes HTML through: `<`, `>` and `&` as
/// entities, the rest (its emphasis, its `$...$`) kept. Text of a problem goes through
/// [`escape_markdown`] instead.
pub fn escape_html(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            c => out.push(c),
        }
    }
    out
}

/// Text of a problem (a name, a title, a note, an erratum, an echoed key, a message that echoes
/// one) for Markdown: shown as written, never read as Markdown. Its control characters as in
/// [`escape_text`] (so it is one line and cannot begin a block); `<`, `>` and `&` as entities
/// (no raw HTML, no autolink, no entity); a backslash before every other character that opens
/// or closes inline Markdown (`` \ ` * _ [ ] ~ | $ # @ ``: no link, image, code span, emphasis,
/// strikethrough, mathematics or heading mark); and before the `:` of `://` and the `.` of
/// `www.`, which GitHub's Markdown links by themselves.
///
/// ```
/// use cagd_keys::escape_markdown;
/// assert_eq!(escape_markdown("[a](javascript:x)"), "\\[a\\](javascript:x)");
/// assert_eq!(escape_markdown("<b> *c* https://d"), "&lt;b&gt; \\*c\\* https\\://d");
/// assert_eq!(escape_markdown("e\u{1b}[2J"), "e\\\\u{1b}\\[2J");
/// ```
pub fn escape_markdown(s: &str) -> String {
    let visible = escape_text(s);
    let mut out = String::with_capacity(visible.len() + visible.len() / 8);
    for (i, c) in visible.char_indices() {
        let after = visible.get(i + c.len_utf8()..).unwrap_or_default();
        let before = visible.get(..i).unwrap_or_default();
        match c {
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            '\\' | '`' | '*' | '_' | '[' | ']' | '~' | '|' | '$' | '#' | '@' => {
                out.push('\\');
                out.push(c);
            }
            ':' if after.starts_with("//") => out.push_str("\\:"),
            '.' if before
                .get(before.len().saturating_sub(3)..)
                .is_some_and(|w| w.eq_ignore_ascii_case("www")) =>
            {
                out.push_str("\\.")
            }
            c => out.push(c),
        }
    }
    out
}

/// Text of a problem (a name, a title, a note, an erratum, an echoed key, a message that echoes
/// one, a file name) for a plain-text key or a terminal: shown as written, on one line, never
/// read by the terminal. Every control character (C0, the line feed and the tab included, DEL
/// and C1, such as ESC, BEL, CR, BS and the one-byte CSI U+009B) and every bidirectional
/// embedding, override or isolate (U+202A to U+202E, U+2066 to U+2069) is written as its
/// escape: `\n`, `\r`, `\t`, else `\u{1b}`. The text cannot move the cursor, clear the screen,
/// set the clipboard, ring, reorder what follows, or begin a line of its own (a line that
/// would read as the key's own, `verdict: ...`).
///
/// ```
/// use cagd_keys::escape_text;
/// assert_eq!(escape_text("a\u{1b}[2J\rverdict: ok\n"), "a\\u{1b}[2J\\rverdict: ok\\n");
/// assert_eq!(escape_text("c\u{9b}1m \u{202e}x"), "c\\u{9b}1m \\u{202e}x");
/// assert_eq!(escape_text("Bézier, C^1, ĉ"), "Bézier, C^1, ĉ");
/// ```
pub fn escape_text(s: &str) -> String {
    let bidi = |c: char| matches!(c, '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}');
    if !s.chars().any(|c| c.is_control() || bidi(c)) {
        return s.to_string();
    }
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        match c {
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if c.is_control() || bidi(c) => out.push_str(&format!("\\u{{{:x}}}", u32::from(c))),
            c => out.push(c),
        }
    }
    out
}
