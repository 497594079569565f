//! Statement sheets: the problems of a set for students, in LaTeX, with their data and what to
//! find, never an answer.

use crate::latex_key::{latex_item, latex_preamble};
use crate::parts::{key_parts, meta};
use crate::verdict::no_raise;
use crate::vocabulary::{op_words, Word};
use crate::{tex, Lang};
use cagd_contract::Verdict;

/// One problem as a LaTeX section of a statement sheet (inside [`statement_document`]): its
/// number and title, the data, and what to find (the names of its results), never an answer.
pub fn statement_latex(verdict: &Verdict, lang: Lang) -> String {
    let k = key_parts(verdict, lang, no_raise);
    let (meta, _) = meta(verdict);
    let title = match lang {
        Lang::Es => meta
            .es
            .as_ref()
            .and_then(|e| e.title.clone())
            .or(meta.title.clone()),
        Lang::En => meta.title.clone(),
    }
    .unwrap_or_else(|| op_words(&k.op, lang).to_string());
    let heading = match verdict.index {
        Some(i) => format!("{} {}: {title}", lang.word("Problem"), i + 1),
        None => title,
    };
    let mut out = format!("\\section*{{{}}}\n", tex::words(&heading));
    if let Some(n) = &k.note {
        out += &format!("\\textit{{{}}}\\\\\n", tex::words(n));
    }
    if !k.inputs.is_empty() {
        out += &format!("{}:\n\\begin{{itemize}}\n", lang.word("Data"));
        for it in &k.inputs {
            out += &format!("\\item {}\n", latex_item(it, lang));
        }
        out += "\\end{itemize}\n";
    }
    let find: Vec<String> = k
        .result
        .iter()
        .map(|it| match &it.words {
            Some(_) => tex::words(&it.label.text),
            None => format!("${}$", it.label.latex),
        })
        .collect();
    if !find.is_empty() {
        out += &format!("{}: {}.\n\n", lang.word("Find"), find.join(", "));
    }
    tex::known_characters(&out)
}

/// A complete LaTeX document around sections from [`statement_latex`]: the problems of a
/// set, for students, without their answers.
pub fn statement_document(title: &str, sections: &[String], lang: Lang) -> String {
    let mut out = latex_preamble(lang);
    out += &format!(
        "\\title{{{}}}\n\\date{{}}\n\\begin{{document}}\n\\maketitle\n",
        tex::words(&format!("{}: {title}", lang.word("Statements")))
    );
    for s in sections {
        out += s;
    }
    out + "\\end{document}\n"
}
