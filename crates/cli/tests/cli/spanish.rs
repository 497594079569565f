//! The command line's own messages in Spanish when the command line asks for it (`--lang es`):
//! usage errors (clap's: an unknown flag or command, a missing argument, a bad value) worded
//! by our sentences, on one line, exit code 2; an output that cannot be written.

use crate::common::{cagd, stderr, stdout};

/// The one line of standard error of `cagd ARGS`, which must be a usage error.
fn usage_error(args: &[&str]) -> String {
    let out = cagd(args);
    assert_eq!(out.status.code(), Some(2), "args {args:?}");
    assert!(stdout(&out).is_empty());
    let err = stderr(&out);
    assert_eq!(err.lines().count(), 1, "{err}");
    err
}

#[test]
fn usage_errors_in_spanish() {
    let hint = " (`cagd help` da la lista de órdenes)\n";
    for (args, said) in [
        (
            &["examples", "--fromat", "json", "--lang", "es"][..],
            "argumento inesperado '--fromat': ¿quería decir '--format'?",
        ),
        (
            &["solve", "-", "--format", "pdf", "--lang", "es"][..],
            "'pdf' no es un valor de --format (sus valores: text, latex, markdown, json)",
        ),
        (
            &["check", "--lang", "es"][..],
            "falta el argumento <FILE>...",
        ),
        (
            &["expand", "u", "v", "--lang=es"][..],
            "argumento inesperado 'v'",
        ),
        (
            &["solve", "-", "--lang", "es", "--max-depth", "x"][..],
            "--max-depth lleva un entero positivo, y se encontró 'x'",
        ),
    ] {
        assert_eq!(usage_error(args), format!("cagd: {said}{hint}"), "{args:?}");
    }
    // no English word of clap's is left
    for args in [
        &["examples", "--fromat", "--lang", "es"][..],
        &["render", "--lang", "es"][..],
        &["examples", "--lang", "es", "--format"][..],
    ] {
        let err = usage_error(args);
        for english in ["error", "unexpected", "required", "invalid", "tip", "Usage"] {
            assert!(!err.contains(english), "{english} in {err}");
        }
    }
}

#[test]
fn usage_errors_in_english() {
    let hint = " (run `cagd help` for the list of commands)\n";
    assert_eq!(
        usage_error(&["examples", "--fromat", "json"]),
        format!("cagd: unexpected argument '--fromat': did you mean '--format'?{hint}")
    );
    assert_eq!(
        usage_error(&["sovle"]),
        format!("cagd: unknown command 'sovle': did you mean 'solve'?{hint}")
    );
    assert_eq!(
        usage_error(&["examples", "--lang", "fr"]),
        format!("cagd: 'fr' is not a value of --lang (its values: en, es){hint}")
    );
}

/// A full disk is said in the language asked (the system's reason is data).
#[test]
fn an_output_that_cannot_be_written_in_spanish() {
    let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") else {
        return;
    };
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(["examples", "--lang", "es"])
        .stdout(full)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert!(
        err.starts_with("cagd: no se puede escribir la salida: "),
        "{err}"
    );
}
