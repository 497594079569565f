//! The keywords of a problem (`basis`, `end`, `blend`, `parametrization`, `direction`) are
//! echoed in its key as words, never as JSON strings in quotes, in every format, and in
//! Spanish where they have Spanish words of their own (`cagd_keys::Keyword`); the `sign` of the Gaussian
//! curvature is said in words.

use cagd_keys::{example_latex, example_markdown, example_text, Lang};
use cagd_problem::{check_with_settings, Settings};
use serde_json::{json, Value};

/// The three keys (text, Markdown, LaTeX) of `problem` in `lang`.
fn keys(problem: &Value, lang: Lang) -> [String; 3] {
    let v = check_with_settings(problem, &Settings::default());
    [
        example_text(&v, lang),
        example_markdown(&v, lang),
        example_latex(&v, lang),
    ]
}

fn grid() -> Value {
    json!([
        [[0, 0, 0], [0, 1, 0], [0, 2, 1]],
        [[1, 0, 1], [1, 1, 0], [1, 2, 2]],
        [[2, 0, 0], [2, 1, 1], [2, 2, 0]]
    ])
}

#[test]
fn keywords_are_words_in_every_format_and_language() {
    let problems = [
        (
            json!({"op": "interpolate", "basis": "bicubic", "end": "bessel", "u": [0, "1/2", 1], "v": [0, "1/2", 1], "points": grid()}),
            [
                ("basis = bicubic", "base = spline bicúbico"),
                (
                    "end conditions = Bessel",
                    "condiciones en los extremos = de Bessel",
                ),
            ],
        ),
        (
            json!({"op": "interpolate", "basis": "bezier", "parametrization": "uniform", "points": grid()}),
            [
                ("basis = Bézier", "base = Bézier"),
                (
                    "parameters from the data = uniform",
                    "parámetros a partir de los datos = uniformes",
                ),
            ],
        ),
        (
            json!({"op": "coons", "blend": "cubic", "c1": {"bezier": [[0, 0, 0], [1, 0, 0]]}, "c2": {"bezier": [[0, 1, 0], [1, 1, 0]]}, "d1": {"bezier": [[0, 0, 0], [0, 1, 0]]}, "d2": {"bezier": [[1, 0, 0], [1, 1, 0]]}}),
            [
                (
                    "blending functions = cubic",
                    "funciones de mezcla = cúbicas",
                ),
                (
                    "blending functions = cubic",
                    "funciones de mezcla = cúbicas",
                ),
            ],
        ),
    ];
    for (problem, pairs) in &problems {
        for (lang, pick) in [(Lang::En, 0), (Lang::Es, 1)] {
            let [text, markdown, latex] = keys(problem, lang);
            for (en, es) in pairs {
                let line = if pick == 0 { en } else { es };
                assert!(text.contains(line), "text: {line} in\n{text}");
                let (label, word) = line.split_once(" = ").expect("label = word");
                let md = format!("- {label}: {word}");
                assert!(markdown.contains(&md), "markdown: {md} in\n{markdown}");
                let tex = format!("$\\text{{{label}}}$: {word}");
                assert!(latex.contains(&tex), "latex: {tex} in\n{latex}");
            }
            for key in [&text, &markdown, &latex] {
                assert!(
                    !key.contains("\"bicubic\"")
                        && !key.contains("\"bezier\"")
                        && !key.contains("\"cubic\"")
                        && !key.contains("\"uniform\"")
                        && !key.contains("\"bessel\""),
                    "{key}"
                );
            }
        }
    }
}

/// The `sign` of `gaussian_curvature` is said in words: 0 means G vanishes somewhere on the
/// domain (docs/format.md), not that G is 0, so a key no longer prints "sign of G = 0".
#[test]
fn the_sign_of_the_gaussian_curvature_is_said_in_words() {
    let cases = [
        (
            "(u, v, u^3 - v^2)",
            "sign of G = none (G vanishes on the domain)",
            "signo de G = ninguno (G se anula en el recinto)",
        ),
        (
            "(u, v, u^2 + v^2)",
            "sign of G = positive (G > 0)",
            "signo de G = positivo (G > 0)",
        ),
        (
            "(u, v, u^2 - v^2)",
            "sign of G = negative (G < 0)",
            "signo de G = negativo (G < 0)",
        ),
    ];
    for (expr, en, es) in cases {
        let problem = json!({"op": "gaussian_curvature", "surface": {"expr": expr}});
        for (lang, line) in [(Lang::En, en), (Lang::Es, es)] {
            let [text, markdown, latex] = keys(&problem, lang);
            assert!(text.contains(line), "{line} in\n{text}");
            assert!(
                ["0", "1", "-1"]
                    .iter()
                    .all(|n| !text.contains(&format!("sign of G = {n}\n"))
                        && !text.contains(&format!("signo de G = {n}\n"))),
                "{text}"
            );
            let (label, words) = line.split_once(" = ").expect("label = words");
            let words_md = words.replace('<', "&lt;").replace('>', "&gt;");
            assert!(
                markdown.contains(&format!("- {label}: {words_md}")),
                "{markdown}"
            );
            assert!(
                latex.contains(&format!("$\\text{{{label}}}$: {words}")),
                "{latex}"
            );
        }
    }
    // in each piece of a B-spline surface too
    let problem = json!({"op": "gaussian_curvature", "surface": {"bspline": [[[0, 0, 0], [0, 1, 0], [0, 2, 0]], [[1, 0, 0], [1, 1, 1], [1, 2, 0]], [[2, 0, 0], [2, 1, 0], [2, 2, 1]]], "degree": [1, 1], "knots": [[0, 1, 2], [0, 1, 2]]}});
    let [text, _, _] = keys(&problem, Lang::Es);
    assert_eq!(
        text.matches("signo de G = negativo (G < 0)").count(),
        5,
        "{text}"
    );
}

/// An expression of the problem (`graph`'s `f`) is echoed as mathematics, the polynomial it
/// reads as, in every format and language: `f = x y`, never the JSON string `"x*y"`; in
/// LaTeX and Markdown typeset as math, not as words in quotes.
#[test]
fn expressions_are_echoed_as_mathematics() {
    let cases = [
        (
            json!({"op": "graph", "f": "x*y", "degree": [1, 1]}),
            "f = x y",
            "$\\displaystyle f = x y$",
            "- $f = x y$",
        ),
        (
            json!({"op": "graph", "f": "x^2 + 3/2*y", "domain": [[0, 0], [1, 0], [0, 1]]}),
            "f = x^2 + 3/2 y",
            "$\\displaystyle f = x^{2} + \\frac{3}{2} y$",
            "- $f = x^{2} + \\frac{3}{2} y$",
        ),
        (
            json!({"op": "graph", "f": "a*x*y", "parameters": ["a"]}),
            "f = a x y",
            "$\\displaystyle f = a x y$",
            "- $f = a x y$",
        ),
    ];
    for (problem, text_line, latex_line, markdown_line) in &cases {
        for lang in [Lang::En, Lang::Es] {
            let [text, markdown, latex] = keys(problem, lang);
            assert!(text.contains(text_line), "text: {text_line} in\n{text}");
            assert!(
                latex.contains(latex_line),
                "latex: {latex_line} in\n{latex}"
            );
            assert!(
                markdown.contains(markdown_line),
                "markdown: {markdown_line} in\n{markdown}"
            );
            for key in [&text, &markdown, &latex] {
                assert!(!key.contains("f = \"") && !key.contains("f: \""), "{key}");
                assert!(!key.contains("\\text{\"") && !key.contains("``"), "{key}");
            }
        }
    }
}
