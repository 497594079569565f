//! The routes (API.md), the security headers every response carries, the body limit, the
//! teacher's gate, and the serving loop.

// A handler's early answer is its `Err(Response)`, made once per request: its size does not
// matter.
#![allow(clippy::result_large_err)]

use crate::assets::{self, Asset};
use crate::markdown;
use crate::message::ServeMessage;
use crate::pool::{Pool, Refused};
use crate::served::{self, Served, ServedProblem, Set};
use crate::template::CellKind;
use crate::{base64, Config, Reveal, ServeError};
use axum::body::{Body, Bytes};
use axum::extract::rejection::{BytesRejection, FormRejection};
use axum::extract::{DefaultBodyLimit, Form, Path, Query, State};
use axum::http::header::{
    CACHE_CONTROL, CONTENT_DISPOSITION, CONTENT_SECURITY_POLICY, CONTENT_TYPE, REFERRER_POLICY,
    X_CONTENT_TYPE_OPTIONS,
};
use axum::http::{HeaderMap, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use axum::routing::{get, post};
use axum::{middleware, Json, Router};
use cagd_keys::{
    error_sentence, example_latex_beside, example_markdown, latex_key_document, legend_latex,
    statement_document, statement_latex, statement_markdown, SheetHeader, Word,
};
use cagd_problem::{check_with_settings, Limits, Settings, Verdict};
use cagd_render::{inline_script, to_html, HtmlOptions, Scene};
use cagd_words::{Lang, Message};
use serde::Deserialize;
use serde_json::{json, Value};
use sha2::{Digest, Sha256};
use std::net::SocketAddr;
use std::sync::Arc;

/// The largest body a request may have.
pub const BODY_LIMIT: usize = 256 * 1024;

/// The policy of every response (API.md), unless a response sets its own: no script but the
/// pages' own files. Styles may be inline: KaTeX sets a `style` attribute on the SVG of a
/// tall delimiter or a root (`\left[`, `\sqrt`), which `style-src 'self'` would refuse (and
/// the delimiter would be drawn at the wrong width); a style runs nothing.
pub const CSP: &str = "default-src 'self'; script-src 'self'; style-src 'self' 'unsafe-inline'; img-src 'self' data:; font-src 'self'; connect-src 'self'; frame-src 'self'; object-src 'none'; base-uri 'none'; form-action 'self'; frame-ancestors 'self'";

/// The policy of a figure's SVG: its own `<style>`, nothing else.
const SVG_CSP: &str = "default-src 'none'; style-src 'unsafe-inline'; frame-ancestors 'self'";

/// Who may use the teacher's pages.
#[derive(Debug, Clone, PartialEq, Eq)]
enum Teacher {
    /// Whoever gives the token.
    Token(String),
    /// Anyone: the server listens on the loopback only.
    Open,
    /// No one: the server listens beyond the loopback and has no token.
    Off,
}

/// What the handlers share.
struct Shared {
    served: Served,
    lang: Lang,
    reveal: Reveal,
    limits: Limits,
    teacher: Teacher,
    pool: Pool,
}

type AppState = Arc<Shared>;

/// The routes, ready; the startup report (the problems left out, the teacher's pages); the
/// pool.
pub struct Prepared {
    /// The routes.
    pub router: Router,
    /// The startup report, in the server's language, one line each (without the addresses,
    /// which [`crate::run`] adds once it listens).
    pub report: Vec<String>,
    /// The pool of workers.
    pub pool: Pool,
    teacher: Teacher,
    lang: Lang,
}

/// The set read and keyed, the routes built.
pub fn prepare(set: &Set, config: &Config) -> Result<Prepared, ServeError> {
    let served = Served::new(set, &config.limits);
    let lang = config.lang;
    let mut report: Vec<String> = served
        .left_out
        .iter()
        .map(|l| {
            ServeMessage::LeftOutAtStart {
                name: l.name.clone(),
                inner: error_sentence_phrase(&l.error, lang),
            }
            .phrase(lang)
            .text()
        })
        .collect();
    report.push(
        match served.problems.len() {
            0 => ServeMessage::NoProblems,
            count => ServeMessage::Serving { count },
        }
        .phrase(lang)
        .text(),
    );
    let teacher = match (&config.token, config.bind.ip().is_loopback()) {
        (Some(t), _) => Teacher::Token(t.clone()),
        (None, true) => Teacher::Open,
        (None, false) => Teacher::Off,
    };
    let pool = Pool::new(config.workers, config.queue);
    let shared = Arc::new(Shared {
        served,
        lang,
        reveal: config.reveal,
        limits: config.limits,
        teacher: teacher.clone(),
        pool: pool.clone(),
    });
    let router = Router::new()
        .route("/", get(student_page))
        .route("/teacher", get(teacher_page))
        .route("/assets/{*name}", get(asset))
        .route("/api/set", get(api_set))
        .route("/api/figure/{file}", get(api_figure))
        .route("/api/read", post(api_read))
        .route("/api/check", post(api_check))
        .route("/api/teacher/solve", post(teacher_solve))
        .route("/api/teacher/preview", post(teacher_preview))
        .route("/teacher/figure", post(teacher_figure))
        .route("/teacher/download", post(teacher_download))
        .fallback(not_found)
        .with_state(shared)
        .layer(DefaultBodyLimit::max(BODY_LIMIT))
        .layer(middleware::map_response(security_headers));
    Ok(Prepared {
        router,
        report,
        pool,
        teacher,
        lang,
    })
}

/// An engine's error as one sentence, as the command line writes it.
fn error_sentence_phrase(e: &cagd_problem::ProblemError, lang: Lang) -> cagd_words::Phrase {
    cagd_words::Phrase::data(error_sentence(e, lang).text)
}

/// Listens on the configured address and serves until Ctrl-C.
pub async fn serve(prepared: Prepared, config: &Config) -> Result<(), ServeError> {
    let listener = tokio::net::TcpListener::bind(config.bind)
        .await
        .map_err(|e| {
            ServeError(ServeMessage::CannotBind {
                addr: config.bind.to_string(),
                error: e.to_string(),
            })
        })?;
    let addr = listener.local_addr().unwrap_or(config.bind);
    let shown = match addr.ip().is_unspecified() {
        true => SocketAddr::from(([127, 0, 0, 1], addr.port())),
        false => addr,
    };
    let lang = prepared.lang;
    let mut lines = prepared.report.clone();
    lines.push(
        ServeMessage::StudentsAt {
            url: format!("http://{shown}/"),
        }
        .phrase(lang)
        .text(),
    );
    lines.push(match &prepared.teacher {
        Teacher::Token(t) => ServeMessage::TeacherAt {
            url: format!("http://{shown}/teacher?token={}", percent_encode(t)),
        }
        .phrase(lang)
        .text(),
        Teacher::Open => ServeMessage::TeacherAt {
            url: format!("http://{shown}/teacher"),
        }
        .phrase(lang)
        .text(),
        Teacher::Off => ServeMessage::TeacherOff.phrase(lang).text(),
    });
    // a left-out problem's name and error come from the set's file: shown as written, never
    // read by the terminal (the text keys' escape)
    for line in lines {
        println!("{}", cagd_keys::escape_text(&line));
    }
    axum::serve(listener, prepared.router)
        .with_graceful_shutdown(async {
            let _ = tokio::signal::ctrl_c().await;
        })
        .await
        .map_err(|e| {
            ServeError(ServeMessage::Failed {
                error: e.to_string(),
            })
        })
}

/// A token in a URL's query.
fn percent_encode(s: &str) -> String {
    let mut out = String::new();
    for b in s.bytes() {
        match b {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'.' | b'_' | b'~' => {
                out.push(char::from(b))
            }
            b => out.push_str(&format!("%{b:02X}")),
        }
    }
    out
}

/// The headers of every response: the policy (unless the response has its own), no
/// sniffing, no referrer.
async fn security_headers(mut res: Response) -> Response {
    let h = res.headers_mut();
    h.entry(CONTENT_SECURITY_POLICY)
        .or_insert(HeaderValue::from_static(CSP));
    h.insert(X_CONTENT_TYPE_OPTIONS, HeaderValue::from_static("nosniff"));
    h.insert(REFERRER_POLICY, HeaderValue::from_static("no-referrer"));
    res
}

/// A JSON answer, never cached.
fn json_response(status: StatusCode, value: Value) -> Response {
    let mut res = (status, Json(value)).into_response();
    res.headers_mut()
        .insert(CACHE_CONTROL, HeaderValue::from_static("no-store"));
    res
}

/// An error: `{"error": sentence}`.
fn error(status: StatusCode, m: &ServeMessage, lang: Lang) -> Response {
    json_response(status, json!({"error": m.phrase(lang).text()}))
}

/// Busy: `{"error": "busy", "message": sentence}`.
fn busy(lang: Lang) -> Response {
    json_response(
        StatusCode::SERVICE_UNAVAILABLE,
        json!({"error": "busy", "message": ServeMessage::Busy.phrase(lang).text()}),
    )
}

/// A refusal of the pool as a response.
fn refused(r: Refused, lang: Lang) -> Response {
    match r {
        Refused::Busy => busy(lang),
        Refused::Panicked => error(
            StatusCode::INTERNAL_SERVER_ERROR,
            &ServeMessage::Internal,
            lang,
        ),
    }
}

/// An embedded file.
fn asset_response(a: Asset, cache: &'static str) -> Response {
    let mut res = Response::new(Body::from(a.bytes));
    let h = res.headers_mut();
    h.insert(CONTENT_TYPE, HeaderValue::from_static(a.content_type));
    h.insert(CACHE_CONTROL, HeaderValue::from_static(cache));
    res
}

/// The query every page and API reads: the language, the token.
#[derive(Debug, Default, Deserialize)]
struct Params {
    lang: Option<String>,
    token: Option<String>,
}

/// The language asked (`?lang=` or a body's `lang`), else the server's.
fn lang_of(asked: Option<&str>, state: &Shared) -> Lang {
    asked.and_then(Lang::parse).unwrap_or(state.lang)
}

/// The query, or none when it does not read.
fn params(q: Result<Query<Params>, axum::extract::rejection::QueryRejection>) -> Params {
    q.map(|Query(p)| p).unwrap_or_default()
}

/// Two tokens compared in constant time (their SHA-256 digests, byte by byte, all of them).
fn same_token(given: &str, expected: &str) -> bool {
    let a = Sha256::digest(given.as_bytes());
    let b = Sha256::digest(expected.as_bytes());
    a.iter()
        .zip(b.iter())
        .fold(0u8, |acc, (x, y)| acc | (x ^ y))
        == 0
}

/// Whether the teacher's pages answer this request: `Err` is the response (404 when they are
/// off, 403 without the token).
fn gate(
    state: &Shared,
    headers: &HeaderMap,
    token: Option<&str>,
    lang: Lang,
) -> Result<(), Response> {
    match &state.teacher {
        Teacher::Off => Err(error(StatusCode::NOT_FOUND, &ServeMessage::NotFound, lang)),
        Teacher::Open => Ok(()),
        Teacher::Token(t) => {
            let given = headers
                .get("x-cagd-token")
                .and_then(|v| v.to_str().ok())
                .or(token);
            match given {
                Some(g) if same_token(g, t) => Ok(()),
                _ => Err(error(
                    StatusCode::FORBIDDEN,
                    &ServeMessage::NeedsToken,
                    lang,
                )),
            }
        }
    }
}

/// A body as JSON of type `T`, or the error response (413 past the limit, 400 otherwise).
fn body_json<T: serde::de::DeserializeOwned>(
    body: Result<Bytes, BytesRejection>,
    lang: Lang,
) -> Result<T, Response> {
    let bytes = body.map_err(|r| rejected(r.status(), r.body_text(), lang))?;
    serde_json::from_slice(&bytes).map_err(|e| {
        error(
            StatusCode::BAD_REQUEST,
            &ServeMessage::BadRequest {
                error: e.to_string(),
            },
            lang,
        )
    })
}

/// A rejected body: 413 past the limit, else 400.
fn rejected(status: StatusCode, text: String, lang: Lang) -> Response {
    if status == StatusCode::PAYLOAD_TOO_LARGE {
        error(
            StatusCode::PAYLOAD_TOO_LARGE,
            &ServeMessage::BodyTooLarge {
                kib: BODY_LIMIT / 1024,
            },
            lang,
        )
    } else {
        error(
            StatusCode::BAD_REQUEST,
            &ServeMessage::BadRequest { error: text },
            lang,
        )
    }
}

async fn not_found(State(state): State<AppState>) -> Response {
    error(StatusCode::NOT_FOUND, &ServeMessage::NotFound, state.lang)
}

async fn student_page() -> Response {
    asset_response(assets::STUDENT_HTML, "no-cache")
}

async fn teacher_page(
    State(state): State<AppState>,
    headers: HeaderMap,
    q: Result<Query<Params>, axum::extract::rejection::QueryRejection>,
) -> Response {
    let p = params(q);
    let lang = lang_of(p.lang.as_deref(), &state);
    if let Err(res) = gate(&state, &headers, p.token.as_deref(), lang) {
        return res;
    }
    asset_response(assets::TEACHER_HTML, "no-cache")
}

async fn asset(State(state): State<AppState>, Path(name): Path<String>) -> Response {
    match assets::get(&name) {
        Some(a) => asset_response(a, "public, max-age=3600"),
        None => error(StatusCode::NOT_FOUND, &ServeMessage::NotFound, state.lang),
    }
}

/// The URL of a served problem's figure, when it has one.
fn figure_url(p: &ServedProblem) -> Option<String> {
    p.figure
        .en
        .as_ref()
        .map(|_| format!("/api/figure/{}.svg", p.index))
}

async fn api_set(
    State(state): State<AppState>,
    q: Result<Query<Params>, axum::extract::rejection::QueryRejection>,
) -> Response {
    let lang = lang_of(params(q).lang.as_deref(), &state);
    json_response(
        StatusCode::OK,
        state.served.set_json(lang, state.reveal, &figure_url),
    )
}

async fn api_figure(
    State(state): State<AppState>,
    Path(file): Path<String>,
    q: Result<Query<Params>, axum::extract::rejection::QueryRejection>,
) -> Response {
    let lang = lang_of(params(q).lang.as_deref(), &state);
    let svg = file
        .strip_suffix(".svg")
        .and_then(|n| n.parse::<usize>().ok())
        .and_then(|n| state.served.problems.get(n))
        .and_then(|p| p.figure.get(lang).clone());
    match svg {
        Some(svg) => {
            let mut res = Response::new(Body::from(svg));
            let h = res.headers_mut();
            h.insert(CONTENT_TYPE, HeaderValue::from_static("image/svg+xml"));
            h.insert(
                CACHE_CONTROL,
                HeaderValue::from_static("public, max-age=3600"),
            );
            h.insert(CONTENT_SECURITY_POLICY, HeaderValue::from_static(SVG_CSP));
            res
        }
        None => error(StatusCode::NOT_FOUND, &ServeMessage::NotFound, lang),
    }
}

/// The body of `/api/read`.
#[derive(Debug, Deserialize)]
struct ReadBody {
    problem: usize,
    text: String,
    kind: String,
    lang: Option<String>,
}

async fn api_read(State(state): State<AppState>, body: Result<Bytes, BytesRejection>) -> Response {
    let b: ReadBody = match body_json(body, state.lang) {
        Ok(b) => b,
        Err(res) => return res,
    };
    let lang = lang_of(b.lang.as_deref(), &state);
    let p = match state.served.problem(b.problem) {
        Ok(p) => Arc::clone(p),
        Err(m) => return error(StatusCode::BAD_REQUEST, &m, lang),
    };
    let Some(kind) = CellKind::parse(&b.kind) else {
        return error(
            StatusCode::BAD_REQUEST,
            &ServeMessage::UnknownKind { kind: b.kind },
            lang,
        );
    };
    let limits = state.limits;
    let work = move || match cagd_scalar::cancel::with_deadline(limits.max_seconds, || {
        served::read_cell(&p.problem, &b.text, kind, lang)
    }) {
        Ok(v) => v,
        Err(_) => json!({"ok": false, "error": ServeMessage::Deadline.phrase(lang).text()}),
    };
    match state.pool.run(work).await {
        Ok(v) => json_response(StatusCode::OK, v),
        Err(r) => refused(r, lang),
    }
}

/// The body of `/api/check`.
#[derive(Debug, Deserialize)]
struct CheckBody {
    problem: usize,
    answer: Value,
    lang: Option<String>,
}

async fn api_check(State(state): State<AppState>, body: Result<Bytes, BytesRejection>) -> Response {
    let b: CheckBody = match body_json(body, state.lang) {
        Ok(b) => b,
        Err(res) => return res,
    };
    let lang = lang_of(b.lang.as_deref(), &state);
    let p = match state.served.problem(b.problem) {
        Ok(p) => Arc::clone(p),
        Err(m) => return error(StatusCode::BAD_REQUEST, &m, lang),
    };
    let (reveal, limits) = (state.reveal, state.limits);
    match state
        .pool
        .run(move || served::check(&p, &b.answer, lang, reveal, &limits))
        .await
    {
        Ok(v) => json_response(StatusCode::OK, v),
        Err(r) => refused(r, lang),
    }
}

/// A problem's error as the teacher's API writes it: its path and the command line's
/// sentence.
fn error_json(e: &cagd_problem::ProblemError, lang: Lang) -> Value {
    json!({"path": e.field, "message": error_sentence(e, lang).text})
}

/// The body of `/api/teacher/solve`.
#[derive(Debug, Deserialize)]
struct SolveBody {
    problem: Value,
    lang: Option<String>,
}

/// The JSON body of a request to the teacher's API, once past the gate (the token in the
/// header or the query); the gate's and the body's errors in the query's language.
fn teacher_body<T: serde::de::DeserializeOwned>(
    state: &Shared,
    headers: &HeaderMap,
    q: Result<Query<Params>, axum::extract::rejection::QueryRejection>,
    body: Result<Bytes, BytesRejection>,
) -> Result<T, Response> {
    let p = params(q);
    gate(
        state,
        headers,
        p.token.as_deref(),
        lang_of(p.lang.as_deref(), state),
    )?;
    body_json(body, state.lang)
}

/// The settings of the teacher's solves: the limits, with the steps.
fn settings(limits: &Limits) -> Settings {
    Settings {
        limits: *limits,
        steps: true,
    }
}

async fn teacher_solve(
    State(state): State<AppState>,
    headers: HeaderMap,
    q: Result<Query<Params>, axum::extract::rejection::QueryRejection>,
    body: Result<Bytes, BytesRejection>,
) -> Response {
    let b: SolveBody = match teacher_body(&state, &headers, q, body) {
        Ok(b) => b,
        Err(res) => return res,
    };
    let lang = lang_of(b.lang.as_deref(), &state);
    let limits = state.limits;
    let work = move || {
        let v = check_with_settings(&b.problem, &settings(&limits));
        match &v.answer {
            Err(e) => json!({"ok": false, "errors": [error_json(e, lang)]}),
            Ok(_) => json!({
                "ok": true,
                "key_html": markdown::to_html(&example_markdown(&v, lang)),
                "statement_html": markdown::to_html(&statement_markdown(&v, lang)),
            }),
        }
    };
    match state.pool.run(work).await {
        Ok(v) => json_response(StatusCode::OK, v),
        Err(r) => refused(r, lang),
    }
}

/// The body of `/api/teacher/preview`.
#[derive(Debug, Deserialize)]
struct PreviewBody {
    set: Value,
    lang: Option<String>,
}

async fn teacher_preview(
    State(state): State<AppState>,
    headers: HeaderMap,
    q: Result<Query<Params>, axum::extract::rejection::QueryRejection>,
    body: Result<Bytes, BytesRejection>,
) -> Response {
    let b: PreviewBody = match teacher_body(&state, &headers, q, body) {
        Ok(b) => b,
        Err(res) => return res,
    };
    let lang = lang_of(b.lang.as_deref(), &state);
    let (limits, reveal) = (state.limits, state.reveal);
    let work = move || {
        let mut set = Set::from_json(&b.set);
        set.problems.truncate(limits.max_batch);
        let served = Served::new(&set, &limits);
        if !served.left_out.is_empty() {
            let errors: Vec<Value> = served
                .left_out
                .iter()
                .map(|l| {
                    let path = match l.error.field.is_empty() {
                        true => format!("[{}]", l.index),
                        false => format!("[{}].{}", l.index, l.error.field),
                    };
                    json!({"path": path, "message": error_sentence(&l.error, lang).text})
                })
                .collect();
            return json!({"ok": false, "errors": errors});
        }
        let data_url = |p: &ServedProblem| {
            p.figure
                .get(lang)
                .as_ref()
                .map(|svg| format!("data:image/svg+xml;base64,{}", base64(svg.as_bytes())))
        };
        let mut v = served.set_json(lang, reveal, &data_url);
        if let Some(o) = v.as_object_mut() {
            o.insert("ok".into(), Value::Bool(true));
        }
        v
    };
    match state.pool.run(work).await {
        Ok(v) => json_response(StatusCode::OK, v),
        Err(r) => refused(r, lang),
    }
}

/// The fields of the teacher's forms.
#[derive(Debug, Deserialize)]
struct TeacherForm {
    problem: String,
    lang: Option<String>,
    token: Option<String>,
    what: Option<String>,
}

/// A small HTML page saying `text` (escaped), for a form's answer that failed.
fn message_page(status: StatusCode, text: &str) -> Response {
    let page = format!(
        "<!DOCTYPE html>\n<html>\n<head><meta charset=\"utf-8\"></head>\n<body><p>{}</p></body>\n</html>\n",
        markdown::escape_attribute(text)
    );
    let mut res = (status, page).into_response();
    let h = res.headers_mut();
    h.insert(
        CONTENT_TYPE,
        HeaderValue::from_static("text/html; charset=utf-8"),
    );
    h.insert(
        CONTENT_SECURITY_POLICY,
        HeaderValue::from_static("default-src 'none'; frame-ancestors 'self'; sandbox"),
    );
    h.insert(CACHE_CONTROL, HeaderValue::from_static("no-store"));
    res
}

/// A form of the teacher's, read and let through the gate; `Err` is the response.
fn teacher_form(
    state: &Shared,
    headers: &HeaderMap,
    form: Result<Form<TeacherForm>, FormRejection>,
) -> Result<(TeacherForm, Lang), Response> {
    let Form(f) = form.map_err(|r| rejected(r.status(), r.body_text(), state.lang))?;
    let lang = lang_of(f.lang.as_deref(), state);
    gate(state, headers, f.token.as_deref(), lang)?;
    Ok((f, lang))
}

/// A problem's (or a set's) JSON text from a form, or the page that says why not.
fn form_json(text: &str, lang: Lang) -> Result<Value, Response> {
    serde_json::from_str(text).map_err(|e| {
        let m = ServeMessage::BadRequest {
            error: e.to_string(),
        };
        message_page(StatusCode::BAD_REQUEST, &m.phrase(lang).text())
    })
}

async fn teacher_figure(
    State(state): State<AppState>,
    headers: HeaderMap,
    form: Result<Form<TeacherForm>, FormRejection>,
) -> Response {
    let (f, lang) = match teacher_form(&state, &headers, form) {
        Ok(x) => x,
        Err(res) => return res,
    };
    let problem = match form_json(&f.problem, lang) {
        Ok(p) => p,
        Err(res) => return res,
    };
    let limits = state.limits;
    let work = move || -> Result<String, String> {
        let v = check_with_settings(&problem, &settings(&limits));
        let answer = v.answer.map_err(|e| error_sentence(&e, lang).text)?;
        let scene = Scene::from_answer(&answer, false).map_err(|e| {
            ServeMessage::NoFigure {
                inner: e.phrase(lang),
            }
            .phrase(lang)
            .text()
        })?;
        to_html(
            &scene,
            // the canvas fits the teacher's page's frame (page.css: #figure)
            &HtmlOptions {
                lang,
                width: 600,
                height: 420,
                ..HtmlOptions::default()
            },
        )
        .map_err(|e| {
            ServeMessage::NoFigure {
                inner: e.phrase(lang),
            }
            .phrase(lang)
            .text()
        })
    };
    match state.pool.run(work).await {
        Ok(Ok(page)) => {
            let hash = base64(&Sha256::digest(inline_script().as_bytes()));
            let csp = format!(
                "default-src 'none'; script-src 'sha256-{hash}'; style-src 'unsafe-inline'; img-src data:; base-uri 'none'; form-action 'none'; frame-ancestors 'self'; sandbox allow-scripts"
            );
            let mut res = Response::new(Body::from(page));
            let h = res.headers_mut();
            h.insert(
                CONTENT_TYPE,
                HeaderValue::from_static("text/html; charset=utf-8"),
            );
            h.insert(CACHE_CONTROL, HeaderValue::from_static("no-store"));
            if let Ok(v) = HeaderValue::from_str(&csp) {
                h.insert(CONTENT_SECURITY_POLICY, v);
            }
            res
        }
        Ok(Err(text)) => message_page(StatusCode::OK, &text),
        Err(r) => refused(r, lang),
    }
}

async fn teacher_download(
    State(state): State<AppState>,
    headers: HeaderMap,
    form: Result<Form<TeacherForm>, FormRejection>,
) -> Response {
    let (f, lang) = match teacher_form(&state, &headers, form) {
        Ok(x) => x,
        Err(res) => return res,
    };
    let doc = match form_json(&f.problem, lang) {
        Ok(p) => p,
        Err(res) => return res,
    };
    let what = f.what.unwrap_or_default();
    let sheet = match what.as_str() {
        "key" => false,
        "sheet" => true,
        _ => {
            let m = ServeMessage::UnknownDownload { what };
            return message_page(StatusCode::BAD_REQUEST, &m.phrase(lang).text());
        }
    };
    let limits = state.limits;
    let work = move || {
        let mut set = Set::from_json(&doc);
        set.problems.truncate(limits.max_batch);
        let header = SheetHeader {
            title: set.title.clone(),
            ..SheetHeader::default()
        };
        let verdicts: Vec<Verdict> = set
            .problems
            .iter()
            .enumerate()
            .map(|(i, (_, json))| {
                let mut v = check_with_settings(json, &settings(&limits));
                v.index = Some(i);
                v
            })
            .collect();
        if sheet {
            let sections: Vec<String> = verdicts
                .iter()
                .filter(|v| v.problem.is_some())
                .map(|v| statement_latex(v, lang))
                .collect();
            statement_document(&header, &sections, lang)
        } else {
            let title = format!("{}: {}", lang.word("Answer key"), header.title_in(lang));
            let sections: Vec<String> = verdicts
                .iter()
                .map(|v| example_latex_beside(v, lang, None))
                .collect();
            latex_key_document(&title, &legend_latex(&verdicts, lang), &sections, lang)
        }
    };
    match state.pool.run(work).await {
        Ok(tex) => {
            let name = if sheet { "sheet.tex" } else { "key.tex" };
            let mut res = Response::new(Body::from(tex));
            let h = res.headers_mut();
            h.insert(
                CONTENT_TYPE,
                HeaderValue::from_static("application/x-tex; charset=utf-8"),
            );
            h.insert(CACHE_CONTROL, HeaderValue::from_static("no-store"));
            if let Ok(v) = HeaderValue::from_str(&format!("attachment; filename=\"{name}\"")) {
                h.insert(CONTENT_DISPOSITION, v);
            }
            res
        }
        Err(r) => refused(r, lang),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tokens_compare_whole() {
        assert!(same_token("abc", "abc"));
        assert!(!same_token("abd", "abc"));
        assert!(!same_token("ab", "abc"));
        assert!(!same_token("", "abc"));
    }

    #[test]
    fn the_token_in_a_url() {
        assert_eq!(percent_encode("a b&c"), "a%20b%26c");
    }

    #[test]
    fn lang_code_is_the_query_word() {
        assert_eq!(Lang::parse(served::lang_code(Lang::Es)), Some(Lang::Es));
    }
}
