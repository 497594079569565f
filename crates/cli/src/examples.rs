//! `cagd examples`: every worked example of the notes, solved and checked exactly.

use crate::cli::{KeyArgs, KeyFormat};
use crate::figures::{figure, Figure};
use crate::fixtures::FIXTURES;
use crate::said::CliMessage;
use crate::{CliError, Report};
use cagd_keys::{
    example_latex, example_markdown, example_text, latex_document, markdown_document,
    markdown_image, Lang,
};
use cagd_problem::{check, check_with_settings, Limits, Settings, Verdict};
use clap::Args;
use serde_json::{json, Value};

/// The usage line of `cagd examples`.
pub const USAGE: &str =
    "cagd examples [NAME...] [--list] [--steps] [--format FORMAT] [--lang LANG] [--figures DIR]";

/// Run every worked example of the notes and check it exactly
///
/// Runs the worked examples of the notes (fixtures/, built into the binary): for each, its name,
/// its source in the notes, the input, the steps the notes show, the exact result and a verdict,
/// `matches the notes` or `erratum: the notes print X, the exact value is Y`. Ends with a summary.
/// With --figures DIR (Markdown and LaTeX), each example's figure is written to DIR (SVG for
/// Markdown, PNG for LaTeX) and included in the key.
/// Exit code 1 if any computed result differs from the exact expectation.
#[derive(Debug, Clone, Args)]
#[command(verbatim_doc_comment, override_usage = USAGE)]
pub struct ExamplesArgs {
    /// Run only these examples: a name, or a prefix such as ch5
    #[arg(value_name = "NAME")]
    pub names: Vec<String>,
    /// Print the names only
    #[arg(long)]
    pub list: bool,
    #[command(flatten)]
    pub key: KeyArgs,
    /// Write each example's figure to DIR and include it in the key (Markdown and LaTeX)
    #[arg(long, value_name = "DIR", value_parser = crate::cli::path("--figures", crate::cli::PathKind::Folder))]
    pub figures: Option<String>,
    /// Show the intermediate values of every example (without it, the steps the notes check)
    #[arg(long)]
    pub steps: bool,
}

/// One loaded example.
struct Example {
    path: &'static str,
    fixture: Value,
}

fn load() -> Result<Vec<Example>, CliError> {
    FIXTURES
        .iter()
        .map(|(path, text)| {
            serde_json::from_str(text)
                .map(|fixture| Example { path, fixture })
                .map_err(|e| {
                    CliError::input(CliMessage::FixtureNotJson {
                        path: path.to_string(),
                        error: e.to_string(),
                    })
                })
        })
        .collect()
}

fn name(e: &Example) -> &str {
    e.fixture
        .get("name")
        .and_then(Value::as_str)
        .unwrap_or(e.path)
}

/// The JSON object of one example: name, source, op, result, matches_notes, errata.
pub fn example_json(fixture: &Value, v: &Verdict) -> Value {
    let s = |k: &str| fixture.get(k).cloned().unwrap_or(Value::Null);
    let (result, error) = match &v.answer {
        Ok(a) => (
            a.to_json(true)
                .get("result")
                .cloned()
                .unwrap_or(Value::Null),
            Value::Null,
        ),
        Err(e) => (Value::Null, json!(e.to_string())),
    };
    json!({
        "name": s("name"),
        "title": s("title"),
        "source": s("source"),
        "equation": s("equation"),
        "op": s("op"),
        "result": result,
        "error": error,
        "passed": v.passed(),
        "mismatches": v.mismatches,
        "matches_notes": v.matches_notes(),
        "errata": v.errata.iter().map(|e| json!({
            "where": e.place, "printed": e.printed, "exact": e.exact, "why": e.why
        })).collect::<Vec<_>>(),
    })
}

/// The summary line: the examples of the notes that match them or have errata, the examples
/// beyond the notes that match their expected answer, and the failures.
fn summary(verdicts: &[Verdict], lang: Lang) -> String {
    let total = verdicts.len();
    let failed = verdicts.iter().filter(|v| !v.passed()).count();
    let errata = verdicts
        .iter()
        .filter(|v| v.passed() && !v.errata.is_empty())
        .count();
    let from_notes = |v: &&Verdict| v.problem.as_ref().is_some_and(|p| p.meta.from_notes());
    let beyond = verdicts
        .iter()
        .filter(|v| v.passed() && v.errata.is_empty() && !from_notes(v))
        .count();
    let matching = total - failed - errata - beyond;
    let n = |k: usize, one: &str, many: &str| format!("{k} {}", if k == 1 { one } else { many });
    match lang {
        // the examples beyond the notes are named only when there are some
        Lang::En => format!(
            "{}: {} the notes, {errata} with errata in the notes (the exact value is kept), {}{failed} failed",
            n(total, "example", "examples"),
            n(matching, "matches", "match"),
            if beyond == 0 {
                String::new()
            } else {
                format!(
                    "{beyond} beyond the notes {} the expected answer, ",
                    if beyond == 1 { "matches" } else { "match" }
                )
            },
        ),
        Lang::Es => format!(
            "{}: {} con los apuntes, {errata} con erratas en los apuntes (se da el valor exacto), {}{}",
            n(total, "ejemplo", "ejemplos"),
            n(matching, "coincide", "coinciden"),
            if beyond == 0 {
                String::new()
            } else {
                format!(
                    "{beyond} fuera de los apuntes {} con la respuesta esperada, ",
                    if beyond == 1 { "coincide" } else { "coinciden" }
                )
            },
            n(failed, "falla", "fallan"),
        ),
    }
}

/// Runs `cagd examples`, its errors in the language asked.
pub fn run(args: &ExamplesArgs) -> Result<Report, CliError> {
    let lang = args.key.lang.lang();
    run_in(args).map_err(|e| e.in_lang(lang))
}

/// Runs `cagd examples`.
fn run_in(args: &ExamplesArgs) -> Result<Report, CliError> {
    let (format, lang) = (args.key.format, args.key.lang.lang());
    let all = load()?;
    let selected: Vec<&Example> = if args.names.is_empty() {
        all.iter().collect()
    } else {
        let chosen: Vec<&Example> = all
            .iter()
            .filter(|e| args.names.iter().any(|n| name(e).starts_with(n.as_str())))
            .collect();
        if chosen.is_empty() {
            return Err(CliError::usage(CliMessage::NoExample {
                names: args.names.join(", "),
            }));
        }
        chosen
    };
    if args.list {
        let mut text = String::new();
        for e in &selected {
            let title = e.fixture.get("title").and_then(Value::as_str).unwrap_or("");
            text += &format!("{:<36} {title}\n", name(e));
        }
        return Ok(text.into());
    }
    let settings = Settings {
        limits: Limits::DEFAULT,
        steps: true,
    };
    let verdicts: Vec<Verdict> = selected
        .iter()
        .map(|e| match args.steps {
            true => check_with_settings(&e.fixture, &settings),
            false => check(&e.fixture),
        })
        .collect();
    let code = u8::from(verdicts.iter().any(|v| !v.passed()));
    let pairs = selected.iter().zip(&verdicts);
    let text = match format {
        KeyFormat::Text => {
            let mut t: String = pairs.map(|(_, v)| example_text(v, lang) + "\n").collect();
            t += &summary(&verdicts, lang);
            t + "\n"
        }
        KeyFormat::Json => {
            let arr: Vec<Value> = pairs.map(|(e, v)| example_json(&e.fixture, v)).collect();
            serde_json::to_string_pretty(&arr).unwrap_or_default() + "\n"
        }
        KeyFormat::Latex => {
            let mut sections = Vec::new();
            for (e, v) in pairs {
                let mut s = example_latex(v, lang);
                if let Some(dir) = &args.figures {
                    // one example a page, its figure (no float) after its text: a figure
                    // never lands beside another example
                    s = format!("\\clearpage\n{s}");
                    if let Some(path) = figure(dir, name(e), v, Figure::Png, lang, false)? {
                        s += &format!(
                            "\\begin{{center}}{}\\end{{center}}\n\n",
                            cagd_keys::tex::graphics(
                                &path,
                                "width=0.55\\textwidth,height=0.5\\textheight,keepaspectratio"
                            )
                        );
                    }
                }
                sections.push(s);
            }
            latex_document(&summary(&verdicts, lang), &sections, lang)
        }
        KeyFormat::Markdown => {
            let mut sections = Vec::new();
            for (e, v) in pairs {
                let mut s = example_markdown(v, lang);
                if let Some(dir) = &args.figures {
                    if let Some(path) = figure(dir, name(e), v, Figure::Svg, lang, false)? {
                        s += &format!("{}\n\n", markdown_image(name(e), &path));
                    }
                }
                sections.push(s);
            }
            markdown_document(&summary(&verdicts, lang), &sections, lang)
        }
    };
    Ok(Report { text, code })
}
