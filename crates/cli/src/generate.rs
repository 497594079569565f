//! `cagd generate --topic TOPIC --count N --seed S [--out DIR] [--lang en|es]`: problem sets.

use crate::{CliError, Report};
use cagd_exercises::{generate_in, problem_set_files, problems_json, topics, Lang};

/// The help of `cagd generate`.
pub const HELP: &str = "\
Usage: cagd generate --topic TOPIC [--count N] [--seed S] [--out DIR] [--lang en|es]
       cagd generate --list

Random problems for students, with small friendly numbers whose exact answers stay friendly,
one topic of the notes at a time. Prints a JSON array of problems ready for `cagd solve`;
with --out DIR, writes DIR/problems.json and the answer key in every format (key.txt,
key.md, key.tex, key.json). The same topic, count and seed always give the same bytes.
Defaults: --count 10, --seed 1.
";

fn list() -> String {
    topics()
        .iter()
        .map(|t| format!("{:<14} {}\n", t.name, t.description))
        .collect()
}

/// Runs `cagd generate`.
pub fn run(args: &[String]) -> Result<Report, CliError> {
    let (mut topic, mut count, mut seed, mut out, mut lang) = (None, 10usize, 1u64, None, Lang::En);
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        let mut value = |name: &str| {
            it.next()
                .cloned()
                .ok_or_else(|| CliError::Usage(format!("{name} needs a value")))
        };
        match arg.as_str() {
            "-h" | "--help" => return Ok(HELP.to_string().into()),
            "--list" => return Ok(list().into()),
            "--topic" => topic = Some(value("--topic")?),
            "--count" => {
                let v = value("--count")?;
                count = v.parse().map_err(|_| {
                    CliError::Usage(format!("--count takes a whole number, found '{v}'"))
                })?;
            }
            "--seed" => {
                let v = value("--seed")?;
                seed = v.parse().map_err(|_| {
                    CliError::Usage(format!("--seed takes a whole number, found '{v}'"))
                })?;
            }
            "--out" => out = Some(value("--out")?),
            "--lang" => {
                let v = value("--lang")?;
                lang = Lang::parse(&v).ok_or_else(|| {
                    CliError::Usage(format!("unknown language '{v}' (expected en or es)"))
                })?;
            }
            other => return Err(CliError::Usage(format!("unknown option '{other}'"))),
        }
    }
    let topic = topic.ok_or_else(|| {
        CliError::Usage(format!("--topic is required; the topics are:\n{}", list()))
    })?;
    let bad_input = |e: cagd_exercises::ExerciseError| CliError::Input(e.to_string());
    match out {
        None => {
            Ok(problems_json(&generate_in(&topic, count, seed, lang).map_err(bad_input)?).into())
        }
        Some(dir) => {
            let files = problem_set_files(&topic, count, seed, lang).map_err(bad_input)?;
            std::fs::create_dir_all(&dir)
                .map_err(|e| CliError::Input(format!("cannot create {dir}: {e}")))?;
            let mut text = String::new();
            for (name, contents) in files {
                let path = std::path::Path::new(&dir).join(&name);
                std::fs::write(&path, contents).map_err(|e| {
                    CliError::Input(format!("cannot write {}: {e}", path.display()))
                })?;
                text += &format!("wrote {}\n", path.display());
            }
            Ok(text.into())
        }
    }
}
