//! The sentence of an error of the problem layer, with how a front end raises a limit, and the
//! verdict of a checked problem: `matches the notes`, an erratum, or the failure.

use crate::escape::escape_latex;
use crate::said::{self, Sentence};
use crate::sentences::Raise;
use crate::vocabulary::Word;
use crate::{tex, Lang};
use cagd_contract::{Limit, ProblemError, Verdict};

/// How a front end says to raise a limit (the command line names its flag): the sentence
/// after the message of an error past `limit`, or `None`.
pub type RaiseWith = fn(Limit) -> Option<Raise>;

/// A key written by no front end: nothing said after an error past a limit.
pub fn no_raise(_: Limit) -> Option<Raise> {
    None
}

/// An error of the problem layer in the language asked: `problem 2: field `c1`: ...`, problems
/// numbered from 1, the message by its type ([`said::message`]).
pub fn error_sentence(e: &ProblemError, lang: Lang) -> Sentence {
    error_sentence_with(e, lang, no_raise)
}

/// [`error_sentence`], and after an error past a limit, how the front end raises it
/// (`(raise it with --max-degree)`).
pub fn error_sentence_with(e: &ProblemError, lang: Lang, raise: RaiseWith) -> Sentence {
    let mut prefix = String::new();
    if let Some(i) = e.index {
        prefix += &format!("{} {}: ", lang.word("problem"), i + 1);
    }
    if !e.field.is_empty() {
        prefix += &format!("{} `{}`: ", lang.word("field"), e.field);
    }
    let mut s = said::message_line(&e.message, lang);
    if let Some(r) = e.limit.and_then(raise) {
        s = s.then(&r.sentence(lang));
    }
    Sentence {
        text: prefix.clone() + &s.text.replace('\n', " "),
        latex: escape_latex(&prefix) + &s.latex.replace('\n', " "),
    }
}

/// Whether a mismatch is one of a result or step that the assessment marks entry by entry.
fn assessed_mismatch(m: &cagd_contract::Message) -> bool {
    use cagd_contract::message::check::Check;
    matches!(m, cagd_contract::Message::Check(c) if matches!(**c, Check::Result { .. } | Check::Step { .. }))
}

/// `matches the notes`, `erratum: the notes print X, the exact value is Y`, or the failure.
pub fn verdict_text(v: &Verdict, lang: Lang) -> String {
    verdict_sentence(v, lang, no_raise).text
}

/// The verdict as text and LaTeX; a student's assessed answer, correct or wrong with its
/// score.
pub(crate) fn verdict_sentence(v: &Verdict, lang: Lang, raise: RaiseWith) -> Sentence {
    if let Err(e) = &v.answer {
        let s = error_sentence_with(e, lang, raise);
        return Sentence {
            text: format!("{}: {}", lang.word("failed"), s.text),
            latex: format!("{}: {}", lang.word("failed"), s.latex),
        };
    }
    if let Some(a) = crate::assessment::of(v) {
        // a student's answer assessed: its score, the entries and mistakes below; what the
        // assessment does not cover (a key that is not a result, words of the wrong shape)
        // is said after it, and makes the answer wrong
        let s = crate::assessment::verdict_sentence(a, v.passed(), lang);
        let others: Vec<Sentence> = v
            .mismatches
            .iter()
            .filter(|m| !assessed_mismatch(m))
            .map(|m| said::message(m, lang))
            .collect();
        if others.is_empty() {
            return s;
        }
        let join = |f: fn(&Sentence) -> &str| others.iter().map(f).collect::<Vec<_>>().join("; ");
        return Sentence {
            text: format!("{}; {}", s.text, join(|s| &s.text)),
            latex: format!("{}; {}", s.latex, join(|s| &s.latex)),
        };
    }
    if !v.mismatches.is_empty() {
        let ms: Vec<Sentence> = v
            .mismatches
            .iter()
            .map(|m| said::message(m, lang))
            .collect();
        let join = |f: fn(&Sentence) -> &str| ms.iter().map(f).collect::<Vec<_>>().join("; ");
        return Sentence {
            text: format!("{}: {}", lang.word("failed"), join(|s| &s.text)),
            latex: format!("{}: {}", lang.word("failed"), join(|s| &s.latex)),
        };
    }
    if v.errata.is_empty() {
        let from_notes = v.problem.as_ref().is_some_and(|p| p.meta.from_notes());
        let w = lang.word(if from_notes {
            "matches the notes"
        } else {
            "matches the expected answer"
        });
        return Sentence {
            latex: escape_latex(&w),
            text: w,
        };
    }
    let (mut text, mut tex) = (Vec::new(), Vec::new());
    for e in &v.errata {
        let es = match lang {
            Lang::Es => e.es.clone().unwrap_or_default(),
            Lang::En => Default::default(),
        };
        // a fixture's own words (an erratum found by computing has its own Spanish), else
        // the English ones, which are mathematics
        let place = es.place.unwrap_or_else(|| e.place.clone());
        let printed = es.printed.unwrap_or_else(|| e.printed.clone());
        let exact = es.exact.unwrap_or_else(|| e.exact.clone());
        let why = es.why.unwrap_or_else(|| e.why.clone());
        // an erratum of scale is said as such (the direction is the same)
        let [erratum, notes_print, exact_is] = e.kind.words(lang);
        text.push(format!(
            "{erratum} ({place}): {notes_print} {printed}, {exact_is} {exact}{}",
            if why.is_empty() {
                String::new()
            } else {
                format!(" — {why}")
            }
        ));
        tex.push(format!(
            "{erratum} ({}): {notes_print} {}, {exact_is} {}{}",
            tex::words(&place),
            formula_latex(&printed),
            formula_latex(&exact),
            if why.is_empty() {
                String::new()
            } else {
                format!(" --- {}", tex::words(&why))
            }
        ));
    }
    Sentence {
        text: text.join("; "),
        latex: tex.join("; "),
    }
}

/// What an erratum's `printed` or `exact` says, in LaTeX: a formula (no word of four letters)
/// wholly in math mode, else words with their mathematics.
fn formula_latex(s: &str) -> String {
    let words = s
        .split(|c: char| !c.is_alphabetic())
        .any(|w| w.chars().count() >= 4 && w != "sqrt");
    if words {
        tex::words(s)
    } else {
        format!("${}$", tex::math(s))
    }
}
