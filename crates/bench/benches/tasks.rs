//! `cargo bench -p cagd-bench`: tasks T1-T6 at every size of the issue, `cagd examples`, and
//! `cagd solve` on 1,000 generated problems.

use cagd_bench::{examples_fixtures, generated_problems, run_examples, run_problems, Input, TASKS};
use cagd_scalar::BigRational;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use std::time::Duration;

fn tasks(c: &mut Criterion) {
    for label in ["T1", "T2", "T3", "T4", "T5", "T6"] {
        let mut group = c.benchmark_group(label);
        group
            .sample_size(10)
            .warm_up_time(Duration::from_millis(300))
            .measurement_time(Duration::from_secs(2));
        for task in TASKS.iter().filter(|t| t.label() == label) {
            let input = Input::new(*task).prepare::<BigRational>();
            let id = BenchmarkId::from_parameter(task.name().trim_start_matches(label).trim());
            group.bench_with_input(id, &input, |b, input| b.iter(|| task.run(input)));
        }
        group.finish();
    }
}

fn whole_runs(c: &mut Criterion) {
    let mut group = c.benchmark_group("cagd");
    group
        .sample_size(10)
        .warm_up_time(Duration::from_millis(300))
        .measurement_time(Duration::from_secs(3));
    let fixtures = examples_fixtures();
    group.bench_function("examples", |b| b.iter(|| run_examples(&fixtures)));
    let problems = generated_problems(1000);
    group.bench_function("solve 1000 generated", |b| {
        b.iter(|| run_problems(&problems))
    });
    group.finish();
}

criterion_group!(benches, tasks, whole_runs);
criterion_main!(benches);
