//! `cagd render` and the figures of the keys: the languages of a figure and of the HTML page,
//! a problem in letters, the steps in panels.

use crate::common::{cagd, cagd_stdin, stderr, stdout};

fn fixture(path: &str) -> String {
    format!("{}/../../fixtures/{path}", env!("CARGO_MANIFEST_DIR"))
}

fn temp(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("cagd-figures-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// A Coons patch without a title or a name: the figure and the page are titled by what the
/// operation computes, in the language asked.
const UNTITLED_COONS: &str = r#"{"op": "coons",
 "c1": {"bezier": [[0, 0, 0], [1, 0, 1], [2, 0, 0]]},
 "c2": {"bezier": [[0, 2, 0], [1, 2, 1], [2, 2, 0]]},
 "d1": {"bezier": [[0, 0, 0], [0, 1, 1], [0, 2, 0]]},
 "d2": {"bezier": [[2, 0, 0], [2, 1, 1], [2, 2, 0]]}}"#;

#[test]
fn the_html_page_and_the_figure_in_both_languages() {
    let dir = temp("lang");
    let path = |f: &str| dir.join(f).to_string_lossy().into_owned();
    let out = cagd_stdin(
        &[
            "render",
            "-",
            "--html",
            &path("es.html"),
            "--svg",
            &path("es.svg"),
            "--lang",
            "es",
        ],
        UNTITLED_COONS,
    );
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let page = std::fs::read_to_string(path("es.html")).unwrap();
    assert!(page.contains("<html lang=\"es\">"));
    assert!(
        page.contains("<title>Superficie de Coons</title>"),
        "{page:.400}"
    );
    assert!(page.contains("> malla de control</label>") && page.contains("Arrastre para girar"));
    let svg = std::fs::read_to_string(path("es.svg")).unwrap();
    assert!(svg.contains(">Superficie de Coons</text>"));
    assert!(svg.contains(">superficie</text>"), "the legend in Spanish");
    let out = cagd_stdin(&["render", "-", "--html", &path("en.html")], UNTITLED_COONS);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let page = std::fs::read_to_string(path("en.html")).unwrap();
    assert!(page.contains("<html lang=\"en\">") && page.contains("<title>Coons surface</title>"));
    assert!(!page.contains("<title>coons</title>"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_problem_in_letters_asks_for_values_in_both_languages_and_is_drawn_at_them() {
    let dir = temp("letters");
    let svg = dir.join("octant.svg").to_string_lossy().into_owned();
    let octant = fixture("slides/04-sphere-octant-radius-r.json");
    let out = cagd(&["render", &octant, "--svg", &svg]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        stderr(&out).contains("written in letters (R)")
            && stderr(&out).contains("\"values\": {\"R\": 1}"),
        "{}",
        stderr(&out)
    );
    assert!(!stderr(&out).contains("1e308"));
    let out = cagd(&["render", &octant, "--svg", &svg, "--lang", "es"]);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        stderr(&out).contains("escrito con letras (R)")
            && stderr(&out).contains("\"values\": {\"R\": 1}"),
        "{}",
        stderr(&out)
    );
    // with values, the figure is drawn at them
    let mut problem: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&octant).unwrap()).unwrap();
    problem["values"] = serde_json::json!({"R": 2});
    let out = cagd_stdin(&["render", "-", "--svg", &svg], problem.to_string());
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    assert!(std::fs::read_to_string(&svg)
        .unwrap()
        .contains(">surface</text>"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn render_steps_draws_each_step_in_a_panel() {
    let dir = temp("steps");
    let svg = dir.join("steps.svg").to_string_lossy().into_owned();
    let out = cagd(&[
        "render",
        &fixture("ch6/07-coons-bezier.json"),
        "--svg",
        &svg,
        "--steps",
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", stderr(&out));
    let drawn = std::fs::read_to_string(&svg).unwrap();
    assert_eq!(drawn.matches("<svg ").count(), 5, "one panel per surface");
    for step in ["surface", "c_c", "c_d", "c_cd"] {
        assert!(drawn.contains(&format!(">{step}</text>")), "{step}");
    }
    assert!(stdout(&out).contains("steps.svg"));
    let _ = std::fs::remove_dir_all(&dir);
}
