//! `cagd check FILE...`: checks written answers (a teacher's own, or a class's), written under
//! `"expected"`, and diagnoses them: every entry right or wrong, a score, and the common
//! mistakes that explain a wrong answer (cagd-diagnose). A class at once: a file per student,
//! or problems that name their `"student"`; each student's report, and the teacher's summary.

use crate::cli::{path, KeyArgs, KeyFormat, LimitArgs, PathKind};
use crate::said::CliMessage;
use crate::solve::{problems, read_json};
use crate::{CliError, Report};
use cagd_diagnose::class::ClassSummary;
use cagd_diagnose::{diagnose_with, Key};
use cagd_keys::{
    escape_latex, escape_markdown, escape_text, example_latex_with, example_markdown_with,
    example_text_with, latex_key_document, legend_latex, legend_markdown, markdown_key_document,
    Lang,
};
use cagd_problem::{check_problem, Problem, Settings, Verdict};
use cagd_words::{said, Message, Phrase};
use clap::Args;
use serde_json::Value;
use std::collections::HashMap;
use std::path::Path;
use std::sync::Arc;

/// The usage line of `cagd check`.
pub const USAGE: &str =
    "cagd check FILE... [--format FORMAT] [--lang LANG] [--out DIR] [--summary] [--max-... N]";

/// Check written answers: a teacher's own, or a class's, diagnosed
///
/// Each FILE holds a problem or a JSON array of problems, each with an answer under
/// "expected" (same keys as the answer's result: surface, closed_form, points...). The
/// "result" of `cagd solve --format json` (with or without --steps) can be given whole: its
/// results and its "steps" list are compared; its "remarks" and "derivation", words and
/// layout, are read and not compared. Every problem is solved exactly, once for all the
/// answers to it, and each answer is diagnosed: every entry right or wrong, a score, and the
/// common mistakes whose exact answer is the one written ("ambiguous" when several are, "no
/// known mistake" when none is). Exit code 1 if any answer is wrong or missing, or names a key
/// that is not a result. The limits and their flags are those of `cagd solve`
/// (docs/format.md, Limits).
///
/// A class at once: a file per student (the student is the file's name without its
/// extension, unless its problems say "student"), or one file whose problems say "student".
/// With --out DIR each student's report is written to DIR/<student>.<ext> (the name made a
/// safe file name) and the teacher's summary to DIR/summary.<ext>; without it, the reports are
/// printed, then the summary. The summary (per problem: answers, right, mean score, the
/// mistakes made and how often) is written when two students or more answered, or with
/// --summary. In JSON: a list of the answers (`cagd solve --format json` with "assessment",
/// "student", "file" and "problem"); with a summary and no --out, an object of "answers" and
/// "summary" (docs/format.md, "Checking a student's answer").
#[derive(Debug, Clone, Args)]
#[command(verbatim_doc_comment, override_usage = USAGE)]
pub struct CheckArgs {
    /// The files of problems with their answers under "expected"
    #[arg(value_name = "FILE", required = true, value_parser = path("FILE", PathKind::File))]
    pub files: Vec<String>,
    #[command(flatten)]
    pub key: KeyArgs,
    /// Write each student's report and the summary into this folder (made if missing)
    #[arg(long, value_name = "DIR", value_parser = path("--out", PathKind::Folder))]
    pub out: Option<String>,
    /// Write the class summary even for one student's answers
    #[arg(long)]
    pub summary: bool,
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// Runs `cagd check`, its errors in the language asked.
pub fn run(args: &CheckArgs) -> Result<Report, CliError> {
    let lang = args.key.lang.lang();
    run_in(args).map_err(|e| e.in_lang(lang))
}

/// One answer checked: where it was read, whose it is, the key it was checked against, and
/// its verdict.
struct Checked {
    /// The file it was read from.
    file: String,
    /// Its place in the file, from 0.
    index: usize,
    /// The student.
    student: Option<String>,
    /// The number of its problem (its key), the same for every answer to the same problem.
    problem: usize,
    /// The verdict, with its assessment.
    verdict: Verdict,
}

/// The keys of the problems checked, each solved once: a problem is known by its JSON
/// without the fields that differ from student to student (`expected`, `student`) and the
/// words (`name`, `title`), written canonically.
#[derive(Default)]
struct Keys {
    /// The number of each problem, by its canonical text.
    numbers: HashMap<String, usize>,
    /// The key of each problem, by number (none until one answer to it could be read).
    keys: Vec<Option<Key>>,
}

/// The fields of a problem that are not the problem: the answer, whose it is, its words.
const NOT_THE_PROBLEM: [&str; 4] = ["expected", "student", "name", "title"];

impl Keys {
    /// The number of the problem `p` (a JSON problem), new when it is the first of its kind.
    fn number(&mut self, p: &Value) -> usize {
        let mut text = String::new();
        match p {
            Value::Object(o) => {
                let mut fields: Vec<(&String, &Value)> = o
                    .iter()
                    .filter(|(k, _)| !NOT_THE_PROBLEM.contains(&k.as_str()))
                    .collect();
                fields.sort_by(|a, b| a.0.cmp(b.0));
                for (k, v) in fields {
                    text += &Value::String(k.clone()).to_string();
                    text.push(':');
                    canonical(v, &mut text);
                    text.push(',');
                }
            }
            other => canonical(other, &mut text),
        }
        let next = self.numbers.len();
        let n = *self.numbers.entry(text).or_insert(next);
        if n == self.keys.len() {
            self.keys.push(None);
        }
        n
    }

    /// The verdict on the answer `value` (read as `problem`), checked against the key of
    /// problem number `n` (solved on first use).
    fn verdict(&mut self, n: usize, problem: &Arc<Problem>, settings: &Settings) -> Verdict {
        let Some(slot) = self.keys.get_mut(n) else {
            return check_problem(problem, settings);
        };
        let key = slot.get_or_insert_with(|| Key::new(problem, settings));
        diagnose_with(key, problem, settings)
    }
}

/// A JSON value written canonically: objects with their keys sorted, no spaces.
fn canonical(v: &Value, out: &mut String) {
    match v {
        Value::Object(o) => {
            let mut fields: Vec<(&String, &Value)> = o.iter().collect();
            fields.sort_by(|a, b| a.0.cmp(b.0));
            out.push('{');
            for (k, v) in fields {
                *out += &Value::String(k.clone()).to_string();
                out.push(':');
                canonical(v, out);
                out.push(',');
            }
            out.push('}');
        }
        Value::Array(items) => {
            out.push('[');
            for v in items {
                canonical(v, out);
                out.push(',');
            }
            out.push(']');
        }
        other => *out += &other.to_string(),
    }
}

/// The student of the answer `p` read from `file`: its `"student"`, else the file's name
/// without its extension (none for standard input).
fn student_of(p: &Value, file: &str) -> Option<String> {
    if let Some(s) = p.get("student").and_then(Value::as_str) {
        return Some(s.to_string());
    }
    if file == "-" {
        return None;
    }
    Path::new(file)
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
}

/// Runs `cagd check`.
fn run_in(args: &CheckArgs) -> Result<Report, CliError> {
    let (format, lang) = (args.key.format, args.key.lang.lang());
    let settings = Settings {
        limits: args.limits.limits(),
        steps: true,
    };
    let mut keys = Keys::default();
    let mut checked: Vec<Checked> = Vec::new();
    for file in &args.files {
        let doc = read_json(file)?;
        for (index, p) in problems(&doc).iter().enumerate() {
            let problem = keys.number(p);
            let verdict = match Problem::read(p, &settings.limits) {
                Ok(read) => keys.verdict(problem, &Arc::new(read), &settings),
                Err(e) => Verdict::failed(e),
            }
            .require_expected(p);
            checked.push(Checked {
                file: file.clone(),
                index,
                student: student_of(p, file),
                problem,
                verdict,
            });
        }
    }
    let wrong = checked.iter().filter(|c| !c.verdict.passed()).count();
    let code = u8::from(wrong > 0);
    // the students in the order met, each with their answers
    let mut students: Vec<(Option<String>, Vec<&Checked>)> = Vec::new();
    for c in &checked {
        match students.iter_mut().find(|(s, _)| *s == c.student) {
            Some((_, list)) => list.push(c),
            None => students.push((c.student.clone(), vec![c])),
        }
    }
    let summary = (students.len() > 1 || args.summary).then(|| {
        let mut s = ClassSummary::new();
        for c in &checked {
            s.add(c.problem, c.student.as_deref(), &c.verdict);
        }
        s
    });
    let named = students.len() > 1 || args.out.is_some();
    let text = match &args.out {
        Some(dir) => {
            write_out(dir, &students, summary.as_ref(), format, lang)?
                + &count_line(checked.len(), wrong, lang)
        }
        None => print(&students, summary.as_ref(), named, format, lang),
    };
    Ok(Report { text, code })
}

/// The reports (and the summary) on standard output: text and Markdown one after another;
/// LaTeX one document; JSON the list of the answers, or with a summary an object of
/// `answers` and `summary`.
fn print(
    students: &[(Option<String>, Vec<&Checked>)],
    summary: Option<&ClassSummary>,
    named: bool,
    format: KeyFormat,
    lang: Lang,
) -> String {
    match format {
        KeyFormat::Json => {
            let answers: Vec<Value> = students
                .iter()
                .flat_map(|(_, list)| list.iter().map(|c| answer_json(c)))
                .collect();
            let doc = match summary {
                Some(s) => serde_json::json!({"answers": answers, "summary": s.to_json()}),
                None => Value::Array(answers),
            };
            serde_json::to_string_pretty(&doc).unwrap_or_default() + "\n"
        }
        KeyFormat::Latex => {
            let mut sections = Vec::new();
            let mut verdicts = Vec::new();
            for (student, list) in students {
                if named {
                    let heading = CheckWord::Student(student.clone()).phrase(lang).text();
                    sections.push(format!("\\part*{{{}}}\n", escape_latex(&heading)));
                }
                sections.extend(latex_sections(list, lang));
                verdicts.extend(list.iter().map(|c| &c.verdict));
            }
            if let Some(s) = summary {
                sections.push(s.latex_body(lang));
            }
            let title = CheckWord::Report(None).phrase(lang).text();
            latex_key_document(&title, &legend_latex(verdicts, lang), &sections, lang)
        }
        KeyFormat::Markdown => {
            let mut out: Vec<String> = students
                .iter()
                .map(|(student, list)| markdown_report(student.as_deref(), list, named, lang))
                .collect();
            if let Some(s) = summary {
                out.push(s.markdown(lang));
            }
            out.join("\n")
        }
        KeyFormat::Text => {
            let mut out: Vec<String> = students
                .iter()
                .map(|(student, list)| text_report(student.as_deref(), list, named, lang))
                .collect();
            if let Some(s) = summary {
                out.push(s.text(lang));
            }
            out.join("\n")
        }
    }
}

/// Writes each student's report to `dir/<student>.<ext>` and the summary to
/// `dir/summary.<ext>`; the lines naming the files written.
fn write_out(
    dir: &str,
    students: &[(Option<String>, Vec<&Checked>)],
    summary: Option<&ClassSummary>,
    format: KeyFormat,
    lang: Lang,
) -> Result<String, CliError> {
    std::fs::create_dir_all(dir).map_err(|e| {
        CliError::input(CliMessage::CannotCreate {
            path: dir.to_string(),
            why: e.to_string(),
        })
    })?;
    let ext = match format {
        KeyFormat::Text => "txt",
        KeyFormat::Markdown => "md",
        KeyFormat::Latex => "tex",
        KeyFormat::Json => "json",
    };
    let mut files: Vec<(String, String)> = Vec::new();
    // "summary" is the teacher's: no student's report takes its name
    let mut taken: Vec<String> = vec!["summary".into()];
    for (student, list) in students {
        let name = file_name(student.as_deref(), &taken);
        taken.push(name.clone());
        let report = match format {
            KeyFormat::Text => text_report(student.as_deref(), list, true, lang),
            KeyFormat::Markdown => markdown_report(student.as_deref(), list, true, lang),
            KeyFormat::Latex => latex_report(student.as_deref(), list, lang),
            KeyFormat::Json => {
                let answers: Vec<Value> = list.iter().map(|c| answer_json(c)).collect();
                serde_json::to_string_pretty(&answers).unwrap_or_default() + "\n"
            }
        };
        files.push((format!("{name}.{ext}"), report));
    }
    if let Some(s) = summary {
        let text = match format {
            KeyFormat::Text => s.text(lang),
            KeyFormat::Markdown => s.markdown(lang),
            KeyFormat::Latex => s.latex(lang),
            KeyFormat::Json => {
                serde_json::to_string_pretty(&s.to_json()).unwrap_or_default() + "\n"
            }
        };
        files.push((format!("summary.{ext}"), text));
    }
    let mut out = String::new();
    for (name, contents) in &files {
        let path = Path::new(dir).join(name);
        std::fs::write(&path, contents).map_err(|e| {
            CliError::input(CliMessage::CannotWrite {
                path: path.display().to_string(),
                why: e.to_string(),
            })
        })?;
        out += &crate::generate::wrote(&path, lang);
    }
    Ok(out)
}

/// A safe file name for `student`'s report, none of `taken`: the letters, digits, `-`, `_`
/// and `.` of the name (any other character a `_`), without leading dots (never `..`, never
/// hidden), at most 64 characters; `student` when nothing is left; `-2`, `-3`... after a
/// name already taken.
fn file_name(student: Option<&str>, taken: &[String]) -> String {
    let safe: String = student
        .unwrap_or_default()
        .chars()
        .map(|c| match c {
            c if c.is_alphanumeric() || matches!(c, '-' | '_' | '.') => c,
            _ => '_',
        })
        .take(64)
        .collect();
    let safe = safe.trim_start_matches('.');
    let base = if safe.is_empty() || safe.chars().all(|c| c == '_') {
        "student".to_string()
    } else {
        safe.to_string()
    };
    let same = |n: &str| taken.iter().any(|t| t.eq_ignore_ascii_case(n));
    if !same(&base) {
        return base;
    }
    (2..)
        .map(|k| format!("{base}-{k}"))
        .find(|n| !same(n))
        .unwrap_or(base)
}

/// The JSON of one answer: the verdict's with the key's steps and the assessment (what the
/// Python module's `check` gives), and `student`, `file` and `problem` (its place in the file,
/// from 1).
fn answer_json(c: &Checked) -> Value {
    let mut v = c.verdict.to_json(true);
    if let Some(o) = v.as_object_mut() {
        if let Some(s) = &c.student {
            o.insert("student".into(), Value::String(s.clone()));
        }
        o.insert("file".into(), Value::String(c.file.clone()));
        o.insert("problem".into(), Value::from(c.index + 1));
    }
    v
}

/// One student's report as text: the student (when `named`), each answer's key with its
/// diagnosis under `-- file, problem n`, and the count.
fn text_report(student: Option<&str>, list: &[&Checked], named: bool, lang: Lang) -> String {
    let mut text = String::new();
    if named && student.is_some() {
        let heading = CheckWord::Student(student.map(str::to_string));
        text += &format!("=== {} ===\n", escape_text(&heading.phrase(lang).text()));
    }
    for c in list {
        let place = CheckWord::Place {
            file: c.file.clone(),
            problem: c.index + 1,
        };
        text += &format!("-- {}\n", escape_text(&place.phrase(lang).text()));
        text += &example_text_with(&c.verdict, lang, crate::said::raise);
        text.push('\n');
    }
    let wrong = list.iter().filter(|c| !c.verdict.passed()).count();
    text + &count_line(list.len(), wrong, lang)
}

/// One student's report as a Markdown document.
fn markdown_report(student: Option<&str>, list: &[&Checked], named: bool, lang: Lang) -> String {
    let title = CheckWord::Report(student.filter(|_| named).map(str::to_string));
    let sections: Vec<String> = list
        .iter()
        .map(|c| example_markdown_with(&c.verdict, lang, crate::said::raise))
        .collect();
    let legend = legend_markdown(list.iter().map(|c| &c.verdict), lang);
    let wrong = list.iter().filter(|c| !c.verdict.passed()).count();
    markdown_key_document(&title.phrase(lang).text(), &legend, &sections)
        + "\n"
        + &escape_markdown(count_line(list.len(), wrong, lang).trim_end())
        + "\n"
}

/// The LaTeX sections of a student's answers, the count last.
fn latex_sections(list: &[&Checked], lang: Lang) -> Vec<String> {
    let mut sections: Vec<String> = list
        .iter()
        .map(|c| example_latex_with(&c.verdict, lang, crate::said::raise))
        .collect();
    let wrong = list.iter().filter(|c| !c.verdict.passed()).count();
    sections.push(format!(
        "\\bigskip\n{}\n\n",
        escape_latex(count_line(list.len(), wrong, lang).trim_end())
    ));
    sections
}

/// One student's report as a LaTeX document.
fn latex_report(student: Option<&str>, list: &[&Checked], lang: Lang) -> String {
    let title = CheckWord::Report(student.map(str::to_string));
    let legend = legend_latex(list.iter().map(|c| &c.verdict), lang);
    latex_key_document(
        &title.phrase(lang).text(),
        &legend,
        &latex_sections(list, lang),
        lang,
    )
}

/// The words of `cagd check`'s reports, English and Spanish.
#[derive(Debug, Clone, PartialEq)]
enum CheckWord {
    /// The heading of a student's answers.
    Student(Option<String>),
    /// The title of a report: a student's checked answers.
    Report(Option<String>),
    /// Where an answer was read: its file and its place in it.
    Place {
        /// The file.
        file: String,
        /// Its place, from 1.
        problem: usize,
    },
}

impl Message for CheckWord {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            CheckWord::Student(Some(s)) => said(lang, "Student: ‹›", "Alumno: ‹›", [s.into()]),
            CheckWord::Student(None) => said(lang, "Student", "Alumno", []),
            CheckWord::Report(Some(s)) => said(
                lang,
                "Checked answers: ‹›",
                "Respuestas corregidas: ‹›",
                [s.into()],
            ),
            CheckWord::Report(None) => said(lang, "Checked answers", "Respuestas corregidas", []),
            CheckWord::Place { file, problem } => said(
                lang,
                "‹›, problem ‹›",
                "‹›, problema ‹›",
                [file.into(), problem.into()],
            ),
        }
    }
}

/// The last line: `1 problem checked: 1 correct, 0 wrong`, in the language asked, with its
/// plurals.
fn count_line(total: usize, wrong: usize, lang: Lang) -> String {
    let right = total - wrong;
    match lang {
        Lang::En => format!(
            "{total} {} checked: {right} correct, {wrong} wrong\n",
            if total == 1 { "problem" } else { "problems" }
        ),
        Lang::Es => format!(
            "{total} {}: {right} {}, {wrong} {}\n",
            if total == 1 {
                "problema comprobado"
            } else {
                "problemas comprobados"
            },
            if right == 1 { "correcto" } else { "correctos" },
            if wrong == 1 {
                "incorrecto"
            } else {
                "incorrectos"
            },
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_word_is_worded_in_both_languages() {
        for w in [
            CheckWord::Student(Some("Ana".into())),
            CheckWord::Student(None),
            CheckWord::Report(Some("Ana".into())),
            CheckWord::Report(None),
            CheckWord::Place {
                file: "ana.json".into(),
                problem: 2,
            },
        ] {
            assert_eq!(cagd_words::check_both(&w), Ok(()), "{w:?}");
        }
    }

    #[test]
    fn a_student_s_file_name_stays_in_its_folder() {
        let taken = vec!["summary".to_string()];
        assert_eq!(file_name(Some("../x"), &taken), "_x");
        assert_eq!(file_name(Some(".."), &taken), "student");
        assert_eq!(file_name(Some("/etc/passwd"), &taken), "_etc_passwd");
        assert_eq!(file_name(Some("José Pérez"), &taken), "José_Pérez");
        assert_eq!(file_name(Some("summary"), &taken), "summary-2");
        assert_eq!(file_name(None, &taken), "student");
        let taken = vec!["summary".to_string(), "ana".to_string()];
        assert_eq!(file_name(Some("Ana"), &taken), "Ana-2");
    }

    #[test]
    fn the_words_left_out_make_the_same_problem() {
        let mut keys = Keys::default();
        let a = serde_json::json!({"op": "circle", "arcs": 4, "student": "a", "expected": {}});
        let b = serde_json::json!({"arcs": 4, "name": "x", "op": "circle"});
        let c = serde_json::json!({"op": "circle", "arcs": 3});
        assert_eq!(keys.number(&a), 0);
        assert_eq!(keys.number(&b), 0);
        assert_eq!(keys.number(&c), 1);
    }
}
