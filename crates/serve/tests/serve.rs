//! `cagd serve`'s routes end to end, on the router itself (tower's `oneshot`, no network):
//! each route's answer, and each hostile request refused.

#![allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::indexing_slicing,
    clippy::panic
)]

use axum::body::{to_bytes, Body};
use axum::http::{HeaderMap, Request, StatusCode};
use axum::Router;
use cagd_diagnose::Key;
use cagd_problem::{Limits, Problem, Settings};
use cagd_serve::{prepare, Config, Reveal, Set};
use serde_json::{json, Value};
use tower::ServiceExt;

/// The Bézier Coons patch of the notes (chapter 6, eq. (18)-(19)).
fn coons() -> Value {
    let (_, text) = cagd_fixtures::FIXTURES
        .iter()
        .find(|(path, _)| path.ends_with("07-coons-bezier.json"))
        .copied()
        .unwrap();
    serde_json::from_str(text).unwrap()
}

fn set_of(problems: Vec<Value>) -> Set {
    Set::from_json(&Value::Array(problems))
}

fn config() -> Config {
    Config {
        workers: 2,
        queue: 8,
        ..Config::default()
    }
}

fn router(set: &Set, config: &Config) -> Router {
    prepare(set, config).unwrap().router
}

struct Answer {
    status: StatusCode,
    headers: HeaderMap,
    body: Vec<u8>,
}

impl Answer {
    fn json(&self) -> Value {
        serde_json::from_slice(&self.body)
            .unwrap_or_else(|e| panic!("{e}: {}", String::from_utf8_lossy(&self.body)))
    }

    fn text(&self) -> String {
        String::from_utf8_lossy(&self.body).into_owned()
    }
}

async fn call(router: &Router, req: Request<Body>) -> Answer {
    let res = router.clone().oneshot(req).await.unwrap();
    let status = res.status();
    let headers = res.headers().clone();
    let body = to_bytes(res.into_body(), usize::MAX)
        .await
        .unwrap()
        .to_vec();
    Answer {
        status,
        headers,
        body,
    }
}

async fn get(router: &Router, uri: &str) -> Answer {
    call(router, Request::get(uri).body(Body::empty()).unwrap()).await
}

async fn post(router: &Router, uri: &str, body: &Value) -> Answer {
    let req = Request::post(uri)
        .header("content-type", "application/json")
        .body(Body::from(body.to_string()))
        .unwrap();
    call(router, req).await
}

async fn post_form(router: &Router, uri: &str, fields: &[(&str, &str)]) -> Answer {
    let body: Vec<String> = fields
        .iter()
        .map(|(k, v)| format!("{k}={}", encode(v)))
        .collect();
    let req = Request::post(uri)
        .header("content-type", "application/x-www-form-urlencoded")
        .body(Body::from(body.join("&")))
        .unwrap();
    call(router, req).await
}

fn encode(s: &str) -> String {
    s.bytes()
        .map(|b| match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' => char::from(b).to_string(),
            b => format!("%{b:02X}"),
        })
        .collect()
}

/// The key of a problem, as the server computes it.
fn key_of(problem: &Value) -> Key {
    let p = Problem::read(problem, &Limits::DEFAULT).unwrap();
    Key::new(
        &p,
        &Settings {
            limits: Limits::DEFAULT,
            steps: true,
        },
    )
}

/// A key's results as the answer object of `/api/check` (every number as its text).
fn answer_of(result: &[(cagd_problem::Quantity, cagd_problem::Exact)]) -> Value {
    Value::Object(
        result
            .iter()
            .map(|(q, x)| (q.name().into_owned(), x.to_json()))
            .collect(),
    )
}

/// Every `*_html` field of a JSON answer, at any depth.
fn html_fields(v: &Value, out: &mut Vec<String>) {
    match v {
        Value::Object(o) => {
            for (k, x) in o {
                match (k.ends_with("_html"), x) {
                    (true, Value::String(s)) => out.push(s.clone()),
                    _ => html_fields(x, out),
                }
            }
        }
        Value::Array(xs) => xs.iter().for_each(|x| html_fields(x, out)),
        _ => {}
    }
}

#[tokio::test]
async fn the_set_in_spanish_and_english() {
    let r = router(&set_of(vec![coons()]), &config());
    let es = get(&r, "/api/set?lang=es").await;
    assert_eq!(es.status, StatusCode::OK);
    let es = es.json();
    assert_eq!(es["lang"], "es");
    assert_eq!(es["reveal"], "never");
    assert_eq!(es["title"], "Hoja de problemas");
    assert_eq!(es["words"]["check"], "Comprobar");
    let p = &es["problems"][0];
    assert_eq!(p["index"], 0);
    assert!(
        p["title"].as_str().unwrap().starts_with("Problema 1"),
        "{p}"
    );
    let statement = p["statement_html"].as_str().unwrap();
    assert!(
        statement.contains("la curva de Bézier de polígono de control"),
        "{statement}"
    );
    assert!(
        statement.contains("class=\"math\" data-tex="),
        "{statement}"
    );
    assert_eq!(p["figure"], "/api/figure/0.svg");
    let result = &p["results"][0];
    assert_eq!(result["key"], "surface");
    assert_eq!(
        result["template"]["bezier"][0][0][0],
        json!({"cell": "c_0,0", "kind": "number", "name": {"en": "c_0,0", "es": "c_0,0"}})
    );
    let en = get(&r, "/api/set?lang=en").await.json();
    assert_eq!(en["title"], "Problem sheet");
    assert_eq!(en["words"]["check"], "Check");
    assert!(en["problems"][0]["statement_html"]
        .as_str()
        .unwrap()
        .contains("Bézier curve of control polygon"));
}

#[tokio::test]
async fn the_figure_is_the_data() {
    let r = router(&set_of(vec![coons()]), &config());
    let svg = get(&r, "/api/figure/0.svg").await;
    assert_eq!(svg.status, StatusCode::OK);
    assert_eq!(svg.headers["content-type"], "image/svg+xml");
    assert!(svg.text().contains("<svg"), "{}", svg.text());
    assert_eq!(
        get(&r, "/api/figure/1.svg").await.status,
        StatusCode::NOT_FOUND
    );
    assert_eq!(
        get(&r, "/api/figure/x.svg").await.status,
        StatusCode::NOT_FOUND
    );
}

#[tokio::test]
async fn a_cell_read_and_a_cell_refused() {
    let r = router(&set_of(vec![coons()]), &config());
    let ok = post(
        &r,
        "/api/read",
        &json!({"problem": 0, "text": "5/6", "kind": "number"}),
    )
    .await;
    assert_eq!(ok.status, StatusCode::OK);
    assert_eq!(ok.json(), json!({"ok": true, "tex": "\\frac{5}{6}"}));
    let root = post(
        &r,
        "/api/read",
        &json!({"problem": 0, "text": "sqrt2/2", "kind": "number"}),
    )
    .await;
    assert_eq!(root.json()["ok"], true, "{}", root.text());
    let expr = post(
        &r,
        "/api/read",
        &json!({"problem": 0, "text": "(u, v^2, 1/2)", "kind": "expression"}),
    )
    .await;
    assert_eq!(expr.json()["ok"], true, "{}", expr.text());
    let bad_en = post(
        &r,
        "/api/read",
        &json!({"problem": 0, "text": "5/", "kind": "number", "lang": "en"}),
    )
    .await;
    let bad_es = post(
        &r,
        "/api/read",
        &json!({"problem": 0, "text": "5/", "kind": "number", "lang": "es"}),
    )
    .await;
    assert_eq!(bad_en.json()["ok"], false);
    let (en, es) = (
        bad_en.json()["error"].clone(),
        bad_es.json()["error"].clone(),
    );
    assert!(en.as_str().is_some_and(|e| !e.is_empty()));
    assert_ne!(en, es, "the grammar's message in each language");
    let unknown = post(
        &r,
        "/api/read",
        &json!({"problem": 7, "text": "1", "kind": "number"}),
    )
    .await;
    assert_eq!(unknown.status, StatusCode::BAD_REQUEST);
    assert!(unknown.json()["error"].is_string());
}

#[tokio::test]
async fn a_right_answer_is_correct_with_every_mark_right() {
    let problem = coons();
    let key = key_of(&problem);
    let answer = answer_of(&key.answer.as_ref().unwrap().result);
    let r = router(&set_of(vec![problem]), &config());
    let out = post(
        &r,
        "/api/check",
        &json!({"problem": 0, "answer": answer, "lang": "es"}),
    )
    .await;
    assert_eq!(out.status, StatusCode::OK);
    let v = out.json();
    assert_eq!(v["verdict"], "correct", "{v}");
    assert_eq!(v["score"], "1");
    let marks = v["marks"].as_array().unwrap();
    assert!(!marks.is_empty());
    assert!(marks.iter().all(|m| m["right"] == true), "{v}");
    assert!(marks.iter().any(|m| m["cell"] == "c_1,2"), "{v}");
    assert_eq!(v["diagnoses"], json!([]));
    assert!(
        v["summary"].as_str().unwrap().starts_with("Correcto"),
        "{v}"
    );
    assert!(v["report_html"].as_str().unwrap().contains("<"), "{v}");
    assert_eq!(v["solution_html"], Value::Null);
}

#[tokio::test]
async fn the_results_left_empty_are_named_as_the_page_names_them() {
    let problem = coons();
    let key = key_of(&problem);
    let mut answer = answer_of(&key.answer.as_ref().unwrap().result);
    let written: Vec<String> = answer.as_object().unwrap().keys().cloned().collect();
    assert!(written.len() > 1, "{answer}");
    // only the first result written: the others are said by their labels, never their keys
    answer
        .as_object_mut()
        .unwrap()
        .retain(|k, _| *k == written[0]);
    let r = router(&set_of(vec![problem]), &config());
    let set = get(&r, "/api/set?lang=es").await.json();
    let v = post(
        &r,
        "/api/check",
        &json!({"problem": 0, "answer": answer, "lang": "es"}),
    )
    .await
    .json();
    assert_eq!(v["verdict"], "wrong", "{v}");
    let summary = v["summary"].as_str().unwrap();
    for result in set["problems"][0]["results"]
        .as_array()
        .unwrap()
        .iter()
        .skip(1)
    {
        let (key, label) = (
            result["key"].as_str().unwrap(),
            result["label"].as_str().unwrap(),
        );
        assert!(summary.contains(label), "{label}: {summary}");
        if key != label {
            assert!(!summary.contains(key), "{key}: {summary}");
        }
    }
}

#[tokio::test]
async fn a_known_mistake_is_diagnosed() {
    let problem = coons();
    let key = key_of(&problem);
    let (_, mistaken) = key
        .mistaken
        .iter()
        .find(|(m, _)| cagd_problem::Catalogued::id(m) == "coons.cd_added")
        .expect("the Coons patch has the mistake c_cd added");
    let answer = answer_of(&mistaken.result);
    let config = Config {
        reveal: Reveal::AfterCheck,
        ..config()
    };
    let r = router(&set_of(vec![problem]), &config);
    let v = post(
        &r,
        "/api/check",
        &json!({"problem": 0, "answer": answer, "lang": "en"}),
    )
    .await
    .json();
    assert_eq!(v["verdict"], "wrong", "{v}");
    let ids: Vec<&str> = v["diagnoses"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|d| d["id"].as_str())
        .collect();
    assert!(ids.contains(&"coons.cd_added"), "{v}");
    let d = &v["diagnoses"][0];
    assert!(d["said"].as_str().is_some_and(|s| !s.is_empty()));
    assert!(
        d["place"].as_str().is_some_and(|s| s.contains("Chapter 6")),
        "{d}"
    );
    assert!(v["marks"]
        .as_array()
        .unwrap()
        .iter()
        .any(|m| m["right"] == false));
    assert!(v["score"].as_str().is_some());
    assert!(
        v["report_html"]
            .as_str()
            .unwrap()
            .contains("coons.cd_added"),
        "{v}"
    );
    assert!(
        v["solution_html"].as_str().is_some_and(|s| s.len() > 100),
        "{v}"
    );
    // without the key revealed, the report names the wrong entries with the student's values
    // only
    let r = router(&set_of(vec![coons()]), &config_never());
    let v = post(
        &r,
        "/api/check",
        &json!({"problem": 0, "answer": answer, "lang": "en"}),
    )
    .await
    .json();
    let report = v["report_html"].as_str().unwrap();
    println!("{report}");
    assert!(!report.contains("key "), "{report}");
    assert!(report.contains("coons.cd_added"), "{report}");
    assert_eq!(v["solution_html"], Value::Null);
}

fn config_never() -> Config {
    Config {
        reveal: Reveal::Never,
        ..config()
    }
}

#[tokio::test]
async fn a_malformed_cell_is_a_clear_error() {
    let problem = coons();
    let key = key_of(&problem);
    let mut answer = answer_of(&key.answer.as_ref().unwrap().result);
    answer["surface"]["bezier"][1][2][0] = json!("1/");
    let r = router(&set_of(vec![problem]), &config());
    // in Spanish the result is named as the page names it, never by its JSON key
    let es = post(
        &r,
        "/api/check",
        &json!({"problem": 0, "answer": answer, "lang": "es"}),
    )
    .await
    .json();
    let summary = es["summary"].as_str().unwrap();
    assert!(summary.contains("superficie, c_1,2"), "{summary}");
    assert!(!summary.contains("surface"), "{summary}");
    let v = post(
        &r,
        "/api/check",
        &json!({"problem": 0, "answer": answer, "lang": "en"}),
    )
    .await
    .json();
    assert_eq!(v["verdict"], "unreadable", "{v}");
    assert_eq!(v["errors"][0]["cell"], "c_1,2", "{v}");
    assert_eq!(v["errors"][0]["result"], "surface", "{v}");
    let summary = v["summary"].as_str().unwrap();
    assert!(summary.contains("c_1,2"), "{summary}");
    // a cell left empty beside written ones
    let mut partly = answer.clone();
    partly["surface"]["bezier"][1][2][0] = json!("");
    let v = post(
        &r,
        "/api/check",
        &json!({"problem": 0, "answer": partly, "lang": "en"}),
    )
    .await
    .json();
    assert_eq!(v["verdict"], "unreadable", "{v}");
    assert_eq!(v["errors"][0]["cell"], "c_1,2", "{v}");
    assert!(
        v["errors"][0]["message"]
            .as_str()
            .unwrap()
            .contains("left empty"),
        "{v}"
    );
    // a result left wholly empty is not checked
    let mut empty = answer.clone();
    for (_, v) in empty.as_object_mut().unwrap() {
        *v = json!({"bezier": [[["", " "]]]});
    }
    let v = post(&r, "/api/check", &json!({"problem": 0, "answer": empty}))
        .await
        .json();
    assert_eq!(v["verdict"], "unreadable", "{v}");
    assert!(v["summary"].as_str().unwrap().contains("empty"), "{v}");
    // an answer that is not an object, a key that is not a result
    let v = post(&r, "/api/check", &json!({"problem": 0, "answer": [1]}))
        .await
        .json();
    assert_eq!(v["verdict"], "unreadable", "{v}");
    let v = post(
        &r,
        "/api/check",
        &json!({"problem": 0, "answer": {"nope": 1}}),
    )
    .await
    .json();
    assert_eq!(v["verdict"], "unreadable", "{v}");
    // JSON that does not read
    let req = Request::post("/api/check")
        .body(Body::from("{not json"))
        .unwrap();
    let bad = call(&r, req).await;
    assert_eq!(bad.status, StatusCode::BAD_REQUEST);
    assert!(bad.json()["error"].is_string());
}

#[tokio::test]
async fn a_body_of_ten_megabytes_is_refused() {
    let r = router(&set_of(vec![coons()]), &config());
    let big = vec![b' '; 10 * 1024 * 1024];
    let req = Request::post("/api/check")
        .header("content-type", "application/json")
        .body(Body::from(big))
        .unwrap();
    let out = call(&r, req).await;
    assert_eq!(out.status, StatusCode::PAYLOAD_TOO_LARGE);
    assert!(out.json()["error"].as_str().unwrap().contains("256"));
}

#[tokio::test]
async fn a_problem_past_a_limit_is_an_error_at_its_path() {
    let small = Config {
        limits: Limits {
            max_degree: 3,
            ..Limits::DEFAULT
        },
        ..config()
    };
    let r = router(&set_of(vec![coons()]), &small);
    let problem = json!({"op": "elevate", "curve": {"bezier": [[0, 0], [1, 1], [2, 0], [3, 1], [4, 0], [5, 1]]}, "by": 1});
    let v = post(
        &r,
        "/api/teacher/solve",
        &json!({"problem": problem, "lang": "en"}),
    )
    .await
    .json();
    assert_eq!(v["ok"], false, "{v}");
    let e = &v["errors"][0];
    assert!(
        e["path"].as_str().is_some_and(|p| p.starts_with("curve")),
        "{v}"
    );
    assert!(
        e["message"].as_str().is_some_and(|m| m.contains('3')),
        "{v}"
    );
    // the same problem under the default limits is solved
    let r = router(&set_of(vec![coons()]), &config());
    let v = post(
        &r,
        "/api/teacher/solve",
        &json!({"problem": problem, "lang": "es"}),
    )
    .await
    .json();
    assert_eq!(v["ok"], true, "{v}");
    assert!(v["key_html"].as_str().unwrap().contains("data-tex"));
    assert!(v["statement_html"].as_str().unwrap().contains("<p>"));
}

#[tokio::test]
async fn a_script_in_a_title_is_text() {
    let mut problem = coons();
    problem["title"] = json!("<script>alert(1)</script>");
    problem["es"]["title"] = json!("<script>alert(1)</script>");
    problem["note"] = json!("<img src=x onerror=alert(1)> $\\input{x}$");
    let key = key_of(&problem);
    let answer = answer_of(&key.answer.as_ref().unwrap().result);
    let r = router(&set_of(vec![problem.clone()]), &config());
    let mut htmls = Vec::new();
    for lang in ["en", "es"] {
        let set = get(&r, &format!("/api/set?lang={lang}")).await.json();
        // the title is plain text (the page sets it with textContent)
        assert!(set["problems"][0]["title"]
            .as_str()
            .unwrap()
            .contains("<script>"));
        html_fields(&set, &mut htmls);
        let checked = post(
            &r,
            "/api/check",
            &json!({"problem": 0, "answer": answer, "lang": lang}),
        )
        .await
        .json();
        html_fields(&checked, &mut htmls);
        let solved = post(
            &r,
            "/api/teacher/solve",
            &json!({"problem": problem, "lang": lang}),
        )
        .await
        .json();
        html_fields(&solved, &mut htmls);
    }
    assert!(htmls.len() >= 6);
    for h in &htmls {
        assert!(!h.contains("<script"), "{h}");
        assert!(!h.contains("<img"), "{h}");
    }
    assert!(
        htmls.iter().any(|h| h.contains("&lt;script&gt;")),
        "the title is shown, escaped"
    );
}

#[tokio::test]
async fn a_path_in_a_url_opens_nothing() {
    let r = router(&set_of(vec![coons()]), &config());
    for uri in [
        "/assets/../../etc/passwd",
        "/assets/%2e%2e%2fCargo.toml",
        "/assets/..%2f..%2fCargo.toml",
        "/assets/katex/../../../Cargo.toml",
        "/assets/",
        "/etc/passwd",
    ] {
        let out = get(&r, uri).await;
        assert_eq!(out.status, StatusCode::NOT_FOUND, "{uri}");
        assert!(out.json()["error"].is_string(), "{uri}");
    }
    let js = get(&r, "/assets/student.js").await;
    assert_eq!(js.status, StatusCode::OK);
    assert_eq!(js.headers["content-type"], "text/javascript; charset=utf-8");
    assert!(js.headers.contains_key("cache-control"));
    let css = get(&r, "/assets/katex/katex.min.css").await;
    assert_eq!(css.headers["content-type"], "text/css; charset=utf-8");
}

#[tokio::test]
async fn busy_when_every_worker_is_taken_and_no_one_may_wait() {
    let config = Config {
        workers: 1,
        queue: 0,
        ..config()
    };
    let prepared = prepare(&set_of(vec![coons()]), &config).unwrap();
    let held = prepared.pool.try_hold().expect("a free worker");
    let r = prepared.router;
    let out = post(
        &r,
        "/api/read",
        &json!({"problem": 0, "text": "1", "kind": "number"}),
    )
    .await;
    assert_eq!(out.status, StatusCode::SERVICE_UNAVAILABLE);
    assert_eq!(out.json()["error"], "busy");
    assert!(out.json()["message"].is_string());
    drop(held);
    let out = post(
        &r,
        "/api/read",
        &json!({"problem": 0, "text": "1", "kind": "number"}),
    )
    .await;
    assert_eq!(out.status, StatusCode::OK);
}

#[tokio::test]
async fn every_response_has_the_security_headers() {
    let r = router(&set_of(vec![coons()]), &config());
    for uri in ["/", "/teacher", "/api/set", "/nowhere", "/assets/page.css"] {
        let out = get(&r, uri).await;
        let csp = out.headers["content-security-policy"].to_str().unwrap();
        assert!(csp.contains("default-src 'self'"), "{uri}: {csp}");
        assert!(csp.contains("frame-ancestors 'self'"), "{uri}: {csp}");
        assert!(csp.contains("object-src 'none'"), "{uri}: {csp}");
        // no script but the pages' own files: never inline, never evaluated
        let script = csp.split(';').find(|d| d.trim().starts_with("script-src"));
        assert_eq!(
            script.map(str::trim),
            Some("script-src 'self'"),
            "{uri}: {csp}"
        );
        assert_eq!(out.headers["x-content-type-options"], "nosniff", "{uri}");
        assert_eq!(out.headers["referrer-policy"], "no-referrer", "{uri}");
    }
    let page = get(&r, "/").await;
    assert_eq!(page.headers["content-type"], "text/html; charset=utf-8");
}

#[tokio::test]
async fn the_teachers_pages_behind_the_token() {
    let config = Config {
        token: Some("s3cret".into()),
        ..config()
    };
    let r = router(&set_of(vec![coons()]), &config);
    assert_eq!(get(&r, "/teacher").await.status, StatusCode::FORBIDDEN);
    assert_eq!(
        get(&r, "/teacher?token=wrong").await.status,
        StatusCode::FORBIDDEN
    );
    assert_eq!(
        get(&r, "/teacher?token=s3cret").await.status,
        StatusCode::OK
    );
    let solve = json!({"problem": coons(), "lang": "en"});
    assert_eq!(
        post(&r, "/api/teacher/solve", &solve).await.status,
        StatusCode::FORBIDDEN
    );
    let req = Request::post("/api/teacher/solve")
        .header("x-cagd-token", "s3cret")
        .body(Body::from(solve.to_string()))
        .unwrap();
    let out = call(&r, req).await;
    assert_eq!(out.status, StatusCode::OK);
    assert_eq!(out.json()["ok"], true);
    // beyond the loopback without a token: off, and the report says so
    let open = Config {
        bind: "0.0.0.0:8080".parse().unwrap(),
        ..config.clone()
    };
    let off = Config {
        token: None,
        ..open
    };
    let prepared = prepare(&set_of(vec![coons()]), &off).unwrap();
    assert_eq!(
        get(&prepared.router, "/teacher").await.status,
        StatusCode::NOT_FOUND
    );
    assert_eq!(
        post(&prepared.router, "/api/teacher/solve", &solve)
            .await
            .status,
        StatusCode::NOT_FOUND
    );
}

#[tokio::test]
async fn a_bad_problem_is_left_out_and_named() {
    let bad = json!({"name": "broken", "op": "coons", "c1": {"bezier": [[0, 0, 0]]}});
    let prepared = prepare(&set_of(vec![bad, coons()]), &config()).unwrap();
    assert!(
        prepared.report.iter().any(|l| l.contains("broken")),
        "{:?}",
        prepared.report
    );
    let set = get(&prepared.router, "/api/set").await.json();
    assert_eq!(set["problems"].as_array().unwrap().len(), 1);
}

#[tokio::test]
async fn the_teachers_preview_figure_and_downloads() {
    let r = router(&set_of(vec![coons()]), &config());
    let preview = post(
        &r,
        "/api/teacher/preview",
        &json!({"set": {"title": "Hoja 3", "problems": [coons()]}, "lang": "es"}),
    )
    .await
    .json();
    assert_eq!(preview["ok"], true, "{preview}");
    assert_eq!(preview["title"], "Hoja 3");
    assert!(preview["problems"][0]["figure"]
        .as_str()
        .unwrap()
        .starts_with("data:image/svg+xml;base64,"));
    let bad = post(
        &r,
        "/api/teacher/preview",
        &json!({"set": [coons(), {"op": "coons"}], "lang": "en"}),
    )
    .await
    .json();
    assert_eq!(bad["ok"], false, "{bad}");
    assert!(
        bad["errors"][0]["path"]
            .as_str()
            .unwrap()
            .starts_with("[1]"),
        "{bad}"
    );

    let problem = coons().to_string();
    let figure = post_form(
        &r,
        "/teacher/figure",
        &[("problem", &problem), ("lang", "es")],
    )
    .await;
    assert_eq!(figure.status, StatusCode::OK);
    let csp = figure.headers["content-security-policy"].to_str().unwrap();
    assert!(csp.contains("script-src 'sha256-"), "{csp}");
    assert!(csp.contains("sandbox allow-scripts"), "{csp}");
    assert!(figure.text().contains("<canvas"));

    let key = post_form(
        &r,
        "/teacher/download",
        &[("problem", &problem), ("what", "key"), ("lang", "es")],
    )
    .await;
    assert_eq!(key.status, StatusCode::OK);
    assert!(key.headers["content-disposition"]
        .to_str()
        .unwrap()
        .contains("key.tex"));
    assert!(key.text().contains("\\documentclass"));
    let sheet = post_form(
        &r,
        "/teacher/download",
        &[("problem", &problem), ("what", "sheet"), ("lang", "es")],
    )
    .await;
    assert!(sheet.headers["content-disposition"]
        .to_str()
        .unwrap()
        .contains("sheet.tex"));
    assert!(sheet.text().contains("Nombre y apellidos"));
    let neither = post_form(
        &r,
        "/teacher/download",
        &[("problem", &problem), ("what", "x")],
    )
    .await;
    assert_eq!(neither.status, StatusCode::BAD_REQUEST);
}
