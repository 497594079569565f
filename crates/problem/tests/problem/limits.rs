//! Each resource limit of `solve` (docs/format.md, Limits): refused before the work, with an
//! error that names the field, the limit and the flag that raises it; raised, the same problem
//! is solved. (How fast a refusal is, is the benchmarks' business, not the tests'.)

use cagd_problem::{solve, solve_batch_with, solve_with, Limit, Limits};
use serde_json::{json, Value};

fn err(p: &Value) -> String {
    solve(p).unwrap_err().to_string()
}

fn err_with(p: &Value, limits: &Limits) -> String {
    solve_with(p, limits).unwrap_err().to_string()
}

/// `n` points of the X axis.
fn line(n: usize) -> Vec<Value> {
    (0..n).map(|i| json!([i, 0])).collect()
}

#[test]
fn degree_given() {
    let p = json!({"op": "evaluate", "curve": {"bspline": line(60), "degree": 51, "knots": []}, "params": [0]});
    assert_eq!(
        err(&p),
        "field `curve.degree`: 51 is above the limit of 50 for degrees"
    );
    let s = json!({"op": "evaluate", "surface": {"bspline": [[[0, 0, 0]]], "degree": [1, 70], "knots": [[], []]}, "params": []});
    assert_eq!(
        err(&s),
        "field `surface.degree[1]`: 70 is above the limit of 50 for degrees"
    );
}

/// Regression (issue 16): the degree limit used to bound only a `degree` written, so a Bézier
/// curve of 60 points (degree 59) was evaluated under `--max-degree 50`.
#[test]
fn degree_of_a_bezier_curve_or_patch_given_by_its_points() {
    let p = json!({"op": "evaluate", "curve": {"bezier": line(60)}, "params": [0]});
    assert_eq!(
        err(&p),
        "field `curve.bezier`: 60 control points make a Bézier curve of degree 59, above the limit of 50 for degrees"
    );
    let e = solve(&p).unwrap_err();
    assert_eq!(e.limit, Some(cagd_problem::Limit::Degree));
    let raised = Limits {
        max_degree: 59,
        ..Limits::default()
    };
    assert!(solve_with(&p, &raised).is_ok());
    // 51 points, degree 50: within the limit
    let ok = json!({"op": "evaluate", "curve": {"bezier": line(51)}, "params": [0]});
    assert!(solve(&ok).is_ok());
    let rows: Vec<Value> = (0..52).map(|i| json!([[i, 0, 0], [i, 1, 0]])).collect();
    let s = json!({"op": "evaluate", "surface": {"bezier": rows}, "params": [[0, 0]]});
    assert_eq!(
        err(&s),
        "field `surface.bezier`: 52 control points make a Bézier patch (in u) of degree 51, above the limit of 50 for degrees"
    );
}

#[test]
fn degree_computed_by_an_elevation() {
    let curve = json!({"op": "elevate", "curve": {"bezier": [[0, 0], [1, 2], [3, 3]]}, "by": 1_000_000_000u64});
    assert_eq!(
        err(&curve),
        "field `by`: elevating degree 2 by 1000000000 gives degree 1000000002, above the limit of 50"
    );
    let surface = json!({"op": "elevate", "surface": {"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]}, "by": [60, 0]});
    assert_eq!(
        err(&surface),
        "field `by`: elevating bidegree (1, 1) by (60, 0) gives degree 61, above the limit of 50"
    );
    // raised, it is answered: a segment elevated to degree 60 has 61 points
    let raised = Limits {
        max_degree: 61,
        ..Limits::default()
    };
    let a = solve_with(&surface, &raised).unwrap();
    assert_eq!(
        a.get("surface").unwrap().to_json()["bezier"]
            .as_array()
            .unwrap()
            .len(),
        62
    );
}

#[test]
fn degree_of_an_expression_and_of_a_derivative() {
    let p = json!({"op": "closed_form", "surface": {"expr": "(u, v, u^30 v^30)"}});
    assert_eq!(
        err(&p),
        "field `surface.expr`: \"(u, v, u^30 v^30)\": degree 60 is above the limit of 50"
    );
    // u^1000 * v^1000 is refused by the limit, before the expansion budget is reached
    let big = json!({"op": "closed_form", "curve": {"expr": "(u^1000 * v^1000, 0)"}});
    assert!(err(&big).contains("degree 2000 is above the limit of 50"));
    let d = json!({"op": "derivative", "curve": {"expr": "(t, t^2)"}, "order": 4_000_000_000u64});
    assert_eq!(
        err(&d),
        "field `order`: 4000000000 is above the limit of 50 for degrees"
    );
}

#[test]
fn points_given() {
    let p = json!({"op": "evaluate", "curve": {"bezier": line(1001)}, "params": [0]});
    assert_eq!(
        err(&p),
        "field `curve.bezier`: a list of 1001 items is longer than the limit of 1000"
    );
    let row: Vec<Value> = (0..40).map(|j| json!([0, j, 0])).collect();
    let mesh: Vec<Value> = (0..30).map(|_| json!(row)).collect();
    let m = json!({"op": "closed_form", "surface": {"bezier": mesh}});
    assert_eq!(
        err(&m),
        "field `surface.bezier`: a mesh of 1200 points is larger than the limit of 1000"
    );
    let params: Vec<Value> = (0..2000).map(|_| json!(0)).collect();
    let e = json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 1]]}, "params": params});
    assert_eq!(
        err(&e),
        "field `params`: a list of 2000 items is longer than the limit of 1000"
    );
    let raised = Limits {
        max_points: 2000,
        ..Limits::default()
    };
    assert!(solve_with(&e, &raised).is_ok());
}

#[test]
fn points_computed() {
    let graph = json!({"op": "graph", "f": "x*y", "degree": [40, 40]});
    assert_eq!(
        err(&graph),
        "field `degree`: the graph of bidegree (40, 40) would have 1681 control points, more than the limit of 1000"
    );
    let elevated = json!({"op": "elevate", "surface": {"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]}, "by": [39, 39]});
    assert_eq!(
        err(&elevated),
        "field `by`: the elevated patch of bidegree (40, 40) would have 1681 control points, more than the limit of 1000"
    );
    let circle = json!({"op": "circle", "arcs": 1_000_000});
    assert_eq!(
        err(&circle),
        "field `arcs`: 1000000 is above the limit of 1000"
    );
    let ls =
        json!({"op": "approximate", "degree": [40, 40], "points": [[0, 0, 0]], "params": [[0, 0]]});
    assert_eq!(
        err(&ls),
        "field `degree`: a patch of bidegree (40, 40) would have 1681 control points, more than the limit of 1000"
    );
}

#[test]
fn digits() {
    let long = format!("1{}", "0".repeat(1000));
    let p = json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [long, 1]]}, "params": [0]});
    assert_eq!(
        err(&p),
        format!(
            "field `curve.bezier[1][0]`: \"{}...\": limit exceeded: number at column 1 has more than 1000 digits",
            &long[..40]
        )
    );
    // computed: a power longer than the limit is refused before it is computed
    let pow = json!({"op": "evaluate", "curve": {"bezier": [[0, 0], ["((10^1000)^1000)^1000", 1]]}, "params": [0]});
    assert_eq!(
        err(&pow),
        "field `curve.bezier[1][0]`: \"((10^1000)^1000)^1000\": limit exceeded: the power at column 11 would have more than 1000 digits"
    );
    let ok =
        json!({"op": "evaluate", "curve": {"bezier": [[0, 0], ["(2^1000)^4", 1]]}, "params": [1]});
    assert_eq!(
        err(&ok),
        "field `curve.bezier[1][0]`: \"(2^1000)^4\": limit exceeded: the power at column 9 would have more than 1000 digits"
    );
    let raised = Limits {
        max_digits: 2000,
        ..Limits::default()
    };
    let a = solve_with(&ok, &raised).unwrap();
    assert_eq!(a.get("points").unwrap().to_json()[0][1], "1");
    // a tighter limit applies to JSON integers too
    let tight = Limits {
        max_digits: 3,
        ..Limits::default()
    };
    let small = json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1234, 1]]}, "params": [0]});
    assert_eq!(
        err_with(&small, &tight),
        "field `curve.bezier[1][0]`: a number of 4 digits is longer than the limit of 3 digits"
    );
}

#[test]
fn exponent() {
    let p = json!({"op": "evaluate", "curve": {"bezier": [[0, 0], ["(1/3)^(10^9)", 1]]}, "params": [0]});
    assert_eq!(
        err(&p),
        "field `curve.bezier[1][0]`: \"(1/3)^(10^9)\": limit exceeded: exponent 1000000000 at column 6 is larger than 1000"
    );
    let e = json!({"op": "closed_form", "curve": {"expr": "(u, (1 + u)^1001)"}});
    assert!(err(&e).ends_with("exponent 1001 at column 12 is larger than 1000"));
    let tight = Limits {
        max_exponent: 2,
        ..Limits::default()
    };
    // a power of a power: each exponent within the limit, the power it builds not
    let tower = json!({"op": "closed_form", "curve": {"expr": "(u, ((u + 0)^37)^37)"}});
    assert_eq!(
        err(&tower),
        "field `curve.expr`: \"(u, ((u + 0)^37)^37)\": at column 17: expression too large to expand: the power u^1369, above the exponent limit of 1000"
    );
    let raised = Limits {
        max_exponent: 2000,
        max_degree: 2000,
        ..Limits::default()
    };
    assert!(solve_with(&tower, &raised).is_ok());
    let sq = json!({"op": "closed_form", "curve": {"expr": "(u, u^3)"}});
    assert_eq!(
        err_with(&sq, &tight),
        "field `curve.expr`: \"(u, u^3)\": limit exceeded: exponent 3 at column 6 is larger than 2"
    );
}

#[test]
fn depth() {
    let deep = format!("{}1{}", "(".repeat(300), ")".repeat(300));
    let p = json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [deep, 1]]}, "params": [0]});
    assert!(
        err(&p).ends_with("limit exceeded: expression nested deeper than 200 at column 202"),
        "{}",
        err(&p)
    );
    // exactly 200 read
    let at_the_limit = format!("{}1{}", "(".repeat(200), ")".repeat(200));
    let q =
        json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [at_the_limit, 1]]}, "params": [0]});
    assert!(solve(&q).is_ok());
    let raised = Limits {
        max_depth: 400,
        ..Limits::default()
    };
    assert!(solve_with(&p, &raised).is_ok());
    // nesting of lists and objects (a JSON reader refuses deeper than 128): the typed reading
    // refuses the first list where a number belongs, without going deeper
    let mut nested = json!(0);
    for _ in 0..200 {
        nested = json!([nested]);
    }
    let n = json!({"op": "circle", "center": nested});
    assert_eq!(
        err(&n),
        "field `center[0]`: expected a number, found a list of 1"
    );
}

#[test]
fn batch() {
    let one = json!({"op": "circle", "arcs": 4});
    let batch = Value::Array(vec![one.clone(); 5]);
    let small = Limits {
        max_batch: 3,
        ..Limits::default()
    };
    let answers = solve_batch_with(&batch, &small, 1);
    assert_eq!(answers.len(), 5);
    assert!(answers[..3].iter().all(Result::is_ok));
    for (i, a) in answers.iter().enumerate().skip(3) {
        assert_eq!(
            a.as_ref().unwrap_err().to_string(),
            format!(
                "problem {}: not solved: the batch holds 5 problems, more than the limit of 3",
                i + 1
            )
        );
    }
    // the default is far above a teacher's batch
    assert_eq!(Limits::default().max_batch, 10_000);
}

/// Clamped uniform knots (notes' convention) for `n` control points of degree `p`.
fn clamped(n: usize, p: usize) -> Vec<Value> {
    let inner = n - p - 1;
    let mut k = vec![json!(0); p];
    k.extend((1..=inner).map(|i| json!(format!("{i}/{}", inner + 1))));
    k.extend(vec![json!(1); p]);
    k
}

/// A B-spline's elevation gains r points per span: the size is known, and refused, before the
/// work (31 x 32 points elevated by (10, 10) would be 311 x 322).
#[test]
fn points_computed_by_a_bspline_elevation_or_insertion() {
    let mesh: Vec<Vec<Value>> = (0..31)
        .map(|i| (0..32).map(|j| json!([i, j, (i * j) % 7])).collect())
        .collect();
    let surface =
        json!({"bspline": mesh, "degree": [3, 3], "knots": [clamped(31, 3), clamped(32, 3)]});
    assert_eq!(
        err(&json!({"op": "elevate", "surface": surface, "by": [10, 10]})),
        "field `by`: the elevated patch of bidegree (13, 13) would have 100142 control points, more than the limit of 1000"
    );
    assert_eq!(
        err(&json!({"op": "insert_knot", "surface": surface, "direction": "u", "knot": "1/3", "times": 3})),
        "field `surface`: the surface with the knot inserted would have 1088 control points, more than the limit of 1000"
    );
    let curve = json!({"bspline": line(990), "degree": 3, "knots": clamped(990, 3)});
    assert_eq!(
        err(&json!({"op": "elevate", "curve": curve, "by": 47})),
        "field `curve`: the elevated curve would have 47379 control points, more than the limit of 1000"
    );
    // the estimate is the count the elevation gives: 10 + 2·7 points per direction
    let small: Vec<Vec<Value>> = (0..10)
        .map(|i| (0..10).map(|j| json!([i, j, (i + j) % 3])).collect())
        .collect();
    let small =
        json!({"bspline": small, "degree": [3, 3], "knots": [clamped(10, 3), clamped(10, 3)]});
    let tight = Limits {
        max_points: 24 * 24,
        ..Limits::default()
    };
    let a = solve_with(
        &json!({"op": "elevate", "surface": small, "by": [2, 2]}),
        &tight,
    )
    .unwrap();
    assert_eq!(
        a.to_json(false)["result"]["surface"]["bspline"]
            .as_array()
            .unwrap()
            .len(),
        24
    );
    let tighter = Limits {
        max_points: 24 * 24 - 1,
        ..Limits::default()
    };
    assert!(err_with(
        &json!({"op": "elevate", "surface": small, "by": [2, 2]}),
        &tighter
    )
    .contains("would have 576 control points"));
}

/// Regression (issue 16): an answer could hold numbers past the digit limit and then could not
/// be fed back as a problem, without a word. Now the answer says so, with the limit that reads
/// it back; and read under that limit, it reads.
#[test]
fn an_answer_past_the_digit_limit_says_so() {
    let p = json!({"op": "evaluate", "curve": {"bezier": [[0], [0], [0], [0], [1]]}, "params": ["1/10^300"]});
    let a = solve(&p).unwrap();
    assert_eq!(
        a.remarks,
        ["a number of this answer has 1201 digits, more than the digit limit of 1000 it was read under: to feed the answer back as a problem, raise the digit limit to 1201 or more"]
    );
    // the point 1/10^1200, fed back as a parameter, is refused under the default limit...
    let point = a.get("points").unwrap().to_json()[0][0].clone();
    let back = json!({"op": "evaluate", "curve": {"bezier": [[0], [1]]}, "params": [point]});
    assert!(err(&back).contains("1000"), "{}", err(&back));
    // ... and read under the limit the remark names
    let raised = Limits {
        max_digits: 1201,
        ..Limits::default()
    };
    assert!(solve_with(&back, &raised).is_ok());
    // solved under that limit, the answer has no remark
    assert!(solve_with(&p, &raised).unwrap().remarks.is_empty());
}

/// The first `n` primes above 100.
fn primes_above_100(n: usize) -> Vec<u64> {
    (101u64..)
        .filter(|p| (2..*p).take_while(|d| d * d <= *p).all(|d| p % d != 0))
        .take(n)
        .collect()
}

/// A least-squares fit of bidegree (6, 6) through 200 points whose parameters have unrelated
/// prime denominators: the normal equations on integers have 49 x 49 entries over the lcm of
/// every q^6 s^6, some 9000 digits each (about 9.5 MB).
fn wide_least_squares() -> Value {
    let ps = primes_above_100(143);
    let params: Vec<Value> = (0..200)
        .map(|k| {
            json!([
                format!("1/{}", ps[k % 143]),
                format!("2/{}", ps[(k * 7 + 3) % 143])
            ])
        })
        .collect();
    let points: Vec<Value> = (0..200).map(|k| json!([k % 10, (k * 3) % 7, 1])).collect();
    json!({"op": "approximate", "degree": [6, 6], "params": params, "points": points})
}

#[test]
fn memory_of_the_least_squares_normal_equations_is_claimed_before_the_work() {
    let tight = Limits {
        max_memory: 1,
        ..Limits::default()
    };
    let e = solve_with(&wide_least_squares(), &tight).unwrap_err();
    assert_eq!(e.limit, Some(Limit::Memory));
    let m = e.to_string();
    let (what, rest) = m.split_once(" would take ").unwrap();
    let digits: u64 = what
        .strip_prefix("the normal equations of the least squares (49 x 49 integers of at least ")
        .and_then(|d| d.strip_suffix(" digits each)"))
        .unwrap()
        .parse()
        .unwrap();
    let mb: u64 = rest
        .strip_suffix(" MB, more than the memory limit of 1 MB: refused before the work")
        .unwrap()
        .parse()
        .unwrap();
    // 49² integers of that many digits (3.32 bits a digit, 8 bytes a word, 32 bytes each)
    assert!(digits > 4000, "{m}");
    let least = 49 * 49 * (32 + digits * 332 / 100 / 8) / 1_000_000;
    assert!(mb >= least && mb < 2 * least + 1, "{m}");
    // under a budget that holds them, the claim passes: refused only past it
    let roomy = Limits {
        max_memory: 10 * mb as usize,
        max_seconds: Some(std::time::Duration::from_millis(200)),
        ..Limits::default()
    };
    let e = solve_with(&wide_least_squares(), &roomy)
        .map(|_| ())
        .unwrap_err();
    assert_ne!(e.limit, Some(Limit::Memory), "{e}");
}

/// An `each` of `check_stream` that writes a key: past the problem's deadline or memory
/// budget, what it writes is the problem's error instead (the writing counts with the
/// solving).
#[test]
fn writing_a_key_counts_against_the_deadline_and_the_memory_budget() {
    use cagd_problem::{check_stream, Settings, Verdict};
    let p = json!({"op": "circle", "arcs": 4});
    let run = |limits: Limits, write: &(dyn Fn() + Sync)| -> Verdict {
        let settings = Settings {
            limits,
            steps: false,
        };
        let mut out = Vec::new();
        let done: Result<(), ()> = check_stream(
            [&p],
            &settings,
            1,
            |v: Verdict| {
                if v.answer.is_ok() {
                    write();
                }
                v
            },
            |v| {
                out.push(v);
                Ok(())
            },
        );
        assert!(done.is_ok());
        out.pop().unwrap()
    };
    // a key that takes ever longer to write: stopped at the deadline
    let start = std::time::Instant::now();
    let slow = || {
        while start.elapsed() < std::time::Duration::from_secs(20) {
            cagd_scalar::cancel::checkpoint();
        }
    };
    let deadline = Limits {
        max_seconds: Some(std::time::Duration::from_millis(100)),
        ..Limits::default()
    };
    let v = run(deadline, &slow);
    let e = v.answer.unwrap_err();
    assert_eq!(e.limit, Some(Limit::Seconds));
    assert_eq!(
        e.to_string(),
        "problem 1: not written within the limit of 0.1 s: the answer was found, and writing \
         its key was stopped"
    );
    assert!(start.elapsed() < std::time::Duration::from_secs(20));
    // a key that needs more memory than the budget (as a writer would claim it)
    let big = || cagd_scalar::cancel::claim(3_000_000, || cagd_scalar::cancel::Claimed::Work);
    let small = Limits {
        max_memory: 2,
        ..Limits::default()
    };
    let e = run(small, &big).answer.unwrap_err();
    assert_eq!(e.limit, Some(Limit::Memory));
    assert!(
        e.to_string()
            .starts_with("problem 1: not written within the memory limit of 2 MB"),
        "{e}"
    );
    // within both, the key is written
    assert!(run(Limits::default(), &big).answer.is_ok());
}
