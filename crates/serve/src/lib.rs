//! `cagd serve`: a problem set served to students, who check their answers on a page, and
//! the teacher's page (a problem's key and figure). The HTTP contract is `API.md` beside this
//! crate's `Cargo.toml`.
//!
//! Each problem is read once and its key (cagd-diagnose's [`cagd_diagnose::Key`]: the answer
//! with its steps and every mistake's answer) computed once at startup ([`Served`]); a
//! student's answer is then checked against it by the engine's own `diagnose_with`, on a
//! bounded pool of workers ([`pool::Pool`]) under the problem limits. Every word the server
//! writes is typed ([`message::ServeMessage`]); every HTML fragment comes from the keys'
//! Markdown through one converter that lets no HTML of its own through ([`markdown`]).

pub mod assets;
mod http;
pub mod markdown;
pub mod message;
pub mod pool;
pub mod served;
pub mod template;
pub mod words;

use cagd_problem::Limits;
use cagd_words::{Lang, Message, Phrase};
use message::ServeMessage;
use std::net::SocketAddr;

pub use http::Prepared;
pub use served::{LeftOut, Served, ServedProblem, Set};

/// When the worked key is shown to a student.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Reveal {
    /// Never: the student sees the marks and the diagnosis only.
    #[default]
    Never,
    /// After each check.
    AfterCheck,
}

impl Reveal {
    /// Its name in the JSON (`never`, `after_check`).
    pub fn name(self) -> &'static str {
        match self {
            Reveal::Never => "never",
            Reveal::AfterCheck => "after_check",
        }
    }
}

/// How the server runs.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Config {
    /// The address to listen on.
    pub bind: SocketAddr,
    /// The teacher's token; without it the teacher's pages are open on the loopback only.
    pub token: Option<String>,
    /// The default language of the pages.
    pub lang: Lang,
    /// When the worked key is shown to a student.
    pub reveal: Reveal,
    /// The limits every problem is read, solved and checked under.
    pub limits: Limits,
    /// How many solves, checks and reads run at once.
    pub workers: usize,
    /// How many requests may wait for a worker (more are answered "busy").
    pub queue: usize,
}

impl Default for Config {
    fn default() -> Self {
        Config {
            bind: SocketAddr::from(([127, 0, 0, 1], 8080)),
            token: None,
            lang: Lang::En,
            reveal: Reveal::Never,
            limits: Limits::DEFAULT,
            workers: std::thread::available_parallelism().map_or(1, usize::from),
            queue: 256,
        }
    }
}

/// Why the server could not run.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ServeError(pub ServeMessage);

impl Message for ServeError {
    fn phrase(&self, lang: Lang) -> Phrase {
        self.0.phrase(lang)
    }
}

cagd_words::display_english!(ServeError);

impl std::error::Error for ServeError {}

/// The server's routes for `set` under `config`: every problem read and keyed now (those
/// that fail are left out, named in [`Prepared::report`]).
pub fn router(set: &Set, config: &Config) -> Result<axum::Router, ServeError> {
    Ok(prepare(set, config)?.router)
}

/// The routes, the startup report and the pool (a test holds a worker through
/// [`pool::Pool::try_hold`]).
pub fn prepare(set: &Set, config: &Config) -> Result<Prepared, ServeError> {
    http::prepare(set, config)
}

/// Serves `set` until Ctrl-C: prints the students' and the teacher's addresses (and the
/// problems left out), then answers on a multi-threaded runtime of its own.
pub fn run(set: &Set, config: &Config) -> Result<(), ServeError> {
    let prepared = prepare(set, config)?;
    // The blocking threads are the workers: as many as the pool lets work at once (so none is
    // made and dropped per request, and memory stays flat under load), each with the solver
    // threads' stack of `cagd solve` (the engine's recursion on a deep expression).
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .enable_all()
        .max_blocking_threads(config.workers.max(1))
        .thread_stack_size(SOLVER_STACK)
        .build()
        .map_err(|e| {
            ServeError(ServeMessage::Failed {
                error: e.to_string(),
            })
        })?;
    runtime.block_on(http::serve(prepared, config))
}

/// The stack of a thread that solves (as `cagd solve`'s solver threads).
const SOLVER_STACK: usize = 64 * 1024 * 1024;

/// `data` in base64 (RFC 4648, with padding): a CSP hash, a figure as a `data:` URL.
pub fn base64(data: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let symbol = |i: u32| char::from(ALPHABET.get((i & 63) as usize).copied().unwrap_or(b'A'));
    let mut out = String::with_capacity(data.len().div_ceil(3) * 4);
    for chunk in data.chunks(3) {
        let b = |k: usize| u32::from(chunk.get(k).copied().unwrap_or(0));
        let n = (b(0) << 16) | (b(1) << 8) | b(2);
        out.push(symbol(n >> 18));
        out.push(symbol(n >> 12));
        out.push(if chunk.len() > 1 { symbol(n >> 6) } else { '=' });
        out.push(if chunk.len() > 2 { symbol(n) } else { '=' });
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_as_the_rfc() {
        assert_eq!(base64(b""), "");
        assert_eq!(base64(b"f"), "Zg==");
        assert_eq!(base64(b"fo"), "Zm8=");
        assert_eq!(base64(b"foo"), "Zm9v");
        assert_eq!(base64(b"foobar"), "Zm9vYmFy");
    }
}
