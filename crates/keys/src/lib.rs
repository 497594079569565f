//! Answer keys of cagd-exact: text, LaTeX and Markdown, in English or in the notes' Spanish.
//!
//! A key is written from a [`Verdict`]: the typed problem (its fixture fields, its arguments in
//! the order written) and its answer (results, steps, remarks), and the comparison with
//! `expected` when the problem says what to expect. Nothing here reads JSON or solves.

pub mod names;

pub use names::Label;
pub use said::Sentence;
pub use sentences::{CurvatureSign, KeyRemark, Keyword, Raise};

use cagd_linalg::Point;
use cagd_problem::input::{CurveIn, SurfaceIn};
use cagd_problem::value::{matrix_text, numbers_text};
use cagd_problem::Number;
use cagd_problem::{Exact, Limit, Meta, ProblemError, Verdict};
use cagd_scalar::Print;
use cagd_surface::{Grid, Mesh};

pub mod said;
pub mod sentences;
pub mod steps;
pub mod tex;

pub use cagd_words::Lang;

/// The fixed words of the keys (headings, labels) in each language.
pub trait Word {
    /// A word of the answer keys in this language.
    fn word(self, key: &str) -> String;
}

impl Word for Lang {
    fn word(self, key: &str) -> String {
        let es = match key {
            "source" => "fuente",
            "the notes, eq." => "los apuntes, ec.",
            "input" => "datos",
            "steps" => "pasos",
            "result" => "resultado",
            "verdict" => "veredicto",
            "matches the notes" => "coincide con los apuntes",
            "matches the expected answer" => "coincide con la respuesta esperada",
            "erratum" => "errata",
            "the notes print" => "los apuntes dicen",
            "the exact value is" => "el valor exacto es",
            "mesh" => "malla de control",
            "weights" => "pesos",
            "knots" => "nudos",
            "bidegree" => "bigrado",
            "degree" => "grado",
            "polygon" => "polígono de control",
            "closed form" => "parametrización",
            "error" => "error",
            "failed" => "falla",
            "Answer key" => "Soluciones",
            "Problem" => "Problema",
            "problem" => "problema",
            "field" => "campo",
            "remarks" => "observaciones",
            "note" => "nota",
            "operation" => "operación",
            "Statements" => "Enunciados",
            "Data" => "Datos",
            "Find" => "Calcula",
            other => other,
        };
        match self {
            Lang::En => key.to_string(),
            Lang::Es => es.to_string(),
        }
    }
}

fn points_text(ps: &[Point<Number>]) -> String {
    format!(
        "{{{}}}",
        ps.iter().map(Point::to_text).collect::<Vec<_>>().join(", ")
    )
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
            .map(|(k, v)| {
                format!(
                    "{} = {}",
                    names::label(k, v, None, lang).text,
                    text(v, lang)
                )
            })
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
            s
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
                s
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
            .map(|(k, v)| {
                format!(
                    "{} = {}",
                    names::label(k, v, None, lang).latex,
                    latex(v, lang)
                )
            })
            .collect::<Vec<_>>()
            .join(",\\ "),
    }
}

/// A result or step name as LaTeX: `c_hat` → `\hat{c}`, `c_cd` → `c_{cd}`, `B_U` → `B_{U}`, and
/// a formula of names term by term.
///
/// ```
/// use cagd_keys::latex_name;
/// assert_eq!(latex_name("c_cd"), "c_{cd}");
/// assert_eq!(latex_name("d_tilde"), "\\tilde{d}");
/// assert_eq!(latex_name("c_uv · (c_u × c_v)"), "c_{uv}\\cdot (c_{u}\\times c_{v})");
/// assert_eq!(latex_name("weights"), "\\text{weights}");
/// ```
pub fn latex_name(name: &str) -> String {
    if let Some(x) = name
        .strip_suffix("_tilde")
        .filter(|x| x.chars().count() == 1)
    {
        return format!("\\tilde{{{}}}", tex::math(x));
    }
    if let Some(x) = name.strip_suffix("_hat").filter(|x| x.chars().count() == 1) {
        return format!("\\hat{{{}}}", tex::math(x));
    }
    match name {
        "closed_form" => "c(u, v)".into(),
        _ if name.contains([' ', '·', '×', '(']) => {
            // a formula of names, as the developable test's `c_uv · (c_u × c_v)`
            let mut out = String::new();
            let mut word = String::new();
            for c in name.chars().chain([' ']) {
                if c.is_alphanumeric() || c == '_' {
                    word.push(c);
                    continue;
                }
                if !word.is_empty() {
                    out += &latex_name(&word);
                    word.clear();
                }
                match c {
                    '·' => out += "\\cdot ",
                    '×' => out += "\\times ",
                    ' ' => {}
                    _ => out += &tex::math(&c.to_string()),
                }
            }
            out.trim_end().to_string()
        }
        _ => match name.split_once('_') {
            // a name with an index: letters and digits, braces balanced (`c_{1,0}`)
            Some((a, b))
                if !a.is_empty()
                    && !b.is_empty()
                    && a.len() <= 3
                    && index_like(a)
                    && index_like(b) =>
            {
                format!("{a}_{{{}}}", b.replace('_', ","))
            }
            _ => format!("\\text{{{}}}", escape_latex(&name.replace('_', " "))),
        },
    }
}

/// A part of a name that [`latex_name`] writes as it is: ASCII letters and digits, `,`, `_`,
/// and braces that close what they open; or one letter the preamble declares (`β_{1}`).
fn index_like(s: &str) -> bool {
    let mut depth = 0usize;
    for c in s.chars() {
        match c {
            '{' => depth += 1,
            '}' if depth == 0 => return false,
            '}' => depth -= 1,
            c if c.is_ascii_alphanumeric() || matches!(c, ',' | '_') => {}
            c if s.chars().count() == 1 && !tex::math(&c.to_string()).contains('\\') => {}
            _ => return false,
        }
    }
    depth == 0
}

/// Text for LaTeX's text mode, every special character escaped: [`tex::text`], the one
/// escaper, under its older name.
pub fn escape_latex(s: &str) -> String {
    tex::text(s)
}

/// The fixture's fields of a verdict's problem (empty when it could not be read).
fn meta(v: &Verdict) -> (Meta, String) {
    match &v.problem {
        Some(p) => (p.meta.clone(), p.op.name().to_string()),
        None => (Meta::default(), String::new()),
    }
}

/// What an operation computes, in words: the line under a key's heading.
pub fn op_words(op: &str, lang: Lang) -> &'static str {
    let (en, es) = match op {
        "evaluate" => ("evaluation", "evaluación"),
        "closed_form" => ("closed form", "parametrización"),
        "restrict" => ("restriction to a subdomain", "restricción a un subrecinto"),
        "elevate" => ("degree elevation", "elevación del grado"),
        "derivative" => ("derivative", "derivada"),
        "normal" => ("normal vector", "vector normal"),
        "continuity" => (
            "continuity of a join",
            "continuidad de la unión de dos parches",
        ),
        "interpolate" => ("interpolation", "interpolación"),
        "approximate" => (
            "least-squares approximation",
            "aproximación por mínimos cuadrados",
        ),
        "translational" => ("translational surface", "superficie traslacional"),
        "ruled" => ("ruled surface", "superficie reglada"),
        "developable" => ("developability test", "test de desarrollabilidad"),
        "coons" => ("Coons surface", "superficie de Coons"),
        "revolution" => ("surface of revolution", "superficie de revolución"),
        "insert_knot" => ("knot insertion", "algoritmo de inserción"),
        "graph" => ("graph of a function", "gráfica de una función"),
        "circle" => ("circle", "circunferencia"),
        "blossom" => ("blossom (polar form)", "forma polar"),
        "subdivide" => ("subdivision", "subdivisión"),
        "boundary" => ("boundary curves", "curvas borde"),
        "isocurve" => ("iso-parametric curve", "curva isoparamétrica"),
        "extract" => ("Bézier extraction", "extracción de los trozos de Bézier"),
        "remove_knot" => ("knot removal", "eliminación de un nudo"),
        "reverse" => ("reversal", "inversión del sentido"),
        "reduce_degree" => ("degree reduction", "reducción del grado"),
        "curve_continuity" => (
            "continuity of two curves",
            "continuidad de la unión de dos curvas",
        ),
        "gaussian_curvature" => ("Gaussian curvature", "curvatura de Gauss"),
        "tangent_developable" => (
            "tangent developable surface",
            "superficie desarrollable tangencial",
        ),
        "conic" => ("conic", "cónica"),
        "arc_length" => ("arc length", "longitud de arco"),
        // an operation without words: its name is printed (never an empty title)
        _ => ("", ""),
    };
    match lang {
        Lang::En => en,
        Lang::Es => es,
    }
}

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

impl Item {
    /// Between the label and the value: ` = `, or `: ` before equations (`at: u = 1`).
    fn sep(&self) -> &'static str {
        match self.value {
            Exact::Object(_) => ": ",
            _ => " = ",
        }
    }
}

/// One input, step or result of a key: its label and its value.
struct Item {
    label: Label,
    value: Exact,
    /// The value written as data points (an interpolation's grid), not as a control mesh.
    data: bool,
    /// The value in words, after the label (`parameters from the data = chord length`): a
    /// sentence, a keyword, a sign, or text.
    words: Option<Sentence>,
}

/// The parts of an answer key, shared by the text, LaTeX and Markdown writers.
struct KeyParts {
    heading: String,
    source: String,
    note: Option<String>,
    op: String,
    inputs: Vec<Item>,
    steps: Vec<Item>,
    result: Vec<Item>,
    remarks: Vec<Sentence>,
    error: Option<Sentence>,
    verdict: Sentence,
}

fn items(named: &[(String, Exact)], verdict: &Verdict, lang: Lang) -> Vec<Item> {
    let problem = verdict.problem.as_deref();
    let op = problem.map(|p| p.op.name()).unwrap_or_default();
    named
        .iter()
        .map(|(name, given)| {
            let value = curvature_sign_words(name, given, op, lang);
            Item {
                label: names::label(name, given, problem, lang),
                words: item_words(name, &value, op, lang),
                value,
                data: (name == "points" && matches!(op, "interpolate" | "approximate"))
                    || name == "C_tilde"
                    || name == "d_tilde",
            }
        })
        .collect()
}

/// The words of an item's value, when it is said in words: a sentence of the engine in the
/// language asked, a keyword argument of a problem (`basis`, `end`, `blend`, `direction`, an
/// interpolation's `parametrization`) as words (`chord_length` is "chord length", `bessel`
/// "Bessel", in Spanish where it has words of its own: [`Keyword`]), other text as it is.
fn item_words(name: &str, value: &Exact, op: &str, lang: Lang) -> Option<Sentence> {
    let keyword = matches!(name, "basis" | "end" | "blend" | "direction")
        || (name == "parametrization" && matches!(op, "interpolate" | "approximate"));
    match value {
        Exact::Sentence(m) => Some(said::message(m, lang)),
        Exact::Text(k) if keyword => Some(match Keyword::of(k) {
            Some(w) => said::said(&w, lang),
            None => Sentence::data(&sentences::keyword_text(k)),
        }),
        Exact::Text(t) => Some(Sentence::data(t)),
        _ => None,
    }
}

/// The `sign` of `gaussian_curvature` (1, -1, or 0 when G vanishes somewhere on the domain,
/// docs/format.md), in words: "positive (G > 0)", "negative (G < 0)", "none (G vanishes on
/// the domain)" ([`CurvatureSign`]), also in each piece of a B-spline surface's `pieces`. A
/// bare 0 read as if G vanished everywhere.
fn curvature_sign_words(name: &str, value: &Exact, op: &str, lang: Lang) -> Exact {
    if op != "gaussian_curvature" {
        return value.clone();
    }
    match (name, value) {
        ("sign", Exact::Int(s)) => {
            let words = CurvatureSign::of(*s);
            Exact::Text(cagd_words::Message::phrase(&words, lang).text())
        }
        (_, Exact::List(xs)) => Exact::List(
            xs.iter()
                .map(|x| curvature_sign_words("", x, op, lang))
                .collect(),
        ),
        (_, Exact::Object(fields)) => Exact::Object(
            fields
                .iter()
                .map(|(k, x)| (k.clone(), curvature_sign_words(k, x, op, lang)))
                .collect(),
        ),
        (_, v) => v.clone(),
    }
}

/// Whether a problem gives its knots with the end knots (Piegl and Tiller's convention, one
/// more knot at each end than the notes'): its keys then print the answer's knots so too.
fn full_knots(inputs: &[(String, Exact)]) -> bool {
    inputs.iter().any(|(_, v)| match v {
        Exact::Curve(CurveIn::BSpline {
            points,
            degree,
            knots,
            ..
        }) => knots.len() == points.len() + degree + 1,
        Exact::Surface(SurfaceIn::BSpline {
            mesh,
            degree,
            knots,
            ..
        }) => knots.0.len() == mesh.rows() + degree.0 + 1,
        _ => false,
    })
}

/// A knot vector of the notes' convention with one more knot at each end.
fn with_end_knots(knots: &[Number]) -> Vec<Number> {
    let mut out = Vec::with_capacity(knots.len() + 2);
    out.extend(knots.first().cloned());
    out.extend(knots.iter().cloned());
    out.extend(knots.last().cloned());
    out
}

/// A result with its knots in the full convention (the answer's are in the notes').
fn in_full_convention(value: &Exact) -> Option<Exact> {
    match value {
        Exact::Curve(CurveIn::BSpline {
            points,
            degree,
            knots,
            weights,
        }) => Some(Exact::Curve(CurveIn::BSpline {
            points: points.clone(),
            degree: *degree,
            knots: with_end_knots(knots),
            weights: weights.clone(),
        })),
        Exact::Surface(SurfaceIn::BSpline {
            mesh,
            degree,
            knots,
            weights,
        }) => Some(Exact::Surface(SurfaceIn::BSpline {
            mesh: mesh.clone(),
            degree: *degree,
            knots: (with_end_knots(&knots.0), with_end_knots(&knots.1)),
            weights: weights.clone(),
        })),
        _ => None,
    }
}

fn key_parts(verdict: &Verdict, lang: Lang, raise: RaiseWith) -> KeyParts {
    let (meta, op) = meta(verdict);
    let es = meta.es.clone().unwrap_or_default();
    let name = meta.name.clone().unwrap_or_default();
    let title = match lang {
        Lang::Es => es.title.clone().or(meta.title.clone()),
        Lang::En => meta.title.clone(),
    }
    .unwrap_or_default();
    let problem = match verdict.index {
        Some(i) => format!("{} {}", lang.word("Problem"), i + 1),
        None => lang.word("Problem"),
    };
    let heading = match (name.is_empty(), title.is_empty()) {
        (false, false) => format!("{name}: {title}"),
        (false, true) => name,
        (true, false) if verdict.index.is_some() => format!("{problem}: {title}"),
        (true, false) => title,
        (true, true) if op.is_empty() => problem,
        (true, true) => format!("{problem} ({})", op_words(&op, lang)),
    };
    let source = meta.source.clone().unwrap_or_default();
    let source = match meta.equation.as_deref() {
        None | Some("") => source,
        // an example beyond the notes that uses an equation of theirs
        Some(eq) if source.is_empty() => format!(
            "{} ({})",
            lang.word("the notes, eq."),
            eq.trim_matches(['(', ')'])
        ),
        Some(eq) => format!("{source}, ({})", eq.trim_matches(['(', ')'])),
    };
    let note = match lang {
        Lang::Es => es.note.clone().or(meta.note.clone()),
        Lang::En => meta.note.clone(),
    }
    .filter(|n| !n.is_empty());
    let none = Vec::new();
    let (steps, result, remarks, error) = match &verdict.answer {
        Ok(a) => (
            items(&a.steps, verdict, lang),
            items(&a.result, verdict, lang),
            a.remarks.iter().map(|r| said::message(r, lang)).collect(),
            None,
        ),
        Err(e) => (
            none,
            Vec::new(),
            Vec::new(),
            Some(error_sentence_with(e, lang, raise)),
        ),
    };
    let inputs = verdict
        .problem
        .as_ref()
        .map(|p| p.inputs())
        .unwrap_or_default();
    let (mut steps, mut result, mut remarks) = (steps, result, remarks);
    if full_knots(&inputs) {
        // the knots in the convention the problem gave them, and a word to say so
        let mut converted = false;
        for it in steps.iter_mut().chain(result.iter_mut()) {
            if let Some(v) = in_full_convention(&it.value) {
                it.value = v;
                converted = true;
            }
        }
        if converted {
            remarks.push(said::said(&KeyRemark::FullKnots, lang));
        }
    }
    KeyParts {
        heading,
        source,
        note,
        op,
        inputs: items(&inputs, verdict, lang),
        steps,
        result,
        remarks,
        error,
        verdict: verdict_sentence(verdict, lang, raise),
    }
}

/// The plain text of an item's value.
fn item_text(it: &Item, lang: Lang) -> String {
    match (&it.value, it.data) {
        (
            Exact::Surface(SurfaceIn::Bezier {
                mesh,
                weights: None,
            }),
            true,
        ) => mesh.to_text(),
        (v, _) => match &it.words {
            Some(w) => escape_text(&w.text),
            None => text(v, lang),
        },
    }
}

/// The LaTeX (math mode) of an item's value.
fn item_latex(it: &Item, lang: Lang) -> String {
    match (&it.value, it.data) {
        (
            Exact::Surface(SurfaceIn::Bezier {
                mesh,
                weights: None,
            }),
            true,
        ) => mesh.to_latex(),
        // a rational map: its numerator over w, and w on a line of its own (a fraction of
        // long polynomials cannot break across lines)
        (Exact::Rational(r), _) if r.denominator().to_text() != "1" => format!(
            "\\frac{{1}}{{w}}\\, {},\\quad w = {}",
            r.numerator().to_latex(),
            r.denominator().to_latex()
        ),
        (v, _) => latex(v, lang),
    }
}

/// The plain-text answer key of one problem (or checked example): name, source, input,
/// steps, result and verdict.
pub fn example_text(verdict: &Verdict, lang: Lang) -> String {
    example_text_with(verdict, lang, no_raise)
}

/// [`example_text`] written by a front end that says how to raise a limit.
pub fn example_text_with(verdict: &Verdict, lang: Lang, raise: RaiseWith) -> String {
    let k = key_parts(verdict, lang, raise);
    let mut out = String::new();
    out += &format!("== {}\n", escape_text(&k.heading));
    if !k.source.is_empty() {
        out += &format!("{}: {}\n", lang.word("source"), escape_text(&k.source));
    }
    if let Some(n) = &k.note {
        out += &format!("{}: {}\n", lang.word("note"), escape_text(n));
    }
    if verdict.problem.is_some() {
        out += &format!(
            "{}: {} (`{}`)\n",
            lang.word("operation"),
            op_words(&k.op, lang),
            k.op
        );
        out += &format!("{}:\n", lang.word("input"));
        for it in &k.inputs {
            out += &format!("  {}{}{}\n", it.label.text, it.sep(), item_text(it, lang));
        }
    }
    if verdict.answer.is_ok() {
        out += &steps::text_block(verdict, lang);
        if !k.steps.is_empty() {
            out += &format!("{}:\n", lang.word("steps"));
            for it in &k.steps {
                out += &format!("  {} = {}\n", it.label.text, value_lines(it, lang));
            }
        }
        out += &format!("{}:\n", lang.word("result"));
        for it in &k.result {
            out += &format!("  {} = {}\n", it.label.text, value_lines(it, lang));
        }
        for r in &k.remarks {
            out += &format!("  ({})\n", escape_text(&r.text));
        }
    }
    if let Some(e) = &k.error {
        out += &format!("{}: {}\n", lang.word("error"), escape_text(&e.text));
    }
    if verdict.checked {
        out += &format!(
            "{}: {}\n",
            lang.word("verdict"),
            escape_text(&k.verdict.text)
        );
    }
    out
}

/// The text of an item's value, a mesh (or matrix) with one row per line; a sentence as it is.
fn value_lines(it: &Item, lang: Lang) -> String {
    match &it.words {
        Some(_) => item_text(it, lang),
        None => rows_on_lines(&item_text(it, lang)),
    }
}

/// A value of the text key with one mesh (or matrix) row per line, as the notes print them:
/// rows are the only things separated by `;`.
fn rows_on_lines(text: &str) -> String {
    text.replace("; ", ";\n      ")
}

/// `matches the notes`, `erratum: the notes print X, the exact value is Y`, or the failure.
pub fn verdict_text(v: &Verdict, lang: Lang) -> String {
    verdict_sentence(v, lang, no_raise).text
}

/// The verdict as text and LaTeX.
fn verdict_sentence(v: &Verdict, lang: Lang, raise: RaiseWith) -> Sentence {
    if let Err(e) = &v.answer {
        let s = error_sentence_with(e, lang, raise);
        return Sentence {
            text: format!("{}: {}", lang.word("failed"), s.text),
            latex: format!("{}: {}", lang.word("failed"), s.latex),
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
        text.push(format!(
            "{} ({place}): {} {printed}, {} {exact}{}",
            lang.word("erratum"),
            lang.word("the notes print"),
            lang.word("the exact value is"),
            if why.is_empty() {
                String::new()
            } else {
                format!(" — {why}")
            }
        ));
        tex.push(format!(
            "{} ({}): {} {}, {} {}{}",
            lang.word("erratum"),
            tex::words(&place),
            lang.word("the notes print"),
            formula_latex(&printed),
            lang.word("the exact value is"),
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

/// The LaTeX of one item: `$\displaystyle label = value$`, matrices scaled to the line when
/// wider, lists free to break after a comma.
fn latex_item(it: &Item, lang: Lang) -> String {
    if let Some(words) = &it.words {
        if let (Exact::Text(t), "c(u, v)") = (&it.value, it.label.text.as_str()) {
            // the parametrization of a surface of revolution: mathematics with cos v, sin v
            return format!("$\\displaystyle {} = {}$", it.label.latex, tex::math(t));
        }
        return format!("${}$: {}", it.label.latex, words.latex);
    }
    // a closed form breaks inside its parentheses; a list of points between them
    let value = item_latex(it, lang);
    // a list of surfaces breaks between the meshes of its surfaces (below), and a list of
    // pieces between its pieces, which the brackets \left[ ... \right] could not span
    let value = if value.contains(",\\quad ") || value.contains(";\\quad ") {
        value.replace("\\left[", "[").replace("\\right]", "]")
    } else {
        value
    };
    let formula = match it.value {
        Exact::Map(_) | Exact::Rational(_) | Exact::Poly(_) => true,
        // a point in letters, long as a closed form
        Exact::Point(_) => value.len() > 120,
        _ => false,
    };
    // a mesh, its weights and its knots: one line each
    let parts: Vec<String> = value
        .split(",\\quad ")
        .map(|part| match formula {
            true => fit_matrices(&open_parentheses(part)),
            false => fit_matrices(part),
        })
        .collect();
    let item = format!(
        "$\\displaystyle {}{}{}$",
        it.label.latex,
        if it.sep() == " = " {
            " = "
        } else {
            "\\colon\\ "
        },
        parts.join(",$\\newline$\\displaystyle ")
    );
    if formula && value.len() > LONG_FORMULA {
        // a long polynomial breaks only after its + and -, between terms of a few hundred
        // points each (the fractions of a big interpolation): set ragged right, a line may
        // end short instead of running off the page
        format!("{{\\raggedright {item}\\par}}")
    } else {
        item
    }
}

/// The length (in characters of LaTeX) above which a formula of a key is set ragged right,
/// free to end a line short between its terms ([`latex_item`]).
const LONG_FORMULA: usize = 250;

/// Wraps every matrix of a formula in `\fitmath{...}` (scaled down to the line when wider,
/// see [`latex_document`]) and lets lists break after their commas.
fn fit_matrices(math: &str) -> String {
    let mut out = String::new();
    let mut rest = math;
    while let Some(i) = rest.find("\\begin{") {
        let (before, tail) = rest.split_at(i);
        out += &breakable(before);
        let env = tail
            .get(7..)
            .and_then(|t| t.split_once('}'))
            .map(|(e, _)| e)
            .unwrap_or_default();
        let end = format!("\\end{{{env}}}");
        match tail.find(&end) {
            Some(j) => {
                let (m, after) = tail.split_at(j + end.len());
                out += &format!("\\fitmath{{{m}}}");
                rest = after;
            }
            None => {
                out += tail;
                rest = "";
            }
        }
    }
    out + &breakable(rest)
}

/// The worked solution's long lines (closed forms in letters, a hundred terms) free to break
/// inside their parentheses.
fn long_lines_breakable(tex: &str) -> String {
    tex.split_inclusive('\n')
        .map(|line| match line.len() > 250 {
            true => open_parentheses(&columns_as_tuples(line)),
            false => line.to_string(),
        })
        .collect()
}

/// A column vector `\begin{pmatrix} a \\ b \end{pmatrix}` written as the tuple `(a, b)`,
/// which can break across lines (a matrix cannot); a matrix with columns is left alone.
fn columns_as_tuples(line: &str) -> String {
    let (open, close) = ("\\begin{pmatrix}", "\\end{pmatrix}");
    let mut out = String::new();
    let mut rest = line;
    while let Some(i) = rest.find(open) {
        let (before, tail) = rest.split_at(i);
        out += before;
        let Some(j) = tail.find(close) else {
            rest = tail;
            break;
        };
        let inner = &tail[open.len()..j];
        if inner.contains('&') {
            out += &tail[..j + close.len()];
        } else {
            let rows: Vec<&str> = inner.split("\\\\").map(str::trim).collect();
            out += &format!("({})", rows.join(", "));
        }
        rest = &tail[j + close.len()..];
    }
    out + rest
}

/// A formula whose parentheses do not stop a line break: `\left(...\right)` is one box to
/// TeX, `(...)` is not.
fn open_parentheses(math: &str) -> String {
    math.replace("\\left(", "(").replace("\\right)", ")")
}

/// A formula free to break after its commas (inline math breaks only where allowed).
fn breakable(math: &str) -> String {
    math.replace(",\\quad ", ",\\allowbreak\\quad ")
        .replace(";\\quad ", ";\\allowbreak\\quad ")
        .replace(", ", ",\\allowbreak ")
}

/// One example as a LaTeX section (inside [`latex_document`]).
pub fn example_latex(verdict: &Verdict, lang: Lang) -> String {
    example_latex_with(verdict, lang, no_raise)
}

/// [`example_latex`] written by a front end that says how to raise a limit.
pub fn example_latex_with(verdict: &Verdict, lang: Lang, raise: RaiseWith) -> String {
    let k = key_parts(verdict, lang, raise);
    let mut out = format!("\\section*{{{}}}\n", tex::words(&k.heading));
    if !k.source.is_empty() {
        out += &format!(
            "\\textit{{{}: {}}}\\\\\n",
            lang.word("source"),
            escape_latex(&k.source)
        );
    }
    if let Some(n) = &k.note {
        out += &format!("\\textit{{{}:}} {}\\\\\n", lang.word("note"), tex::words(n));
    }
    if !k.op.is_empty() {
        out += &format!(
            "{}: {} (\\texttt{{{}}})\n",
            lang.word("operation"),
            op_words(&k.op, lang),
            escape_latex(&k.op)
        );
    }
    let block = |title: &str, items: &[Item]| -> String {
        if items.is_empty() {
            return String::new();
        }
        let mut b = format!(
            "\\paragraph{{{}}}\n\\begin{{itemize}}\n",
            escape_latex(title)
        );
        for it in items {
            b += &format!("\\item {}\n", latex_item(it, lang));
        }
        b + "\\end{itemize}\n"
    };
    out += &block(&lang.word("input"), &k.inputs);
    out += &long_lines_breakable(&steps::latex_block(verdict, lang));
    out += &block(&lang.word("steps"), &k.steps);
    out += &block(&lang.word("result"), &k.result);
    for r in &k.remarks {
        out += &format!("\\textit{{{}}}\\\\\n", r.latex);
    }
    if let Some(e) = &k.error {
        out += &format!("\\textbf{{{}}}: {}\\\\\n", lang.word("error"), e.latex);
    }
    if verdict.checked {
        out += &format!(
            "\\paragraph{{{}}} {}\n\n",
            escape_latex(&lang.word("verdict")),
            k.verdict.latex
        );
    }
    tex::known_characters(&out)
}

/// The preamble of every LaTeX document of cagd-exact: vector fonts (T1, Latin Modern), the
/// AMS packages, landscape pages, and `\fitmath`, which scales a formula down to 0.8 of the
/// line when it is wider (the hemisphere's 9-column meshes), leaving room for its label (the
/// Spanish `puntos de datos =` before a scaled grid of data).
pub fn latex_preamble(lang: Lang) -> String {
    let babel = match lang {
        Lang::En => "",
        Lang::Es => "",
    };
    // the mathematical characters a note or a title may have in its words, and Greek letters
    let unicode = tex::declarations();
    format!(
        "\\documentclass[10pt]{{article}}\n\
         \\usepackage[utf8]{{inputenc}}\n\
         \\usepackage[T1]{{fontenc}}\n\
         \\usepackage{{lmodern}}\n{babel}\
         \\usepackage{{amsmath,amssymb}}\n\
         \\usepackage[margin=2cm,landscape]{{geometry}}\n\
         \\usepackage{{graphicx}}\n\
         \\setcounter{{MaxMatrixCols}}{{40}}\n\
         {unicode}\
         \\allowdisplaybreaks\n\
         \\setlength{{\\parindent}}{{0pt}}\n\
         \\emergencystretch=3em\n\
         \\newsavebox{{\\cagdbox}}\n\
         \\newcommand{{\\fitmath}}[1]{{\\sbox{{\\cagdbox}}{{$\\displaystyle #1$}}%\n\
         \\ifdim\\wd\\cagdbox>0.8\\linewidth\\resizebox{{0.8\\linewidth}}{{!}}{{\\usebox{{\\cagdbox}}}}%\n\
         \\else\\usebox{{\\cagdbox}}\\fi}}\n"
    )
}

/// A complete LaTeX document around sections from [`example_latex`]; compiles with pdflatex.
pub fn latex_document(title: &str, sections: &[String], lang: Lang) -> String {
    let mut out = latex_preamble(lang);
    out += &format!(
        "\\title{{{}}}\n\\date{{}}\n\\begin{{document}}\n\\maketitle\n",
        tex::words(&format!("{}: {title}", lang.word("Answer key")))
    );
    for s in sections {
        out += s;
    }
    out + "\\end{document}\n"
}

/// One problem as a LaTeX section of a statement sheet (inside [`statement_document`]): its
/// number and title, the data, and what to find (the names of its results), never an answer.
pub fn statement_latex(verdict: &Verdict, lang: Lang) -> String {
    let k = key_parts(verdict, lang, no_raise);
    let (meta, _) = meta(verdict);
    let title = match lang {
        Lang::Es => meta
            .es
            .as_ref()
            .and_then(|e| e.title.clone())
            .or(meta.title.clone()),
        Lang::En => meta.title.clone(),
    }
    .unwrap_or_else(|| op_words(&k.op, lang).to_string());
    let heading = match verdict.index {
        Some(i) => format!("{} {}: {title}", lang.word("Problem"), i + 1),
        None => title,
    };
    let mut out = format!("\\section*{{{}}}\n", tex::words(&heading));
    if let Some(n) = &k.note {
        out += &format!("\\textit{{{}}}\\\\\n", tex::words(n));
    }
    if !k.inputs.is_empty() {
        out += &format!("{}:\n\\begin{{itemize}}\n", lang.word("Data"));
        for it in &k.inputs {
            out += &format!("\\item {}\n", latex_item(it, lang));
        }
        out += "\\end{itemize}\n";
    }
    let find: Vec<String> = k
        .result
        .iter()
        .map(|it| match &it.words {
            Some(_) => tex::words(&it.label.text),
            None => format!("${}$", it.label.latex),
        })
        .collect();
    if !find.is_empty() {
        out += &format!("{}: {}.\n\n", lang.word("Find"), find.join(", "));
    }
    tex::known_characters(&out)
}

/// A complete LaTeX document around sections from [`statement_latex`]: the problems of a
/// set, for students, without their answers.
pub fn statement_document(title: &str, sections: &[String], lang: Lang) -> String {
    let mut out = latex_preamble(lang);
    out += &format!(
        "\\title{{{}}}\n\\date{{}}\n\\begin{{document}}\n\\maketitle\n",
        tex::words(&format!("{}: {title}", lang.word("Statements")))
    );
    for s in sections {
        out += s;
    }
    out + "\\end{document}\n"
}

/// One example as Markdown with `$...$` math.
pub fn example_markdown(verdict: &Verdict, lang: Lang) -> String {
    example_markdown_with(verdict, lang, no_raise)
}

/// [`example_markdown`] written by a front end that says how to raise a limit.
pub fn example_markdown_with(verdict: &Verdict, lang: Lang, raise: RaiseWith) -> String {
    let k = key_parts(verdict, lang, raise);
    let mut out = format!("## {}\n\n", escape_markdown(&k.heading));
    if !k.source.is_empty() {
        out += &format!(
            "*{}: {}*\n\n",
            lang.word("source"),
            escape_markdown(&k.source)
        );
    }
    if let Some(n) = &k.note {
        out += &format!("*{}:* {}\n\n", lang.word("note"), escape_markdown(n));
    }
    if !k.op.is_empty() {
        out += &format!(
            "{}: {} (`{}`)\n\n",
            lang.word("operation"),
            op_words(&k.op, lang),
            k.op
        );
    }
    let block = |title: &str, items: &[Item]| -> String {
        if items.is_empty() {
            return String::new();
        }
        let mut b = format!("**{title}**\n\n");
        for it in items {
            match &it.words {
                Some(words) => b += &format!("- {}: {}\n", it.label.text, words.markdown()),
                None => {
                    let sep = if it.sep() == " = " {
                        " = "
                    } else {
                        "\\colon\\ "
                    };
                    b += &format!("- ${}{sep}{}$\n", it.label.latex, item_latex(it, lang))
                }
            }
        }
        b + "\n"
    };
    out += &block(&lang.word("input"), &k.inputs);
    out += &steps::markdown_block(verdict, lang);
    out += &block(&lang.word("steps"), &k.steps);
    out += &block(&lang.word("result"), &k.result);
    for r in &k.remarks {
        out += &format!("*{}*\n\n", escape_markdown(&r.text));
    }
    if let Some(e) = &k.error {
        out += &format!(
            "**{}**: {}\n\n",
            lang.word("error"),
            escape_markdown(&e.text)
        );
    }
    if verdict.checked {
        out += &format!(
            "**{}**: {}\n\n",
            lang.word("verdict"),
            escape_markdown(&k.verdict.text)
        );
    }
    out
}

/// The engine's own words for Markdown, which passes HTML through: `<`, `>` and `&` as
/// entities, the rest (its emphasis, its `$...$`) kept. Text of a problem goes through
/// [`escape_markdown`] instead.
pub fn escape_html(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            c => out.push(c),
        }
    }
    out
}

/// Text of a problem (a name, a title, a note, an erratum, an echoed key, a message that echoes
/// one) for Markdown: shown as written, never read as Markdown. Its control characters as in
/// [`escape_text`] (so it is one line and cannot begin a block); `<`, `>` and `&` as entities
/// (no raw HTML, no autolink, no entity); a backslash before every other character that opens
/// or closes inline Markdown (`` \ ` * _ [ ] ~ | $ # @ ``: no link, image, code span, emphasis,
/// strikethrough, mathematics or heading mark); and before the `:` of `://` and the `.` of
/// `www.`, which GitHub's Markdown links by themselves.
///
/// ```
/// use cagd_keys::escape_markdown;
/// assert_eq!(escape_markdown("[a](javascript:x)"), "\\[a\\](javascript:x)");
/// assert_eq!(escape_markdown("<b> *c* https://d"), "&lt;b&gt; \\*c\\* https\\://d");
/// assert_eq!(escape_markdown("e\u{1b}[2J"), "e\\\\u{1b}\\[2J");
/// ```
pub fn escape_markdown(s: &str) -> String {
    let visible = escape_text(s);
    let mut out = String::with_capacity(visible.len() + visible.len() / 8);
    for (i, c) in visible.char_indices() {
        let after = visible.get(i + c.len_utf8()..).unwrap_or_default();
        let before = visible.get(..i).unwrap_or_default();
        match c {
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '&' => out.push_str("&amp;"),
            '\\' | '`' | '*' | '_' | '[' | ']' | '~' | '|' | '$' | '#' | '@' => {
                out.push('\\');
                out.push(c);
            }
            ':' if after.starts_with("//") => out.push_str("\\:"),
            '.' if before
                .get(before.len().saturating_sub(3)..)
                .is_some_and(|w| w.eq_ignore_ascii_case("www")) =>
            {
                out.push_str("\\.")
            }
            c => out.push(c),
        }
    }
    out
}

/// A Markdown image of a file written beside the key: `![alt](path)`, the alternative text
/// through [`escape_markdown`] and the path as a relative URL, every byte but the unreserved
/// ones (`A-Z a-z 0-9 - . _ ~`) and `/` percent-encoded, so that a folder named `set #3`
/// (a space, a `#` that would start a fragment, a parenthesis that would end the destination)
/// is read back as that path.
///
/// ```
/// use cagd_keys::markdown_image;
/// assert_eq!(markdown_image("fig", "set #3/a (1).svg"), "![fig](set%20%233/a%20%281%29.svg)");
/// ```
pub fn markdown_image(alt: &str, path: &str) -> String {
    let mut url = String::with_capacity(path.len());
    for b in path.bytes() {
        match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'.' | b'_' | b'~' | b'/' => {
                url.push(char::from(b))
            }
            b => url.push_str(&format!("%{b:02X}")),
        }
    }
    format!("![{}]({url})", escape_markdown(alt))
}

/// Text of a problem (a name, a title, a note, an erratum, an echoed key, a message that echoes
/// one, a file name) for a plain-text key or a terminal: shown as written, on one line, never
/// read by the terminal. Every control character (C0, the line feed and the tab included, DEL
/// and C1, such as ESC, BEL, CR, BS and the one-byte CSI U+009B) and every bidirectional
/// embedding, override or isolate (U+202A to U+202E, U+2066 to U+2069) is written as its
/// escape: `\n`, `\r`, `\t`, else `\u{1b}`. The text cannot move the cursor, clear the screen,
/// set the clipboard, ring, reorder what follows, or begin a line of its own (a line that
/// would read as the key's own, `verdict: ...`).
///
/// ```
/// use cagd_keys::escape_text;
/// assert_eq!(escape_text("a\u{1b}[2J\rverdict: ok\n"), "a\\u{1b}[2J\\rverdict: ok\\n");
/// assert_eq!(escape_text("c\u{9b}1m \u{202e}x"), "c\\u{9b}1m \\u{202e}x");
/// assert_eq!(escape_text("Bézier, C^1, ĉ"), "Bézier, C^1, ĉ");
/// ```
pub fn escape_text(s: &str) -> String {
    let bidi = |c: char| matches!(c, '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}');
    if !s.chars().any(|c| c.is_control() || bidi(c)) {
        return s.to_string();
    }
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        match c {
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if c.is_control() || bidi(c) => out.push_str(&format!("\\u{{{:x}}}", u32::from(c))),
            c => out.push(c),
        }
    }
    out
}

/// A complete Markdown document around sections from [`example_markdown`].
pub fn markdown_document(title: &str, sections: &[String], lang: Lang) -> String {
    let mut out = format!(
        "# {}: {}\n\n",
        lang.word("Answer key"),
        escape_markdown(title)
    );
    for s in sections {
        out += s;
    }
    out
}
