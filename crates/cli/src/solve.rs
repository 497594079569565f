//! `cagd solve FILE|-`: the answer key of one problem or a batch.

use crate::args::{self, KeyFormat};
use crate::{CliError, Report};
use cagd_problem::render::{
    example_latex, example_markdown, example_text, latex_document, markdown_document,
};
use cagd_problem::{check_batch, error_json, Settings, Verdict};
use serde_json::Value;
use std::io::Read;

/// The help of `cagd solve`.
pub const HELP: &str = "\
Usage: cagd solve FILE|- [--format text|latex|markdown|json] [--steps] [--lang en|es]
                  [--threads N] [--max-degree N] [--max-points N] [--max-digits N]
                  [--max-batch N] [--max-depth N] [--max-exponent N]

Reads one problem (a JSON object) or a batch (a JSON array of problems) from FILE, or from
standard input with -, and writes the exact answer key. The format of problems and answers is
in docs/format.md. With --steps, the intermediate values the notes show are included.
Each problem is answered on its own: a bad problem gets a one-line error naming its index
and field, and the others are still answered. Exit code 0 when all were answered, 1 when
some failed, 2 for usage errors.

Limits (docs/format.md, Limits): a problem past one is refused with an error naming the
field and the flag that raises it.
  --max-degree N    degree of a curve or surface, given or computed (default 50)
  --max-points N    items of a list, points of a mesh, given or computed (default 1000)
  --max-digits N    digits of a number (default 1000)
  --max-batch N     problems of a batch; those past it are not solved (default 10000)
  --max-depth N     nesting of an expression (default 200, at most 1000)
  --max-exponent N  |e| in x^e (default 1000)
  --threads N       solve a batch on N threads; the output does not depend on N (default 1)
";

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
pub fn run(args: &[String]) -> Result<Report, CliError> {
    let mut allowed = vec!["--format", "--lang", "--steps", "--threads"];
    allowed.extend_from_slice(args::LIMIT_FLAGS);
    let o = args::parse(args, &allowed)?;
    if o.help {
        return Ok(HELP.to_string().into());
    }
    let [path] = o.positional.as_slice() else {
        return Err(CliError::Usage(
            "solve takes one FILE (or - for standard input)".into(),
        ));
    };
    let doc = read_json(path)?;
    let settings = Settings {
        limits: o.limits,
        steps: o.steps,
    };
    let mut verdicts = check_batch(&doc, &settings, o.threads);
    if !o.steps {
        // a problem whose `expected` names steps was solved with them, to check them
        for v in &mut verdicts {
            if let Ok(a) = &mut v.answer {
                a.steps.clear();
            }
        }
    }
    // a problem that failed, or whose `expected` differs from what was computed
    let code = u8::from(verdicts.iter().any(|v| !v.passed()));
    let text = match o.format {
        KeyFormat::Json => {
            let items: Vec<Value> = verdicts.iter().map(|v| answer_json(v, o.steps)).collect();
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
                    KeyFormat::Latex => example_latex(v, o.lang),
                    KeyFormat::Markdown => example_markdown(v, o.lang),
                    _ => example_text(v, o.lang) + "\n",
                })
                .collect();
            match format {
                KeyFormat::Latex => latex_document(path, &sections, o.lang),
                KeyFormat::Markdown => markdown_document(path, &sections, o.lang),
                _ => sections.concat(),
            }
        }
    };
    Ok(Report { text, code })
}

/// The JSON answer of one problem; a problem that says what to expect also gets `passed` and
/// its `mismatches`.
fn answer_json(v: &Verdict, steps: bool) -> Value {
    let mut out = match &v.answer {
        Ok(a) => a.to_json(steps),
        Err(e) => return error_json(e),
    };
    if v.checked {
        if let Some(obj) = out.as_object_mut() {
            obj.insert("passed".into(), Value::Bool(v.passed()));
            obj.insert("mismatches".into(), serde_json::json!(v.mismatches));
        }
    }
    out
}
