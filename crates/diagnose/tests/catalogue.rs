//! The documentation of the catalogue stays current: `docs/mistakes.md` and
//! `docs/errores-frecuentes.md` are what `cargo run -p cagd-diagnose --example mistakes` writes
//! from the catalogue.

#![allow(clippy::expect_used, clippy::panic)]

#[path = "../examples/mistakes.rs"]
mod mistakes;

#[test]
fn the_catalogue_docs_are_current() {
    for (file, lang) in mistakes::DOCUMENTS {
        let path = mistakes::docs().join(file);
        let written = std::fs::read_to_string(&path).unwrap_or_default();
        assert!(
            written == mistakes::document(lang),
            "docs/{file} is not the catalogue's: run `cargo run -p cagd-diagnose --example mistakes`"
        );
    }
}
