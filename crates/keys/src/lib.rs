//! Answer keys of cagd-exact: text, LaTeX and Markdown, in English or in the notes' Spanish.
//!
//! A key is written from a [`Verdict`]: the typed problem (its fixture fields, its arguments in
//! the order written) and its answer (results, steps, remarks), and the comparison with
//! `expected` when the problem says what to expect. Nothing here reads JSON or solves.

use cagd_linalg::Point;
use cagd_problem::input::{CurveIn, SurfaceIn};
use cagd_problem::value::{matrix_text, numbers_text};
use cagd_problem::Number;
use cagd_problem::{Exact, Meta, Verdict};
use cagd_scalar::Print;
use cagd_surface::{Grid, Mesh};

pub mod steps;

/// The language of an answer key.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Lang {
    /// English.
    #[default]
    En,
    /// Spanish, with the notes' vocabulary (malla de control, pesos, bigrado, nudos).
    Es,
}

impl Lang {
    /// Reads `en` or `es`.
    pub fn parse(s: &str) -> Option<Lang> {
        match s {
            "en" => Some(Lang::En),
            "es" => Some(Lang::Es),
            _ => None,
        }
    }

    /// A word of the answer keys in this language.
    pub fn word(self, key: &str) -> String {
        let es = match key {
            "source" => "fuente",
            "input" => "datos",
            "steps" => "pasos",
            "result" => "resultado",
            "verdict" => "veredicto",
            "matches the notes" => "coincide con los apuntes",
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
            "remarks" => "observaciones",
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
        Exact::Text(t) => t.clone(),
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
                .join(", ")
        ),
        Exact::Object(kv) => kv
            .iter()
            .map(|(k, v)| format!("{k} = {}", text(v, lang)))
            .collect::<Vec<_>>()
            .join(", "),
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

/// LaTeX (math mode) of an exact value.
pub fn latex(x: &Exact, lang: Lang) -> String {
    match x {
        Exact::Bool(_) | Exact::Int(_) => format!("\\text{{{}}}", text(x, lang)),
        Exact::Text(t) => format!("\\text{{{}}}", escape_latex(t)),
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
                    s += &format!(",\\ w = {}", latex_numbers(w));
                }
                s
            }
            CurveIn::BSpline {
                points,
                degree,
                knots,
                weights,
            } => {
                let mut s = format!("p = {degree},\\ {}", latex_points(points));
                if let Some(w) = weights {
                    s += &format!(",\\ w = {}", latex_numbers(w));
                }
                s + &format!(",\\ {}", latex_numbers(knots))
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
                let mut t = format!("({}, {}),\\ {}", degree.0, degree.1, latex_mesh(mesh));
                if let Some(w) = weights {
                    t += &format!(",\\quad w = {}", latex_grid(w));
                }
                t + &format!(
                    ",\\quad {} \\times {}",
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
                .join(", ")
        ),
        Exact::Object(kv) => kv
            .iter()
            .map(|(k, v)| format!("{} = {}", latex_name(k), latex(v, lang)))
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
/// assert_eq!(latex_name("c_uv · (c_u × c_v)"), "c_{uv}\\cdot (c_{u}\\times c_{v})");
/// assert_eq!(latex_name("weights"), "\\text{weights}");
/// ```
pub fn latex_name(name: &str) -> String {
    match name {
        "c_hat" => "\\hat{c}".into(),
        "c_tilde" => "\\tilde{c}".into(),
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
                    _ => out.push(c),
                }
            }
            out.trim_end().to_string()
        }
        _ => match name.split_once('_') {
            Some((a, b)) if !a.is_empty() && !b.is_empty() && a.len() <= 3 => {
                format!("{a}_{{{}}}", b.replace('_', ","))
            }
            _ => format!("\\text{{{}}}", escape_latex(&name.replace('_', " "))),
        },
    }
}

/// Escapes the characters LaTeX treats specially in text.
pub fn escape_latex(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '\\' => out.push_str("\\textbackslash{}"),
            '&' | '%' | '$' | '#' | '_' | '{' | '}' => {
                out.push('\\');
                out.push(c);
            }
            '^' => out.push_str("\\^{}"),
            '~' => out.push_str("\\~{}"),
            '√' => out.push_str("$\\sqrt{}$"),
            'Δ' => out.push_str("$\\Delta$"),
            _ => out.push(c),
        }
    }
    out
}

/// The fixture's fields of a verdict's problem (empty when it could not be read).
fn meta(v: &Verdict) -> (Meta, String) {
    match &v.problem {
        Some(p) => (p.meta.clone(), p.op.name().to_string()),
        None => (Meta::default(), String::new()),
    }
}

/// The plain-text answer key of one problem (or checked example): name, source, input,
/// steps, result and verdict.
pub fn example_text(verdict: &Verdict, lang: Lang) -> String {
    let k = key_parts(verdict, lang);
    let mut out = String::new();
    out += &format!("== {}\n", k.heading);
    if !k.source.is_empty() {
        out += &format!("{}: {}\n", lang.word("source"), k.source);
    }
    if verdict.problem.is_some() {
        out += &format!("op: {}\n", k.op);
        out += &format!("{}:\n", lang.word("input"));
        for (name, v) in &k.inputs {
            out += &format!("  {name} = {}\n", text(v, lang));
        }
    }
    match &verdict.answer {
        Ok(a) => {
            out += &steps::text_block(verdict, lang);
            if !a.steps.is_empty() {
                out += &format!("{}:\n", lang.word("steps"));
                for (name, v) in &a.steps {
                    out += &format!("  {name} = {}\n", rows_on_lines(&text(v, lang)));
                }
            }
            out += &format!("{}:\n", lang.word("result"));
            for (name, v) in &a.result {
                out += &format!("  {name} = {}\n", rows_on_lines(&text(v, lang)));
            }
            for r in &a.remarks {
                out += &format!("  ({r})\n");
            }
        }
        Err(e) => out += &format!("{}: {e}\n", lang.word("error")),
    }
    if verdict.checked {
        out += &format!(
            "{}: {}\n",
            lang.word("verdict"),
            verdict_text(verdict, lang)
        );
    }
    out
}

/// A value of the text key with one mesh (or matrix) row per line, as the notes print them:
/// rows are the only things separated by `;`.
fn rows_on_lines(text: &str) -> String {
    text.replace("; ", ";\n      ")
}

/// `matches the notes`, `erratum: the notes print X, the exact value is Y`, or the failure.
pub fn verdict_text(v: &Verdict, lang: Lang) -> String {
    if let Err(e) = &v.answer {
        return format!("{}: {e}", lang.word("failed"));
    }
    if !v.mismatches.is_empty() {
        return format!("{}: {}", lang.word("failed"), v.mismatches.join("; "));
    }
    if v.errata.is_empty() {
        return lang.word("matches the notes");
    }
    v.errata
        .iter()
        .map(|e| {
            format!(
                "{} ({}): {} {}, {} {}{}",
                lang.word("erratum"),
                e.place,
                lang.word("the notes print"),
                e.printed,
                lang.word("the exact value is"),
                e.exact,
                if e.why.is_empty() {
                    String::new()
                } else {
                    format!(" — {}", e.why)
                }
            )
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// The parts of an answer key, shared by the LaTeX and Markdown writers.
struct KeyParts {
    heading: String,
    source: String,
    op: String,
    inputs: Vec<(String, Exact)>,
    steps: Vec<(String, Exact)>,
    result: Vec<(String, Exact)>,
    remarks: Vec<String>,
    error: Option<String>,
    verdict: String,
}

fn key_parts(verdict: &Verdict, lang: Lang) -> KeyParts {
    let (meta, op) = meta(verdict);
    let name = meta.name.clone().unwrap_or_default();
    let title = meta.title.clone().unwrap_or_default();
    let heading = match (name.is_empty(), title.is_empty()) {
        (false, false) => format!("{name}: {title}"),
        (false, true) => name,
        (true, false) => title,
        (true, true) if op.is_empty() => lang.word("Problem"),
        (true, true) => format!("{} ({op})", lang.word("Problem")),
    };
    let source = meta.source.clone().unwrap_or_default();
    let source = match meta.equation.as_deref() {
        None | Some("") => source,
        Some(eq) => format!("{source}, ({})", eq.trim_matches(['(', ')'])),
    };
    let (steps, result, remarks, error) = match &verdict.answer {
        Ok(a) => (a.steps.clone(), a.result.clone(), a.remarks.clone(), None),
        Err(e) => (Vec::new(), Vec::new(), Vec::new(), Some(e.to_string())),
    };
    KeyParts {
        heading,
        source,
        op,
        inputs: verdict
            .problem
            .as_ref()
            .map(|p| p.inputs())
            .unwrap_or_default(),
        steps,
        result,
        remarks,
        error,
        verdict: verdict_text(verdict, lang),
    }
}

/// One example as a LaTeX section (inside [`latex_document`]).
pub fn example_latex(verdict: &Verdict, lang: Lang) -> String {
    let k = key_parts(verdict, lang);
    let mut out = format!("\\section*{{{}}}\n", escape_latex(&k.heading));
    if !k.source.is_empty() {
        out += &format!(
            "\\textit{{{}: {}}}\\\\\n",
            lang.word("source"),
            escape_latex(&k.source)
        );
    }
    out += &format!("\\texttt{{{}}}\n", escape_latex(&k.op));
    let block = |title: &str, items: &[(String, Exact)]| -> String {
        if items.is_empty() {
            return String::new();
        }
        let mut b = format!(
            "\\paragraph{{{}}}\n\\begin{{itemize}}\n",
            escape_latex(title)
        );
        for (name, v) in items {
            match v {
                Exact::Text(t) => {
                    b += &format!("\\item ${}$: {}\n", latex_name(name), escape_latex(t))
                }
                _ => {
                    b += &format!(
                        "\\item $\\displaystyle {} = {}$\n",
                        latex_name(name),
                        latex(v, lang)
                    )
                }
            }
        }
        b + "\\end{itemize}\n"
    };
    out += &block(&lang.word("input"), &k.inputs);
    out += &steps::latex_block(verdict, lang);
    out += &block(&lang.word("steps"), &k.steps);
    out += &block(&lang.word("result"), &k.result);
    for r in &k.remarks {
        out += &format!("\\textit{{{}}}\\\\\n", escape_latex(r));
    }
    if let Some(e) = &k.error {
        out += &format!(
            "\\textbf{{{}}}: {}\\\\\n",
            lang.word("error"),
            escape_latex(e)
        );
    }
    if verdict.checked {
        out += &format!(
            "\\paragraph{{{}}} {}\n\n",
            escape_latex(&lang.word("verdict")),
            escape_latex(&k.verdict)
        );
    }
    out
}

/// A complete LaTeX document around sections from [`example_latex`]; compiles with pdflatex.
pub fn latex_document(title: &str, sections: &[String], lang: Lang) -> String {
    let mut out = String::from(
        "\\documentclass[10pt]{article}\n\\usepackage[utf8]{inputenc}\n\\usepackage[T1]{fontenc}\n\\usepackage{amsmath,amssymb}\n\\usepackage[margin=2cm,landscape]{geometry}\n\\usepackage{graphicx}\n\\allowdisplaybreaks\n\\setlength{\\parindent}{0pt}\n",
    );
    out += &format!(
        "\\title{{{}}}\n\\date{{}}\n\\begin{{document}}\n\\maketitle\n",
        escape_latex(&format!("{}: {title}", lang.word("Answer key")))
    );
    for s in sections {
        out += s;
    }
    out + "\\end{document}\n"
}

/// One example as Markdown with `$...$` math.
pub fn example_markdown(verdict: &Verdict, lang: Lang) -> String {
    let k = key_parts(verdict, lang);
    let mut out = format!("## {}\n\n", escape_html(&k.heading));
    if !k.source.is_empty() {
        out += &format!("*{}: {}*\n\n", lang.word("source"), escape_html(&k.source));
    }
    out += &format!("`{}`\n\n", k.op);
    let block = |title: &str, items: &[(String, Exact)]| -> String {
        if items.is_empty() {
            return String::new();
        }
        let mut b = format!("**{title}**\n\n");
        for (name, v) in items {
            match v {
                Exact::Text(t) => b += &format!("- `{name}`: {}\n", escape_html(t)),
                _ => b += &format!("- ${} = {}$\n", latex_name(name), latex(v, lang)),
            }
        }
        b + "\n"
    };
    out += &block(&lang.word("input"), &k.inputs);
    out += &steps::markdown_block(verdict, lang);
    out += &block(&lang.word("steps"), &k.steps);
    out += &block(&lang.word("result"), &k.result);
    for r in &k.remarks {
        out += &format!("*{}*\n\n", escape_html(r));
    }
    if let Some(e) = &k.error {
        out += &format!("**{}**: {}\n\n", lang.word("error"), escape_html(e));
    }
    if verdict.checked {
        out += &format!(
            "**{}**: {}\n\n",
            lang.word("verdict"),
            escape_html(&k.verdict)
        );
    }
    out
}

/// Text of a problem (a title, a name, a message) for Markdown, which passes HTML through:
/// `<`, `>` and `&` as entities, so that a title such as `<script>` is shown, never run.
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

/// A complete Markdown document around sections from [`example_markdown`].
pub fn markdown_document(title: &str, sections: &[String], lang: Lang) -> String {
    let mut out = format!("# {}: {}\n\n", lang.word("Answer key"), escape_html(title));
    for s in sections {
        out += s;
    }
    out
}
