//! Options shared by the commands that write answer keys.

use crate::CliError;
use cagd_problem::render::Lang;
use cagd_problem::Limits;

/// The format of an answer key.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KeyFormat {
    /// Plain text (default).
    Text,
    /// A complete LaTeX document.
    Latex,
    /// A Markdown document with `$...$` math.
    Markdown,
    /// JSON.
    Json,
}

/// Options and positional arguments of a command.
pub struct Options {
    pub format: KeyFormat,
    pub lang: Lang,
    pub steps: bool,
    pub list: bool,
    pub figures: Option<String>,
    pub help: bool,
    pub positional: Vec<String>,
    /// The limits of `solve` (`--max-degree`, `--max-points`, ...).
    pub limits: Limits,
    /// Threads for a batch (`--threads`).
    pub threads: usize,
}

/// The flags that raise (or lower) a limit of `solve`.
pub const LIMIT_FLAGS: &[&str] = &[
    "--max-degree",
    "--max-points",
    "--max-digits",
    "--max-batch",
    "--max-depth",
    "--max-exponent",
];

/// A positive integer value of `flag`.
fn positive(flag: &str, v: &str) -> Result<usize, CliError> {
    match v.parse::<usize>() {
        Ok(n) if n > 0 => Ok(n),
        _ => Err(CliError::Usage(format!(
            "{flag} takes a positive integer, found '{v}'"
        ))),
    }
}

/// Reads `--format`, `--lang`, `--steps`, `--list`, `--help`; the rest is positional.
pub fn parse(args: &[String], allowed: &[&str]) -> Result<Options, CliError> {
    let mut o = Options {
        format: KeyFormat::Text,
        lang: Lang::En,
        steps: false,
        list: false,
        figures: None,
        help: false,
        positional: Vec::new(),
        limits: Limits::default(),
        threads: 1,
    };
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        let (flag, inline) = match arg.split_once('=') {
            Some((f, v)) if f.starts_with("--") => (f, Some(v.to_string())),
            _ => (arg.as_str(), None),
        };
        let mut value = |name: &str| -> Result<String, CliError> {
            inline
                .clone()
                .or_else(|| it.next().cloned())
                .ok_or_else(|| CliError::Usage(format!("{name} needs a value")))
        };
        if flag.starts_with('-')
            && flag != "-"
            && !allowed.contains(&flag)
            && flag != "-h"
            && flag != "--help"
        {
            return Err(CliError::Usage(format!("unknown option '{flag}'")));
        }
        match flag {
            "-h" | "--help" => o.help = true,
            "--format" => {
                o.format = match value("--format")?.as_str() {
                    "text" => KeyFormat::Text,
                    "latex" => KeyFormat::Latex,
                    "markdown" | "md" => KeyFormat::Markdown,
                    "json" => KeyFormat::Json,
                    other => {
                        return Err(CliError::Usage(format!(
                            "unknown format '{other}' (expected text, latex, markdown or json)"
                        )))
                    }
                }
            }
            "--lang" => {
                let v = value("--lang")?;
                o.lang = Lang::parse(&v).ok_or_else(|| {
                    CliError::Usage(format!("unknown language '{v}' (expected en or es)"))
                })?;
            }
            "--steps" => o.steps = true,
            "--threads" => o.threads = positive(flag, &value(flag)?)?,
            "--max-degree" => o.limits.max_degree = positive(flag, &value(flag)?)?,
            "--max-points" => o.limits.max_points = positive(flag, &value(flag)?)?,
            "--max-digits" => o.limits.max_digits = positive(flag, &value(flag)?)?,
            "--max-batch" => o.limits.max_batch = positive(flag, &value(flag)?)?,
            "--max-depth" => {
                let n = positive(flag, &value(flag)?)?;
                if n > Limits::DEPTH_CEILING {
                    return Err(CliError::Usage(format!(
                        "--max-depth is at most {}",
                        Limits::DEPTH_CEILING
                    )));
                }
                o.limits.max_depth = n;
            }
            "--max-exponent" => {
                let v = value(flag)?;
                o.limits.max_exponent = u32::try_from(positive(flag, &v)?).map_err(|_| {
                    CliError::Usage(format!("--max-exponent is at most {}", u32::MAX))
                })?;
            }
            "--figures" => o.figures = Some(value("--figures")?),
            "--list" => o.list = true,
            _ => o.positional.push(arg.clone()),
        }
    }
    Ok(o)
}
