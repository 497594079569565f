//! Exams of several topics: the parts read from `coons,revolution:1,interpolate:3`, the
//! problems numbered as one exam, each topic's problems those of its own set, the same bytes
//! for the same seed; the header the teacher sets.

// Test helpers outside #[test] functions may unwrap, expect, index and panic, as tests do.
#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

use cagd_exercises::{
    exam_files, exam_parts, generate, generate_exam, ExamPart, ExerciseError, Lang, SheetHeader,
};

#[test]
fn parts_with_and_without_counts() {
    let parts = exam_parts("coons, revolution:1,interpolate:3", 2).unwrap();
    let read: Vec<(&str, usize)> = parts.iter().map(|p| (p.topic.as_str(), p.count)).collect();
    assert_eq!(read, [("coons", 2), ("revolution", 1), ("interpolate", 3)]);
    assert_eq!(
        exam_parts("coons:two", 1).unwrap_err(),
        ExerciseError::BadCount {
            part: "coons:two".into()
        }
    );
    assert_eq!(
        exam_parts("coons,ruled,coons:1", 1).unwrap_err(),
        ExerciseError::RepeatedTopic {
            name: "coons".into()
        }
    );
    assert!(matches!(
        exam_parts("coons,spheres", 1),
        Err(ExerciseError::UnknownTopic { .. })
    ));
    assert!(matches!(
        exam_parts("coons:600,ruled:600", 1),
        Err(ExerciseError::TooMany { count: 1200 })
    ));
}

#[test]
fn an_exam_is_numbered_as_one_and_its_topics_are_their_own_sets() {
    let parts = exam_parts("coons,revolution:1,interpolate:3", 2).unwrap();
    let problems = generate_exam(&parts, 7, Lang::Es).unwrap();
    let names: Vec<&str> = problems
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
    // each problem its own stream: the coons of the exam are those of --topic coons
    let strip = |p: &serde_json::Value| {
        let mut p = p.clone();
        p.as_object_mut().unwrap().remove("title");
        p
    };
    let coons = generate("coons", 2, 7).unwrap();
    assert_eq!(strip(&problems[0]), strip(&coons[0]));
    assert_eq!(strip(&problems[1]), strip(&coons[1]));
    let header = SheetHeader {
        course: Some("Diseño Geométrico 2026/27".into()),
        title: Some("Examen parcial".into()),
        date: Some("12 de enero".into()),
    };
    let files = exam_files(&parts, 7, Lang::Es, &header, &|_, _| None).unwrap();
    let sheet = &files[1].1;
    for i in 1..=6 {
        assert_eq!(
            sheet
                .matches(&format!("\\section*{{Problema {i}}}"))
                .count(),
            1,
            "{sheet}"
        );
    }
    assert!(!sheet.contains("Problema 7"));
    let at = |s: &str| sheet.find(s).unwrap();
    assert!(at("Problema 2}") < at("superficie de revolución"));
    assert!(at("superficie de revolución") < at("Problema 4}"));
    assert!(sheet.contains("Examen parcial") && sheet.contains("12 de enero"));
    assert!(sheet.contains("Nombre y apellidos:"));
    assert!(!sheet.contains("semilla") && !sheet.contains("Enunciados"));
    let key = &files[4].1;
    assert_eq!(key.matches("\\section*{").count(), 6);
    assert_eq!(
        files,
        exam_files(&parts, 7, Lang::Es, &header, &|_, _| None).unwrap()
    );
    // one topic alone is an exam of one part
    let one = [ExamPart {
        topic: "coons".into(),
        count: 2,
    }];
    assert_eq!(generate_exam(&one, 7, Lang::En).unwrap(), coons);
}

#[test]
fn the_header_is_data() {
    let parts = exam_parts("ruled:1", 1).unwrap();
    let header = SheetHeader {
        course: Some("100% $x$ & #1".into()),
        title: Some("\\input{/etc/passwd}".into()),
        date: Some("{\\bf}".into()),
    };
    let files = exam_files(&parts, 1, Lang::En, &header, &|_, _| None).unwrap();
    let sheet = &files[1].1;
    assert!(!sheet.contains("\\input{/etc"), "{sheet}");
    assert!(
        !sheet.contains("$x$") && !sheet.contains("{\\bf}"),
        "{sheet}"
    );
    assert!(sheet.contains("Name:"));
    let plain = exam_files(&parts, 1, Lang::En, &SheetHeader::default(), &|_, _| None).unwrap();
    assert!(plain[1].1.contains("Problem sheet"));
}
