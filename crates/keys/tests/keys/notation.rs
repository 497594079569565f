//! Keys in the notes' notation: no internal names, data points called data points, knots in
//! the convention they were given, problems numbered from 1, a fixture's note printed.

use cagd_keys::{example_latex, example_markdown, example_text, Lang};
use cagd_problem::{check, check_batch, Limits, Settings};
use serde_json::json;

fn every_format(v: &cagd_problem::Verdict, lang: Lang) -> [String; 3] {
    [
        example_text(v, lang),
        example_latex(v, lang),
        example_markdown(v, lang),
    ]
}

#[test]
fn no_internal_names() {
    let interpolation = json!({"op": "interpolate", "basis": "bezier", "u": [0, "1/2", 1],
        "v": [0, 1], "points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 1], [1, 1, 1]], [[2, 0, 0], [2, 1, 1]]]});
    let least_squares = json!({"op": "approximate", "degree": [1, 1],
        "points": [[0, 0, 0], [1, 0, 1], [0, 1, 1], [1, 1, 0], ["1/2", "1/2", "1/4"]],
        "params": [[0, 0], [1, 0], [0, 1], [1, 1], ["1/2", "1/2"]]});
    let normal = json!({"op": "normal", "surface": {"bezier": [[[1, 0, 0], [1, 1, 0], [0, 1, 0]],
        [[1, 0, 1], [1, 1, 1], [0, 1, 1]], [[0, 0, 1], [0, 0, 1], [0, 0, 1]]]}});
    let settings = Settings {
        limits: Limits::DEFAULT,
        steps: true,
    };
    let bicubic = json!({"op": "interpolate", "basis": "bicubic", "end": "natural", "u": [0, 1, 2],
        "v": [0, 1, 2], "points": [[[0, 0, 0], [0, 1, 1], [0, 2, 0]], [[1, 0, 1], [1, 1, 2], [1, 2, 1]],
        [[2, 0, 0], [2, 1, 1], [2, 2, 0]]]});
    for p in [interpolation, least_squares, normal, bicubic] {
        let v = cagd_problem::check_with_settings(&p, &settings);
        assert!(v.answer.is_ok(), "{p}");
        for lang in [Lang::En, Lang::Es] {
            for key in every_format(&v, lang) {
                for internal in [
                    "C_tilde",
                    "BtB",
                    "BtA",
                    "corner_",
                    "closed_form =",
                    "tilde}",
                ] {
                    assert!(!key.contains(internal), "{internal} in\n{key}");
                }
            }
        }
    }
    let v = check(
        &json!({"op": "interpolate", "basis": "bezier", "u": [0, 1], "v": [0, 1],
        "points": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]}),
    );
    let text = example_text(&v, Lang::En);
    assert!(
        text.contains("  data points = {(0, 0, 0), (0, 1, 0); (1, 0, 0), (1, 1, 1)}\n"),
        "{text}"
    );
    assert!(example_text(&v, Lang::Es).contains("  puntos dato = {"));
}

#[test]
fn closed_forms_are_named_by_what_they_are() {
    let derivative = check(&json!({"op": "derivative",
        "surface": {"expr": "(u, v, u^2 - v u^2 + v + v u^3 - u v + u v^2)"}, "order": [1, 0], "at": {"u": 1}}));
    assert!(example_text(&derivative, Lang::En).contains("  c_u(1, v) = (1, 0, v^2 + 2)\n"));
    assert!(example_latex(&derivative, Lang::En).contains("c_{u}(1, v) = "));
    let curve = check(&json!({"op": "closed_form", "curve": {"bezier": [[0, 0], [1, 2], [3, 3]]}}));
    let text = example_text(&curve, Lang::En);
    assert!(
        text.contains("  c(u) = ") || text.contains("  c(t) = "),
        "{text}"
    );
    let surface = check(&json!({"op": "closed_form",
        "surface": {"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]}}));
    assert!(example_text(&surface, Lang::En).contains("  c(u, v) = (u, v, u v)\n"));
}

#[test]
fn knots_in_the_convention_given() {
    let notes = json!({"op": "insert_knot", "curve": {"bspline": [[0, 0], [1, 2], [3, 2], [4, 0]],
        "degree": 2, "knots": [0, 0, 1, 2, 2]}, "knot": "1/2", "times": 1});
    let book = json!({"op": "insert_knot", "curve": {"bspline": [[0, 0], [1, 2], [3, 2], [4, 0]],
        "degree": 2, "knots": [0, 0, 0, 1, 2, 2, 2]}, "knot": "1/2", "times": 1});
    let (a, b) = (check(&notes), check(&book));
    // the same exact answer
    assert_eq!(
        a.answer.as_ref().unwrap().result,
        b.answer.as_ref().unwrap().result
    );
    let (ta, tb) = (example_text(&a, Lang::En), example_text(&b, Lang::En));
    assert!(ta.contains("knots {0, 0, 1/2, 1, 2, 2}\n"), "{ta}");
    assert!(!ta.contains("one more knot at each end"));
    assert!(tb.contains("knots {0, 0, 0, 1/2, 1, 2, 2, 2}\n"), "{tb}");
    assert!(
        tb.contains("with one more knot at each end than the notes' convention"),
        "{tb}"
    );
    assert!(example_text(&b, Lang::Es).contains("nudos {0, 0, 0, 1/2, 1, 2, 2, 2}\n"));
}

#[test]
fn problems_are_numbered_from_one() {
    let batch = json!([{"op": "circle", "arcs": 4}, {"op": "circle", "radius": -1}]);
    let settings = Settings {
        limits: Limits::DEFAULT,
        steps: false,
    };
    let vs = check_batch(&batch, &settings, 1);
    assert!(example_text(&vs[0], Lang::En).starts_with("== Problem 1 (circle)\n"));
    let second = example_text(&vs[1], Lang::En);
    assert!(second.starts_with("== Problem 2 (circle)\n"), "{second}");
    assert!(
        second.contains("error: problem 2: not a circle"),
        "{second}"
    );
    let es = example_text(&vs[1], Lang::Es);
    assert!(
        es.contains("error: problema 2: no es una circunferencia: el radio -1 no es positivo"),
        "{es}"
    );
}

#[test]
fn a_fixtures_note_is_printed_in_every_format() {
    let fixture: serde_json::Value = serde_json::from_str(include_str!(
        "../../../../fixtures/ch6/09-truncated-cone-quadrant.json"
    ))
    .unwrap();
    let v = check(&fixture);
    for key in every_format(&v, Lang::En) {
        assert!(
            key.contains("The notes give the mesh symbolically"),
            "{key}"
        );
    }
    for key in every_format(&v, Lang::Es) {
        assert!(
            key.contains("Los apuntes dan la malla de control simbólicamente"),
            "{key}"
        );
    }
}

#[test]
fn every_operation_has_words_in_both_languages() {
    for op in cagd_problem::operations() {
        for lang in [cagd_keys::Lang::En, cagd_keys::Lang::Es] {
            assert!(
                !cagd_keys::op_words(op, lang).is_empty(),
                "`{op}` has no words in {lang:?}"
            );
        }
    }
}
