//! The HTML page in a real browser: headless Chromium loads it, the canvas is not blank, and
//! a rotation (a different `#azimuth=` in the URL) changes the picture. Skipped, with a
//! message, when Chromium is not installed, unless `CAGD_REQUIRE_BROWSER=1` (set by
//! `tests/browser_check.sh`), which makes a missing browser a failure.

use crate::debug_out::out_dir;
use crate::scenes;
use cagd_render::{to_html, HtmlOptions};
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

fn find_chromium() -> Option<PathBuf> {
    let path = std::env::var_os("PATH")?;
    for dir in std::env::split_paths(&path) {
        for name in ["chromium", "chromium-browser", "google-chrome"] {
            let p = dir.join(name);
            if p.is_file() {
                return Some(p);
            }
        }
    }
    None
}

/// Screenshot of `url` (800 x 700) into `png`, with a time limit.
fn screenshot(chromium: &Path, url: &str, png: &Path) {
    let profile = out_dir().join(format!(
        "chromium-profile-{}",
        png.file_stem().unwrap().to_string_lossy()
    ));
    let _ = std::fs::remove_file(png);
    let mut child = Command::new(chromium)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--no-first-run",
            "--hide-scrollbars",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .arg(format!("--screenshot={}", png.display()))
        .arg("--window-size=840,760")
        .arg(url)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("chromium starts");
    let deadline = Instant::now() + Duration::from_secs(90);
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            assert!(status.success(), "chromium failed: {status}");
            break;
        }
        if Instant::now() > deadline {
            let _ = child.kill();
            let _ = child.wait();
            panic!("chromium did not finish within 90 s");
        }
        std::thread::sleep(Duration::from_millis(100));
    }
    assert!(png.exists(), "no screenshot written to {}", png.display());
}

/// Pixels of the canvas area that are neither white nor the page's grey text: drawn.
fn drawn_pixels(p: &resvg::tiny_skia::Pixmap) -> Vec<(u32, u32, [u8; 3])> {
    let mut out = Vec::new();
    for y in 0..p.height() {
        for x in 0..p.width() {
            let px = p.pixel(x, y).unwrap();
            let c = [px.red(), px.green(), px.blue()];
            if c.iter().any(|v| *v < 235) {
                out.push((x, y, c));
            }
        }
    }
    out
}

#[test]
fn html_page_draws_and_rotates_in_a_browser() {
    let Some(chromium) = find_chromium() else {
        if std::env::var("CAGD_REQUIRE_BROWSER").is_ok_and(|v| v == "1") {
            panic!("CAGD_REQUIRE_BROWSER=1 but chromium is not installed");
        }
        eprintln!("skipped: chromium is not installed (apt-get install -y chromium)");
        return;
    };
    let page = to_html(&scenes::coons_scene(), &HtmlOptions::default()).unwrap();
    let file = out_dir().join("coons.html");
    std::fs::write(&file, &page).unwrap();
    let url = format!("file://{}", file.display());
    let (a, b) = (
        out_dir().join("browser-a.png"),
        out_dir().join("browser-b.png"),
    );
    screenshot(&chromium, &format!("{url}#azimuth=30&elevation=25"), &a);
    screenshot(&chromium, &format!("{url}#azimuth=120&elevation=40"), &b);
    let pa = resvg::tiny_skia::Pixmap::load_png(&a).unwrap();
    let pb = resvg::tiny_skia::Pixmap::load_png(&b).unwrap();
    let da = drawn_pixels(&pa);
    let total = (pa.width() * pa.height()) as usize;
    assert!(
        da.len() > total / 20,
        "the canvas looks blank: {} drawn pixels",
        da.len()
    );
    // the surface is blue, the mesh red: both are on the canvas
    let blue = da
        .iter()
        .filter(|(_, _, c)| u16::from(c[2]) > u16::from(c[0]) + 40)
        .count();
    let red = da
        .iter()
        .filter(|(_, _, c)| c[0] > 150 && c[1] < 90 && c[2] < 90)
        .count();
    assert!(
        blue > total / 40,
        "no surface on the canvas ({blue} bluish pixels)"
    );
    assert!(red > 100, "no mesh on the canvas ({red} red pixels)");
    let differ = pa
        .pixels()
        .iter()
        .zip(pb.pixels())
        .filter(|(x, y)| x != y)
        .count();
    assert!(differ > total / 50, "rotating changed only {differ} pixels");
}

/// Runs chromium with `--dump-dom` and returns the DOM after the scripts ran.
fn dump_dom(chromium: &Path, url: &str) -> String {
    let profile = out_dir().join("chromium-profile-dom");
    let out = Command::new(chromium)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--no-first-run",
            "--window-size=840,760",
            "--dump-dom",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .arg(url)
        .stderr(std::process::Stdio::null())
        .output()
        .expect("chromium runs");
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// Hovering: a script sweeps the mouse over the canvas and records the tooltips it shows; the
/// tooltip of the inner control point c1,1 of the Coons patch reads its exact coordinates.
#[test]
fn hovering_a_control_point_shows_it_exactly() {
    let Some(chromium) = find_chromium() else {
        if std::env::var("CAGD_REQUIRE_BROWSER").is_ok_and(|v| v == "1") {
            panic!("CAGD_REQUIRE_BROWSER=1 but chromium is not installed");
        }
        eprintln!("skipped: chromium is not installed (apt-get install -y chromium)");
        return;
    };
    let page = to_html(&scenes::coons_scene(), &HtmlOptions::default()).unwrap();
    let sweep = r#"<script>
(function () {
  var c = document.getElementById("view"), r = c.getBoundingClientRect(), tip = document.getElementById("tip");
  var seen = {};
  for (var y = 0; y < r.height; y += 2) {
    for (var x = 0; x < r.width; x += 2) {
      c.dispatchEvent(new MouseEvent("mousemove", { clientX: r.left + x, clientY: r.top + y, bubbles: true }));
      if (tip.style.display === "block") { seen[tip.textContent] = true; }
    }
  }
  var out = document.createElement("pre");
  out.id = "hover-log";
  out.textContent = Object.keys(seen).sort().join("\n");
  document.body.appendChild(out);
})();
</script>
</body>"#;
    let page = page.replace("</body>", sweep);
    let file = out_dir().join("coons-hover.html");
    std::fs::write(&file, page).unwrap();
    let dom = dump_dom(&chromium, &format!("file://{}", file.display()));
    let log = dom
        .split("<pre id=\"hover-log\">")
        .nth(1)
        .and_then(|s| s.split("</pre>").next())
        .unwrap_or_else(|| panic!("no hover log in the DOM: {}", &dom[..dom.len().min(400)]));
    assert!(
        log.contains("Coons patch: c1,1 = (1/2, 5/6, 31/6)"),
        "hover log: {log}"
    );
    assert!(log.contains("c1: b1 = (1/2, 0, 2)"), "hover log: {log}");
}
