//! The names a key prints for the problem's arguments and the answer's values, in the notes'
//! notation: `closed_form` is `c(u, v)` for a surface, `c(t)` for a curve in t, `c_u(1, v)` for
//! a derivative at u = 1; `C_tilde` is C̃; `BtB` is BᵗB; an interpolation's `points` are the
//! data points. The engine's identifiers (`closed_form`, `first_cell_planar`) stay in the JSON
//! answers; keys print these labels.

use crate::escape::escape_latex;
use crate::{tex, Lang};
use cagd_contract::problem::{Op, UorV};
use cagd_contract::spec::Orders;
use cagd_contract::{Exact, Problem};
use cagd_scalar::Print;

/// A label: plain text and LaTeX (math mode).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Label {
    /// Plain text.
    pub text: String,
    /// LaTeX, math mode.
    pub latex: String,
}

impl Label {
    fn math(text: &str, latex: &str) -> Label {
        Label {
            text: text.into(),
            latex: latex.into(),
        }
    }

    fn words(en: &str, es: &str, lang: Lang) -> Label {
        let w = match lang {
            Lang::En => en,
            Lang::Es => es,
        };
        Label {
            text: w.into(),
            latex: format!("\\text{{{}}}", escape_latex(w)),
        }
    }
}

/// The variables of a closed form, as its argument list: `u, v`, `t`, `u`.
fn arguments(value: &Exact) -> String {
    let vars: Vec<String> = match value {
        Exact::Map(m) => m.vars().iter().map(ToString::to_string).collect(),
        Exact::Poly(p) => p.vars().iter().map(ToString::to_string).collect(),
        Exact::Rational(r) => {
            let t = r.to_text();
            ["u", "v", "t"]
                .iter()
                .filter(|v| t.contains(**v))
                .map(|v| v.to_string())
                .collect()
        }
        _ => Vec::new(),
    };
    if vars.is_empty() {
        "u, v".into()
    } else {
        vars.join(", ")
    }
}

/// The left-hand side of a derivative: `c_u(1, v)`, `c_{uv}(u, v)`, `c'(t)`.
fn derivative_label(problem: &Problem, value: &Exact) -> Option<Label> {
    let Op::Derivative(d) = &problem.op else {
        return None;
    };
    let (r, s) = match &d.order {
        Some(Orders::One(r)) => (r.0, 0),
        Some(Orders::Two(r, s)) => (r.0, s.0),
        None => (1, 0),
    };
    if d.curve.is_some() {
        let primes = "'".repeat(usize::try_from(r).unwrap_or(1));
        let t = arguments(value);
        let t = if t.contains(',') { "t".to_string() } else { t };
        return Some(Label::math(
            &format!("c{primes}({t})"),
            &format!("c^{{({r})}}({t})"),
        ));
    }
    let sub =
        "u".repeat(usize::try_from(r).unwrap_or(0)) + &"v".repeat(usize::try_from(s).unwrap_or(0));
    let (u, v) = match &d.at {
        Some(at) => (
            at.u.as_ref().map_or("u".to_string(), |x| x.0.to_text()),
            at.v.as_ref().map_or("v".to_string(), |x| x.0.to_text()),
        ),
        None => ("u".into(), "v".into()),
    };
    Some(Label::math(
        &format!("c_{sub}({u}, {v})"),
        &format!("c_{{{sub}}}({u}, {v})"),
    ))
}

/// The border of a continuity problem: `u` (the default) or `v`.
fn border_u(problem: Option<&Problem>) -> bool {
    match problem.map(|p| &p.op) {
        Some(Op::Continuity(c)) => !matches!(c.border, Some(UorV::V)),
        _ => true,
    }
}

/// The label of a name in a key: an argument of the problem, a result or a step.
pub fn label(name: &str, value: &Exact, problem: Option<&Problem>, lang: Lang) -> Label {
    let op = problem.map(|p| p.op.name()).unwrap_or_default();
    let fit = matches!(op, "interpolate" | "approximate");
    let u = border_u(problem);
    let w = |en: &str, es: &str| Label::words(en, es, lang);
    match name {
        "closed_form" => {
            if let Some(l) = problem.and_then(|p| derivative_label(p, value)) {
                return l;
            }
            if op == "normal" {
                return Label::math("N(u, v)", "N(u, v)");
            }
            let a = arguments(value);
            Label::math(&format!("c({a})"), &format!("c({a})"))
        }
        "parametrization" if fit => w(
            "parameters from the data",
            "parámetros a partir de los datos",
        ),
        "parametrization" => Label::math("c(u, v)", "c(u, v)"),
        "c1" | "c2" | "d1" | "d2" => {
            let (a, b) = name.split_at(1);
            Label::math(name, &format!("{a}_{b}"))
        }
        "closed_form_first" => Label::math("c(u, v)", "c(u, v)"),
        "closed_form_second" => Label::math("c~(u, v)", "\\tilde{c}(u, v)"),
        "differences_first" if u => Label::math("Δ^{1,0} c_{m-1,j}", "\\Delta^{1,0} c_{m-1,j}"),
        "differences_second" if u => {
            Label::math("Δ^{1,0} c~_{0,j}", "\\Delta^{1,0} \\tilde{c}_{0,j}")
        }
        "differences_first" => Label::math("Δ^{0,1} c_{i,n-1}", "\\Delta^{0,1} c_{i,n-1}"),
        "differences_second" => Label::math("Δ^{0,1} c~_{i,0}", "\\Delta^{0,1} \\tilde{c}_{i,0}"),
        "derivative_first" if u => Label::math("c_u(1, v)", "c_u(1, v)"),
        "derivative_second" if u => Label::math("c~_u(0, v)", "\\tilde{c}_u(0, v)"),
        "derivative_first" => Label::math("c_v(u, 1)", "c_v(u, 1)"),
        "derivative_second" => Label::math("c~_v(u, 0)", "\\tilde{c}_v(u, 0)"),
        "normal_first" if u => Label::math("N(1, v)", "N(1, v)"),
        "normal_second" if u => Label::math("N~(0, v)", "\\tilde{N}(0, v)"),
        "normal_first" => Label::math("N(u, 1)", "N(u, 1)"),
        "normal_second" => Label::math("N~(u, 0)", "\\tilde{N}(u, 0)"),
        "polynomial" => Label::math("c_uv · (c_u × c_v)", "c_{uv} \\cdot (c_u \\times c_v)"),
        "c_hat" => Label::math("ĉ", "\\hat{c}"),
        "c_tilde" => Label::math("c~", "\\tilde{c}"),
        "d_tilde" => Label::math("d~", "\\tilde{d}"),
        "C_tilde" => Label::math("C~ = A (B_V^t)^(-1)", "\\tilde{C} = A (B_V^t)^{-1}"),
        "BtB" => Label::math("B^t B", "B^t B"),
        "BtA" => Label::math("B^t A", "B^t A"),
        "C_x" if op == "interpolate" => Label::math("C_x", "C_x"),
        "points" if fit => w("data points", "puntos de datos"),
        "params" => w("parameters", "parámetros"),
        "surface" => w("surface", "superficie"),
        "curve" => w("curve", "curva"),
        "points" => w("points", "puntos"),
        "first" => w("first patch", "primer parche"),
        "second" => w("second patch", "segundo parche"),
        "border" => w("common border", "borde común"),
        "lengths" => w("interval lengths", "longitudes de los intervalos"),
        "basis" => w("basis", "base"),
        "end" => w("end conditions", "condiciones en los extremos"),
        "tangents" if fit => w("end derivatives", "derivadas en los extremos"),
        "degree" => w("degree", "grado"),
        "by" => w("elevation", "elevación"),
        "order" if op == "continuity" => w("order of continuity", "orden de continuidad"),
        "order" => w("order", "orden"),
        "at" => w("on the border", "en el borde"),
        "arcs" => w("arcs", "arcos"),
        "radius" => w("radius", "radio"),
        "center" => w("center", "centro"),
        "interval" => w("interval", "intervalo"),
        "quadrant" => w("quadrant", "cuadrante"),
        "knot" => w("knot", "nudo"),
        "times" => w("times", "veces"),
        "direction" => w("direction", "dirección"),
        "blend" => w("blending functions", "funciones de mezcla"),
        "first_cell_planar" => w("first cell planar", "primera celda plana"),
        "last_cell_planar" => w("last cell planar", "última celda plana"),
        "developable" => w("developable", "desarrollable"),
        "corners" => w("corners", "esquinas"),
        "smoothness" => w("continuity", "continuidad"),
        "fails" => w("condition that fails", "condición que falla"),
        "mesh" => w("control mesh", "malla de control"),
        // a triangular patch's result is `{"triangle": rows}` (it feeds back as input): the
        // result is the patch, its one entry the net
        "triangle" if problem.is_none() => w("control net", "red de control"),
        "triangle" => w("triangular patch", "superficie triangular"),
        "weights" => w("weights", "pesos"),
        "knots" => w("knots", "nudos"),
        "point" => w("point", "punto"),
        "curve_u0" => Label::math("c(0, v)", "c(0, v)"),
        "curve_u1" => Label::math("c(1, v)", "c(1, v)"),
        "curve_v0" => Label::math("c(u, 0)", "c(u, 0)"),
        "curve_v1" => Label::math("c(u, 1)", "c(u, 1)"),
        "curve_uv1" => Label::math("b(u, 1 - u)", "b(u, 1 - u)"),
        "exact" if op == "reduce_degree" => w("exact reduction", "reducción exacta"),
        "exact" => w("exact", "exacto"),
        "residual" => w("residual", "residuo"),
        "pieces" => w("pieces", "trozos"),
        "weight" => w("weight", "peso"),
        "multiplicity" => w("multiplicity", "multiplicidad"),
        "knots_u" => w("knots in u", "nudos en u"),
        "knots_v" => w("knots in v", "nudos en v"),
        "knot_lines" => w("knot lines", "líneas de nudos"),
        "expected" => w("expected order", "orden esperado"),
        "edge_of_regression" => w("edge of regression", "arista de retroceso"),
        "derivatives_first" => w(
            "derivatives of the first curve",
            "derivadas de la primera curva",
        ),
        "derivatives_second" => w(
            "derivatives of the second curve",
            "derivadas de la segunda curva",
        ),
        "length" => w("length", "longitud"),
        "curves" => w("curves", "curvas"),
        "surfaces" => w("surfaces", "superficies"),
        "triangles" => w("triangular patches", "superficies triangulares"),
        "intervals" => w("intervals", "intervalos"),
        "u_intervals" => w("intervals in u", "intervalos en u"),
        "v_intervals" => w("intervals in v", "intervalos en v"),
        "geometric" => w(
            "order of geometric continuity",
            "orden de continuidad geométrica",
        ),
        "shape_factor" => w("shape factor", "factor de forma"),
        "kind" => w("kind of conic", "tipo de cónica"),
        "normal" => Label::math("N(u, v)", "N(u, v)"),
        "normals" => w("normal vectors", "vectores normales"),
        // where the numerator of the Gaussian curvature vanishes
        "numerator" => Label::math("G(u, v)", "G(u, v)"),
        "sign" => w("sign of G", "signo de G"),
        "zeros" => w("zeros of G", "ceros de G"),
        "speed_squared" => Label::math("c'·c'", "c' \\cdot c'"),
        "zero" => w("zero of G", "cero de G"),
        "sign_change" => w("points where G > 0 and G < 0", "puntos donde G > 0 y G < 0"),
        "domain" => w("domain", "dominio"),
        "segment" => w("segment of the domain", "segmento del dominio"),
        "vertices" => w("vertices", "vértices"),
        // a parameter or a coordinate: u, v, t, f
        _ if name.chars().count() == 1 => Label::math(name, name),
        _ => corner(name, lang).unwrap_or_else(|| Label::math(name, &latex_name(name))),
    }
}

/// The normal at a corner, `corner_10` → N(1, 0), and its limit, `corner_10_limit`; the
/// numerator of the Gaussian curvature at a corner, `G_10` → G(1, 0).
fn corner(name: &str, lang: Lang) -> Option<Label> {
    if let Some([i, j]) = name
        .strip_prefix("G_")
        .and_then(|ij| <[u8; 2]>::try_from(ij.as_bytes()).ok())
        .filter(|ij| ij.iter().all(u8::is_ascii_digit))
    {
        let (i, j) = (char::from(i), char::from(j));
        return Some(Label::math(
            &format!("G({i}, {j})"),
            &format!("G({i}, {j})"),
        ));
    }
    let rest = name.strip_prefix("corner_")?;
    let (ij, limit) = match rest.strip_suffix("_limit") {
        Some(ij) => (ij, true),
        None => (rest, false),
    };
    let mut cs = ij.chars();
    let (i, j) = (cs.next()?, cs.next()?);
    if cs.next().is_some() || !i.is_ascii_digit() || !j.is_ascii_digit() {
        return None;
    }
    if !limit {
        return Some(Label::math(
            &format!("N({i}, {j})"),
            &format!("N({i}, {j})"),
        ));
    }
    let (text, latex) = match lang {
        Lang::En => (
            format!("limit of N at ({i}, {j})"),
            format!("\\text{{limit of }} N \\text{{ at }} ({i}, {j})"),
        ),
        Lang::Es => (
            format!("límite de N en ({i}, {j})"),
            format!("\\text{{límite de }} N \\text{{ en }} ({i}, {j})"),
        ),
    };
    Some(Label { text, latex })
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
