//! clap's usage errors (an unknown flag or command, a missing argument, a bad value...) as
//! typed sentences of our own, worded in English and in Spanish, so that a command line that
//! asked for Spanish (`--lang es`, see [`crate::cli::lang_of`]) is answered in Spanish even
//! when clap is the one that refuses it.
//!
//! [`Usage::of`] reads a clap error by its kind and its context (the argument, the value, the
//! values allowed, clap's suggestion); clap's own English text is never printed.

use cagd_keys::Lang;
use cagd_words::{said, Message, Phrase};
use clap::error::{ContextKind, ContextValue, ErrorKind};

/// What clap found wrong with a command line.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum Usage {
    /// An argument the command does not take (`--fromat`).
    UnknownArgument {
        /// The argument given.
        arg: String,
    },
    /// An argument the command does not take, and the one it looks like.
    UnknownArgumentNear {
        /// The argument given.
        arg: String,
        /// The nearest argument the command takes (`--format`).
        nearest: String,
    },
    /// A command `cagd` does not have (`sovle`).
    UnknownCommand {
        /// The command given.
        command: String,
    },
    /// A command `cagd` does not have, and the one it looks like.
    UnknownCommandNear {
        /// The command given.
        command: String,
        /// The nearest command (`solve`).
        nearest: String,
    },
    /// `cagd` without a command.
    #[default]
    MissingCommand,
    /// A value that is not one of the flag's values (`--format pdf`).
    BadValue {
        /// The flag (`--format`).
        arg: String,
        /// The value given.
        value: String,
        /// The values it takes, separated by commas.
        valid: String,
    },
    /// A value the flag's parser refuses, without a sentence of ours.
    InvalidValue {
        /// The flag.
        arg: String,
        /// The value given.
        value: String,
    },
    /// A flag given without its value.
    MissingValue {
        /// The flag.
        arg: String,
    },
    /// A flag given without its value, which is one of a list.
    MissingValueOf {
        /// The flag.
        arg: String,
        /// The values it takes, separated by commas.
        valid: String,
    },
    /// One argument the command needs, not given (`<FILE>`).
    MissingArgument {
        /// The argument.
        arg: String,
    },
    /// Several arguments the command needs, not given.
    MissingArguments {
        /// The arguments, separated by commas.
        args: String,
    },
    /// A flag that takes its value after `=` only.
    NoEquals {
        /// The flag.
        arg: String,
    },
    /// A value too many for a flag or an argument.
    TooManyValues {
        /// The flag.
        arg: String,
        /// The value too many.
        value: String,
    },
    /// Fewer values than a flag takes.
    TooFewValues {
        /// The flag.
        arg: String,
        /// The least number of values.
        min: String,
        /// The number given.
        found: String,
    },
    /// Another number of values than a flag takes.
    WrongNumberOfValues {
        /// The flag.
        arg: String,
        /// The number of values it takes.
        expected: String,
        /// The number given.
        found: String,
    },
    /// Two arguments that cannot go together.
    Conflict {
        /// The argument given second.
        arg: String,
        /// The one it conflicts with.
        with: String,
    },
    /// An argument that is not UTF-8.
    NotUtf8,
    /// A command line clap refuses for a reason it has no kind for here.
    Unreadable,
}

/// The text of a context value: a string, or strings separated by commas.
fn text(v: Option<&ContextValue>) -> Option<String> {
    match v? {
        ContextValue::String(s) => Some(s.clone()),
        ContextValue::Strings(v) if !v.is_empty() => Some(v.join(", ")),
        ContextValue::Number(n) => Some(n.to_string()),
        ContextValue::StyledStr(s) => Some(s.to_string()),
        _ => None,
    }
}

/// Clap's nearest suggestion of a kind: the nearest (clap lists them nearest last: `sheet, solve`
/// for `solvee`), so that the sentence asks about one.
fn nearest(e: &clap::Error, kind: ContextKind) -> Option<String> {
    match e.get(kind)? {
        ContextValue::Strings(v) => v.last().cloned(),
        other => text(Some(other)),
    }
}

/// A flag as the user types it: `--format` of clap's `--format <FORMAT>`.
fn flag(arg: String) -> String {
    match arg.split_once(' ') {
        Some((flag, _)) if flag.starts_with('-') => flag.to_string(),
        _ => arg,
    }
}

impl Usage {
    /// The usage error of a clap error, read from its kind and its context.
    pub fn of(e: &clap::Error) -> Usage {
        let get = |k: ContextKind| text(e.get(k));
        let arg = || get(ContextKind::InvalidArg).map(flag).unwrap_or_default();
        let value = || get(ContextKind::InvalidValue).unwrap_or_default();
        match e.kind() {
            ErrorKind::UnknownArgument => {
                let nearest = nearest(e, ContextKind::SuggestedArg)
                    .or_else(|| nearest(e, ContextKind::SuggestedSubcommand));
                match nearest {
                    Some(nearest) => Usage::UnknownArgumentNear {
                        arg: arg(),
                        nearest,
                    },
                    None => Usage::UnknownArgument { arg: arg() },
                }
            }
            ErrorKind::InvalidSubcommand => {
                let command = get(ContextKind::InvalidSubcommand).unwrap_or_default();
                match nearest(e, ContextKind::SuggestedSubcommand) {
                    Some(nearest) => Usage::UnknownCommandNear { command, nearest },
                    None => Usage::UnknownCommand { command },
                }
            }
            ErrorKind::MissingSubcommand => Usage::MissingCommand,
            ErrorKind::InvalidValue => {
                let value = value();
                match (value.is_empty(), get(ContextKind::ValidValue)) {
                    (true, Some(valid)) => Usage::MissingValueOf { arg: arg(), valid },
                    (true, None) => Usage::MissingValue { arg: arg() },
                    (false, Some(valid)) => Usage::BadValue {
                        arg: arg(),
                        value,
                        valid,
                    },
                    (false, None) => Usage::InvalidValue { arg: arg(), value },
                }
            }
            ErrorKind::ValueValidation => Usage::InvalidValue {
                arg: arg(),
                value: value(),
            },
            ErrorKind::MissingRequiredArgument => match e.get(ContextKind::InvalidArg) {
                Some(ContextValue::Strings(args)) if args.len() > 1 => Usage::MissingArguments {
                    args: args.join(", "),
                },
                _ => Usage::MissingArgument { arg: arg() },
            },
            ErrorKind::NoEquals => Usage::NoEquals { arg: arg() },
            ErrorKind::TooManyValues => Usage::TooManyValues {
                arg: arg(),
                value: value(),
            },
            ErrorKind::TooFewValues => Usage::TooFewValues {
                arg: arg(),
                min: get(ContextKind::MinValues).unwrap_or_default(),
                found: get(ContextKind::ActualNumValues).unwrap_or_default(),
            },
            ErrorKind::WrongNumberOfValues => Usage::WrongNumberOfValues {
                arg: arg(),
                expected: get(ContextKind::ExpectedNumValues).unwrap_or_default(),
                found: get(ContextKind::ActualNumValues).unwrap_or_default(),
            },
            ErrorKind::ArgumentConflict => Usage::Conflict {
                arg: get(ContextKind::InvalidArg)
                    .or_else(|| get(ContextKind::InvalidSubcommand))
                    .map(flag)
                    .unwrap_or_default(),
                with: get(ContextKind::PriorArg).map(flag).unwrap_or_default(),
            },
            ErrorKind::InvalidUtf8 => Usage::NotUtf8,
            // help and version are printed, not refused; an error of clap's own making (an
            // I/O or formatting error) or of a kind clap adds later has no words of ours
            ErrorKind::DisplayHelp
            | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand
            | ErrorKind::DisplayVersion
            | ErrorKind::Io
            | ErrorKind::Format => Usage::Unreadable,
            _ => Usage::Unreadable,
        }
    }
}

impl Message for Usage {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Usage::UnknownArgument { arg } => said(
                lang,
                "unexpected argument '‹›'",
                "argumento inesperado '‹›'",
                [arg.into()],
            ),
            Usage::UnknownArgumentNear { arg, nearest } => said(
                lang,
                "unexpected argument '‹›': did you mean '‹›'?",
                "argumento inesperado '‹›': ¿quería decir '‹›'?",
                [arg.into(), nearest.into()],
            ),
            Usage::UnknownCommand { command } => said(
                lang,
                "unknown command '‹›'",
                "orden desconocida '‹›'",
                [command.into()],
            ),
            Usage::UnknownCommandNear { command, nearest } => said(
                lang,
                "unknown command '‹›': did you mean '‹›'?",
                "orden desconocida '‹›': ¿quería decir '‹›'?",
                [command.into(), nearest.into()],
            ),
            Usage::MissingCommand => said(
                lang,
                "a command is needed (examples, solve, check, generate, sheet, serve, render, expand...)",
                "falta la orden (examples, solve, check, generate, sheet, serve, render, expand...)",
                [],
            ),
            Usage::BadValue { arg, value, valid } => said(
                lang,
                "'‹›' is not a value of ‹› (its values: ‹›)",
                "'‹›' no es un valor de ‹› (sus valores: ‹›)",
                [value.into(), arg.into(), valid.into()],
            ),
            Usage::InvalidValue { arg, value } => said(
                lang,
                "'‹›' is not a valid value of ‹›",
                "'‹›' no es un valor válido de ‹›",
                [value.into(), arg.into()],
            ),
            Usage::MissingValue { arg } => said(
                lang,
                "‹› needs a value",
                "‹› necesita un valor",
                [arg.into()],
            ),
            Usage::MissingValueOf { arg, valid } => said(
                lang,
                "‹› needs a value (its values: ‹›)",
                "‹› necesita un valor (sus valores: ‹›)",
                [arg.into(), valid.into()],
            ),
            Usage::MissingArgument { arg } => said(
                lang,
                "missing argument ‹›",
                "falta el argumento ‹›",
                [arg.into()],
            ),
            Usage::MissingArguments { args } => said(
                lang,
                "missing arguments ‹›",
                "faltan los argumentos ‹›",
                [args.into()],
            ),
            Usage::NoEquals { arg } => said(
                lang,
                "‹› takes its value after '='",
                "‹› lleva su valor tras '='",
                [arg.into()],
            ),
            Usage::TooManyValues { arg, value } => said(
                lang,
                "unexpected value '‹›' for ‹›",
                "valor inesperado '‹›' para ‹›",
                [value.into(), arg.into()],
            ),
            Usage::TooFewValues { arg, min, found } => said(
                lang,
                "‹› takes at least ‹› values, found ‹›",
                "‹› lleva al menos ‹› valores, se encontraron ‹›",
                [arg.into(), min.into(), found.into()],
            ),
            Usage::WrongNumberOfValues {
                arg,
                expected,
                found,
            } => said(
                lang,
                "‹› takes ‹› values, found ‹›",
                "‹› lleva ‹› valores, se encontraron ‹›",
                [arg.into(), expected.into(), found.into()],
            ),
            Usage::Conflict { arg, with } => said(
                lang,
                "‹› cannot be used with ‹›",
                "‹› no se puede usar con ‹›",
                [arg.into(), with.into()],
            ),
            Usage::NotUtf8 => said(
                lang,
                "an argument is not valid UTF-8",
                "un argumento no está en UTF-8",
                [],
            ),
            Usage::Unreadable => said(
                lang,
                "the command line cannot be read",
                "no se entiende la línea de órdenes",
                [],
            ),
        }
    }
}

cagd_words::display_english!(Usage);

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    /// The usage error of a command line, in `lang`.
    fn refused(args: &[&str], lang: Lang) -> String {
        let e = crate::cli::parse(args.iter().map(std::ffi::OsString::from))
            .expect_err("a usage error");
        Usage::of(&e).phrase(lang).text()
    }

    #[test]
    fn every_variant_in_both_languages() {
        for m in Usage::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }

    #[test]
    fn clap_errors_are_worded_by_kind() {
        assert_eq!(
            refused(&["examples", "--fromat", "json"], Lang::Es),
            "argumento inesperado '--fromat': ¿quería decir '--format'?"
        );
        assert_eq!(
            refused(&["examples", "--fromat", "json"], Lang::En),
            "unexpected argument '--fromat': did you mean '--format'?"
        );
        assert_eq!(
            refused(&["sovle"], Lang::Es),
            "orden desconocida 'sovle': ¿quería decir 'solve'?"
        );
        // clap suggests `sheet, solve` for `solvee`: the sentence asks about the nearest
        assert_eq!(
            refused(&["solvee"], Lang::Es),
            "orden desconocida 'solvee': ¿quería decir 'solve'?"
        );
        assert_eq!(
            refused(&["frobnicate"], Lang::Es),
            "orden desconocida 'frobnicate'"
        );
        assert_eq!(
            refused(&[], Lang::Es),
            "falta la orden (examples, solve, check, generate, sheet, serve, render, expand...)"
        );
        assert_eq!(
            refused(&["examples", "--format", "pdf"], Lang::Es),
            "'pdf' no es un valor de --format (sus valores: text, latex, markdown, json)"
        );
        assert_eq!(
            refused(&["examples", "--lang"], Lang::Es),
            "--lang necesita un valor (sus valores: en, es)"
        );
        assert_eq!(
            refused(&["check"], Lang::Es),
            "falta el argumento <FILE>..."
        );
        assert_eq!(
            refused(&["expand", "u", "v"], Lang::Es),
            "argumento inesperado 'v'"
        );
    }
}
