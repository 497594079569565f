//! The Markdown answer key, its mathematics in `$...$`, and the document around its sections.

use crate::assessment;
use crate::escape::escape_markdown;
use crate::latex_key::item_latex;
use crate::parts::{key_parts, Item};
use crate::steps;
use crate::verdict::{no_raise, RaiseWith};
use crate::vocabulary::{operation_words, Word};
use crate::Lang;
use cagd_contract::Verdict;

/// One example as Markdown with `$...$` math.
pub fn example_markdown(verdict: &Verdict, lang: Lang) -> String {
    example_markdown_with(verdict, lang, no_raise)
}

/// [`example_markdown`] written by a front end that says how to raise a limit.
pub fn example_markdown_with(verdict: &Verdict, lang: Lang, raise: RaiseWith) -> String {
    let k = key_parts(verdict, lang, raise);
    let mut out = format!("## {}\n\n", escape_markdown(&k.heading));
    if !k.source.is_empty() {
        out += &format!(
            "*{}: {}*\n\n",
            lang.word("source"),
            escape_markdown(&k.source)
        );
    }
    if let Some(n) = &k.note {
        out += &format!("*{}:* {}\n\n", lang.word("note"), escape_markdown(n));
    }
    if !k.op.is_empty() {
        out += &format!(
            "{}: {}\n\n",
            lang.word("operation"),
            escape_markdown(&operation_words(&k.op, lang))
        );
    }
    let block = |title: &str, items: &[Item]| -> String {
        if items.is_empty() {
            return String::new();
        }
        let mut b = format!("**{title}**\n\n");
        for it in items {
            match &it.words {
                Some(words) => b += &format!("- {}: {}\n", it.label.text, words.markdown()),
                None => {
                    let sep = if it.sep() == " = " {
                        " = "
                    } else {
                        "\\colon\\ "
                    };
                    b += &format!("- ${}{sep}{}$\n", it.label.latex, item_latex(it, lang))
                }
            }
        }
        b + "\n"
    };
    out += &block(&lang.word("input"), &k.inputs);
    out += &steps::markdown_block(verdict, lang);
    out += &block(&lang.word("steps"), &k.steps);
    out += &block(&lang.word("result"), &k.result);
    for r in &k.remarks {
        out += &format!("*{}*\n\n", escape_markdown(&r.text));
    }
    if let Some(e) = &k.error {
        out += &format!(
            "**{}**: {}\n\n",
            lang.word("error"),
            escape_markdown(&e.text)
        );
    }
    if verdict.checked {
        out += &format!(
            "**{}**: {}\n\n",
            lang.word("verdict"),
            escape_markdown(&k.verdict.text)
        );
        if let Some(a) = assessment::of(verdict) {
            out += &assessment::markdown_block(a, verdict.problem.as_deref(), lang);
        }
    }
    out
}

/// A student's checked answer as Markdown, for the student: the heading, the verdict's line
/// and the assessment (each result's score, its wrong entries, the mistakes that explain
/// them), without the key's inputs, steps or results; each wrong entry with the key's value
/// beside the student's only when `key_values` (the key is revealed). A verdict without an
/// assessment is its heading and verdict line.
pub fn assessment_markdown(verdict: &Verdict, lang: Lang, key_values: bool) -> String {
    let k = key_parts(verdict, lang, no_raise);
    let mut out = format!("## {}\n\n", escape_markdown(&k.heading));
    if let Some(e) = &k.error {
        out += &format!(
            "**{}**: {}\n\n",
            lang.word("error"),
            escape_markdown(&e.text)
        );
        return out;
    }
    out += &format!(
        "**{}**: {}\n\n",
        lang.word("verdict"),
        escape_markdown(&k.verdict.text)
    );
    if let Some(a) = assessment::of(verdict) {
        out += &assessment::markdown_block_with(a, verdict.problem.as_deref(), lang, key_values);
    }
    out
}

/// A Markdown image of a file written beside the key: `![alt](path)`, the alternative text
/// through [`escape_markdown`] and the path as a relative URL, every byte but the unreserved
/// ones (`A-Z a-z 0-9 - . _ ~`) and `/` percent-encoded, so that a folder named `set #3`
/// (a space, a `#` that would start a fragment, a parenthesis that would end the destination)
/// is read back as that path.
///
/// ```
/// use cagd_keys::markdown_image;
/// assert_eq!(markdown_image("fig", "set #3/a (1).svg"), "![fig](set%20%233/a%20%281%29.svg)");
/// ```
pub fn markdown_image(alt: &str, path: &str) -> String {
    let mut url = String::with_capacity(path.len());
    for b in path.bytes() {
        match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'.' | b'_' | b'~' | b'/' => {
                url.push(char::from(b))
            }
            b => url.push_str(&format!("%{b:02X}")),
        }
    }
    format!("![{}]({url})", escape_markdown(alt))
}

/// A complete Markdown document around sections from [`example_markdown`], titled "Answer
/// key: `title`".
pub fn markdown_document(title: &str, sections: &[String], lang: Lang) -> String {
    let title = format!("{}: {title}", lang.word("Answer key"));
    markdown_key_document(&title, "", sections)
}

/// A complete Markdown document of keys under its own `title` (shown as written), the
/// `legend` (from [`crate::legend_markdown`]) once after the title, then the sections from
/// [`example_markdown`].
pub fn markdown_key_document(title: &str, legend: &str, sections: &[String]) -> String {
    let mut out = format!("# {}\n\n{legend}", escape_markdown(title));
    for s in sections {
        out += s;
    }
    out
}
