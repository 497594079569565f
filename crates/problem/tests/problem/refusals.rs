//! The reading's refusals, in both languages: a decimal comma, a limit, a value at fault
//! named by its path.

use cagd_problem::{solve_with, Limit, Limits, ProblemError};
use cagd_words::{english_in, Lang, Message as _};
use serde_json::{json, Value};

fn refused(p: &Value, limits: &Limits) -> ProblemError {
    solve_with(p, limits).unwrap_err()
}

fn point(y: Value) -> Value {
    json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, y]]}, "params": ["1/2"]})
}

/// The error in both languages: its field, its English, and its Spanish without an English
/// word and without the marks the reading once carried in its text.
fn said(e: &ProblemError) -> (String, String) {
    let en = e.message.phrase(Lang::En).text();
    let es = e.message.phrase(Lang::Es);
    assert_eq!(english_in(&es), Vec::<String>::new(), "{}", es.text());
    let text = e.to_string();
    assert!(!text.contains(['\u{1}', '\u{2}', '\u{3}']), "{text:?}");
    (en, es.text())
}

#[test]
fn a_decimal_comma_is_told_how_to_write_it() {
    let e = refused(&point(json!("1,5")), &Limits::DEFAULT);
    assert_eq!(e.field, "curve.bezier[1][1]");
    assert_eq!(
        said(&e),
        (
            "\"1,5\": the decimal mark is a point: write 3/2 or 1.5".to_string(),
            "\"1,5\": la marca decimal es el punto: escriba 3/2 o 1.5".to_string()
        )
    );
    let e = refused(&point(json!("-0,25")), &Limits::DEFAULT);
    assert_eq!(
        e.message.to_string(),
        "\"-0,25\": the decimal mark is a point: write -1/4 or -0.25"
    );
    // two commas are no decimal: the grammar's error stands
    let e = refused(&point(json!("1,5,2")), &Limits::DEFAULT);
    assert!(e.message.to_string().starts_with("\"1,5,2\": at column 2"));
}

#[test]
fn a_square_root_in_words_is_told_how_to_write_it() {
    for (text, fixed) in [
        ("raiz2", "sqrt2"),
        ("raíz2", "sqrt2"),
        ("Raiz(2)", "sqrt(2)"),
        ("3*raiz 5/2", "3*sqrt 5/2"),
        ("root2", "sqrt2"),
    ] {
        let e = refused(&point(json!(text)), &Limits::DEFAULT);
        assert_eq!(e.field, "curve.bezier[1][1]");
        let (en, es) = said(&e);
        assert_eq!(
            en,
            format!("\"{text}\": a square root is written √2 or sqrt(2): write \"{fixed}\"")
        );
        assert_eq!(
            es,
            format!("\"{text}\": una raíz cuadrada se escribe √2 o sqrt(2): escriba \"{fixed}\"")
        );
    }
    // a word that is no root: the grammar's error stands
    let e = refused(&point(json!("abc2")), &Limits::DEFAULT);
    assert!(e.message.to_string().starts_with("\"abc2\": at column 1"));
}

#[test]
fn shapes_that_do_not_read_are_said_in_spanish() {
    let cases = [
        (point(json!(true)), "curve.bezier[1][1]", "expected a number, found true", "se esperaba un número, se encontró true"),
        (
            json!({"op": "evaluate", "curve": {"bezier": [[0, 0], {"x": 1}]}, "params": [0]}),
            "curve.bezier[1]",
            "expected a point [x, y, z], found an object",
            "se esperaba un punto [x, y, z], se encontró un objeto",
        ),
        (
            json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1]]}, "params": [0]}),
            "curve.bezier[1]",
            "this point has 1 coordinates but the first has 2",
            "este punto tiene 1 coordenadas, pero el primero tiene 2",
        ),
        (
            json!({"op": "evaluate", "curve": {"bezier": [[0, 0]], "weights": [1, 2]}, "params": [0]}),
            "curve.weights",
            "2 weights for 1 control points",
            "2 pesos para 1 puntos de control",
        ),
        (
            json!({"op": "evaluate", "curve": {"bspline": [[0, 0], [1, 1]], "knots": [0, 1]}, "params": [0]}),
            "curve.degree",
            "missing (this operation needs it)",
            "falta (esta operación lo necesita)",
        ),
        (
            json!({"op": "evaluate", "surface": {"bezier": [[[0, 0, 0]], [[1, 0, 0], [1, 1, 0]]]}, "params": [0, 0]}),
            "surface.bezier[1]",
            "row 1 has 2 points but row 0 has 1: a mesh needs rows of equal length",
            "la fila 1 tiene 2 puntos, pero la fila 0 tiene 1: las filas de una malla de control han de tener la misma longitud",
        ),
        (
            json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 1.5]]}, "params": [0]}),
            "curve.bezier[1][1]",
            "the number 1.5 has a fraction part; write it as a string (\"1.5\") so it is read exactly",
            "el número 1.5 tiene parte decimal; escríbalo como cadena (\"1.5\") para leerlo exactamente",
        ),
    ];
    for (p, field, en, es) in cases {
        let e = refused(&p, &Limits::DEFAULT);
        assert_eq!(e.field, field, "{p}");
        assert_eq!(said(&e), (en.to_string(), es.to_string()), "{p}");
        assert_eq!(e.limit, None);
    }
}

#[test]
fn a_limit_is_carried_typed() {
    let tight = Limits {
        max_degree: 2,
        max_points: 4,
        max_digits: 10,
        ..Limits::default()
    };
    let cases = [
        (
            json!({"op": "evaluate", "curve": {"bezier": [[0], [1], [2], [3]]}, "params": [0]}),
            "curve.bezier",
            "4 control points make a Bézier curve of degree 3, above the limit of 2 for degrees",
            Limit::Degree,
        ),
        (
            json!({"op": "evaluate", "curve": {"bezier": [[0], [1], [2], [3], [4]]}, "params": [0]}),
            "curve.bezier",
            "a list of 5 items is longer than the limit of 4",
            Limit::Points,
        ),
        (
            point(json!("10^10")),
            "curve.bezier[1][1]",
            "\"10^10\": limit exceeded: a number of 11 digits is longer than the limit of 10 digits",
            Limit::Digits,
        ),
        (
            point(json!(123_456_789_012_i64)),
            "curve.bezier[1][1]",
            "a number of 12 digits is longer than the limit of 10 digits",
            Limit::Digits,
        ),
    ];
    for (p, field, en, limit) in cases {
        let e = refused(&p, &tight);
        assert_eq!(e.field, field, "{p}");
        assert_eq!(said(&e).0, en, "{p}");
        assert_eq!(e.limit, Some(limit), "{p}");
    }
}

#[test]
fn a_second_root_names_the_first() {
    let p =
        json!({"op": "evaluate", "curve": {"bezier": [[0, "sqrt2"], [1, "sqrt3"]]}, "params": [0]});
    let e = refused(&p, &Limits::DEFAULT);
    assert_eq!(e.field, "curve.bezier[1][1]");
    assert_eq!(
        said(&e),
        (
            "this number needs √3, but curve.bezier[0][1] needs √2: a problem runs in one field a + b√d".to_string(),
            "este número necesita √3, pero curve.bezier[0][1] necesita √2: un problema se resuelve en un solo cuerpo a + b√d".to_string()
        )
    );
}

#[test]
fn a_repeating_decimal_is_remarked_typed() {
    let a = solve_with(&point(json!("0.3333")), &Limits::DEFAULT).unwrap();
    let remark = a.remarks.first().unwrap();
    assert_eq!(
        remark.to_string(),
        "\"0.3333\" is read exactly as 3333/10000; if 1/3 is meant, write \"1/3\""
    );
    assert_eq!(
        remark.phrase(Lang::Es).text(),
        "\"0.3333\" se lee exactamente como 3333/10000; si se quiere decir 1/3, escriba \"1/3\""
    );
}
