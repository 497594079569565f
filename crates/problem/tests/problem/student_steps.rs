//! The worked steps a student needs, as the notes give them: the ruled mesh's columns, the
//! restriction's passes in the notes' order, a curve raised before a ruled or Coons mesh,
//! the translational weights, a derivative before its value on a border, the systems of a
//! bicubic spline, the generic corner normal in factored form, and the errata said as what
//! they are (a scale; the hemisphere's printed rows).

use cagd_keys::{example_latex, example_text, Lang};
use cagd_problem::{check, check_with_settings, Settings};
use serde_json::{json, Value};
use std::path::Path;

fn fixture(path: &str) -> Value {
    let file = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../fixtures")
        .join(path);
    let text = std::fs::read_to_string(&file).expect("readable fixture");
    serde_json::from_str(&text).expect("a fixture")
}

/// The key of a fixture (its steps included) in `lang`, as text.
fn fixture_key(path: &str, lang: Lang) -> String {
    let verdict = check(&fixture(path));
    assert!(verdict.passed(), "{path}: {:?}", verdict.mismatches);
    example_text(&verdict, lang)
}

/// The key of a problem with its steps in `lang`, as text.
fn key(problem: &Value, lang: Lang) -> String {
    let verdict = check_with_settings(problem, &Settings::default());
    assert!(verdict.answer.is_ok(), "{:?}", verdict.answer.err());
    example_text(&verdict, lang)
}

/// The position of `needle` in `text`, or a panic that shows the text.
fn at(text: &str, needle: &str) -> usize {
    text.find(needle)
        .unwrap_or_else(|| panic!("{needle:?} not in:\n{text}"))
}

#[test]
fn the_ruled_mesh_is_its_columns_as_the_notes_say() {
    let es = fixture_key("ch6/04-ruled-bezier.json", Lang::Es);
    at(
        &es,
        "sus dos columnas, j = 0 y j = 1, son los polígonos de c_1 y c_2",
    );
    assert!(!es.contains("las filas son los polígonos"), "{es}");
    let en = fixture_key("ch6/04-ruled-bezier.json", Lang::En);
    at(
        &en,
        "its two columns, j = 0 and j = 1, are the polygons of c_1 and c_2",
    );
    // and the printed mesh is laid out so: its rows are (c_{1i}, c_{2i})
    at(&es, "c_{i,0} = c_{1i} = {(0, 0, 0), (1, 0, 1), (2, 0, 0)}");
}

#[test]
fn the_restriction_works_the_rows_in_v_first_and_shows_the_notes_c_hat() {
    let es = fixture_key("ch5/04-restriction.json", Lang::Es);
    at(
        &es,
        "primero cada fila en v, restringida a [c, d] (la malla ĉ)",
    );
    assert!(!es.contains("primero en u (la malla ĉ)"), "{es}");
    // the notes' ĉ_{0,0} = c_0[1/3, 1/3] = (2/3, 0, 19/9), then the columns of ĉ in u
    let rows = at(&es, "Primer paso, en v");
    let hat = at(&es, "ĉ_{0,0} = c_0[1/3, 1/3] = (2/3, 0, 19/9)");
    let columns = at(&es, "Segundo paso, en u: cada columna j de ĉ");
    let tilde = at(&es, "c̃_{0,0} = c[1/2, 1/2; 1/3, 1/3] = (2/3, 2, 47/18)");
    assert!(rows < hat && hat < columns && columns < tilde, "{es}");
}

/// A Coons patch of c1 quadratic and c2 cubic (the notes' example with c1 of degree 2).
fn coons_of_different_degrees() -> Value {
    json!({"op": "coons",
        "c1": {"bezier": [[0, 0, 0], [1, 0, 2], [2, 0, 0]]},
        "c2": {"bezier": [[0, 3, 0], ["1/2", 3, 3], [1, 3, 1], [2, 4, 0]]},
        "d1": {"bezier": [[0, 0, 0], [0, 1, 3], [0, 3, 0]]},
        "d2": {"bezier": [[2, 0, 0], [2, 1, 2], [2, 4, 0]]}})
}

#[test]
fn a_coons_curve_of_lower_degree_is_raised_in_a_step() {
    let es = key(&coons_of_different_degrees(), Lang::Es);
    let raised = at(
        &es,
        "c_1 es de grado 2 y c_2 de grado 3: la malla de control necesita polígonos del mismo grado, así que primero se eleva c_1 al grado 3",
    );
    let point = at(
        &es,
        "c_{11}^{(1)} = 1/3 c_{10} + 2/3 c_{11} = 1/3 (0, 0, 0) + 2/3 (1, 0, 2) = (2/3, 0, 4/3)",
    );
    at(&es, "c_{12}^{(1)} = 2/3 c_{11} + 1/3 c_{12}");
    // before the mesh where c_{1,0} = (2/3, 0, 4/3) is used
    let mesh = at(
        &es,
        "c_{1,0} = c_{c 1,0} + c_{d 1,0} - c_{cd 1,0} = (2/3, 0, 4/3)",
    );
    assert!(raised < point && point < mesh, "{es}");
    let en = key(&coons_of_different_degrees(), Lang::En);
    at(&en, "so c_1 is first raised to degree 3");
    // the same curves at the same degree: no elevation step
    let mut same = coons_of_different_degrees();
    same["c1"] = json!({"bezier": [[0, 0, 0], ["1/2", 0, 2], [1, 0, 3], [2, 0, 0]]});
    assert!(!key(&same, Lang::Es).contains("se eleva"));
}

#[test]
fn a_ruled_curve_of_lower_degree_is_raised_in_the_same_step() {
    let problem = json!({"op": "ruled",
        "c1": {"bezier": [[0, 0, 0], [1, 0, 2], [2, 0, 0]]},
        "c2": {"bezier": [[0, 3, 0], ["1/2", 3, 3], [1, 3, 1], [2, 4, 0]]}});
    let es = key(&problem, Lang::Es);
    at(&es, "primero se eleva c_1 al grado 3");
    at(&es, "c_{11}^{(1)} = 1/3 c_{10} + 2/3 c_{11}");
    at(
        &es,
        "c_{i,0} = c_{1i}^{(1)} = {(0, 0, 0), (2/3, 0, 4/3), (4/3, 0, 4/3), (2, 0, 0)}",
    );
}

#[test]
fn the_rational_translational_surface_shows_its_intermediate_values() {
    let problem = json!({"op": "translational",
        "c": {"bezier": [[1, 0, 0], [1, 1, 0], [0, 1, 0]], "weights": [1, "1/2", 1]},
        "d": {"bezier": [[1, 0, 0], [1, 0, 1], [1, 1, 1]], "weights": [1, 2, 1]}});
    let es = key(&problem, Lang::Es);
    let follow = at(&es, "siguen sus valores intermedios");
    let point = at(
        &es,
        "c_{1,1} = c_{11} + d_{11} - a = (1, 1, 0) + (1, 0, 1) - (1, 0, 0) = (1, 1, 1)",
    );
    let weight = at(&es, "w_{1,1} = w_{11} ω_{11} = 1/2 · 2 = 1");
    assert!(follow < point && point < weight, "{es}");
}

#[test]
fn the_cross_boundary_derivative_shows_c_u_before_its_value_on_the_border() {
    let es = fixture_key("ch6/08-coons-cross-derivative.json", Lang::Es);
    let general = at(&es, "c_u(u, v) = (1, 0, 3 u^2 v - 2 u v + v^2 + 2 u - v)");
    let border = at(&es, "\n    u = 1\n");
    let value = at(&es, "c_u(1, v) = (1, 0, v^2 + 2)");
    assert!(general < border && border < value, "{es}");
}

#[test]
fn the_bicubic_spline_shows_the_system_of_each_pass() {
    let problem = json!({"op": "interpolate", "basis": "bicubic",
        "u": [0, 1, 2], "v": [0, 1, 2],
        "points": [[[0, 0, 0], [0, 1, 1], [0, 2, 0]], [[1, 0, 1], [1, 1, 2], [1, 2, 1]],
                   [[2, 0, 0], [2, 1, 1], [2, 2, 0]]]});
    let es = key(&problem, Lang::Es);
    let rows = at(
        &es,
        "Primer paso, en v: cada fila i de puntos dato se interpola",
    );
    // the matrix (tridiagonal but for its rows of end conditions) and the first row's system
    let matrix = at(
        &es,
        "N_V = [6, -9, 3, 0, 0;\n        1, 0, 0, 0, 0;\n        0, 1/4, 1/2, 1/4, 0;",
    );
    let rhs = at(&es, "A_0 = [0, 0, 0;\n        0, 0, 0;\n        0, 1, 1;");
    let solution = at(&es, "D̃_0 = [0, 0, 0;\n        0, 1/3, 1/2;");
    let columns = at(&es, "Segundo paso, en u: cada columna j de d̃");
    at(&es, "N_U = [");
    at(&es, "A\u{303}_0 = [");
    at(&es, "D_0 = [0, 0, 0;\n        1/3, 0, 1/2;");
    assert!(rows < matrix && matrix < rhs && rhs < solution && solution < columns);
    let en = key(&problem, Lang::En);
    at(
        &en,
        "First pass, in v: each row i of data points is interpolated",
    );
}

#[test]
fn the_generic_corner_normal_is_factored_as_the_notes_print_it() {
    for lang in [Lang::Es, Lang::En] {
        let text = fixture_key("ch5/14-formula-corner-normal.json", lang);
        at(
            &text,
            "n(0, 0) = mn Δ^{1,0} c_{0,0} × Δ^{0,1} c_{0,0} = 4 (c_{1,0} - c_{0,0}) × (c_{0,1} - c_{0,0})",
        );
        // no expanded c_u, c_v nor closed form n(u, v): the key was three pages of them
        assert!(text.len() < 6_000, "{} characters:\n{text}", text.len());
        assert!(!text.contains("u v^2"), "{text}");
        let verdict = check(&fixture("ch5/14-formula-corner-normal.json"));
        let latex = example_latex(&verdict, lang);
        assert!(latex.len() < 9_000, "{} characters:\n{latex}", latex.len());
        at(&latex, "(c_{1,0} - c_{0,0}) \\times (c_{0,1} - c_{0,0})");
    }
}

#[test]
fn the_corner_normal_erratum_is_one_of_scale_without_expanded_polynomials() {
    let es = fixture_key("ch5/14-formula-corner-normal.json", Lang::Es);
    let verdict = &es[at(&es, "veredicto:")..];
    at(verdict, "errata de escala (la dirección es la misma)");
    at(verdict, "n(0, 0) = Δ^{1,0}c_{0,0} × Δ^{0,1}c_{0,0}");
    at(verdict, "4 (c_{1,0} - c_{0,0}) × (c_{0,1} - c_{0,0})");
    at(verdict, "dividido entre mn (aquí 4)");
    // the notes never print the cross product expanded in the letters
    assert!(!verdict.contains("y_{0,0} z_{1,0}"), "{verdict}");
    let en = fixture_key("ch5/14-formula-corner-normal.json", Lang::En);
    at(&en, "erratum of scale (the direction is the same)");
}

#[test]
fn the_hemisphere_erratum_describes_the_printed_rows() {
    for path in [
        "slides/01-hemisphere.json",
        "slides/05-hemisphere-radius-r.json",
    ] {
        let es = fixture_key(path, Lang::Es);
        let verdict = &es[at(&es, "veredicto:")..];
        // the printed middle row is √2/2, 1/2, ... with a tenth entry 1/2
        at(
            verdict,
            "√2/2, 1/2, √2/2, 1/2, √2/2, 1/2, √2/2, 1/2, √2/2, 1/2; 1, √2/2",
        );
        at(verdict, "1/2 al final de la fila central");
        // the exact middle row has 9 weights, beginning and ending with √2/2
        at(
            verdict,
            "√2/2, 1/2, √2/2, 1/2, √2/2, 1/2, √2/2, 1/2, √2/2; 1, √2/2",
        );
    }
}
