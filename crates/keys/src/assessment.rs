//! A student's answer assessed, in a key (`cagd check`): in place of the first mismatch, each
//! result the student wrote with its score ("7 of 9 entries right"), every wrong entry with the
//! key's value and the student's, the mistakes of the catalogue that explain them (what the
//! student did, its identifier, the notes' section, and the formula used instead beside the
//! notes' one), "ambiguous" when several mistakes give the same values, "no known mistake"
//! when none does, and the first step where the student leaves the key. A correct result is
//! said correct with its score, never diagnosed. Its words are typed ([`AssessmentWords`]),
//! English and Spanish side by side; the values are the engine's printers'; the problem's text
//! (a student's name, a string written where a number was asked) goes through the format's
//! escaper.

use crate::escape::{escape_latex, escape_markdown, escape_text};
use crate::names::{self, Label};
use crate::said::{self, Sentence};
use crate::values::{latex, text};
use crate::{tex, Lang};
use cagd_contract::diagnosis::{Assessed, Diagnosis, Entry, Mark};
use cagd_contract::{Assessment, Catalogued, Exact, Mistake, Problem, Verdict};
use cagd_words::{said, Message, Phrase};

/// The words of an assessment in a key, each worded in English and in the notes' Spanish.
#[derive(Debug, Clone, PartialEq, Eq, Default, strum::EnumIter)]
pub enum AssessmentWords {
    /// The whole answer: correct or not, and how many of its entries are right.
    Answer {
        /// Whether every result (and every step written) is right.
        correct: bool,
        /// The entries right.
        right: usize,
        /// The entries of the results.
        total: usize,
    },
    /// A correct result: "correct: 9 of 9 entries right".
    Correct {
        /// The entries right.
        right: usize,
        /// The entries.
        total: usize,
    },
    /// A wrong result's score: "7 of 9 entries right".
    Score {
        /// The entries right.
        right: usize,
        /// The entries.
        total: usize,
    },
    /// Before the key's value of a wrong entry.
    #[default]
    Key,
    /// Before the student's value of a wrong entry.
    Written,
    /// An entry of the key the student did not write.
    NotWritten,
    /// What the student did: a mistake's sentence after it.
    Mistake,
    /// Several mistakes give the student's values: exact arithmetic cannot tell them apart.
    Ambiguous,
    /// Before the entries a mistake explains, when it does not explain the whole result.
    Explains,
    /// Before the notes' formula.
    NotesFormula,
    /// Before the formula the student used instead.
    UsedFormula,
    /// A wrong result that no mistake of the catalogue explains.
    NoKnownMistake,
    /// The student's value could not be read, and why.
    Unread {
        /// Why, as the reader says it.
        why: Phrase,
    },
    /// The student wrote a result the problem does not have.
    Unknown,
    /// The steps the student wrote, assessed.
    StepsWritten,
    /// Before the first step where the student's values leave the key's.
    FirstDeparture,
    /// The student, by name.
    Student {
        /// The name, as the answer gives it (data).
        name: String,
    },
}

impl Message for AssessmentWords {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            AssessmentWords::Answer {
                correct: true,
                right,
                total: total @ 1,
            } => said(
                lang,
                "correct answer: ‹› of ‹› entry right",
                "respuesta correcta: ‹› de ‹› entrada correcta",
                [right.into(), total.into()],
            ),
            AssessmentWords::Answer {
                correct: false,
                right,
                total: total @ 1,
            } => said(
                lang,
                "wrong answer: ‹› of ‹› entry right",
                "respuesta incorrecta: ‹› de ‹› entrada correcta",
                [right.into(), total.into()],
            ),
            AssessmentWords::Answer {
                correct: true,
                right,
                total,
            } => said(
                lang,
                "correct answer: ‹› of ‹› entries right",
                "respuesta correcta: ‹› de ‹› entradas correctas",
                [right.into(), total.into()],
            ),
            AssessmentWords::Answer {
                correct: false,
                right,
                total,
            } => said(
                lang,
                "wrong answer: ‹› of ‹› entries right",
                "respuesta incorrecta: ‹› de ‹› entradas correctas",
                [right.into(), total.into()],
            ),
            AssessmentWords::Correct {
                right,
                total: total @ 1,
            } => said(
                lang,
                "correct: ‹› of ‹› entry right",
                "correcto: ‹› de ‹› entrada correcta",
                [right.into(), total.into()],
            ),
            AssessmentWords::Correct { right, total } => said(
                lang,
                "correct: ‹› of ‹› entries right",
                "correcto: ‹› de ‹› entradas correctas",
                [right.into(), total.into()],
            ),
            AssessmentWords::Score {
                right,
                total: total @ 1,
            } => said(
                lang,
                "‹› of ‹› entry right",
                "‹› de ‹› entrada correcta",
                [right.into(), total.into()],
            ),
            AssessmentWords::Score { right, total } => said(
                lang,
                "‹› of ‹› entries right",
                "‹› de ‹› entradas correctas",
                [right.into(), total.into()],
            ),
            AssessmentWords::Key => said(lang, "key", "clave", []),
            AssessmentWords::Written => said(lang, "answer", "respuesta", []),
            AssessmentWords::NotWritten => said(lang, "not written", "sin escribir", []),
            AssessmentWords::Mistake => said(lang, "mistake", "error", []),
            AssessmentWords::Ambiguous => said(
                lang,
                "ambiguous: each of these mistakes gives these values",
                "ambiguo: cada uno de estos errores da estos valores",
                [],
            ),
            AssessmentWords::Explains => said(lang, "explains", "explica", []),
            AssessmentWords::NotesFormula => said(lang, "notes", "apuntes", []),
            AssessmentWords::UsedFormula => said(lang, "used", "usada", []),
            AssessmentWords::NoKnownMistake => said(
                lang,
                "no known mistake explains these entries",
                "ningún error conocido explica estas entradas",
                [],
            ),
            AssessmentWords::Unread { why } => said(
                lang,
                "the answer could not be read: «»",
                "no se pudo leer la respuesta: «»",
                [why.clone().into()],
            ),
            AssessmentWords::Unknown => said(
                lang,
                "not a result of this problem",
                "no es un resultado de este problema",
                [],
            ),
            AssessmentWords::StepsWritten => said(lang, "steps written", "pasos escritos", []),
            AssessmentWords::FirstDeparture => said(
                lang,
                "first step that leaves the key",
                "primer paso que se aparta de la clave",
                [],
            ),
            AssessmentWords::Student { name } => {
                said(lang, "student: ‹›", "estudiante: ‹›", [name.into()])
            }
        }
    }
}

cagd_words::display_english!(AssessmentWords);

/// The assessment a verdict's key writes in place of its mismatches: the verdict's, when it
/// has one with a result or a step assessed and the problem was solved.
pub(crate) fn of(verdict: &Verdict) -> Option<&Assessment> {
    let a = verdict.assessment.as_deref()?;
    let assessed = !a.results.is_empty() || !a.steps.is_empty();
    (verdict.answer.is_ok() && assessed).then_some(a)
}

/// The verdict's sentence of an assessed answer: correct or wrong, with the score; correct
/// only when every result is and the check found nothing else (`passed`).
pub(crate) fn verdict_sentence(a: &Assessment, passed: bool, lang: Lang) -> Sentence {
    said::said(
        &AssessmentWords::Answer {
            correct: passed && a.correct(),
            right: a.right(),
            total: a.total(),
        },
        lang,
    )
}

/// One line of an assessment: its depth in the list and what it says.
enum Line {
    /// Words (already in the format).
    Words(String),
    /// A formula shown beside the notes' one: the notes' and the one used instead.
    Formulas(Mistake),
}

/// How a format writes the parts of an assessment.
trait Format {
    /// A typed sentence.
    fn said(&self, m: &dyn Message, lang: Lang) -> String;
    /// A label of a result or step.
    fn label(&self, l: &Label) -> String;
    /// An exact value.
    fn value(&self, x: &Exact, lang: Lang) -> String;
    /// An entry of a value (`c_1,1`).
    fn entry(&self, e: &Entry, lang: Lang) -> String;
    /// A mistake's identifier.
    fn id(&self, id: &str) -> String;
    /// What the student did, a mistake's sentence (its mathematics in its words: `c_cd`).
    fn mistake(&self, m: &Mistake, lang: Lang) -> String {
        self.said(m, lang)
    }
    /// Whether a wrong entry shows the key's value beside the student's (not on a student's
    /// own report while the key is not revealed).
    fn shows_key(&self) -> bool {
        true
    }
}

struct Text;
struct Latex;
struct Markdown;
/// Markdown for the student: the key's values left out.
struct MarkdownWithoutKey;

impl Format for MarkdownWithoutKey {
    fn said(&self, m: &dyn Message, lang: Lang) -> String {
        Markdown.said(m, lang)
    }
    fn label(&self, l: &Label) -> String {
        Markdown.label(l)
    }
    fn value(&self, x: &Exact, lang: Lang) -> String {
        Markdown.value(x, lang)
    }
    fn entry(&self, e: &Entry, lang: Lang) -> String {
        Markdown.entry(e, lang)
    }
    fn id(&self, id: &str) -> String {
        Markdown.id(id)
    }
    fn shows_key(&self) -> bool {
        false
    }
}

impl Format for Text {
    fn said(&self, m: &dyn Message, lang: Lang) -> String {
        escape_text(&m.phrase(lang).text())
    }
    fn label(&self, l: &Label) -> String {
        l.text.clone()
    }
    fn value(&self, x: &Exact, lang: Lang) -> String {
        text(x, lang)
    }
    fn entry(&self, e: &Entry, lang: Lang) -> String {
        escape_text(&e.phrase(lang).text())
    }
    fn id(&self, id: &str) -> String {
        format!("`{}`", escape_text(id))
    }
}

impl Format for Latex {
    fn said(&self, m: &dyn Message, lang: Lang) -> String {
        said::said(m, lang).latex
    }
    fn label(&self, l: &Label) -> String {
        format!("${}$", l.latex)
    }
    fn value(&self, x: &Exact, lang: Lang) -> String {
        // a closed form breaks between its terms, a mesh is scaled to the line
        crate::latex_math::inline_value(&latex(x, lang))
    }
    fn entry(&self, e: &Entry, lang: Lang) -> String {
        match entry_math(e) {
            Some(m) => format!("${m}$"),
            None => match e {
                Entry::Item(k, inner) => format!("[{}] {}", k + 1, self.entry(inner, lang)),
                Entry::Field(name, inner) => {
                    format!("{}: {}", tex::text(name), self.entry(inner, lang))
                }
                _ => said::said(e, lang).latex,
            },
        }
    }
    fn id(&self, id: &str) -> String {
        format!("\\texttt{{{}}}", escape_latex(id))
    }
    fn mistake(&self, m: &Mistake, lang: Lang) -> String {
        mathematics_in_words(&m.phrase(lang))
    }
}

/// A phrase in LaTeX's text mode whose words carry mathematics (a mistake's `the bilinear
/// patch c_cd`): every word through [`tex::words`], which sets a word that looks like
/// mathematics as mathematics and escapes the rest; its mathematics in `$...$`.
pub fn mathematics_in_words(p: &Phrase) -> String {
    said::latex_pieces(p, &tex::words, &|d| {
        // a mistake's identifier is code, set as typed (never as mathematics)
        if cagd_contract::Mistake::from_id(d).is_some() {
            format!("\\texttt{{{}}}", tex::text(d))
        } else {
            tex::words(d)
        }
    })
}

impl Format for Markdown {
    fn said(&self, m: &dyn Message, lang: Lang) -> String {
        escape_markdown(&m.phrase(lang).text())
    }
    fn label(&self, l: &Label) -> String {
        format!("${}$", l.latex)
    }
    fn value(&self, x: &Exact, lang: Lang) -> String {
        // what a student wrote as words is data, shown as written: never in a math span,
        // where Markdown's escapes would not hold
        match words_in(x) {
            true => escape_markdown(&text(x, lang)),
            false => format!("${}$", latex(x, lang)),
        }
    }
    fn entry(&self, e: &Entry, lang: Lang) -> String {
        match entry_math(e) {
            Some(m) => format!("${m}$"),
            None => match e {
                Entry::Item(k, inner) => format!("\\[{}\\] {}", k + 1, self.entry(inner, lang)),
                Entry::Field(name, inner) => {
                    format!("{}: {}", escape_markdown(name), self.entry(inner, lang))
                }
                _ => escape_markdown(&e.phrase(lang).text()),
            },
        }
    }
    fn id(&self, id: &str) -> String {
        format!("`{}`", id.replace('`', "'"))
    }
}

/// Whether a value holds words (text a student wrote where a value was asked, a sentence, a
/// yes or no) anywhere.
fn words_in(x: &Exact) -> bool {
    match x {
        Exact::Text(_) | Exact::Sentence(_) | Exact::Bool(_) => true,
        Exact::List(xs) => xs.iter().any(words_in),
        Exact::Object(kv) => kv.iter().any(|(_, x)| words_in(x)),
        _ => false,
    }
}

/// An entry of a control polygon or mesh as mathematics (`c_{1,1}`, `w_{2}`); `None` for an
/// entry said in words (the knots, the degree).
fn entry_math(e: &Entry) -> Option<String> {
    Some(match e {
        Entry::Point(i) => format!("b_{{{i}}}"),
        Entry::Weight(i) => format!("w_{{{i}}}"),
        Entry::MeshPoint(i, j) => format!("c_{{{i},{j}}}"),
        Entry::MeshWeight(i, j) => format!("w_{{{i},{j}}}"),
        Entry::Component(0) => "x".into(),
        Entry::Component(1) => "y".into(),
        Entry::Component(2) => "z".into(),
        Entry::Component(k) => format!("x_{{{}}}", k + 1),
        Entry::Whole
        | Entry::Knots
        | Entry::KnotsU
        | Entry::KnotsV
        | Entry::Degree
        | Entry::Cell(..)
        | Entry::Extra
        | Entry::Item(..)
        | Entry::Field(..) => return None,
    })
}

/// The lines of an assessment, each with its depth (0 for a result, 1 under it, 2 under a
/// mistake).
fn lines(
    a: &Assessment,
    problem: Option<&Problem>,
    lang: Lang,
    f: &dyn Format,
) -> Vec<(usize, Line)> {
    let mut out = Vec::new();
    if let Some(name) = &a.student {
        let s = AssessmentWords::Student { name: name.clone() };
        out.push((0, Line::Words(f.said(&s, lang))));
    }
    for r in &a.results {
        assessed(r, 0, problem, lang, f, &mut out);
    }
    if !a.steps.is_empty() {
        out.push((0, Line::Words(f.said(&AssessmentWords::StepsWritten, lang))));
        for s in &a.steps {
            assessed(s, 1, problem, lang, f, &mut out);
        }
    }
    if let Some(q) = &a.first_departure {
        let l = names::label(q, problem, lang);
        out.push((
            0,
            Line::Words(format!(
                "{}: {}",
                f.said(&AssessmentWords::FirstDeparture, lang),
                f.label(&l)
            )),
        ));
    }
    out
}

/// The lines of one result (or step) at `depth`: its label and score, its wrong entries, its
/// diagnoses.
fn assessed(
    r: &Assessed,
    depth: usize,
    problem: Option<&Problem>,
    lang: Lang,
    f: &dyn Format,
    out: &mut Vec<(usize, Line)>,
) {
    let label = f.label(&names::label(&r.quantity, problem, lang));
    let (right, total) = (r.right(), r.total());
    if r.correct() {
        let s = AssessmentWords::Correct { right, total };
        out.push((depth, Line::Words(format!("{label}: {}", f.said(&s, lang)))));
        return;
    }
    let s = AssessmentWords::Score { right, total };
    out.push((depth, Line::Words(format!("{label}: {}", f.said(&s, lang)))));
    let inner = depth + 1;
    if r.unknown {
        out.push((inner, Line::Words(f.said(&AssessmentWords::Unknown, lang))));
    }
    if let Some(why) = &r.unread {
        let s = AssessmentWords::Unread {
            why: why.phrase(lang),
        };
        out.push((inner, Line::Words(f.said(&s, lang))));
    } else {
        for m in r.wrong() {
            out.push((inner, Line::Words(wrong_entry(m, lang, f))));
        }
    }
    if r.diagnoses.is_empty() {
        let s = AssessmentWords::NoKnownMistake;
        out.push((inner, Line::Words(f.said(&s, lang))));
    }
    for d in &r.diagnoses {
        diagnosis(d, inner, lang, f, out);
    }
}

/// A wrong entry: `c_1,1: key (1/2, 1, 5); answer (1/2, 5/6, 31/6)`.
fn wrong_entry(m: &Mark, lang: Lang, f: &dyn Format) -> String {
    let entry = f.entry(&m.entry, lang);
    let Some(key) = &m.key else {
        // entries beyond the key's
        return entry;
    };
    let written = match &m.written {
        Some(w) => f.value(w, lang),
        None => f.said(&AssessmentWords::NotWritten, lang),
    };
    if !f.shows_key() {
        return format!(
            "{entry}: {} {written}",
            f.said(&AssessmentWords::Written, lang)
        );
    }
    format!(
        "{entry}: {} {}; {} {written}",
        f.said(&AssessmentWords::Key, lang),
        f.value(key, lang),
        f.said(&AssessmentWords::Written, lang),
    )
}

/// A diagnosis: "ambiguous" over its mistakes when it has several, the entries it explains
/// when not the whole result, and each mistake with its formulas.
fn diagnosis(
    d: &Diagnosis,
    depth: usize,
    lang: Lang,
    f: &dyn Format,
    out: &mut Vec<(usize, Line)>,
) {
    let explains = (!d.whole).then(|| {
        let entries: Vec<String> = d.entries.iter().map(|e| f.entry(e, lang)).collect();
        format!(
            " ({} {})",
            f.said(&AssessmentWords::Explains, lang),
            entries.join(", ")
        )
    });
    let explains = explains.unwrap_or_default();
    let depth = match d.ambiguous() {
        true => {
            out.push((
                depth,
                Line::Words(format!(
                    "{}{explains}",
                    f.said(&AssessmentWords::Ambiguous, lang)
                )),
            ));
            depth + 1
        }
        false => depth,
    };
    for m in &d.mistakes {
        let explains = if d.ambiguous() { "" } else { &explains };
        out.push((
            depth,
            Line::Words(format!(
                "{} {}: {}{explains}; {}",
                f.said(&AssessmentWords::Mistake, lang),
                f.id(m.id()),
                f.mistake(m, lang),
                f.said(&m.place(), lang),
            )),
        ));
        out.push((depth + 1, Line::Formulas(*m)));
    }
}

/// The assessment as plain text, two spaces a level under the verdict's line.
pub(crate) fn text_block(a: &Assessment, problem: Option<&Problem>, lang: Lang) -> String {
    let mut out = String::new();
    for (depth, line) in lines(a, problem, lang, &Text) {
        let indent = "  ".repeat(depth + 1);
        match line {
            Line::Words(w) => out += &format!("{indent}{w}\n"),
            Line::Formulas(m) => {
                let (notes, used) = formula_words(lang);
                let width = notes.chars().count().max(used.chars().count()) + 1;
                out += &format!("{indent}{:<width$} {}\n", notes + ":", m.right().text);
                out += &format!("{indent}{:<width$} {}\n", used + ":", m.used().text);
            }
        }
    }
    out
}

/// The assessment as Markdown: a nested list.
pub(crate) fn markdown_block(a: &Assessment, problem: Option<&Problem>, lang: Lang) -> String {
    markdown_block_with(a, problem, lang, true)
}

/// [`markdown_block`], each wrong entry with the key's value (`key`) or with the student's
/// only.
pub(crate) fn markdown_block_with(
    a: &Assessment,
    problem: Option<&Problem>,
    lang: Lang,
    key: bool,
) -> String {
    let f: &dyn Format = match key {
        true => &Markdown,
        false => &MarkdownWithoutKey,
    };
    let mut out = String::new();
    for (depth, line) in lines(a, problem, lang, f) {
        let indent = "  ".repeat(depth);
        match line {
            Line::Words(w) => out += &format!("{indent}- {w}\n"),
            Line::Formulas(m) => {
                let (notes, used) = formula_words(lang);
                out += &format!("{indent}- {notes}: {}\n", escape_markdown(m.right().text));
                out += &format!("{indent}- {used}: {}\n", escape_markdown(m.used().text));
            }
        }
    }
    out + "\n"
}

/// The assessment as LaTeX: nested lists, each mistake's formula typeset below the notes' one
/// in a two-row display.
pub(crate) fn latex_block(a: &Assessment, problem: Option<&Problem>, lang: Lang) -> String {
    let mut out = String::new();
    let mut open = 0;
    for (depth, line) in lines(a, problem, lang, &Latex) {
        while open <= depth {
            out += "\\begin{itemize}\n";
            open += 1;
        }
        while open > depth + 1 {
            out += "\\end{itemize}\n";
            open -= 1;
        }
        match line {
            // `{}` so that a line that starts with `[` (an item of a list) is no label
            Line::Words(w) => out += &format!("\\item{{}}{w}\n"),
            Line::Formulas(m) => {
                let (notes, used) = formula_words(lang);
                out += &format!(
                    "\\item[] $\\displaystyle \\begin{{aligned}} \\text{{{}:}}\\ & {} \\\\ \\text{{{}:}}\\ & {} \\end{{aligned}}$\n",
                    escape_latex(&notes),
                    m.right().tex,
                    escape_latex(&used),
                    m.used().tex
                );
            }
        }
    }
    while open > 0 {
        out += "\\end{itemize}\n";
        open -= 1;
    }
    out
}

/// The words before the notes' formula and the one used instead.
fn formula_words(lang: Lang) -> (String, String) {
    (
        AssessmentWords::NotesFormula.phrase(lang).text(),
        AssessmentWords::UsedFormula.phrase(lang).text(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_variant_in_both_languages() {
        for m in AssessmentWords::iter() {
            assert_eq!(cagd_words::check_both(&m), Ok(()));
        }
        for total in [1, 9] {
            for correct in [true, false] {
                let m = AssessmentWords::Answer {
                    correct,
                    right: 1,
                    total,
                };
                assert_eq!(cagd_words::check_both(&m), Ok(()));
            }
            for m in [
                AssessmentWords::Correct { right: 1, total },
                AssessmentWords::Score { right: 0, total },
            ] {
                assert_eq!(cagd_words::check_both(&m), Ok(()));
            }
        }
        let one = AssessmentWords::Score { right: 0, total: 1 };
        assert_eq!(one.phrase(Lang::Es).text(), "0 de 1 entrada correcta");
    }

    #[test]
    fn a_mistake_sets_its_mathematics() {
        let m = Mistake::all()
            .into_iter()
            .find(|m| m.id() == "coons.cd_added")
            .unwrap();
        let s = Latex.mistake(&m, Lang::Es);
        assert!(s.contains("$c_{cd}$"), "{s}");
        assert!(!s.contains("\\_"), "{s}");
    }

    #[test]
    fn what_a_student_writes_is_data() {
        use cagd_contract::Quantity;
        let hostile = "<b>*x*</b> [a](javascript:y) $\\input{/etc/passwd}$ \u{1b}[2J";
        let a = Assessment {
            student: Some(hostile.into()),
            results: vec![Assessed {
                quantity: Quantity::Surface,
                marks: vec![Mark {
                    entry: Entry::MeshPoint(0, 1),
                    key: Some(Exact::Int(1)),
                    written: Some(Exact::Text(hostile.into())),
                    right: false,
                }],
                diagnoses: Vec::new(),
                unread: None,
                unknown: false,
            }],
            steps: Vec::new(),
            first_departure: None,
        };
        let markdown = markdown_block(&a, None, Lang::Es);
        assert!(!markdown.contains("<b>"), "{markdown}");
        assert!(!markdown.contains("[a]("), "{markdown}");
        assert!(!markdown.contains("$\\input"), "{markdown}");
        let latex = latex_block(&a, None, Lang::Es);
        assert!(!latex.contains("\\input"), "{latex}");
        let text = text_block(&a, None, Lang::Es);
        assert!(!text.contains('\u{1b}'), "{text}");
        assert!(text.contains("ningún error conocido explica estas entradas"));
    }

    #[test]
    fn a_score_in_words() {
        let s = AssessmentWords::Score { right: 7, total: 9 };
        assert_eq!(s.to_string(), "7 of 9 entries right");
        assert_eq!(s.phrase(Lang::Es).text(), "7 de 9 entradas correctas");
    }
}
