//! `cagd`, the command line of cagd-exact.
//!
//! The command line is parsed by clap (`cli`); one module per subcommand, each with the struct
//! of its arguments and its `run`. `main` only dispatches, prints, and maps errors to exit
//! codes: 0 success, 1 bad input (an expression that does not parse...), 2 bad usage.

mod check;
mod cli;
mod completions;
mod elements;
mod encoding;
mod examples;
mod expand;
mod figures;
mod fixtures;
mod generate;
mod render;
mod said;
mod serve;
mod sheet;
mod solve;
mod usage;

use cagd_keys::Lang;
use cli::Command;
use said::Said;
use std::io::Write;
use std::process::ExitCode;

/// The allocator: mimalloc, counted. Reading, solving and printing a problem allocate many
/// small values (big integers, strings, vectors); glibc's malloc and free took a quarter of the
/// instructions of a batch of elevations, and its arenas contended across `--threads`. Every
/// allocation and release is told to `cagd_scalar::cancel::count_bytes`, which keeps the bytes
/// each thread holds: the checkpoints of a problem's work compare them with its memory limit
/// (`--max-memory`).
#[global_allocator]
static ALLOCATOR: counted::Counted = counted::Counted;

/// The counting allocator (the one unsafe code of the workspace: a global allocator cannot be
/// written without it).
#[allow(unsafe_code)]
mod counted {
    use cagd_scalar::cancel::count_bytes;
    use std::alloc::{GlobalAlloc, Layout};

    /// mimalloc, each allocation and release counted on the thread that makes it.
    pub struct Counted;

    /// `bytes` as a signed count: exact, as a layout's size (and a reallocation's new size)
    /// is at most `isize::MAX` by the contract of `Layout` and `GlobalAlloc::realloc`. A plain
    /// conversion: a saturating one added a compare and a move to every release, inlined into
    /// every drop, which then no longer inlined into their callers (+1 to 3 % instructions).
    #[inline(always)]
    fn signed(bytes: usize) -> isize {
        bytes as isize
    }

    // SAFETY: every call is forwarded to mimalloc with the same arguments, under the same
    // contract; the counting neither allocates nor unwinds.
    unsafe impl GlobalAlloc for Counted {
        unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
            // SAFETY: the caller's contract, forwarded
            let p = unsafe { mimalloc::MiMalloc.alloc(layout) };
            if !p.is_null() {
                count_bytes(signed(layout.size()));
            }
            p
        }

        unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
            // SAFETY: the caller's contract, forwarded
            let p = unsafe { mimalloc::MiMalloc.alloc_zeroed(layout) };
            if !p.is_null() {
                count_bytes(signed(layout.size()));
            }
            p
        }

        unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
            // SAFETY: the caller's contract, forwarded
            unsafe { mimalloc::MiMalloc.dealloc(ptr, layout) };
            count_bytes(-signed(layout.size()));
        }

        unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
            // SAFETY: the caller's contract, forwarded
            let p = unsafe { mimalloc::MiMalloc.realloc(ptr, layout, new_size) };
            if !p.is_null() {
                count_bytes(signed(new_size) - signed(layout.size()));
            }
            p
        }
    }
}

/// What went wrong, and so which exit code; what it says is typed, and worded when printed.
#[derive(Debug)]
pub enum CliError {
    /// The command line itself is wrong (exit code 2).
    Usage(Said),
    /// The input is wrong: an expression that does not parse... (exit code 1).
    Input(Said),
    /// The output could not be written (exit code 1; a closed pipe ends quietly).
    Output(std::io::Error),
    /// An error to print in a language (a command's errors in the language it was asked for;
    /// English otherwise).
    In(Lang, Box<CliError>),
}

impl CliError {
    /// The same error, printed in `lang`.
    pub fn in_lang(self, lang: Lang) -> CliError {
        match self {
            CliError::Output(e) => CliError::Output(e),
            CliError::In(l, e) => CliError::In(l, e),
            other => CliError::In(lang, Box::new(other)),
        }
    }

    /// A usage error of a sentence of the command line.
    pub fn usage(m: said::CliMessage) -> CliError {
        CliError::Usage(Said::from(m))
    }

    /// An input error of a sentence of the command line.
    pub fn input(m: said::CliMessage) -> CliError {
        CliError::Input(Said::from(m))
    }
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
    let args: Vec<std::ffi::OsString> = std::env::args_os().skip(1).collect();
    let cli = match cli::parse(args.iter().cloned()) {
        Ok(cli) => cli,
        Err(e) if !e.use_stderr() => {
            // --help, help, --version: to standard output, exit code 0; a closed pipe is not
            // an error worth a message
            let _ = e.print();
            return ExitCode::SUCCESS;
        }
        Err(e) => {
            // in the language asked (`--lang es` on the command line): a sentence of ours
            // (a flag's value), or clap's error worded by its kind (`usage`)
            let lang = cli::lang_of(&args);
            let text = match cli::sentence_of(&e) {
                Some(m) => cagd_words::Message::phrase(m, lang).text(),
                None => cagd_words::Message::phrase(&usage::Usage::of(&e), lang).text(),
            };
            return usage_error(&text, lang);
        }
    };
    // an error that carries no language of its own (writing the output) is said in the
    // language the command line asked for
    streamed(cli::lang_of(&args), |out| run(&cli.command, out))
}

/// Runs a command with buffered standard output as its output, and maps how it ended to
/// the exit code (an error in `lang`, unless it carries its own).
fn streamed(lang: Lang, run: impl FnOnce(&mut dyn Write) -> Result<u8, CliError>) -> ExitCode {
    let mut out = std::io::BufWriter::with_capacity(1 << 16, std::io::stdout().lock());
    // a closed pipe at the end leaves the command's own exit code
    let done = run(&mut out).and_then(|code| match out.flush() {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(CliError::Output(e)),
        _ => Ok(code),
    });
    match done {
        Ok(code) => ExitCode::from(code),
        Err(e) => failed(e, lang),
    }
}

/// Prints an error in `lang` (or in the language it carries) on standard error; its exit code.
fn failed(e: CliError, lang: Lang) -> ExitCode {
    match e {
        CliError::In(lang, e) => failed(*e, lang),
        CliError::Input(said) => {
            eprintln!("cagd: {}", cagd_keys::escape_text(&said.text(lang)));
            ExitCode::from(1)
        }
        CliError::Output(e) => output_error(&e, lang),
        CliError::Usage(said) => usage_error(&said.text(lang), lang),
    }
}

/// An error writing the output while a command ran: exit code 1 with a message
/// ([`write_error`]), except a closed pipe (`cagd ... | head`), which ends quietly (exit code
/// 0: the reader has all it wanted).
fn output_error(e: &std::io::Error, lang: Lang) -> ExitCode {
    write_error(e, lang).unwrap_or(ExitCode::SUCCESS)
}

/// The exit of a failed write to standard output: a closed pipe (`cagd ... | head`) is not an
/// error worth a message (`None`: the command's own exit code stands); any other failure (a
/// full disk, `> /dev/full`) is reported in `lang`, exit code 1, so that no answer is lost
/// without a word.
pub fn write_error(e: &std::io::Error, lang: Lang) -> Option<ExitCode> {
    if e.kind() == std::io::ErrorKind::BrokenPipe {
        return None;
    }
    let m = said::CliMessage::CannotWriteOutput { why: e.to_string() };
    eprintln!(
        "cagd: {}",
        cagd_keys::escape_text(&cagd_words::Message::phrase(&m, lang).text())
    );
    Some(ExitCode::from(1))
}

/// Prints a usage error on standard error, with the hint in `lang`; exit code 2.
fn usage_error(msg: &str, lang: Lang) -> ExitCode {
    let msg = cagd_keys::escape_text(msg);
    match lang {
        Lang::En => eprintln!("cagd: {msg} (run `cagd help` for the list of commands)"),
        Lang::Es => eprintln!("cagd: {msg} (`cagd help` da la lista de órdenes)"),
    }
    ExitCode::from(2)
}

/// Runs a command, writing its output to `out`: `cagd solve` writes its answers as it
/// computes them, the other commands their text once done. Returns the exit code.
fn run(command: &Command, out: &mut dyn Write) -> Result<u8, CliError> {
    let report = match command {
        Command::Solve(args) => return solve::run(args, out),
        Command::Examples(args) => examples::run(args)?,
        Command::Check(args) => check::run(args)?,
        Command::Generate(args) => generate::run(args)?,
        Command::Sheet(args) => sheet::run(args)?,
        Command::Serve(args) => serve::run(args)?,
        Command::Render(args) => render::run(args)?,
        Command::Expand(args) => expand::run(args).map(Report::from)?,
        Command::Completions(args) => completions::run(args).into(),
    };
    match out.write_all(report.text.as_bytes()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(CliError::Output(e)),
        _ => Ok(report.code),
    }
}
