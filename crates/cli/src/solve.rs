//! `cagd solve FILE|-`: the answer key of one problem or a batch.

use crate::cli::{positive, KeyArgs, KeyFormat, LimitArgs};
use crate::{CliError, Report};
use cagd_keys::{example_latex, example_markdown, example_text, latex_document, markdown_document};
use cagd_problem::{check_batch, Settings, Verdict};
use clap::Args;
use serde_json::Value;
use std::io::Read;

/// The usage line of `cagd solve`.
pub const USAGE: &str =
    "cagd solve FILE|- [--format FORMAT] [--lang LANG] [--steps] [--threads N] [--max-... N]";

/// Answer a problem (or a JSON array of problems) exactly
///
/// Reads one problem (a JSON object) or a batch (a JSON array of problems) from FILE, or from
/// standard input with -, and writes the exact answer key. The format of problems and answers is
/// in docs/format.md. With --steps, the intermediate values the notes show are included.
/// Each problem is answered on its own: a bad problem gets a one-line error naming its index
/// and field, and the others are still answered. Exit code 0 when all were answered, 1 when
/// some failed, 2 for usage errors. A problem past a limit is refused with an error naming
/// the field and the flag that raises it (docs/format.md, Limits).
#[derive(Debug, Clone, Args)]
#[command(verbatim_doc_comment, override_usage = USAGE)]
pub struct SolveArgs {
    /// The problem or batch (a JSON file), or - for standard input
    #[arg(value_name = "FILE|-")]
    pub file: String,
    #[command(flatten)]
    pub key: KeyArgs,
    /// Include the intermediate values the notes show
    #[arg(long)]
    pub steps: bool,
    /// Solve a batch on N threads; the output does not depend on N
    #[arg(long, value_name = "N", default_value_t = 1, allow_negative_numbers = true,
          value_parser = positive("--threads"))]
    pub threads: usize,
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// Reads a JSON document from a file or standard input (`-`).
pub fn read_json(path: &str) -> Result<Value, CliError> {
    let text = if path == "-" {
        let mut s = String::new();
        std::io::stdin()
            .read_to_string(&mut s)
            .map_err(|e| CliError::Input(format!("cannot read standard input: {e}")))?;
        s
    } else {
        std::fs::read_to_string(path)
            .map_err(|e| CliError::Input(format!("cannot read {path}: {e}")))?
    };
    serde_json::from_str(&text).map_err(|e| {
        CliError::Input(format!(
            "{}: not valid JSON at line {}, column {}: {e}",
            if path == "-" { "standard input" } else { path },
            e.line(),
            e.column()
        ))
    })
}

/// The problems of a document, as a list.
pub fn problems(doc: &Value) -> Vec<Value> {
    match doc {
        Value::Array(items) => items.clone(),
        single => vec![single.clone()],
    }
}

/// Runs `cagd solve`.
pub fn run(args: &SolveArgs) -> Result<Report, CliError> {
    let path = &args.file;
    let (format, lang, steps) = (args.key.format, args.key.lang.lang(), args.steps);
    let doc = read_json(path)?;
    let settings = Settings {
        limits: args.limits.limits(),
        steps,
    };
    let mut verdicts: Vec<Verdict> = check_batch(&doc, &settings, args.threads)
        .into_iter()
        .map(LimitArgs::flag_verdict)
        .collect();
    if !steps {
        // a problem whose `expected` names steps was solved with them, to check them
        for v in &mut verdicts {
            if let Ok(a) = &mut v.answer {
                a.steps.clear();
            }
        }
    }
    // a problem that failed, or whose `expected` differs from what was computed
    let code = u8::from(verdicts.iter().any(|v| !v.passed()));
    let text = match format {
        KeyFormat::Json => {
            let items: Vec<Value> = verdicts.iter().map(|v| v.to_json(steps)).collect();
            let out = match (&doc, items.as_slice()) {
                (Value::Array(_), _) => Value::Array(items),
                (_, [one]) => one.clone(),
                _ => Value::Array(items),
            };
            serde_json::to_string_pretty(&out).unwrap_or_default() + "\n"
        }
        format => {
            let sections: Vec<String> = verdicts
                .iter()
                .map(|v| match format {
                    KeyFormat::Latex => example_latex(v, lang),
                    KeyFormat::Markdown => example_markdown(v, lang),
                    _ => example_text(v, lang) + "\n",
                })
                .collect();
            match format {
                KeyFormat::Latex => latex_document(path, &sections, lang),
                KeyFormat::Markdown => markdown_document(path, &sections, lang),
                _ => sections.concat(),
            }
        }
    };
    Ok(Report { text, code })
}
