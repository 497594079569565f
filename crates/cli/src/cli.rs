//! The command line: one clap parser, its subcommands, and the flags several of them share.
//!
//! Each subcommand's own flags live beside its logic (`solve::SolveArgs`, ...); the flags shared
//! by several commands are the [`KeyArgs`], [`LangArgs`] and [`LimitArgs`] groups here, flattened
//! into the commands that take them.

use crate::said::CliMessage;
use crate::{check, completions, examples, expand, generate, render, serve, sheet, solve};
use cagd_keys::Lang;
use cagd_problem::{Limit, Limits};
use clap::{Args, CommandFactory, FromArgMatches, Parser, Subcommand, ValueEnum};
use std::ffi::OsString;
use std::time::Duration;

/// How the help of every subcommand is laid out: its usage first, then what it does.
const SUBCOMMAND_HELP: &str = "\
{usage-heading} {usage}

{about-with-newline}
{all-args}{after-help}";

/// cagd: exact answers for computer-aided geometric design (Bézier, B-spline and NURBS curves
/// and surfaces)
#[derive(Debug, Parser)]
#[command(
    name = "cagd",
    bin_name = "cagd",
    version,
    subcommand_required = true,
    arg_required_else_help = false,
    after_help = "Run `cagd help COMMAND` (or `cagd COMMAND --help`) for the options of one command.\n\
                  Exit codes: 0 success, 1 bad input or a failed check (the rest is still answered),\n\
                  2 bad usage. A closed pipe (`cagd examples | head`) ends quietly, with the code of\n\
                  the work done until then."
)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands; the help of each is the doc comment of its arguments struct.
#[derive(Debug, Subcommand)]
pub enum Command {
    Examples(examples::ExamplesArgs),
    Solve(solve::SolveArgs),
    Check(check::CheckArgs),
    Generate(generate::GenerateArgs),
    Sheet(sheet::SheetArgs),
    Serve(serve::ServeArgs),
    Render(render::RenderArgs),
    Expand(expand::ExpandArgs),
    Completions(completions::CompletionsArgs),
}

/// The format of an answer key (`--format`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, ValueEnum)]
pub enum KeyFormat {
    /// Plain text
    #[default]
    Text,
    /// A complete LaTeX document
    Latex,
    /// A Markdown document with `$...$` math
    #[value(alias = "md")]
    Markdown,
    /// JSON
    Json,
}

/// The language of an answer key (`--lang`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, ValueEnum)]
pub enum LangArg {
    /// English
    #[default]
    En,
    /// Spanish, with the notes' vocabulary (malla de control, pesos, bigrado, nudos)
    Es,
}

impl From<LangArg> for Lang {
    fn from(l: LangArg) -> Lang {
        match l {
            LangArg::En => Lang::En,
            LangArg::Es => Lang::Es,
        }
    }
}

/// `--lang`.
#[derive(Debug, Clone, Copy, Args)]
pub struct LangArgs {
    /// The language of the text
    #[arg(long, value_enum, value_name = "LANG", default_value_t)]
    pub lang: LangArg,
}

impl LangArgs {
    /// The language chosen.
    pub fn lang(&self) -> Lang {
        self.lang.into()
    }
}

/// The header of a statement sheet: `--course`, `--title`, `--date` (each written as typed,
/// as text).
#[derive(Debug, Clone, Default, Args)]
pub struct HeaderArgs {
    /// The course, under the title of the statement sheet
    #[arg(long, value_name = "TEXT")]
    pub course: Option<String>,
    /// The title of the statement sheet (default: Problem sheet, Hoja de problemas)
    #[arg(long, value_name = "TEXT")]
    pub title: Option<String>,
    /// The date, under the title of the statement sheet
    #[arg(long, value_name = "TEXT")]
    pub date: Option<String>,
}

impl HeaderArgs {
    /// The header these flags set.
    pub fn header(&self) -> cagd_keys::SheetHeader {
        cagd_keys::SheetHeader {
            course: self.course.clone(),
            title: self.title.clone(),
            date: self.date.clone(),
        }
    }
}

/// The flags of an answer key: `--format` and `--lang`.
#[derive(Debug, Clone, Copy, Args)]
pub struct KeyArgs {
    /// The format of the answer key (md is markdown)
    #[arg(long, value_enum, value_name = "FORMAT", default_value_t)]
    pub format: KeyFormat,
    #[command(flatten)]
    pub lang: LangArgs,
}

/// The limits a problem is read and solved under (docs/format.md, Limits): a problem past one
/// is refused with an error naming the field and the flag that raises it.
#[derive(Debug, Clone, Args)]
#[command(next_help_heading = "Limits (docs/format.md)")]
pub struct LimitArgs {
    /// Degree of a curve or surface, given or computed
    #[arg(long, value_name = "N", allow_negative_numbers = true,
          value_parser = positive("--max-degree"), default_value_t = Limits::default().max_degree)]
    pub max_degree: usize,
    /// Items of a list, points of a mesh, given or computed
    #[arg(long, value_name = "N", allow_negative_numbers = true,
          value_parser = positive("--max-points"), default_value_t = Limits::default().max_points)]
    pub max_points: usize,
    /// Digits of a number
    #[arg(long, value_name = "N", allow_negative_numbers = true,
          value_parser = positive("--max-digits"), default_value_t = Limits::default().max_digits)]
    pub max_digits: usize,
    /// Problems of a batch; those past it are not solved
    #[arg(long, value_name = "N", allow_negative_numbers = true,
          value_parser = positive("--max-batch"), default_value_t = Limits::default().max_batch)]
    pub max_batch: usize,
    /// Nesting of an expression (at most 1000)
    #[arg(long, value_name = "N", allow_negative_numbers = true,
          value_parser = max_depth, default_value_t = Limits::default().max_depth)]
    pub max_depth: usize,
    /// |e| in x^e
    #[arg(long, value_name = "N", allow_negative_numbers = true,
          value_parser = max_exponent, default_value_t = Limits::default().max_exponent)]
    pub max_exponent: u32,
    /// Seconds one problem may take to solve (0: no deadline); past it the problem gets an
    /// error and the others are answered
    #[arg(long, value_name = "SECONDS", allow_negative_numbers = true,
          value_parser = max_seconds, default_value = "5")]
    pub max_seconds: f64,
    /// Megabytes one problem may hold while it is solved and its key written; past it the
    /// problem gets an error and the others are answered
    #[arg(long, value_name = "MB", allow_negative_numbers = true,
          value_parser = positive("--max-memory"), default_value_t = Limits::default().max_memory)]
    pub max_memory: usize,
}

impl LimitArgs {
    /// The flag that raises `limit` (`--max-degree`), read from these arguments' own
    /// definitions (whose ids are the limits' names), so that it is spelled once.
    pub fn flag(limit: Limit) -> String {
        let id = limit.name();
        let command = <LimitArgs as clap::Args>::augment_args(clap::Command::new("limits"));
        command
            .get_arguments()
            .find(|a| a.get_id() == id)
            .and_then(clap::Arg::get_long)
            .map(|long| format!("--{long}"))
            .unwrap_or_default()
    }

    /// The limits given (each flag not given has the default of [`Limits`]).
    pub fn limits(&self) -> Limits {
        Limits {
            max_degree: self.max_degree,
            max_points: self.max_points,
            max_digits: self.max_digits,
            max_batch: self.max_batch,
            max_depth: self.max_depth,
            max_exponent: self.max_exponent,
            max_seconds: deadline(self.max_seconds),
            max_memory: self.max_memory,
        }
    }
}

/// A parser of the positive integer value of `flag`.
pub fn positive(flag: &'static str) -> impl Fn(&str) -> Result<usize, CliMessage> + Clone {
    move |v: &str| match v.parse::<usize>() {
        Ok(n) if n > 0 => Ok(n),
        _ => Err(CliMessage::Positive {
            flag: flag.into(),
            found: v.into(),
        }),
    }
}

/// `--max-seconds`: a number of seconds, `0` for no deadline.
fn max_seconds(v: &str) -> Result<f64, CliMessage> {
    let bad = || CliMessage::Seconds { found: v.into() };
    match v.parse::<f64>() {
        Ok(s) if s == 0.0 || Duration::try_from_secs_f64(s).is_ok() => Ok(s),
        _ => Err(bad()),
    }
}

/// The deadline of `--max-seconds` (0: none).
fn deadline(seconds: f64) -> Option<Duration> {
    Duration::try_from_secs_f64(seconds)
        .ok()
        .filter(|d| !d.is_zero())
}

/// `--max-depth`: a positive integer, at most [`Limits::DEPTH_CEILING`].
fn max_depth(v: &str) -> Result<usize, CliMessage> {
    let n = positive("--max-depth")(v)?;
    if n > Limits::DEPTH_CEILING {
        return Err(CliMessage::AtMost {
            flag: "--max-depth".into(),
            max: Limits::DEPTH_CEILING.to_string(),
        });
    }
    Ok(n)
}

/// `--max-exponent`: a positive integer that fits a `u32`.
fn max_exponent(v: &str) -> Result<u32, CliMessage> {
    let n = positive("--max-exponent")(v)?;
    u32::try_from(n).map_err(|_| CliMessage::AtMost {
        flag: "--max-exponent".into(),
        max: u32::MAX.to_string(),
    })
}

/// What a path names: a file or a folder.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PathKind {
    /// A file.
    File,
    /// A folder.
    Folder,
}

/// A parser of a path given to `what` (`--out`, `FILE`), the file or folder it names: any
/// text but the empty one, which names no file (`--out ''` wrote into the current folder,
/// `--figures ''` to the root).
pub fn path(
    what: &'static str,
    kind: PathKind,
) -> impl Fn(&str) -> Result<String, CliMessage> + Clone {
    move |v: &str| {
        if !v.is_empty() {
            return Ok(v.to_string());
        }
        let what = what.to_string();
        Err(match kind {
            PathKind::File => CliMessage::EmptyFile { what },
            PathKind::Folder => CliMessage::EmptyFolder { what },
        })
    }
}

/// The language asked on a command line that did not parse (`--lang es`, `--lang=es`), so
/// that its usage error is said in it.
pub fn lang_of(args: &[OsString]) -> Lang {
    let es = args
        .windows(2)
        .any(|w| w.first().is_some_and(|a| a == "--lang") && w.get(1).is_some_and(|b| b == "es"))
        || args.iter().any(|a| a == "--lang=es");
    if es {
        Lang::Es
    } else {
        Lang::En
    }
}

/// A parser of the whole number (`u64`, `usize`...) value of `flag`.
pub fn whole<T: std::str::FromStr>(
    flag: &'static str,
) -> impl Fn(&str) -> Result<T, CliMessage> + Clone {
    move |v: &str| {
        v.parse::<T>().map_err(|_| CliMessage::Whole {
            flag: flag.into(),
            found: v.into(),
        })
    }
}

/// The command line as clap sees it, with the usage of every command in the usage of `cagd`.
pub fn command() -> clap::Command {
    let usage = [
        "cagd <COMMAND> [ARGS]",
        examples::USAGE,
        solve::USAGE,
        check::USAGE,
        generate::USAGE,
        sheet::USAGE,
        serve::USAGE,
        render::USAGE,
        expand::USAGE,
        completions::USAGE,
    ]
    .join("\n       ");
    Cli::command()
        .override_usage(usage)
        .mut_subcommands(|sc| sc.help_template(SUBCOMMAND_HELP))
}

/// Parses the command line (without the program name).
pub fn parse<I>(args: I) -> Result<Cli, clap::Error>
where
    I: IntoIterator<Item = OsString>,
{
    let args: Vec<OsString> = args.into_iter().collect();
    if let Some(cli) = parse_solve(&args) {
        return Ok(cli);
    }
    let matches = command().try_get_matches_from(std::iter::once("cagd".into()).chain(args))?;
    let mut cli = Cli::from_arg_matches(&matches)?;
    if let (Command::Render(r), Some(("render", m))) = (&mut cli.command, matches.subcommand()) {
        r.order_outputs(m);
    }
    Ok(cli)
}

/// `cagd solve ...` read by the parser of `solve` alone, which costs a fraction of building
/// the whole command line (clap builds every subcommand and its arguments first: a third of the
/// instructions of `cagd solve` on an empty batch). `None` for any other command and for any
/// error, help included: those go through [`command`], which words them.
fn parse_solve(args: &[OsString]) -> Option<Cli> {
    if args.first()? != "solve" {
        return None;
    }
    let solve = <solve::SolveArgs as Args>::augment_args(clap::Command::new("solve"));
    // the first argument, `solve`, stands for the program name
    let matches = solve.try_get_matches_from(args).ok()?;
    let args = solve::SolveArgs::from_arg_matches(&matches).ok()?;
    Some(Cli {
        command: Command::Solve(args),
    })
}

/// The sentence of the command line a clap error carries: the error of one of our value
/// parsers (`--max-depth is at most 1000`), read by clap's kind of error and its source, so
/// that it is worded in the language asked.
pub fn sentence_of(e: &clap::Error) -> Option<&CliMessage> {
    use std::error::Error as _;
    match e.kind() {
        clap::error::ErrorKind::ValueValidation => e.source()?.downcast_ref::<CliMessage>(),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_str(args: &[&str]) -> Result<Cli, clap::Error> {
        parse(args.iter().map(OsString::from))
    }

    #[test]
    fn the_command_line_is_well_formed() {
        command().debug_assert();
    }

    #[test]
    fn md_is_markdown_and_limits_default() {
        let cli = parse_str(&["solve", "-", "--format", "md", "--lang=es"]).unwrap();
        let Command::Solve(s) = cli.command else {
            panic!("solve parses as solve");
        };
        assert_eq!(s.key.format, KeyFormat::Markdown);
        assert_eq!(s.key.lang.lang(), Lang::Es);
        assert_eq!(s.limits.limits(), Limits::default());
        assert_eq!(s.threads, 1);
    }

    /// The parser of `solve` alone reads what the whole command line reads, and leaves help
    /// and errors to it.
    #[test]
    fn solve_alone_parses_as_the_whole_command_line() {
        let full = |args: &[&str]| {
            let m =
                command().try_get_matches_from(std::iter::once("cagd").chain(args.iter().copied()));
            m.and_then(|m| Cli::from_arg_matches(&m))
                .map(|c| format!("{c:?}"))
                .ok()
        };
        let alone = |args: &[&str]| {
            let args: Vec<OsString> = args.iter().map(OsString::from).collect();
            parse_solve(&args).map(|c| format!("{c:?}"))
        };
        for args in [
            &["solve", "p.json"][..],
            &["solve", "-", "--format", "json", "--lang=es", "--steps"],
            &[
                "solve",
                "b.json",
                "--threads",
                "2",
                "--max-degree",
                "40",
                "--max-seconds",
                "0",
            ],
            &["solve", "--format", "md", "x.json", "--max-depth", "7"],
        ] {
            assert!(alone(args).is_some(), "{args:?}");
            assert_eq!(alone(args), full(args), "{args:?}");
        }
        for args in [
            &["solve"][..],
            &["solve", "--help"],
            &["solve", "-h"],
            &["solve", "p.json", "--threads", "0"],
            &["solve", "p.json", "--colour"],
            &["solve", "p.json", "q.json"],
            &["expand", "u"],
        ] {
            assert_eq!(alone(args), None, "{args:?}");
        }
    }

    #[test]
    fn render_outputs_keep_their_order() {
        let cli = parse_str(&[
            "render", "in.json", "--obj", "a.obj", "--svg", "b.svg", "--obj", "c.obj",
        ])
        .unwrap();
        let Command::Render(r) = cli.command else {
            panic!("render parses as render");
        };
        let paths: Vec<&str> = r.given.iter().map(|(_, p)| p.as_str()).collect();
        assert_eq!(paths, ["a.obj", "b.svg", "c.obj"]);
    }
}
