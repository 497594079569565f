//! The cases of issue 32: each compiled the way a teacher would, each failing on the escaping
//! the keys had before (a file written, a file read, or no PDF at all).

use super::*;

const OPENOUT: &str = "x_( \\immediate\\openout7=pwned.tex \\immediate\\closeout7 )";
const INPUT: &str = "see x_( \\input /etc/hostname )";

/// A title that opened a file for writing through `\immediate\openout` (`pwned.tex` was
/// written), in every text field, the key and the statement sheet, in both languages: the
/// document compiles, writes nothing but its own files, and shows the words.
#[test]
#[ignore = "runs pdflatex: .ci/latex-check runs it with --ignored"]
fn openout_in_a_title_writes_nothing() {
    let problem = evaluate_with("title", json!(OPENOUT));
    let v = check(&problem);
    // the key shows the title; the statement sheet asks its question (no title), under the
    // header's title, which is the attack here
    for (i, c) in both_languages("openout", std::slice::from_ref(&v), OPENOUT)
        .iter()
        .enumerate()
    {
        c.harmless();
        assert!(!c.dir.join("pwned.tex").exists());
        assert!(c.text.contains("openout7=pwned.tex"), "{i}: {}", c.text);
    }
}

/// A note that read `/etc/hostname` through `\input` (and printed the machine's name): the
/// note is shown as written, and nothing outside TeX's own files is read.
#[test]
#[ignore = "runs pdflatex: .ci/latex-check runs it with --ignored"]
fn input_in_a_note_reads_nothing() {
    let mut problem = evaluate_with("note", json!(INPUT));
    problem["es"] = json!({"note": INPUT, "title": OPENOUT});
    let v = check(&problem);
    // the key shows the note; the statement sheet (its question, no note) is harmless
    for (i, c) in both_languages("input", std::slice::from_ref(&v), "q.json")
        .iter()
        .enumerate()
    {
        c.harmless();
        assert!(
            i % 2 == 1 || c.text.contains("input /etc/hostname"),
            "{}",
            c.text
        );
    }
}

/// Every text field with both attacks (name, title, note, their Spanish, every errata field
/// and its Spanish, an `expected` key echoed in the verdict) and the input file's name as the
/// document's title.
#[test]
#[ignore = "runs pdflatex: .ci/latex-check runs it with --ignored"]
fn every_text_field_and_the_file_name_are_text() {
    let words = format!("{OPENOUT} {INPUT} $x$ %c #1 &~ {{ }}}} ^^5cinput");
    let erratum = json!({"where": words, "printed": words, "exact": words, "why": words});
    let mut problem = evaluate();
    problem["name"] = json!(words);
    problem["title"] = json!(words);
    problem["note"] = json!(words);
    problem["es"] = json!({"title": words, "note": words});
    let mut es = erratum.clone();
    es["es"] = erratum.clone();
    problem["errata"] = json!([es]);
    let mut expected_key = evaluate();
    expected_key["expected"] = json!({ words.clone(): 1 });
    let verdicts = [check(&problem), check(&expected_key)];
    for c in both_languages("fields", &verdicts, &format!("{OPENOUT}.json")) {
        c.harmless();
    }
}

/// A title with TeX's `^^` notation lost the whole PDF ("Double superscript"); `^^5c` is a
/// backslash to TeX.
#[test]
#[ignore = "runs pdflatex: .ci/latex-check runs it with --ignored"]
fn a_double_superscript_compiles() {
    let verdicts: Vec<Verdict> = [
        "x^^2",
        "x^^5cinput /etc/hostname",
        "x_1_2^3^4'^5''",
        "^^",
        "x^2'",
    ]
    .iter()
    .map(|t| {
        let mut p = evaluate_with("title", json!(t));
        p["note"] = json!(t);
        check(&p)
    })
    .collect();
    for c in both_languages("carets", &verdicts, "x^^2.json") {
        c.harmless();
    }
}

/// Error messages that echo a string lost the PDF: an unknown `op` or `blend`, a `values` key,
/// a bad number or expression, an `expected` value.
#[test]
#[ignore = "runs pdflatex: .ci/latex-check runs it with --ignored"]
fn errors_that_echo_a_string_compile() {
    let bad = "x^^2 \\input{/etc/hostname} $#%&~_{";
    let mut coons: Value = serde_json::from_str(include_str!(
        "../../../../fixtures/ch6/06-coons-parametric.json"
    ))
    .expect("the fixture");
    coons["blend"] = json!(bad);
    let mut values = evaluate();
    values["curve"] = json!({"bezier": [[0, 0], [1, "k"]]});
    values["parameters"] = json!(["k"]);
    values["values"] = json!({ bad: 1 });
    let mut expected = evaluate();
    expected["expected"] = json!({"points": [[bad, 1]]});
    let problems = [
        json!({"op": bad}),
        coons,
        values,
        evaluate_with("params", json!([bad])),
        json!({"op": "evaluate", "curve": {"expr": format!("(u^^2 {bad}, u)")}, "params": ["1/2"]}),
        expected,
    ];
    let verdicts: Vec<Verdict> = problems.iter().map(check).collect();
    for v in &verdicts {
        assert!(!v.passed(), "{v:?}");
    }
    for (i, c) in both_languages("errors", &verdicts, "errors.json")
        .iter()
        .enumerate()
    {
        c.harmless();
        // the keys (not the statement sheets, which have no answers) show the errors
        if i % 2 == 0 {
            assert!(c.text.contains("input{/etc/hostname}"), "{}", c.text);
        }
    }
}

/// Greek letters that `parameters` accepts (β, γ, φ) were not set up by the preamble; a
/// letter of another alphabet neither. With the worked solution.
#[test]
#[ignore = "runs pdflatex: .ci/latex-check runs it with --ignored"]
fn greek_and_other_parameters_compile() {
    let problems = [
        json!({"op": "evaluate", "curve": {"bezier": [["β", 0], ["γ", "φ"], [1, "β"]]},
               "params": ["1/2"], "parameters": ["β", "γ", "φ"]}),
        json!({"op": "closed_form", "curve": {"bezier": [["ж", 0], ["中", 1], [1, "Ω"]]},
               "parameters": ["ж", "中", "Ω"]}),
    ];
    let verdicts: Vec<Verdict> = problems.iter().map(with_steps).collect();
    for v in &verdicts {
        assert!(v.answer.is_ok(), "{v:?}");
    }
    for c in both_languages("greek", &verdicts, "greek.json") {
        c.harmless();
    }
}

/// Cyrillic, Chinese, emoji and control characters in every field: the key compiles, the
/// characters the preamble cannot set shown by their code.
#[test]
#[ignore = "runs pdflatex: .ci/latex-check runs it with --ignored"]
fn other_scripts_emoji_and_control_characters_compile() {
    let words = "Жук 中文 😀 \u{1b}[2J \u{7}\u{0}\u{8}\u{9b} é ñ ß Ħ \r\n\n\t c_ж";
    let mut problem = evaluate();
    for k in ["name", "title", "note"] {
        problem[k] = json!(words);
    }
    problem["es"] = json!({"title": words, "note": words});
    problem["errata"] = json!([{"where": words, "printed": words, "exact": words, "why": words}]);
    let verdicts = [check(&problem), check(&json!({"op": words}))];
    for c in both_languages("scripts", &verdicts, words) {
        c.harmless();
        assert!(c.text.contains("U+0416"), "{}", c.text);
        assert!(c.text.contains("U+001B"), "{}", c.text);
    }
}

/// A figure in a folder whose name has TeX's special characters (`examples --figures "set
/// #3"` gave a key that did not compile): `tex::graphics` includes it.
#[test]
#[ignore = "runs pdflatex: .ci/latex-check runs it with --ignored"]
fn a_figure_in_a_folder_of_any_name_is_included() {
    let dir = temp_dir("figure");
    let folder = "fig set #3 %&{x}~^^5c$ _ é";
    std::fs::create_dir_all(dir.join(folder)).expect("the folder");
    std::fs::write(dir.join(folder).join("a b.png"), PNG).expect("the figure");
    let v = check(&evaluate());
    let section = example_latex(&v, Lang::En) + &figure_line(&format!("{folder}/a b.png"));
    let c = compile_in(&dir, &latex_document("figures", &[section], Lang::En));
    c.harmless();
    assert!(
        c.inputs.iter().any(|i| i.ends_with("a b.png")),
        "the figure was not read: {:?}",
        c.inputs
    );
    // a path that TeX's file lookup would rewrite ($HOME) is shown, not opened
    let section = example_latex(&v, Lang::En) + &figure_line("fig$HOME/a.png");
    let c = compile("kpathsea", &latex_document("figures", &[section], Lang::En));
    c.harmless();
    assert!(c.text.contains("fig$HOME/a.png"), "{}", c.text);
}
