//! `cagd generate --topic TOPIC --count N --seed S [--out DIR] [--lang en|es]`: problem sets.

use crate::cli::{path, whole, HeaderArgs, LangArgs, PathKind};
use crate::figures::{figure, Figure};
use crate::said::{CliMessage, Said};
use crate::{CliError, Report};
use cagd_exercises::{exam_files, exam_parts, generate_exam, problems_json, topics, SetFigure};
use cagd_keys::Lang;
use cagd_problem::Verdict;
use clap::Args;

/// The usage lines of `cagd generate`.
pub const USAGE: &str =
    "cagd generate --topic TOPIC[:N][,TOPIC[:N]...] [--count N] [--seed S] [--out DIR] [--lang LANG] [--course TEXT] [--title TEXT] [--date TEXT]
       cagd generate --list";

/// A problem set for students, with its answer key
///
/// Random problems for students, with small friendly numbers whose exact answers stay friendly,
/// of one topic of the notes or of several as one exam (--topic coons,revolution:1,interpolate:3:
/// each topic with its own count, or --count problems). Prints a JSON array of problems ready
/// for `cagd solve`; with --out DIR, writes DIR/problems.json, the statement sheet for students
/// (statements.tex: a header with --title, --course, --date and a line for the name, each
/// problem a question and its data, no answer) and the answer key in every format (key.txt,
/// key.md, key.tex, key.json), the LaTeX documents with a figure per problem (DIR/fig) and
/// compiled to PDF when pdflatex is on the PATH. The same topics, counts and seed always give
/// the same problems and keys.
#[derive(Debug, Clone, Args)]
#[command(verbatim_doc_comment, override_usage = USAGE)]
pub struct GenerateArgs {
    /// The topic of the notes (see --list), or several: coons,revolution:1,interpolate:3
    #[arg(long, value_name = "TOPIC[:N],...")]
    pub topic: Option<String>,
    /// How many problems (of each topic without its own :N)
    #[arg(long, value_name = "N", default_value_t = 10, allow_negative_numbers = true,
          value_parser = whole::<usize>("--count"))]
    pub count: usize,
    /// The seed of the random draw
    #[arg(long, value_name = "S", default_value_t = 1, allow_negative_numbers = true,
          value_parser = whole::<u64>("--seed"))]
    pub seed: u64,
    /// Write problems.json and the answer keys to DIR instead of printing the problems
    #[arg(long, value_name = "DIR", value_parser = path("--out", PathKind::Folder))]
    pub out: Option<String>,
    /// List the topics and stop
    #[arg(long)]
    pub list: bool,
    #[command(flatten)]
    pub lang: LangArgs,
    #[command(flatten)]
    pub header: HeaderArgs,
}

fn list() -> String {
    topics()
        .iter()
        .map(|t| format!("{:<14} {}\n", t.name, t.description))
        .collect()
}

/// Runs `cagd generate`, its errors in the language asked.
pub fn run(args: &GenerateArgs) -> Result<Report, CliError> {
    let lang = args.lang.lang();
    run_in(args).map_err(|e| e.in_lang(lang))
}

/// Runs `cagd generate`.
fn run_in(args: &GenerateArgs) -> Result<Report, CliError> {
    if args.list {
        return Ok(list().into());
    }
    let (count, seed, lang) = (args.count, args.seed, args.lang.lang());
    let topic = args
        .topic
        .as_deref()
        .ok_or_else(|| CliError::usage(CliMessage::TopicRequired { topics: list() }))?;
    let bad_input = |e: cagd_exercises::ExerciseError| CliError::Input(Said::from(e));
    let parts = exam_parts(topic, count).map_err(bad_input)?;
    match &args.out {
        None => Ok(problems_json(&generate_exam(&parts, seed, lang).map_err(bad_input)?).into()),
        Some(dir) => write_set(dir, lang, &|draw| {
            exam_files(&parts, seed, lang, &args.header.header(), draw).map_err(bad_input)
        }),
    }
}

/// The files of a set, given how to draw each problem's figure ([`cagd_exercises::sheet_files`]).
pub type SetFiles<'a> = &'a dyn Fn(SetFigure<'_>) -> Result<Vec<(String, String)>, CliError>;

/// Writes a problem set to `dir` (`cagd generate --out` and `cagd sheet` alike): the figures
/// of each problem in DIR/fig (the data for the statement sheet, the answer for the key), the
/// files `files` gives, and the LaTeX documents compiled to PDF when pdflatex is on the PATH.
/// The lines to report, and code 1 when pdflatex failed on a document.
pub fn write_set(dir: &str, lang: Lang, files: SetFiles<'_>) -> Result<Report, CliError> {
    let figures = std::path::Path::new(dir).join("fig");
    let figures = figures.to_string_lossy();
    // each problem's figure, for the statement (the data) and for the key (the answer);
    // the first that cannot be written (DIR/fig is a file, the disk is full) stops the
    // set: nothing else is written, and the error says why (exit code 1)
    let failed: std::cell::RefCell<Option<CliError>> = std::cell::RefCell::new(None);
    let draw = |v: &Verdict, statement: bool| -> Option<String> {
        if failed.borrow().is_some() {
            return None;
        }
        let name = v
            .problem
            .as_ref()
            .and_then(|p| p.meta.name.clone())
            .filter(|n| {
                !n.is_empty()
                    && n.chars()
                        .all(|c| c.is_ascii_alphanumeric() || c == '-' || c == '_')
            })
            .unwrap_or_else(|| format!("{}", v.index.unwrap_or(0) + 1));
        let name = format!("{name}-{}", if statement { "data" } else { "answer" });
        match figure(&figures, &name, v, Figure::Png, lang, statement) {
            Ok(drawn) => drawn?,
            Err(e) => {
                failed.replace(Some(e));
                return None;
            }
        };
        // included relative to DIR, where the documents are
        Some(format!("fig/{name}.png"))
    };
    let files = files(&draw)?;
    if let Some(e) = failed.into_inner() {
        return Err(match e {
            CliError::Input(crate::said::Said::Cli(why)) => {
                CliError::input(CliMessage::SetNotWritten { why })
            }
            other => other,
        });
    }
    std::fs::create_dir_all(dir).map_err(|e| {
        CliError::input(CliMessage::CannotCreate {
            path: dir.to_string(),
            why: e.to_string(),
        })
    })?;
    let mut text = String::new();
    for (name, contents) in &files {
        let path = std::path::Path::new(dir).join(name);
        std::fs::write(&path, contents).map_err(|e| {
            CliError::input(CliMessage::CannotWrite {
                path: path.display().to_string(),
                why: e.to_string(),
            })
        })?;
        text += &wrote(&path, lang);
    }
    let (compiled, failed) = pdfs(dir, &["statements", "key"], lang);
    text += &compiled;
    // a document pdflatex could not compile is a problem set not wholly written
    Ok(Report {
        text,
        code: u8::from(failed),
    })
}

/// Compiles `DIR/NAME.tex` to PDF for each name when pdflatex is on the PATH (without shell
/// escape, whatever the TeX installation allows); the lines to report (the PDFs written, or
/// where pdflatex failed, with its log) and whether pdflatex failed on any.
fn pdfs(dir: &str, names: &[&str], lang: Lang) -> (String, bool) {
    let mut text = String::new();
    let mut failed = false;
    for name in names {
        let run = std::process::Command::new("pdflatex")
            .args([
                "-no-shell-escape",
                "-interaction=nonstopmode",
                "-halt-on-error",
            ])
            .arg(format!("{name}.tex"))
            .current_dir(dir)
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::null())
            .status();
        let path = std::path::Path::new(dir).join(format!("{name}.pdf"));
        match run {
            // no pdflatex: the LaTeX documents are there to compile elsewhere
            Err(_) => return (text, failed),
            Ok(s) if s.success() => {
                for aux in ["aux", "log"] {
                    let _ = std::fs::remove_file(
                        std::path::Path::new(dir).join(format!("{name}.{aux}")),
                    );
                }
                text += &wrote(&path, lang);
            }
            Ok(_) => {
                failed = true;
                let log = std::path::Path::new(dir).join(format!("{name}.log"));
                let failed = CliMessage::PdflatexFailed {
                    document: format!("{name}.tex"),
                    log: log.display().to_string(),
                };
                text += &format!("{}\n", crate::said::Said::from(failed).text(lang));
            }
        }
    }
    (text, failed)
}

/// The line reporting a file written, in `lang` ("wrote DIR/key.tex", "se ha escrito …").
pub fn wrote(path: &std::path::Path, lang: Lang) -> String {
    let m = CliMessage::Wrote {
        path: path.display().to_string(),
    };
    format!("{}\n", crate::said::Said::from(m).text(lang))
}
