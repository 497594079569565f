//! `cagd solve FILE|-`: the answer key of one problem or a batch.

use crate::cli::{path, positive, KeyArgs, KeyFormat, LimitArgs, PathKind};
use crate::elements::Elements;
use crate::encoding::{self, NotUtf8};
use crate::said::{raise, CliMessage, Input, Io};
use crate::CliError;
use cagd_keys::{
    example_latex_with, example_markdown_with, example_text_with, latex_key_document, legend_latex,
    legend_markdown, legend_text, markdown_key_document, Word,
};
use cagd_problem::{check_stream, Settings, Verdict, VerdictJson};
use clap::Args;
use serde_json::value::RawValue;
use serde_json::Value;
use std::io::{BufRead, Read, Write};

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
    #[arg(value_name = "FILE|-", value_parser = path("FILE", PathKind::File))]
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

/// The UTF-8 byte-order mark some editors write at the start of a file.
const BOM: &[u8] = b"\xEF\xBB\xBF";

/// Reads the bytes of a file or of standard input (`-`), without a UTF-8 byte-order mark.
pub fn read_input(path: &str) -> Result<Vec<u8>, CliError> {
    let mut bytes = if path == "-" {
        let mut b = Vec::new();
        std::io::stdin()
            .read_to_end(&mut b)
            .map_err(|e| cannot_read(path, &e))?;
        b
    } else {
        std::fs::read(path).map_err(|e| cannot_read(path, &e))?
    };
    if bytes.starts_with(BOM) {
        bytes.drain(..BOM.len());
    }
    Ok(bytes)
}

/// The error of an input (a file, or standard input: `-`) that cannot be read.
fn cannot_read(path: &str, e: &std::io::Error) -> CliError {
    CliError::input(match path {
        "-" => CliMessage::CannotReadStdin { why: e.to_string() },
        _ => CliMessage::CannotRead {
            path: path.to_string(),
            why: Io::of(e),
        },
    })
}

/// The error of a document that is not JSON.
fn invalid_json(path: &str, e: &serde_json::Error) -> CliError {
    CliError::input(CliMessage::NotJson {
        input: Input::of(path),
        line: e.line(),
        column: e.column(),
        error: e.to_string(),
    })
}

/// The error of a document that is not UTF-8: what it looks like, and to save it as UTF-8.
fn not_utf8(path: &str, e: &NotUtf8) -> CliError {
    CliError::input(e.message(path))
}

/// Reads a JSON document from a file or standard input (`-`); a document that is not UTF-8
/// (UTF-16, Latin-1...) is refused as such.
pub fn read_json(path: &str) -> Result<Value, CliError> {
    let bytes = read_input(path)?;
    let text = encoding::utf8(&bytes, 1, 1).map_err(|e| not_utf8(path, &e))?;
    serde_json::from_str(text).map_err(|e| invalid_json(path, &e))
}

/// The problems of a document, as a list.
pub fn problems(doc: &Value) -> Vec<Value> {
    match doc {
        Value::Array(items) => items.clone(),
        single => vec![single.clone()],
    }
}

/// Runs `cagd solve`, its errors in the language asked.
pub fn run(args: &SolveArgs, out: &mut dyn Write) -> Result<u8, CliError> {
    let lang = args.key.lang.lang();
    run_in(args, out).map_err(|e| e.in_lang(lang))
}

/// The input of `cagd solve`: a file, or standard input (`-`), buffered.
fn open_input(path: &str) -> Result<Box<dyn BufRead + Send>, CliError> {
    if path == "-" {
        return Ok(Box::new(std::io::BufReader::with_capacity(
            1 << 16,
            std::io::stdin(),
        )));
    }
    let file = std::fs::File::open(path).map_err(|e| cannot_read(path, &e))?;
    Ok(Box::new(std::io::BufReader::with_capacity(1 << 16, file)))
}

/// What a document starts with: a batch, read element by element from where its `[` ends, or
/// one problem, read whole.
enum Document {
    Batch(Elements<Box<dyn BufRead + Send>>),
    One(Vec<u8>),
}

/// Reads the start of the input (a UTF-8 byte-order mark and white space skipped): a batch
/// when it begins with `[`. An input in UTF-16 or UTF-32 is refused as such from its first
/// bytes.
fn open_document(path: &str) -> Result<Document, CliError> {
    let cannot = |e: std::io::Error| cannot_read(path, &e);
    let mut input = open_input(path)?;
    if let Some(encoding) = encoding::wide(input.fill_buf().map_err(cannot)?) {
        return Err(not_utf8(path, &NotUtf8 { encoding, at: None }));
    }
    let mut skipped = Vec::new();
    let (mut line, mut column) = (1, 1);
    loop {
        let buf = input.fill_buf().map_err(cannot)?;
        if skipped.is_empty() && buf.starts_with(BOM) {
            input.consume(BOM.len());
            continue;
        }
        match buf.first().copied() {
            Some(b @ (b' ' | b'\t' | b'\n' | b'\r')) => {
                input.consume(1);
                skipped.push(b);
                if b == b'\n' {
                    (line, column) = (line + 1, 1);
                } else {
                    column += 1;
                }
            }
            Some(b'[') => {
                input.consume(1);
                return Ok(Document::Batch(Elements::new(input, line, column + 1)));
            }
            _ => break,
        }
    }
    input.read_to_end(&mut skipped).map_err(cannot)?;
    Ok(Document::One(skipped))
}

/// Runs `cagd solve`, writing the answers to `out` as they are computed: a batch is read
/// element by element (a problem, once its text is known to be JSON, is handed to a solver
/// thread, read, solved, written and dropped), on `--threads` (at most 64 problems per
/// thread ahead of the output), and each answer is written in the order of the problems, so
/// memory does not grow with the batch (LaTeX and Markdown documents, which wrap all their
/// sections, excepted). A syntax error in a batch stops it there: the problems before it are
/// answered (a JSON batch is closed), then the error names its line, column and problem.
/// Returns the exit code: 1 when a problem failed or differs from its `expected`.
fn run_in(args: &SolveArgs, out: &mut dyn Write) -> Result<u8, CliError> {
    let path = &args.file;
    let (format, lang, steps) = (args.key.format, args.key.lang.lang(), args.steps);
    let document = open_document(path)?;
    let batch = matches!(document, Document::Batch(_));
    let settings = Settings {
        limits: args.limits.limits(),
        steps,
    };
    // each verdict is written out on its solver thread: whether it passed, and its text
    let each = |mut v: Verdict| -> (bool, Vec<u8>, String) {
        if !batch {
            // one problem, not a batch: no index to name
            if let Err(e) = &mut v.answer {
                e.index = None;
            }
            v.index = None;
        }
        if !steps {
            // a problem whose `expected` names steps was solved with them, to check them
            if let Ok(a) = &mut v.answer {
                a.steps.clear();
            }
        }
        // the notation legend its worked solution needs, said once a document (in the sink)
        let legend = match format {
            KeyFormat::Json => String::new(),
            KeyFormat::Latex => legend_latex([&v], lang),
            KeyFormat::Markdown => legend_markdown([&v], lang),
            _ => legend_text([&v], lang),
        };
        let text = match format {
            KeyFormat::Json => verdict_json(&v, steps, batch),
            KeyFormat::Latex => example_latex_with(&v, lang, raise).into_bytes(),
            KeyFormat::Markdown => example_markdown_with(&v, lang, raise).into_bytes(),
            _ => (example_text_with(&v, lang, raise) + "\n").into_bytes(),
        };
        (v.passed(), text, legend)
    };
    let mut failed = false;
    let mut count = 0usize;
    let mut sections: Vec<String> = Vec::new();
    let json = matches!(format, KeyFormat::Json);
    if json && batch {
        match out.write_all(b"[") {
            Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => return Ok(0),
            other => other.map_err(CliError::Output)?,
        }
    }
    let mut legends: Vec<String> = Vec::new();
    let sink = |(passed, text, legend): (bool, Vec<u8>, String)| {
        failed |= !passed;
        let new_legend = !legend.is_empty() && !legends.contains(&legend);
        if new_legend {
            legends.push(legend.clone());
        }
        match format {
            KeyFormat::Latex | KeyFormat::Markdown => {
                sections.push(String::from_utf8_lossy(&text).into_owned());
                Ok(())
            }
            KeyFormat::Json if batch => {
                out.write_all(if count == 0 { b"\n  " } else { b",\n  " })?;
                count += 1;
                out.write_all(&text)
            }
            _ => {
                if new_legend {
                    out.write_all(legend.as_bytes())?;
                }
                out.write_all(&text)
            }
        }
    };
    let mut syntax = None;
    let streamed = match document {
        Document::Batch(mut elements) => {
            let streamed = check_stream(elements.by_ref(), &settings, args.threads, each, sink);
            syntax = elements.error;
            streamed
        }
        Document::One(bytes) => {
            // the whole document is checked first: a syntax error answers nothing
            let text = encoding::utf8(&bytes, 1, 1).map_err(|e| not_utf8(path, &e))?;
            let doc: &RawValue = serde_json::from_str(text).map_err(|e| invalid_json(path, &e))?;
            check_stream([doc], &settings, 1, each, sink)
        }
    };
    // a closed pipe (`cagd solve b.json | head`) stops the batch quietly, with the exit code
    // of the problems answered until then
    let closed = |e: std::io::Error| match e.kind() {
        std::io::ErrorKind::BrokenPipe => Ok(u8::from(failed)),
        _ => Err(CliError::Output(e)),
    };
    if let Err(e) = streamed {
        return closed(e);
    }
    let tail: Vec<u8> = match format {
        KeyFormat::Json if batch && count > 0 => b"\n]\n".to_vec(),
        KeyFormat::Json if batch => b"]\n".to_vec(),
        KeyFormat::Json => b"\n".to_vec(),
        KeyFormat::Latex => {
            latex_key_document(&lang.word("Answer key"), &legends.concat(), &sections, lang)
                .into_bytes()
        }
        KeyFormat::Markdown => {
            markdown_key_document(&lang.word("Answer key"), &legends.concat(), &sections)
                .into_bytes()
        }
        _ => Vec::new(),
    };
    if let Err(e) = out.write_all(&tail) {
        return closed(e);
    }
    if let Some(e) = syntax {
        return Err(CliError::input(CliMessage::NotJsonInBatch {
            input: Input::of(path),
            line: e.line,
            column: e.column,
            problem: e.element + 1,
            error: e.message,
        }));
    }
    Ok(u8::from(failed))
}

/// The pretty JSON of one verdict (as `serde_json::to_string_pretty` writes it); inside a
/// batch, indented one level further. The error of a problem past a limit says, in English,
/// the flag that raises it.
fn verdict_json(v: &Verdict, steps: bool, nested: bool) -> Vec<u8> {
    if let Err(e) = &v.answer {
        if let Some(r) = e.limit.and_then(raise) {
            return error_json(&format!("{e} {r}"), nested);
        }
    }
    let mut buf = Vec::with_capacity(4096);
    VerdictJson { verdict: v, steps }.write_pretty(&mut buf, usize::from(nested));
    buf
}

/// The pretty JSON of a failed problem, `{"ok": false, "error": ...}`, as
/// `serde_json::to_string_pretty` writes it; inside a batch, indented one level further.
fn error_json(error: &str, nested: bool) -> Vec<u8> {
    #[derive(serde::Serialize)]
    struct ErrorJson<'a> {
        ok: bool,
        error: &'a str,
    }
    // a struct of a bool and a string always serializes
    let text = serde_json::to_string_pretty(&ErrorJson { ok: false, error }).unwrap_or_default();
    match nested {
        true => text.replace('\n', "\n  ").into_bytes(),
        false => text.into_bytes(),
    }
}
