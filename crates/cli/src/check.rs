//! `cagd check FILE...`: checks a teacher's own answers, written under `"expected"`.

use crate::cli::{path, LangArgs, LimitArgs, PathKind};
use crate::solve::{problems, read_json};
use crate::{CliError, Report};
use cagd_keys::{escape_text, example_text_with, Lang};
use cagd_problem::check_with;
use clap::Args;

/// The usage line of `cagd check`.
pub const USAGE: &str = "cagd check FILE... [--lang LANG] [--max-... N]";

/// Check the answers a teacher wrote under "expected"
///
/// Each FILE holds a problem or a JSON array of problems, each with the answer its author
/// expects under "expected" (same keys as the answer's result: surface, closed_form,
/// points...). The "result" of `cagd solve --format json` (with or without --steps) can be
/// given whole: its results and its "steps" list are compared; its "remarks" and
/// "derivation", words and layout, are read and not compared. Every problem is solved exactly
/// and compared with it; where they differ, the report says where, as `cagd examples` reports
/// the errata of the notes. Exit code 1 if any expected answer is wrong or missing, or names a
/// key that is not a result. The limits and their flags are those of `cagd solve`
/// (docs/format.md, Limits).
#[derive(Debug, Clone, Args)]
#[command(verbatim_doc_comment, override_usage = USAGE)]
pub struct CheckArgs {
    /// The files of problems with their expected answers
    #[arg(value_name = "FILE", required = true, value_parser = path("FILE", PathKind::File))]
    pub files: Vec<String>,
    #[command(flatten)]
    pub lang: LangArgs,
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// Runs `cagd check`, its errors in the language asked.
pub fn run(args: &CheckArgs) -> Result<Report, CliError> {
    let lang = args.lang.lang();
    run_in(args).map_err(|e| e.in_lang(lang))
}

/// Runs `cagd check`.
fn run_in(args: &CheckArgs) -> Result<Report, CliError> {
    let (lang, limits) = (args.lang.lang(), args.limits.limits());
    let (mut text, mut total, mut wrong) = (String::new(), 0usize, 0usize);
    for path in &args.files {
        let doc = read_json(path)?;
        for (i, p) in problems(&doc).iter().enumerate() {
            total += 1;
            let v = check_with(p, &limits).require_expected(p);
            if !v.passed() {
                wrong += 1;
            }
            let file = escape_text(path);
            text += &match lang {
                Lang::En => format!("-- {file}, problem {}\n", i + 1),
                Lang::Es => format!("-- {file}, problema {}\n", i + 1),
            };
            text += &example_text_with(&v, lang, crate::said::raise);
            text.push('\n');
        }
    }
    text += &summary(total, wrong, lang);
    Ok(Report {
        text,
        code: u8::from(wrong > 0),
    })
}

/// The last line: `1 problem checked: 1 correct, 0 wrong`, in the language asked, with its
/// plurals.
fn summary(total: usize, wrong: usize, lang: Lang) -> String {
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
