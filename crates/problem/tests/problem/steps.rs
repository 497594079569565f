//! The worked solution of every operation (`cagd solve --steps`), pinned in each language:
//! one problem per operation (and per kind where the steps differ: curve or patch, Bézier,
//! B-spline, rational), its key as text, Markdown and LaTeX, in English and in Spanish.

use cagd_keys::{example_latex, example_markdown, example_text, Lang};
use cagd_problem::steps::{Fact, Line, Step, TableTitle};
use cagd_problem::{check_with_settings, Settings};
use serde_json::Value;

fn problems() -> Vec<(String, Value)> {
    let text = include_str!("steps.json");
    let list: Vec<(String, Value)> = serde_json::from_str(text).expect("steps.json");
    list
}

#[test]
fn every_operation_shows_its_steps() {
    let ops: std::collections::BTreeSet<String> = problems()
        .iter()
        .map(|(_, p)| p["op"].as_str().expect("op").to_string())
        .collect();
    for op in cagd_problem::operations() {
        assert!(ops.contains(*op), "no steps problem for {op}");
    }
    for (name, problem) in problems() {
        let verdict = check_with_settings(&problem, &Settings::default());
        let answer = verdict
            .answer
            .as_ref()
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(!answer.derivation.is_empty(), "{name}: no worked solution");
        assert!(
            answer
                .derivation
                .iter()
                .any(|s| matches!(s, cagd_problem::steps::Step::Formula { .. })),
            "{name}: no formula"
        );
        let json = answer.to_json(true);
        assert!(
            json["result"]["derivation"].is_array(),
            "{name}: no derivation in JSON"
        );
    }
}

#[test]
fn no_steps_without_steps() {
    let settings = Settings {
        steps: false,
        ..Settings::default()
    };
    for (name, problem) in problems() {
        let verdict = check_with_settings(&problem, &settings);
        let answer = verdict
            .answer
            .as_ref()
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(answer.derivation.is_empty(), "{name}: steps recorded");
        // the result is the same with and without steps
        let with = check_with_settings(&problem, &Settings::default());
        assert_eq!(
            with.answer.as_ref().map(|a| &a.result).ok(),
            Some(&answer.result),
            "{name}"
        );
    }
}

#[test]
fn every_operation_key_is_pinned_in_each_language() {
    let mut settings = insta::Settings::clone_current();
    settings.set_snapshot_path("../../../../snapshots");
    settings.set_prepend_module_to_snapshot(false);
    settings.bind(|| {
        for (name, problem) in problems() {
            let verdict = check_with_settings(&problem, &Settings::default());
            for (lang, code) in [(Lang::En, "en"), (Lang::Es, "es")] {
                let key = format!(
                    "{}\n---- markdown ----\n{}\n---- latex ----\n{}",
                    example_text(&verdict, lang),
                    example_markdown(&verdict, lang),
                    example_latex(&verdict, lang)
                );
                insta::assert_snapshot!(format!("steps__{name}__{code}"), key);
            }
        }
    });
}

/// `evaluate` at a long list of parameters works the steps of the first three points and says
/// once that the others are found in the same way; every point is still in the result.
#[test]
fn a_long_list_of_points_is_worked_for_the_first_three() {
    let problems = [
        serde_json::json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 2], [3, 3]]},
            "params": [0, "1/5", "2/5", "3/5", "4/5", 1]}),
        serde_json::json!({"op": "evaluate", "surface": {"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]},
            "params": [[0, 0], ["1/2", 0], [1, 0], [0, 1], ["1/2", 1], [1, 1]]}),
        serde_json::json!({"op": "evaluate", "triangle": {"triangle": [[[0, 0, 0]], [[1, 0, 0], [0, 1, 0]]]},
            "params": [[0, 0], ["1/2", 0], [1, 0], [0, 1], ["1/2", "1/2"], [0, "1/2"]]}),
    ];
    for problem in problems {
        let verdict = check_with_settings(&problem, &Settings::default());
        let text = example_text(&verdict, Lang::En);
        assert_eq!(text.matches("At the parameter").count(), 3, "{text}");
        assert!(
            text.contains(
                "The other 3 points are found in the same way (the steps are worked for the first 3)."
            ),
            "{text}"
        );
        let answer = verdict.answer.as_ref().expect("answered");
        let json = answer.to_json(false);
        assert_eq!(json["result"]["points"].as_array().map(Vec::len), Some(6));
        let es = example_text(&verdict, Lang::Es);
        assert!(
            es.contains("Los otros 3 puntos se obtienen del mismo modo"),
            "{es}"
        );
    }
}

/// Problems above the thresholds of the worked steps (`ops/explain.rs`): a (5, 5) patch
/// evaluated at five points, elevations with passes of more than 24 combinations, an (8, 8)
/// grid, twelve points fitted by a (2, 2) patch.
fn big_problems() -> Vec<(String, Value)> {
    serde_json::from_str(include_str!("big_steps.json")).expect("big_steps.json")
}

/// The problem of `big_steps.json` named `name`, solved with steps.
fn big(name: &str) -> cagd_problem::Answer {
    let (_, problem) = big_problems()
        .into_iter()
        .find(|(n, _)| n == name)
        .expect(name);
    check_with_settings(&problem, &Settings::default())
        .answer
        .expect(name)
}

/// A number of an answer's JSON (a JSON integer or a string of the grammar) as a rational.
fn rational(v: &Value) -> cagd_scalar::BigRational {
    match v {
        Value::Number(n) => cagd_scalar::BigRational::from_integer(n.as_i64().expect("int").into()),
        Value::String(s) => s.replace(' ', "").parse().expect("a rational"),
        _ => panic!("not a number: {v}"),
    }
}

/// The first rows of the matrix `symbol` summarised in a derivation's JSON, with its size.
fn summary(json: &Value, symbol: &str) -> ((u64, u64), Vec<Vec<cagd_scalar::BigRational>>) {
    let m = json["result"]["derivation"]
        .as_array()
        .expect("derivation")
        .iter()
        .find(|s| s["kind"] == "matrix" && s["symbol"] == symbol)
        .unwrap_or_else(|| panic!("no summary of {symbol}"));
    let rows = m["first_rows"]
        .as_array()
        .expect("rows")
        .iter()
        .map(|r| r.as_array().expect("row").iter().map(rational).collect())
        .collect();
    let size = (
        m["rows"].as_u64().expect("rows"),
        m["cols"].as_u64().expect("cols"),
    );
    (size, rows)
}

/// Above the thresholds the answer is the one without steps, the key says what it left out,
/// and it names no English word in Spanish.
#[test]
fn big_problems_are_summarised_with_the_same_answer() {
    let quiet = Settings {
        steps: false,
        ..Settings::default()
    };
    for (name, problem) in big_problems() {
        let with = check_with_settings(&problem, &Settings::default());
        let without = check_with_settings(&problem, &quiet);
        let answer = with
            .answer
            .as_ref()
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(
            without.answer.as_ref().map(|a| &a.result).ok(),
            Some(&answer.result),
            "{name}"
        );
        let text = example_text(&with, Lang::En);
        let es = example_text(&with, Lang::Es);
        assert!(
            text.contains("worked in the same way") || text.contains(" matrix ("),
            "{name}: nothing said of what is left out\n{text}"
        );
        assert!(
            es.contains("del mismo modo") || es.contains(" matriz "),
            "{name}\n{es}"
        );
        for key in [
            example_latex(&with, Lang::Es),
            example_markdown(&with, Lang::Es),
        ] {
            for english in ["worked in the same way", " matrix (", "its first"] {
                assert!(!key.contains(english), "{name}: {english}\n{key}");
            }
        }
    }
}

/// A (5, 5) patch (more than four columns) at five points: the first point worked, with the
/// scheme of its first column, the results of the other five columns and the scheme along v;
/// the other four points found in the same way.
#[test]
fn a_big_patch_is_evaluated_with_the_scheme_of_its_first_column() {
    let answer = big("evaluate (5, 5) at 5 points");
    let count = |f: &dyn Fn(&Step) -> bool| answer.derivation.iter().filter(|s| f(s)).count();
    assert_eq!(
        count(&|s| matches!(
            s,
            Step::Table {
                title: TableTitle::DeCasteljau,
                ..
            }
        )),
        2
    );
    assert_eq!(
        count(&|s| matches!(
            s,
            Step::Fact(Fact::SameInTheOtherLines {
                line: Line::Column,
                shown: 1,
                more: 5
            })
        )),
        1
    );
    assert_eq!(
        count(&|s| matches!(s, Step::Fact(Fact::SameForTheOthers { shown: 1, more: 4 }))),
        1
    );
    assert_eq!(
        count(&|s| matches!(s, Step::Value { symbol, .. } if symbol.starts_with("c_{0,"))),
        6,
        "every column's result is listed"
    );
    // the scheme along v starts from the columns' results and ends at the answer's first point
    let json = answer.to_json(true);
    let derivation = json["result"]["derivation"].as_array().expect("derivation");
    let firsts: Vec<&Value> = derivation
        .iter()
        .filter(|s| {
            s["kind"] == "value" && s["symbol"].as_str().is_some_and(|x| x.starts_with("c_{0,"))
        })
        .map(|s| &s["value"])
        .collect();
    let along_v = derivation
        .iter()
        .filter(|s| s["kind"] == "table")
        .nth(3)
        .expect("the scheme along v");
    let rows = along_v["table"]["rows"].as_array().expect("rows");
    for (j, row) in rows.iter().enumerate() {
        assert_eq!(&row[1][0], firsts[j], "c_{{0,{j}}}");
    }
    assert_eq!(
        rows[0][1].as_array().and_then(|c| c.last()),
        Some(&json["result"]["points"][0])
    );
}

/// Elevating a (3, 3) patch by (3, 2) works the first column by 3 at once (7 points) and the
/// first row by 2 at once (6 points); their values are the first column and row of the answer.
#[test]
fn a_big_elevation_works_its_first_column_and_row_at_once() {
    let answer = big("elevate (3, 3) by (3, 2)");
    let json = answer.to_json(true);
    let combos: Vec<&Value> = json["result"]["derivation"]
        .as_array()
        .expect("derivation")
        .iter()
        .filter(|s| s["kind"] == "combination")
        .collect();
    assert_eq!(combos.len(), 7 + 6);
    let mesh = json["result"]["surface"]["bezier"]
        .as_array()
        .expect("mesh");
    for (i, c) in combos.iter().take(7).enumerate() {
        assert_eq!(c["value"], mesh[i][0], "c_{{{i},0}}");
        // Σ_k C(3, k) C(3, i - k) / C(6, i) = 1
        let sum = c["terms"]
            .as_array()
            .expect("terms")
            .iter()
            .map(|t| rational(&t[0]))
            .fold(cagd_scalar::BigRational::from_integer(0.into()), |a, b| {
                a + b
            });
        assert_eq!(sum, cagd_scalar::BigRational::from_integer(1.into()));
    }
    for (j, c) in combos.iter().skip(7).enumerate() {
        assert_eq!(c["value"], mesh[0][j], "c_{{0,{j}}}");
    }
    // a pass under the threshold keeps every combination: (3, 3) by (1, 1) works its four
    // columns (20) and, its rows being 25, the first row
    let small = big("elevate (3, 3) by (1, 1)");
    let count = small
        .derivation
        .iter()
        .filter(|s| matches!(s, Step::Combination { .. }))
        .count();
    assert_eq!(count, 20 + 5);
}

/// An (8, 8) grid: B_U and B_V by their size and first rows (the Bernstein values at u_0 and
/// u_1), and the first row of C̃, the Bézier curve through the first row of the data.
#[test]
fn a_big_grid_shows_its_matrices_by_their_first_rows() {
    use cagd_scalar::BigRational;
    let answer = big("interpolate a (8, 8) grid");
    let json = answer.to_json(true);
    let ts: Vec<BigRational> = (0..=8)
        .map(|i| BigRational::new(i.into(), 8.into()))
        .collect();
    let b = cagd_fit::bernstein_matrix(8, &ts).to_rows();
    for symbol in ["B_U", "B_V"] {
        let (size, rows) = summary(&json, symbol);
        assert_eq!(size, (9, 9));
        assert_eq!(rows.as_slice(), &b[..2], "{symbol}");
    }
    let (_, problem) = big_problems()
        .into_iter()
        .find(|(n, _)| n == "interpolate a (8, 8) grid")
        .expect("grid");
    let data: Vec<Vec<cagd_linalg::Point<BigRational>>> = problem["points"]
        .as_array()
        .expect("rows")
        .iter()
        .map(|row| {
            row.as_array()
                .expect("row")
                .iter()
                .map(|p| {
                    cagd_linalg::Point::new(
                        p.as_array().expect("point").iter().map(rational).collect(),
                    )
                })
                .collect()
        })
        .collect();
    let data = cagd_surface::Mesh::mesh(data).expect("mesh");
    let mut steps = Vec::new();
    cagd_fit::interpolate_bezier_surface_in_passes(
        &ts,
        &ts,
        &data,
        cagd_fit::PassOrder::RowsFirst,
        &mut steps,
    )
    .expect("steps");
    let intermediate = steps
        .iter()
        .find_map(|s| match s {
            cagd_fit::GridStep::FirstPass { mesh, .. } => Some(mesh),
            _ => None,
        })
        .expect("the first pass");
    let first = json["result"]["derivation"]
        .as_array()
        .expect("derivation")
        .iter()
        .find(|s| s["kind"] == "value")
        .expect("the first row of C~");
    let row: Vec<Vec<BigRational>> = first["value"]
        .as_array()
        .expect("points")
        .iter()
        .map(|p| p.as_array().expect("point").iter().map(rational).collect())
        .collect();
    let expected: Vec<Vec<BigRational>> = intermediate
        .row(0)
        .expect("row 0")
        .iter()
        .map(|p| p.coords().to_vec())
        .collect();
    assert_eq!(row, expected);
}

/// The matrices B, BᵗB and the right-hand side BᵗA of a least-squares fit, as recorded.
struct LeastSquares {
    collocation: cagd_linalg::Matrix<cagd_scalar::BigRational>,
    normal_matrix: cagd_linalg::Matrix<cagd_scalar::BigRational>,
    rhs: Vec<cagd_linalg::Point<cagd_scalar::BigRational>>,
}

/// The step-by-step route's least-squares fit of bidegree (2, 2) of the problem of
/// `big_steps.json` named `name` (its `params` and `points`), over `BigRational`.
fn least_squares_steps(name: &str) -> LeastSquares {
    use cagd_scalar::BigRational;
    let (_, problem) = big_problems()
        .into_iter()
        .find(|(n, _)| n == name)
        .expect(name);
    let list = |key: &str| -> Vec<Vec<BigRational>> {
        problem[key]
            .as_array()
            .expect(key)
            .iter()
            .map(|p| p.as_array().expect("item").iter().map(rational).collect())
            .collect()
    };
    let params: Vec<(BigRational, BigRational)> = list("params")
        .into_iter()
        .map(|p| (p[0].clone(), p[1].clone()))
        .collect();
    let points: Vec<cagd_linalg::Point<BigRational>> = list("points")
        .into_iter()
        .map(cagd_linalg::Point::new)
        .collect();
    let mut steps = Vec::new();
    cagd_fit::approximate_bezier_surface_by_normal_equations(2, 2, &params, &points, &mut steps)
        .expect("fit");
    use cagd_fit::LeastSquaresStep as Step;
    let [Step::Collocation(collocation), Step::NormalMatrix(normal_matrix), Step::NormalRhs(rhs)] =
        <[Step<BigRational>; 3]>::try_from(steps).expect("three steps")
    else {
        panic!("B, BtB and BtA in order");
    };
    LeastSquares {
        collocation,
        normal_matrix,
        rhs,
    }
}

/// Twelve points on a (2, 2) patch: B (12 × 9), BᵗB (9 × 9) and BᵗA (9 × 3) by their first
/// rows, those of the step-by-step route's matrices.
#[test]
fn a_big_least_squares_fit_shows_its_matrices_by_their_first_rows() {
    use cagd_scalar::BigRational;
    let answer = big("least squares (2, 2), 12 points");
    let json = answer.to_json(true);
    let ls = least_squares_steps("least squares (2, 2), 12 points");
    let rhs: Vec<Vec<BigRational>> = ls.rhs.iter().map(|p| p.coords().to_vec()).collect();
    for (symbol, size, whole) in [
        ("B", (12, 9), ls.collocation.to_rows()),
        ("B^t B", (9, 9), ls.normal_matrix.to_rows()),
        ("B^t A", (9, 3), rhs),
    ] {
        let (shown_size, rows) = summary(&json, symbol);
        assert_eq!(shown_size, size, "{symbol}");
        assert_eq!(rows.as_slice(), &whole[..2], "{symbol}");
    }
}

/// A matrix of rationals as the JSON of `expected` writes it (numbers as strings).
fn matrix_json(rows: &[Vec<cagd_scalar::BigRational>]) -> Value {
    Value::Array(
        rows.iter()
            .map(|r| Value::Array(r.iter().map(|x| Value::String(x.to_string())).collect()))
            .collect(),
    )
}

/// The problem of `big_steps.json` named `name` with `"expected": {"steps": steps}`, checked.
fn check_big(name: &str, steps: Value) -> cagd_problem::Verdict {
    let (_, mut problem) = big_problems()
        .into_iter()
        .find(|(n, _)| n == name)
        .expect(name);
    problem["expected"] = serde_json::json!({ "steps": steps });
    check_with_settings(&problem, &Settings::default())
}

/// Above the limits the key shows B_U by its first rows, but a problem whose `expected` names
/// `B_U` (or `C_x`) has it computed and compared in full: the whole matrix matches, and an
/// entry changed in a row the key does not show is a mismatch of that step, not "not
/// computed".
#[test]
fn a_checked_step_of_a_big_grid_is_compared_in_full() {
    use cagd_scalar::BigRational;
    let name = "interpolate a (8, 8) grid";
    let ts: Vec<BigRational> = (0..=8)
        .map(|i| BigRational::new(i.into(), 8.into()))
        .collect();
    let b = cagd_fit::bernstein_matrix(8, &ts).to_rows();
    let whole = big(name).to_json(true);
    let c_x = whole["result"]["surface"]["bezier"]
        .as_array()
        .expect("mesh")
        .iter()
        .map(|row| {
            row.as_array()
                .expect("row")
                .iter()
                .map(|p| rational(&p[0]))
                .collect()
        })
        .collect::<Vec<Vec<BigRational>>>();
    let good = check_big(
        name,
        serde_json::json!({"B_U": matrix_json(&b), "C_x": matrix_json(&c_x)}),
    );
    assert!(good.passed(), "{:?}", good.mismatches);
    let derivation = &good.answer.as_ref().expect("answer").derivation;
    assert!(
        derivation
            .iter()
            .any(|s| matches!(s, Step::Matrix(m) if m.symbol == "B_U")),
        "the key still shows B_U by its first rows"
    );
    let mut wrong = b.clone();
    wrong[8][8] = BigRational::new(2.into(), 1.into());
    let bad = check_big(name, serde_json::json!({"B_U": matrix_json(&wrong)}));
    assert!(!bad.passed());
    assert_eq!(bad.mismatches.len(), 1, "{:?}", bad.mismatches);
    assert!(
        bad.mismatches[0].to_string().starts_with("step `B_U`:")
            && !bad.mismatches[0].to_string().contains("records no"),
        "{:?}",
        bad.mismatches
    );
}

/// The same for a least-squares fit above the limits: BᵗB named in `expected` is the whole
/// normal matrix, compared entry by entry.
#[test]
fn a_checked_step_of_a_big_least_squares_fit_is_compared_in_full() {
    use cagd_scalar::BigRational;
    let name = "least squares (2, 2), 12 points";
    let ls = least_squares_steps(name);
    let btb = ls.normal_matrix.to_rows();
    let good = check_big(name, serde_json::json!({"BtB": matrix_json(&btb)}));
    assert!(good.passed(), "{:?}", good.mismatches);
    let mut wrong = btb.clone();
    wrong[8][7] += BigRational::new(1.into(), 1.into());
    let bad = check_big(name, serde_json::json!({"BtB": matrix_json(&wrong)}));
    assert_eq!(bad.mismatches.len(), 1, "{:?}", bad.mismatches);
    assert!(
        bad.mismatches[0].to_string().starts_with("step `BtB`:")
            && !bad.mismatches[0].to_string().contains("records no"),
        "{:?}",
        bad.mismatches
    );
}

/// A step named in `expected` that the operation does not record (a typo: `c_CD` for `c_cd`)
/// is a mismatch that says so and lists the steps it records, so that the name can be
/// corrected; an operation that records no named steps says that instead. A step it records
/// is still compared, value by value.
#[test]
fn a_step_the_operation_does_not_record_is_named_with_the_steps_it_does() {
    let coons = |steps: Value| {
        serde_json::json!({"op": "coons",
            "c1": {"bezier": [[0, 0, 0], [1, 0, 0]]}, "c2": {"bezier": [[0, 1, 0], [1, 1, 0]]},
            "d1": {"bezier": [[0, 0, 0], [0, 1, 0]]}, "d2": {"bezier": [[1, 0, 0], [1, 1, 0]]},
            "expected": {"steps": steps}})
    };
    let typo = check_with_settings(
        &coons(
            serde_json::json!({"c_CD": {"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]]}}),
        ),
        &Settings::default(),
    );
    assert_eq!(
        typo.mismatches,
        ["step `c_CD`: `coons` records no step named `c_CD` (its steps: `c_c`, `c_d`, `c_cd`)"]
    );
    // the step recorded is compared as before: right, then wrong
    let right = check_with_settings(
        &coons(
            serde_json::json!({"c_cd": {"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]]}}),
        ),
        &Settings::default(),
    );
    assert!(right.passed(), "{:?}", right.mismatches);
    let wrong = check_with_settings(
        &coons(
            serde_json::json!({"c_cd": {"bezier": [[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]}}),
        ),
        &Settings::default(),
    );
    assert_eq!(wrong.mismatches.len(), 1, "{:?}", wrong.mismatches);
    assert!(
        wrong.mismatches[0].to_string().starts_with("step `c_cd`: ")
            && !wrong.mismatches[0].to_string().contains("records no step"),
        "{:?}",
        wrong.mismatches
    );
    let none = check_with_settings(
        &serde_json::json!({"op": "evaluate", "curve": {"bezier": [[0, 0], [1, 2], [3, 0]]},
            "params": ["1/2"], "expected": {"steps": {"c_hat": [[0, 0]]}}}),
        &Settings::default(),
    );
    assert_eq!(
        none.mismatches,
        ["step `c_hat`: `evaluate` records no named steps to check"]
    );
}
