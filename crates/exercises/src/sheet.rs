//! The files of a problem set, for generated problems and for a teacher's own alike: the
//! problems, the statement sheet (without answers) and the answer keys, from the problems'
//! verdicts ([`sheet_files`]). The library does no I/O: files are returned as names and
//! contents.

use crate::{problems_json, Lang};
use cagd_keys::{
    example_latex_beside, example_markdown, example_text, latex_key_document, legend_latex,
    legend_markdown, legend_text, markdown_key_document, statement_document, statement_latex,
    SheetHeader, Word,
};
use cagd_problem::Verdict;
use serde_json::Value;

/// A figure of a problem set: its verdict, and whether it goes with the statement (the data
/// only) or with the answer key; returns the path to include, or `None` when there is nothing
/// to draw. The caller draws and writes it (the library does no I/O).
pub type SetFigure<'a> = &'a dyn Fn(&Verdict, bool) -> Option<String>;

/// The files of a problem set: `problems.json` (the problems as given), the statement sheet
/// `statements.tex` (under `header`, each problem a question and its data, no answer, a
/// complete LaTeX document) and the answer keys `key.txt`, `key.md`, `key.tex` (a complete
/// LaTeX document) and `key.json` (one answer per problem, `{"name", "ok", "op", "result"}`
/// with the steps). `problems` and `verdicts` go together, in order; each verdict's `index`
/// numbers its problem (Problem 1, 2, ...). `figure` gives the path of each problem's figure,
/// for the statement sheet and for the key, included after the problem.
pub fn sheet_files(
    problems: &[Value],
    verdicts: &[Verdict],
    header: &SheetHeader,
    lang: Lang,
    figure: SetFigure<'_>,
) -> Vec<(String, String)> {
    let title = header.title_in(lang);
    let sections = |f: fn(&Verdict, Lang) -> String| -> Vec<String> {
        verdicts.iter().map(|v| f(v, lang)).collect()
    };
    // the key: the notation legend once, then each problem (its figure beside its data)
    let text = format!(
        "{}: {title}\n\n{}{}",
        lang.word("Answer key"),
        legend_text(verdicts, lang),
        sections(example_text).join("\n")
    );
    let key_title = format!("{}: {title}", lang.word("Answer key"));
    let markdown = markdown_key_document(
        &key_title,
        &legend_markdown(verdicts, lang),
        &sections(example_markdown),
    );
    let key_sections: Vec<String> = verdicts
        .iter()
        .map(|v| example_latex_beside(v, lang, figure(v, false).as_deref()))
        .collect();
    let latex = latex_key_document(
        &key_title,
        &legend_latex(verdicts, lang),
        &key_sections,
        lang,
    );
    let statement_sections: Vec<String> = verdicts
        .iter()
        .map(|v| {
            let mut s = statement_latex(v, lang);
            if let Some(path) = figure(v, true) {
                s += &format!(
                    "\\begin{{center}}{}\\end{{center}}\n\n",
                    cagd_keys::tex::graphics(
                        &path,
                        "width=0.45\\textwidth,height=0.4\\textheight,keepaspectratio"
                    )
                );
            }
            s
        })
        .collect();
    let statements = statement_document(header, &statement_sections, lang);
    let keys: Vec<Value> = problems
        .iter()
        .zip(verdicts)
        .map(|(p, v)| {
            let mut answer = match &v.answer {
                Ok(a) => a.to_json(true),
                Err(e) => cagd_problem::error_json(e),
            };
            if let Some(obj) = answer.as_object_mut() {
                obj.insert("name".into(), p.get("name").cloned().unwrap_or(Value::Null));
            }
            answer
        })
        .collect();
    vec![
        ("problems.json".into(), problems_json(problems)),
        ("statements.tex".into(), statements),
        ("key.txt".into(), text),
        ("key.md".into(), markdown),
        ("key.tex".into(), latex),
        ("key.json".into(), problems_json(&keys)),
    ]
}
