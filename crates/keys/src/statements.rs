//! Statement sheets: the problems of a set for students, in LaTeX, each a question in the
//! notes' language ([`Question`]) and its data described as the notes describe them ("the
//! Bézier curve of control polygon …"), under a header the teacher sets ([`SheetHeader`]),
//! never an answer.

use crate::latex_key::{item_latex, latex_item, latex_preamble};
use crate::parts::{key_parts, Item};
use crate::question::Question;
use crate::said;
use crate::verdict::no_raise;
use crate::vocabulary::Word;
use crate::{escape_markdown, tex, Lang};
use cagd_contract::input::{CurveIn, SurfaceIn};
use cagd_contract::{Argument, Exact, Number, Verdict};
use cagd_linalg::Point;
use cagd_scalar::Print;
use cagd_words::{said as say, Message, Phrase};

/// The header of a statement sheet, as the teacher sets it: the course, the title (by
/// default "Problem sheet") and the date; each is data, written as typed.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct SheetHeader {
    /// The course ("Diseño Geométrico Asistido por Ordenador, 2026/27").
    pub course: Option<String>,
    /// The title; [`SheetWord::DefaultTitle`] when none.
    pub title: Option<String>,
    /// The date, as written ("12 de enero de 2027").
    pub date: Option<String>,
}

impl SheetHeader {
    /// The title given, or the default "Problem sheet" in `lang`.
    pub fn title_in(&self, lang: Lang) -> String {
        self.title
            .clone()
            .filter(|t| !t.trim().is_empty())
            .unwrap_or_else(|| SheetWord::DefaultTitle.phrase(lang).text())
    }
}

/// The fixed words of a statement sheet.
#[derive(Debug, Clone, Copy, PartialEq, Eq, strum::EnumIter)]
pub enum SheetWord {
    /// The default title of a sheet.
    DefaultTitle,
    /// The line where a student writes their name.
    NameLine,
    /// Before the list of data.
    Data,
    /// The first patch of a join.
    FirstPiece,
    /// The second patch of a join.
    SecondPiece,
    /// "the first curve", of a join of curves.
    FirstCurve,
    /// "the second curve".
    SecondCurve,
    /// Between a control polygon or mesh and its weights.
    WithWeights,
    /// Between the control points (and weights) and the knots.
    WithKnots,
    /// Between the knots in u and the knots in v.
    KnotsInUAndV,
    /// After the knots in v.
    InV,
    /// The data points of a fit.
    DataPoints,
    /// A problem that could not be read.
    Unreadable,
}

impl Message for SheetWord {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            SheetWord::DefaultTitle => say(lang, "Problem sheet", "Hoja de problemas", []),
            SheetWord::NameLine => say(lang, "Name:", "Nombre y apellidos:", []),
            SheetWord::Data => say(lang, "Data:", "Datos:", []),
            SheetWord::FirstPiece => say(lang, "the first piece", "el primer trozo", []),
            SheetWord::SecondPiece => say(lang, "the second piece", "el segundo trozo", []),
            SheetWord::FirstCurve => say(lang, "the first curve", "la primera curva", []),
            SheetWord::SecondCurve => say(lang, "the second curve", "la segunda curva", []),
            SheetWord::WithWeights => say(lang, "with weights", "con pesos", []),
            SheetWord::WithKnots => say(lang, "with knots", "con nudos", []),
            SheetWord::KnotsInUAndV => say(lang, "in $u$ and", "en $u$ y", []),
            SheetWord::InV => say(lang, "in $v$", "en $v$", []),
            SheetWord::DataPoints => say(lang, "the data points", "los puntos dato", []),
            SheetWord::Unreadable => say(
                lang,
                "This problem could not be read.",
                "Este problema no se pudo leer.",
                [],
            ),
        }
    }
}

/// What a curve or a surface of the data is, as the notes say it: "the Bézier curve of
/// control polygon", "the B-spline surface of bidegree (2, 1) of control mesh"; the
/// values follow.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Described {
    /// A Bézier curve (rational with weights).
    BezierCurve {
        /// With weights.
        rational: bool,
    },
    /// A B-spline curve of degree p (NURBS with weights).
    BSplineCurve {
        /// The degree.
        degree: usize,
        /// With weights.
        rational: bool,
    },
    /// A Bézier surface (rational with weights).
    BezierSurface {
        /// With weights.
        rational: bool,
    },
    /// A B-spline surface of bidegree (p, q) (NURBS with weights).
    BSplineSurface {
        /// The bidegree.
        degree: (usize, usize),
        /// With weights.
        rational: bool,
    },
}

impl Message for Described {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            Described::BezierCurve { rational: false } => say(
                lang,
                "the Bézier curve of control polygon",
                "la curva de Bézier de polígono de control",
                [],
            ),
            Described::BezierCurve { rational: true } => say(
                lang,
                "the rational Bézier curve of control polygon",
                "la curva racional de Bézier de polígono de control",
                [],
            ),
            Described::BSplineCurve {
                degree,
                rational: false,
            } => say(
                lang,
                "the B-spline curve of degree ‹› of control polygon",
                "la curva B-spline de grado ‹› de polígono de control",
                [degree.into()],
            ),
            Described::BSplineCurve {
                degree,
                rational: true,
            } => say(
                lang,
                "the NURBS curve of degree ‹› of control polygon",
                "la curva NURBS de grado ‹› de polígono de control",
                [degree.into()],
            ),
            Described::BezierSurface { rational: false } => say(
                lang,
                "the Bézier surface of control mesh",
                "la superficie de Bézier de malla de control",
                [],
            ),
            Described::BezierSurface { rational: true } => say(
                lang,
                "the rational Bézier surface of control mesh",
                "la superficie racional de Bézier de malla de control",
                [],
            ),
            Described::BSplineSurface {
                degree: (p, q),
                rational: false,
            } => say(
                lang,
                "the B-spline surface of bidegree $(‹›, ‹›)$ of control mesh",
                "la superficie B-spline de bigrado $(‹›, ‹›)$ de malla de control",
                [p.into(), q.into()],
            ),
            Described::BSplineSurface {
                degree: (p, q),
                rational: true,
            } => say(
                lang,
                "the NURBS surface of bidegree $(‹›, ‹›)$ of control mesh",
                "la superficie NURBS de bigrado $(‹›, ‹›)$ de malla de control",
                [p.into(), q.into()],
            ),
        }
    }
}

/// A sentence of the sheet in LaTeX's text mode.
fn words(m: &dyn Message, lang: Lang) -> String {
    said::said(m, lang).latex
}

/// Numbers in braces, free to break after their commas: `\{0, 0, 1, 1\}`.
fn numbers(xs: &[Number]) -> String {
    let inner: Vec<String> = xs.iter().map(Print::to_latex).collect();
    format!("$\\{{{}\\}}$", inner.join(",\\allowbreak "))
}

/// Points in braces, free to break after their commas.
fn points(ps: &[Point<Number>]) -> String {
    let inner: Vec<String> = ps.iter().map(Point::to_latex).collect();
    format!("$\\{{{}\\}}$", inner.join(",\\allowbreak "))
}

/// A matrix of the data on a line of its own, scaled to the line when wider.
fn matrix(latex: &str) -> String {
    format!("\\\\\n\\hspace*{{1em}}\\fitmath{{{latex}}}")
}

/// How a sheet writes the data: LaTeX (the statement sheet) or Markdown (`cagd serve`'s page).
struct Writer {
    /// A sentence of the sheet.
    words: fn(&dyn Message, Lang) -> String,
    /// Numbers in braces.
    numbers: fn(&[Number]) -> String,
    /// Points in braces.
    points: fn(&[Point<Number>]) -> String,
    /// A matrix (a mesh, its weights) given as LaTeX, on a line of its own.
    matrix: fn(&str) -> String,
    /// What goes before the weights and the knots of a mesh: a new line, or a space.
    line: &'static str,
}

/// The statement sheet's LaTeX.
const LATEX: Writer = Writer {
    words,
    numbers,
    points,
    matrix,
    line: "\\\\\n",
};

/// The page's Markdown: mathematics in `$...$`, a mesh and its weights as displays.
const MARKDOWN: Writer = Writer {
    words: words_markdown,
    numbers: numbers_markdown,
    points: points_markdown,
    matrix: |latex| format!(" $${latex}$$"),
    line: " ",
};

/// A curve or surface of the data described in words with its values, or `None` for a
/// closed form (written as `label = value`).
fn described(value: &Exact, lang: Lang, w: &Writer) -> Option<String> {
    let words = |m: &dyn Message| (w.words)(m, lang);
    let (with_weights, with_knots) = (words(&SheetWord::WithWeights), words(&SheetWord::WithKnots));
    let line = w.line;
    Some(match value {
        Exact::Curve(CurveIn::Bezier { points: p, weights }) => {
            let what = Described::BezierCurve {
                rational: weights.is_some(),
            };
            let mut s = format!("{} {}", words(&what), (w.points)(p));
            if let Some(ws) = weights {
                s += &format!(" {with_weights} {}", (w.numbers)(ws));
            }
            s
        }
        Exact::Curve(CurveIn::BSpline {
            points: p,
            degree,
            knots,
            weights,
        }) => {
            let what = Described::BSplineCurve {
                degree: *degree,
                rational: weights.is_some(),
            };
            let mut s = format!("{} {}", words(&what), (w.points)(p));
            if let Some(ws) = weights {
                s += &format!(" {with_weights} {}", (w.numbers)(ws));
            }
            s + &format!(" {with_knots} {}", (w.numbers)(knots))
        }
        Exact::Surface(SurfaceIn::Bezier { mesh, weights }) => {
            let what = Described::BezierSurface {
                rational: weights.is_some(),
            };
            let mut s = format!("{}{}", words(&what), (w.matrix)(&mesh.to_latex()));
            if let Some(ws) = weights {
                s += &format!("{line}{with_weights}{}", (w.matrix)(&ws.to_latex_numbers()));
            }
            s
        }
        Exact::Surface(SurfaceIn::BSpline {
            mesh,
            degree,
            knots,
            weights,
        }) => {
            let what = Described::BSplineSurface {
                degree: *degree,
                rational: weights.is_some(),
            };
            let mut s = format!("{}{}", words(&what), (w.matrix)(&mesh.to_latex()));
            if let Some(ws) = weights {
                s += &format!("{line}{with_weights}{}", (w.matrix)(&ws.to_latex_numbers()));
            }
            s + &format!(
                "{line}{with_knots} {} {} {} {}",
                (w.numbers)(&knots.0),
                words(&SheetWord::KnotsInUAndV),
                (w.numbers)(&knots.1),
                words(&SheetWord::InV)
            )
        }
        _ => return None,
    })
}

/// Whether an argument is said by the question already (a spline's basis and end
/// conditions, a Coons surface's blending, the common border of a join, how far a profile
/// turns): not listed again.
fn said_by_the_question(argument: Argument) -> bool {
    matches!(
        argument,
        Argument::Basis
            | Argument::EndConditions
            | Argument::Blend
            | Argument::CommonBorder
            | Argument::Arcs
            | Argument::Quadrant
            | Argument::Sweep
            | Argument::Start
    )
}

/// What a data item says before its values, in LaTeX or Markdown: its name when the question
/// refers to it ($c_1$, the first piece, the second curve), and a curve or surface described
/// in words ([`described`]).
fn name_and_description(
    argument: Argument,
    item: &Item,
    lang: Lang,
    w: &Writer,
) -> (Option<String>, Option<String>) {
    let curve = matches!(item.value, Exact::Curve(_));
    let role = |first: bool| {
        let word = match (first, curve) {
            (true, false) => SheetWord::FirstPiece,
            (false, false) => SheetWord::SecondPiece,
            (true, true) => SheetWord::FirstCurve,
            (false, true) => SheetWord::SecondCurve,
        };
        Some((w.words)(&word, lang))
    };
    let name = match argument {
        Argument::C | Argument::D | Argument::C1 | Argument::C2 | Argument::D1 | Argument::D2 => {
            Some(format!("${}$", item.label.latex))
        }
        Argument::First => role(true),
        Argument::Second => role(false),
        _ => None,
    };
    let shape = matches!(
        argument,
        Argument::Surface
            | Argument::Curve
            | Argument::First
            | Argument::Second
            | Argument::C
            | Argument::D
            | Argument::C1
            | Argument::C2
            | Argument::D1
            | Argument::D2
    );
    let described = shape.then(|| described(&item.value, lang, w)).flatten();
    (name, described)
}

/// One item of the data: a curve or surface in words with its values (labelled with its
/// name when the question refers to it: $c_1$, the first piece), any other argument as
/// `label = value`.
fn data_item(argument: Argument, item: &Item, lang: Lang) -> String {
    let (name, described) = name_and_description(argument, item, lang, &LATEX);
    if argument == Argument::Points && item.data {
        // the data points of a fit: a grid on lines of its own, a list free to break
        let value = item_latex(item, lang);
        let value = match item.value {
            Exact::Surface(_) => matrix(&value),
            _ => format!(" ${}$", value.replace(", ", ",\\allowbreak ")),
        };
        return format!("{}:{value}", words(&SheetWord::DataPoints, lang));
    }
    match (described, name) {
        (Some(d), Some(n)) => format!("{n}: {d}"),
        (Some(d), None) => d,
        // an object (a triangle's control net and weights) free to break between its
        // lists, which \left[ ... \right] would make one box
        (None, _) if matches!(item.value, Exact::Object(_)) => latex_item(item, lang)
            .replace("\\left[", "[")
            .replace("\\right]", "]")
            .replace(",\\ ", ",\\allowbreak\\ "),
        (None, _) => latex_item(item, lang),
    }
}

/// One problem as a LaTeX section of a statement sheet (inside [`statement_document`]): its
/// number, the question (a sentence, [`Question`]) and the data described in words, never an
/// answer.
pub fn statement_latex(verdict: &Verdict, lang: Lang) -> String {
    let heading = match verdict.index {
        Some(i) => format!("{} {}", lang.word("Problem"), i + 1),
        None => lang.word("Problem"),
    };
    let mut out = format!("\\section*{{{}}}\n", tex::text(&heading));
    let Some(problem) = verdict.problem.as_deref() else {
        out += &format!("{}\n\n", words(&SheetWord::Unreadable, lang));
        return out;
    };
    out += &format!("{}\n\n", words(&Question::of(problem), lang));
    let k = key_parts(verdict, lang, no_raise);
    let items: Vec<String> = problem
        .inputs()
        .iter()
        .zip(&k.inputs)
        .filter(|((argument, _), _)| !said_by_the_question(*argument))
        .map(|((argument, _), item)| data_item(*argument, item, lang))
        .collect();
    if !items.is_empty() {
        out += &format!(
            "\\smallskip\n{}\n\\begin{{itemize}}\n",
            words(&SheetWord::Data, lang)
        );
        for it in items {
            out += &format!("\\item {it}\n");
        }
        out += "\\end{itemize}\n";
    }
    tex::known_characters(&out)
}

/// A sentence of the sheet in Markdown: words and data escaped ([`escape_markdown`]), its
/// mathematics in `$...$`.
fn words_markdown(m: &dyn Message, lang: Lang) -> String {
    said::latex_pieces(&m.phrase(lang), &escape_markdown, &escape_markdown)
}

/// Numbers in braces, in Markdown's `$...$`.
fn numbers_markdown(xs: &[Number]) -> String {
    let inner: Vec<String> = xs.iter().map(Print::to_latex).collect();
    format!("$\\{{{}\\}}$", inner.join(", "))
}

/// Points in braces, in Markdown's `$...$`.
fn points_markdown(ps: &[Point<Number>]) -> String {
    let inner: Vec<String> = ps.iter().map(Point::to_latex).collect();
    format!("$\\{{{}\\}}$", inner.join(", "))
}

/// [`data_item`] in Markdown: the same item, its mathematics in `$...$`.
fn data_item_markdown(argument: Argument, item: &Item, lang: Lang) -> String {
    let (name, described) = name_and_description(argument, item, lang, &MARKDOWN);
    if argument == Argument::Points && item.data {
        let value = item_latex(item, lang);
        let value = match item.value {
            Exact::Surface(_) => format!(" $${value}$$"),
            _ => format!(" ${value}$"),
        };
        return format!("{}:{value}", words_markdown(&SheetWord::DataPoints, lang));
    }
    match (described, name) {
        (Some(d), Some(n)) => format!("{n}: {d}"),
        (Some(d), None) => d,
        (None, _) => match &item.words {
            Some(words) => format!(
                "{}: {}",
                escape_markdown(&item.label.text),
                words.markdown()
            ),
            None => {
                let sep = match item.sep() {
                    " = " => " = ",
                    _ => "\\colon\\ ",
                };
                format!("${}{sep}{}$", item.label.latex, item_latex(item, lang))
            }
        },
    }
}

/// One problem as Markdown (a web page's statement): the question of [`statement_latex`]
/// and the same data items, its mathematics in `$...$` and `$$...$$`, every word of the
/// problem escaped; no heading (the page shows the problem's title, [`statement_heading`]),
/// never an answer.
pub fn statement_markdown(verdict: &Verdict, lang: Lang) -> String {
    let Some(problem) = verdict.problem.as_deref() else {
        return format!("{}\n", words_markdown(&SheetWord::Unreadable, lang));
    };
    let mut out = format!("{}\n\n", words_markdown(&Question::of(problem), lang));
    let k = key_parts(verdict, lang, no_raise);
    let items: Vec<String> = problem
        .inputs()
        .iter()
        .zip(&k.inputs)
        .filter(|((argument, _), _)| !said_by_the_question(*argument))
        .map(|((argument, _), item)| data_item_markdown(*argument, item, lang))
        .collect();
    if !items.is_empty() {
        out += &format!("{}\n\n", words_markdown(&SheetWord::Data, lang));
        for it in items {
            out += &format!("- {it}\n");
        }
        out += "\n";
    }
    out
}

/// The heading of a problem as its key writes it, plain text: its title in `lang`
/// ("Problema 1: title" when the verdict is numbered in a set), or the operation in words.
pub fn statement_heading(verdict: &Verdict, lang: Lang) -> String {
    key_parts(verdict, lang, no_raise).heading
}

/// The preamble of a statement sheet: the keys' preamble, on portrait pages.
fn sheet_preamble(lang: Lang) -> String {
    latex_preamble(lang).replace("margin=2cm,landscape", "a4paper,margin=2.2cm")
}

/// A complete LaTeX document around sections from [`statement_latex`]: the problems of a
/// set for students, without their answers, under the header the teacher set (title, course,
/// date) and a line for the student's name.
pub fn statement_document(header: &SheetHeader, sections: &[String], lang: Lang) -> String {
    let mut out = sheet_preamble(lang);
    out += "\\begin{document}\n\\begin{center}\n";
    out += &format!(
        "{{\\Large\\bfseries {}}}\\\\[4pt]\n",
        tex::text(&header.title_in(lang))
    );
    for line in [&header.course, &header.date].into_iter().flatten() {
        if !line.trim().is_empty() {
            out += &format!("{}\\\\\n", tex::text(line));
        }
    }
    out += "\\end{center}\n\\bigskip\n";
    out += &format!(
        "{} \\rule{{0.6\\linewidth}}{{0.4pt}}\n\\bigskip\n\n",
        words(&SheetWord::NameLine, lang)
    );
    for s in sections {
        out += s;
    }
    out + "\\end{document}\n"
}

#[cfg(test)]
mod tests {
    use super::*;
    use strum::IntoEnumIterator;

    #[test]
    fn every_sheet_word_in_both_languages() {
        for w in SheetWord::iter() {
            assert_eq!(cagd_words::check_both(&w), Ok(()), "{w:?}");
        }
        for d in [
            Described::BezierCurve { rational: false },
            Described::BezierCurve { rational: true },
            Described::BSplineCurve {
                degree: 2,
                rational: false,
            },
            Described::BSplineCurve {
                degree: 2,
                rational: true,
            },
            Described::BezierSurface { rational: false },
            Described::BezierSurface { rational: true },
            Described::BSplineSurface {
                degree: (2, 1),
                rational: false,
            },
            Described::BSplineSurface {
                degree: (2, 1),
                rational: true,
            },
        ] {
            assert_eq!(cagd_words::check_both(&d), Ok(()), "{d:?}");
        }
    }

    #[test]
    fn the_header_is_data() {
        let header = SheetHeader {
            course: Some("CAGD $x$".into()),
            title: Some("\\input{x}".into()),
            date: None,
        };
        let doc = statement_document(&header, &[], Lang::Es);
        assert!(!doc.contains("\\input{x}"), "{doc}");
        assert!(!doc.contains("CAGD $x$"), "{doc}");
        assert!(doc.contains("Nombre y apellidos:"));
        let plain = statement_document(&SheetHeader::default(), &[], Lang::Es);
        assert!(plain.contains("Hoja de problemas"));
        let en = statement_document(&SheetHeader::default(), &[], Lang::En);
        assert!(en.contains("Problem sheet") && en.contains("Name:"));
    }
}
