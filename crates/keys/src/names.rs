//! The names a key prints for the problem's arguments and the answer's values, in the notes'
//! notation: a closed form is `c(u, v)` for a surface, `c(t)` for a curve in t, `c_u(1, v)`
//! for a derivative at u = 1; BᵗB is `B^t B`; an interpolation's `points` are the
//! data points. The answer's results and steps are labelled by their kind ([`label`] on a
//! [`Quantity`]), and so are the fields of an object value (a piece's interval in `u`, the
//! corners' `G_10`); the problem's arguments by theirs ([`argument_label`] on an
//! [`Argument`]). The engine's identifiers (`closed_form`, `first_cell_planar`) stay in the
//! JSON answers; keys print these labels.

use crate::escape::escape_latex;
use crate::{tex, Lang};
use cagd_contract::problem::{Op, UorV};
use cagd_contract::spec::Orders;
use cagd_contract::value::quantity::{Axis, Border, Corner, Side, Variables};
use cagd_contract::{Argument, Problem, Quantity};
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

    pub(crate) fn words(en: &str, es: &str, lang: Lang) -> Label {
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

/// The left-hand side of a derivative: `c_u(1, v)`, `c_{uv}(u, v)`, `c'(t)`.
fn derivative_label(problem: &Problem, variables: &Variables) -> Option<Label> {
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
        let t = variables.arguments();
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

/// Whether the operation fits data (`interpolate`, `approximate`).
fn fits(op: &str) -> bool {
    matches!(op, "interpolate" | "approximate")
}

/// The label of a result or step in a key, by its kind, in the context of its problem.
pub fn label(quantity: &Quantity, problem: Option<&Problem>, lang: Lang) -> Label {
    use Quantity as Q;
    let op = problem.map(|p| p.op.name()).unwrap_or_default();
    let fit = fits(op);
    let u = border_u(problem);
    let w = |en: &str, es: &str| Label::words(en, es, lang);
    match quantity {
        Q::ClosedForm(variables) => {
            if let Some(l) = problem.and_then(|p| derivative_label(p, variables)) {
                return l;
            }
            if op == "normal" {
                return Label::math("N(u, v)", "N(u, v)");
            }
            let a = variables.arguments();
            Label::math(&format!("c({a})"), &format!("c({a})"))
        }
        Q::Parametrization if fit => w(
            "parameters from the data",
            "parámetros a partir de los datos",
        ),
        Q::Parametrization => Label::math("c(u, v)", "c(u, v)"),
        Q::PatchClosedForm(Side::First) => Label::math("c(u, v)", "c(u, v)"),
        Q::PatchClosedForm(Side::Second) => Label::math("c~(u, v)", "\\tilde{c}(u, v)"),
        Q::BorderDifferences(Side::First) if u => {
            Label::math("Δ^{1,0} c_{m-1,j}", "\\Delta^{1,0} c_{m-1,j}")
        }
        Q::BorderDifferences(Side::Second) if u => {
            Label::math("Δ^{1,0} c~_{0,j}", "\\Delta^{1,0} \\tilde{c}_{0,j}")
        }
        Q::BorderDifferences(Side::First) => {
            Label::math("Δ^{0,1} c_{i,n-1}", "\\Delta^{0,1} c_{i,n-1}")
        }
        Q::BorderDifferences(Side::Second) => {
            Label::math("Δ^{0,1} c~_{i,0}", "\\Delta^{0,1} \\tilde{c}_{i,0}")
        }
        Q::BorderDerivative(Side::First) if u => Label::math("c_u(1, v)", "c_u(1, v)"),
        Q::BorderDerivative(Side::Second) if u => Label::math("c~_u(0, v)", "\\tilde{c}_u(0, v)"),
        Q::BorderDerivative(Side::First) => Label::math("c_v(u, 1)", "c_v(u, 1)"),
        Q::BorderDerivative(Side::Second) => Label::math("c~_v(u, 0)", "\\tilde{c}_v(u, 0)"),
        Q::BorderNormal(Side::First) if u => Label::math("N(1, v)", "N(1, v)"),
        Q::BorderNormal(Side::Second) if u => Label::math("N~(0, v)", "\\tilde{N}(0, v)"),
        Q::BorderNormal(Side::First) => Label::math("N(u, 1)", "N(u, 1)"),
        Q::BorderNormal(Side::Second) => Label::math("N~(u, 0)", "\\tilde{N}(u, 0)"),
        Q::DevelopablePolynomial => {
            Label::math("c_uv · (c_u × c_v)", "c_{uv} \\cdot (c_u \\times c_v)")
        }
        Q::CHat => Label::math("ĉ", "\\hat{c}"),
        Q::CTilde => Label::math("c~", "\\tilde{c}"),
        Q::DTilde => Label::math("d~", "\\tilde{d}"),
        Q::CTildeMesh => Label::math("C̃ = A (B_V^t)^(-1)", "\\tilde{C} = A (B_V^t)^{-1}"),
        Q::NormalMatrix => Label::math("B^t B", "B^t B"),
        Q::NormalRhs => Label::math("B^t A", "B^t A"),
        Q::CoordinateMatrix(Axis::X) if op == "interpolate" => Label::math("C_x", "C_x"),
        Q::Points if fit => w("data points", "puntos dato"),
        Q::Points => w("points", "puntos"),
        Q::Surface => w("surface", "superficie"),
        Q::Curve => w("curve", "curva"),
        Q::Order if op == "continuity" => w("order of continuity", "orden de continuidad"),
        Q::Order => w("order", "orden"),
        Q::FirstCellPlanar => w("first cell planar", "primera celda plana"),
        Q::LastCellPlanar => w("last cell planar", "última celda plana"),
        Q::Developable => w("developable", "desarrollable"),
        Q::Corners => w("corners", "esquinas"),
        Q::Smoothness => w("continuity", "continuidad"),
        Q::Fails => w("condition that fails", "condición que falla"),
        // a triangular patch's result is `{"triangle": rows}` (it feeds back as input): the
        // result is the patch, its one entry the net
        Q::Triangle if problem.is_none() => w("control net", "red de control"),
        Q::Triangle => w("triangular patch", "superficie triangular"),
        Q::Point => w("point", "punto"),
        Q::BoundaryCurve(Border::U0) => Label::math("c(0, v)", "c(0, v)"),
        Q::BoundaryCurve(Border::U1) => Label::math("c(1, v)", "c(1, v)"),
        Q::BoundaryCurve(Border::V0) => Label::math("c(u, 0)", "c(u, 0)"),
        Q::BoundaryCurve(Border::V1) => Label::math("c(u, 1)", "c(u, 1)"),
        Q::BoundaryCurve(Border::Uv1) => Label::math("b(u, 1 - u)", "b(u, 1 - u)"),
        Q::IsExact if op == "reduce_degree" => w("exact reduction", "reducción exacta"),
        Q::IsExact => w("exact", "exacto"),
        Q::Residual => w("residual", "residuo"),
        Q::Pieces => w("pieces", "trozos"),
        Q::KnotLines => w("knot lines", "líneas de nudos"),
        Q::EdgeOfRegression => w("edge of regression", "arista de retroceso"),
        Q::JoinDerivatives(Side::First) => w(
            "derivatives of the first curve",
            "derivadas de la primera curva",
        ),
        Q::JoinDerivatives(Side::Second) => w(
            "derivatives of the second curve",
            "derivadas de la segunda curva",
        ),
        Q::Length => w("length", "longitud"),
        Q::Curves => w("curves", "curvas"),
        Q::Surfaces => w("surfaces", "superficies"),
        Q::Triangles => w("triangular patches", "superficies triangulares"),
        Q::Intervals => w("intervals", "intervalos"),
        Q::IntervalsU => w("intervals in u", "intervalos en u"),
        Q::IntervalsV => w("intervals in v", "intervalos en v"),
        Q::GeometricOrder => w(
            "order of geometric continuity",
            "orden de continuidad geométrica",
        ),
        Q::ShapeFactor => w("shape factor", "factor de forma"),
        Q::ConicKind => w("kind of conic", "tipo de cónica"),
        Q::Integral => Label::math("∫ c(t) dt", r"\int c(t)\, dt"),
        Q::Mean => w("parametric mean", "media paramétrica"),
        Q::BasisIntegrals => w(
            "integrals of the basis functions",
            "integrales de las funciones base",
        ),
        Q::Area => w("area", "área"),
        Q::SignedArea => w("signed area", "área con signo"),
        Q::Orientation => w("orientation", "sentido de recorrido"),
        Q::Jacobian => Label::math("J(u, v)", "J(u, v)"),
        Q::PlaneNormal => w("normal of the plane", "normal del plano"),
        Q::Normal => Label::math("N(u, v)", "N(u, v)"),
        Q::Normals => w("normal vectors", "vectores normales"),
        // where the numerator of the Gaussian curvature vanishes
        Q::GaussianNumerator => Label::math("G(u, v)", "G(u, v)"),
        Q::CurvatureSign => w("sign of G", "signo de G"),
        Q::Zeros => w("zeros of G", "ceros de G"),
        Q::SpeedSquared => Label::math("c'·c'", "c' \\cdot c'"),
        Q::Zero => w("zero of G", "cero de G"),
        Q::SignChange => w("points where G > 0 and G < 0", "puntos donde G > 0 y G < 0"),
        Q::Domain => w("domain", "dominio"),
        Q::Segment => w("segment of the domain", "segmento del dominio"),
        Q::CornerNormal { corner, limit } => corner_normal(*corner, *limit, lang),
        Q::CornerNumerator(Corner { i, j }) | Q::VertexNumerator(Corner { i, j }) => {
            Label::math(&format!("G({i}, {j})"), &format!("G({i}, {j})"))
        }
        // the fields of a knot line and of a rational triangle
        Q::KnotDirection => w("direction", "dirección"),
        Q::Knot => w("knot", "nudo"),
        Q::Multiplicity => w("multiplicity", "multiplicidad"),
        Q::ExpectedOrder => w("expected order", "orden esperado"),
        Q::Knots => w("knots", "nudos"),
        Q::Multiplicities => w(
            "multiplicities of the knots",
            "multiplicidades de los nudos",
        ),
        Q::Spans => w("spans of the parameters", "tramos de los parámetros"),
        Q::Span => w("span", "tramo"),
        Q::Weights => w("weights", "pesos"),
        Q::Inverse => Label::math("t : c(t) = P", "t : c(t) = P"),
        Q::OnCurve => w("P on the curve", "P en la curva"),
        Q::DataParameters => w(
            "parameters of the data points",
            "parámetros de los puntos dato",
        ),
        // a piece's interval in u, the value of u on a border: the variable
        Q::Variable(v) => symbol(v.name()),
        // symbols, written as the notes write them: α, B_U, c_c, a construction's `c_u`
        Q::CoordinateMatrix(_)
        | Q::Alpha
        | Q::Beta
        | Q::CollocationU
        | Q::CollocationV
        | Q::Collocation
        | Q::CoonsC
        | Q::CoonsD
        | Q::CoonsCd
        | Q::Symbol(_) => symbol(&quantity.name()),
    }
}

/// The label of an argument of a problem in a key, by its kind, in the context of its
/// problem: a curve, a surface, points as the results of that kind ([`label`]); c1 is c_1.
pub fn argument_label(argument: &Argument, problem: Option<&Problem>, lang: Lang) -> Label {
    use Argument as A;
    let w = |en: &str, es: &str| Label::words(en, es, lang);
    let as_result = |q: Quantity| label(&q, problem, lang);
    match argument {
        A::C1 => Label::math("c1", "c_1"),
        A::C2 => Label::math("c2", "c_2"),
        A::D1 => Label::math("d1", "d_1"),
        A::D2 => Label::math("d2", "d_2"),
        A::Parameters => w("parameters", "parámetros"),
        A::First => w("first patch", "primera superficie"),
        A::Second => w("second patch", "segunda superficie"),
        A::CommonBorder => w("common border", "borde común"),
        A::IntervalLengths => w("interval lengths", "longitudes de los intervalos"),
        A::Basis => w("basis", "base"),
        A::EndConditions => w("end conditions", "condiciones en los extremos"),
        // an argument of an interpolation only
        A::EndDerivatives => w("end derivatives", "derivadas en los extremos"),
        A::Degree => w("degree", "grado"),
        A::Elevation => w("elevation", "elevación"),
        A::AtBorder => w("on the border", "en el borde"),
        A::Arcs => w("arcs", "arcos"),
        A::Radius => w("radius", "radio"),
        A::Center => w("center", "centro"),
        A::Interval => w("interval", "intervalo"),
        A::Quadrant => w("quadrant", "cuadrante"),
        A::Knot => w("knot", "nudo"),
        A::Times => w("times", "veces"),
        A::Direction => w("direction", "dirección"),
        A::Blend => w("blending functions", "funciones de mezcla"),
        A::Knots => w("knots", "nudos"),
        A::Weight => w("weight", "peso"),
        A::KnotsU => w("knots in u", "nudos en u"),
        A::KnotsV => w("knots in v", "nudos en v"),
        A::Vertices => w("vertices", "vértices"),
        A::Convention => w("convention of the knots", "convenio de los nudos"),
        A::Spacing => w("spacing of the knots", "espaciado de los nudos"),
        A::ControlPoints => w("number of control points", "número de puntos de control"),
        A::Point => Label::math("P", "P"),
        A::Surface => as_result(Quantity::Surface),
        A::Curve => as_result(Quantity::Curve),
        A::Triangle => as_result(Quantity::Triangle),
        A::Points => as_result(Quantity::Points),
        A::Order => as_result(Quantity::Order),
        A::Parametrization => as_result(Quantity::Parametrization),
        A::Domain => as_result(Quantity::Domain),
        A::Sections => w("sections", "secciones"),
        A::Sweep => w("sweep angle", "ángulo de barrido"),
        A::Start => w("start angle", "ángulo inicial"),
        // the notes' letters
        A::U | A::V | A::T | A::W | A::C | A::D | A::Function => symbol(argument.name()),
    }
}

/// A symbol as the notes write it: a parameter or a coordinate as it is (u, v, t, f, B),
/// else by [`latex_name`] (`c_u` is c_{u}).
fn symbol(name: &str) -> Label {
    if name.chars().count() == 1 {
        return Label::math(name, name);
    }
    Label::math(name, &latex_name(name))
}

/// The normal at a corner, N(1, 0), or its limit there ("limit of N at (1, 0)").
fn corner_normal(Corner { i, j }: Corner, limit: bool, lang: Lang) -> Label {
    if !limit {
        return Label::math(&format!("N({i}, {j})"), &format!("N({i}, {j})"));
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
    Label { text, latex }
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

#[cfg(test)]
mod tests {
    use super::*;
    use cagd_contract::Limits;

    /// The words of a label's text (letters only, lower case).
    fn words(text: &str) -> Vec<String> {
        text.split(|c: char| !c.is_alphabetic())
            .filter(|w| !w.is_empty())
            .map(str::to_lowercase)
            .collect()
    }

    /// Problems whose operation changes some labels (a fit's points, a continuity's order,
    /// the border v of a continuity, a derivative's closed form).
    fn problems() -> Vec<Option<Problem>> {
        let read = |v: serde_json::Value| Problem::read(&v, &Limits::DEFAULT).ok();
        let mut all = vec![None];
        all.extend(
            [
                serde_json::json!({"op": "interpolate", "points": [[0, 0], [1, 1]]}),
                serde_json::json!({"op": "continuity", "border": "v",
                    "first": {"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]]},
                    "second": {"bezier": [[[0, 1, 0], [0, 2, 0]], [[1, 1, 0], [1, 2, 0]]]}}),
                serde_json::json!({"op": "derivative", "curve": {"bezier": [[0, 0], [1, 2]]}}),
                serde_json::json!({"op": "reduce_degree",
                    "curve": {"bezier": [[0, 0], [1, 2], [2, 4]]}}),
            ]
            .into_iter()
            .map(|v| Some(read(v).expect("problem"))),
        );
        all
    }

    /// A label in both languages, neither empty, the Spanish without an English word.
    fn assert_labelled(en: &Label, es: &Label, what: &dyn std::fmt::Debug) {
        assert!(!en.text.is_empty() && !en.latex.is_empty(), "{what:?}");
        assert!(!es.text.is_empty() && !es.latex.is_empty(), "{what:?}");
        let english: Vec<String> = words(&es.text)
            .into_iter()
            .filter(|w| {
                cagd_words::ENGLISH.contains(&w.as_str())
                    || cagd_words::ENGLISH_IN_KEYS.contains(&w.as_str())
            })
            .collect();
        assert!(english.is_empty(), "{what:?}: {} has {english:?}", es.text);
    }

    #[test]
    fn every_quantity_has_a_label_in_both_languages_and_spanish_has_no_english() {
        for problem in problems() {
            for q in Quantity::kinds() {
                let en = label(&q, problem.as_ref(), Lang::En);
                let es = label(&q, problem.as_ref(), Lang::Es);
                assert_labelled(&en, &es, &q);
            }
        }
    }

    #[test]
    fn every_argument_has_a_label_in_both_languages_and_spanish_has_no_english() {
        for problem in problems() {
            for a in Argument::ALL {
                let en = argument_label(&a, problem.as_ref(), Lang::En);
                let es = argument_label(&a, problem.as_ref(), Lang::Es);
                assert_labelled(&en, &es, &a);
            }
        }
    }
}
