//! `cargo bench -p cagd-bench --bench class`: checking a class. Ten generated problems of
//! different topics, 300 students' answers to each (right, the Coons mistake `coons.cd_added`
//! where the problem is a Coons surface, or with random entries changed), diagnosed as
//! `cagd check` does: the key once per problem (`cagd_diagnose::Key::new`: the problem solved
//! with its steps and every applicable mistake computed), then each answer compared and
//! assessed against it (`cagd_diagnose::diagnose_with`).

use cagd_bench::Rng;
use cagd_diagnose::{diagnose_with, Key};
use cagd_problem::{solve_problem, Catalogued, Limits, Problem, Settings};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use serde_json::{Map, Value};
use std::hint::black_box;
use std::sync::Arc;
use std::time::Duration;

/// The topics of the ten problems, one each (cagd-exercises' names).
const TOPICS: [&str; 10] = [
    "closed_form",
    "evaluate",
    "restrict",
    "elevate",
    "derivative",
    "interpolate",
    "approximate",
    "ruled",
    "coons",
    "revolution",
];

/// Students in the class.
const STUDENTS: usize = 300;

/// One problem of the class: the teacher's problem, its key, and the students' answers read
/// as problems whose `expected` is the answer.
struct Exercise {
    topic: &'static str,
    problem: Arc<Problem>,
    key: Key,
    answers: Vec<Arc<Problem>>,
    /// The answers as the students' files hold them: the problem with `expected` and
    /// `student`.
    files: Vec<Value>,
}

fn settings() -> Settings {
    Settings {
        limits: Limits::DEFAULT,
        steps: false,
    }
}

/// The results written as a student's answer: an object of results by name.
fn written(result: &[cagd_problem::Named]) -> Value {
    let mut o = Map::new();
    for (q, x) in result {
        o.insert(q.name().into_owned(), x.to_json());
    }
    Value::Object(o)
}

/// The string leaves of `v` (numbers and expressions), as mutable references.
fn leaves(v: &mut Value) -> Vec<&mut String> {
    match v {
        Value::String(s) => vec![s],
        Value::Array(xs) => xs.iter_mut().flat_map(leaves).collect(),
        Value::Object(o) => o.values_mut().flat_map(leaves).collect(),
        _ => Vec::new(),
    }
}

/// `right` with one to three entries changed: the first digit of a number (or of an
/// expression) raised by one (9 to 8), a value that still reads.
fn wrong(right: &Value, rng: &mut Rng) -> Value {
    let mut v = right.clone();
    let mut ls = leaves(&mut v);
    let n = i64::try_from(ls.len()).unwrap_or(0);
    if n == 0 {
        return v;
    }
    for _ in 0..rng.range(1, 3) {
        let k = usize::try_from(rng.range(0, n - 1)).unwrap_or(0);
        if let Some(s) = ls.get_mut(k) {
            if let Some(at) = s.find(|c: char| c.is_ascii_digit()) {
                let d = s.as_bytes().get(at).copied().unwrap_or(b'0');
                let e = if d == b'9' { '8' } else { char::from(d + 1) };
                s.replace_range(at..=at, &e.to_string());
            }
        }
    }
    v
}

/// The class: each topic's first generated problem (seed 2026), its key, and 300 answers.
fn class() -> Vec<Exercise> {
    let mut rng = Rng::new(30);
    TOPICS
        .iter()
        .filter_map(|topic| {
            let json = cagd_exercises::generate(topic, 1, 2026).ok()?.pop()?;
            let problem = Arc::new(Problem::read(&json, &Limits::DEFAULT).ok()?);
            let key = Key::new(&problem, &settings());
            let right = written(&key.answer.as_ref().ok()?.result);
            let cd_added = key
                .mistaken
                .iter()
                .find(|(m, _)| m.id() == "coons.cd_added")
                .map(|(_, x)| written(&x.result));
            let files: Vec<Value> = (0..STUDENTS)
                .map(|s| {
                    let answer = match (rng.range(0, 9), &cd_added) {
                        (0..=3, _) => right.clone(),
                        (4..=6, Some(m)) => m.clone(),
                        _ => wrong(&right, &mut rng),
                    };
                    let mut student = json.clone();
                    if let Some(o) = student.as_object_mut() {
                        o.insert("expected".into(), answer);
                        o.insert("student".into(), format!("student {s}").into());
                    }
                    student
                })
                .collect();
            let answers = files
                .iter()
                .filter_map(|f| Problem::read(f, &Limits::DEFAULT).ok().map(Arc::new))
                .collect();
            Some(Exercise {
                topic,
                problem,
                key,
                answers,
                files,
            })
        })
        .collect()
}

/// What the class's answers are, once: answers, correct ones, and wrong ones diagnosed with a
/// known mistake (the mix the timings run over).
fn describe(class: &[Exercise], settings: &Settings) {
    for e in class {
        let (mut correct, mut diagnosed) = (0, 0);
        for a in &e.answers {
            let v = diagnose_with(&e.key, a, settings);
            let assessment = v.assessment.as_deref();
            if assessment.is_some_and(|x| x.correct()) {
                correct += 1;
            } else if assessment.is_some_and(|x| !x.mistakes().is_empty()) {
                diagnosed += 1;
            }
        }
        eprintln!(
            "{}: {} answers, {correct} correct, {diagnosed} wrong with a known mistake, {} mistakes in the key",
            e.topic,
            e.answers.len(),
            e.key.mistaken.len()
        );
    }
}

fn checking_a_class(c: &mut Criterion) {
    let class = class();
    let settings = settings();
    describe(&class, &settings);
    let mut once = c.benchmark_group("class: each problem once");
    once.sample_size(10)
        .warm_up_time(Duration::from_millis(200))
        .measurement_time(Duration::from_secs(1));
    for e in &class {
        once.bench_with_input(BenchmarkId::new("solve", e.topic), e, |b, e| {
            b.iter(|| solve_problem(black_box(&e.problem), &settings))
        });
        once.bench_with_input(BenchmarkId::new("key", e.topic), e, |b, e| {
            b.iter(|| Key::new(black_box(&e.problem), &settings))
        });
    }
    once.finish();

    let mut each = c.benchmark_group("class: 300 answers to a problem");
    each.sample_size(10)
        .warm_up_time(Duration::from_millis(200))
        .measurement_time(Duration::from_secs(1));
    for e in &class {
        each.bench_with_input(BenchmarkId::new("diagnose", e.topic), e, |b, e| {
            b.iter(|| {
                for a in &e.answers {
                    black_box(diagnose_with(&e.key, a, &settings));
                }
            })
        });
    }
    each.finish();

    let mut whole = c.benchmark_group("class: 300 students x 10 problems");
    whole
        .sample_size(10)
        .warm_up_time(Duration::from_millis(200))
        .measurement_time(Duration::from_secs(3));
    whole.bench_function("keys and 3000 answers", |b| {
        b.iter(|| {
            for e in &class {
                let key = Key::new(&e.problem, &settings);
                for a in &e.answers {
                    black_box(diagnose_with(&key, a, &settings));
                }
            }
        })
    });
    whole.bench_function("keys and 3000 answers read and diagnosed", |b| {
        b.iter(|| {
            for e in &class {
                let key = Key::new(&e.problem, &settings);
                for f in &e.files {
                    if let Ok(p) = Problem::read(f, &Limits::DEFAULT) {
                        black_box(diagnose_with(&key, &Arc::new(p), &settings));
                    }
                }
            }
        })
    });
    whole.finish();
}

criterion_group!(benches, checking_a_class);
criterion_main!(benches);
