//! The HTML page without a browser: self-contained, exact labels, parseable data.

use crate::scenes;
use cagd_render::{to_html, HtmlOptions, RenderError, Scene};
use serde_json::Value;

fn data(page: &str) -> Value {
    let start = page
        .find("<script type=\"application/json\" id=\"scene-data\">")
        .unwrap();
    let rest = &page[start..];
    let body = &rest[rest.find('>').unwrap() + 1..rest.find("</script>").unwrap()];
    serde_json::from_str(body).unwrap()
}

#[test]
fn page_is_self_contained_and_deterministic() {
    let page = to_html(&scenes::coons_scene(), &HtmlOptions::default()).unwrap();
    assert!(page.starts_with("<!DOCTYPE html>"));
    for network in ["http://", "https://", "<link", "src=", "import ", "fetch("] {
        assert!(!page.contains(network), "the page refers to {network}");
    }
    assert!(page.contains("<canvas id=\"view\" width=\"800\" height=\"600\">"));
    assert_eq!(
        page,
        to_html(&scenes::coons_scene(), &HtmlOptions::default()).unwrap()
    );
}

#[test]
fn data_holds_exact_labels_and_the_sampled_grid() {
    let page = to_html(&scenes::coons_scene(), &HtmlOptions::default()).unwrap();
    let d = data(&page);
    let s = &d["surfaces"][0];
    assert_eq!(s["name"], "Coons patch");
    assert_eq!(s["net_text"][1][1], "(1/2, 5/6, 31/6)");
    assert_eq!(s["net_text"][2][1], "(1, 2/3, 13/3)");
    assert!(s["weights_text"].is_null());
    assert_eq!(s["cells"], serde_json::json!([12, 12]));
    assert_eq!(s["grid"].as_array().unwrap().len(), 37);
    // grid[0][0] = c(0, 0) = (0, 0, 0), grid[36][36] = c(1, 1) = (2, 4, 0)
    // compared as numbers: serde_json (arbitrary_precision) keeps a number as written, 2.00000
    let corner: Vec<f64> = s["grid"][36][36]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    assert_eq!(corner, [2.0, 4.0, 0.0]);
    assert_eq!(d["curves"].as_array().unwrap().len(), 4);
    assert_eq!(d["curves"][0]["polygon_text"][1], "(1/2, 0, 2)");
    // the key lists the exact mesh too
    assert!(page.contains("(1/2, 0, 2)  (1/2, 5/6, 31/6)  (1/2, 3, 3)"));
}

#[test]
fn sphere_weights_are_exact_in_the_page() {
    let page = to_html(&scenes::sphere_scene(), &HtmlOptions::default()).unwrap();
    let d = data(&page);
    let w = &d["surfaces"][0]["weights_text"];
    assert_eq!(w[1], serde_json::json!(["√2/2", "1/2", "√2/2"]));
    assert!(page.contains("weights 1, √2/2, 1"));
}

#[test]
fn names_cannot_break_out_of_the_page() {
    let mut scene = scenes::ruled_scene();
    scene.surfaces[0].name = "</script><b>x</b>".into();
    let page = to_html(&scene, &HtmlOptions::default()).unwrap();
    assert_eq!(
        page.matches("</script>").count(),
        2,
        "only the two script elements end"
    );
    assert_eq!(data(&page)["surfaces"][0]["name"], "</script><b>x</b>");
    assert!(page.contains("&lt;/script&gt;&lt;b&gt;x&lt;/b&gt;"));
    let empty = Scene::<cagd_scalar::BigRational>::new();
    assert_eq!(
        to_html(&empty, &HtmlOptions::default()).unwrap_err(),
        RenderError::EmptyScene
    );
}

#[test]
fn the_page_speaks_the_language_asked_and_keeps_the_problem_text_escaped() {
    let mut scene = scenes::sphere_scene();
    scene.title = Some("<i>R</i> & \"octante\"".into());
    let es = HtmlOptions {
        lang: cagd_words::Lang::Es,
        ..HtmlOptions::default()
    };
    let page = to_html(&scene, &es).unwrap();
    assert!(page.contains("<html lang=\"es\">"));
    for words in [
        "> superficie</label>",
        "> malla de control</label>",
        "> borde</label>",
        "> curvas</label>",
        "> ejes</label>",
        "Arrastre para girar",
        "pesos 1, √2/2, 1",
    ] {
        assert!(page.contains(words), "{words}");
    }
    for english in [
        ">Drag to rotate",
        "  weights",
        "> surface</label>",
        "lang=\"en\"",
    ] {
        assert!(!page.contains(english), "{english}");
    }
    // the ids the viewer reads stay as they are, the problem's text stays data
    assert!(page.contains("id=\"show-mesh\""));
    assert!(page.contains("<title>&lt;i&gt;R&lt;/i&gt; &amp; &quot;octante&quot;</title>"));
    assert_eq!(page.matches("</script>").count(), 2);
    let en = to_html(&scene, &HtmlOptions::default()).unwrap();
    assert!(en.contains("<html lang=\"en\">") && en.contains("> control mesh</label>"));
    // a scene without a title: the page's own words
    scene.title = None;
    assert!(to_html(&scene, &es)
        .unwrap()
        .contains("<title>figura de cagd-exact</title>"));
}
