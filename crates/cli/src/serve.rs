//! `cagd serve [FILE]`: a problem set served to students on a page where they check their
//! answers, and the teacher's page (cagd-serve).

use crate::cli::{positive, whole, LangArgs, LimitArgs};
use crate::fixtures::FIXTURES;
use crate::said::{CliMessage, Said};
use crate::solve::read_json;
use crate::{CliError, Report};
use cagd_serve::{Config, Reveal, Set};
use clap::{Args, ValueEnum};
use serde_json::Value;
use std::net::{IpAddr, SocketAddr};

/// The usage line of `cagd serve`.
pub const USAGE: &str = "cagd serve [FILE] [--port N] [--bind ADDR] [--token T] [--lang LANG] [--reveal WHEN] [--workers N] [--queue N]";

/// Serve a problem set to students, who check their answers on a web page
///
/// Reads a problem or a JSON array of problems (docs/format.md) from FILE, or an object
/// {"title": ..., "problems": [...]}; without FILE, the worked examples of the notes. Each
/// problem is solved once, with its steps and the answers of the known mistakes; a problem
/// that cannot be solved is named and left out. Then it serves, until Ctrl-C:
///   http://127.0.0.1:8080/         the students' page: each problem's statement and figure,
///                                  a form for the answer, checked exactly, entry by entry,
///                                  with the mistake that explains a wrong answer
///   http://127.0.0.1:8080/teacher  the teacher's page: a problem's key, figure and LaTeX
/// Without --token the teacher's page is open on this computer only (--bind 127.0.0.1, the
/// default); bound to another address without --token, it is off. Nothing is read from or
/// written to disk while it serves.
#[derive(Debug, Clone, Args)]
#[command(verbatim_doc_comment, override_usage = USAGE)]
pub struct ServeArgs {
    /// The problems (a JSON file); without it, the notes' worked examples
    #[arg(value_name = "FILE", value_parser = crate::cli::path("FILE", crate::cli::PathKind::File))]
    pub file: Option<String>,
    /// The port to listen on
    #[arg(long, value_name = "N", default_value_t = 8080, value_parser = whole::<u16>("--port"))]
    pub port: u16,
    /// The address to listen on (0.0.0.0 for every network of this computer)
    #[arg(long, value_name = "ADDR", default_value = "127.0.0.1", value_parser = address)]
    pub bind: IpAddr,
    /// The teacher's token: the teacher's page asks for it (as ?token=T)
    #[arg(long, value_name = "T")]
    pub token: Option<String>,
    #[command(flatten)]
    pub lang: LangArgs,
    /// When a student sees the worked key
    #[arg(long, value_enum, value_name = "WHEN", default_value_t = RevealArg::Never)]
    pub reveal: RevealArg,
    /// How many checks run at once (default: the number of cores)
    #[arg(long, value_name = "N", value_parser = positive("--workers"))]
    pub workers: Option<usize>,
    /// How many requests may wait for a worker (a class of students checking at once); more are
    /// answered "busy"
    #[arg(long, value_name = "N", default_value_t = 256, value_parser = whole::<usize>("--queue"))]
    pub queue: usize,
    #[command(flatten)]
    pub limits: LimitArgs,
}

/// When a student sees the worked key (`--reveal`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, ValueEnum)]
pub enum RevealArg {
    /// Never: the marks and the diagnosis only
    #[default]
    Never,
    /// After each check
    AfterCheck,
}

/// `--bind`: an IP address.
fn address(v: &str) -> Result<IpAddr, CliMessage> {
    v.parse().map_err(|_| CliMessage::NotAnAddress {
        found: v.to_string(),
    })
}

/// The notes' worked examples as a set, in the order of `cagd examples`.
fn examples() -> Result<Set, CliError> {
    let mut problems = Vec::new();
    for (path, text) in crate::examples::in_notes_order(FIXTURES) {
        let fixture: Value = serde_json::from_str(text).map_err(|e| {
            CliError::input(CliMessage::FixtureNotJson {
                path: path.to_string(),
                error: e.to_string(),
            })
        })?;
        problems.push(fixture);
    }
    Ok(Set::from_json(&Value::Array(problems)))
}

/// Runs `cagd serve`, its errors in the language asked.
pub fn run(args: &ServeArgs) -> Result<Report, CliError> {
    let lang = args.lang.lang();
    run_in(args).map_err(|e| e.in_lang(lang))
}

/// Runs `cagd serve`: until Ctrl-C.
fn run_in(args: &ServeArgs) -> Result<Report, CliError> {
    let set = match &args.file {
        Some(f) => Set::from_json(&read_json(f)?),
        None => examples()?,
    };
    let config = Config {
        bind: SocketAddr::new(args.bind, args.port),
        token: args.token.clone(),
        lang: args.lang.lang(),
        reveal: match args.reveal {
            RevealArg::Never => Reveal::Never,
            RevealArg::AfterCheck => Reveal::AfterCheck,
        },
        limits: args.limits.limits(),
        workers: args
            .workers
            .unwrap_or_else(|| std::thread::available_parallelism().map_or(1, usize::from)),
        queue: args.queue,
    };
    cagd_serve::run(&set, &config).map_err(|e| CliError::Input(Said::from(e)))?;
    Ok(String::new().into())
}
