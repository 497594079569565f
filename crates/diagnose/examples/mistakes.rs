//! Writes the catalogue of common mistakes as documentation, from the catalogue itself (one
//! source of truth): `docs/mistakes.md` in English and `docs/errores-frecuentes.md` in the
//! notes' Spanish. Per operation family, a table: each mistake's identifier, what the student
//! did, the formula used instead, the notes' formula and the section it violates.
//!
//! ```sh
//! cargo run -p cagd-diagnose --example mistakes
//! ```
//!
//! The test `tests/catalogue.rs` fails when the files differ from what this writes.

use cagd_problem::diagnosis::Family;
use cagd_problem::{Catalogued, Mistake};
use cagd_words::{Lang, Message};
use std::path::{Path, PathBuf};

/// The documents this writes: the file under `docs/` and its language.
pub const DOCUMENTS: [(&str, Lang); 2] = [
    ("mistakes.md", Lang::En),
    ("errores-frecuentes.md", Lang::Es),
];

/// The repository's `docs/` folder.
pub fn docs() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../docs")
}

/// The operations of a family, as the problem format names them.
fn operations(f: Family) -> &'static [&'static str] {
    match f {
        Family::Evaluate => &["evaluate"],
        Family::Elevate => &["elevate"],
        Family::Subdivide => &["restrict", "subdivide"],
        Family::InsertKnot => &["insert_knot"],
        Family::Derivative => &["derivative"],
        Family::Normal => &["normal"],
        Family::Continuity => &["continuity", "curve_continuity"],
        Family::Ruled => &["ruled"],
        Family::Translational => &["translational"],
        Family::Coons => &["coons"],
        Family::Revolution => &["revolution"],
        Family::Circle => &["circle"],
        Family::Interpolate => &["interpolate"],
    }
}

/// Text in a cell of a Markdown table: its marks escaped (`|` too, which would end the cell).
fn cell(s: &str) -> String {
    cagd_keys::escape_markdown(s)
}

/// A formula in a cell: code, its `|` escaped (GitHub reads a table's `|` before code).
fn formula(s: &str) -> String {
    format!("`{}`", s.replace('|', "\\|"))
}

/// The fixed words of a document, in its language.
struct Words {
    title: &'static str,
    intro: &'static str,
    columns: [&'static str; 5],
}

fn words(lang: Lang) -> Words {
    match lang {
        Lang::En => Words {
            title: "Common mistakes",
            intro: "The catalogue of common mistakes that `cagd check` diagnoses. Each mistake is \
a one-line change of the notes' formula (a coefficient, a sign, a direction, an index, a step \
left out) that the engine computes exactly, as a student who made it would have: when its \
answer equals the student's on the wrong entries, the report names it; when several give the \
same values the report says they are ambiguous; when none does, it says that no known mistake \
explains them, and never guesses. A correct answer is never diagnosed.\n\n\
The Spanish version is [errores-frecuentes.md](errores-frecuentes.md). This file is written by \
`cargo run -p cagd-diagnose --example mistakes` from the catalogue itself; do not edit it by \
hand.",
            columns: [
                "id",
                "what the student did",
                "formula used instead",
                "the notes' formula",
                "where",
            ],
        },
        Lang::Es => Words {
            title: "Errores frecuentes",
            intro: "El catálogo de errores frecuentes que diagnostica `cagd check`. Cada error es \
un cambio de una línea en la fórmula de los apuntes (un coeficiente, un signo, un sentido, un \
índice, un paso omitido) que el programa calcula de forma exacta, como lo habría calculado el \
estudiante que lo cometió: si su respuesta coincide con la del estudiante en las entradas \
incorrectas, el informe lo nombra; si varios dan los mismos valores, el informe dice que son \
ambiguos; si ninguno los da, dice que ningún error conocido los explica, y nunca adivina. Una \
respuesta correcta nunca recibe un diagnóstico.\n\n\
La versión en inglés es [mistakes.md](mistakes.md). Este archivo lo escribe \
`cargo run -p cagd-diagnose --example mistakes` a partir del propio catálogo; no se edita a \
mano.",
            columns: [
                "identificador",
                "qué hizo el estudiante",
                "fórmula usada",
                "fórmula de los apuntes",
                "dónde",
            ],
        },
    }
}

/// The catalogue as a Markdown document in `lang`.
pub fn document(lang: Lang) -> String {
    let w = words(lang);
    let mut out = format!("# {}\n\n{}\n", w.title, w.intro);
    let all = Mistake::all();
    // the families in the catalogue's order (family by family, as `Mistake::all` lists them)
    let mut families: Vec<Family> = Vec::new();
    for m in &all {
        if !families.contains(&m.family()) {
            families.push(m.family());
        }
    }
    for family in families {
        let ops: Vec<String> = operations(family)
            .iter()
            .map(|o| format!("`{o}`"))
            .collect();
        let name = family.phrase(lang).text();
        let mut first = name.chars();
        let name: String = first
            .next()
            .map(|c| c.to_uppercase().chain(first).collect())
            .unwrap_or_default();
        out += &format!("\n## {} ({})\n\n", cell(&name), ops.join(", "));
        out += &format!("| {} |\n", w.columns.join(" | "));
        out += &format!("|{}\n", "---|".repeat(w.columns.len()));
        for m in all.iter().filter(|m| m.family() == family) {
            out += &format!(
                "| `{}` | {} | {} | {} | {} |\n",
                m.id(),
                cell(&m.phrase(lang).text()),
                formula(m.used().text),
                formula(m.right().text),
                cell(&m.place().phrase(lang).text()),
            );
        }
    }
    out
}

#[allow(dead_code)] // the test includes this file for `document`
fn main() -> std::io::Result<()> {
    for (file, lang) in DOCUMENTS {
        let path = docs().join(file);
        std::fs::write(&path, document(lang))?;
        println!("{}", path.display());
    }
    Ok(())
}
