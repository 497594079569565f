//! `solve` on problems that have the right shape more often than random JSON does: every
//! operation with its keys, curves and surfaces of small degree with small exact numbers (and
//! now and then a zero weight, a repeated knot, a huge degree, a string that does not parse),
//! built with `arbitrary` from the fuzzer's bytes. Never a panic; the answers print.
#![no_main]

use arbitrary::{Result, Unstructured};
use cagd_keys::{example_text, Lang};
use cagd_problem::{check, operations};
use libfuzzer_sys::fuzz_target;
use serde_json::{json, Map, Value};

/// A number: mostly small rationals, sometimes √2/2, zero, a float, a huge or broken one.
fn number(u: &mut Unstructured<'_>) -> Result<Value> {
    Ok(match u.int_in_range(0u8..=19)? {
        0..=7 => json!(u.int_in_range(-3i64..=3)?),
        8..=12 => {
            let n = u.int_in_range(-4i64..=4)?;
            let d = u.int_in_range(1i64..=4)?;
            json!(format!("{n}/{d}"))
        }
        13 => json!(*u.choose(&["sqrt2/2", "1/2 + sqrt2/2", "-sqrt2", "sqrt3/2"])?),
        14 => json!(0),
        15 => json!(*u.choose(&["1/4", "3/4", "1/3", "2/3"])?),
        16 => json!(0.5),
        17 => json!(u.arbitrary::<i64>()?),
        18 => json!(*u.choose(&["", "1/0", "abc", "u", "sqrt(-1)", "10^1000", "0.000001"])?),
        _ => json!(u.arbitrary::<String>()?),
    })
}

/// A small count, sometimes huge (to meet the limits).
fn count(u: &mut Unstructured<'_>, max: u64) -> Result<Value> {
    Ok(match u.int_in_range(0u8..=15)? {
        0 => json!(u.arbitrary::<u64>()?),
        1 => json!(-1),
        2 => json!("2"),
        _ => json!(u.int_in_range(0..=max)?),
    })
}

fn numbers(u: &mut Unstructured<'_>, n: usize) -> Result<Value> {
    (0..n).map(|_| number(u)).collect::<Result<Vec<_>>>().map(Value::Array)
}

fn point(u: &mut Unstructured<'_>, dim: usize) -> Result<Value> {
    numbers(u, dim)
}

/// Parameters in [0, 1] (mostly), as numbers.
fn param(u: &mut Unstructured<'_>) -> Result<Value> {
    Ok(match u.int_in_range(0u8..=9)? {
        0 => json!(0),
        1 => json!(1),
        2..=7 => json!(*u.choose(&["1/4", "1/3", "1/2", "2/3", "3/4", "1/5"])?),
        _ => number(u)?,
    })
}

/// Knots: non-decreasing most of the time.
fn knots(u: &mut Unstructured<'_>, n: usize) -> Result<Value> {
    if u.ratio(1u8, 6)? {
        return numbers(u, n);
    }
    let mut k = 0i64;
    let mut out = Vec::new();
    for _ in 0..n {
        k += u.int_in_range(0i64..=2)?;
        out.push(json!(k));
    }
    Ok(Value::Array(out))
}

/// An expression of a curve (`t` or `u`) or a surface (`u`, `v`).
fn expr(u: &mut Unstructured<'_>, surface: bool) -> Result<Value> {
    let vars: &[&str] = if surface { &["u", "v", "u v", "u^2", "v^2"] } else { &["u", "u^2", "u^3", "t"] };
    let mut comps = Vec::new();
    let dim = u.int_in_range(1usize..=3)?;
    for _ in 0..dim {
        let terms = u.int_in_range(1usize..=3)?;
        let mut c = Vec::new();
        for _ in 0..terms {
            let n = u.int_in_range(-3i64..=3)?;
            c.push(format!("{n}*{}", u.choose(vars)?));
        }
        comps.push(c.join(" + "));
    }
    if u.ratio(1u8, 10)? {
        return Ok(json!({"expr": u.arbitrary::<String>()?}));
    }
    Ok(json!({"expr": format!("({})", comps.join(", "))}))
}

fn weights(u: &mut Unstructured<'_>, n: usize) -> Result<Value> {
    let mut out = Vec::new();
    for _ in 0..n {
        out.push(match u.int_in_range(0u8..=9)? {
            0 => json!(0),
            1 => json!(-1),
            2 => json!("sqrt2/2"),
            3 => json!("1/2"),
            _ => json!(u.int_in_range(1i64..=3)?),
        });
    }
    Ok(Value::Array(out))
}

fn curve(u: &mut Unstructured<'_>, dim: usize) -> Result<Value> {
    Ok(match u.int_in_range(0u8..=5)? {
        0..=2 => {
            let n = u.int_in_range(1usize..=5)?;
            let pts = (0..n).map(|_| point(u, dim)).collect::<Result<Vec<_>>>()?;
            let mut c = json!({"bezier": pts});
            if u.ratio(1u8, 3)? {
                let extra = usize::from(u.ratio(1u8, 8)?);
                c["weights"] = weights(u, n + extra)?;
            }
            c
        }
        3 | 4 => {
            let n = u.int_in_range(1usize..=7)?;
            let p = u.int_in_range(0usize..=3)?;
            let pts = (0..n).map(|_| point(u, dim)).collect::<Result<Vec<_>>>()?;
            let len = if u.arbitrary()? { n + p + 1 } else { (n + p).saturating_sub(1) };
            let len = len + usize::from(u.ratio(1u8, 8)?);
            let mut c = json!({"bspline": pts, "degree": p, "knots": knots(u, len)?});
            if u.ratio(1u8, 3)? {
                c["weights"] = weights(u, n)?;
            }
            c
        }
        _ => expr(u, false)?,
    })
}

fn surface(u: &mut Unstructured<'_>, dim: usize) -> Result<Value> {
    Ok(match u.int_in_range(0u8..=5)? {
        0..=2 => {
            let (m, n) = (u.int_in_range(1usize..=4)?, u.int_in_range(1usize..=4)?);
            let rows = (0..m)
                .map(|_| (0..n).map(|_| point(u, dim)).collect::<Result<Vec<_>>>())
                .collect::<Result<Vec<_>>>()?;
            let mut s = json!({"bezier": rows});
            if u.ratio(1u8, 3)? {
                s["weights"] = (0..m).map(|_| weights(u, n)).collect::<Result<Vec<_>>>()?.into();
            }
            s
        }
        3 | 4 => {
            let (m, n) = (u.int_in_range(1usize..=5)?, u.int_in_range(1usize..=5)?);
            let (p, q) = (u.int_in_range(0usize..=3)?, u.int_in_range(0usize..=3)?);
            let rows = (0..m)
                .map(|_| (0..n).map(|_| point(u, dim)).collect::<Result<Vec<_>>>())
                .collect::<Result<Vec<_>>>()?;
            let ku = knots(u, m + p + 1)?;
            let kv = knots(u, (n + q).saturating_sub(1))?;
            let mut s = json!({"bspline": rows, "degree": [p, q], "knots": [ku, kv]});
            if u.ratio(1u8, 3)? {
                s["weights"] = (0..m).map(|_| weights(u, n)).collect::<Result<Vec<_>>>()?.into();
            }
            s
        }
        _ => expr(u, true)?,
    })
}

/// The value of argument `key` of a problem.
fn argument(u: &mut Unstructured<'_>, key: &str, dim: usize) -> Result<Value> {
    Ok(match key {
        "curve" | "c" | "d" | "c1" | "c2" | "d1" | "d2" => curve(u, dim)?,
        "surface" | "first" | "second" => surface(u, dim)?,
        "params" => {
            let n = u.int_in_range(0usize..=4)?;
            let pairs = u.arbitrary::<bool>()?;
            (0..n)
                .map(|_| {
                    if pairs {
                        Ok(json!([param(u)?, param(u)?]))
                    } else {
                        param(u)
                    }
                })
                .collect::<Result<Vec<_>>>()?
                .into()
        }
        "t" | "u" | "v" | "lengths" | "interval" => {
            if key != "t" && u.ratio(1u8, 3)? {
                let n = u.int_in_range(1usize..=4)?;
                (0..n).map(|_| param(u)).collect::<Result<Vec<_>>>()?.into()
            } else {
                json!([param(u)?, param(u)?])
            }
        }
        "by" | "order" | "degree" => {
            if u.arbitrary()? {
                json!([count(u, 3)?, count(u, 3)?])
            } else {
                count(u, 4)?
            }
        }
        "times" | "quadrant" => count(u, 4)?,
        "arcs" => count(u, 6)?,
        "at" => json!({*u.choose(&["u", "v"])?: param(u)?}),
        "border" | "direction" => json!(*u.choose(&["u", "v", "w"])?),
        "basis" => json!(*u.choose(&["bezier", "bicubic", "nurbs"])?),
        "end" => json!(*u.choose(&["natural", "bessel", "clamped"])?),
        "blend" => json!(*u.choose(&["linear", "cubic", "quintic"])?),
        "f" => json!(*u.choose(&["x*y", "x^2 - y", "x^3*y + 1", "2", "(x, y)", "x/y"])?),
        "points" => {
            if u.arbitrary()? {
                let n = u.int_in_range(1usize..=5)?;
                (0..n).map(|_| point(u, dim)).collect::<Result<Vec<_>>>()?.into()
            } else {
                let (m, n) = (u.int_in_range(1usize..=4)?, u.int_in_range(1usize..=4)?);
                (0..m)
                    .map(|_| (0..n).map(|_| point(u, dim)).collect::<Result<Vec<_>>>().map(Value::Array))
                    .collect::<Result<Vec<_>>>()?
                    .into()
            }
        }
        "radius" | "knot" => number(u)?,
        "center" => point(u, dim)?,
        _ => number(u)?,
    })
}

/// The keys an operation reads (and some it does not).
fn keys(op: &str) -> &'static [&'static str] {
    match op {
        "evaluate" => &["curve", "surface", "params"],
        "closed_form" => &["surface", "curve"],
        "restrict" => &["curve", "surface", "t", "u", "v"],
        "elevate" => &["curve", "surface", "by"],
        "derivative" => &["curve", "surface", "order", "at"],
        "normal" => &["surface"],
        "continuity" => &["first", "second", "border", "lengths"],
        "interpolate" => &["basis", "end", "u", "v", "points", "params"],
        "approximate" => &["degree", "points", "params"],
        "translational" => &["c", "d"],
        "ruled" | "developable" => &["c1", "c2", "surface"],
        "coons" => &["c1", "c2", "d1", "d2", "blend"],
        "revolution" => &["curve", "arcs", "interval", "quadrant"],
        "circle" => &["radius", "arcs", "center", "interval"],
        "insert_knot" => &["curve", "surface", "knot", "times", "direction"],
        "graph" => &["f", "degree"],
        _ => &["curve"],
    }
}

fn problem(u: &mut Unstructured<'_>) -> Result<Value> {
    let op = *u.choose(operations())?;
    let dim = u.int_in_range(1usize..=4)?;
    let mut p = Map::new();
    p.insert("op".into(), json!(op));
    for key in keys(op) {
        if u.ratio(7u8, 8)? {
            p.insert((*key).into(), argument(u, key, dim)?);
        }
    }
    Ok(Value::Object(p))
}

fuzz_target!(|data: &[u8]| {
    let mut u = Unstructured::new(data);
    let Ok(p) = problem(&mut u) else {
        return;
    };
    let v = check(&p);
    match &v.answer {
        Ok(a) => {
            let _ = a.to_json(true);
        }
        Err(e) => assert!(!e.message.contains("internal error"), "{e}"),
    }
    let _ = example_text(&v, Lang::En);
});
