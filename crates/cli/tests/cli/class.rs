//! `cagd check` on a class: a file per student and a file whose problems name their student,
//! diagnosed against one key per problem; each student's report and the teacher's summary.

use crate::common::{cagd, stdout};
use cagd_diagnose::Key;
use cagd_problem::diagnosis::CoonsMistake;
use cagd_problem::{Limits, Mistake, Problem, Settings};
use serde_json::{json, Value};
use std::path::PathBuf;

/// A fresh temporary folder.
fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cagd-class-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The Coons problem of docs/format.md, with a title; `top` the last point of c2.
fn coons(top: i64) -> Value {
    json!({
        "op": "coons",
        "title": "Coons patch",
        "c1": {"bezier": [[0, 0, 0], ["1/2", 0, 2], [1, 0, 3], [2, 0, 0]]},
        "c2": {"bezier": [[0, 3, 0], ["1/2", 3, 3], [1, 3, 1], [2, top, 0]]},
        "d1": {"bezier": [[0, 0, 0], [0, 1, 3], [0, 3, 0]]},
        "d2": {"bezier": [[2, 0, 0], [2, 1, 2], [2, top, 0]]}
    })
}

/// The key's surface of `problem`, and the surface of a student who added c_cd.
fn right_and_cd_added(problem: &Value) -> (Value, Value) {
    let p = Problem::read(problem, &Limits::DEFAULT).unwrap();
    let key = Key::new(&p, &Settings::default());
    let answer = key.answer.as_ref().unwrap();
    let right = answer.result.first().unwrap().1.to_json();
    let (_, mistaken) = key
        .mistaken
        .iter()
        .find(|(m, _)| *m == Mistake::Coons(CoonsMistake::CdAdded))
        .unwrap();
    let wrong = mistaken.result.first().unwrap().1.to_json();
    (right, wrong)
}

/// `problem` answered with `surface`, by `student` when given.
fn answered(problem: &Value, surface: &Value, student: Option<&str>) -> Value {
    let mut p = problem.clone();
    p["expected"] = json!({ "surface": surface });
    if let Some(s) = student {
        p["student"] = s.into();
    }
    p
}

/// Three students: ana (a file: c_cd added in problem 1, problem 2 right), bea (a file:
/// both right), and "../x" (named in the problems of a third file: problem 1 right, problem 2
/// wrong in a way no known mistake explains).
fn class(dir: &std::path::Path) -> Vec<String> {
    let (p1, p2) = (coons(4), coons(5));
    let (r1, w1) = right_and_cd_added(&p1);
    let (r2, _) = right_and_cd_added(&p2);
    let mut odd = r2.clone();
    odd["bezier"][1][1] = json!(["9", "9", "9"]);
    let files = [
        (
            "ana.json",
            json!([answered(&p1, &w1, None), answered(&p2, &r2, None)]),
        ),
        (
            "bea.json",
            json!([answered(&p1, &r1, None), answered(&p2, &r2, None)]),
        ),
        (
            "late.json",
            json!([
                answered(&p1, &r1, Some("../x")),
                answered(&p2, &odd, Some("../x"))
            ]),
        ),
    ];
    files
        .iter()
        .map(|(name, doc)| {
            let path = dir.join(name);
            std::fs::write(&path, doc.to_string()).unwrap();
            path.to_str().unwrap().to_string()
        })
        .collect()
}

#[test]
fn a_class_is_checked_into_reports_and_a_summary() {
    let dir = folder("out");
    let files = class(&dir);
    let out_dir = dir.join("reports");
    let mut args: Vec<&str> = vec!["check"];
    args.extend(files.iter().map(String::as_str));
    args.extend(["--out", out_dir.to_str().unwrap(), "--lang", "es"]);
    let out = cagd(&args);
    assert_eq!(out.status.code(), Some(1), "{}", stdout(&out));
    let mut written: Vec<String> = std::fs::read_dir(&out_dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    written.sort();
    // "../x" stays inside the folder, as a safe file name
    assert_eq!(written, ["_x.txt", "ana.txt", "bea.txt", "summary.txt"]);
    assert!(!dir.join("x.txt").exists());
    assert!(stdout(&out).ends_with("6 problemas comprobados: 4 correctos, 2 incorrectos\n"));
    let ana = std::fs::read_to_string(out_dir.join("ana.txt")).unwrap();
    assert!(ana.starts_with("=== Alumno: ana ===\n"), "{ana}");
    let summary = std::fs::read_to_string(out_dir.join("summary.txt")).unwrap();
    for line in [
        "Resumen de la clase: 3 alumnos\n",
        "Problema 1: Coons patch\n  3 respuestas, 2 correctas, puntuación media",
        "  - coons.cd_added, una vez: sumó la superficie bilineal c_cd en lugar de restarla\n",
        "Problema 2: Coons patch\n  3 respuestas, 2 correctas, puntuación media 35/36\n  - 1 respuesta incorrecta que ningún error conocido explica\n",
    ] {
        assert!(summary.contains(line), "{line:?} in\n{summary}");
    }
    // the summary in JSON, the reports in Markdown
    for (format, ext) in [("json", "json"), ("markdown", "md")] {
        let mut args = args.clone();
        args.extend(["--format", format]);
        let out = cagd(&args);
        assert_eq!(out.status.code(), Some(1));
        assert!(out_dir.join(format!("summary.{ext}")).exists());
        assert!(out_dir.join(format!("_x.{ext}")).exists());
    }
    let summary: Value =
        serde_json::from_str(&std::fs::read_to_string(out_dir.join("summary.json")).unwrap())
            .unwrap();
    assert_eq!(summary["students"], 3);
    assert_eq!(
        summary["problems"][0]["mistakes"][0]["id"],
        "coons.cd_added"
    );
    assert_eq!(summary["problems"][0]["mistakes"][0]["count"], 1);
    assert_eq!(summary["problems"][1]["unexplained"], 1);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_class_in_json_has_each_answer_diagnosed() {
    let dir = folder("json");
    let files = class(&dir);
    let mut args: Vec<&str> = vec!["check", "--format", "json"];
    args.extend(files.iter().map(String::as_str));
    let out = cagd(&args);
    assert_eq!(out.status.code(), Some(1));
    let doc: Value = serde_json::from_slice(&out.stdout).unwrap();
    let answers = doc["answers"].as_array().unwrap();
    assert_eq!(answers.len(), 6);
    let ana = &answers[0];
    assert_eq!(ana["student"], "ana");
    assert!(ana["file"].as_str().unwrap().ends_with("ana.json"));
    assert_eq!(ana["problem"], 1);
    assert_eq!(ana["passed"], false);
    let diagnoses = &ana["assessment"]["results"][0]["diagnoses"];
    assert_eq!(diagnoses[0]["id"], "coons.cd_added", "{ana}");
    assert_eq!(diagnoses[0]["whole"], true);
    assert_eq!(answers[4]["student"], "../x");
    assert_eq!(answers[4]["assessment"]["correct"], true);
    assert_eq!(doc["summary"]["students"], 3);
    // one student: the list of answers alone, exit code 0 when all are right
    let out = cagd(&["check", "--format", "json", &files[1]]);
    assert_eq!(out.status.code(), Some(0));
    let doc: Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(doc.as_array().unwrap().len(), 2);
    assert_eq!(doc[0]["assessment"]["score"], "1");
    // --summary: the summary for one student too
    let out = cagd(&["check", &files[1], "--summary"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(
        stdout(&out).contains("Class summary: 1 student\n"),
        "{}",
        stdout(&out)
    );
    let _ = std::fs::remove_dir_all(&dir);
}
