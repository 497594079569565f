//! The harness of the family tests: a student's answer written as JSON from a mistaken
//! answer, and the property each mistake must have.

use cagd_diagnose::Key;
use cagd_problem::{
    Assessment, Catalogued, Exact, Limits, Mistake, Named, Problem, Quantity, Settings,
};
use serde_json::{Map, Value};

/// The settings of the tests: the default limits, steps on.
pub fn settings() -> Settings {
    Settings {
        limits: Limits::DEFAULT,
        steps: true,
    }
}

/// The results written as a student's answer: an object of results by name, each value as
/// the answer's JSON writes it.
pub fn written(result: &[Named]) -> Value {
    let mut o = Map::new();
    for (q, x) in result {
        o.insert(q.name().into_owned(), x.to_json());
    }
    Value::Object(o)
}

/// The key of a problem given as JSON.
pub fn key(problem: &Value) -> Key {
    let p = Problem::read(problem, &Limits::DEFAULT).expect("the problem reads");
    Key::new(&p, &settings())
}

/// The property of mistake `m` on `problem`: when `m` applies (its answer differs from the
/// key's), the student who made it is diagnosed as `m` (alone, or ambiguous naming it) on
/// every result it changes, and the key's own answer is correct with no diagnosis.
/// Returns whether `m` applied.
pub fn diagnosed_as(problem: &Value, m: Mistake) -> bool {
    let key = key(problem);
    let answer = key.answer.as_ref().expect("the problem has an answer");
    // the key's own answer: correct, never diagnosed
    let right = key.assess(&written(&answer.result));
    assert!(
        right.correct(),
        "{}: the key is not correct: {right:?}",
        m.id()
    );
    assert!(
        right.mistakes().is_empty(),
        "{}: the key is diagnosed",
        m.id()
    );
    let Some((_, mistaken)) = key.mistaken.iter().find(|(k, _)| *k == m) else {
        return false;
    };
    let student = written(&mistaken.result);
    let a = key.assess(&student);
    if a.correct() {
        // the mistake changes only results the student did not write: nothing to see
        return false;
    }
    for r in a.results.iter().filter(|r| !r.correct()) {
        assert!(
            r.diagnoses
                .iter()
                .any(|d| d.whole && d.mistakes.contains(&m)),
            "{}: result `{}` not diagnosed as it: {:?}\nproblem: {problem}",
            m.id(),
            r.quantity.name(),
            r.diagnoses
        );
    }
    true
}

/// Runs [`diagnosed_as`] for `m` over `problems` and fails unless `m` applied to at least
/// one of them (a property that never runs proves nothing).
pub fn holds_over(problems: &[Value], m: Mistake) {
    let applied = problems.iter().filter(|p| diagnosed_as(p, m)).count();
    assert!(
        applied > 0,
        "{} applied to none of {} problems",
        m.id(),
        problems.len()
    );
}

/// `count` random problems of the exercises' topic `topic` (deterministic by `seed`).
pub fn generated(topic: &str, count: usize, seed: u64) -> Vec<Value> {
    cagd_exercises::generate(topic, count, seed).expect("the topic exists")
}

/// The result `q` of mistake `m`'s answer to `problem` (`None` when `m` does not apply).
pub fn mistaken_result(problem: &Value, m: Mistake, q: &Quantity) -> Option<Exact> {
    let key = key(problem);
    let (_, x) = key.mistaken.iter().find(|(k, _)| *k == m)?;
    x.result
        .iter()
        .find(|(k, _)| k == q)
        .map(|(_, x)| x.clone())
}

/// The key's result `q` of `problem`.
pub fn solved(problem: &Value, q: &Quantity) -> Exact {
    let a = key(problem).answer.expect("an answer");
    a.result
        .into_iter()
        .find(|(k, _)| k == q)
        .expect("the result")
        .1
}

/// The assessment of a student's report (`tests/reports/<family>.json`, the snapshot tests'
/// input), whose answer is wrong.
pub fn report(text: &str) -> Assessment {
    let problem: Value = serde_json::from_str(text).expect("the report reads");
    let verdict = cagd_diagnose::diagnose(&problem, &settings());
    let a = verdict.assessment.expect("an assessment");
    assert!(!a.correct(), "the report's answer is right");
    *a
}
