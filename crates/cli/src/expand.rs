//! `cagd expand EXPR [--format text|latex|json]`: the expanded closed form of an expression.

use crate::{CliError, Output};
use cagd_poly::{parse_expr, Expr};
use serde::Serialize;

/// The help of `cagd expand`.
pub const HELP: &str = "\
Usage: cagd expand EXPR [--format text|latex|json]

Expands a polynomial expression in u, v, w, t, s, x, y, z with exact coefficients (3/4, 0.125,
sqrt2/2) to its closed form. Tuples are points: (1 - v)*(u, 0, u^3) + v*(u, 1, u^2).
Terms are printed by descending total degree, then by higher powers of u, v, ...

Formats:
  text    (default) (u, v, -u^3 v + u^3 + u^2 v)
  latex   \\left(u, v, -u^{3} v + u^{3} + u^{2} v\\right)
  json    {\"expr\": ..., \"closed_form\": ..., \"latex\": ..., \"json\": ...}
          where \"json\" is a form that reads back exactly: (u, v, -u^3*v + u^3 + u^2*v)

An expression starting with '-' goes after `--`: cagd expand -- -u + 1
";

/// The output format.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Format {
    Text,
    Latex,
    Json,
}

impl Format {
    fn parse(s: &str) -> Result<Format, CliError> {
        match s {
            "text" => Ok(Format::Text),
            "latex" => Ok(Format::Latex),
            "json" => Ok(Format::Json),
            other => Err(CliError::Usage(format!(
                "unknown format '{other}' (expected text, latex or json)"
            ))),
        }
    }
}

/// Runs `cagd expand` with the arguments after `expand`.
pub fn run(args: &[String]) -> Result<Output, CliError> {
    let mut format = Format::Text;
    let mut expr: Option<&str> = None;
    let mut only_positional = false;
    let mut i = 0;
    while let Some(arg) = args.get(i).map(String::as_str) {
        if !only_positional && (arg == "-h" || arg == "--help") {
            return Ok(HELP.to_string());
        } else if !only_positional && arg == "--" {
            only_positional = true;
        } else if !only_positional && arg == "--format" {
            i += 1;
            let value = args.get(i).ok_or_else(|| {
                CliError::Usage("--format needs a value: text, latex or json".into())
            })?;
            format = Format::parse(value)?;
        } else if let Some(value) = arg.strip_prefix("--format=").filter(|_| !only_positional) {
            format = Format::parse(value)?;
        } else if !only_positional && arg.starts_with("--") {
            return Err(CliError::Usage(format!(
                "unknown option '{arg}' for expand"
            )));
        } else if expr.is_some() {
            return Err(CliError::Usage(format!(
                "expand takes one expression, found a second one '{arg}' (quote the expression)"
            )));
        } else {
            expr = Some(arg);
        }
        i += 1;
    }
    let text =
        expr.ok_or_else(|| CliError::Usage("expand needs an expression: cagd expand EXPR".into()))?;
    let value = parse_expr(text).map_err(|e| CliError::Input(e.to_string()))?;
    Ok(render(text, &value, format))
}

/// The JSON output of `cagd expand --format json`.
#[derive(Serialize)]
struct ExpandJson<'a> {
    /// The expression as given.
    expr: &'a str,
    /// The expanded closed form, plain text (`(u, v, -u^3 v + u^3 + u^2 v)`).
    closed_form: String,
    /// The closed form in LaTeX.
    latex: String,
    /// The closed form in the grammar, read back exactly by `cagd expand` (`-u^3*v`).
    json: String,
}

/// The output of one expression in one format, with a final newline.
fn render(input: &str, value: &Expr, format: Format) -> String {
    match format {
        Format::Text => format!("{}\n", value.to_text()),
        Format::Latex => format!("{}\n", value.to_latex()),
        Format::Json => {
            let json = ExpandJson {
                expr: input,
                closed_form: value.to_text(),
                latex: value.to_latex(),
                json: value.to_json_string(),
            };
            // a struct of strings always serializes
            format!(
                "{}\n",
                serde_json::to_string_pretty(&json).unwrap_or_default()
            )
        }
    }
}
