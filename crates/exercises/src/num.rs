//! Small exact numbers for the problems: integers and simple fractions (`Rational64`), and
//! their JSON and text forms (`docs/format.md`: a JSON integer, or a string `"1/2"`).
//!
//! Everything a generator draws is tiny (coordinates in -9..9, denominators 1..4), so the
//! 64-bit rationals never come near overflow; the answers are computed by `cagd-problem` in
//! arbitrary precision.

use num_rational::Rational64;
use serde_json::{json, Value};

/// A small exact number.
pub(crate) type Q = Rational64;

/// A point of space.
pub(crate) type P3 = [Q; 3];

/// The integer `n`.
pub(crate) fn int(n: i64) -> Q {
    Q::from_integer(n)
}

/// `n / d` for a nonzero constant `d` of the generators.
pub(crate) fn frac(n: i64, d: i64) -> Q {
    if d == 0 {
        return int(n);
    }
    Q::new(n, d)
}

/// The point `(x, y, z)` of integers.
pub(crate) fn pt(x: i64, y: i64, z: i64) -> P3 {
    [int(x), int(y), int(z)]
}

/// A number as JSON: an integer, or a string of the grammar (`"-5/2"`).
pub(crate) fn num_json(x: &Q) -> Value {
    if x.is_integer() {
        json!(x.to_integer())
    } else {
        json!(x.to_string())
    }
}

/// A point as JSON.
pub(crate) fn point_json(p: &P3) -> Value {
    Value::Array(p.iter().map(num_json).collect())
}

/// A control polygon `{"bezier": [...]}`.
pub(crate) fn bezier_curve_json(ps: &[P3]) -> Value {
    json!({"bezier": ps.iter().map(point_json).collect::<Vec<_>>()})
}

/// A rational Bézier curve `{"bezier": [...], "weights": [...]}`.
pub(crate) fn rational_curve_json(ps: &[P3], weights: &[Q]) -> Value {
    json!({"bezier": ps.iter().map(point_json).collect::<Vec<_>>(), "weights": numbers_json(weights)})
}

/// A B-spline curve `{"bspline": [...], "degree": p, "knots": [...]}`, its knots in the
/// notes' convention (no end knots: n + p - 1 of them for n control points).
pub(crate) fn bspline_curve_json(ps: &[P3], degree: usize, knots: &[Q]) -> Value {
    json!({"bspline": ps.iter().map(point_json).collect::<Vec<_>>(), "degree": degree, "knots": numbers_json(knots)})
}

/// The rows of a control mesh `[[...], ...]`, outer index along u.
pub(crate) fn mesh_json(rows: &[Vec<P3>]) -> Value {
    Value::Array(
        rows.iter()
            .map(|r| Value::Array(r.iter().map(point_json).collect()))
            .collect(),
    )
}

/// A control mesh `{"bezier": [[...], ...]}`, outer index along u.
pub(crate) fn bezier_surface_json(rows: &[Vec<P3>]) -> Value {
    json!({ "bezier": mesh_json(rows) })
}

/// A list of numbers as JSON.
pub(crate) fn numbers_json(xs: &[Q]) -> Value {
    Value::Array(xs.iter().map(num_json).collect())
}

/// `[a, b]` in text.
pub(crate) fn interval_text(a: &Q, b: &Q) -> String {
    format!("[{a}, {b}]")
}

/// `{0, 1/2, 1}` in text.
pub(crate) fn set_text(xs: &[Q]) -> String {
    format!(
        "{{{}}}",
        xs.iter().map(Q::to_string).collect::<Vec<_>>().join(", ")
    )
}

/// `(1/2, 0, 3)` in text.
pub(crate) fn point_text(p: &P3) -> String {
    format!("({}, {}, {})", p[0], p[1], p[2])
}

/// p + q.
pub(crate) fn add(p: &P3, q: &P3) -> P3 {
    [p[0] + q[0], p[1] + q[1], p[2] + q[2]]
}

/// p - q.
pub(crate) fn sub(p: &P3, q: &P3) -> P3 {
    [p[0] - q[0], p[1] - q[1], p[2] - q[2]]
}

/// k p.
pub(crate) fn scale(p: &P3, k: Q) -> P3 {
    [p[0] * k, p[1] * k, p[2] * k]
}

/// Transposes a mesh: rows become columns (u and v exchange roles).
pub(crate) fn transpose(rows: &[Vec<P3>]) -> Vec<Vec<P3>> {
    let cols = rows.first().map_or(0, Vec::len);
    (0..cols)
        .map(|j| rows.iter().filter_map(|r| r.get(j).copied()).collect())
        .collect()
}

/// A polynomial in two variables with small integer coefficients, as a list of terms
/// `(coefficient, power of the first variable, power of the second)`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Poly2(pub Vec<(i64, u32, u32)>);

impl Poly2 {
    /// The polynomial in the grammar of `docs/format.md`, in the printer's order (graded
    /// lexicographic: higher total degree first, then the higher power of the first
    /// variable), with `*` written out: `x^2*y - 2*x + 3`.
    pub(crate) fn to_expr(&self, a: &str, b: &str) -> String {
        let mut terms: Vec<_> = self.0.iter().filter(|t| t.0 != 0).copied().collect();
        terms.sort_by_key(|t| std::cmp::Reverse((t.1 + t.2, t.1)));
        if terms.is_empty() {
            return "0".into();
        }
        let mut out = String::new();
        for (k, (c, i, j)) in terms.iter().enumerate() {
            let mut factors = Vec::new();
            for (var, e) in [(a, *i), (b, *j)] {
                match e {
                    0 => {}
                    1 => factors.push(var.to_string()),
                    e => factors.push(format!("{var}^{e}")),
                }
            }
            let mag = c.unsigned_abs();
            let body = match (mag, factors.is_empty()) {
                (_, true) => mag.to_string(),
                (1, false) => factors.join("*"),
                (_, false) => format!("{mag}*{}", factors.join("*")),
            };
            out += &match (k, *c < 0) {
                (0, false) => body,
                (0, true) => format!("-{body}"),
                (_, false) => format!(" + {body}"),
                (_, true) => format!(" - {body}"),
            };
        }
        out
    }

    /// The highest powers of the two variables.
    pub(crate) fn degrees(&self) -> (u32, u32) {
        self.0
            .iter()
            .filter(|t| t.0 != 0)
            .fold((0, 0), |(m, n), t| (m.max(t.1), n.max(t.2)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_print_as_the_grammar() {
        assert_eq!(num_json(&int(3)), json!(3));
        assert_eq!(num_json(&frac(-5, 2)), json!("-5/2"));
        assert_eq!(num_json(&frac(4, 2)), json!(2));
        assert_eq!(point_text(&[frac(1, 2), int(0), int(-3)]), "(1/2, 0, -3)");
        assert_eq!(set_text(&[int(0), frac(1, 3), int(1)]), "{0, 1/3, 1}");
    }

    #[test]
    fn polynomials_print_in_graded_order() {
        let p = Poly2(vec![
            (3, 0, 0),
            (-2, 1, 0),
            (1, 2, 1),
            (-1, 1, 1),
            (0, 2, 2),
        ]);
        assert_eq!(p.to_expr("x", "y"), "x^2*y - x*y - 2*x + 3");
        assert_eq!(p.degrees(), (2, 1));
        assert_eq!(Poly2(vec![(-1, 0, 2)]).to_expr("u", "v"), "-v^2");
        assert_eq!(Poly2(vec![]).to_expr("u", "v"), "0");
    }

    #[test]
    fn transpose_swaps_indices() {
        let m = vec![
            vec![pt(0, 0, 0), pt(0, 1, 2)],
            vec![pt(1, 0, 3), pt(1, 1, 4)],
            vec![pt(2, 0, 5), pt(2, 1, 6)],
        ];
        let t = transpose(&m);
        assert_eq!(t.len(), 2);
        assert_eq!(t[1][2], pt(2, 1, 6));
        assert_eq!(transpose(&t), m);
    }
}
