//! `cagd completions SHELL`: the completion script of a shell, from the clap command line.

use crate::{cli, Output};
use clap::Args;
use clap_complete::Shell;

/// The usage line of `cagd completions`.
pub const USAGE: &str = "cagd completions SHELL";

/// Print the completion script of a shell
///
/// Prints a script that completes the commands and flags of cagd in SHELL. For example:
///   bash:  cagd completions bash > ~/.local/share/bash-completion/completions/cagd
///   zsh:   cagd completions zsh > ~/.zfunc/_cagd   (with fpath+=~/.zfunc before compinit)
///   fish:  cagd completions fish > ~/.config/fish/completions/cagd.fish
#[derive(Debug, Clone, Args)]
#[command(verbatim_doc_comment, override_usage = USAGE)]
pub struct CompletionsArgs {
    /// The shell
    #[arg(value_enum)]
    pub shell: Shell,
}

/// Runs `cagd completions`.
pub fn run(args: &CompletionsArgs) -> Output {
    let mut script = Vec::new();
    clap_complete::generate(args.shell, &mut cli::command(), "cagd", &mut script);
    String::from_utf8_lossy(&script).into_owned()
}
