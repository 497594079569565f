//! `cagd expand EXPR [--format text|latex|json]`: the expanded closed form of an expression.

use crate::said::{CliMessage, Said};
use crate::{CliError, Output};
use cagd_poly::{parse_expr, Expr};
use clap::{Args, ValueEnum};
use serde::Serialize;

/// The usage line of `cagd expand`.
pub const USAGE: &str = "cagd expand EXPR [--parameters R,a,...] [--format text|latex|json]";

/// Expand a polynomial expression to its closed form
///
/// Expands a polynomial expression in u, v, w, t, s, x, y, z with exact coefficients (3/4, 0.125,
/// sqrt2/2) to its closed form. Tuples are points: (1 - v)*(u, 0, u^3) + v*(u, 1, u^2).
/// Terms are printed by descending total degree, then by higher powers of u, v, ...
///
/// Formats:
///   text    (default) (u, v, -u^3 v + u^3 + u^2 v)
///   latex   \left(u, v, -u^{3} v + u^{3} + u^{2} v\right)
///   json    {"expr": ..., "closed_form": ..., "latex": ..., "json": ...}
///           where "json" is a form that reads back exactly: (u, v, -u^3*v + u^3 + u^2*v)
///
/// An expression is one argument: quote it. One starting with '-' may go after `--`:
///   cagd expand -- "-u + 1"
#[derive(Debug, Clone, Args)]
#[command(verbatim_doc_comment, override_usage = USAGE)]
pub struct ExpandArgs {
    /// The expression (quote it)
    #[arg(allow_hyphen_values = true)]
    pub expr: String,
    /// The output format
    #[arg(long, value_enum, value_name = "FORMAT", default_value_t)]
    pub format: Format,
    /// Letters that stand for numbers (comma-separated, one letter each): with
    /// `--parameters a`, `(u + a)^2` expands to `u^2 + 2 a u + a^2`
    #[arg(long, value_name = "LETTERS", value_delimiter = ',')]
    pub parameters: Vec<String>,
}

/// The output format of `cagd expand`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, ValueEnum)]
pub enum Format {
    /// The closed form as text
    #[default]
    Text,
    /// The closed form in LaTeX
    Latex,
    /// The expression, its closed form in text and LaTeX, and a form that reads back exactly
    Json,
}

/// Runs `cagd expand`.
pub fn run(args: &ExpandArgs) -> Result<Output, CliError> {
    let text = args.expr.as_str();
    if !args.parameters.is_empty() {
        return expand_in_letters(text, &args.parameters, args.format);
    }
    let value = parse_expr(text).map_err(|e| {
        CliError::Input(match e {
            cagd_poly::PolyError::UnknownVariable { .. } => {
                Said::from(CliMessage::DeclareParameters {
                    error: e.to_string(),
                })
            }
            e => Said::Engine(Box::new(e.into())),
        })
    })?;
    Ok(render(text, &value, args.format))
}

/// `cagd expand --parameters`: the coefficients may use the declared letters.
fn expand_in_letters(text: &str, letters: &[String], format: Format) -> Result<Output, CliError> {
    let mut names: Vec<cagd_param::Name> = Vec::new();
    for l in letters {
        let mut chars = l.chars();
        let one = matches!((chars.next(), chars.next()), (Some(c), None) if c.is_alphabetic());
        if !one || "uvwtsxyz".contains(l.as_str()) {
            return Err(CliError::input(CliMessage::NotParameter {
                given: format!("{l:?}"),
            }));
        }
        names.push(cagd_param::Name::new(l));
    }
    let value = cagd_param::parse_param_expr(text, &names, &cagd_scalar::Limits::default())
        .map_err(|e| CliError::Input(Said::Engine(Box::new(e.into()))))?;
    let (plain, latex, json) = match &value {
        cagd_param::ParamExpr::Scalar(p) => (p.to_text(), p.to_latex(), p.to_json_string()),
        cagd_param::ParamExpr::Vector(m) => (m.to_text(), m.to_latex(), m.to_json_string()),
    };
    Ok(match format {
        Format::Text => format!("{plain}\n"),
        Format::Latex => format!("{latex}\n"),
        Format::Json => format!(
            "{}\n",
            serde_json::to_string_pretty(&ExpandJson {
                expr: text,
                closed_form: plain,
                latex,
                json,
            })
            .unwrap_or_default()
        ),
    })
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
