//! Exact values in the notes' notation: plain text ([`text`], meshes as `{row; row}`) and
//! LaTeX in math mode ([`latex`]).

use crate::escape::{escape_latex, escape_text};
use crate::vocabulary::Word;
use crate::{names, said, tex, Lang};
use cagd_contract::input::{CurveIn, SurfaceIn};
use cagd_contract::value::{matrix_text, numbers_text};
use cagd_contract::{Exact, Number};
use cagd_linalg::Point;
use cagd_scalar::{FieldOps, Print};
use cagd_surface::{Grid, Mesh};

fn points_text(ps: &[Point<Number>]) -> String {
    format!(
        "{{{}}}",
        ps.iter().map(Point::to_text).collect::<Vec<_>>().join(", ")
    )
}

/// The entries of weight zero: the control vectors (homogeneous (v, 0)), as `(index, vector)`.
fn control_vectors<'a>(
    points: &'a [Point<Number>],
    weights: &'a Option<Vec<Number>>,
) -> Vec<(usize, &'a Point<Number>)> {
    let Some(w) = weights else {
        return Vec::new();
    };
    points
        .iter()
        .zip(w)
        .enumerate()
        .filter(|(_, (_, w))| **w == <Number as FieldOps>::from_i64(0))
        .map(|(i, (p, _))| (i, p))
        .collect()
}

/// `, control vector c_1 = (0, 1)` for the entries of weight zero (nothing when none).
fn vectors_text(points: &[Point<Number>], weights: &Option<Vec<Number>>, lang: Lang) -> String {
    control_vectors_in(points, weights, |word, list| {
        let list: Vec<String> = list
            .iter()
            .map(|(i, p)| format!("c_{i} = {}", p.to_text()))
            .collect();
        format!(", {} {}", lang.word(word), list.join(", "))
    })
}

/// The LaTeX of [`vectors_text`].
fn vectors_latex(points: &[Point<Number>], weights: &Option<Vec<Number>>, lang: Lang) -> String {
    control_vectors_in(points, weights, |word, list| {
        let list: Vec<String> = list
            .iter()
            .map(|(i, p)| format!("c_{{{i}}} = {}", p.to_latex()))
            .collect();
        format!(",\\quad {}{}", latex_word(word, lang), list.join(", "))
    })
}

/// The control vectors of a polygon written by `write` (its word, singular or plural, and
/// the vectors), or nothing when there is none.
fn control_vectors_in(
    points: &[Point<Number>],
    weights: &Option<Vec<Number>>,
    write: impl FnOnce(&str, &[(usize, &Point<Number>)]) -> String,
) -> String {
    let vs = control_vectors(points, weights);
    match vs.len() {
        0 => String::new(),
        1 => write("control vector", &vs),
        _ => write("control vectors", &vs),
    }
}

fn grid_text(g: &Grid<Number>) -> String {
    g.to_text_numbers()
}

/// Plain text of an exact value, in the notes' notation (meshes as `{row; row}`).
pub fn text(x: &Exact, lang: Lang) -> String {
    match x {
        Exact::Bool(b) => match (b, lang) {
            (true, Lang::En) => "yes".into(),
            (false, Lang::En) => "no".into(),
            (true, Lang::Es) => "sí".into(),
            (false, Lang::Es) => "no".into(),
        },
        Exact::Int(i) => i.to_string(),
        Exact::Text(t) => escape_text(t),
        Exact::Sentence(m) => escape_text(&said::message(m, lang).text),
        Exact::Number(q) => q.to_text(),
        Exact::Point(p) => p.to_text(),
        Exact::Points(ps) => points_text(ps),
        Exact::Matrix(rows) => matrix_text(rows),
        Exact::Poly(p) => p.to_text(),
        Exact::Map(m) => m.to_text(),
        Exact::Rational(r) => r.to_text(),
        Exact::Curve(c) => curve_text(c, lang),
        Exact::Surface(s) => surface_text(s, lang),
        Exact::List(xs) => format!(
            "[{}]",
            xs.iter()
                .map(|x| text(x, lang))
                .collect::<Vec<_>>()
                .join(item_separator(xs, "; ", ", "))
        ),
        Exact::Object(kv) => kv
            .iter()
            .map(|(k, v)| format!("{} = {}", names::label(k, None, lang).text, text(v, lang)))
            .collect::<Vec<_>>()
            .join(", "),
    }
}

/// Between the items of a list: `between_objects` when every item is an object, a curve or a
/// surface (a list of pieces, `u = [0, 1/2], order = 0; u = [1/2, 1], order = 0`, or of
/// surfaces, each with its degree, mesh and knots, whose own parts are separated by commas),
/// else `otherwise`.
fn item_separator<'a>(xs: &[Exact], between_objects: &'a str, otherwise: &'a str) -> &'a str {
    let compound = |x: &Exact| matches!(x, Exact::Object(_) | Exact::Curve(_) | Exact::Surface(_));
    if !xs.is_empty() && xs.iter().all(compound) {
        between_objects
    } else {
        otherwise
    }
}

fn curve_text(c: &CurveIn<Number>, lang: Lang) -> String {
    match c {
        CurveIn::Bezier { points, weights } => {
            let mut s = format!("{} {}", lang.word("polygon"), points_text(points));
            if let Some(w) = weights {
                s += &format!(", {} {}", lang.word("weights"), numbers_text(w));
            }
            s + &vectors_text(points, weights, lang)
        }
        CurveIn::BSpline {
            points,
            degree,
            knots,
            weights,
        } => {
            let mut s = format!(
                "{} {degree}, {} {}",
                lang.word("degree"),
                lang.word("polygon"),
                points_text(points)
            );
            if let Some(w) = weights {
                s += &format!(", {} {}", lang.word("weights"), numbers_text(w));
            }
            s += &vectors_text(points, weights, lang);
            s + &format!(", {} {}", lang.word("knots"), numbers_text(knots))
        }
        CurveIn::Expr(e) => e.to_text(),
    }
}

fn surface_text(s: &SurfaceIn<Number>, lang: Lang) -> String {
    match s {
        SurfaceIn::Bezier { mesh, weights } => {
            let mut t = format!(
                "{} ({}, {}), {} {}",
                lang.word("bidegree"),
                mesh.rows() - 1,
                mesh.cols() - 1,
                lang.word("mesh"),
                mesh.to_text()
            );
            if let Some(w) = weights {
                t += &format!(", {} {}", lang.word("weights"), grid_text(w));
            }
            t
        }
        SurfaceIn::BSpline {
            mesh,
            degree,
            knots,
            weights,
        } => {
            let mut t = format!(
                "{} ({}, {}), {} {}",
                lang.word("bidegree"),
                degree.0,
                degree.1,
                lang.word("mesh"),
                mesh.to_text()
            );
            if let Some(w) = weights {
                t += &format!(", {} {}", lang.word("weights"), grid_text(w));
            }
            t + &format!(
                ", {} {} × {}",
                lang.word("knots"),
                numbers_text(&knots.0),
                numbers_text(&knots.1)
            )
        }
        SurfaceIn::Expr(e) => e.to_text(),
    }
}

fn latex_points(ps: &[Point<Number>]) -> String {
    format!(
        "\\{{{}\\}}",
        ps.iter()
            .map(Point::to_latex)
            .collect::<Vec<_>>()
            .join(", ")
    )
}

fn latex_numbers(xs: &[Number]) -> String {
    format!(
        "\\{{{}\\}}",
        xs.iter()
            .map(Print::to_latex)
            .collect::<Vec<_>>()
            .join(", ")
    )
}

fn latex_grid(g: &Grid<Number>) -> String {
    g.to_latex_numbers()
}

fn latex_mesh(m: &Mesh<Number>) -> String {
    m.to_latex()
}

/// A word of the keys in math mode: `\text{knots}`.
fn latex_word(key: &str, lang: Lang) -> String {
    format!("\\text{{{} }}", escape_latex(&lang.word(key)))
}

/// LaTeX (math mode) of an exact value; a letter the preamble cannot set (a parameter named
/// `ж`) written visibly ([`tex::known_characters`]).
pub fn latex(x: &Exact, lang: Lang) -> String {
    tex::known_characters(&value_latex(x, lang))
}

fn value_latex(x: &Exact, lang: Lang) -> String {
    match x {
        Exact::Bool(_) => format!("\\text{{{}}}", text(x, lang)),
        Exact::Int(i) => i.to_string(),
        Exact::Text(t) => format!("\\text{{{}}}", escape_latex(t)),
        Exact::Sentence(m) => format!("\\text{{{}}}", said::message(m, lang).latex),
        Exact::Number(q) => q.to_latex(),
        Exact::Point(p) => p.to_latex(),
        Exact::Points(ps) => latex_points(ps),
        Exact::Matrix(rows) => {
            let rs: Vec<String> = rows
                .iter()
                .map(|r| {
                    r.iter()
                        .map(Print::to_latex)
                        .collect::<Vec<_>>()
                        .join(" & ")
                })
                .collect();
            format!("\\begin{{pmatrix}} {} \\end{{pmatrix}}", rs.join(" \\\\ "))
        }
        Exact::Poly(p) => p.to_latex(),
        Exact::Map(m) => m.to_latex(),
        Exact::Rational(r) => r.to_latex(),
        Exact::Curve(c) => match c {
            CurveIn::Bezier { points, weights } => {
                let mut s = latex_points(points);
                if let Some(w) = weights {
                    s += &format!(",\\quad w = {}", latex_numbers(w));
                }
                s + &vectors_latex(points, weights, lang)
            }
            CurveIn::BSpline {
                points,
                degree,
                knots,
                weights,
            } => {
                let mut s = format!(
                    "{} {degree},\\quad {}",
                    latex_word("degree", lang),
                    latex_points(points)
                );
                if let Some(w) = weights {
                    s += &format!(",\\quad w = {}", latex_numbers(w));
                }
                s += &vectors_latex(points, weights, lang);
                s + &format!(
                    ",\\quad {} {}",
                    latex_word("knots", lang),
                    latex_numbers(knots)
                )
            }
            CurveIn::Expr(e) => e.to_latex(),
        },
        Exact::Surface(s) => match s {
            SurfaceIn::Bezier { mesh, weights } => {
                let mut t = latex_mesh(mesh);
                if let Some(w) = weights {
                    t += &format!(",\\quad w = {}", latex_grid(w));
                }
                t
            }
            SurfaceIn::BSpline {
                mesh,
                degree,
                knots,
                weights,
            } => {
                let mut t = format!(
                    "{} ({}, {}),\\quad {}",
                    latex_word("bidegree", lang),
                    degree.0,
                    degree.1,
                    latex_mesh(mesh)
                );
                if let Some(w) = weights {
                    t += &format!(",\\quad w = {}", latex_grid(w));
                }
                t + &format!(
                    ",\\quad {} {} \\times {}",
                    latex_word("knots", lang),
                    latex_numbers(&knots.0),
                    latex_numbers(&knots.1)
                )
            }
            SurfaceIn::Expr(e) => e.to_latex(),
        },
        Exact::List(xs) => format!(
            "\\left[{}\\right]",
            xs.iter()
                .map(|x| latex(x, lang))
                .collect::<Vec<_>>()
                .join(item_separator(xs, ";\\quad ", ", "))
        ),
        Exact::Object(kv) => kv
            .iter()
            .map(|(k, v)| format!("{} = {}", names::label(k, None, lang).latex, latex(v, lang)))
            .collect::<Vec<_>>()
            .join(",\\ "),
    }
}
