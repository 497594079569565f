//! The short legend for readers of Farin or The NURBS Book, where their names differ from the
//! notes', one sentence per kind of formula used: printed once, at the head of a document of
//! keys ([`legend_text`], [`legend_latex`], [`legend_markdown`]), never in every example.

use super::inline_math::{latex_words, math_words};
use crate::escape::escape_html;
use crate::vocabulary::words;
use crate::Lang;
use cagd_contract::steps::{Formula, Step};
use cagd_contract::Verdict;

/// Which readers' legend a formula needs.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Legend {
    Bezier,
    BSpline,
    Patch,
}

fn legend_of(f: Formula) -> Option<Legend> {
    use Formula::*;
    match f {
        DeCasteljau
        | DeCasteljauRational
        | BernsteinSum
        | ElevateCurve
        | RestrictCurve
        | DerivativeCurve
        | ClosedFormCurve
        | ClosedFormRationalCurve
        | InterpolateCurve
        | LeastSquaresCurve => Some(Legend::Bezier),
        DeBoor
        | BSplineSum
        | Boehm
        | ElevateBSpline
        | InterpolateSpline
        | Circle
        | BSplineSurface
        | NurbsSurface
        | InterpolateBicubic
        | PiecewiseSurface
        | DerivativeBSplineSurface
        | KnotLineContinuity
        | SplinePatchesJoin
        | DerivativeBSplineCurve
        | PiecewiseCurve => Some(Legend::BSpline),
        DeCasteljauSurface | BernsteinSurface | RationalSurface | ElevateU | ElevateV
        | ElevateUAtOnce | ElevateVAtOnce | RestrictSurface | DerivativeSurface
        | DerivativeBorder0 | DerivativeBorder1 | CornerNormal | JoinC0 | JoinC1 | JoinCr
        | Graph => Some(Legend::Patch),
        _ => None,
    }
}

fn legend_sentence(l: Legend, lang: Lang) -> &'static str {
    match (l, lang) {
        (Legend::Bezier, Lang::En) => {
            "Farin writes b_i for the control points c_i and b_i^r for c_i^r; The NURBS Book writes P_i."
        }
        (Legend::Bezier, Lang::Es) => {
            "Farin escribe b_i para los puntos de control c_i y b_i^r para c_i^r; Piegl y Tiller escriben P_i."
        }
        (Legend::BSpline, Lang::En) => {
            "The notes' knots are Farin's: The NURBS Book writes P_i for d_i and adds one knot at each end, so its u_i is the notes' u_{i-1}."
        }
        (Legend::BSpline, Lang::Es) => {
            "Los nudos de los apuntes son los de Farin: Piegl y Tiller escriben P_i para d_i y añaden un nudo en cada extremo, de modo que su u_i es el u_{i-1} de los apuntes."
        }
        (Legend::Patch, Lang::En) => {
            "Farin writes b_{i,j} for the mesh c_{i,j}; The NURBS Book writes P_{i,j} and bidegree (p, q) for (m, n)."
        }
        (Legend::Patch, Lang::Es) => {
            "Farin escribe b_{i,j} para la malla c_{i,j}; Piegl y Tiller escriben P_{i,j} y bigrado (p, q) para (m, n)."
        }
    }
}

fn legends(steps: &[Step]) -> Vec<Legend> {
    let mut out = Vec::new();
    for s in steps {
        if let Step::Formula { formula, .. } = s {
            if let Some(l) = legend_of(*formula) {
                if !out.contains(&l) {
                    out.push(l);
                }
            }
        }
    }
    out
}

/// The legends the worked solutions of these verdicts need, each once, in the order met.
fn document_legends<'a>(verdicts: impl IntoIterator<Item = &'a Verdict>) -> Vec<Legend> {
    let mut out = Vec::new();
    for v in verdicts {
        let steps = match &v.answer {
            Ok(a) => a.derivation.as_slice(),
            Err(_) => &[],
        };
        for l in legends(steps) {
            if !out.contains(&l) {
                out.push(l);
            }
        }
    }
    out
}

fn legend_heading(lang: Lang) -> String {
    words(lang, "Notation", "Notación")
}

/// The legend of a document of keys in plain text (empty when no worked solution needs one).
pub fn legend_text<'a>(verdicts: impl IntoIterator<Item = &'a Verdict>, lang: Lang) -> String {
    let sentences: Vec<&str> = document_legends(verdicts)
        .into_iter()
        .map(|l| legend_sentence(l, lang))
        .collect();
    match sentences.is_empty() {
        true => String::new(),
        false => format!("{}: {}\n\n", legend_heading(lang), sentences.join(" ")),
    }
}

/// The legend of a document of keys as a LaTeX paragraph (empty when none is needed).
pub fn legend_latex<'a>(verdicts: impl IntoIterator<Item = &'a Verdict>, lang: Lang) -> String {
    let sentences: Vec<String> = document_legends(verdicts)
        .into_iter()
        .map(|l| latex_words(legend_sentence(l, lang)))
        .collect();
    match sentences.is_empty() {
        true => String::new(),
        false => format!(
            "\\paragraph{{{}}} {}\n\n",
            legend_heading(lang),
            sentences.join(" ")
        ),
    }
}

/// The legend of a document of keys in Markdown (empty when none is needed).
pub fn legend_markdown<'a>(verdicts: impl IntoIterator<Item = &'a Verdict>, lang: Lang) -> String {
    let sentences: Vec<String> = document_legends(verdicts)
        .into_iter()
        .map(|l| math_words(legend_sentence(l, lang), &escape_html))
        .collect();
    match sentences.is_empty() {
        true => String::new(),
        false => format!("*{}:* {}\n\n", legend_heading(lang), sentences.join(" ")),
    }
}
