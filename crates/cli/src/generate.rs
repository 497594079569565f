//! `cagd generate --topic TOPIC --count N --seed S [--out DIR] [--lang en|es]`: problem sets.

use crate::cli::{whole, LangArgs};
use crate::{CliError, Report};
use cagd_exercises::{generate_in, problem_set_files, problems_json, topics};
use clap::Args;

/// The usage lines of `cagd generate`.
pub const USAGE: &str =
    "cagd generate --topic TOPIC [--count N] [--seed S] [--out DIR] [--lang LANG]
       cagd generate --list";

/// A problem set for students, with its answer key
///
/// Random problems for students, with small friendly numbers whose exact answers stay friendly,
/// one topic of the notes at a time. Prints a JSON array of problems ready for `cagd solve`;
/// with --out DIR, writes DIR/problems.json and the answer key in every format (key.txt,
/// key.md, key.tex, key.json). The same topic, count and seed always give the same bytes.
#[derive(Debug, Clone, Args)]
#[command(verbatim_doc_comment, override_usage = USAGE)]
pub struct GenerateArgs {
    /// The topic of the notes (see --list)
    #[arg(long)]
    pub topic: Option<String>,
    /// How many problems
    #[arg(long, value_name = "N", default_value_t = 10, allow_negative_numbers = true,
          value_parser = whole::<usize>("--count"))]
    pub count: usize,
    /// The seed of the random draw
    #[arg(long, value_name = "S", default_value_t = 1, allow_negative_numbers = true,
          value_parser = whole::<u64>("--seed"))]
    pub seed: u64,
    /// Write problems.json and the answer keys to DIR instead of printing the problems
    #[arg(long, value_name = "DIR")]
    pub out: Option<String>,
    /// List the topics and stop
    #[arg(long)]
    pub list: bool,
    #[command(flatten)]
    pub lang: LangArgs,
}

fn list() -> String {
    topics()
        .iter()
        .map(|t| format!("{:<14} {}\n", t.name, t.description))
        .collect()
}

/// Runs `cagd generate`.
pub fn run(args: &GenerateArgs) -> Result<Report, CliError> {
    if args.list {
        return Ok(list().into());
    }
    let (count, seed, lang) = (args.count, args.seed, args.lang.lang());
    let topic = args.topic.as_deref().ok_or_else(|| {
        CliError::Usage(format!("--topic is required; the topics are:\n{}", list()))
    })?;
    let bad_input = |e: cagd_exercises::ExerciseError| CliError::Input(e.to_string());
    match &args.out {
        None => {
            Ok(problems_json(&generate_in(topic, count, seed, lang).map_err(bad_input)?).into())
        }
        Some(dir) => {
            let files = problem_set_files(topic, count, seed, lang).map_err(bad_input)?;
            std::fs::create_dir_all(dir)
                .map_err(|e| CliError::Input(format!("cannot create {dir}: {e}")))?;
            let mut text = String::new();
            for (name, contents) in files {
                let path = std::path::Path::new(dir).join(&name);
                std::fs::write(&path, contents).map_err(|e| {
                    CliError::Input(format!("cannot write {}: {e}", path.display()))
                })?;
                text += &format!("wrote {}\n", path.display());
            }
            Ok(text.into())
        }
    }
}
