//! The one way Markdown becomes HTML on the pages: the keys' Markdown (cagd-keys, whose
//! writers escape every word of a problem) read by pulldown-cmark, with every raw HTML event
//! turned into escaped text, links and images dropped (their text kept), and mathematics put
//! in `data-tex` attributes for the page's script to typeset: `$x$` becomes
//! `<span class="math" data-tex="x"></span>`, `$$x$$` becomes
//! `<div class="math display" data-tex="x"></div>`.

use pulldown_cmark::{html, Alignment, CowStr, Event, Options, Parser, Tag, TagEnd};

/// `text` escaped for an HTML attribute value in double quotes (and for text): the figures'
/// escape.
pub use cagd_render::escape_xml as escape_attribute;

/// Markdown (with `$...$` mathematics and tables) as HTML that runs nothing: no raw HTML, no
/// link, no image; mathematics as empty elements carrying their TeX in `data-tex`.
pub fn to_html(markdown: &str) -> String {
    let options = Options::ENABLE_MATH | Options::ENABLE_TABLES;
    let events = Parser::new_ext(markdown, options).filter_map(|event| match event {
        Event::Html(raw) | Event::InlineHtml(raw) => Some(Event::Text(raw)),
        Event::InlineMath(tex) => Some(Event::InlineHtml(CowStr::from(format!(
            "<span class=\"math\" data-tex=\"{}\"></span>",
            escape_attribute(&tex)
        )))),
        Event::DisplayMath(tex) => Some(Event::InlineHtml(CowStr::from(format!(
            "<div class=\"math display\" data-tex=\"{}\"></div>",
            escape_attribute(&tex)
        )))),
        Event::Start(Tag::Link { .. } | Tag::Image { .. })
        | Event::End(TagEnd::Link | TagEnd::Image) => None,
        Event::Start(Tag::HtmlBlock) | Event::End(TagEnd::HtmlBlock) => None,
        // a column's alignment would be a `style` attribute: the tables are aligned by the
        // pages' style sheet, and the server's HTML carries no style
        Event::Start(Tag::Table(columns)) => Some(Event::Start(Tag::Table(vec![
            Alignment::None;
            columns.len()
        ]))),
        other => Some(other),
    });
    let mut out = String::new();
    html::push_html(&mut out, events);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_style_attribute() {
        let html = to_html("| a | b |\n|:-|-:|\n| 1 | 2 |\n");
        assert!(html.contains("<table>"), "{html}");
        assert!(!html.contains("style="), "{html}");
    }

    #[test]
    fn raw_html_is_text() {
        let html =
            to_html("<script>alert(1)</script>\n\nA <b>bold</b> <img src=x onerror=alert(1)> word");
        assert!(!html.contains("<script"), "{html}");
        assert!(!html.contains("<b>"), "{html}");
        assert!(!html.contains("<img"), "{html}");
        assert!(html.contains("&lt;script&gt;"), "{html}");
    }

    #[test]
    fn mathematics_in_attributes() {
        let html = to_html("Let $c_1(u) = \"<x>\"$ and\n\n$$\\frac{1}{2}$$\n");
        assert!(
            html.contains(
                "<span class=\"math\" data-tex=\"c_1(u) = &quot;&lt;x&gt;&quot;\"></span>"
            ),
            "{html}"
        );
        assert!(
            html.contains("<div class=\"math display\" data-tex=\"\\frac{1}{2}\"></div>"),
            "{html}"
        );
    }

    #[test]
    fn links_and_images_keep_their_text_only() {
        let html = to_html("[click](javascript:alert(1)) ![alt](http://x/y.png)");
        assert!(!html.contains("href"), "{html}");
        assert!(!html.contains("javascript"), "{html}");
        assert!(!html.contains("<img"), "{html}");
        assert!(html.contains("click"), "{html}");
    }

    #[test]
    fn a_title_with_a_script_from_a_key_is_escaped() {
        let title = "<script>alert(1)</script>";
        let markdown = format!("## {}\n", cagd_keys::escape_markdown(title));
        let html = to_html(&markdown);
        assert!(!html.contains("<script"), "{html}");
        assert!(html.contains("alert(1)"), "{html}");
    }

    #[test]
    fn tables_are_read() {
        let html = to_html("| a | b |\n|---|---|\n| 1 | 2 |\n");
        assert!(html.contains("<table>"), "{html}");
    }
}
