//! Tests of the contract's sentences.

use super::*;
use strum::IntoEnumIterator;

#[test]
fn every_variant_in_both_languages() {
    for m in Contract::iter() {
        // serde's text as it is has no words of its own: some text in its hole
        let m = match m {
            Contract::Serde { .. } => Contract::Serde {
                text: "invalid value: integer `-1`, expected usize".into(),
            },
            Contract::Host { .. } => Contract::Host {
                what: "TypeError: unhashable type: 'list'".into(),
            },
            m => m,
        };
        assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
    }
    // the inner sentences, each of their variants
    for found in Found::iter() {
        let m = Contract::InvalidType {
            found,
            expected: Expected::default(),
        };
        assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
    }
    for expected in Expected::iter() {
        let m = Contract::InvalidType {
            found: Found::default(),
            expected,
        };
        assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
    }
    for what in Syntax::iter() {
        for line in [0, 3] {
            let m = Contract::CannotRead {
                why: Box::new(Contract::Syntax {
                    what: what.clone(),
                    line,
                    column: 5,
                }),
            };
            assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
        }
    }
    for first in RootSource::iter() {
        let m = Contract::RootConflict {
            root: 3,
            first,
            first_root: 2,
        };
        assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
    }
    for general in Decided::iter() {
        let m = Contract::Differs {
            letters: "k".into(),
            result: "developable".into(),
            general,
            at: "k = 0".into(),
            special: Decided::Yes,
        };
        assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
    }
    // the variants with a choice of words by their data
    for m in [
        Contract::UnknownOperation {
            found: "coonz".into(),
            nearest: Some("coons".into()),
        },
        Contract::UnknownKey {
            nearest: Some("radius".into()),
            owner: "circle".into(),
            valid: vec!["radius".into(), "center".into()],
        },
        Contract::UnknownWord {
            valid: vec!["bezier".into(), "bspline".into(), "bicubic".into()],
            found: "bezeir".into(),
        },
    ] {
        assert_eq!(cagd_words::check_both(&m), Ok(()), "{m:?}");
    }
}

/// The syntax errors are read by their words: each word of the table is its variant's
/// English.
#[test]
fn the_syntax_words_are_the_variants_english() {
    for (words, what) in Syntax::WORDS {
        assert_eq!(what.english(), words);
    }
    assert_eq!(Syntax::WORDS.len() + 1, Syntax::iter().count());
}

/// The field's choice said in Spanish throughout, whoever needs the other root (it said
/// "pero the operation necesita √2").
#[test]
fn the_field_choice_is_spanish_throughout() {
    let m = Contract::RootConflict {
        root: 3,
        first: RootSource::Operation,
        first_root: 2,
    };
    assert_eq!(
        m.english(),
        "this number needs √3, but the operation needs √2: a problem runs in one field a + b√d"
    );
    assert_eq!(
        m.phrase(Lang::Es).text(),
        "este número necesita √3, pero la operación necesita √2: un problema se resuelve en \
         un solo cuerpo a + b√d"
    );
    let m = Contract::RootConflict {
        root: 5,
        first: RootSource::Numbers,
        first_root: 2,
    };
    assert_eq!(
        m.phrase(Lang::Es).text(),
        "este número necesita √5, pero los números del problema necesitan √2: un problema \
         se resuelve en un solo cuerpo a + b√d"
    );
    for first in RootSource::iter() {
        let m = Contract::RootConflict {
            root: 3,
            first,
            first_root: 2,
        };
        assert!(
            cagd_words::english_in(&m.phrase(Lang::Es)).is_empty(),
            "{m:?}"
        );
    }
}
