//! Random Unicode and TeX-special text in every text field of a problem: the key and the
//! statement sheet compile in both languages and do no harm. Few cases, each batching many
//! random strings into one document (pdflatex is slow).

use super::*;

/// Pieces of text that TeX reads specially, the attacks, and characters of every kind.
const PIECES: &[&str] = &[
    "\\",
    "{",
    "}",
    "$",
    "%",
    "#",
    "&",
    "~",
    "^",
    "^^",
    "_",
    "x_(",
    "(",
    ")",
    "`",
    "'",
    "''",
    " ",
    "\n\n",
    "\t",
    "\\input /etc/hostname",
    "\\immediate\\openout7=pwned.tex",
    "\\def\\x{",
    "\\catcode`\\^^M=13",
    "c_{1,1}",
    "Δ^{1,0}",
    "√2/2",
    "c~",
    "²",
    "ᵗ",
    "₁",
    "⁻¹",
    "β",
    "ж",
    "中",
    "😀",
    "\u{1b}",
    "\u{0}",
    "\u{7f}",
    "\u{9b}",
    "é",
    "Ħ",
    "·",
    "×",
    "-",
    "--",
    "[",
    "]",
    "\\\\",
    "!`",
    "?`",
    "<<",
    "\u{302}",
    "\u{303}",
    "x",
    "1",
];

/// A random string of those pieces and of any characters.
fn words() -> impl Strategy<Value = String> {
    prop::collection::vec(
        prop_oneof![
            3 => prop::sample::select(PIECES).prop_map(str::to_string),
            2 => any::<char>().prop_map(String::from),
            1 => prop::char::range('\u{0}', '\u{7f}').prop_map(String::from),
        ],
        0..16,
    )
    .prop_map(|v| v.concat())
}

/// A problem with `w` in each of its text fields (fourteen strings), and an `expected` key.
fn problem(w: &[String]) -> Value {
    let at = |i: usize| w.get(i).cloned().unwrap_or_default();
    let mut p = evaluate();
    p["name"] = json!(at(0));
    p["title"] = json!(at(1));
    p["note"] = json!(at(2));
    p["es"] = json!({"title": at(3), "note": at(4)});
    p["errata"] = json!([{
        "where": at(5), "printed": at(6), "exact": at(7), "why": at(8),
        "es": {"where": at(9), "printed": at(10), "exact": at(11), "why": at(12)}
    }]);
    p["expected"] = json!({ at(13): at(1) });
    p
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 4, ..ProptestConfig::default() })]

    #[test]
    #[ignore = "runs pdflatex: .ci/latex-check runs it with --ignored"]
    fn random_text_in_every_field_compiles(
        strings in prop::collection::vec(words(), 14 * 6),
        title in words(),
    ) {
        let verdicts: Vec<Verdict> = strings.chunks(14).map(|w| check(&problem(w))).collect();
        for c in both_languages("random", &verdicts, &title) {
            c.harmless();
        }
    }
}
