//! Shared drawing helpers: friendly meshes, curves, parameters and polynomials, and the
//! [`Draft`] every topic returns.

use crate::num::{frac, int, Poly2, P3, Q};
use crate::rng::Rng;
use serde_json::Value;

/// A problem before it gets its name: the title in both languages and the operation's
/// arguments, in the order they are written.
#[derive(Debug, Clone)]
pub(crate) struct Draft {
    /// The statement in English.
    pub en: String,
    /// The statement in Spanish, with the notes' vocabulary.
    pub es: String,
    /// The arguments of the operation (`surface`, `u`, `v`...).
    pub args: Vec<(&'static str, Value)>,
}

impl Draft {
    /// A draft with its two titles and arguments.
    pub(crate) fn new(en: String, es: String, args: Vec<(&'static str, Value)>) -> Self {
        Draft { en, es, args }
    }
}

/// How a random mesh is laid out.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Layout {
    /// x and y on a regular grid (x = i·sx, y = j·sy), z small integers: the closed form
    /// has x and y linear in u and v, as the notes' examples.
    Grid,
    /// The grid with some interior x, y moved by ±1.
    Jitter,
    /// Every coordinate a small integer in -3..3.
    Free,
}

/// A small height: an integer in -2..3, or with `halves` sometimes a half.
pub(crate) fn height(rng: &mut Rng, halves: bool) -> Q {
    if halves && rng.chance(1, 5) {
        frac(2 * rng.range(-2, 2) + 1, 2)
    } else {
        int(rng.range(-2, 3))
    }
}

/// A random control mesh of bidegree (m, n): (m + 1) rows along u of n + 1 points.
/// The heights are never all equal (the patch is not planar).
pub(crate) fn mesh(
    rng: &mut Rng,
    m: usize,
    n: usize,
    layout: Layout,
    halves: bool,
) -> Vec<Vec<P3>> {
    let sx = if m == 1 { rng.range(1, 2) } else { 1 };
    let sy = if n == 1 { rng.range(1, 2) } else { 1 };
    let mut rows: Vec<Vec<P3>> = (0..=m)
        .map(|i| {
            (0..=n)
                .map(|j| {
                    let (i, j) = (i as i64, j as i64);
                    match layout {
                        Layout::Free => [
                            int(rng.range(-3, 3)),
                            int(rng.range(-3, 3)),
                            int(rng.range(-3, 3)),
                        ],
                        Layout::Grid | Layout::Jitter => {
                            let interior = i > 0 && j > 0 && i < m as i64 && j < n as i64;
                            let jitter = layout == Layout::Jitter && interior;
                            let dx = if jitter { rng.range(-1, 1) } else { 0 };
                            let dy = if jitter { rng.range(-1, 1) } else { 0 };
                            [int(i * sx + dx), int(j * sy + dy), height(rng, halves)]
                        }
                    }
                })
                .collect()
        })
        .collect();
    make_nonplanar(rng, &mut rows);
    rows
}

/// Raises one height when all heights are equal, so the patch is not a plane z = const.
pub(crate) fn make_nonplanar(rng: &mut Rng, rows: &mut [Vec<P3>]) {
    let first = rows.first().and_then(|r| r.first()).map(|p| p[2]);
    let flat = rows.iter().flatten().all(|p| Some(p[2]) == first);
    if flat {
        let i = rng.below(rows.len() as u64) as usize;
        if let Some(row) = rows.get_mut(i) {
            let j = rng.below(row.len() as u64) as usize;
            if let Some(p) = row.get_mut(j) {
                p[2] += int(rng.range(1, 2));
            }
        }
    }
}

/// One of the friendly parameter sets: {0, 1/2, 1}, {0, 1/3, 2/3, 1} or
/// {0, 1/4, 1/2, 3/4, 1}. Drawing the parameters of one direction from one set keeps the
/// denominators of the answers small (at most 4^degree).
pub(crate) fn parameter_set(rng: &mut Rng) -> Vec<Q> {
    match rng.below(3) {
        0 => vec![int(0), frac(1, 2), int(1)],
        1 => vec![int(0), frac(1, 3), frac(2, 3), int(1)],
        _ => vec![int(0), frac(1, 4), frac(1, 2), frac(3, 4), int(1)],
    }
}

/// The k + 1 equally spaced parameters 0, 1/k, ..., 1.
pub(crate) fn uniform(k: usize) -> Vec<Q> {
    let k = k.max(1) as i64;
    (0..=k).map(|i| frac(i, k)).collect()
}

/// An interval [a, b] with a < b, both from `set`.
pub(crate) fn interval(rng: &mut Rng, set: &[Q]) -> (Q, Q) {
    let n = set.len() as u64;
    let i = rng.below(n.saturating_sub(1)) as usize;
    let j = i + 1 + rng.below(n.saturating_sub(1 + i as u64)) as usize;
    let a = set.get(i).copied().unwrap_or_else(|| int(0));
    let b = set.get(j).copied().unwrap_or_else(|| int(1));
    (a, b)
}

/// A random polynomial of `terms` terms with powers up to (`du`, `dv`) and coefficients in
/// -3..3 (never zero), with no repeated monomial.
pub(crate) fn poly2(rng: &mut Rng, terms: usize, du: u32, dv: u32) -> Poly2 {
    let mut out: Vec<(i64, u32, u32)> = Vec::new();
    for _ in 0..terms * 4 {
        if out.len() >= terms {
            break;
        }
        let i = rng.below(u64::from(du) + 1) as u32;
        let j = rng.below(u64::from(dv) + 1) as u32;
        if out.iter().any(|t| (t.1, t.2) == (i, j)) {
            continue;
        }
        let mut c = rng.range(-3, 2);
        if c >= 0 {
            c += 1;
        }
        out.push((c, i, j));
    }
    Poly2(out)
}

/// A polynomial in one variable p(t) with p(0) = `start` and p(1) = `end`: the line through
/// them plus a multiple of t^2 - t and, when `cubic`, of t^3 - t (which vanish at 0 and 1).
pub(crate) fn bridge(rng: &mut Rng, start: i64, end: i64, cubic: bool) -> Poly2 {
    let k2 = rng.range(-2, 2);
    let k3 = if cubic { rng.range(-1, 1) } else { 0 };
    // start + (end - start) t + k2 (t^2 - t) + k3 (t^3 - t)
    Poly2(vec![
        (k3, 3, 0),
        (k2, 2, 0),
        (end - start - k2 - k3, 1, 0),
        (start, 0, 0),
    ])
}

/// The knots of a clamped B-spline of degree p with n control points, in the notes'
/// convention (no end knots, n + p - 1 of them): p zeros, 1, 2, ..., n - p - 1, then p
/// times n - p (`{0, 0, 1, 2, 2}` for n = 4, p = 2).
pub(crate) fn clamped_knots(n: usize, p: usize) -> Vec<Q> {
    let last = n.saturating_sub(p) as i64;
    let mut knots = vec![int(0); p];
    knots.extend((1..last).map(int));
    knots.extend(vec![int(last); p]);
    knots
}

/// [`clamped_knots`] divided by the last one, so that the domain is [0, 1] (`{0, 0, 1/2, 1,
/// 1}` for n = 4, p = 2): the borders u = 0, 1 and the friendly parameters stay the patch's.
pub(crate) fn unit_knots(n: usize, p: usize) -> Vec<Q> {
    let knots = clamped_knots(n, p);
    let last = knots.last().copied().unwrap_or_else(|| int(1));
    if last == int(0) {
        return knots;
    }
    knots.into_iter().map(|k| k / last).collect()
}

/// The word for the bidegree of a mesh: `bidegree (2, 1)`.
pub(crate) fn bidegree(rows: &[Vec<P3>]) -> (usize, usize) {
    (
        rows.len().saturating_sub(1),
        rows.first().map_or(0, Vec::len).saturating_sub(1),
    )
}

/// Writes a tuple of component expressions: `(u, 0, u^2 - 1)`.
pub(crate) fn tuple(parts: &[String]) -> String {
    format!("({})", parts.join(", "))
}

/// The keys of a problem that are not its data: its name, title, source and operation, and
/// the angles of a partial turn (settings in degrees, such as `sweep` = 180).
const NOT_DATA: [&str; 6] = ["name", "title", "source", "op", "sweep", "start"];

/// The data of a problem: its arguments without the keys of [`NOT_DATA`].
pub(crate) fn data(problem: &Value) -> Value {
    match problem {
        Value::Object(m) => Value::Object(
            m.iter()
                .filter(|(k, _)| !NOT_DATA.contains(&k.as_str()))
                .map(|(k, v)| (k.clone(), v.clone()))
                .collect(),
        ),
        v => v.clone(),
    }
}

/// Whether two problems are alike: the same data once one coordinate (x, y or z) of every
/// point and of every component tuple `(x(u), y(u), z(u))` is left out, so that the same
/// grid with other heights, or the same curves lifted in z, count as one problem. A set
/// redraws a problem alike an earlier one.
pub fn alike(a: &Value, b: &Value) -> bool {
    let (a, b) = (data(a), data(b));
    (0..3).any(|k| without_coordinate(&a, k) == without_coordinate(&b, k))
}

/// The keys whose numbers say which variant a problem is (a quadrant or a full turn, the
/// degrees, the orders, the parameter lengths), kept in its [`variant`].
const SETTINGS: [&str; 7] = ["arcs", "sweep", "degree", "by", "order", "lengths", "at"];

/// The variant of a problem: its data with every number left out but the settings'
/// ([`SETTINGS`]) and every expression written `expr`; the kind of curves and surfaces,
/// the sizes of their meshes, the turn, the blending, the basis and the end conditions remain.
fn variant(v: &Value) -> Value {
    fn walk(v: &Value, setting: bool) -> Value {
        match v {
            Value::Object(m) => Value::Object(
                m.iter()
                    .map(|(k, x)| {
                        let keep = SETTINGS.contains(&k.as_str());
                        let x = match x {
                            Value::String(_) if k == "expr" || k == "f" => Value::from("expr"),
                            x => walk(x, keep),
                        };
                        (k.clone(), x)
                    })
                    .collect(),
            ),
            Value::Array(xs) => Value::Array(xs.iter().map(|x| walk(x, setting)).collect()),
            Value::Number(_) if !setting => Value::Null,
            Value::String(s)
                if !setting
                    && s.starts_with(|c: char| c.is_ascii_digit() || c == '-' || c == 's') =>
            {
                Value::Null
            }
            v => v.clone(),
        }
    }
    walk(&data(v), false)
}

/// Whether two problems are of one variant ([`variant`]): a set prefers a new variant for
/// its next problem while it can find one.
pub(crate) fn same_variant(a: &Value, b: &Value) -> bool {
    variant(a) == variant(b)
}

/// `v` with the coordinate `k` of every point (a list of three numbers) and of every tuple
/// of three expressions left out (written as null, or as `_`).
fn without_coordinate(v: &Value, k: usize) -> Value {
    let is_number = |x: &Value| x.is_number() || x.is_string();
    match v {
        Value::Array(xs) if xs.len() == 3 && xs.iter().all(is_number) => Value::Array(
            xs.iter()
                .enumerate()
                .map(|(i, x)| if i == k { Value::Null } else { x.clone() })
                .collect(),
        ),
        Value::Array(xs) => Value::Array(xs.iter().map(|x| without_coordinate(x, k)).collect()),
        Value::Object(m) => Value::Object(
            m.iter()
                .map(|(key, x)| (key.clone(), without_coordinate(x, k)))
                .collect(),
        ),
        Value::String(s) => {
            let parts = tuple_parts(s);
            if parts.len() == 3 {
                let kept: Vec<&str> = parts
                    .iter()
                    .enumerate()
                    .map(|(i, p)| if i == k { "_" } else { p })
                    .collect();
                Value::from(format!("({})", kept.join(",")))
            } else {
                v.clone()
            }
        }
        v => v.clone(),
    }
}

/// The components of a tuple `(a, b, c)` split at its top-level commas (empty when `s` is
/// not a tuple).
fn tuple_parts(s: &str) -> Vec<&str> {
    let Some(inner) = s.trim().strip_prefix('(').and_then(|t| t.strip_suffix(')')) else {
        return vec![];
    };
    let mut parts = Vec::new();
    let (mut depth, mut start) = (0i32, 0usize);
    for (i, c) in inner.char_indices() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(inner.get(start..i).unwrap_or("").trim());
                start = i + 1;
            }
            _ => {}
        }
        if depth < 0 {
            return vec![];
        }
    }
    parts.push(inner.get(start..).unwrap_or("").trim());
    parts
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn variants_keep_kinds_sizes_and_settings() {
        use serde_json::json;
        let quadrant = json!({"curve": {"bezier": [[1, 0, 0], [0, 0, 2]]}, "arcs": 1});
        let other = json!({"curve": {"bezier": [[3, 0, 1], [1, 0, 5]]}, "arcs": 1});
        let full = json!({"curve": {"bezier": [[1, 0, 0], [0, 0, 2]]}, "arcs": 4});
        let rational =
            json!({"curve": {"bezier": [[1, 0, 0], [0, 0, 2]], "weights": [1, "1/2"]}, "arcs": 1});
        let circle = json!({"curve": {"bezier": [[1, 0, 0], [0, 0, 2]], "weights": [1, "sqrt2/2"]}, "arcs": 1});
        assert!(same_variant(&quadrant, &other));
        assert!(!same_variant(&quadrant, &full));
        assert!(!same_variant(&quadrant, &rational));
        assert!(same_variant(&rational, &circle));
        let basis = json!({"basis": "bezier", "u": [0, "1/2", 1]});
        assert!(!same_variant(
            &basis,
            &json!({"basis": "bicubic", "u": [0, 1, 2]})
        ));
        assert!(same_variant(
            &basis,
            &json!({"basis": "bezier", "u": [0, "1/3", 1]})
        ));
    }

    #[test]
    fn clamped_knots_in_the_notes_convention() {
        // n + p - 1 knots for n control points, p at each end.
        assert_eq!(clamped_knots(4, 2), [0, 0, 1, 2, 2].map(int));
        assert_eq!(clamped_knots(5, 2), [0, 0, 1, 2, 3, 3].map(int));
        assert_eq!(clamped_knots(3, 2), [0, 0, 1, 1].map(int));
        assert_eq!(clamped_knots(3, 1), [0, 1, 2].map(int));
        assert_eq!(
            unit_knots(4, 2),
            [int(0), int(0), frac(1, 2), int(1), int(1)]
        );
        assert_eq!(unit_knots(2, 1), [int(0), int(1)]);
    }

    #[test]
    fn alike_leaves_out_one_coordinate() {
        use serde_json::json;
        let a = json!({"name": "a-1", "op": "x", "points": [[0, 0, 1], [1, 0, 2]]});
        let b = json!({"name": "a-2", "op": "x", "points": [[0, 0, 3], [1, 0, "1/2"]]});
        let c = json!({"name": "a-3", "op": "x", "points": [[0, 1, 3], [1, 0, 5]]});
        assert!(alike(&a, &b));
        assert!(!alike(&a, &c));
        let e = json!({"c1": {"expr": "(u, 0, u^2 - 1)"}, "sweep": 90});
        let f = json!({"c1": {"expr": "(u, 0, 2*u^3)"}, "sweep": 180});
        let g = json!({"c1": {"expr": "(2*u, 0, 2*u^3)"}});
        assert!(alike(&e, &f));
        assert!(alike(&f, &g), "only x differs");
        assert!(!alike(&e, &g), "x and z differ");
        assert_eq!(tuple_parts("(u, f(1, 2), 3)"), ["u", "f(1, 2)", "3"]);
        assert!(tuple_parts("x^2 + y").is_empty());
    }

    #[test]
    fn meshes_have_the_bidegree_and_are_not_flat() {
        for seed in 0..50 {
            let mut rng = Rng::new(seed);
            let m = mesh(&mut rng, 2, 1, Layout::Grid, true);
            assert_eq!(bidegree(&m), (2, 1));
            let z0 = m[0][0][2];
            assert!(m.iter().flatten().any(|p| p[2] != z0));
        }
    }

    #[test]
    fn intervals_are_increasing_and_from_the_set() {
        for seed in 0..100 {
            let mut rng = Rng::new(seed);
            let set = parameter_set(&mut rng);
            let (a, b) = interval(&mut rng, &set);
            assert!(a < b);
            assert!(set.contains(&a) && set.contains(&b));
        }
    }

    #[test]
    fn bridges_meet_their_ends() {
        for seed in 0..30 {
            let mut rng = Rng::new(seed);
            let p = bridge(&mut rng, 2, -1, true);
            let at = |t: i64| -> i64 { p.0.iter().map(|(c, i, _)| c * t.pow(*i)).sum() };
            assert_eq!(at(0), 2);
            assert_eq!(at(1), -1);
        }
    }
}
