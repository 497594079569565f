//! `cagd examples`: every worked example of the notes, solved and checked exactly.

use crate::cli::{KeyArgs, KeyFormat};
use crate::figures::{figure, Figure};
use crate::fixtures::FIXTURES;
use crate::said::CliMessage;
use crate::{CliError, Report};
use cagd_keys::{
    example_latex_beside, example_markdown, example_text, latex_key_document, legend_latex,
    legend_markdown, legend_text, markdown_image, markdown_key_document, Lang,
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

/// The place of a fixture's folder in a key of the examples: the notes' order (chapter 5,
/// chapter 6, the slides of chapter 6), then the examples beyond the notes.
fn notes_order(path: &str) -> usize {
    const FOLDERS: [&str; 5] = ["ch5/", "ch6/", "slides/", "beyond/", "triangle/"];
    FOLDERS
        .iter()
        .position(|f| path.starts_with(f))
        .unwrap_or(FOLDERS.len())
}

/// The fixtures (path, text) in the notes' order ([`notes_order`]), each folder in the order
/// of its files: the order of `cagd examples` and `cagd serve`.
pub fn in_notes_order(
    fixtures: &[(&'static str, &'static str)],
) -> Vec<(&'static str, &'static str)> {
    let mut out = fixtures.to_vec();
    out.sort_by_key(|(path, _)| (notes_order(path), *path));
    out
}

/// The worked examples, in the notes' order ([`notes_order`]), each folder in the order of its
/// files (numbered as in the notes).
fn load() -> Result<Vec<Example>, CliError> {
    in_notes_order(FIXTURES)
        .into_iter()
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

/// An example's title in the language asked (its name when it has none): the alternative text
/// of its figure.
fn example_title(e: &Example, lang: Lang) -> String {
    let title = |v: &Value| v.get("title").and_then(Value::as_str).map(str::to_string);
    let es = e.fixture.get("es").and_then(title);
    match lang {
        Lang::Es => es.or_else(|| title(&e.fixture)),
        Lang::En => title(&e.fixture),
    }
    .unwrap_or_else(|| name(e).to_string())
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

/// The title of the key of the notes' examples.
fn title(lang: Lang) -> &'static str {
    match lang {
        Lang::En => "Solutions to the worked examples of the notes (chapters 5 and 6)",
        Lang::Es => "Soluciones de los ejemplos de los apuntes (temas 5 y 6)",
    }
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
            let mut t = format!("{}\n\n{}", title(lang), legend_text(&verdicts, lang));
            t += &pairs
                .map(|(_, v)| example_text(v, lang) + "\n")
                .collect::<String>();
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
                let path = match &args.figures {
                    Some(dir) => figure(dir, name(e), v, Figure::Png, lang, false)?,
                    None => None,
                };
                // the figure (no float) beside its example's data: never on a page of its own,
                // never beside another example
                sections.push(example_latex_beside(v, lang, path.as_deref()));
            }
            latex_key_document(title(lang), &legend_latex(&verdicts, lang), &sections, lang)
        }
        KeyFormat::Markdown => {
            let mut sections = Vec::new();
            for (e, v) in pairs {
                let mut s = example_markdown(v, lang);
                if let Some(dir) = &args.figures {
                    if let Some(path) = figure(dir, name(e), v, Figure::Svg, lang, false)? {
                        s += &format!("{}\n\n", markdown_image(&example_title(e, lang), &path));
                    }
                }
                sections.push(s);
            }
            markdown_key_document(title(lang), &legend_markdown(&verdicts, lang), &sections)
        }
    };
    Ok(Report { text, code })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The key of the examples follows the notes: chapter 5, chapter 6, the slides, then the
    /// examples beyond the notes (beyond/, triangle/), each folder in its numbered order.
    #[test]
    fn the_examples_in_the_notes_order() -> Result<(), CliError> {
        let folders: Vec<&str> = load()?
            .iter()
            .map(|e| e.path.split('/').next().unwrap_or_default())
            .collect();
        let mut runs = folders.clone();
        runs.dedup();
        assert_eq!(runs, ["ch5", "ch6", "slides", "beyond", "triangle"]);
        let paths: Vec<&str> = load()?.iter().map(|e| e.path).collect();
        assert!(paths[0].starts_with("ch5/01-"), "{paths:?}");
        for pair in paths.windows(2) {
            if pair[0].split('/').next() == pair[1].split('/').next() {
                assert!(pair[0] < pair[1], "{pair:?}");
            }
        }
        Ok(())
    }
}
