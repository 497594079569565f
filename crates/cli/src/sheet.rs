//! `cagd sheet FILE --out DIR [--lang en|es] [--course TEXT] [--title TEXT] [--date TEXT]`:
//! the statement sheet and the answer keys of a teacher's own problems.

use crate::cli::{path, HeaderArgs, LangArgs, PathKind};
use crate::generate::write_set;
use crate::solve::{problems, read_json};
use crate::{CliError, Report};
use cagd_exercises::sheet_files;
use cagd_keys::error_sentence;
use cagd_problem::{check_batch, Settings, Verdict};
use clap::Args;

/// The usage line of `cagd sheet`.
pub const USAGE: &str =
    "cagd sheet FILE --out DIR [--lang LANG] [--course TEXT] [--title TEXT] [--date TEXT]";

/// A statement sheet and its answer key from your own problems
///
/// Reads a problem or a JSON array of problems (docs/format.md) from FILE and writes to DIR
/// what `cagd generate --out` writes but the problems (FILE is left as it is): the statement
/// sheet for students (statements.tex: a header with --title, --course, --date and a line for
/// the name, each problem a question and its data, without answers), the answer key in every format
/// (key.txt, key.md, key.tex, key.json), a figure per problem (DIR/fig) and the PDFs when
/// pdflatex is on the PATH. A problem that cannot be solved is named with its error and left
/// out; the others are still written (exit code 1).
#[derive(Debug, Clone, Args)]
#[command(verbatim_doc_comment, override_usage = USAGE)]
pub struct SheetArgs {
    /// The problems (a JSON file: one problem or an array), or - for standard input
    #[arg(value_name = "FILE|-", value_parser = path("FILE", PathKind::File))]
    pub file: String,
    /// The folder to write the sheet, the keys and the figures to
    #[arg(long, value_name = "DIR", required = true, value_parser = path("--out", PathKind::Folder))]
    pub out: String,
    #[command(flatten)]
    pub lang: LangArgs,
    #[command(flatten)]
    pub header: HeaderArgs,
}

/// Runs `cagd sheet`, its errors in the language asked.
pub fn run(args: &SheetArgs) -> Result<Report, CliError> {
    let lang = args.lang.lang();
    run_in(args).map_err(|e| e.in_lang(lang))
}

/// Runs `cagd sheet`.
fn run_in(args: &SheetArgs) -> Result<Report, CliError> {
    let lang = args.lang.lang();
    let doc = read_json(&args.file)?;
    let settings = Settings {
        steps: true,
        ..Settings::default()
    };
    let verdicts = check_batch(&doc, &settings, 1);
    let mut kept: (Vec<serde_json::Value>, Vec<Verdict>) = (Vec::new(), Vec::new());
    let mut failures = String::new();
    for (problem, mut verdict) in problems(&doc).into_iter().zip(verdicts) {
        match &verdict.answer {
            Err(e) => {
                let name = problem
                    .get("name")
                    .and_then(|n| n.as_str())
                    .map(|n| format!(" ({n:?})"))
                    .unwrap_or_default();
                failures += &format!("{}{name}\n", error_sentence(e, lang).text);
            }
            Ok(_) => {
                verdict.index = Some(kept.1.len());
                kept.0.push(problem);
                kept.1.push(verdict);
            }
        }
    }
    let header = args.header.header();
    // the teacher's problems are theirs: problems.json is not written over them
    let mut report = write_set(&args.out, lang, &|draw| {
        let mut files = sheet_files(&kept.0, &kept.1, &header, lang, draw);
        files.retain(|(name, _)| name != "problems.json");
        Ok(files)
    })?;
    if !failures.is_empty() {
        report.text = failures + &report.text;
        report.code = 1;
    }
    Ok(report)
}
