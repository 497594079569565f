//! The commands: expand, help, solve, check, examples, generate, render.

use crate::common::{cagd, cagd_stdin, format_doc_problems, stderr, stdout};
use std::process::Output;

/// Runs `cagd expand EXPR` expecting success; returns stdout.
fn expand_ok(args: &[&str]) -> String {
    let mut all = vec!["expand"];
    all.extend_from_slice(args);
    let out = cagd(&all);
    assert_eq!(out.status.code(), Some(0), "stderr: {}", stderr(&out));
    assert!(stderr(&out).is_empty());
    stdout(&out)
}

/// Runs `cagd expand EXPR` expecting bad input; returns the one-line stderr.
fn expand_err(expr: &str) -> String {
    let out = cagd(&["expand", expr]);
    assert_eq!(out.status.code(), Some(1), "input {expr}");
    assert!(stdout(&out).is_empty());
    let err = stderr(&out);
    assert_eq!(err.lines().count(), 1, "one line: {err}");
    assert!(!err.contains("panicked"));
    err
}

#[test]
fn expands_the_ruled_surface() {
    assert_eq!(
        expand_ok(&["(1-v)*(u,0,u^3) + v*(u,1,u^2)"]),
        "(u, v, -u^3 v + u^3 + u^2 v)\n"
    );
    assert_eq!(
        expand_ok(&["(1-v)(u,0,u^3) + v(u,1,u^2)"]),
        "(u, v, -u^3 v + u^3 + u^2 v)\n"
    );
}

#[test]
fn expands_exact_roots() {
    assert_eq!(expand_ok(&["(sqrt2/2)^2"]), "1/2\n");
    assert_eq!(expand_ok(&["3/2*u^2 - sqrt2/2*v"]), "3/2 u^2 - √2/2 v\n");
    assert_eq!(
        expand_ok(&["3/2*u^2 - sqrt2/2*v", "--format", "latex"]),
        "\\frac{3}{2} u^{2} - \\frac{\\sqrt{2}}{2} v\n"
    );
    assert_eq!(
        expand_ok(&["--format=text", "(u, v + 1, u^2 + v^3)"]),
        "(u, v + 1, v^3 + u^2)\n"
    );
    assert_eq!(expand_ok(&["--", "-u + 1"]), "-u + 1\n");
}

#[test]
fn json_output_reads_back() {
    let input = "(1 - v)*(u, 0, u^3) + v*(u, 1, u^2)";
    let out = expand_ok(&[input, "--format", "json"]);
    let value: serde_json::Value = serde_json::from_str(&out).expect("valid JSON");
    assert_eq!(value["expr"], input);
    assert_eq!(value["closed_form"], "(u, v, -u^3 v + u^3 + u^2 v)");
    assert_eq!(
        value["latex"],
        "\\left(u, v, -u^{3} v + u^{3} + u^{2} v\\right)"
    );
    assert_eq!(value["json"], "(u, v, -u^3*v + u^3 + u^2*v)");
    // the json form expands to the same closed form
    let json_form = value["json"].as_str().expect("a string");
    assert_eq!(expand_ok(&[json_form]), "(u, v, -u^3 v + u^3 + u^2 v)\n");
    // fields in the documented order
    let keys: Vec<usize> = ["\"expr\"", "\"closed_form\"", "\"latex\"", "\"json\""]
        .iter()
        .map(|k| out.find(k).expect("key present"))
        .collect();
    assert!(keys.windows(2).all(|w| w[0] < w[1]), "{out}");
}

#[test]
fn bad_input_names_the_column() {
    assert_eq!(
        expand_err("(u + 1"),
        "cagd: at column 7: expected ')' (unbalanced parenthesis), found the end of the input\n"
    );
    assert_eq!(
        expand_err("u + q"),
        "cagd: at column 5: unknown variable 'q' (the variables are u, v, w, t, s, x, y, z; 'uv' means u v); a letter that stands for a number is declared with --parameters\n"
    );
    assert_eq!(expand_err("1/0"), "cagd: at column 2: division by zero\n");
    assert_eq!(
        expand_err("sqrt(-2)"),
        "cagd: at column 1: square root of a negative number (-2) is not real\n"
    );
    assert_eq!(
        expand_err("sqrt2 + sqrt3"),
        "cagd: at column 9: numbers with √2 and √3 cannot be mixed: an expression runs in one field a + b√d\n"
    );
    assert!(expand_err("(u, v)*(u, v)")
        .starts_with("cagd: at column 7: cannot multiply a tuple by a tuple"));
    assert!(expand_err("1/u")
        .starts_with("cagd: at column 2: division by a polynomial is not a polynomial"));
    assert!(expand_err("u^99999").contains("limit exceeded"));
    assert!(expand_err("").contains("expected an expression"));
}

#[test]
fn usage_errors_exit_2() {
    for args in [
        &[][..],
        &["frobnicate"][..],
        &["expand"][..],
        &["expand", "u", "v"][..],
        &["expand", "u", "--format"][..],
        &["expand", "u", "--format", "pdf"][..],
        &["expand", "u", "--colour"][..],
        &["help", "frobnicate"][..],
    ] {
        let out = cagd(args);
        assert_eq!(out.status.code(), Some(2), "args {args:?}");
        assert!(stdout(&out).is_empty());
        assert_eq!(
            stderr(&out).lines().count(),
            1,
            "args {args:?}: {}",
            stderr(&out)
        );
        assert!(stderr(&out).contains("cagd help"));
    }
}

#[test]
fn help_lists_the_commands() {
    for args in [&["--help"][..], &["help"][..], &["-h"][..]] {
        let out = cagd(args);
        assert_eq!(out.status.code(), Some(0));
        let text = stdout(&out);
        assert!(text.contains("Commands:"));
        assert!(text.contains("expand EXPR"));
    }
    for args in [&["help", "expand"][..], &["expand", "--help"][..]] {
        let out = cagd(args);
        assert_eq!(out.status.code(), Some(0));
        assert!(stdout(&out).starts_with("Usage: cagd expand EXPR"));
    }
    // the help's own examples work as printed
    let help = stdout(&cagd(&["expand", "--help"]));
    assert!(help.contains("cagd expand -- \"-u + 1\""), "{help}");
    assert_eq!(expand_ok(&["--", "-u + 1"]), "-u + 1\n");
    assert_eq!(
        expand_ok(&["(1 - v)*(u, 0, u^3) + v*(u, 1, u^2)"]),
        "(u, v, -u^3 v + u^3 + u^2 v)\n"
    );
    let out = cagd(&["--version"]);
    assert!(stdout(&out).starts_with("cagd "));
}

// ---- solve, check, examples -------------------------------------------------------------

fn json(out: &Output) -> serde_json::Value {
    serde_json::from_str(&stdout(out)).unwrap_or_else(|e| panic!("not JSON ({e}): {}", stdout(out)))
}

const COONS: &str = r#"{"op": "coons",
  "c1": {"bezier": [[0, 0, 0], ["1/2", 0, 2], [1, 0, 3], [2, 0, 0]]},
  "c2": {"bezier": [[0, 3, 0], ["1/2", 3, 3], [1, 3, 1], [2, 4, 0]]},
  "d1": {"bezier": [[0, 0, 0], [0, 1, 3], [0, 3, 0]]},
  "d2": {"bezier": [[2, 0, 0], [2, 1, 2], [2, 4, 0]]}}"#;

#[test]
fn solve_answers_a_problem_in_json_with_steps() {
    let out = cagd_stdin(&["solve", "-", "--format", "json", "--steps"], COONS);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let a = json(&out);
    assert_eq!(a["ok"], true);
    assert_eq!(a["op"], "coons");
    assert_eq!(
        a["result"]["surface"]["bezier"][1][1],
        serde_json::json!(["1/2", "5/6", "31/6"])
    );
    let steps: Vec<&str> = a["result"]["steps"]
        .as_array()
        .expect("steps")
        .iter()
        .filter_map(|s| s["name"].as_str())
        .collect();
    assert_eq!(steps, ["c_c", "c_d", "c_cd"]);
}

#[test]
fn an_answer_feeds_back_as_a_problem() {
    let out = cagd_stdin(&["solve", "-", "--format", "json"], COONS);
    let surface = json(&out)["result"]["surface"].clone();
    let again =
        serde_json::json!({"op": "evaluate", "surface": surface, "params": [["1/3", "1/2"]]});
    let out = cagd_stdin(&["solve", "-", "--format", "json"], again.to_string());
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert_eq!(
        json(&out)["result"]["points"].as_array().map(Vec::len),
        Some(1)
    );
}

#[test]
fn a_batch_with_broken_problems_still_answers_the_others() {
    let batch = r#"[
      {"op": "closed_form", "surface": {"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]}},
      {"op": "restrict", "surface": {"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]}, "u": [0, 1]},
      {"op": "frobnicate"},
      {"op": "elevate", "surface": {"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]}, "by": "two"},
      {"op": "elevate", "surface": {"bezier": [[[0, 0, 0], [0, 1]], [[1, 0, 0], [1, 1, 1]]]}, "by": [1, 0]},
      {"op": "evaluate", "surface": {"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]}, "params": [[0.5, 0]]},
      {"op": "closed_form", "curve": {"bezier": [[0, 0], [1, 1]], "weights": [0, 0]}},
      {"op": "graph", "f": "x*y", "degree": [1, 1]}
    ]"#;
    let out = cagd_stdin(&["solve", "-", "--format", "json"], batch);
    assert_eq!(out.status.code(), Some(1), "some failed, so exit code 1");
    let answers = json(&out);
    let answers = answers.as_array().expect("one answer per problem");
    assert_eq!(answers.len(), 8);
    assert_eq!(answers[0]["ok"], true);
    assert_eq!(answers[7]["ok"], true);
    let err = |i: usize| answers[i]["error"].as_str().unwrap_or_default().to_string();
    assert_eq!(
        err(1),
        "problem 2: field `v`: missing (this operation needs it)"
    );
    assert!(err(2).starts_with(
        "problem 3: field `op`: unknown operation \"frobnicate\"; the operations are: `evaluate`"
    ));
    assert_eq!(
        err(3),
        "problem 4: field `by`: expected an integer r or a list [r, s], found the string \"two\""
    );
    assert_eq!(
        err(4),
        "problem 5: field `surface.bezier[0][1]`: this point has 2 coordinates but the first has 3"
    );
    assert!(
        err(5).starts_with("problem 6: field `params[0][0]`: the number 0.5 has a fraction part"),
        "{}",
        err(5)
    );
    assert!(
        err(6).starts_with("problem 7: field `curve`: ") && err(6).contains("weight"),
        "{}",
        err(6)
    );
    for i in 1..7 {
        assert_eq!(answers[i]["ok"], false);
        assert_eq!(err(i).lines().count(), 1);
    }
}

#[test]
fn malformed_json_is_one_line_naming_where() {
    let out = cagd_stdin(&["solve", "-"], "{\"op\": \"closed_form\", ");
    assert_eq!(out.status.code(), Some(1));
    let e = stderr(&out);
    assert_eq!(e.lines().count(), 1, "{e}");
    assert!(
        e.starts_with("cagd: standard input: not valid JSON at line 1, column"),
        "{e}"
    );
}

#[test]
fn text_answer_keys_in_english_and_spanish() {
    let out = cagd_stdin(&["solve", "-", "--steps"], COONS);
    let text = stdout(&out);
    assert!(text.contains("c_cd = "), "{text}");
    assert!(text.contains("(1/2, 5/6, 31/6)"), "{text}");
    let out = cagd_stdin(&["solve", "-", "--lang", "es"], COONS);
    assert!(
        stdout(&out).contains("malla de control"),
        "{}",
        stdout(&out)
    );
}

#[test]
fn examples_check_every_fixture_and_say_so() {
    let out = cagd(&["examples"]);
    let text = stdout(&out);
    let last = text.lines().last().unwrap_or_default();
    assert!(
        last.contains("examples:") && last.ends_with(" 0 failed"),
        "{last}"
    );
    // the examples beyond the notes (fixtures/beyond, fixtures/triangle) are counted apart
    let beyond = |dir: &str| {
        std::fs::read_dir(format!(
            "{}/../../fixtures/{dir}",
            env!("CARGO_MANIFEST_DIR")
        ))
        .map(|d| d.count())
        .unwrap_or(0)
    };
    let n = beyond("beyond") + beyond("triangle");
    assert!(n > 0);
    assert!(
        last.contains(&format!("{n} beyond the notes match the expected answer")),
        "{last}"
    );
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(text.contains(
        "erratum (c_1,2^{1,0}): the notes print (0, 4/3, 11/3), the exact value is (2, 4/3, 11/3)"
    ));
    let out = cagd(&["examples", "ch6-coons-bezier", "--format", "json"]);
    let arr = json(&out);
    let e = &arr[0];
    for key in ["name", "source", "op", "result", "matches_notes", "errata"] {
        assert!(e.get(key).is_some(), "missing {key}");
    }
    assert_eq!(e["matches_notes"], true);
    assert_eq!(e["source"], "000_4f266b7df5f64f70.txt §5");
}

#[test]
fn examples_list_and_unknown_names() {
    let out = cagd(&["examples", "--list"]);
    assert!(stdout(&out).lines().count() >= 20);
    let out = cagd(&["examples", "no-such-example"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn check_reports_a_wrong_expected_answer() {
    let dir = std::env::temp_dir().join(format!("cagd-check-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let file = dir.join("mine.json");
    std::fs::write(
        &file,
        r#"[{"op": "graph", "f": "x*y", "degree": [1, 1], "expected": {"closed_form": "(u, v, u v)"}},
            {"op": "graph", "f": "x*y", "degree": [1, 1], "expected": {"closed_form": "(u, v, 2 u v)"}}]"#,
    )
    .expect("write");
    let out = cagd(&["check", file.to_str().unwrap_or_default()]);
    assert_eq!(out.status.code(), Some(1));
    let text = stdout(&out);
    // every entry marked, and no mistake guessed: the closed form's z is the one wrong
    for line in [
        "verdict: wrong answer: 2 of 3 entries right",
        "the function z: key u v; answer 2 u v",
        "no known mistake explains these entries",
    ] {
        assert!(text.contains(line), "{line}\n{text}");
    }
    assert!(
        text.ends_with("2 problems checked: 1 correct, 1 wrong\n"),
        "{text}"
    );
}

#[test]
fn generate_is_deterministic_and_solvable() {
    let a = cagd(&[
        "generate", "--topic", "coons", "--count", "3", "--seed", "7",
    ]);
    let b = cagd(&[
        "generate", "--topic", "coons", "--count", "3", "--seed", "7",
    ]);
    assert_eq!(a.status.code(), Some(0), "{}", stderr(&a));
    assert_eq!(a.stdout, b.stdout, "same seed, same bytes");
    let c = cagd(&[
        "generate", "--topic", "coons", "--count", "3", "--seed", "8",
    ]);
    assert_ne!(a.stdout, c.stdout);
    let solved = cagd_stdin(&["solve", "-", "--format", "json"], stdout(&a));
    assert_eq!(solved.status.code(), Some(0), "{}", stderr(&solved));
    assert_eq!(json(&solved).as_array().map(Vec::len), Some(3));
    let dir = std::env::temp_dir().join(format!("cagd-generate-{}", std::process::id()));
    let out = cagd(&[
        "generate",
        "--topic",
        "restrict",
        "--count",
        "2",
        "--out",
        dir.to_str().unwrap_or_default(),
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    for f in [
        "problems.json",
        "statements.tex",
        "key.txt",
        "key.md",
        "key.tex",
        "key.json",
        "fig/restrict-1-data.png",
        "fig/restrict-1-answer.png",
    ] {
        assert!(dir.join(f).exists(), "{f} written");
    }
    // the statement sheet: numbered problems, each a question, their figures, no answer
    let sheet = std::fs::read_to_string(dir.join("statements.tex")).unwrap();
    assert!(
        sheet.contains("\\section*{Problem 1}\nFind the control mesh of the surface restricted"),
        "{sheet}"
    );
    assert!(sheet.contains("\\includegraphics[width=0.45\\textwidth,height=0.4\\textheight,keepaspectratio]{fig/restrict-2-data.png}"));
    assert!(!sheet.contains("answer.png"));
    let key = std::fs::read_to_string(dir.join("key.tex")).unwrap();
    assert!(key.contains("{fig/restrict-2-answer.png}"));
    // a PDF of each when pdflatex is there
    let pdflatex = std::process::Command::new("pdflatex")
        .arg("--version")
        .output()
        .is_ok();
    assert_eq!(dir.join("statements.pdf").exists(), pdflatex);
    assert_eq!(dir.join("key.pdf").exists(), pdflatex);
    let _ = std::fs::remove_dir_all(&dir);
    assert_eq!(
        cagd(&["generate", "--topic", "nope"]).status.code(),
        Some(1)
    );
}

#[test]
fn render_writes_every_figure_format_deterministically() {
    let dir = std::env::temp_dir().join(format!("cagd-render-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let p = |f: &str| dir.join(f).to_string_lossy().into_owned();
    let fixture = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../fixtures/ch6/10-sphere-octant.json"
    );
    let args = [
        "render",
        fixture,
        "--svg",
        &p("a.svg"),
        "--html",
        &p("a.html"),
        "--obj",
        &p("a.obj"),
        "--stl",
        &p("a.stl"),
        "--iges",
        &p("a.igs"),
    ];
    let out = cagd(&args);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let svg = std::fs::read_to_string(p("a.svg")).expect("svg written");
    assert!(
        svg.starts_with("<svg") || svg.starts_with("<?xml"),
        "an SVG document"
    );
    let html = std::fs::read_to_string(p("a.html")).expect("html written");
    assert!(html.contains("<canvas") && !html.contains("http://") && !html.contains("https://"));
    assert!(html.contains("√2/2"), "exact weights shown on hover");
    let obj = std::fs::read_to_string(p("a.obj")).expect("obj written");
    assert!(
        obj.lines().any(|l| l.starts_with("vn ")),
        "normals in the OBJ"
    );
    let iges = std::fs::read_to_string(p("a.igs")).expect("iges written");
    assert!(
        iges.lines().all(|l| l.len() == 80),
        "IGES lines are 80 columns"
    );
    assert!(std::fs::metadata(p("a.stl")).map(|m| m.len()).unwrap_or(0) > 84);
    // the same input gives the same bytes
    let again = cagd(&["render", fixture, "--svg", &p("b.svg")]);
    assert_eq!(again.status.code(), Some(0));
    assert_eq!(
        std::fs::read(p("a.svg")).ok(),
        std::fs::read(p("b.svg")).ok()
    );
    let none = cagd(&["render", fixture]);
    assert_eq!(none.status.code(), Some(2), "an output is required");
}

#[test]
fn examples_with_figures_link_them_in_the_keys() {
    let dir = std::env::temp_dir().join(format!("cagd-figures-{}", std::process::id()));
    let d = dir.to_string_lossy().into_owned();
    let out = cagd(&[
        "examples",
        "ch6-coons-bezier",
        "--format",
        "markdown",
        "--figures",
        &d,
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(stdout(&out).contains(&format!(
        "![Bézier Coons patch of bidegree (3, 2) from two cubics and two parabolas]({d}/ch6-coons-bezier.svg)"
    )));
    assert!(dir.join("ch6-coons-bezier.svg").exists());
    let out = cagd(&[
        "examples",
        "ch6-sphere-octant",
        "--format",
        "latex",
        "--figures",
        &d,
    ]);
    assert!(stdout(&out).contains("\\includegraphics"));
    let png = std::fs::read(dir.join("ch6-sphere-octant.png")).expect("png written");
    assert_eq!(&png[..4], b"\x89PNG");
}

/// With `--lang es` the errors of the command line are in Spanish too, and `cagd check`'s
/// summary has its plurals.
#[test]
fn errors_in_spanish() {
    let out = cagd(&["examples", "nope", "--lang", "es"]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        stderr(&out),
        "cagd: ningún ejemplo se llama nope (vea cagd examples --list) (`cagd help` da la lista de órdenes)\n"
    );
    let out = cagd(&["solve", "/no/such/file.json", "--lang", "es"]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(
        stderr(&out),
        "cagd: no se puede leer /no/such/file.json: el archivo no existe\n"
    );
    let out = cagd_stdin(&["solve", "-", "--lang", "es"], "{\"op\":");
    assert!(stderr(&out).starts_with("cagd: entrada estándar: JSON no válido en la línea"));
    let batch = r#"[{"op": "circle"}, {"op": "circle"}, {"op": "circle"}]"#;
    let out = cagd_stdin(&["solve", "-", "--lang", "es", "--max-batch", "2"], batch);
    assert!(stdout(&out).contains(
        "== Problema 3\nerror: problema 3: sin resolver: el lote tiene 3 problemas, más que el límite de 2 (súbalo con --max-batch)\n"
    ), "{}", stdout(&out));
    let dir = std::env::temp_dir().join(format!("cagd-check-es-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("one.json");
    std::fs::write(
        &file,
        r#"{"op": "circle", "expected": {"curve": {"bezier": [[1, 0]]}}}"#,
    )
    .unwrap();
    let out = cagd(&["check", file.to_str().unwrap(), "--lang", "es"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        stdout(&out).contains(", problema 1\n== Problema (circunferencia)\n"),
        "{}",
        stdout(&out)
    );
    assert!(
        stdout(&out).ends_with("1 problema comprobado: 0 correctos, 1 incorrecto\n"),
        "{}",
        stdout(&out)
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// `cagd examples` takes `--steps`, as `cagd solve` does.
#[test]
fn examples_take_steps() {
    let out = cagd(&["examples", "ch6-coons-bezier", "--steps", "--lang", "es"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(
        stdout(&out).contains("pasos:\n  c_c = "),
        "{}",
        stdout(&out)
    );
    assert!(stdout(&out).ends_with("1 ejemplo: 1 coincide con los apuntes, 0 con erratas en los apuntes (se da el valor exacto), 0 fallan\n"));
}

/// Every worked example gets its figure, the circle included (a curve with no surface), the
/// examples in letters (radius R: drawn with R = 1; a, b, c, d = 1, 2, 3, 4) and the profile
/// in functions f(u), g(u).
#[test]
fn every_example_has_a_figure() {
    let dir = std::env::temp_dir().join(format!("cagd-all-figures-{}", std::process::id()));
    let d = dir.to_string_lossy().into_owned();
    let out = cagd(&["examples", "--format", "markdown", "--figures", &d]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let names = stdout(&cagd(&["examples", "--list"]));
    let names: Vec<&str> = names
        .lines()
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    assert!(names.len() >= 22, "{names:?}");
    // the formula fixtures are drawn with sample values, a mesh of generic points c_{i,j} as
    // the graph of the scalar patch, a profile (f(u), 0, g(u)) in functions of u with the
    // sample profile f(u) = 1 + u², g(u) = 2u
    for name in names {
        assert!(
            dir.join(format!("{name}.svg")).exists(),
            "no figure for {name}"
        );
        // the figure's alternative text is the example's title, never its name
        assert!(stdout(&out).contains(&format!("]({d}/{name}.svg)")));
        assert!(!stdout(&out).contains(&format!("![{name}]")));
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn render_plots_the_quantity_that_teaches_something() {
    let dir = std::env::temp_dir().join(format!("cagd-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let out_file = dir.join("dev.svg").to_string_lossy().into_owned();
    let fixture = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../fixtures/ch6/05-non-developable.json"
    );
    let out = cagd(&["render", fixture, "--plot", &out_file]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let svg = std::fs::read_to_string(&out_file).expect("plot written");
    assert!(
        svg.contains("-8 u^3 - 4 u^2 + 12 u"),
        "the polynomial is named"
    );
    let octant = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../fixtures/ch6/10-sphere-octant.json"
    );
    let out = cagd(&["render", octant, "--plot", &out_file]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(std::fs::read_to_string(&out_file)
        .unwrap_or_default()
        .contains("weights"));
}

#[test]
fn every_operation_of_the_format_doc_runs_through_the_binary() {
    let problems = format_doc_problems();
    let batch = serde_json::Value::Array(problems.clone()).to_string();
    let out = cagd_stdin(&["solve", "-", "--format", "json"], &batch);
    assert_eq!(out.status.code(), Some(0), "{}", stdout(&out));
    let answers = json(&out);
    let answers = answers.as_array().expect("one answer per problem");
    assert_eq!(answers.len(), problems.len());
    let mut ops: Vec<&str> = answers.iter().filter_map(|a| a["op"].as_str()).collect();
    ops.sort_unstable();
    ops.dedup();
    assert!(ops.len() >= 17, "every operation answered: {ops:?}");
    assert!(answers.iter().all(|a| a["ok"] == true));
}

/// `cagd solve` on a problem whose `expected` is wrong compares, reports the mismatch and
/// exits 1, as `cagd check` does; with the right `expected` it says so and exits 0. (It used
/// to print "verdict: matches the notes" without comparing.)
#[test]
fn solve_checks_what_a_problem_expects() {
    let wrong = r#"{"op": "elevate", "curve": {"bezier": [[0, 0], [1, 2], [3, 3]]}, "by": 1,
      "expected": {"curve": {"bezier": [[0, 0], [1, 1], [2, 3], [3, 3]]}}}"#;
    let out = cagd_stdin(&["solve", "-"], wrong);
    assert_eq!(out.status.code(), Some(1), "{}", stdout(&out));
    assert!(
        stdout(&out)
            .contains("verdict: failed: `curve`: point 1: expected (1, 1), computed (2/3, 4/3)"),
        "{}",
        stdout(&out)
    );
    let json = cagd_stdin(&["solve", "-", "--format", "json"], wrong);
    assert_eq!(json.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    assert_eq!(v["passed"], false);
    assert_eq!(
        v["mismatches"][0],
        "`curve`: point 1: expected (1, 1), computed (2/3, 4/3)"
    );
    let right = wrong.replace("[1, 1], [2, 3]", r#"["2/3", "4/3"], ["5/3", "7/3"]"#);
    let out = cagd_stdin(&["solve", "-"], &right);
    assert_eq!(out.status.code(), Some(0), "{}", stdout(&out));
    assert!(stdout(&out).contains("verdict: matches the expected answer"));
    // without `expected` there is no verdict to print
    let plain = r#"{"op": "elevate", "curve": {"bezier": [[0, 0], [1, 2], [3, 3]]}, "by": 1}"#;
    let out = cagd_stdin(&["solve", "-"], plain);
    assert_eq!(out.status.code(), Some(0));
    assert!(!stdout(&out).contains("verdict"), "{}", stdout(&out));
}

/// A misspelled key is refused with the nearest valid one, and the rest of the batch is
/// answered; the steps are in the key only with --steps.
#[test]
fn solve_refuses_unknown_keys_and_computes_steps_only_when_asked() {
    let batch = r#"[{"op": "coons", "blned": "cubic",
        "c1": {"bezier": [[0, 0, 0], [1, 0, 1]]}, "c2": {"bezier": [[0, 1, 0], [1, 1, 1]]},
        "d1": {"bezier": [[0, 0, 0], [0, 1, 0]]}, "d2": {"bezier": [[1, 0, 1], [1, 1, 1]]}},
      {"op": "restrict", "surface": {"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]},
        "u": ["1/2", 1], "v": [0, 1]}]"#;
    let out = cagd_stdin(&["solve", "-", "--format", "json"], batch);
    assert_eq!(out.status.code(), Some(1));
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(
        v[0]["error"],
        "problem 1: field `blned`: unknown key: did you mean `blend`? `coons` takes `c1`, `c2`, `d1`, `d2`, `blend`"
    );
    assert_eq!(v[1]["ok"], true);
    assert!(v[1]["result"].get("steps").is_none());
    let with = cagd_stdin(&["solve", "-", "--format", "json", "--steps"], batch);
    let w: serde_json::Value = serde_json::from_slice(&with.stdout).unwrap();
    assert_eq!(w[1]["result"]["steps"][0]["name"], "c_hat");
    assert_eq!(w[1]["result"]["surface"], v[1]["result"]["surface"]);
}

/// `cagd ARGS > FILE`, with standard output opened on `file`.
fn cagd_to(args: &[&str], file: std::fs::File) -> Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(args)
        .stdout(file)
        .stderr(std::process::Stdio::piped())
        .output()
        .expect("the cagd binary runs")
}

#[test]
fn a_failed_write_is_an_error_and_a_closed_pipe_is_quiet() {
    let circle = std::env::temp_dir().join(format!("cagd-write-{}.json", std::process::id()));
    std::fs::write(&circle, r#"{"op": "circle", "arcs": 4}"#).unwrap();
    let circle = circle.to_str().unwrap();
    if let Ok(full) = std::fs::OpenOptions::new().write(true).open("/dev/full") {
        for args in [
            &["solve", circle][..],
            &["solve", circle, "--format", "json"],
            &["examples"],
            &["check", circle],
            &["expand", "u + v"],
            &[
                "generate", "--topic", "coons", "--count", "2", "--seed", "1",
            ],
        ] {
            let out = cagd_to(args, full.try_clone().unwrap());
            assert_eq!(out.status.code(), Some(1), "{args:?}");
            let err = stderr(&out);
            assert!(
                err.starts_with("cagd: cannot write the output: "),
                "{args:?}: {err}"
            );
        }
    }
    // a reader that stops at once: no message
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(["examples", "--format", "latex"])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    assert_eq!(stderr(&out), "");
    std::fs::remove_file(circle).ok();
}

/// Drawing evaluates exactly point by point: a figure too slow for the deadline is refused
/// with the flags that change it.
#[test]
fn render_stops_at_its_deadline() {
    let mesh: Vec<Vec<serde_json::Value>> = (0..20)
        .map(|i| {
            (0..50)
                .map(|j| serde_json::json!([i, j, format!("{}/{}", (i * j) % 17, 1 + (i + j) % 7)]))
                .collect()
        })
        .collect();
    // a bare surface: nothing to solve, only the drawing runs under the deadline
    let problem = serde_json::json!({"bezier": mesh});
    let dir = std::env::temp_dir().join(format!("cagd-render-deadline-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let obj = dir.join("p.obj");
    let out = cagd_stdin(
        &[
            "render",
            "-",
            "--obj",
            obj.to_str().unwrap(),
            "--density",
            "128",
            "--max-seconds",
            "0.3",
        ],
        problem.to_string(),
    );
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert!(
        err.contains("not drawn within the limit of 0.3 s: the work was stopped (raise it with --max-seconds, or lower --density)"),
        "{err}"
    );
    assert!(!obj.exists());
    std::fs::remove_dir_all(dir).ok();
}

#[test]
fn letters_through_the_binary() {
    // the circle of radius R, as the slides print it, and specialized to R = 2
    let out = cagd_stdin(
        &["solve", "-", "--format", "json"],
        r#"[{"op": "circle", "radius": "R", "arcs": 4, "parameters": ["R"]},
            {"op": "circle", "radius": "R", "arcs": 4, "parameters": ["R"], "values": {"R": 2}},
            {"op": "circle", "radius": "2 r", "arcs": 4, "parameters": ["R"]}]"#,
    );
    let answers: serde_json::Value = serde_json::from_str(&stdout(&out)).unwrap();
    let points = |k: usize| answers[k]["result"]["curve"]["bspline"][1].clone();
    assert_eq!(points(0), serde_json::json!(["R", "R", "0"]));
    assert_eq!(points(1), serde_json::json!(["2", "2", "0"]));
    let error = answers[2]["error"].as_str().unwrap();
    assert!(
        error.contains("'r', which is not a declared parameter"),
        "{error}"
    );
    // expand with declared letters
    let out = cagd(&["expand", "--parameters", "a", "(u + a)^2"]);
    assert_eq!(stdout(&out), "u^2 + 2 a u + a^2\n");
    let out = cagd(&["expand", "--parameters", "u", "u + 1"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains("not one of the variables"));
}

/// The key of all the notes' examples goes to students as it is: a real title, the notation
/// legend once, no file name of the notes and no example's name, chapter 5 before the examples
/// beyond the notes, in every format.
#[test]
fn the_key_of_the_examples_is_for_students() {
    let names = stdout(&cagd(&["examples", "--list"]));
    let names: Vec<&str> = names
        .lines()
        .filter_map(|l| l.split_whitespace().next())
        .collect();
    for format in ["text", "latex", "markdown"] {
        let out = cagd(&["examples", "--format", format, "--lang", "es"]);
        assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
        let key = stdout(&out);
        assert!(key.contains("Soluciones de los ejemplos de los apuntes (temas 5 y 6)"));
        assert_eq!(key.matches("Notación").count(), 1, "{format}");
        assert!(!key.contains(".txt"), "{format}");
        for name in &names {
            assert!(!key.contains(name), "{name} in the {format} key");
        }
        let chapter5 = key.find("Tema 5, §2").unwrap();
        let chapter6 = key.find("Tema 6, §2").unwrap();
        let beyond = key.find("Fuera de los apuntes").unwrap();
        assert!(chapter5 < chapter6 && chapter6 < beyond, "{format}");
    }
}

/// `cagd serve`: its help, and a bad address refused as a usage error before anything is
/// served.
#[test]
fn serve_says_its_usage_and_refuses_a_bad_address() {
    let out = cagd(&["serve", "--help"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(
        stdout(&out).starts_with("Usage: cagd serve [FILE]"),
        "{}",
        stdout(&out)
    );
    let out = cagd(&["serve", "--bind", "nowhere"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        stderr(&out).contains("'nowhere' is not an IP address"),
        "{}",
        stderr(&out)
    );
    let help = stdout(&cagd(&["--help"]));
    assert!(help.contains("cagd serve [FILE]"), "{help}");
}
