"""The pages of `cagd serve` as a student and a teacher meet them: Debian's Chromium, headless,
driven by Playwright (its Python package, never its own browser download), against the real
`cagd` binary serving the Coons report's problem and the notes' examples.

    CAGD_BIN=target/release/cagd pytest crates/serve/tests/browser

Screenshots go to $CAGD_SCREENSHOTS (default: a temporary folder), for a person to look at.
"""
import json
import os
import shutil
import socket
import subprocess
import tempfile
import time
import urllib.request

import pytest
from PIL import Image
from playwright.sync_api import sync_playwright

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", "..", "..", ".."))
REPORTS = os.path.join(ROOT, "crates", "diagnose", "tests", "reports")
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser") or "/usr/bin/chromium"
ARGS = ["--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
        "--disable-component-update", "--disable-sync"]


def cagd_bin():
    b = os.environ.get("CAGD_BIN") or os.path.join(ROOT, "target", "release", "cagd")
    if not os.path.exists(b):
        pytest.skip(f"no cagd binary at {b} (set CAGD_BIN)")
    return b


def free_port():
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    p = s.getsockname()[1]
    s.close()
    return p


def start(args):
    port = free_port()
    proc = subprocess.Popen([cagd_bin(), "serve", *args, "--port", str(port)], stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True)
    base = f"http://127.0.0.1:{port}"
    for _ in range(300):
        try:
            urllib.request.urlopen(base + "/api/set", timeout=2).read()
            return proc, base
        except OSError:
            if proc.poll() is not None:
                raise RuntimeError("cagd serve stopped: " + proc.stdout.read())
            time.sleep(0.1)
    proc.kill()
    raise RuntimeError("cagd serve did not answer")


@pytest.fixture(scope="module")
def coons_report():
    return json.load(open(os.path.join(REPORTS, "coons.json")))


@pytest.fixture(scope="module")
def server(coons_report, tmp_path_factory):
    d = tmp_path_factory.mktemp("set")
    problem = {k: v for k, v in coons_report.items() if k not in ("expected", "student")}
    # a title that tries to run a script: shown as text, never run
    problem["title"] = problem["title"] + " <script>window.pwned = 1</script>"
    problem["es"] = {"title": problem["es"]["title"] + " <script>window.pwned = 1</script>"}
    path = d / "set.json"
    path.write_text(json.dumps([problem]))
    proc, base = start([str(path), "--reveal", "after-check"])
    key = json.loads(subprocess.run([cagd_bin(), "solve", str(path), "--format", "json"], check=True,
                                    capture_output=True, text=True).stdout)[0]["result"]
    yield base, key
    proc.terminate()
    proc.wait(timeout=10)


@pytest.fixture(scope="module")
def browser():
    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        yield b
        b.close()


@pytest.fixture(scope="module")
def shots():
    d = os.environ.get("CAGD_SCREENSHOTS") or tempfile.mkdtemp(prefix="cagd-serve-shots-")
    os.makedirs(d, exist_ok=True)
    return d


# the backgrounds of the marked entries (page.css: --right-bg, --wrong-bg)
RIGHT_BG = (0xE3, 0xF5, 0xEF)
WRONG_BG = (0xFD, 0xEB, 0xE3)


def assert_colour(page, selector, png, colour):
    """A screenshot of the element shows the marks' background, and not the other mark's."""
    page.locator(selector).screenshot(path=png)
    count = {c: n for n, c in Image.open(png).convert("RGB").getcolors(1 << 22)}
    other = WRONG_BG if colour == RIGHT_BG else RIGHT_BG
    assert count.get(colour, 0) > 1000, f"{png}: the marks' colour {colour} is not drawn"
    assert count.get(other, 0) == 0, f"{png}: the other mark's colour {other} is drawn"


def open_page(browser, url):
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    problems = []
    page.on("console", lambda m: problems.append(f"{m.type}: {m.text}") if m.type in ("error", "warning") else None)
    page.on("pageerror", lambda e: problems.append(f"pageerror: {e}"))
    page.goto(url)
    page.wait_for_selector("[data-problem='0'] [data-result]")
    return page, problems


def cells_of(template, answer, path, out):
    """(path, value) for each cell of the template (its path in the result, as the page's
    `data-path` writes it), with the answer's value at that place."""
    if isinstance(template, dict) and "cell" in template and "kind" in template:
        out.append((json.dumps(path, separators=(",", ":")), answer))
    elif isinstance(template, list):
        for i, (t, a) in enumerate(zip(template, answer)):
            cells_of(t, a, path + [i], out)
    elif isinstance(template, dict):
        for key, t in template.items():
            cells_of(t, answer[key], path + [key], out)
    return out


def fill(page, result, template, answer):
    for path, value in cells_of(template, answer, [], []):
        cell = page.locator(f"[data-problem='0'] [data-result='{result}'] [data-path='{path}']")
        if isinstance(value, bool):
            cell.select_option("true" if value else "false")
        else:
            cell.fill(str(value))


def template_of(page, base, lang):
    data = json.loads(urllib.request.urlopen(f"{base}/api/set?lang={lang}").read())
    return data, {r["key"]: r["template"] for r in data["problems"][0]["results"]}


def check(page):
    page.locator("[data-problem='0'] .check").click()
    page.wait_for_selector("[data-problem='0'] .verdict[data-verdict]")
    return page.locator("[data-problem='0'] .verdict").get_attribute("data-verdict")


@pytest.mark.parametrize("lang", ["es", "en"])
def test_a_right_answer_is_correct(server, browser, shots, lang):
    base, key = server
    page, problems = open_page(browser, f"{base}/?lang={lang}")
    _, templates = template_of(page, base, lang)
    for result, template in templates.items():
        fill(page, result, template, key[result])
    # the preview typesets what the engine read
    page.wait_for_selector("[data-problem='0'] .preview .katex")
    assert check(page) == "correct"
    assert page.locator("[data-problem='0'] .diagnosis").count() == 0
    # every entry of the mesh marked right (12 control points), none wrong
    surface = "[data-problem='0'] [data-result='surface']"
    assert page.locator(f"{surface} .entry[data-mark='right']").count() == 12
    assert page.locator(f"{surface} .entry[data-mark='wrong']").count() == 0
    assert_colour(page, surface, os.path.join(shots, f"mesh-right-{lang}.png"), RIGHT_BG)
    # the title's script is text on the page, never run
    assert page.evaluate("window.pwned") is None
    assert "<script>" in page.locator("[data-problem='0']").inner_text()
    page.screenshot(path=os.path.join(shots, f"right-{lang}.png"), full_page=True)
    assert problems == [], problems


@pytest.mark.parametrize("lang", ["es", "en"])
def test_a_known_mistake_is_named(server, coons_report, browser, shots, lang):
    base, _ = server
    page, problems = open_page(browser, f"{base}/?lang={lang}")
    _, templates = template_of(page, base, lang)
    fill(page, "surface", templates["surface"], coons_report["expected"]["surface"])
    assert check(page) == "wrong"
    diagnosis = page.locator("[data-problem='0'] .diagnosis").first
    assert diagnosis.get_attribute("data-id") == "coons.cd_added"
    text = page.locator("[data-problem='0']").inner_text()
    if lang == "es":
        assert "Tema 6" in text, text
    # c_cd added changes every control point: all 12 marked wrong
    surface = "[data-problem='0'] [data-result='surface']"
    assert page.locator(f"{surface} .entry[data-mark='wrong']").count() == 12
    # revealed after a check
    assert page.locator("[data-problem='0'] .solution").count() == 1
    page.screenshot(path=os.path.join(shots, f"mistake-{lang}.png"), full_page=True)
    assert_colour(page, surface, os.path.join(shots, f"mesh-wrong-{lang}.png"), WRONG_BG)
    assert problems == [], problems


@pytest.mark.parametrize("lang", ["es", "en"])
def test_a_malformed_entry_is_said_at_the_cell(server, browser, lang):
    base, key = server
    page, problems = open_page(browser, f"{base}/?lang={lang}")
    _, templates = template_of(page, base, lang)
    for result, template in templates.items():
        fill(page, result, template, key[result])
    cell = page.locator("[data-problem='0'] [data-result='surface'] [data-path='[\"bezier\",1,1,2]']")
    cell.fill("5/*")
    page.wait_for_selector("[data-problem='0'] [aria-invalid='true']")
    # the check reads every cell first: the malformed one is named, nothing is marked
    assert check(page) == "unreadable"
    assert "c_1,1" in page.locator("[data-problem='0'] .outcome").inner_text()
    assert problems == [], problems


def test_the_teacher_gets_a_key(server, browser, shots):
    base, _ = server
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    page.goto(f"{base}/teacher?lang=es")
    page.wait_for_selector("#problem")
    page.locator("#solve").click()
    page.wait_for_selector("#key .katex")
    # the interactive figure of the key, in its frame
    for _ in range(200):
        frame = page.frame(name="figure")
        if frame is not None and frame.url.endswith("/teacher/figure"):
            break
        time.sleep(0.1)
    frame.wait_for_selector("canvas")
    page.screenshot(path=os.path.join(shots, "teacher-es.png"), full_page=True)
