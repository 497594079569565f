//! Nothing lost without a word: an answer's `result` checks back as its `expected`, an
//! `expected` that checks nothing is said, input that is not UTF-8 is named as such, figures
//! that cannot be written fail `cagd generate`, an empty path and two outputs to one file are
//! refused, and a closed pipe ends quietly with the exit code of the work done.

use crate::common::{cagd, cagd_stdin, format_doc_problems, stderr, stdout};
use serde_json::{json, Value};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// A fresh folder of its own for a test.
fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cagd-lost-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs `cagd ARGS` in the folder `dir`.
fn cagd_in(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the cagd binary runs")
}

/// The round trip `cagd check --help` promises: every example of docs/format.md solved with
/// `cagd solve --format json` (with and without `--steps`), its `result` fed back whole as
/// its `expected`, passes `cagd check`. (Ten of them have `remarks`, which used to be refused:
/// "`remarks`: not a result of this problem".)
#[test]
fn every_answer_of_the_format_doc_checks_back_as_its_expected() {
    let problems = format_doc_problems();
    let dir = folder("round-trip");
    for steps in [false, true] {
        let mut args = vec!["solve", "-", "--format", "json"];
        if steps {
            args.push("--steps");
        }
        let out = cagd_stdin(&args, Value::Array(problems.clone()).to_string());
        assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
        let answers: Vec<Value> = serde_json::from_slice(&out.stdout).unwrap();
        assert_eq!(answers.len(), problems.len());
        let remarks = answers
            .iter()
            .filter(|a| a["result"].get("remarks").is_some())
            .count();
        assert!(remarks >= 10, "answers with remarks: {remarks}");
        let checked: Vec<Value> = problems
            .iter()
            .zip(&answers)
            .map(|(p, a)| {
                let mut p = p.clone();
                p["expected"] = a["result"].clone();
                p
            })
            .collect();
        let file = dir.join(format!("checked-{steps}.json"));
        std::fs::write(&file, Value::Array(checked).to_string()).unwrap();
        let out = cagd(&["check", file.to_str().unwrap()]);
        let n = problems.len();
        assert_eq!(out.status.code(), Some(0), "{}", stdout(&out));
        assert!(
            stdout(&out).ends_with(&format!("{n} problems checked: {n} correct, 0 wrong\n")),
            "{}",
            stdout(&out)
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// An `expected` whose `steps` is not steps, or whose key is not a result, fails the check
/// with the key named (`"steps": "x"` used to pass, checking nothing); in Spanish too.
#[test]
fn an_expected_that_checks_nothing_fails_naming_the_key() {
    let dir = folder("expected");
    let file = dir.join("p.json");
    let circle = |expected: Value| json!({"op": "circle", "arcs": 4, "expected": expected});
    let curve = cagd_stdin(
        &["solve", "-", "--format", "json"],
        json!({"op": "circle", "arcs": 4}).to_string(),
    );
    let curve: Value = serde_json::from_slice(&curve.stdout).unwrap();
    let curve = curve["result"]["curve"].clone();
    for (expected, en, es) in [
        (
            json!({"curve": curve, "steps": "x"}),
            "`steps`: the steps by name (an object) or the list an answer writes, found the string \"x\"",
            "`steps`: los pasos por nombre (un objeto) o la lista que escribe una respuesta, se encontró",
        ),
        (
            json!({"curve": curve, "remarks": 3}),
            "`remarks`: a list of strings (the answer's remarks, not compared), found the number 3",
            "`remarks`: una lista de cadenas (las observaciones de la respuesta, que no se comparan)",
        ),
        (
            json!({"curve": curve, "points": []}),
            "`points`: not a result of this problem (`circle` gives `curve`)",
            "`points`: no es un resultado de este problema (`circle` da `curve`)",
        ),
    ] {
        std::fs::write(&file, circle(expected).to_string()).unwrap();
        let out = cagd(&["check", file.to_str().unwrap()]);
        assert_eq!(out.status.code(), Some(1), "{}", stdout(&out));
        assert!(stdout(&out).contains(en), "{}", stdout(&out));
        let out = cagd(&["check", file.to_str().unwrap(), "--lang", "es"]);
        assert_eq!(out.status.code(), Some(1), "{}", stdout(&out));
        assert!(stdout(&out).contains(es), "{}", stdout(&out));
    }
    // the right curve with the remarks of any words passes: remarks are not compared
    std::fs::write(
        &file,
        circle(json!({"curve": curve, "remarks": ["other words"]})).to_string(),
    )
    .unwrap();
    assert_eq!(
        cagd(&["check", file.to_str().unwrap()]).status.code(),
        Some(0)
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The bytes of `text` in UTF-16 (little- or big-endian), with or without a byte-order mark.
fn utf16(text: &str, little: bool, bom: bool) -> Vec<u8> {
    let units = bom
        .then_some(0xFEFF_u16)
        .into_iter()
        .chain(text.encode_utf16());
    units
        .flat_map(|u| {
            if little {
                u.to_le_bytes()
            } else {
                u.to_be_bytes()
            }
        })
        .collect()
}

/// Input that is not UTF-8 is named as such, with what it looks like and what to do, by
/// `cagd solve` (a file, standard input, a batch read element by element), `cagd check` and
/// `cagd render`, in English and Spanish; a UTF-8 byte-order mark is read. (It used to be
/// "invalid unicode code point" or "expected value at line 1 column 1"; a Latin-1 problem in
/// a batch was read with U+FFFD in place of its letters.)
#[test]
fn input_that_is_not_utf8_is_named_as_such() {
    let dir = folder("utf8");
    let problem = r#"{"op": "circle", "arcs": 4, "title": "Círculo"}"#;
    let latin1: Vec<u8> = problem.chars().map(|c| c as u8).collect();
    let files: Vec<(&str, Vec<u8>, &str, &str)> = vec![
        (
            "latin1.json",
            latin1.clone(),
            "latin1.json is not UTF-8: byte 0xED at line 1, column 40 (it looks like Latin-1): save it as UTF-8",
            "latin1.json no está en UTF-8: byte 0xED en la línea 1, columna 40 (parece Latin-1): guárdelo en UTF-8",
        ),
        (
            "utf16-bom.json",
            utf16(problem, true, true),
            "utf16-bom.json is not UTF-8 (it looks like UTF-16LE): save it as UTF-8",
            "utf16-bom.json no está en UTF-8 (parece UTF-16LE): guárdelo en UTF-8",
        ),
        (
            "utf16be.json",
            utf16(problem, false, false),
            "utf16be.json is not UTF-8 (it looks like UTF-16BE): save it as UTF-8",
            "utf16be.json no está en UTF-8 (parece UTF-16BE): guárdelo en UTF-8",
        ),
        (
            // a batch in UTF-16 without a mark: its `[` is read, then NUL
            "utf16-batch.json",
            utf16(&format!("[{problem}, {problem}]"), true, false),
            "utf16-batch.json is not UTF-8 (it looks like UTF-16LE): save it as UTF-8",
            "utf16-batch.json no está en UTF-8 (parece UTF-16LE): guárdelo en UTF-8",
        ),
    ];
    for (name, bytes, en, es) in &files {
        let path = dir.join(name);
        std::fs::write(&path, bytes).unwrap();
        let path = path.to_str().unwrap();
        let svg = dir.join("x.svg");
        for args in [
            vec!["solve", path],
            vec!["check", path],
            vec!["render", path, "--svg", svg.to_str().unwrap()],
        ] {
            let out = cagd_in(&dir, &args);
            assert_eq!(out.status.code(), Some(1), "{args:?}");
            assert!(
                stderr(&out).ends_with(&format!("{en}\n")),
                "{args:?}: {}",
                stderr(&out)
            );
            assert!(out.stdout.is_empty() || args[0] == "check", "{args:?}");
        }
        for command in ["solve", "check"] {
            let out = cagd_in(&dir, &[command, name, "--lang", "es"]);
            assert_eq!(out.status.code(), Some(1));
            assert_eq!(stderr(&out), format!("cagd: {es}\n"), "{command}");
        }
        // standard input is named as such
        let out = cagd_stdin(&["solve", "-", "--lang", "es"], bytes);
        assert_eq!(out.status.code(), Some(1));
        assert!(
            stderr(&out).starts_with("cagd: la entrada estándar no está en UTF-8"),
            "{}",
            stderr(&out)
        );
    }
    // in a batch read element by element, the problem in Latin-1 is the one refused
    let mut batch = b"[{\"op\": \"circle\", \"arcs\": 4},\n ".to_vec();
    batch.extend_from_slice(&latin1);
    batch.extend_from_slice(b"]");
    let out = cagd_stdin(&["solve", "-", "--format", "json"], &batch);
    assert_eq!(out.status.code(), Some(1));
    let answers: Vec<Value> = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(answers[0]["ok"], true);
    assert_eq!(
        answers[1]["error"],
        "problem 2: the file is not UTF-8: byte 0xED at line 2, column 41 (it looks like Latin-1): save it as UTF-8"
    );
    let out = cagd_stdin(&["solve", "-", "--lang", "es"], &batch);
    assert!(
        stdout(&out).contains("error: problema 2: el archivo no está en UTF-8: byte 0xED en la línea 2, columna 41 (parece Latin-1): guárdelo en UTF-8"),
        "{}",
        stdout(&out)
    );
    // UTF-8 with a byte-order mark is UTF-8, a batch too
    let bom = [&b"\xEF\xBB\xBF"[..], problem.as_bytes()].concat();
    let path = dir.join("bom.json");
    std::fs::write(&path, &bom).unwrap();
    let path = path.to_str().unwrap();
    let svg = dir.join("bom.svg");
    for args in [
        vec!["solve", path],
        vec!["render", path, "--svg", svg.to_str().unwrap()],
    ] {
        let out = cagd(&args);
        assert_eq!(out.status.code(), Some(0), "{args:?}: {}", stderr(&out));
    }
    let out = cagd_stdin(
        &["solve", "-", "--format", "json"],
        [&bom[..], b"\n"].concat(),
    );
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let out = cagd_stdin(
        &["solve", "-", "--format", "json"],
        [&b"\xEF\xBB\xBF["[..], problem.as_bytes(), b"]"].concat(),
    );
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let _ = std::fs::remove_dir_all(&dir);
}

/// `cagd generate --out DIR` whose figures cannot be written (DIR/fig is a file; a full disk,
/// here each figure a link to /dev/full) fails with the reason, exit code 1, and writes no
/// key without its figures. (It used to exit 0 with keys and sheets without figures.)
#[test]
fn figures_that_cannot_be_written_fail_the_problem_set() {
    let dir = folder("figures");
    let out_dir = dir.join("set");
    std::fs::create_dir_all(&out_dir).unwrap();
    std::fs::write(out_dir.join("fig"), "a file, not a folder").unwrap();
    let args = |d: &Path, lang: &'static str| -> Vec<String> {
        [
            "generate", "--topic", "coons", "--count", "2", "--out", "", "--lang", lang,
        ]
        .iter()
        .map(|s| (*s).to_string())
        .map(|s| {
            if s.is_empty() {
                d.to_str().unwrap().to_string()
            } else {
                s
            }
        })
        .collect()
    };
    let run = |a: Vec<String>| {
        let a: Vec<&str> = a.iter().map(String::as_str).collect();
        cagd(&a)
    };
    let out = run(args(&out_dir, "en"));
    assert_eq!(out.status.code(), Some(1), "{}", stdout(&out));
    assert!(
        stderr(&out).starts_with(&format!(
            "cagd: the problem set is not written, as its figures cannot be: cannot create {}: ",
            out_dir.join("fig").display()
        )),
        "{}",
        stderr(&out)
    );
    assert!(!out_dir.join("key.tex").exists());
    let out = run(args(&out_dir, "es"));
    assert!(
        stderr(&out)
            .starts_with("cagd: la colección no se escribe, porque sus figuras no se pueden escribir: no se puede crear "),
        "{}",
        stderr(&out)
    );
    // a full disk: every figure a link to /dev/full
    if Path::new("/dev/full").exists() {
        let full = dir.join("full");
        std::fs::create_dir_all(full.join("fig")).unwrap();
        for name in [
            "coons-1-data",
            "coons-1-answer",
            "coons-2-data",
            "coons-2-answer",
        ] {
            std::os::unix::fs::symlink("/dev/full", full.join(format!("fig/{name}.png"))).unwrap();
        }
        let out = run(args(&full, "en"));
        assert_eq!(out.status.code(), Some(1), "{}", stdout(&out));
        assert!(
            stderr(&out).contains("cannot write ") && stderr(&out).contains("(os error 28)"),
            "{}",
            stderr(&out)
        );
        assert!(!full.join("key.tex").exists());
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// An empty path is refused by every command that takes one (exit code 2, nothing written):
/// `--out ''` used to write the problem set into the current folder, `--figures ''` the
/// figures to the root.
#[test]
fn an_empty_path_is_refused() {
    let dir = folder("empty");
    std::fs::write(dir.join("c.json"), r#"{"op": "circle", "arcs": 4}"#).unwrap();
    for (args, en) in [
        (
            &["generate", "--topic", "coons", "--count", "1", "--out", ""][..],
            "--out takes the path of a folder, found an empty one",
        ),
        (
            &["examples", "ch5", "--format", "markdown", "--figures", ""],
            "--figures takes the path of a folder, found an empty one",
        ),
        (
            &["solve", ""],
            "FILE takes the path of a file, found an empty one",
        ),
        (
            &["check", "c.json", ""],
            "FILE takes the path of a file, found an empty one",
        ),
        (
            &["render", "", "--svg", "x.svg"],
            "FILE takes the path of a file, found an empty one",
        ),
        (
            &["render", "c.json", "--svg", "x.svg", "--plot", ""],
            "--plot takes the path of a file, found an empty one",
        ),
    ] {
        let out = cagd_in(&dir, args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(
            stderr(&out).starts_with(&format!("cagd: {en} (")),
            "{args:?}: {}",
            stderr(&out)
        );
        let files: Vec<_> = std::fs::read_dir(&dir).unwrap().collect();
        assert_eq!(files.len(), 1, "{args:?} wrote nothing");
    }
    let out = cagd_in(
        &dir,
        &["generate", "--topic", "coons", "--out", "", "--lang", "es"],
    );
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(
        stderr(&out),
        "cagd: --out lleva la ruta de una carpeta, y se encontró una vacía (`cagd help` da la lista de órdenes)\n"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// Two outputs of `cagd render` to one file are refused before anything is written, however
/// the paths are spelled (`F` and `./F`, `d/../F`), and so is an output to the input file;
/// the second used to overwrite the first.
#[test]
fn two_outputs_to_one_file_are_refused() {
    let dir = folder("outputs");
    std::fs::create_dir_all(dir.join("d")).unwrap();
    std::fs::write(dir.join("c.json"), r#"{"op": "circle", "arcs": 4}"#).unwrap();
    for (args, en) in [
        (
            &["render", "c.json", "--svg", "F", "--plot", "./F"][..],
            "--svg F and --plot ./F are the same file: give each output a file of its own",
        ),
        (
            &[
                "render", "c.json", "--html", "d/../F", "--svg", "G", "--obj", "F",
            ],
            "--html d/../F and --obj F are the same file: give each output a file of its own",
        ),
        (
            &["render", "c.json", "--svg", "F", "--svg", "F"],
            "--svg F and --svg F are the same file: give each output a file of its own",
        ),
        (
            &["render", "c.json", "--svg", "F", "--iges", "./d/../c.json"],
            "--iges ./d/../c.json is the input file: give the output another name",
        ),
    ] {
        let out = cagd_in(&dir, args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(
            stderr(&out).starts_with(&format!("cagd: {en} (")),
            "{args:?}: {}",
            stderr(&out)
        );
        assert!(
            !dir.join("F").exists() && !dir.join("G").exists(),
            "{args:?}"
        );
        assert_eq!(
            std::fs::read_to_string(dir.join("c.json")).unwrap(),
            r#"{"op": "circle", "arcs": 4}"#
        );
    }
    // an existing file named through a link to its folder is the same file
    std::os::unix::fs::symlink(dir.join("d"), dir.join("link")).unwrap();
    std::fs::write(dir.join("d/F"), "old").unwrap();
    let out = cagd_in(
        &dir,
        &["render", "c.json", "--svg", "d/F", "--plot", "link/F"],
    );
    assert_eq!(out.status.code(), Some(2), "{}", stderr(&out));
    assert_eq!(std::fs::read_to_string(dir.join("d/F")).unwrap(), "old");
    // distinct files are all written
    let out = cagd_in(&dir, &["render", "c.json", "--svg", "F", "--html", "d/F"]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert_eq!(stdout(&out), "wrote F\nwrote d/F\n");
    let _ = std::fs::remove_dir_all(&dir);
}

/// A reader that closes the pipe (`cagd examples | head -1`) ends `cagd` quietly, the
/// convention of the tools that exit on EPIPE without a message: no error, and the exit code
/// of the work done until then (0, or 1 when a problem answered before the pipe closed
/// failed; a batch used to exit 0 then).
#[test]
fn a_closed_pipe_ends_quietly_with_the_code_of_the_work_done() {
    use std::io::BufRead;
    // `cagd examples | head -1`
    let mut child = Command::new(env!("CARGO_BIN_EXE_cagd"))
        .arg("examples")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = String::new();
    std::io::BufReader::new(child.stdout.take().unwrap())
        .read_line(&mut first)
        .unwrap();
    assert!(!first.is_empty());
    let out = child.wait_with_output().unwrap();
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(stderr(&out), "");
    // a batch far longer than the pipe holds, whose first problem fails, its reader gone
    let dir = folder("pipe");
    let mut batch = vec![json!({"op": "nothing"})];
    batch.extend((0..3000).map(|_| json!({"op": "circle", "arcs": 4})));
    let file = dir.join("batch.json");
    std::fs::write(&file, Value::Array(batch).to_string()).unwrap();
    for format in ["json", "text"] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_cagd"))
            .args(["solve", file.to_str().unwrap(), "--format", format])
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        drop(child.stdout.take());
        let out = child.wait_with_output().unwrap();
        assert_eq!(out.status.code(), Some(1), "{format}");
        assert_eq!(stderr(&out), "", "{format}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A pdflatex that fails (a stand-in on the PATH): `cagd generate` says where and exits 1, the
/// documents it wrote kept; pdflatex is called without shell escape.
#[test]
fn a_document_pdflatex_cannot_compile_fails_the_problem_set() {
    use std::os::unix::fs::PermissionsExt;
    let dir = folder("pdflatex");
    let bin = dir.join("bin");
    std::fs::create_dir_all(&bin).unwrap();
    let fake = bin.join("pdflatex");
    // records its arguments, then fails as pdflatex does on an error
    std::fs::write(
        &fake,
        "#!/bin/sh\necho \"$@\" >> ../pdflatex-args\nexit 1\n",
    )
    .unwrap();
    std::fs::set_permissions(&fake, std::fs::Permissions::from_mode(0o755)).unwrap();
    let path = format!(
        "{}:{}",
        bin.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let out_dir = dir.join("set");
    let out = Command::new(env!("CARGO_BIN_EXE_cagd"))
        .args(["generate", "--topic", "coons", "--count", "1", "--out"])
        .arg(&out_dir)
        .env("PATH", path)
        .current_dir(&dir)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(
        stdout(&out).contains("pdflatex failed on statements.tex"),
        "{}",
        stdout(&out)
    );
    assert!(out_dir.join("key.tex").exists());
    let args = std::fs::read_to_string(dir.join("pdflatex-args")).unwrap();
    assert!(
        args.lines().all(|l| l.starts_with("-no-shell-escape ")),
        "{args}"
    );
}
