//! LaTeX that typesets: mathematics in math mode, no escaped carets or `\text{1}`, the
//! revolution parametrization as mathematics, a complete document with vector fonts.

use cagd_keys::{example_latex, latex_document, Lang};
use cagd_problem::check;
use serde_json::json;

#[test]
fn mathematics_in_math_mode() {
    let fixtures = [
        include_str!("../../../../fixtures/ch5/07-c1-join.json"),
        include_str!("../../../../fixtures/ch6/08-coons-cross-derivative.json"),
        include_str!("../../../../fixtures/ch5/05-elevate-u.json"),
        include_str!("../../../../fixtures/slides/02-ruled-bezier-mesh.json"),
    ];
    for f in fixtures {
        let v = check(&serde_json::from_str(f).unwrap());
        for lang in [Lang::En, Lang::Es] {
            let tex = example_latex(&v, lang);
            for bad in [
                "\\^{}",
                "\\text{1}",
                "\\text{0}",
                "d_{tilde}",
                "$\\Delta$\\^",
            ] {
                assert!(!tex.contains(bad), "{bad} in\n{tex}");
            }
        }
    }
    let join = check(&serde_json::from_str(fixtures[0]).unwrap());
    let tex = example_latex(&join, Lang::Es);
    assert!(tex.contains("$C^{0}$, pero no $C^{1}$"), "{tex}");
    assert!(tex.contains("\\text{orden de continuidad} = 0$"), "{tex}");
    assert!(tex.contains("\\tilde{c}(u, v) = "), "{tex}");
}

#[test]
fn the_revolution_parametrization_is_mathematics() {
    let v = check(&json!({"op": "revolution", "curve": {"expr": "(u + 1, 0, u^2)"}}));
    let tex = example_latex(&v, Lang::En);
    assert!(
        tex.contains("$\\displaystyle c(u, v) = ((u + 1) \\cos v, (u + 1) \\sin v, u^{2})$"),
        "{tex}"
    );
}

#[test]
fn a_document_with_vector_fonts_and_wide_matrices_fitted() {
    let doc = latex_document("t", &[], Lang::Es);
    assert!(doc.contains("\\usepackage[T1]{fontenc}\n\\usepackage{lmodern}"));
    assert!(doc.contains("\\newcommand{\\fitmath}"));
    let hemisphere = check(
        &serde_json::from_str(include_str!(
            "../../../../fixtures/slides/01-hemisphere.json"
        ))
        .unwrap(),
    );
    let tex = example_latex(&hemisphere, Lang::En);
    assert!(tex.contains("\\fitmath{\\begin{Bmatrix}"), "{tex}");
}

/// The closed form of a (20, 20) grid interpolation, terms of a few hundred points each
/// (fractions of fifty digits), breaks only after its + and -: it is set ragged right, so a
/// line may end short instead of running off the page (pdflatex reported overfull lines).
/// A short closed form is left as it was.
#[test]
fn a_long_closed_form_is_set_ragged_right() {
    let n = 20;
    let ts: Vec<String> = (0..n).map(|i| format!("{i}/{}", n - 1)).collect();
    let points: Vec<Vec<[usize; 3]>> = (0..n)
        .map(|i| {
            (0..n)
                .map(|j| [i, j, (i * j + 3 * i + 7 * j) % 5])
                .collect()
        })
        .collect();
    let problem =
        json!({"op": "interpolate", "basis": "bezier", "u": ts, "v": ts, "points": points});
    let settings = cagd_problem::Settings {
        steps: false,
        ..Default::default()
    };
    let v = cagd_problem::check_with_settings(&problem, &settings);
    for lang in [Lang::En, Lang::Es] {
        let tex = example_latex(&v, lang);
        let line = tex
            .lines()
            .find(|l| l.contains("c(u, v) = "))
            .expect("the closed form");
        assert!(
            line.starts_with("\\item {\\raggedright $\\displaystyle c(u, v) = ")
                && line.ends_with("$\\par}"),
            "{}",
            &line[..200.min(line.len())]
        );
    }
    let small = check(
        &json!({"op": "closed_form", "surface": {"bezier": [[[0, 0, 0], [0, 1, 1]], [[1, 0, 1], [1, 1, 0]]]}}),
    );
    let tex = example_latex(&small, Lang::En);
    assert!(!tex.contains("raggedright"), "{tex}");
}
