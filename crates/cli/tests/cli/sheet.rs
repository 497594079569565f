//! `cagd sheet FILE --out DIR` (a teacher's own problems) and `cagd generate` of several
//! topics: the statement sheet and keys written, a bad problem named and the others written,
//! the header flags as data.

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

use crate::common::{cagd, stdout};
use serde_json::json;
use std::path::PathBuf;

fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cagd-sheet-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn a_sheet_of_own_problems_names_the_bad_one_and_writes_the_others() {
    let dir = scratch("own");
    let file = dir.join("problems.json");
    let square = json!([[[0, 0, 0], [1, 0, 0]], [[0, 1, 0], [1, 1, 1]]]);
    let problems = json!([
        {"name": "mine-1", "op": "closed_form", "surface": {"bezier": square}},
        {"name": "broken", "op": "circle", "radius": -1},
        {"name": "mine-3", "op": "developable", "surface": {"bezier": square}},
    ]);
    std::fs::write(&file, problems.to_string()).unwrap();
    let out = dir.join("out");
    let run = cagd(&[
        "sheet",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--lang",
        "es",
        "--title",
        "Hoja 3 \\input{x}",
        "--course",
        "DGAO $100",
        "--date",
        "marzo",
    ]);
    assert_eq!(run.status.code(), Some(1), "{run:?}");
    let text = stdout(&run);
    assert!(
        text.contains("problema 2") && text.contains("\"broken\""),
        "{text}"
    );
    let sheet = std::fs::read_to_string(out.join("statements.tex")).unwrap();
    assert!(sheet.contains("\\section*{Problema 1}"), "{sheet}");
    assert!(
        sheet.contains("\\section*{Problema 2}\n¿Es desarrollable"),
        "{sheet}"
    );
    assert!(!sheet.contains("Problema 3"));
    // the header is data: the backslash and the dollar printed, never run
    assert!(!sheet.contains("\\input{x}"), "{sheet}");
    assert!(sheet.contains("DGAO \\$100"), "{sheet}");
    assert!(sheet.contains("Hoja 3") && sheet.contains("marzo"));
    assert!(sheet.contains("Nombre y apellidos:"));
    for f in ["key.txt", "key.md", "key.tex", "key.json"] {
        assert!(out.join(f).exists(), "{f}");
    }
    // the teacher's own file is never written over
    assert!(!out.join("problems.json").exists());
    let beside = cagd(&[
        "sheet",
        file.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert_eq!(beside.status.code(), Some(1));
    assert_eq!(
        std::fs::read_to_string(&file).unwrap(),
        problems.to_string()
    );
    let key: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("key.json")).unwrap()).unwrap();
    assert_eq!(key.as_array().unwrap().len(), 2);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn generate_takes_several_topics_as_one_exam() {
    let printed = cagd(&[
        "generate",
        "--topic",
        "coons:2,revolution:1,interpolate",
        "--count",
        "3",
        "--seed",
        "7",
    ]);
    assert_eq!(printed.status.code(), Some(0), "{printed:?}");
    let problems: serde_json::Value = serde_json::from_str(&stdout(&printed)).unwrap();
    let names: Vec<&str> = problems
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["name"].as_str().unwrap())
        .collect();
    assert_eq!(
        names,
        [
            "coons-1",
            "coons-2",
            "revolution-1",
            "interpolate-1",
            "interpolate-2",
            "interpolate-3"
        ]
    );
    let bad = cagd(&["generate", "--topic", "coons:x"]);
    assert_eq!(bad.status.code(), Some(1));
}
