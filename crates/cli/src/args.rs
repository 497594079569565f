//! Options shared by the commands that write answer keys.

use crate::CliError;
use cagd_problem::render::Lang;

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
            "--figures" => o.figures = Some(value("--figures")?),
            "--list" => o.list = true,
            _ => o.positional.push(arg.clone()),
        }
    }
    Ok(o)
}
