//! Writes the inputs of tasks T1-T6, cagd-exact's exact answers and its timings (exact and
//! over f64) as JSON, for `peers/run.sh`; also times `cagd examples` and `cagd solve` on
//! 1,000 generated problems.
//!
//! Usage: `peers-data OUT.json [FILTER]` (FILTER: only tasks whose name contains it).

use cagd_bench::{
    examples_fixtures, generated_problems, run_examples, run_problems, Input, Task, TASKS,
};
use cagd_scalar::{BigRational, Print};
use serde_json::{json, Value};
use std::time::{Duration, Instant};

/// The median time of `f` over repeated runs: at least 3 runs, and more while the total stays
/// under `budget` (at most 50).
fn time<T>(budget: Duration, mut f: impl FnMut() -> T) -> (f64, usize) {
    let mut times = Vec::new();
    let start = Instant::now();
    while times.len() < 3 || (start.elapsed() < budget && times.len() < 50) {
        let t0 = Instant::now();
        std::hint::black_box(f());
        times.push(t0.elapsed().as_secs_f64());
    }
    times.sort_by(f64::total_cmp);
    // at least 3 runs, so the middle one is there
    let median = times.get(times.len() / 2).copied().unwrap_or_default();
    (median, times.len())
}

fn task_json(task: &Task, budget: Duration) -> Value {
    let input = Input::new(*task);
    let exact = input.prepare::<BigRational>();
    let answer = match task.run(&exact) {
        Ok(a) => task.flatten(&a),
        Err(e) => {
            eprintln!("{}: {e}", task.name());
            std::process::exit(1);
        }
    };
    let (exact_s, reps) = time(budget, || task.run(&exact));
    let float = input.prepare::<f64>();
    let f64_error = task.run(&float).err();
    let (f64_s, _) = time(budget / 4, || task.run(&float));
    eprintln!(
        "{:<22} exact {:>10.3} ms   f64 {:>9.4} ms   ({reps} runs)",
        task.name(),
        exact_s * 1e3,
        f64_s * 1e3
    );
    json!({
        "name": task.name(),
        "label": task.label(),
        "describe": task.describe(),
        "n": task.n,
        "extra": task.extra,
        "input": input.to_json(),
        "answer": answer.iter().map(Print::to_json_string).collect::<Vec<_>>(),
        "exact_seconds": exact_s,
        "f64_seconds": f64_s,
        "f64_error": f64_error,
        "runs": reps,
    })
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Some(out) = args.first() else {
        eprintln!("usage: peers-data OUT.json [FILTER]");
        std::process::exit(2);
    };
    let filter = args.get(1).cloned().unwrap_or_default();
    let budget = Duration::from_millis(1500);
    let tasks: Vec<Value> = TASKS
        .iter()
        .filter(|t| t.name().contains(&filter))
        .map(|t| task_json(t, budget))
        .collect();
    let whole = filter.is_empty() || "examples solve".contains(&filter);
    let (examples, problems) = if whole {
        let fixtures = examples_fixtures();
        let passed = run_examples(&fixtures);
        let (examples_s, _) = time(budget, || run_examples(&fixtures));
        eprintln!(
            "examples: {passed}/{} pass, {:.3} ms",
            fixtures.len(),
            examples_s * 1e3
        );
        let problems = generated_problems(1000);
        let solved = run_problems(&problems);
        let (problems_s, _) = time(budget, || run_problems(&problems));
        eprintln!(
            "solve: {solved}/{} solved, {:.3} ms",
            problems.len(),
            problems_s * 1e3
        );
        (
            json!({"count": fixtures.len(), "passed": passed, "seconds": examples_s}),
            json!({"count": problems.len(), "solved": solved, "seconds": problems_s}),
        )
    } else {
        (Value::Null, Value::Null)
    };
    let doc = json!({"tasks": tasks, "examples": examples, "problems": problems});
    if let Err(e) = std::fs::write(out, serde_json::to_string(&doc).unwrap_or_default()) {
        eprintln!("cannot write {out}: {e}");
        std::process::exit(1);
    }
}
