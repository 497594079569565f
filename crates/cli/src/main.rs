//! `cagd`, the command line of cagd-exact.
//!
//! One module per subcommand; `main` only dispatches, prints, and maps errors to exit codes:
//! 0 success, 1 bad input (an expression that does not parse...), 2 bad usage.

// Bad input is an error value, never a panic: no unwrap, expect, panic! or indexing that can
// fail in library code (tests may).
#![cfg_attr(
    not(test),
    deny(
        clippy::unwrap_used,
        clippy::expect_used,
        clippy::indexing_slicing,
        clippy::panic
    )
)]

mod args;
mod check;
mod examples;
mod expand;
mod fixtures;
mod generate;
mod render;
mod solve;

use std::ffi::OsString;
use std::io::Write;
use std::process::ExitCode;

/// The list of commands, printed by `cagd help`.
const USAGE: &str = "\
cagd: exact answers for computer-aided geometric design (Bézier, B-spline and NURBS curves and surfaces)

Usage: cagd <COMMAND> [ARGS]

Commands:
  examples [NAME...] [--list] [--format text|latex|markdown|json] [--lang en|es]
                          run every worked example of the notes and check it exactly
  solve FILE|- [--format text|latex|markdown|json] [--steps] [--lang en|es]
        [--threads N] [--max-degree N] [--max-points N] [--max-digits N] ...
                          answer a problem (or a JSON array of problems) exactly
  check FILE...           check the answers a teacher wrote under \"expected\"
  generate --topic TOPIC [--count N] [--seed S] [--out DIR] [--lang en|es]
                          a problem set for students, with its answer key
  render FILE|- --svg OUT.svg [--html OUT.html] [--obj|--stl|--iges OUT] [--steps]
                          figures: SVG, an interactive HTML page, OBJ/STL, IGES
  expand EXPR [--format text|latex|json]
                          expand a polynomial expression to its closed form
  help [COMMAND]          print this list, or the help of one command

Options:
  -h, --help      print this list
  -V, --version   print the version

Exit codes: 0 success, 1 bad input or a failed check (the rest is still answered),
2 bad usage.
";

/// What went wrong, and so which exit code.
#[derive(Debug)]
pub enum CliError {
    /// The command line itself is wrong (exit code 2).
    Usage(String),
    /// The input is wrong: an expression that does not parse... (exit code 1).
    Input(String),
}

/// What a command prints when it ran.
pub type Output = String;

/// What a command printed and how it ended: exit code 0, or 1 when part of the work failed
/// (a problem of a batch, an example that does not reproduce) but the rest was printed.
pub struct Report {
    /// Standard output.
    pub text: String,
    /// The exit code.
    pub code: u8,
}

impl From<Output> for Report {
    fn from(text: Output) -> Self {
        Report { text, code: 0 }
    }
}

fn main() -> ExitCode {
    let args: Vec<OsString> = std::env::args_os().skip(1).collect();
    match run(&args) {
        Ok(report) => {
            let mut stdout = std::io::stdout().lock();
            // a closed pipe (cagd ... | head) is not an error worth a message
            let _ = stdout
                .write_all(report.text.as_bytes())
                .and_then(|()| stdout.flush());
            ExitCode::from(report.code)
        }
        Err(CliError::Input(msg)) => {
            eprintln!("cagd: {msg}");
            ExitCode::from(1)
        }
        Err(CliError::Usage(msg)) => {
            eprintln!("cagd: {msg} (run `cagd help` for the list of commands)");
            ExitCode::from(2)
        }
    }
}

/// Dispatches on the first argument.
fn run(args: &[OsString]) -> Result<Report, CliError> {
    let args = args
        .iter()
        .map(|a| {
            a.to_str()
                .map(str::to_string)
                .ok_or_else(|| CliError::Usage(format!("argument {a:?} is not valid UTF-8")))
        })
        .collect::<Result<Vec<String>, CliError>>()?;
    let Some((command, rest)) = args.split_first() else {
        return Err(CliError::Usage("no command given".into()));
    };
    match command.as_str() {
        "examples" => examples::run(rest),
        "solve" => solve::run(rest),
        "check" => check::run(rest),
        "generate" => generate::run(rest),
        "render" => render::run(rest),
        "expand" => expand::run(rest).map(Report::from),
        "help" | "-h" | "--help" => help(rest).map(Report::from),
        "-V" | "--version" => Ok(format!("cagd {}\n", env!("CARGO_PKG_VERSION")).into()),
        other => Err(CliError::Usage(format!("unknown command '{other}'"))),
    }
}

/// `cagd help [COMMAND]`.
fn help(rest: &[String]) -> Result<Output, CliError> {
    match rest.first().map(String::as_str) {
        None => Ok(USAGE.to_string()),
        Some("expand") => Ok(expand::HELP.to_string()),
        Some("examples") => Ok(examples::HELP.to_string()),
        Some("solve") => Ok(solve::HELP.to_string()),
        Some("check") => Ok(check::HELP.to_string()),
        Some("generate") => Ok(generate::HELP.to_string()),
        Some("render") => Ok(render::HELP.to_string()),
        Some(other) => Err(CliError::Usage(format!(
            "no help for unknown command '{other}'"
        ))),
    }
}
