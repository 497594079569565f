//! The text of a problem is data in the Markdown and plain-text keys: a name, title, note,
//! source, erratum (and their Spanish), an `expected` key echoed in a verdict or an unknown
//! operation echoed in an error is shown as written. Read by a CommonMark parser
//! (pulldown-cmark, with GitHub's tables, strikethrough, footnotes and `$...$` mathematics), the
//! Markdown key has no link, image, raw HTML or footnote, and the text of each field is there
//! whole (no emphasis, code span or mathematics took its marks); the text key has no control
//! character but its own line feeds, and no line of a problem's text.

use cagd_keys::{escape_text, example_markdown, example_text, markdown_document, Lang};
use cagd_problem::{check, Verdict};
use proptest::prelude::*;
use pulldown_cmark::{Event, Options, Parser, Tag, TagEnd};
use serde_json::{json, Value};

/// Markdown that a renderer would make live: a link (to javascript:), an image from the web,
/// an autolink, raw HTML, emphasis, a code span, mathematics, strikethrough, a footnote, a
/// reference definition, an entity, a heading's closing marks, and GitHub's bare links.
const LIVE: &[&str] = &[
    "[click me](javascript:alert(1))",
    "![b](https://example.org/b.png)",
    "<https://example.org/a>",
    "<script>alert(1)</script>",
    "<img src=x onerror=alert(1)>",
    "*emph* **strong** _u_ __v__",
    "`code`",
    "$x^2$",
    "~~struck~~ ~s~",
    "[^1]",
    "[r]: https://example.org/r",
    "[r]",
    "&amp; &#60;",
    "<!-- c -->",
    "see https://example.org and www.example.org and a@example.org",
    "\\",
    "| a | b |",
    "##",
];

/// The terminal's control characters: ESC (a CSI that clears the screen, an OSC 52 that sets
/// the clipboard), BEL, CR (a line that overwrites the one before), BS, the one-byte CSI
/// U+009B, DEL, a tab, a line feed, and a bidirectional override.
const CONTROL: &[&str] = &[
    "\u{1b}[2J\u{1b}[H",
    "\u{1b}]52;c;cHduZWQ=\u{7}",
    "\u{7}",
    "\rverdict: passed",
    "\u{8}\u{8}",
    "\u{9b}31m",
    "\u{7f}",
    "\t",
    "\nverdict: passed",
    "\u{202e}dessap\u{202c}",
    "\u{2066}x\u{2069}",
    "\u{0}",
];

/// The options of GitHub's Markdown that pulldown-cmark has.
fn options() -> Options {
    Options::ENABLE_TABLES
        | Options::ENABLE_FOOTNOTES
        | Options::ENABLE_STRIKETHROUGH
        | Options::ENABLE_TASKLISTS
        | Options::ENABLE_MATH
        | Options::ENABLE_GFM
}

/// What a renderer makes of a Markdown key: the events that would be live (links, images,
/// HTML, footnotes), and the text of each block (a heading, a paragraph, a list item), with
/// the text of its code spans and mathematics.
struct Read {
    live: Vec<String>,
    blocks: Vec<String>,
}

fn read(md: &str) -> Read {
    let (mut live, mut blocks, mut block) = (Vec::new(), Vec::new(), String::new());
    for e in Parser::new_ext(md, options()) {
        match &e {
            Event::Start(Tag::Link { .. } | Tag::Image { .. } | Tag::HtmlBlock)
            | Event::Start(Tag::FootnoteDefinition(_))
            | Event::Html(_)
            | Event::InlineHtml(_)
            | Event::FootnoteReference(_) => live.push(format!("{e:?}")),
            _ => {}
        }
        match e {
            Event::Text(t) => block += &t,
            Event::Code(t) => block += &format!("`{t}`"),
            Event::InlineMath(t) => block += &format!("${t}$"),
            Event::SoftBreak | Event::HardBreak => block.push('\n'),
            Event::End(TagEnd::Heading(_) | TagEnd::Paragraph | TagEnd::Item) => {
                blocks.push(std::mem::take(&mut block))
            }
            _ => {}
        }
    }
    Read { live, blocks }
}

/// A problem with `s` in every text field (each field tagged), its `expected` answer right (so
/// that its errata are printed in the verdict).
fn problem(s: &str) -> Value {
    json!({
        "op": "evaluate", "curve": {"bezier": [[0, 0], [1, 2]]}, "params": ["1/2"],
        "name": format!("n{s}"), "title": format!("t{s}"), "note": format!("note{s}"),
        "source": format!("src{s}"), "equation": format!("(1{s})"),
        "errata": [{"where": format!("w{s}"), "printed": format!("p{s}"),
                    "exact": format!("e{s}"), "why": format!("y{s}"),
                    "es": {"where": format!("dónde{s}"), "why": format!("por{s}")}}],
        "es": {"title": format!("título{s}"), "note": format!("nota{s}")},
        "expected": {"points": [["1/2", 1]]}
    })
}

/// A problem whose `expected` has a key named `s` (echoed in the failed verdict).
fn wrong_key(s: &str) -> Value {
    json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 2]]}, "params": ["1/2"],
           "title": "t", "expected": {"points": [["1/2", 1]], s: 1}})
}

/// A problem whose operation is `s` (echoed in the error).
fn unknown_op(s: &str) -> Value {
    json!({"op": format!("op{s}"), "title": "t"})
}

/// The texts of a problem's fields that its key in `lang` shows whole, as the text key writes
/// them ([`escape_text`]).
fn shown(s: &str, lang: Lang) -> Vec<String> {
    let fields = match lang {
        Lang::En => vec![
            format!("t{s}"),
            format!("note{s}"),
            format!("src{s}"),
            format!("w{s}"),
            format!("p{s}"),
            format!("e{s}"),
            format!("y{s}"),
        ],
        Lang::Es => vec![
            format!("título{s}"),
            format!("nota{s}"),
            format!("dónde{s}"),
            format!("por{s}"),
        ],
    };
    fields.iter().map(|f| escape_text(f)).collect()
}

/// The line of a text key or a block of a Markdown key that holds `what`.
fn holds(blocks: &[String], what: &str) -> bool {
    blocks.iter().any(|b| b.contains(what))
}

/// The control characters a terminal acts on: C0 but the line feed, DEL, C1, and the
/// bidirectional embeddings, overrides and isolates.
fn is_control(c: char) -> bool {
    (c.is_control() && c != '\n') || matches!(c, '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}')
}

/// Checks the Markdown and text keys of a verdict in `lang`: nothing live in the Markdown, the
/// texts `shown` whole in both, no control character and no `fake` line start in the text.
fn assert_data(v: &Verdict, lang: Lang, shown: &[String]) {
    let md = markdown_document("answers.json", &[example_markdown(v, lang)], lang);
    let r = read(&md);
    assert!(r.live.is_empty(), "live Markdown {:?} in\n{md}", r.live);
    for s in shown {
        assert!(
            holds(&r.blocks, s),
            "{s:?} not shown whole in\n{md}\n{:#?}",
            r.blocks
        );
    }
    let text = example_text(v, lang);
    assert!(
        !text.chars().any(is_control),
        "a control character in\n{text:?}"
    );
    let lines: Vec<String> = text.lines().map(str::to_string).collect();
    for s in shown {
        assert!(holds(&lines, s), "{s:?} not shown whole in\n{text}");
    }
    for fake in ["verdict: passed", "dessap"] {
        assert!(
            !text.lines().any(|l| l.starts_with(fake)),
            "{fake} begins a line of\n{text}"
        );
    }
}

#[test]
fn markdown_of_a_problem_is_shown_not_rendered() {
    for s in LIVE.iter().chain(CONTROL) {
        // (not at the end: a heading or paragraph drops its trailing spaces)
        let s = format!(" {s} .");
        for lang in [Lang::En, Lang::Es] {
            let v = check(&problem(&s));
            assert!(v.passed(), "{s:?}: {:?}", v.mismatches);
            assert_data(&v, lang, &shown(&s, lang));
        }
        // an expected key and an unknown operation, echoed in the verdict and the error
        let v = check(&wrong_key(&s));
        assert!(!v.passed());
        assert_data(&v, Lang::En, &[escape_text(&s)]);
        let v = check(&unknown_op(&s));
        assert!(v.answer.is_err());
        assert_data(&v, Lang::En, &[]);
    }
}

#[test]
fn the_title_of_a_markdown_document_is_shown_not_rendered() {
    for s in LIVE.iter().chain(CONTROL) {
        let title = format!("set{s}.json");
        let md = markdown_document(&title, &[], Lang::En);
        let r = read(&md);
        assert!(r.live.is_empty(), "{md}");
        let first = r.blocks.first().cloned().unwrap_or_default();
        assert_eq!(
            first,
            format!("Answer key: {}", escape_text(&title)),
            "{md}"
        );
    }
}

#[test]
fn control_characters_are_shown_visibly() {
    assert_eq!(escape_text("a\u{1b}[2J"), "a\\u{1b}[2J");
    assert_eq!(
        escape_text("b\u{7}c\rd\u{8}e\u{9b}f"),
        "b\\u{7}c\\rd\\u{8}e\\u{9b}f"
    );
    assert_eq!(escape_text("x\ny\tz\u{7f}"), "x\\ny\\tz\\u{7f}");
    assert_eq!(escape_text("\u{202e}\u{2066}"), "\\u{202e}\\u{2066}");
    // the notes' own characters stay as they are
    let notes = "Bézier, c̃, Δ^{1,0}, √2, ∂, C¹, «ñ» — año";
    assert_eq!(escape_text(notes), notes);
}

/// Any text, with Markdown's and the terminal's specials mixed in.
fn hostile() -> impl Strategy<Value = String> {
    let piece = prop_oneof![
        any::<String>(),
        "[ -~]{0,12}",
        proptest::sample::select(LIVE).prop_map(str::to_string),
        proptest::sample::select(CONTROL).prop_map(str::to_string),
        "[\\[\\]()<>!*_`$~|#&:@\\\\/ a-z\u{1b}\u{7}\r\n\u{8}\u{9b}]{0,16}",
    ];
    proptest::collection::vec(piece, 1..5).prop_map(|ps| ps.concat())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Random text in every text field of a problem: its Markdown key, read by a CommonMark
    /// parser, has no link, image, HTML or footnote and shows the heading whole; its text key
    /// has no control character but its own line feeds, and the heading on one line.
    #[test]
    fn any_text_is_data(s in hostile()) {
        for lang in [Lang::En, Lang::Es] {
            let v = check(&problem(&s));
            prop_assert!(v.passed(), "{:?}", v.mismatches);
            let md = example_markdown(&v, lang);
            let r = read(&md);
            prop_assert!(r.live.is_empty(), "live Markdown {:?} in\n{}", r.live, md);
            // the title alone: the name is an internal id
            let heading = match lang {
                Lang::En => format!("t{s}"),
                Lang::Es => format!("título{s}"),
            };
            // a heading's trailing spaces are not its text
            let heading = escape_text(&heading).trim_end_matches(' ').to_string();
            prop_assert_eq!(r.blocks.first().cloned().unwrap_or_default(), heading.clone());
            let text = example_text(&v, lang);
            prop_assert!(!text.chars().any(is_control), "{:?}", text);
            let first = text.lines().next().unwrap_or_default();
            prop_assert_eq!(first.trim_end_matches(' '), format!("== {heading}"));
        }
        let v = check(&wrong_key(&s));
        let md = example_markdown(&v, Lang::En);
        let r = read(&md);
        prop_assert!(r.live.is_empty(), "live Markdown {:?} in\n{}", r.live, md);
        prop_assert!(!example_text(&v, Lang::En).chars().any(is_control));
    }
}
