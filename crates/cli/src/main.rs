//! `cagd`, the command line of cagd-exact.
//!
//! One module per subcommand; `main` only dispatches, prints, and maps errors to exit codes:
//! 0 success, 1 bad input (an expression that does not parse...), 2 bad usage.

mod expand;

use std::ffi::OsString;
use std::io::Write;
use std::process::ExitCode;

/// The list of commands, printed by `cagd help`.
const USAGE: &str = "\
cagd: exact answers for computer-aided geometric design (Bézier, B-spline and NURBS curves and surfaces)

Usage: cagd <COMMAND> [ARGS]

Commands:
  expand EXPR [--format text|latex|json]   expand a polynomial expression to its closed form
  help [COMMAND]                           print this list, or the help of one command

Options:
  -h, --help      print this list
  -V, --version   print the version

Exit codes: 0 success, 1 bad input, 2 bad usage.
";

/// What went wrong, and so which exit code.
#[derive(Debug)]
pub enum CliError {
    /// The command line itself is wrong (exit code 2).
    Usage(String),
    /// The input is wrong: an expression that does not parse... (exit code 1).
    Input(String),
}

/// What a command prints on success.
pub type Output = String;

fn main() -> ExitCode {
    let args: Vec<OsString> = std::env::args_os().skip(1).collect();
    match run(&args) {
        Ok(out) => {
            let mut stdout = std::io::stdout().lock();
            // a closed pipe (cagd ... | head) is not an error worth a message
            let _ = stdout
                .write_all(out.as_bytes())
                .and_then(|()| stdout.flush());
            ExitCode::SUCCESS
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
fn run(args: &[OsString]) -> Result<Output, CliError> {
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
        "expand" => expand::run(rest),
        "help" | "-h" | "--help" => help(rest),
        "-V" | "--version" => Ok(format!("cagd {}\n", env!("CARGO_PKG_VERSION"))),
        other => Err(CliError::Usage(format!("unknown command '{other}'"))),
    }
}

/// `cagd help [COMMAND]`.
fn help(rest: &[String]) -> Result<Output, CliError> {
    match rest.first().map(String::as_str) {
        None => Ok(USAGE.to_string()),
        Some("expand") => Ok(expand::HELP.to_string()),
        Some(other) => Err(CliError::Usage(format!(
            "no help for unknown command '{other}'"
        ))),
    }
}
