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
