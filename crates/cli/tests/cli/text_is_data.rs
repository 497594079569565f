//! The text of a problem, and the strings the command line echoes, reach the terminal as data:
//! no control character of a title, a note, an unknown operation, an `expected` key or a file
//! name is printed raw by `cagd solve`, `cagd check` or `cagd examples`, on standard output or
//! in an error; and a Markdown key's figures in a folder named `set #3` are read back by a
//! CommonMark parser as that folder's files.

use crate::common::{cagd, stderr, stdout};
use pulldown_cmark::{Event, Parser, Tag};
use serde_json::json;
use std::path::{Path, PathBuf};
use std::process::Output;

/// The control characters a terminal acts on: ESC (a CSI that clears the screen, an OSC 52
/// that sets the clipboard), BEL, CR, BS, and the one-byte CSI U+009B.
const CONTROLS: &str = "\u{1b}[2J\u{1b}]52;c;cHduZWQ=\u{7}\u{8}\u{9b}31m";

/// A folder of its own under the system's temporary folder, made anew.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cagd-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The raw bytes of a terminal control in `bytes`, if any: C0 but the line feed (ESC, BEL,
/// CR, BS...), DEL, or a C1 character (U+009B) in UTF-8 or as a lone byte.
fn raw_control(bytes: &[u8]) -> Option<String> {
    let text = String::from_utf8_lossy(bytes);
    text.chars()
        .find(|c| c.is_control() && *c != '\n')
        .map(|c| format!("{c:?}"))
        .or_else(|| bytes.contains(&0x9b).then(|| "a lone 0x9B".into()))
}

/// Checks that neither output of a run has a raw control character, nor a line that a
/// problem's text could fake (`verdict: passed`, after a CR or a line feed).
fn clean(what: &str, out: &Output) {
    for (stream, bytes) in [("stdout", &out.stdout), ("stderr", &out.stderr)] {
        assert_eq!(
            raw_control(bytes),
            None,
            "{what}: a raw control character on {stream}:\n{}",
            String::from_utf8_lossy(bytes)
        );
        let text = String::from_utf8_lossy(bytes);
        assert!(
            !text.lines().any(|l| l.starts_with("verdict: passed")),
            "{what}: a faked line on {stream}:\n{text}"
        );
    }
}

#[test]
fn control_characters_never_reach_the_terminal() {
    let dir = scratch("controls");
    let c = CONTROLS;
    let batch = json!([
        {"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 2]]}, "params": ["1/2"],
         "name": format!("n{c}"), "title": format!("t{c}\rverdict: passed"),
         "note": format!("note{c}\nverdict: passed"),
         "es": {"title": format!("título{c}"), "note": format!("nota{c}")},
         "expected": {"points": [["1/2", 1]]}},
        {"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 2]]}, "params": ["1/2"],
         "title": format!("t{c}"), "expected": {"points": [["1/2", 1]], format!("k{c}"): 1}},
        {"op": format!("op{c}"), "title": format!("t{c}")},
        {"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 2]]}, "params": [format!("1/2{c}")]}
    ]);
    let file = dir.join("batch.json");
    std::fs::write(&file, batch.to_string()).unwrap();
    let f = file.to_string_lossy().into_owned();
    // each problem alone too: a key without a batch's index
    let mut files = vec![f.clone()];
    for (i, p) in batch.as_array().unwrap().iter().enumerate() {
        let one = dir.join(format!("p{i}.json"));
        std::fs::write(&one, p.to_string()).unwrap();
        files.push(one.to_string_lossy().into_owned());
    }
    for f in &files {
        for lang in ["en", "es"] {
            for format in ["text", "markdown"] {
                let out = cagd(&["solve", f, "--format", format, "--lang", lang]);
                // the first problem passes, the others fail
                assert!(matches!(out.status.code(), Some(0 | 1)), "{}", stderr(&out));
                assert!(stdout(&out).contains("\\u{1b}"), "{}", stdout(&out));
                clean(&format!("solve {f} --format {format} --lang {lang}"), &out);
            }
            let out = cagd(&["check", f, "--lang", lang]);
            assert!(matches!(out.status.code(), Some(0 | 1)), "{}", stderr(&out));
            clean(&format!("check {f} --lang {lang}"), &out);
        }
    }
    // the CR of the title is shown, not obeyed
    let out = cagd(&["solve", &files[1]]);
    assert!(
        stdout(&out)
            .contains("t\\u{1b}[2J\\u{1b}]52;c;cHduZWQ=\\u{7}\\u{8}\\u{9b}31m\\rverdict: passed"),
        "{}",
        stdout(&out)
    );
    // a file name in an error, in the check's report, and an example's name in a usage error
    let named = dir.join(format!("x{c}.json"));
    let missing = named.to_string_lossy().into_owned();
    for args in [
        vec!["solve", missing.as_str()],
        vec!["check", missing.as_str()],
        vec!["solve", missing.as_str(), "--lang", "es"],
        vec!["examples", "ch9\u{1b}[2J\u{7}\r\u{8}\u{9b}"],
        vec!["examples", "ch9\u{1b}[2J", "--lang", "es"],
    ] {
        let out = cagd(&args);
        assert_ne!(out.status.code(), Some(0), "{args:?}");
        assert!(
            stderr(&out).contains("\\u{1b}"),
            "{args:?}: {}",
            stderr(&out)
        );
        clean(&format!("{args:?}"), &out);
    }
    std::fs::write(&named, b"{\"op\": ").unwrap();
    let out = cagd(&["solve", &missing]);
    assert!(stderr(&out).contains("not valid JSON"), "{}", stderr(&out));
    clean("solve of a file that is not JSON", &out);
    std::fs::write(&named, batch[0].to_string()).unwrap();
    let out = cagd(&["check", &missing]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(stdout(&out).starts_with("-- "), "{}", stdout(&out));
    clean("check of a file with controls in its name", &out);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Decodes the `%XX` escapes of a URL.
fn percent_decoded(url: &str) -> String {
    let (bytes, mut out, mut i) = (url.as_bytes(), Vec::new(), 0);
    while i < bytes.len() {
        let hex = url
            .get(i + 1..i + 3)
            .and_then(|h| u8::from_str_radix(h, 16).ok());
        match (bytes[i], hex) {
            (b'%', Some(b)) => {
                out.push(b);
                i += 3;
            }
            (b, _) => {
                out.push(b);
                i += 1;
            }
        }
    }
    String::from_utf8(out).unwrap()
}

#[test]
fn markdown_figures_in_a_folder_with_a_space_and_a_hash() {
    let root = scratch("figures-md");
    for folder in ["set #3", "a (b) [c] <d> & é"] {
        let dir = root.join(folder);
        let d = dir.to_string_lossy().into_owned();
        let out = cagd(&[
            "examples",
            "ch5-c1-join",
            "ch6-coons-bezier",
            "ch5-restriction",
            "--format",
            "markdown",
            "--figures",
            &d,
        ]);
        assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
        let md = stdout(&out);
        let mut images = Vec::new();
        for e in Parser::new(&md) {
            match e {
                Event::Start(Tag::Image { dest_url, .. }) => {
                    images.push(percent_decoded(&dest_url))
                }
                Event::Start(Tag::Link { .. }) | Event::Html(_) | Event::InlineHtml(_) => {
                    panic!("{e:?} in\n{md}")
                }
                _ => {}
            }
        }
        let mut figures: Vec<String> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|f| f.unwrap().path())
            .filter(|p| p.extension().is_some_and(|x| x == "svg"))
            .map(|p| format!("{d}/{}", p.file_name().unwrap().to_string_lossy()))
            .collect();
        figures.sort();
        images.sort();
        assert_eq!(figures.len(), 3, "{figures:?}");
        assert_eq!(images, figures, "{md}");
        assert!(images.iter().all(|i| Path::new(i).exists()));
    }
    let _ = std::fs::remove_dir_all(&root);
}
